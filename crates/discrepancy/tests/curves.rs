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

/// The standard errors are those of the per-seed values (sample standard deviation / √seeds),
/// and the pair values are the exact 2-D D² (the O(N²) rational reference, rounded) of each
/// seed's pair: two paths for each number of the figure's bands.
#[test]
fn curve_standard_errors_are_those_of_the_per_seed_values() {
    use gartowen_discrepancy::curves::mean_and_se;
    use gartowen_discrepancy::fast2d::quadratic_reference;
    use gartowen_discrepancy::rational::to_f64;
    let dims = 3;
    let set = |seed: u64, n: usize| -> Vec<u64> {
        (0..n * dims)
            .map(|i| mix64(seed * 104_729 + i as u64) & 0xFFFF_FFFF)
            .collect()
    };
    let seeds = [3u64, 4, 5, 6, 7];
    let pairs = pair_list(dims, false);
    let c = curve(Kind::L2Star, dims, Width::W32, &[32], &seeds, &pairs, &set);
    for (k, p) in pairs.iter().enumerate() {
        let values: Vec<f64> = seeds
            .iter()
            .map(|&s| {
                let w = set(s, 32);
                let two: Vec<u64> = (0..32)
                    .flat_map(|i| [w[i * dims + p[0]], w[i * dims + p[1]]])
                    .collect();
                to_f64(&quadratic_reference(Points {
                    words: &two,
                    dims: 2,
                    width: Width::W32,
                }))
            })
            .collect();
        let mean = values.iter().sum::<f64>() / 5.0;
        let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / 4.0).sqrt();
        assert!((c.points[0].pairs[k] / mean - 1.0).abs() < 1e-14);
        assert!((c.points[0].pairs_se[k] / (sd / 5f64.sqrt()) - 1.0).abs() < 1e-12);
        assert!(c.points[0].pairs_se[k] > 0.0);
    }
    assert!(c.points[0].joint_se > 0.0);
    assert_eq!(mean_and_se(&[2.0]), (2.0, 0.0));
    let (m, se) = mean_and_se(&[1.0, 2.0, 3.0, 4.0]);
    assert_eq!(m, 2.5);
    assert!((se - (5.0f64 / 3.0 / 4.0).sqrt()).abs() < 1e-15);
}
