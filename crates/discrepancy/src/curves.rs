//! Pairwise and joint discrepancy curves (the paper's Figure 2): for each N, the mean over
//! seeds of the joint d-dimensional D² and of the 2-D D² of chosen pairs, with the standard
//! error of each mean (sample standard deviation over seeds / √seeds), so a figure can show
//! ±2 SE bands and noise does not read as a finding.
//!
//! 2-D L2-star values come from the exact O(N log N) path ([`crate::fast2d`], correctly
//! rounded), every other value from the compensated sums.

use crate::compensated::compensated;
use crate::fast2d::fast;
use crate::{Kind, Points};
use gartowen_core::Width;
use serde::Serialize;

/// One row of a curve: sample size and means over seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurvePoint {
    /// Number of points.
    pub n: usize,
    /// Mean joint D² over all dimensions.
    pub joint: f64,
    /// Mean 2-D D² per pair, in the order of `pairs`.
    pub pairs: Vec<f64>,
    /// Standard error of `joint` (0 with one seed).
    pub joint_se: f64,
    /// Standard error of each pair's mean.
    pub pairs_se: Vec<f64>,
}

/// Mean and standard error of the mean (sample standard deviation / √n; 0 for n < 2).
pub fn mean_and_se(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    if values.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let mean = values.iter().sum::<f64>() / n;
    if values.len() < 2 {
        return (mean, 0.0);
    }
    let var = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

fn two_d(kind: Kind, points: Points) -> f64 {
    match kind {
        Kind::L2Star => fast(points).map(|d| d.value),
        _ => None,
    }
    .unwrap_or_else(|| compensated(points, kind).value)
}

/// A curve with its pairs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Curve {
    /// Kind of discrepancy.
    pub kind: Kind,
    /// The pairs of dimensions.
    pub pairs: Vec<[usize; 2]>,
    /// Rows by increasing N.
    pub points: Vec<CurvePoint>,
}

/// Pairs (0, j) for every j, or all pairs.
pub fn pair_list(dims: usize, all: bool) -> Vec<[usize; 2]> {
    if all {
        (0..dims)
            .flat_map(|i| (i + 1..dims).map(move |j| [i, j]))
            .collect()
    } else {
        (1..dims).map(|j| [0, j]).collect()
    }
}

/// The curve for point sets produced by `set(seed, n)` (row-major words), averaged over seeds.
pub fn curve(
    kind: Kind,
    dims: usize,
    width: Width,
    sizes: &[usize],
    seeds: &[u64],
    pairs: &[[usize; 2]],
    set: &dyn Fn(u64, usize) -> Vec<u64>,
) -> Curve {
    let points = sizes
        .iter()
        .map(|&n| {
            let mut joint = Vec::with_capacity(seeds.len());
            let mut per_pair = vec![Vec::with_capacity(seeds.len()); pairs.len()];
            for &seed in seeds {
                let words = set(seed, n);
                joint.push(
                    compensated(
                        Points {
                            words: &words,
                            dims,
                            width,
                        },
                        kind,
                    )
                    .value,
                );
                for (k, p) in pairs.iter().enumerate() {
                    let two: Vec<u64> = (0..n)
                        .flat_map(|i| [words[i * dims + p[0]], words[i * dims + p[1]]])
                        .collect();
                    per_pair[k].push(two_d(
                        kind,
                        Points {
                            words: &two,
                            dims: 2,
                            width,
                        },
                    ));
                }
            }
            let (joint, joint_se) = mean_and_se(&joint);
            let (pairs, pairs_se) = per_pair.iter().map(|v| mean_and_se(v)).unzip();
            CurvePoint {
                n,
                joint,
                pairs,
                joint_se,
                pairs_se,
            }
        })
        .collect();
    Curve {
        kind,
        pairs: pairs.to_vec(),
        points,
    }
}

impl Curve {
    /// CSV: `n,joint,pair_i_j,...`.
    pub fn to_csv(&self) -> String {
        let mut out = String::from("n,joint");
        for p in &self.pairs {
            out += &format!(",pair_{}_{}", p[0], p[1]);
        }
        out.push('\n');
        for row in &self.points {
            out += &format!("{},{:e}", row.n, row.joint);
            for v in &row.pairs {
                out += &format!(",{v:e}");
            }
            out.push('\n');
        }
        out
    }
}
