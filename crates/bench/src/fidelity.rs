//! How close to Owen, by the estimator's variance: for each scrambler, the variance over seeds
//! of the box-volume estimate μ̂ = (points in E)/N, divided by its exact value under Owen's
//! nested uniform scrambling (`gartowen::oracles::owen_variance`), at box levels 1, 2 and 3
//! (total digits of the scrambler's base over two coordinates: shapes (1,0), (1,1), (2,1)),
//! on a fixed pseudo-random set of 64 points in 2-D. A ratio of 1 is Owen's law; a ratio far
//! from 1 at some level is a deviation there (too small: the scramble keeps structure; too
//! large: it moves points together). Each ratio carries its standard error
//! (SE of the sample variance: √((m₄ − s⁴)/R + 2s⁴/(R(R − 1))) / V).

use gartowen::core::{BuildContext, PowerOfTwoBase, Registry, SplitMix64, Width};
use gartowen::oracles::owen_variance::owen_box_variance;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The box shapes, in digits of the scrambler's base, whose levels (sums) are 1, 2, 3.
pub const SHAPES: [[u32; 2]; 3] = [[1, 0], [1, 1], [2, 1]];

/// Points in the fixed set.
pub const POINTS: usize = 64;

/// One scrambler's variance ratios to the exact Owen variance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VarianceRow {
    /// Registry request.
    pub scrambler: String,
    /// Base.
    pub base: u32,
    /// Seeds (replicates).
    pub seeds: u64,
    /// Box level (digits) per entry of `ratio`.
    pub levels: Vec<u32>,
    /// Sample variance / exact Owen variance, per level (`None` when the exact variance is 0
    /// or fewer than 10 points are expected in the box over all seeds; JSON `null`).
    pub ratio: Vec<Option<f64>>,
    /// Standard error of each ratio.
    pub ratio_se: Vec<Option<f64>>,
}

/// The fixed 2-D point set (32-bit coordinates).
pub fn fixed_points() -> Vec<Vec<u64>> {
    let mut rng = SplitMix64::new(0x0077_656e); // "wen"
    (0..POINTS)
        .map(|_| vec![rng.next_u64() >> 32, rng.next_u64() >> 32])
        .collect()
}

/// (sample variance, its standard error) of `values`.
pub fn sample_variance(values: &[f64]) -> (f64, f64) {
    let r = values.len() as f64;
    let mean = values.iter().sum::<f64>() / r;
    let s2 = values.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / (r - 1.0);
    let m4 = values.iter().map(|e| (e - mean).powi(4)).sum::<f64>() / r;
    let se = ((m4 - s2 * s2).max(0.0) / r + 2.0 * s2 * s2 / (r * (r - 1.0))).sqrt();
    (s2, se)
}

/// The estimate of the all-zero-prefix box of `shape` (base 2^q) for scrambled `points`.
fn estimate(points: &[Vec<u64>], q: u32, shape: &[u32; 2], y: &[[u64; 2]]) -> f64 {
    let inside = y
        .iter()
        .filter(|p| (0..2).all(|j| shape[j] == 0 || p[j] >> (32 - shape[j] * q) == 0))
        .count();
    inside as f64 / points.len() as f64
}

/// The variance rows of `requests` (with their bases), `seeds` replicates each; one scrambler
/// per task, so the rows are the same for any thread count.
pub fn variance_ratios(
    registry: &Registry,
    requests: &[(String, u32)],
    seeds: u64,
) -> Vec<VarianceRow> {
    let points = fixed_points();
    requests
        .par_iter()
        .map(|(request, base)| {
            let q = base.trailing_zeros();
            let default_base = PowerOfTwoBase::from_q(q).expect("a registry base");
            let mut per_shape = vec![Vec::with_capacity(seeds as usize); SHAPES.len()];
            for seed in 0..seeds {
                let s = registry
                    .build_with(request, &BuildContext { seed, default_base })
                    .expect("registry entries build");
                let y: Vec<[u64; 2]> = points
                    .iter()
                    .map(|p| [0, 1].map(|j| s.scramble(p[j], Width::W32, j as u32)))
                    .collect();
                for (k, shape) in SHAPES.iter().enumerate() {
                    per_shape[k].push(estimate(&points, q, shape, &y));
                }
            }
            let (mut ratio, mut ratio_se) = (Vec::new(), Vec::new());
            for (k, shape) in SHAPES.iter().enumerate() {
                let v = owen_box_variance(&points, 32, q, shape)
                    .map(|v| gartowen::discrepancy::rational::to_f64(&v))
                    .unwrap_or(f64::NAN);
                let (s2, se) = sample_variance(&per_shape[k]);
                // Under 10 expected hits over all seeds the sample variance says nothing (a
                // ratio of 0 would read as "no variance"): no ratio.
                let levels = shape[0] + shape[1];
                let hits = seeds as f64 * POINTS as f64 * 2f64.powi(-((levels * q) as i32));
                let known = v > 0.0 && hits >= 10.0;
                ratio.push(known.then_some(s2 / v));
                ratio_se.push(known.then_some(se / v));
            }
            VarianceRow {
                scrambler: request.clone(),
                base: *base,
                seeds,
                levels: SHAPES.iter().map(|s| s[0] + s[1]).collect(),
                ratio,
                ratio_se,
            }
        })
        .collect()
}
