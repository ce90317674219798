//! The run-time hypotheses of the compensated method's proved bound (`proofs/DdSum.v`): where
//! they hold the bound is given and holds against the exact rational; where they fail
//! (underflow, overflow) no bound is claimed and `--method compensated` computes exactly.

use gartowen_core::Width;
use gartowen_discrepancy::{
    choice::{compute, MethodChoice},
    compensated::compensated,
    exact::exact_rational,
    Kind, Method, Points,
};
use num_rational::BigRational;
use num_traits::Signed;

fn rel(value: f64, truth: &BigRational) -> BigRational {
    ((BigRational::from_float(value).unwrap() - truth) / truth).abs()
}

/// Asserts that compensated claims a bound exactly when `bounded`, that the method choice
/// `compensated` then keeps it and otherwise falls back to exact, and that the bound returned
/// either way holds against the exact rational.
fn assert_case(words: &[u64], dims: usize, width: Width, kind: Kind, bounded: bool) {
    let p = Points { words, dims, width };
    let c = compensated(p, kind);
    assert_eq!(c.rel_error_bound.is_some(), bounded, "{kind:?}, d = {dims}");
    let chosen = compute(p, kind, MethodChoice::Compensated).unwrap();
    let expected = if bounded {
        Method::Compensated
    } else {
        Method::Exact
    };
    assert_eq!(chosen.method, expected, "{kind:?}, d = {dims}");
    let truth = exact_rational(p, kind);
    let b = chosen.rel_error_bound.expect("a bound either way");
    assert!(rel(chosen.value, &truth) <= BigRational::from_float(b).unwrap());
}

#[test]
fn l2star_products_near_underflow_void_the_bound_and_compensated_computes_exactly() {
    // Two points: every coordinate 1 − 2^-50 and ½ (64-bit words, 50 significant bits), so
    // L2-star's factors reach 2^-50 and d of them 2^-50d; 880 bits are allowed.
    for (d, bounded) in [(17, true), (18, false)] {
        let mut words = vec![((1u64 << 50) - 1) << 14; d];
        words.extend(vec![1u64 << 63; d]);
        assert_case(&words, d, Width::W64, Kind::L2Star, bounded);
    }
}

#[test]
fn gl2_sums_near_overflow_void_the_bound() {
    // GL2's pair factor reaches 2, so N points in d dimensions sum to about N²·2^d; the check
    // counts 2·(bits of N) + d + 4 and allows 1000: with 2 points (2 bits) 992 is the last
    // bounded dimension, with 16 points (5 bits) 986.
    for (n, d, bounded) in [
        (2, 990, true),
        (2, 992, true),
        (2, 993, false),
        (2, 1000, false),
        (16, 986, true),
        (16, 987, false),
    ] {
        let words: Vec<u64> = (0..n * d)
            .map(|i| ((i as u64 * 7919) % 1024) << 22)
            .collect();
        assert_case(&words, d, Width::W32, Kind::GeneralizedL2, bounded);
    }
}

#[test]
fn the_underflow_limit_is_exact_at_its_edge_at_both_widths() {
    // Every coordinate 1 − 2^-40 (64-bit words): d factors of 2^-40, d = 22 the last bounded.
    // At 32 bits, 1 − 2^-8: 110 factors of 2^-8 = 880 bits.
    for (d, bounded) in [(22, true), (23, false)] {
        let words = vec![u64::MAX - (1 << 24) + 1; 2 * d];
        assert_case(&words, d, Width::W64, Kind::L2Star, bounded);
        let d32 = d * 5;
        let words = vec![u32::MAX as u64 - (1 << 24) + 1; 2 * d32];
        assert_case(&words, d32, Width::W32, Kind::L2Star, bounded);
    }
}
