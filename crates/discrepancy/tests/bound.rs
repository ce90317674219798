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

/// Two points whose coordinates are all 1 − 2^-50 and ½ (64-bit words, 50 significant bits):
/// L2-star's factors reach 2^-50, so d factors reach 2^-50d.
fn near_one(d: usize) -> Vec<u64> {
    let mut w = vec![((1u64 << 50) - 1) << 14; d];
    w.extend(vec![1u64 << 63; d]);
    w
}

#[test]
fn l2star_products_near_underflow_void_the_bound_and_compensated_computes_exactly() {
    for (d, bounded) in [(17, true), (18, false)] {
        let words = near_one(d);
        let p = Points {
            words: &words,
            dims: d,
            width: Width::W64,
        };
        let c = compensated(p, Kind::L2Star);
        assert_eq!(
            c.rel_error_bound.is_some(),
            bounded,
            "d = {d}: 50·d bits below 1"
        );
        let truth = exact_rational(p, Kind::L2Star);
        if let Some(b) = c.rel_error_bound {
            assert!(rel(c.value, &truth) <= BigRational::from_float(b).unwrap());
        }
        let chosen = compute(p, Kind::L2Star, MethodChoice::Compensated).unwrap();
        let expected = if bounded {
            Method::Compensated
        } else {
            Method::Exact
        };
        assert_eq!(chosen.method, expected, "d = {d}");
        let b = chosen.rel_error_bound.expect("a bound either way");
        assert!(rel(chosen.value, &truth) <= BigRational::from_float(b).unwrap());
    }
}

#[test]
fn gl2_sums_near_overflow_void_the_bound() {
    // GL2's pair factor reaches 2, so two points in d dimensions sum to about 2^(d + 2).
    for (d, bounded) in [(990, true), (1000, false)] {
        let words: Vec<u64> = (0..2 * d)
            .map(|i| ((i as u64 * 7919) % 1024) << 22)
            .collect();
        let p = Points {
            words: &words,
            dims: d,
            width: Width::W32,
        };
        let c = compensated(p, Kind::GeneralizedL2);
        assert_eq!(c.rel_error_bound.is_some(), bounded, "d = {d}");
        let chosen = compute(p, Kind::GeneralizedL2, MethodChoice::Compensated).unwrap();
        assert_eq!(chosen.method == Method::Exact, !bounded);
        let truth = exact_rational(p, Kind::GeneralizedL2);
        let b = chosen.rel_error_bound.expect("a bound either way");
        assert!(rel(chosen.value, &truth) <= BigRational::from_float(b).unwrap());
    }
}

#[test]
fn the_hypothesis_limits_are_exact_at_their_edges() {
    // Overflow: two points in d dimensions of GL2 count 2·2 + d + 4 bits; 1000 is allowed.
    for (d, bounded) in [(992, true), (993, false)] {
        let words: Vec<u64> = (0..2 * d).map(|i| ((i as u64 * 31) % 1024) << 22).collect();
        let p = Points {
            words: &words,
            dims: d,
            width: Width::W32,
        };
        assert_eq!(
            compensated(p, Kind::GeneralizedL2)
                .rel_error_bound
                .is_some(),
            bounded,
            "d = {d}"
        );
    }
    // Underflow: every coordinate 1 − 2^-40 (64-bit words), so each L2-star factor is at least
    // 2^-40 and d factors 2^-40d; 880 bits are allowed: d = 22 is the last bounded dimension.
    for (d, bounded) in [(22, true), (23, false)] {
        let words = vec![u64::MAX - (1 << 24) + 1; 2 * d];
        let p = Points {
            words: &words,
            dims: d,
            width: Width::W64,
        };
        let c = compensated(p, Kind::L2Star);
        assert_eq!(c.rel_error_bound.is_some(), bounded, "d = {d}");
        if let Some(b) = c.rel_error_bound {
            let truth = exact_rational(p, Kind::L2Star);
            assert!(rel(c.value, &truth) <= BigRational::from_float(b).unwrap());
        }
        // The same at 32 bits: 1 − 2^-8 in every coordinate, 110 factors of 2^-8 = 880 bits.
        let d32 = d * 5;
        let words = vec![u32::MAX as u64 - (1 << 24) + 1; 2 * d32];
        let p = Points {
            words: &words,
            dims: d32,
            width: Width::W32,
        };
        assert_eq!(
            compensated(p, Kind::L2Star).rel_error_bound.is_some(),
            bounded,
            "d = {d32}"
        );
    }
}
