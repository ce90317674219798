//! How close to Owen, by the estimator's variance: for each scrambler, the variance over seeds
//! of the box-volume estimate μ̂ = (points in E)/N, divided by its exact value under Owen's
//! nested uniform scrambling (`gartowen::oracles::owen_variance`), at box levels 1, 2 and 3
//! (total digits of the scrambler's base over two coordinates: shapes (1,0), (1,1), (2,1)),
//! on a fixed pseudo-random set of 64 points in 2-D. A ratio of 1 is Owen's law; a ratio far
//! from 1 at some level is a deviation there (too small: the scramble keeps structure; too
//! large: it moves points together). Each ratio carries its standard error
//! (SE of the sample variance: √((m₄ − s⁴)/R + 2s⁴/(R(R − 1))) / V).

use gartowen::battery::owen_equivalence;
use gartowen::core::{PowerOfTwoBase, Registry, Width};
use gartowen::verify::registry_seeds;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

pub use gartowen::battery::owen_equivalence::{fixed_points, sample_variance, POINTS, SHAPES};

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
    /// The coordinate mean's variance / exact Owen variance, dimensions 0 and 1 (empty in
    /// reports written before it existed).
    #[serde(default)]
    pub mean_ratio: Vec<f64>,
    /// Standard error of each `mean_ratio`.
    #[serde(default)]
    pub mean_ratio_se: Vec<f64>,
    /// The diagonal-cell moments of orders 2 and 4 / Owen's exact values
    /// (`gartowen::battery::diagonal_cells`; empty in reports written before them).
    #[serde(default)]
    pub diagonal_ratio: Vec<f64>,
    /// Standard error of each `diagonal_ratio`.
    #[serde(default)]
    pub diagonal_ratio_se: Vec<f64>,
    /// Dimension pairs whose scrambles were translates of each other at the top digit, and
    /// the pairs read (base ≥ 8; `null` below).
    #[serde(default)]
    pub translate_pairs: Option<[u64; 2]>,
}

/// The variance rows of `requests` (with their bases), `seeds` replicates each, measured by
/// [`owen_equivalence::variance_ratios`] (the same measurement as `verify --equivalent-to
/// owen`); one scrambler per task, so the rows are the same for any thread count.
pub fn variance_ratios(
    registry: &Registry,
    requests: &[(String, u32)],
    seeds: u64,
) -> Vec<VarianceRow> {
    requests
        .par_iter()
        .map(|(request, base)| {
            let q = base.trailing_zeros();
            let default_base = PowerOfTwoBase::from_q(q).expect("a registry base");
            let builder = registry_seeds(registry, request, default_base);
            let r = owen_equivalence::variance_ratios(
                builder.as_ref(),
                default_base,
                Width::W32,
                seeds,
            )
            .expect("registry entries build");
            VarianceRow {
                scrambler: request.clone(),
                base: *base,
                seeds,
                levels: r.boxes.iter().map(|l| l.level).collect(),
                ratio: r.boxes.iter().map(|l| l.ratio).collect(),
                ratio_se: r.boxes.iter().map(|l| l.ratio_se).collect(),
                mean_ratio: r.means.iter().map(|m| m.ratio).collect(),
                mean_ratio_se: r.means.iter().map(|m| m.ratio_se).collect(),
                diagonal_ratio: r.diagonal.iter().map(|m| m.ratio).collect(),
                diagonal_ratio_se: r.diagonal.iter().map(|m| m.ratio_se).collect(),
                translate_pairs: r.translates.map(|d| [d.translate_pairs, d.pairs]),
            }
        })
        .collect()
}
