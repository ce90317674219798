//! Pairwise and joint curves: shape, CSV layout, and that the means are means of the values.

use gartowen_core::{mix64, Width};
use gartowen_discrepancy::compensated::compensated;
use gartowen_discrepancy::curves::{curve, pair_list};
use gartowen_discrepancy::{Kind, Points};

#[test]
fn curve_rows_are_means_over_seeds() {
    let dims = 3;
    let set = |seed: u64, n: usize| -> Vec<u64> {
        (0..n * dims)
            .map(|i| mix64(seed * 7919 + i as u64) & 0xFFFF_FFFF)
            .collect()
    };
    let pairs = pair_list(dims, false);
    assert_eq!(pairs, vec![[0, 1], [0, 2]]);
    assert_eq!(pair_list(4, true).len(), 6);
    let c = curve(
        Kind::L2Star,
        dims,
        Width::W32,
        &[16, 24],
        &[1, 2],
        &pairs,
        &set,
    );
    assert_eq!(c.points.len(), 2);
    let joint = |seed, n| {
        compensated(
            Points {
                words: &set(seed, n),
                dims,
                width: Width::W32,
            },
            Kind::L2Star,
        )
        .value
    };
    assert_eq!(c.points[1].joint, (joint(1, 24) + joint(2, 24)) / 2.0);
    let csv = c.to_csv();
    assert_eq!(csv.lines().next().unwrap(), "n,joint,pair_0_1,pair_0_2");
    assert_eq!(csv.lines().count(), 3);
    assert!(csv.lines().nth(2).unwrap().starts_with("24,"));
}
