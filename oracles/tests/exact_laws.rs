//! Owen's lemma, exactly: every assignment of node permutations on depth-2 trees in bases 2
//! and 4, as integer ratios. Uniform satisfies every part; for b = 4, Xor and CyclicShift break
//! the uniformity of the first differing digit over distinct pairs, while Affine does not
//! (AGL(2,2) = S_4).

use gartowen_oracles::exact_laws::{check_lemma, pair_law, parameter_space, LemmaParts};
use gartowen_owen::OwenVariant;

/// Pairs of depth-2 inputs sharing exactly k digits, for k = 0 and 1.
fn pairs(b: u32) -> Vec<(Vec<u32>, Vec<u32>)> {
    vec![
        (vec![0, 0], vec![1, 0]),
        (vec![0, 1], vec![b - 1, 0]),
        (vec![1, 0], vec![1, 1]),
        (vec![0, b - 1], vec![0, 0]),
    ]
}

fn lemma(variant: OwenVariant, q: u32) -> Vec<LemmaParts> {
    pairs(1 << q)
        .into_iter()
        .map(|(x, y)| check_lemma(&pair_law(variant, q, &x, &y)))
        .collect()
}

#[test]
fn parameter_space_sizes() {
    assert_eq!(parameter_space(OwenVariant::Uniform, 2).len(), 24);
    assert_eq!(parameter_space(OwenVariant::CyclicShift, 2).len(), 4);
    assert_eq!(parameter_space(OwenVariant::Xor, 2).len(), 4);
    assert_eq!(parameter_space(OwenVariant::Affine, 2).len(), 24);
    // AGL(2,2) = S_4: the 24 affine maps are exactly the 24 permutations.
    let mut affine: Vec<Vec<u8>> = parameter_space(OwenVariant::Affine, 2)
        .iter()
        .map(|p| p.as_slice().to_vec())
        .collect();
    affine.sort();
    affine.dedup();
    assert_eq!(affine.len(), 24);
}

#[test]
fn uniform_satisfies_owens_lemma_in_bases_2_and_4() {
    for q in [1, 2] {
        for parts in lemma(OwenVariant::Uniform, q) {
            assert!(parts.all(), "q={q}: {parts:?}");
        }
    }
}

#[test]
fn in_base_2_every_variant_is_uniform() {
    // S_2 has two elements; shift, xor and affine maps all reach both with equal weight.
    for v in OwenVariant::ALL {
        for parts in lemma(v, 1) {
            assert!(parts.all(), "{v:?}: {parts:?}");
        }
    }
}

#[test]
fn in_base_4_xor_and_cyclic_shift_break_the_distinct_pair_law_and_affine_does_not() {
    for v in [OwenVariant::Xor, OwenVariant::CyclicShift] {
        for parts in lemma(v, 2) {
            assert!(
                parts.marginal_uniform && parts.shared_digits_equal,
                "{v:?}: {parts:?}"
            );
            assert!(
                !parts.split_digit_uniform_on_distinct_pairs,
                "{v:?} must fail: {parts:?}"
            );
        }
    }
    for parts in lemma(OwenVariant::Affine, 2) {
        assert!(parts.all(), "Affine in base 4: {parts:?}");
    }
}

#[test]
fn the_exact_law_has_the_expected_mass_on_one_outcome() {
    // Independent arithmetic: for Uniform in base 4 with x, x' differing in digit 0,
    // P(σ(x) = (0,0), σ(x') = (1,0)) = 1/(4·3) · 1/4 · 1/4.
    let law = pair_law(OwenVariant::Uniform, 2, &[0, 0], &[1, 0]);
    let c = law.counts[&(vec![0, 0], vec![1, 0])];
    assert_eq!(law.total, 24u64.pow(3));
    assert_eq!(c * 4 * 3 * 4 * 4, law.total);
}
