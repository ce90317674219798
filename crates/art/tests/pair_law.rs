//! ART's pair law as built (`gartowen_art::pair_law`, `proofs/ArtPair.v`): the exact
//! probability ρ(k, δ) that two inputs first differing at digit k by δ reach one symbol below
//! it, computed from the grammar, against a count on the scrambler itself: over every root
//! symbol, every prefix and every digit c, the words prefix·c·r and prefix·(c ⊕ δ)·r whose
//! scrambles agree on every digit below k (for two unrelated suffixes r) are exactly the
//! shared-child cases. And Owen's full-tree oracle does not share: its count is 0.

use gartowen_art::pair_law::{shared_child, symbol_counts, PairLawError};
use gartowen_art::{ArtOwen, ArtVariant};
use gartowen_core::Width;

/// Cases (root, prefix, c) whose scrambles agree below digit k for both suffixes.
fn counted_agreements(art: &ArtOwen, q: u32, depth: u32, delta: u64) -> (u128, u128) {
    let width = Width::W32;
    let b = 1u64 << q;
    let below = 32 - q * (depth + 1);
    let low = (1u64 << below) - 1;
    let suffixes = [
        0x9e37_79b9_7f4a_7c15u64 & low,
        0x3c6e_f372_fe94_f82bu64 & low,
    ];
    let symbols = art.grammar().symbols();
    let (mut agree, mut total) = (0u128, 0u128);
    for root in 0..symbols {
        for prefix in 0..b.pow(depth) {
            for c in 0..b {
                let word = |digit: u64, r: u64| (((prefix << q) | digit) << below) | r;
                let same = suffixes.iter().all(|&r| {
                    let x = art.scramble_from_root(word(c, r), width, root, false);
                    let y = art.scramble_from_root(word(c ^ delta, r), width, root, false);
                    (x ^ y) & low == 0
                });
                agree += u128::from(same);
                total += 1;
            }
        }
    }
    (agree, total)
}

/// The δ with the largest ρ at depth 0 (1 when no δ shares).
fn most_shared_delta(art: &ArtOwen, q: u32) -> u64 {
    (1..1u32 << q)
        .max_by_key(|&d| shared_child(art.grammar(), 0, d).unwrap().shared)
        .unwrap() as u64
}

#[test]
fn the_shared_child_probability_is_what_the_scrambler_does() {
    let mut shared_cases = 0;
    for (variant, symbols, depths) in [
        (ArtVariant::ArtOwen2, 64, 0..=5),
        (ArtVariant::QArt4, 64, 0..=3),
        (ArtVariant::ArtOwen8P, 32, 0..=2),
        (ArtVariant::ArtOwen16P, 32, 0..=1),
        // Tables with fewer symbols than a node has children's worth of distinct factors:
        // siblings share symbols (and subtrees).
        (ArtVariant::ArtOwen16P, 16, 0..=2),
        (ArtVariant::Matrix(5), 16, 0..=1),
        (ArtVariant::Matrix(8), 256, 0..=0),
    ] {
        let art = ArtOwen::new(variant, symbols, 11).unwrap();
        let q = variant.q();
        for depth in depths {
            for delta in [1u64, (1 << q) - 1, most_shared_delta(&art, q)] {
                let exact = shared_child(art.grammar(), depth, delta as u32).unwrap();
                let (agree, total) = counted_agreements(&art, q, depth, delta);
                assert_eq!(total, exact.total, "{variant:?} k = {depth}");
                assert_eq!(
                    agree, exact.shared,
                    "{variant:?} with {symbols} symbols, k = {depth}, δ = {delta}"
                );
                shared_cases += exact.shared;
            }
        }
    }
    // Not vacuous: some grammars do give sibling children one symbol.
    assert!(shared_cases >= 100, "{shared_cases}");
}

/// The registered tables (256 symbols): no sibling ever shares a symbol below base 256; in
/// base 256 the children of digits c and c ⊕ 0xc0 share one almost a quarter of the time.
#[test]
fn registered_tables_share_siblings_only_in_base_256() {
    for variant in ArtVariant::all() {
        let art = ArtOwen::new(variant, gartowen_art::registry::DEFAULT_SYMBOLS, 1).unwrap();
        let q = variant.q();
        let worst = (1..1u32 << q)
            .map(|d| shared_child(art.grammar(), 3, d).unwrap().probability())
            .fold(0.0, f64::max);
        if q < 8 {
            assert_eq!(worst, 0.0, "{variant:?}");
        } else {
            let rho = shared_child(art.grammar(), 3, 0xc0).unwrap();
            // 1/4 less a remainder below 2^-26 of the cases at k = 3.
            let gap = rho.total - 4 * rho.shared;
            assert!(
                gap > 0 && gap < rho.total >> 26,
                "{variant:?}: ρ(3, 0xc0) = {rho:?}"
            );
            assert_eq!(worst, rho.probability(), "{variant:?}");
            assert!((rho.probability() - 0.25).abs() < 1e-7, "{rho:?}");
        }
    }
}

#[test]
fn symbol_counts_sum_to_every_case_and_bad_requests_are_refused() {
    let art = ArtOwen::new(ArtVariant::QArt4, 64, 3).unwrap();
    let g = art.grammar();
    for depth in 0..4 {
        let counts = symbol_counts(g, depth).unwrap();
        assert_eq!(
            counts.iter().sum::<u128>(),
            u128::from(g.symbols()) << (2 * depth)
        );
    }
    assert_eq!(
        shared_child(g, 1, 0),
        Err(PairLawError::BadDelta { delta: 0, base: 4 })
    );
    assert_eq!(
        shared_child(g, 1, 4),
        Err(PairLawError::BadDelta { delta: 4, base: 4 })
    );
    assert_eq!(
        shared_child(g, 70, 1),
        Err(PairLawError::TooDeep { depth: 70 })
    );
    assert_eq!(
        shared_child(g, 1, 4).unwrap_err().to_string(),
        "δ = 4: the digits differ by δ in 1..4"
    );
    assert!(shared_child(g, 70, 1)
        .unwrap_err()
        .to_string()
        .contains("depth 70: |Σ|·b^(k+1) exceeds 128 bits"));
}
