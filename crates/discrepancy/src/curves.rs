//! Pairwise and joint discrepancy curves (the paper's Figure 2): for each N, the mean over
//! seeds of the joint d-dimensional D² and of the 2-D D² of chosen pairs.

use crate::compensated::compensated;
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
            let mut joint = 0.0;
            let mut pair_sums = vec![0.0; pairs.len()];
            for &seed in seeds {
                let words = set(seed, n);
                joint += compensated(
                    Points {
                        words: &words,
                        dims,
                        width,
                    },
                    kind,
                )
                .value;
                for (k, p) in pairs.iter().enumerate() {
                    let two: Vec<u64> = (0..n)
                        .flat_map(|i| [words[i * dims + p[0]], words[i * dims + p[1]]])
                        .collect();
                    pair_sums[k] += compensated(
                        Points {
                            words: &two,
                            dims: 2,
                            width,
                        },
                        kind,
                    )
                    .value;
                }
            }
            let r = seeds.len() as f64;
            CurvePoint {
                n,
                joint: joint / r,
                pairs: pair_sums.iter().map(|s| s / r).collect(),
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
