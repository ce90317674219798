//! `gartowen report`: runs the RMSE harness, the speed measurement, the randomization-quality
//! battery and the discrepancy curves, and writes report.json, report.md and the PNG figures.
//!
//! Every error figure is deterministic (fixed seeds, replicate-ordered reduction). Speeds are
//! stored both as ns per coordinate and as a ratio to the `lk-hash` peer measured in the same
//! run; baselines compare only the ratios.

use crate::curves::sz16_words;
pub use crate::curves::{curve_seeds, discrepancy_curves, DiscrepancyCurve};
use crate::figures::{
    loglog_lines, loglog_lines_banded, loglog_points, pair_matrix, panel_grid, FigureError, Panel,
    Series,
};
use crate::harness::{methods_for, run_method, HarnessConfig, HarnessError, Method, MethodResult};
use crate::integrands::{standard_families, Family, Smoothness};
use crate::spectrum::mean_power_spectrum;
pub use crate::speed::{measure_speed, SpeedRow};
use gartowen::core::Registry;
use gartowen::discrepancy::expected::expected_l2star_random;
use gartowen::seq::SequenceKind;
use gartowen::verify::{verify, Level, Verdict};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
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

/// The randomization-quality table from the verify battery at quick level, one row per
/// request (the same requests as the speed table).
pub fn measure_quality(registry: &Registry, requests: &[String]) -> Vec<QualityRow> {
    verify(registry, requests, Level::Quick)
        .expect("registry entries build")
        .into_iter()
        .zip(requests)
        .map(|(r, request)| {
            let law = r.checks.iter().find(|c| c.check == "node-law");
            let nested = r.checks.iter().find(|c| c.check == "nested");
            QualityRow {
                scrambler: request.clone(),
                base: r.base,
                claims_nested_uniform: r.claims_nested_uniform,
                nested: nested.map_or(Verdict::Skipped, |c| c.verdict),
                node_law: law.map_or(Verdict::Skipped, |c| c.verdict),
                chi_square: law.and_then(|c| c.value),
                detail: law.map_or(String::new(), |c| c.detail.clone()),
                claim: r.claim.clone(),
                profile: r.profile.clone(),
            }
        })
        .collect()
}

fn expected_slope(s: Smoothness) -> Option<f64> {
    match s {
        Smoothness::Smooth => Some(-1.5),
        Smoothness::Discontinuous => Some(-0.75),
        Smoothness::Kinked => None,
    }
}

/// Slopes of every scrambled method on the 2-D integrands with a predicted rate. A slope
/// "meets" the prediction when it is at most 0.25 above it (the fit's noise at these R and N).
pub fn slope_rows(methods: &[MethodResult], families: &[Box<dyn Family>]) -> Vec<SlopeRow> {
    let mut rows = Vec::new();
    for m in methods {
        for (c, fam) in m.curves.iter().zip(families) {
            let (Some(slope), Some(expected)) = (c.slope, expected_slope(c.smoothness)) else {
                continue;
            };
            if fam.dims() != 2 {
                continue;
            }
            rows.push(SlopeRow {
                method: m.label.clone(),
                integrand: c.integrand.clone(),
                slope,
                expected,
                meets: slope <= expected + 0.25,
            });
        }
    }
    rows
}

fn harness_config(quick: bool, seed: u64) -> HarnessConfig {
    let max_log2 = if quick { 14 } else { 16 };
    let mut sizes: Vec<usize> = (2..=max_log2).map(|k| 1usize << k).collect();
    // Non-power sizes: 1.5·2^k sits between the net sizes.
    sizes.extend((3..max_log2).map(|k| 3usize << (k - 1)));
    sizes.sort_unstable();
    HarnessConfig {
        sizes,
        replicates: if quick { 8 } else { 32 },
        seed,
    }
}

fn quick_methods(all: Vec<Method>) -> Vec<Method> {
    let keep = [
        "none",
        "owen-oracle:base=2",
        "owen-oracle:base=4",
        "owen-oracle:base=16",
        "art-owen-2",
        "q-art-4",
        "art-owen-16p",
        "art-owen-t2",
        "art-owen-t4",
        "lk-hash",
    ];
    all.into_iter()
        .filter(|m| {
            m.sequence == "random"
                || (keep.contains(&m.scrambler.as_str())
                    && !(m.sequence == "sobol" && m.scrambler.starts_with("art-owen-t"))
                    && !(m.sequence != "sobol" && m.scrambler == "lk-hash"))
        })
        .collect()
}

/// Runs everything; `progress(done, total, what)` is called as parts finish.
pub fn build_report(
    registry: &Registry,
    config: &ReportConfig,
    progress: &dyn Fn(usize, usize, &str),
) -> Result<Report, ReportError> {
    let start = Instant::now();
    let families = standard_families(4);
    let harness = harness_config(config.quick, config.seed);
    let mut methods = methods_for(registry, &SequenceKind::ALL);
    if config.quick {
        methods = quick_methods(methods);
    }
    let total = methods.len() + 4;
    let mut results = Vec::with_capacity(methods.len());
    for (k, m) in methods.iter().enumerate() {
        results.push(run_method(registry, m, &families, &harness).map_err(ReportError::Harness)?);
        progress(k + 1, total, &m.label());
    }
    let speed = measure_speed(registry, config.quick);
    progress(methods.len() + 1, total, "speed");
    let requests: Vec<String> = speed.iter().map(|s| s.scrambler.clone()).collect();
    let quality = measure_quality(registry, &requests);
    progress(methods.len() + 2, total, "randomization quality");
    let discrepancy = discrepancy_curves(registry, config.quick);
    progress(methods.len() + 3, total, "discrepancy curves");
    let mut with_base: Vec<(String, u32)> = speed
        .iter()
        .map(|s| (s.scrambler.clone(), s.base))
        .collect();
    // The Q-ART paper's variant, judged against translation-only Q-ART as well as Owen.
    with_base.push(("q-art-4:compose=linear".into(), 4));
    let owen_variance = crate::fidelity::variance_ratios(
        registry,
        &with_base,
        // Enough seeds in the full report for the equivalence verdicts to reach level 1 of
        // base 256 (2,000 expected hits; `owen_equivalence::MIN_EXPECTED_HITS`).
        if config.quick { 200 } else { 8000 },
    );
    let tradeoff = crate::tradeoff::measure_tradeoff(config.quick);
    let equivalence = crate::equivalence::equivalence_rows(
        &owen_variance,
        &discrepancy,
        config.margin,
        gartowen::battery::equivalence::DEFAULT_ALPHA,
    );
    let slopes = slope_rows(&results, &families);
    let scene = crate::scene::report::run_scenes(
        &crate::scene::report::ScenePlan {
            scenes: crate::scene::all_scenes(),
            methods: crate::scene::measure::standard_methods(registry),
            layouts: Vec::new(),
            quick: config.quick,
            seed: config.seed,
            margin: config.margin,
        },
        &|_, _, _| {},
    )
    .map_err(|e| ReportError::Harness(HarnessError::Method(e)))?;
    progress(total, total, "scenes");
    Ok(Report {
        schema: REPORT_SCHEMA.into(),
        schema_version: REPORT_VERSION,
        tool_version: env!("CARGO_PKG_VERSION").into(),
        quick: config.quick,
        thresholds: Thresholds {
            slope: 0.15,
            rmse_factor: 1.0 + 3.0 / (2.0 * harness.replicates as f64).sqrt(),
            speed_factor: 1.5,
            speed_z: default_speed_z(),
        },
        harness,
        integrands: families.iter().map(|f| f.name()).collect(),
        methods: results,
        slopes,
        speed,
        quality,
        discrepancy,
        owen_variance,
        tradeoff,
        equivalence,
        scene: Some(scene),
        threads: rayon::current_num_threads(),
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// One regression against a baseline.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Regression {
    /// What regressed (method and integrand, or scrambler).
    pub what: String,
    /// The baseline value.
    pub before: f64,
    /// This run's value.
    pub after: f64,
    /// The threshold that was crossed, in words.
    pub rule: String,
}

/// Compares `now` with `baseline`: slopes, RMSE at the largest common N, and speed ratios.
pub fn compare(baseline: &Report, now: &Report) -> Vec<Regression> {
    let t = &now.thresholds;
    let mut out = Vec::new();
    for m in &now.methods {
        let Some(old) = baseline.methods.iter().find(|o| o.label == m.label) else {
            continue;
        };
        for c in &m.curves {
            let Some(oc) = old.curves.iter().find(|o| o.integrand == c.integrand) else {
                continue;
            };
            if let (Some(a), Some(b)) = (oc.slope, c.slope) {
                if b > a + t.slope {
                    out.push(Regression {
                        what: format!("{} on {}: slope", m.label, c.integrand),
                        before: a,
                        after: b,
                        rule: format!("slope rose by more than {}", t.slope),
                    });
                }
            }
            let common =
                c.n.iter()
                    .zip(&c.rmse)
                    .filter_map(|(n, r)| {
                        oc.n.iter()
                            .position(|m| m == n)
                            .map(|k| (*n, *r, oc.rmse[k]))
                    })
                    .max_by_key(|x| x.0);
            if let Some((n, r, or)) = common {
                if r > or * t.rmse_factor {
                    out.push(Regression {
                        what: format!("{} on {}: RMSE at N = {n}", m.label, c.integrand),
                        before: or,
                        after: r,
                        rule: format!("RMSE grew by more than ×{:.3}", t.rmse_factor),
                    });
                }
            }
        }
    }
    if let (Some(old), Some(new)) = (&baseline.scene, &now.scene) {
        out.extend(
            crate::scene::report::compare_scenes(old, new)
                .into_iter()
                .map(|r| Regression {
                    what: r.what,
                    before: r.before,
                    after: r.after,
                    rule: format!(
                        "RMSE grew by more than ×{} and {} standard errors",
                        crate::scene::report::REGRESSION_FACTOR,
                        crate::scene::report::REGRESSION_Z
                    ),
                }),
        );
    }
    for s in &now.speed {
        if let Some(o) = baseline.speed.iter().find(|o| o.scrambler == s.scrambler) {
            let allowed = crate::speed::allowed_growth(o, s, t.speed_factor, t.speed_z);
            if s.ratio_to_lk_hash > o.ratio_to_lk_hash * allowed {
                out.push(Regression {
                    what: format!("{}: time per coordinate relative to lk-hash", s.scrambler),
                    before: o.ratio_to_lk_hash,
                    after: s.ratio_to_lk_hash,
                    rule: format!(
                        "median ratio grew by more than ×{allowed:.3} (×{} widened by {} \
                         standard errors of the two medians)",
                        t.speed_factor, t.speed_z
                    ),
                });
            }
        }
    }
    out
}

/// Reads a baseline report.json.
pub fn read_baseline(path: &Path) -> Result<Report, ReportError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| ReportError::Baseline(format!("cannot read {}: {e}", path.display())))?;
    let v: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| ReportError::Baseline(format!("{}: not JSON: {e}", path.display())))?;
    if v["schema"] != REPORT_SCHEMA || v["schema_version"] != REPORT_VERSION {
        return Err(ReportError::Baseline(format!(
            "{}: not a {REPORT_SCHEMA} version {REPORT_VERSION} file",
            path.display()
        )));
    }
    let report: Report = serde_json::from_value(v)
        .map_err(|e| ReportError::Baseline(format!("{}: {e}", path.display())))?;
    // A baseline that compares nothing would pass every run: refuse it.
    if report.methods.iter().all(|m| m.curves.is_empty()) && report.speed.is_empty() {
        return Err(ReportError::Baseline(format!(
            "{}: no error curves and no speed rows: nothing to compare",
            path.display()
        )));
    }
    Ok(report)
}

/// The methods each RMSE figure shows (to keep the legend readable).
const FIGURE_METHODS: [&str; 9] = [
    "random",
    "sobol+none",
    "sobol+owen-oracle:base=2",
    "sobol+art-owen-2",
    "sz16+none",
    "sz16+art-owen-2",
    "sz16+art-owen-16p",
    "sz16+owen-oracle:base=16",
    "sz16+art-owen-t4",
];

/// The methods named in the efficiency figures (all methods are drawn).
const EFFICIENCY_LABELS: [&str; 8] = [
    "random",
    "sobol+none",
    "sobol+owen-oracle:base=2",
    "sobol+art-owen-2",
    "sobol+lk-hash",
    "sobol+owen-per-bit-hash",
    "sz16+art-owen-16p",
    "sz16+owen-oracle:base=16",
];

/// The integrands with RMSE figures.
const FIGURE_INTEGRANDS: [&str; 6] = [
    "heaviside",
    "hard-disk",
    "gaussian-2d",
    "soft-disk",
    "genz-oscillatory-2d",
    "genz-corner-peak-4d",
];

/// Writes every figure into `dir`; returns the file names.
pub fn write_figures(
    report: &Report,
    registry: &Registry,
    dir: &Path,
) -> Result<Vec<String>, ReportError> {
    let mut files = Vec::new();
    let fig = ReportError::Figure;
    for integrand in FIGURE_INTEGRANDS {
        let Some(k) = report.integrands.iter().position(|i| i == integrand) else {
            continue;
        };
        let series: Vec<Series> = FIGURE_METHODS
            .iter()
            .filter_map(|label| report.methods.iter().find(|m| m.label == *label))
            .map(|m| Series {
                label: m.label.clone(),
                points: m.curves[k]
                    .n
                    .iter()
                    .zip(&m.curves[k].rmse)
                    .filter(|(n, _)| crate::harness::is_power_of(**n, 2))
                    .map(|(n, r)| (*n as f64, *r))
                    .collect(),
            })
            .collect();
        let name = format!("rmse_{integrand}.png");
        loglog_lines(
            &dir.join(&name),
            &format!(
                "RMSE against N: {integrand} (R = {})",
                report.harness.replicates
            ),
            "N (points)",
            "RMSE",
            &series,
            &[-0.5, -1.0, -1.5],
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Speed against error: RMSE at the largest N against time per point.
    for integrand in ["gaussian-2d", "heaviside"] {
        let Some(k) = report.integrands.iter().position(|i| i == integrand) else {
            continue;
        };
        let pts: Vec<Series> = report
            .methods
            .iter()
            .map(|m| Series {
                label: m.label.clone(),
                points: vec![(
                    m.seconds_per_point * 1e9,
                    *m.curves[k].rmse.last().expect("sizes"),
                )],
            })
            .collect();
        let name = format!("efficiency_{integrand}.png");
        loglog_points(
            &dir.join(&name),
            &format!(
                "Speed against error: {integrand}, N = {}",
                report.harness.sizes.iter().max().expect("sizes")
            ),
            "time per point (ns, 4 coordinates)",
            "RMSE",
            &pts,
            &EFFICIENCY_LABELS,
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Figure 1 (the paper's): every one of the 28 pairs of the first 8 dimensions at N = 256
    // and 512, one matrix per method (scatter of seed 1 above the diagonal, the mean
    // periodogram over FIGURE1_SEEDS seeds below, grey key), then the consecutive pairs
    // (j, j+1) side by side across methods. One realisation's spectrum is noise.
    let methods = [
        ("unscrambled", "none"),
        ("ArtOwen2", "art-owen-2"),
        ("ArtOwen16P", "art-owen-16p"),
    ];
    for n in [256usize, 512] {
        let pairs: Vec<[usize; 2]> = (0..7).map(|j| [j, j + 1]).collect();
        let mut rows = Vec::new();
        for (label, request) in methods {
            // The unscrambled set is the same for every seed.
            let seeds = if request == "none" { 1 } else { FIGURE1_SEEDS };
            let sets: Vec<Vec<u64>> = (1..=seeds)
                .map(|seed| sz16_words(registry, request, 8, n, seed))
                .collect();
            let pair_sets = |a: usize, b: usize| -> Vec<Vec<[f64; 2]>> {
                sets.iter()
                    .map(|w| {
                        let value = |i: usize, j: usize| w[i * 8 + j] as f64 * 2f64.powi(-32);
                        (0..n).map(|i| [value(i, a), value(i, b)]).collect()
                    })
                    .collect()
            };
            // Every pair's mean spectrum once: the matrix and the consecutive pairs share them.
            let spectra: Vec<Vec<Vec<f64>>> = (0..8)
                .map(|a| {
                    (0..8)
                        .map(|b| {
                            if a < b {
                                mean_power_spectrum(&pair_sets(a, b), 24)
                            } else {
                                Vec::new()
                            }
                        })
                        .collect()
                })
                .collect();
            let name = format!("figure1_sz16_n{n}_pairs_{}.png", file_stem(request));
            pair_matrix(
                &dir.join(&name),
                &format!(
                    "Figure 1: sz16, {label}, N = {n}: all 28 pairs of dims 0..7 (spectra: mean of {seeds} seeds)"
                ),
                8,
                &|a, b| pair_sets(a, b).swap_remove(0),
                &|a, b| spectra[a][b].clone(),
                24,
            )
            .map_err(fig)?;
            files.push(name);
            rows.push((
                format!("{label} points"),
                pairs
                    .iter()
                    .map(|p| Panel::Scatter(pair_sets(p[0], p[1]).swap_remove(0)))
                    .collect(),
            ));
            rows.push((
                format!("{label} spectrum"),
                pairs
                    .iter()
                    .map(|p| Panel::Spectrum {
                        values: spectra[p[0]][p[1]].clone(),
                        max_freq: 24,
                    })
                    .collect(),
            ));
        }
        let name = format!("figure1_sz16_n{n}.png");
        panel_grid(
            &dir.join(&name),
            &format!(
                "Figure 1: sz16, first 8 dimensions, N = {n} (spectra |f| ≤ 24, log grey, mean of {FIGURE1_SEEDS} seeds)"
            ),
            &pairs
                .iter()
                .map(|p| format!("dims {},{}", p[0], p[1]))
                .collect::<Vec<_>>(),
            &rows,
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Figure 2: joint 16-D and pair curves.
    let mut joint: Vec<Series> = report
        .discrepancy
        .iter()
        .map(|c| Series {
            label: format!("{} (16-D)", c.scrambler),
            points: c
                .n
                .iter()
                .zip(&c.joint)
                .map(|(n, v)| (*n as f64, *v))
                .collect(),
        })
        .collect();
    // The paper's baseline: independent uniform points, by their exact expectation.
    let random = |dims: u32| Series {
        label: "random points (exact E[D²])".into(),
        points: report
            .discrepancy
            .iter()
            .max_by_key(|c| c.n.len())
            .map_or(Vec::new(), |c| {
                c.n.iter()
                    .map(|&n| (n as f64, expected_l2star_random(n, dims)))
                    .collect()
            }),
    };
    joint.push(random(16));
    loglog_lines(
        &dir.join("figure2_joint.png"),
        "Figure 2a: mean L2-star D², sz16 in 16-D: ART against full-tree Owen of its base",
        "N (points)",
        "mean D²",
        &joint,
        &[-1.0],
    )
    .map_err(fig)?;
    files.push("figure2_joint.png".into());
    // Figure 2b: every pair (0, j), one figure per method, with ±2 SE bands.
    for c in &report.discrepancy {
        let mut pair_series = Vec::new();
        let mut bands = Vec::new();
        for (k, p) in c.pairs.iter().enumerate() {
            let mean: Vec<(f64, f64)> =
                c.n.iter()
                    .zip(&c.pair_values)
                    .map(|(n, v)| (*n as f64, v[k]))
                    .collect();
            bands.push(
                mean.iter()
                    .enumerate()
                    .map(|(i, &(_, m))| {
                        let se = c.pair_se.get(i).and_then(|v| v.get(k)).copied();
                        let se = se.unwrap_or(0.0);
                        (m - 2.0 * se, m + 2.0 * se)
                    })
                    .collect(),
            );
            pair_series.push(Series {
                label: format!("dims {},{}", p[0], p[1]),
                points: mean,
            });
        }
        let base = random(2);
        bands.push(base.points.iter().map(|&(_, m)| (m, m)).collect());
        pair_series.push(base);
        let name = format!("figure2_pairs_{}.png", file_stem(&c.scrambler));
        loglog_lines_banded(
            &dir.join(&name),
            &format!(
                "Figure 2b: mean 2-D L2-star D² of sz16 pairs (0, j), {} ({}–{} seeds, ±2 SE)",
                c.scrambler,
                c.seeds,
                c.seeds_per_n.iter().max().unwrap_or(&c.seeds)
            ),
            "N (points)",
            "mean D²",
            &pair_series,
            &bands,
            &[-2.0],
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Figure 2c: max/min over the 15 pairs against N, per method.
    let spread: Vec<Series> = report
        .discrepancy
        .iter()
        .map(|c| Series {
            label: c.scrambler.clone(),
            points: c
                .n
                .iter()
                .zip(c.pair_spread())
                .map(|(n, r)| (*n as f64, r))
                .collect(),
        })
        .collect();
    let spread_bands: Vec<Vec<(f64, f64)>> = report
        .discrepancy
        .iter()
        .map(|c| {
            c.pair_spread()
                .iter()
                .zip(c.pair_spread_se())
                .map(|(&r, se)| {
                    let se = if se.is_finite() { se } else { 0.0 };
                    ((r - 2.0 * se).max(1.0), r + 2.0 * se)
                })
                .collect()
        })
        .collect();
    loglog_lines_banded(
        &dir.join("figure2_spread.png"),
        "Figure 2c: max / min over pairs (0, j) of the mean 2-D D² (1 = every pair alike; ±2 SE)",
        "N (points)",
        "max / min",
        &spread,
        &spread_bands,
        &[],
    )
    .map_err(fig)?;
    files.push("figure2_spread.png".into());
    if let Some(scene) = &report.scene {
        files.extend(
            crate::scene::output::write_scene_figures(scene, dir).map_err(ReportError::Figure)?,
        );
    }
    Ok(files)
}

/// A scrambler request as a file-name part: `owen-oracle:base=16` → `owen-oracle_base-16`.
fn file_stem(request: &str) -> String {
    request
        .chars()
        .map(|c| match c {
            ':' => '_',
            '=' | ',' => '-',
            c => c,
        })
        .collect()
}

/// The Markdown report.
pub fn markdown(report: &Report, figures: &[String], regressions: Option<&[Regression]>) -> String {
    let mut md = String::new();
    let h = &report.harness;
    md += &format!(
        "# gartowen report{}\n\ngartowen {} · {} worker threads · {:.1} s · R = {} replicates · \
         N up to {} · seed {}\n\n",
        if report.quick { " (quick)" } else { "" },
        report.tool_version,
        report.threads,
        report.seconds,
        h.replicates,
        h.sizes.iter().max().unwrap_or(&0),
        h.seed
    );
    if report.quick {
        md += "Quick mode: R and N are small, so slopes scatter by about ±0.2 and a few fits miss \
               the predicted rate by chance; the full report (without --quick) is the one to read \
               for rates.\n\n";
    }
    md += "Errors are deterministic (fixed seeds); times are this machine's and are compared \
           with baselines only as ratios to `lk-hash` measured in the same run.\n\n";
    md += "## Convergence slopes (2-D integrands, fitted over N = b^k ≥ 64)\n\n\
           Owen-scrambled nets should reach about −1.5 on smooth integrands and about −0.75 on \
           discontinuous ones. A slope meets the rate when it is at most 0.25 above it.\n\n";
    let integrands: Vec<&String> = {
        let mut v: Vec<&String> = report.slopes.iter().map(|s| &s.integrand).collect();
        v.sort();
        v.dedup();
        v
    };
    md += &format!(
        "| method | {} |\n|---|{}\n",
        integrands
            .iter()
            .map(|s| s.as_str())
            .collect::<Vec<_>>()
            .join(" | "),
        "---|".repeat(integrands.len())
    );
    for m in &report.methods {
        let cells: Vec<String> = integrands
            .iter()
            .map(|i| {
                report
                    .slopes
                    .iter()
                    .find(|s| s.method == m.label && &&s.integrand == i)
                    .map_or("–".into(), |s| {
                        format!("{:.2}{}", s.slope, if s.meets { "" } else { " ✗" })
                    })
            })
            .collect();
        md += &format!("| {} | {} |\n", m.label, cells.join(" | "));
    }
    let misses = report.missed_slopes();
    md += &format!(
        "\nScrambled methods that miss the predicted rate: {}.\n\n",
        if misses.is_empty() {
            "none".to_string()
        } else {
            let mut names: Vec<String> = misses.iter().map(|s| s.method.clone()).collect();
            names.dedup();
            names.join(", ")
        }
    );
    md += "## Speed and randomization quality\n\n\
           ns per 32-bit coordinate (random words, dims 0..8; the median of rounds), its ratio to `lk-hash` (the median of per-round ratios), table bytes, \
           and the node-permutation law against uniform S_b from `verify --level quick`.\n\n\
           | scrambler | base | ns/coord | × lk-hash | table bytes | nested | node law | detail |\n\
           |---|---|---|---|---|---|---|---|\n";
    for s in &report.speed {
        let q = report.quality.iter().find(|q| q.scrambler == s.scrambler);
        md += &format!(
            "| {} | {} | {:.1} | {:.2} | {} | {} | {} | {} |\n",
            s.scrambler,
            s.base,
            s.ns_per_coord,
            s.ratio_to_lk_hash,
            s.table_bytes,
            q.map_or("–".into(), |q| format!("{:?}", q.nested).to_lowercase()),
            q.map_or("–".into(), |q| format!("{:?}", q.node_law).to_lowercase()),
            q.map_or(String::new(), |q| q.detail.clone())
        );
    }
    md += "\n## How close to Owen\n\n\
           Per law family of `verify --level quick`, one character per tree depth 0, 1, 2, …: \
           `.` no deviation detected at the stated power, `x` a deviation at the per-test level, \
           `-` not tested. Families a scrambler does not claim are measured, not judged. \
           The variance columns: the variance over seeds of the estimate of a box's volume \
           (64 fixed pseudo-random points in 2-D, boxes of 1, 2 and 3 digits of the scrambler's \
           base) divided by its exact value under Owen's scrambling, ± 2 standard errors: 1 is \
           Owen's law (`gartowen::oracles::owen_variance`).\n\n\
           | scrambler | claim | ns/coord | var. ratio level 1 | level 2 | level 3 | node-law | pair-law | flip-rank | collisions | pair-lemma |\n\
           |---|---|---|---|---|---|---|---|---|---|---|\n";
    for s in &report.speed {
        let Some(q) = report.quality.iter().find(|q| q.scrambler == s.scrambler) else {
            continue;
        };
        let row = |family: &str| {
            q.profile
                .iter()
                .find(|(f, _)| f == family)
                .map_or("–".to_string(), |(_, r)| format!("`{r}`"))
        };
        let var = report
            .owen_variance
            .iter()
            .find(|v| v.scrambler == s.scrambler);
        let level = |k: usize| {
            var.and_then(|v| Some(((*v.ratio.get(k)?)?, (*v.ratio_se.get(k)?)?)))
                .map_or("–".to_string(), |(r, se)| {
                    format!("{r:.2} ± {:.2}", 2.0 * se)
                })
        };
        md += &format!(
            "| {} | {} | {:.1} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            s.scrambler,
            q.claim,
            s.ns_per_coord,
            level(0),
            level(1),
            level(2),
            row("node-law"),
            row("pair-law"),
            row("flip-rank"),
            row("collisions"),
            row("pair-lemma")
        );
    }
    md += &crate::tradeoff::markdown(&report.tradeoff, &report.owen_variance, &|name| {
        let q = report.quality.iter().find(|q| q.scrambler == name)?;
        let family = |f: &str| {
            q.profile
                .iter()
                .find(|(g, _)| g == f)
                .map_or("–".to_string(), |(_, r)| format!("`{r}`"))
        };
        Some(format!("{} / {}", family("node-law"), family("pair-law")))
    });
    md += &crate::equivalence::markdown(&report.equivalence);
    md += "\n## Discrepancy (Figure 2 data): mean L2-star D² of sz16\n\nMeans over the seeds \
           shown, ± 2 standard errors; two methods whose intervals overlap are not told apart by \
           this many seeds. The spread is max / min over the 15 pairs (0, j) of the mean 2-D D², ± 2 SE \
           (delta method on the two extreme pairs).\n\n\
           | scrambler | seeds | N | joint 16-D (± 2 SE) | mean over pairs (0,j) | spread |\n\
           |---|---|---|---|---|---|\n";
    for c in &report.discrepancy {
        let spread = c.pair_spread();
        let spread_se = c.pair_spread_se();
        for (k, n) in c.n.iter().enumerate() {
            let mean = c.pair_values[k].iter().sum::<f64>() / c.pair_values[k].len() as f64;
            let se = c
                .joint_se
                .get(k)
                .map_or(String::new(), |se| format!(" ± {:.1e}", 2.0 * se));
            md += &format!(
                "| {} | {} | {} | {:.4e}{se} | {:.4e} | {:.2} ± {:.2} |\n",
                c.scrambler,
                c.seeds_at(k),
                n,
                c.joint[k],
                mean,
                spread[k],
                2.0 * spread_se[k]
            );
        }
    }
    if let Some(scene) = &report.scene {
        md += "\n## Scenes: does base-2^q decorrelation pay off in rendering?\n\n";
        md += &crate::scene::output::scene_markdown(scene, figures, None, "###");
    }
    md += "\n## Figures\n\n";
    for f in figures.iter().filter(|f| !f.starts_with("scene-")) {
        md += &format!("![{f}]({f})\n\n");
    }
    if let Some(r) = regressions {
        md += &format!(
            "## Baseline comparison\n\nThresholds: slope +{}, RMSE ×{:.3}, speed ratio ×{}.\n\n\
             Speed ratios are medians over rounds, each round's ratio against `lk-hash` timed in \
             the same round; a speed row regresses only beyond ×{} widened by {} standard errors \
             of the two medians (one-sided; at most 0.135% false alarms per row at 3).\n\n",
            report.thresholds.slope,
            report.thresholds.rmse_factor,
            report.thresholds.speed_factor,
            report.thresholds.speed_factor,
            report.thresholds.speed_z
        );
        if r.is_empty() {
            md += "No regressions.\n";
        }
        for x in r {
            md += &format!(
                "- REGRESSION {}: {:.4e} → {:.4e} ({})\n",
                x.what, x.before, x.after, x.rule
            );
        }
    }
    md
}

/// Writes report.json, report.md and the figures into `dir`; returns the regressions against
/// `baseline` (empty without one). All or nothing: every file is written into
/// [`staging_dir`] first and moved into `dir` only when all are complete, so a write error
/// (a full disk) leaves `dir` as it was, an earlier report in it intact, and no staging
/// folder behind.
pub fn write_report(
    report: &Report,
    registry: &Registry,
    dir: &Path,
    baseline: Option<&Report>,
) -> Result<Vec<Regression>, ReportError> {
    let regressions = baseline.map(|b| compare(b, report));
    write_staged(dir, |staging| {
        stage_report(report, registry, staging, regressions.as_deref()).map_err(|e| match e {
            ReportError::Io(m) => m,
            other => other.to_string(),
        })
    })
    .map_err(ReportError::Io)?;
    Ok(regressions.unwrap_or_default())
}

/// Creates `dir`, lets `stage` write files into [`staging_dir`] (returning their names), and
/// moves them into `dir` only when all are complete, so a write error (a full disk) leaves
/// `dir` as it was, an earlier report in it intact, and no staging folder behind.
pub fn write_staged(
    dir: &Path,
    stage: impl FnOnce(&Path) -> Result<Vec<String>, String>,
) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let staging = staging_dir(dir);
    // A staging folder left by a killed run of this pid would only hold stale files.
    let _ = std::fs::remove_dir_all(&staging);
    std::fs::create_dir(&staging)
        .map_err(|e| format!("cannot create {}: {e}", staging.display()))?;
    let moved = stage(&staging).and_then(|names| {
        // Renames within one folder need no space: once every file is staged, the report
        // cannot stop half-written.
        for name in &names {
            std::fs::rename(staging.join(name), dir.join(name))
                .map_err(|e| format!("cannot write {}: {e}", dir.join(name).display()))?;
        }
        Ok(())
    });
    let _ = std::fs::remove_dir_all(&staging);
    moved
}

/// The folder inside `dir` where [`write_report`] writes every file before moving them into
/// place (named by the process id, so two runs into one folder do not share it).
pub fn staging_dir(dir: &Path) -> PathBuf {
    dir.join(format!(".report-staging-{}", std::process::id()))
}

/// Writes the figures, report.json and report.md into `staging`; returns the file names.
fn stage_report(
    report: &Report,
    registry: &Registry,
    staging: &Path,
    regressions: Option<&[Regression]>,
) -> Result<Vec<String>, ReportError> {
    let figures = write_figures(report, registry, staging)?;
    let write = |name: &str, text: &str| -> Result<(), ReportError> {
        std::fs::write(staging.join(name), text)
            .map_err(|e| ReportError::Io(format!("cannot write {name}: {e}")))
    };
    write(
        "report.json",
        &serde_json::to_string_pretty(report).expect("serializable"),
    )?;
    write("report.md", &markdown(report, &figures, regressions))?;
    let mut names = figures;
    names.push("report.json".into());
    names.push("report.md".into());
    Ok(names)
}
