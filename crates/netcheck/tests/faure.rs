//! The Faure sequences over GF(2^q), q = 1..8, and the (0,m,b+1)-nets built from them: t = 0
//! by the rank path, by the counting path and by brute force, and a broken variant (two
//! dimensions with the same field element) is rejected by all three.

use gartowen_core::{PowerOfTwoBase, Width};
use gartowen_netcheck::counting::t_value;
use gartowen_netcheck::{rank, CheckBase, PointSet};
use gartowen_oracles::box_counting;
use gartowen_seq::faure::{faure, faure_columns, faure_net};
use gartowen_seq::{binary_field::BinaryField, DigitalSequence};

fn base(q: u32) -> PowerOfTwoBase {
    PowerOfTwoBase::from_q(q).unwrap()
}

fn points(seq: &DigitalSequence, dims: &[usize], n: u64) -> PointSet {
    PointSet::from_sequence(seq, dims, n, |x, _| x).unwrap()
}

/// The counting path's t-value of the first b^m points.
fn counted(seq: &DigitalSequence, dims: &[usize], q: u32, m: u32) -> u32 {
    let p = points(seq, dims, 1 << (q * m));
    t_value(&p, CheckBase::new(1 << q).unwrap(), m).unwrap()
}

/// The brute-force oracle's t-value of the first b^m points.
fn brute(seq: &DigitalSequence, dims: &[usize], q: u32, m: u32) -> u32 {
    let rows: Vec<Vec<u64>> = (0..1u64 << (q * m))
        .map(|i| dims.iter().map(|&j| seq.point(i, j)).collect())
        .collect();
    box_counting::t_value(&rows, seq.width().bits(), 1 << q, m)
}

#[test]
fn every_base_gives_a_zero_s_sequence_by_the_rank_path() {
    for q in 1..=8u32 {
        let b = 1usize << q;
        // Every dimension where the shapes stay few; for b ≥ 32 all b dimensions at m ≤ 2 and
        // eight spread ones up to 32-bit indices.
        let all: Vec<usize> = (0..b).collect();
        let spread: Vec<usize> = (0..8).map(|k| k * (b - 1) / 7).collect();
        let (wide_m, deep): (u32, &[usize]) = if b <= 16 {
            (if b == 16 { 5 } else { 32 / q }, &all)
        } else {
            (2, &spread)
        };
        let seq = faure(base(q), b, Width::W32).unwrap();
        for m in 1..=wide_m.min(32 / q) {
            assert_eq!(rank::t_value(&seq, deep, q, m).unwrap(), 0, "b {b} m {m}");
        }
        if b > 16 {
            for m in 1..=2 {
                assert_eq!(
                    rank::t_value(&seq, &all, q, m).unwrap(),
                    0,
                    "b {b} m {m}, all"
                );
            }
            for m in 3..=32 / q {
                assert_eq!(
                    rank::t_value(&seq, &spread, q, m).unwrap(),
                    0,
                    "b {b} m {m}"
                );
            }
        }
        // Not more than b dimensions.
        assert!(faure(base(q), b + 1, Width::W32).is_err());
    }
}

#[test]
fn counting_and_brute_force_agree_with_the_rank_path_at_small_sizes() {
    for q in 1..=8u32 {
        let b = 1usize << q;
        let dims: Vec<usize> = [0, 1, b / 2, b - 1]
            .into_iter()
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        for width in [Width::W32, Width::new(q * (12 / q) + 2).unwrap()] {
            let seq = faure(base(q), b, width).unwrap();
            for m in 1..=(12 / q).max(1) {
                let r = rank::t_value(&seq, &dims, q, m).unwrap();
                assert_eq!(r, 0, "b {b} m {m} W {}", width.bits());
                assert_eq!(counted(&seq, &dims, q, m), r, "b {b} m {m}");
                if q * m <= 10 {
                    assert_eq!(
                        brute(&seq, &dims[..dims.len().min(3)], q, m),
                        0,
                        "b {b} m {m}"
                    );
                }
            }
        }
    }
}

#[test]
fn the_reversal_adds_a_dimension_b_plus_1_nets() {
    for q in 1..=8u32 {
        let b = 1usize << q;
        for m in 1..=(16 / q).min(4) {
            let net = faure_net(base(q), m, b + 1, Width::W32).unwrap();
            assert_eq!(net.dims(), b + 1);
            let dims: Vec<usize> = (0..=b).collect();
            if q <= 4 || m <= 2 {
                assert_eq!(rank::t_value(&net, &dims, q, m).unwrap(), 0, "b {b} m {m}");
            }
            let few: Vec<usize> = vec![0, 1, b];
            assert_eq!(counted(&net, &few, q, m), 0, "b {b} m {m}");
            if q * m <= 10 {
                assert_eq!(brute(&net, &few, q, m), 0, "b {b} m {m}");
            }
            // The reversal coordinate is i / b^m exactly.
            for i in [0u64, 1, (1 << (q * m)) - 1] {
                assert_eq!(net.point(i, 0), i << (32 - q * m), "b {b} m {m} i {i}");
            }
        }
    }
    // Too many index bits for the word.
    assert!(faure_net(base(8), 5, 3, Width::W32).is_err());
}

#[test]
fn two_dimensions_with_one_field_element_are_not_a_net_by_any_path() {
    for q in [2u32, 3, 5, 8] {
        let f = BinaryField::new(q).unwrap();
        let cols = vec![
            faure_columns(f, 3, Width::W32, 32),
            faure_columns(f, 3, Width::W32, 32),
        ];
        let seq = DigitalSequence::from_columns("twins", Width::W32, base(q), &cols).unwrap();
        let m = (8 / q).max(2);
        let r = rank::t_value(&seq, &[0, 1], q, m).unwrap();
        assert!(r > 0, "q {q}");
        assert_eq!(counted(&seq, &[0, 1], q, m), r, "q {q}");
        if q * m <= 10 {
            assert_eq!(brute(&seq, &[0, 1], q, m), r, "q {q}");
        }
    }
}
