//! Every kind's closed form (`exact`, Warnock's and Hickernell's formulas with their
//! constants) equals the integral of the kind's definition, computed cell by cell in exact
//! rationals without any closed form (`gartowen_oracles::discrepancy_integral`).

use crate::exactness::reference_kind;
use gartowen_core::{mix64, Width};
use gartowen_discrepancy::{exact::exact, Kind, Points};
use gartowen_oracles::discrepancy_integral::{
    integrate_discrepancy, IntegrationError, MAX_PIECE_PRODUCTS,
};
use gartowen_oracles::exact_discrepancy::ReferenceKind;
use num_bigint::BigInt;
use num_rational::BigRational;

fn closed_form(words: &[u64], d: usize, w: u32, kind: Kind) -> BigRational {
    let p = Points {
        words,
        dims: d,
        width: Width::new(w).unwrap(),
    };
    exact(p, kind).exact.unwrap()
}

fn integral(words: &[u64], d: usize, w: u32, kind: Kind) -> BigRational {
    let rows: Vec<Vec<u64>> = words.chunks(d).map(|c| c.to_vec()).collect();
    integrate_discrepancy(&rows, w, reference_kind(kind)).unwrap()
}

#[test]
fn every_closed_form_is_the_integral_of_its_definition() {
    let mut seed = 0u64;
    let mut compared = 0;
    for (w, dims) in [(1u32, 3usize), (2, 3), (3, 2), (4, 2), (5, 1)] {
        let mask = (1u64 << w) - 1;
        for d in 1..=dims {
            for n in [1usize, 2, 3, 5] {
                seed += 1;
                let mut words: Vec<u64> = (0..n * d)
                    .map(|i| mix64(seed << 8 | i as u64) & mask)
                    .collect();
                // The edges 0 and 1 − 2^-W, the centre 1/2, and a repeated point.
                words[0] = 0;
                if n * d > 1 {
                    words[1] = mask;
                }
                if n * d > 2 {
                    words[2] = 1 << (w - 1);
                }
                if n >= 3 {
                    let first: Vec<u64> = words[..d].to_vec();
                    words[2 * d..3 * d].copy_from_slice(&first);
                }
                for kind in Kind::ALL {
                    // Wrap-around boxes have (2^W)² pieces per coordinate: keep them small.
                    if kind == Kind::WrapAround && (w as usize) * d > 8 {
                        continue;
                    }
                    assert_eq!(
                        integral(&words, d, w, kind),
                        closed_form(&words, d, w, kind),
                        "{kind:?} W={w} d={d} n={n} words {words:x?}"
                    );
                    compared += 1;
                }
            }
        }
    }
    assert_eq!(compared, 176, "every kind on each of the 44 sets");
}

#[test]
fn hand_computed_integrals() {
    // {1/4, 3/4}: ∫₀¹ (A(x)/2 − x)² dx = 1/48 (three pieces); the centred boxes give the same;
    // wrap-around boxes give 1/24.
    let r = |n: i64, d: i64| BigRational::new(BigInt::from(n), BigInt::from(d));
    let words = [1u64, 3];
    assert_eq!(integral(&words, 1, 2, Kind::L2Star), r(1, 48));
    assert_eq!(integral(&words, 1, 2, Kind::Centered), r(1, 48));
    assert_eq!(integral(&words, 1, 2, Kind::WrapAround), r(1, 24));
    // One point at 0 in the square: L2-star ∫∫ (1 − xy)² = 1 − 1/2 + 1/9 = 11/18; GL2 adds the
    // two one-dimensional projections, 1/3 each.
    assert_eq!(integral(&[0, 0], 2, 3, Kind::L2Star), r(11, 18));
    assert_eq!(
        integral(&[0, 0], 2, 3, Kind::GeneralizedL2),
        r(11, 18) + r(2, 3)
    );
}

#[test]
fn the_kinds_differ_so_each_comparison_tests_its_own_formula() {
    let words = [1u64, 6, 3, 2, 7, 5];
    let values: Vec<BigRational> = Kind::ALL
        .iter()
        .map(|&k| integral(&words, 2, 3, k))
        .collect();
    for i in 0..values.len() {
        for j in 0..i {
            assert_ne!(
                values[i],
                values[j],
                "{:?} {:?}",
                Kind::ALL[i],
                Kind::ALL[j]
            );
        }
    }
}

#[test]
fn bad_input_is_refused_with_the_bad_value() {
    let k = ReferenceKind::L2Star;
    assert_eq!(
        integrate_discrepancy(&[], 4, k),
        Err(IntegrationError::Empty)
    );
    assert_eq!(
        integrate_discrepancy(&[vec![1, 2], vec![3]], 4, k),
        Err(IntegrationError::Ragged {
            point: 1,
            dims: 1,
            expected: 2
        })
    );
    assert_eq!(
        integrate_discrepancy(&[vec![16]], 4, k),
        Err(IntegrationError::BadWord {
            word: 16,
            width_bits: 4
        })
    );
    assert_eq!(
        integrate_discrepancy(&[vec![0]], 17, k),
        Err(IntegrationError::BadWord {
            word: 0,
            width_bits: 17
        })
    );
    let wide = vec![vec![0u64; 3]];
    match integrate_discrepancy(&wide, 8, ReferenceKind::WrapAround) {
        Err(IntegrationError::TooLarge { products }) => assert!(products > MAX_PIECE_PRODUCTS),
        other => panic!("{other:?}"),
    }
}
