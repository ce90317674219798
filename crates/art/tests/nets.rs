//! ART scrambling preserves nets in its own base (every root symbol of a small table), and
//! the paper's claim: base-16 ART-Owen breaks sz16's binary pair structure at some
//! non-power-of-16 N, while binary ART-Owen keeps it.

use gartowen_art::{ArtOwen, ArtVariant};
use gartowen_core::{Scrambler, Width};
use gartowen_netcheck::counting::{check_net, t_value};
use gartowen_netcheck::{rank, CheckBase, PointSet};
use gartowen_seq::{sobol, sz, DigitalSequence};

fn scrambled_from_root(
    seq: &DigitalSequence,
    s: &ArtOwen,
    dims: &[usize],
    n: u64,
    root: u32,
) -> PointSet {
    PointSet::from_sequence(seq, dims, n, |x, _| {
        s.scramble_from_root(x, seq.width(), root, false)
    })
    .unwrap()
}

fn scrambled(seq: &DigitalSequence, s: &dyn Scrambler, dims: &[usize], n: u64) -> PointSet {
    PointSet::from_sequence(seq, dims, n, |x, j| s.scramble(x, seq.width(), j as u32)).unwrap()
}

#[test]
fn every_root_symbol_preserves_t_values_in_the_scrambling_base() {
    let sob = sobol::sequence(2, Width::W32).unwrap();
    let sz4 = sz::sz4(4, Width::W32).unwrap();
    let sz16 = sz::sz16(4, Width::W32).unwrap();
    let cases: Vec<(ArtVariant, &DigitalSequence, Vec<usize>, u32)> = vec![
        (ArtVariant::ArtOwen2, &sob, vec![0, 1], 12),
        (ArtVariant::Matrix(1), &sob, vec![0, 1], 12),
        (ArtVariant::Translation(1), &sob, vec![0, 1], 12),
        (ArtVariant::QArt4, &sz4, vec![0, 1, 2, 3], 6),
        (ArtVariant::Matrix(2), &sz4, vec![0, 1, 2, 3], 6),
        (ArtVariant::Translation(2), &sz4, vec![0, 1, 2, 3], 6),
        (ArtVariant::ArtOwen16P, &sz16, vec![0, 1, 2, 3], 3),
        (ArtVariant::Matrix(4), &sz16, vec![0, 1, 2, 3], 3),
        (ArtVariant::Translation(4), &sz16, vec![0, 1, 2, 3], 3),
    ];
    for (v, seq, dims, m) in cases {
        let s = ArtOwen::new(v, 6, 17).unwrap();
        let q = v.q();
        let base = CheckBase::new(1 << q).unwrap();
        for mm in 1..=m {
            let expected = rank::t_value(seq, &dims, q, mm).unwrap();
            for root in 0..6 {
                let p = scrambled_from_root(seq, &s, &dims, 1 << (q * mm), root);
                assert_eq!(
                    t_value(&p, base, mm).unwrap(),
                    expected,
                    "{v:?} m={mm} root={root}"
                );
            }
        }
    }
}

#[test]
fn art_owen_16p_keeps_sz16_a_0_4_16_net_for_20_seeds() {
    let seq = sz::sz16(16, Width::W32).unwrap();
    let dims: Vec<usize> = (0..16).collect();
    for seed in 0..20 {
        let s = ArtOwen::new(ArtVariant::ArtOwen16P, 256, seed).unwrap();
        let p = scrambled(&seq, &s, &dims, 1 << 16);
        let r = check_net(&p, CheckBase::new(16).unwrap(), 4, 0).unwrap();
        assert!(r.holds, "seed {seed}: {:?}", r.first_failure);
    }
}

#[test]
#[ignore = "large tier (scripts/test-large.sh): 2^20 points, the 16^4 test's fact one digit deeper"]
fn art_owen_16p_keeps_sz16_a_0_5_16_net_at_16_to_the_5() {
    let seq = sz::sz16(16, Width::W32).unwrap();
    let dims: Vec<usize> = (0..16).collect();
    let s = ArtOwen::new(ArtVariant::ArtOwen16P, 256, 1).unwrap();
    let p = scrambled(&seq, &s, &dims, 1 << 20);
    assert!(
        check_net(&p, CheckBase::new(16).unwrap(), 5, 0)
            .unwrap()
            .holds
    );
}

#[test]
fn base_16_scrambling_breaks_binary_pairs_that_binary_scrambling_keeps() {
    // The paper's claim: for N = 2^m that is not a power of 16, sz16's consecutive pairs are
    // binary (0,m,2)-nets; ArtOwen2 keeps them all, ArtOwen16P breaks at least one.
    let seq = sz::sz16(16, Width::W32).unwrap();
    let pairs: Vec<[usize; 2]> = (0..8).map(|i| [2 * i, 2 * i + 1]).collect();
    let ms: Vec<u32> = (1..=10).filter(|m| m % 4 != 0).collect();
    let binary = ArtOwen::new(ArtVariant::ArtOwen2, 256, 5).unwrap();
    let hex = ArtOwen::new(ArtVariant::ArtOwen16P, 256, 5).unwrap();
    let base2 = CheckBase::new(2).unwrap();
    let mut broken = 0;
    for pair in &pairs {
        for &m in &ms {
            assert_eq!(
                rank::t_value(&seq, pair, 1, m).unwrap(),
                0,
                "unscrambled pair {pair:?} m {m}"
            );
            let kept = scrambled(&seq, &binary, pair, 1 << m);
            assert_eq!(
                t_value(&kept, base2, m).unwrap(),
                0,
                "ArtOwen2 pair {pair:?} m {m}"
            );
            let p = scrambled(&seq, &hex, pair, 1 << m);
            broken += (t_value(&p, base2, m).unwrap() > 0) as u32;
        }
    }
    assert!(
        broken > 0,
        "ArtOwen16P should break some binary (0,m,2)-net"
    );
    eprintln!(
        "ArtOwen16P broke {broken} of {} (pair, m) binary nets",
        pairs.len() * ms.len()
    );
}
