//! `gartowen report`: runs the RMSE harness, the speed measurement, the randomization-quality
//! battery and the discrepancy curves, and writes report.json, report.md and the PNG figures.
//!
//! Every error figure is deterministic (fixed seeds, replicate-ordered reduction). Speeds are
//! stored both as ns per coordinate and as a ratio to the `lk-hash` peer measured in the same
//! run; baselines compare only the ratios.

mod build;
mod compare;
mod markdown;
mod plots;
mod staging;

pub use crate::staged::{staging_dir, write_staged};
pub use build::{build_report, measure_quality, slope_rows};
pub use compare::{comparable_rows, compare, read_baseline, Regression};
pub use markdown::markdown;
pub use plots::write_figures;
pub use staging::write_report;

use crate::curves::sz16_words;
pub use crate::curves::{curve_seeds, discrepancy_curves, DiscrepancyCurve};
use crate::figures::{
    loglog_lines, loglog_lines_banded, loglog_points, pair_matrix, panel_grid, FigureError, Panel,
    Series,
};
use crate::harness::{methods_for, run_method, HarnessConfig, HarnessError, Method, MethodResult};
use crate::integrands::{standard_families, Family, Smoothness};
use crate::spectrum::mean_pair_spectra;
pub use crate::speed::{measure_speed, SpeedRow};
use gartowen::core::Registry;
use gartowen::discrepancy::expected::expected_l2star_random;
use gartowen::seq::SequenceKind;
use gartowen::verify::{verify, Level, Verdict};
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::time::Instant;

/// Seeds whose periodograms Figure 1 averages.
pub const FIGURE1_SEEDS: u64 = 16;

/// The report's JSON schema name and version.
pub const REPORT_SCHEMA: &str = "gartowen-report";
/// Version of [`REPORT_SCHEMA`].
pub const REPORT_VERSION: u32 = 1;

/// Randomization quality of one scrambler against uniform nested scrambling.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityRow {
    /// Registry name.
    pub scrambler: String,
    /// Base.
    pub base: u32,
    /// Whether it claims nested uniformity.
    pub claims_nested_uniform: bool,
    /// Nestedness verdict from the inspector.
    pub nested: Verdict,
    /// Node-law verdict (measured only for non-claimants).
    pub node_law: Verdict,
    /// χ² of the node law, and its detail (dof, total variation, affine fraction).
    pub chi_square: Option<f64>,
    /// The node-law detail in words.
    pub detail: String,
    /// What it claims (`owen`, `marginal:symmetric`, …).
    #[serde(default)]
    pub claim: String,
    /// How close to Owen, per law family: one character per depth 0, 1, … (`.` no deviation
    /// detected, `x` deviation, `-` not tested), from `verify --level quick`.
    #[serde(default)]
    pub profile: Vec<(String, String)>,
}

/// One slope against its expectation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SlopeRow {
    /// Method label.
    pub method: String,
    /// Integrand.
    pub integrand: String,
    /// Measured slope.
    pub slope: f64,
    /// The rate theory predicts for Owen-scrambled nets (−1.5 smooth, −0.75 discontinuous 2-D).
    pub expected: f64,
    /// slope ≤ expected + tolerance.
    pub meets: bool,
}

/// Noise thresholds the baseline comparison uses (stated in the report).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Thresholds {
    /// A slope regresses when it rises by more than this.
    pub slope: f64,
    /// An RMSE at the largest N regresses when it grows by more than this factor:
    /// 1 + 3/√(2R), three standard errors of an RMSE estimated from R replicates.
    pub rmse_factor: f64,
    /// A speed ratio regresses when it grows by more than this factor, widened by
    /// `speed_z` standard errors of the two runs' medians ([`crate::speed`]).
    pub speed_factor: f64,
    /// Standard errors beyond `speed_factor` a speed change must reach (one-sided; 3 gives
    /// a false-alarm rate of at most 0.135% per row under normal log-noise).
    #[serde(default = "default_speed_z")]
    pub speed_z: f64,
}

fn default_speed_z() -> f64 {
    3.0
}

/// Everything the report shows.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// [`REPORT_SCHEMA`].
    pub schema: String,
    /// [`REPORT_VERSION`].
    pub schema_version: u32,
    /// Tool version.
    pub tool_version: String,
    /// Quick mode.
    pub quick: bool,
    /// Harness settings.
    pub harness: HarnessConfig,
    /// Integrand names in curve order.
    pub integrands: Vec<String>,
    /// RMSE curves per method.
    pub methods: Vec<MethodResult>,
    /// Slopes of every scrambled method on the 2-D integrands, against the expected rates.
    pub slopes: Vec<SlopeRow>,
    /// Speeds.
    pub speed: Vec<SpeedRow>,
    /// Randomization quality.
    pub quality: Vec<QualityRow>,
    /// Figure 2 data.
    pub discrepancy: Vec<DiscrepancyCurve>,
    /// Figure 2b's baseline: Sobol + exact binary Owen (absent in older reports).
    #[serde(default)]
    pub sobol_owen: Option<DiscrepancyCurve>,
    /// Estimator variance against the exact Owen variance, per scrambler (empty in reports
    /// written before it existed).
    #[serde(default)]
    pub owen_variance: Vec<crate::fidelity::VarianceRow>,
    /// The paper's memory/speed trade-off, per ART variant (empty in older reports).
    #[serde(default)]
    pub tradeoff: Vec<crate::tradeoff::TradeoffRow>,
    /// Equivalence verdicts of every ART variant against Owen in its base (empty in older
    /// reports).
    #[serde(default)]
    pub equivalence: Vec<crate::equivalence::EquivalenceRow>,
    /// The scene benchmark (absent in older reports).
    #[serde(default)]
    pub scene: Option<crate::scene::report::SceneReport>,
    /// Baseline thresholds.
    pub thresholds: Thresholds,
    /// Worker threads used.
    pub threads: usize,
    /// Wall seconds for the whole report.
    pub seconds: f64,
}

impl Report {
    /// The slopes of scrambled methods (not the unscrambled or random references) that miss
    /// the predicted rate.
    pub fn missed_slopes(&self) -> Vec<&SlopeRow> {
        self.slopes
            .iter()
            .filter(|s| !s.meets && !s.method.ends_with("+none") && s.method != "random")
            .collect()
    }

    /// The scrambled methods with at least one missed slope, each once, in report order.
    pub fn methods_missing_slopes(&self) -> Vec<String> {
        let mut names: Vec<String> = Vec::new();
        for s in self.missed_slopes() {
            if !names.contains(&s.method) {
                names.push(s.method.clone());
            }
        }
        names
    }
}

/// Why a report could not be made.
#[derive(Debug)]
pub enum ReportError {
    /// The harness refused a method or setting.
    Harness(HarnessError),
    /// A figure failed.
    Figure(FigureError),
    /// Writing an output failed.
    Io(String),
    /// The baseline is not a report this build reads.
    Baseline(String),
}

impl std::fmt::Display for ReportError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReportError::Harness(e) => write!(f, "harness: {e}"),
            ReportError::Figure(e) => write!(f, "{e}"),
            ReportError::Io(e) => write!(f, "{e}"),
            ReportError::Baseline(e) => write!(f, "baseline: {e}"),
        }
    }
}

impl std::error::Error for ReportError {}

/// Report settings.
#[derive(Debug, Clone)]
pub struct ReportConfig {
    /// Quick mode: smaller N, fewer replicates and methods (under a minute on 2 cores).
    pub quick: bool,
    /// Master seed.
    pub seed: u64,
    /// The equivalence margin δ on ratios (0 < δ < 1; default
    /// [`gartowen::battery::equivalence::DEFAULT_MARGIN`]).
    pub margin: f64,
}
