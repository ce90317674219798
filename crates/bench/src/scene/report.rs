//! The scene report: every scene under every method and layout, the base-16 against binary
//! verdicts, tables, words, and comparison with a baseline.

use super::layout::candidate_layouts;
use super::measure::{extremes, measure_scene, SceneConfig, SceneMethod, SceneResult};
use super::{Layout, Scene};
use gartowen::core::Progress;
use serde::{Deserialize, Serialize};
use statrs::distribution::{ContinuousCDF, Normal};
use std::fmt::Write as _;
use std::time::Instant;

/// `schema` of scene.json.
pub const SCENE_SCHEMA: &str = "gartowen.scene-report";
/// `schema_version` of scene.json.
pub const SCENE_VERSION: u32 = 1;

/// Two-sided level of each base-16 against binary comparison, before the Bonferroni split.
pub const HEADLINE_ALPHA: f64 = 0.05;

/// A scene as the report describes it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneInfo {
    /// Name.
    pub name: String,
    /// What is estimated.
    pub summary: String,
    /// `name:dims` per slot.
    pub slots: Vec<String>,
    /// Estimators (pixels).
    pub pixels: usize,
    /// Mean reference value over pixels.
    pub reference_mean: f64,
    /// Stated bound on the reference's error.
    pub reference_error: f64,
    /// The reference per pixel, row-major (multi-pixel scenes only).
    #[serde(default)]
    pub reference_image: Vec<f64>,
}

/// Base 16 against binary at one scene, N and layout statistic.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct HeadlineRow {
    /// Scene.
    pub scene: String,
    /// N.
    pub n: usize,
    /// `worst`, `median` or `best` layout (each method's own).
    pub which: String,
    /// The base-16 method.
    pub base16: String,
    /// The binary method.
    pub binary: String,
    /// RMSE(base 16) / RMSE(binary).
    pub ratio: f64,
    /// Standard error of ln(ratio) (delta method; ignores that the layout was selected).
    pub log_se: f64,
    /// `base 16 helps`, `base 16 hurts` or `no difference detected`.
    pub verdict: String,
}

/// Everything `gartowen scene` measures.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneReport {
    /// [`SCENE_SCHEMA`].
    pub schema: String,
    /// [`SCENE_VERSION`].
    pub schema_version: u32,
    /// Tool version.
    pub tool_version: String,
    /// Quick mode.
    pub quick: bool,
    /// Sizes and seeds of the single-estimator scenes.
    pub config: SceneConfig,
    /// Sizes and seeds of multi-pixel scenes (each pixel has its own seed).
    pub image_config: SceneConfig,
    /// The scenes.
    pub scenes: Vec<SceneInfo>,
    /// One per scene and method.
    pub results: Vec<SceneResult>,
    /// Base 16 against binary.
    pub headline: Vec<HeadlineRow>,
    /// Critical |z| of the headline (two-sided [`HEADLINE_ALPHA`], Bonferroni over its rows).
    pub headline_z: f64,
    /// ART against the exact Owen scramble of its base, per scene and N, on the MSE.
    #[serde(default)]
    pub equivalence: Vec<SceneEquivalence>,
    /// Worker threads.
    pub threads: usize,
    /// Wall seconds.
    pub seconds: f64,
}

/// What to run.
pub struct ScenePlan<'a> {
    /// Scenes.
    pub scenes: Vec<Box<dyn Scene>>,
    /// Methods.
    pub methods: Vec<SceneMethod<'a>>,
    /// A user layout per scene name (replaces the candidate layouts of that scene).
    pub layouts: Vec<(String, Layout)>,
    /// Quick mode.
    pub quick: bool,
    /// Master seed.
    pub seed: u64,
    /// Equivalence margin δ on the MSE ratio of ART against Owen.
    pub margin: f64,
}

/// Sizes and seeds: powers and non-powers of 2 and 16 up to 4096, 256 seeds in full and 32
/// quick; the image to N = 1000 (full) or 64 (quick) with 8 or 2 seeds per pixel (×1024
/// pixels).
pub fn configs(quick: bool, seed: u64) -> (SceneConfig, SceneConfig) {
    let config = |sizes: &[usize], seeds| SceneConfig {
        sizes: sizes.to_vec(),
        seeds,
        seed,
    };
    if quick {
        (
            config(&[16, 64, 100, 256, 1000, 4096], 32),
            config(&[16, 64], 2),
        )
    } else {
        (
            config(
                &[
                    16, 32, 64, 100, 128, 256, 300, 512, 1000, 1024, 2048, 3000, 4096,
                ],
                256,
            ),
            config(&[16, 64, 100, 256, 1000], 8),
        )
    }
}

/// Layouts measured for a scene: the user's, or the candidates (3 scattered ones, 1 for
/// multi-pixel scenes in quick mode).
fn layouts_for(scene: &dyn Scene, plan: &ScenePlan) -> Vec<Layout> {
    if let Some((_, l)) = plan.layouts.iter().find(|(n, _)| n == scene.name()) {
        return vec![l.clone()];
    }
    let scattered = if scene.pixels() > 1 && plan.quick {
        1
    } else {
        3
    };
    candidate_layouts(scene.slots(), scattered, plan.seed)
}

/// Runs the plan. `progress` starts with the number of scene × method pairs, names each pair
/// as it runs and advances as each finishes.
pub fn run_scenes(plan: &ScenePlan, progress: &dyn Progress) -> Result<SceneReport, String> {
    let start = Instant::now();
    let (config, image_config) = configs(plan.quick, plan.seed);
    let total = plan.scenes.len() * plan.methods.len();
    let mut results = Vec::with_capacity(total);
    progress.start(total as u64, "scene × method");
    for scene in &plan.scenes {
        let layouts = layouts_for(scene.as_ref(), plan);
        let c = if scene.pixels() > 1 {
            &image_config
        } else {
            &config
        };
        for m in &plan.methods {
            progress.message(&format!("{} {}", scene.name(), m.label));
            results.push(measure_scene(scene.as_ref(), m, &layouts, c)?);
            progress.advance(1);
        }
    }
    progress.finish();
    let scenes: Vec<SceneInfo> = plan
        .scenes
        .iter()
        .map(|s| SceneInfo {
            name: s.name().into(),
            summary: s.summary().into(),
            slots: s
                .slots()
                .iter()
                .map(|x| format!("{}:{}", x.name, x.dims))
                .collect(),
            pixels: s.pixels(),
            reference_mean: (0..s.pixels()).map(|p| s.reference(p)).sum::<f64>()
                / s.pixels() as f64,
            reference_error: s.reference_error(),
            reference_image: if s.pixels() > 1 {
                (0..s.pixels()).map(|p| s.reference(p)).collect()
            } else {
                Vec::new()
            },
        })
        .collect();
    let (headline, headline_z) = headline(&results);
    let equivalence = equivalence_rows(&results, plan.margin);
    Ok(SceneReport {
        schema: SCENE_SCHEMA.into(),
        schema_version: SCENE_VERSION,
        tool_version: env!("CARGO_PKG_VERSION").into(),
        quick: plan.quick,
        config,
        image_config,
        scenes,
        results,
        headline,
        headline_z,
        equivalence,
        threads: rayon::current_num_threads(),
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// The (base 16, binary) method pairs of the headline: the paper's ART variants on sz16, and
/// the exact base-16 Owen scramble against binary ART.
pub const HEADLINE_PAIRS: [(&str, &str); 2] = [
    ("sz16+art-owen-16p", "sz16+art-owen-2"),
    ("sz16+owen-oracle:base=16", "sz16+art-owen-2"),
];

/// Sizes the headline reports (where measured).
pub const HEADLINE_SIZES: [usize; 5] = [64, 100, 256, 1000, 4096];

/// For each scene where both `a` and `b` were measured: the two results and the
/// [`HEADLINE_SIZES`] both have, with their indices in each.
type Paired<'r> = (&'r SceneResult, &'r SceneResult, Vec<(usize, usize, usize)>);

fn paired<'r>(results: &'r [SceneResult], a: &str, b: &str) -> Vec<Paired<'r>> {
    results
        .iter()
        .filter(|r| r.method == a)
        .filter_map(|ra| {
            let rb = results
                .iter()
                .find(|r| r.method == b && r.scene == ra.scene)?;
            let sizes = HEADLINE_SIZES
                .iter()
                .filter_map(|n| {
                    let sa = ra.n.iter().position(|x| x == n)?;
                    let sb = rb.n.iter().position(|x| x == n)?;
                    Some((*n, sa, sb))
                })
                .collect();
            Some((ra, rb, sizes))
        })
        .collect()
}

/// Base 16 against binary per scene, N in [`HEADLINE_SIZES`] and worst/median/best layout,
/// with the Bonferroni critical z over all rows.
pub fn headline(results: &[SceneResult]) -> (Vec<HeadlineRow>, f64) {
    let mut rows = Vec::new();
    for (b16, b2) in HEADLINE_PAIRS {
        for (a, b, sizes) in paired(results, b16, b2) {
            for (n, sa, sb) in sizes {
                let (ea, eb) = (extremes(a, sa), extremes(b, sb));
                for (k, which) in ["best", "median", "worst"].iter().enumerate() {
                    let (ia, ra) = ea[k];
                    let (ib, rb) = eb[k];
                    let rel =
                        |r: &SceneResult, i: usize, s: usize, v: f64| r.layouts[i].rmse_se[s] / v;
                    let log_se = (rel(a, ia, sa, ra).powi(2) + rel(b, ib, sb, rb).powi(2)).sqrt();
                    rows.push(HeadlineRow {
                        scene: a.scene.clone(),
                        n,
                        which: which.to_string(),
                        base16: b16.into(),
                        binary: b2.into(),
                        ratio: ra / rb,
                        log_se,
                        verdict: String::new(),
                    });
                }
            }
        }
    }
    let z = critical_z(rows.len());
    for r in &mut rows {
        let t = r.ratio.ln() / r.log_se;
        r.verdict = if t.is_nan() || t.abs() <= z {
            "no difference detected".into()
        } else if t < 0.0 {
            "base 16 helps".into()
        } else {
            "base 16 hurts".into()
        };
    }
    (rows, z)
}

/// The (ART, exact Owen of the same base) pairs judged for equivalence in the scenes.
pub const EQUIVALENCE_PAIRS: [(&str, &str); 1] =
    [("sz16+art-owen-16p", "sz16+owen-oracle:base=16")];

/// ART against Owen in one scene at one N.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneEquivalence {
    /// Scene.
    pub scene: String,
    /// N.
    pub n: usize,
    /// The ART method.
    pub implementation: String,
    /// The exact Owen method.
    pub reference: String,
    /// The judgement of MSE(implementation) / MSE(reference), the MSE averaged over the
    /// layouts ([`SceneResult::pooled_mse`]).
    pub judgement: gartowen::battery::equivalence::Equivalence,
}

/// Equivalence of each [`EQUIVALENCE_PAIRS`] pair per scene at the [`HEADLINE_SIZES`]: TOST
/// with margin `margin` at α = 0.05, the difference test Bonferroni over the sizes judged.
pub fn equivalence_rows(results: &[SceneResult], margin: f64) -> Vec<SceneEquivalence> {
    use gartowen::battery::equivalence::{judge, ratio_of_means, EquivalenceSettings};
    let mut rows = Vec::new();
    for (imp, reference) in EQUIVALENCE_PAIRS {
        for (a, b, sizes) in paired(results, imp, reference) {
            let Some(settings) = EquivalenceSettings::new(
                margin,
                gartowen::battery::equivalence::DEFAULT_ALPHA,
                sizes.len().max(1),
            ) else {
                continue;
            };
            for (n, sa, sb) in sizes {
                let at = |v: &[f64], s: usize| v.get(s).copied().unwrap_or(f64::NAN);
                let (ratio, log_se) = ratio_of_means(
                    at(&a.pooled_mse, sa),
                    at(&a.pooled_mse_se, sa),
                    at(&b.pooled_mse, sb),
                    at(&b.pooled_mse_se, sb),
                )
                .unwrap_or((f64::NAN, f64::NAN));
                rows.push(SceneEquivalence {
                    scene: a.scene.clone(),
                    n,
                    implementation: imp.into(),
                    reference: reference.into(),
                    judgement: judge(ratio, log_se, a.seeds * a.pixels as u64, settings),
                });
            }
        }
    }
    rows
}

/// Two-sided critical z at [`HEADLINE_ALPHA`] split over `m` tests.
pub fn critical_z(m: usize) -> f64 {
    let normal = Normal::new(0.0, 1.0).expect("standard normal");
    normal.inverse_cdf(1.0 - HEADLINE_ALPHA / (2.0 * m.max(1) as f64))
}

/// One regression against a baseline scene report.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneRegression {
    /// Scene, method, statistic and N.
    pub what: String,
    /// Baseline RMSE.
    pub before: f64,
    /// This run's RMSE.
    pub after: f64,
}

/// Growth of a worst- or median-layout RMSE that counts as a regression: more than
/// ×[`REGRESSION_FACTOR`] and more than [`REGRESSION_Z`] combined standard errors.
pub const REGRESSION_FACTOR: f64 = 1.1;
/// See [`REGRESSION_FACTOR`].
pub const REGRESSION_Z: f64 = 3.0;

/// Compares each (scene, method, N) present in both: the median and worst layout RMSE.
pub fn compare_scenes(baseline: &SceneReport, now: &SceneReport) -> Vec<SceneRegression> {
    let mut out = Vec::new();
    for r in &now.results {
        let Some(o) = baseline
            .results
            .iter()
            .find(|o| o.scene == r.scene && o.method == r.method)
        else {
            continue;
        };
        for (s, n) in r.n.iter().enumerate() {
            let Some(so) = o.n.iter().position(|x| x == n) else {
                continue;
            };
            let (e, eo) = (extremes(r, s), extremes(o, so));
            for (k, which) in [(1, "median"), (2, "worst")] {
                let (after, before) = (e[k].1, eo[k].1);
                let se = r.layouts[e[k].0].rmse_se[s].hypot(o.layouts[eo[k].0].rmse_se[so]);
                if after > before * REGRESSION_FACTOR && after - before > REGRESSION_Z * se {
                    out.push(SceneRegression {
                        what: format!("{} {}: {which}-layout RMSE at N = {n}", r.scene, r.method),
                        before,
                        after,
                    });
                }
            }
        }
    }
    out
}

/// The (scene, method) pairs of `baseline` that `plan` measures again at some common N: a
/// baseline that shares none would compare nothing and must be refused, not pass.
pub fn comparable_with(baseline: &SceneReport, plan: &ScenePlan) -> Vec<(String, String)> {
    let (config, image) = configs(plan.quick, plan.seed);
    baseline
        .results
        .iter()
        .filter(|r| {
            let Some(scene) = plan.scenes.iter().find(|s| s.name() == r.scene) else {
                return false;
            };
            let sizes = if scene.pixels() > 1 {
                &image.sizes
            } else {
                &config.sizes
            };
            plan.methods.iter().any(|m| m.label == r.method)
                && r.n.iter().any(|n| sizes.contains(n))
        })
        .map(|r| (r.scene.clone(), r.method.clone()))
        .collect()
}

/// Reads and checks a baseline scene.json.
pub fn read_scene_baseline(path: &std::path::Path) -> Result<SceneReport, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let v: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| format!("{}: not JSON: {e}", path.display()))?;
    if v["schema"] != SCENE_SCHEMA || v["schema_version"] != SCENE_VERSION {
        return Err(format!(
            "{}: not a {SCENE_SCHEMA} version {SCENE_VERSION} file",
            path.display()
        ));
    }
    serde_json::from_value(v).map_err(|e| format!("{}: {e}", path.display()))
}

/// The headline in words, one paragraph per scene.
pub fn answer_in_words(report: &SceneReport) -> String {
    let mut s = String::new();
    for info in &report.scenes {
        let rows: Vec<&HeadlineRow> = report
            .headline
            .iter()
            .filter(|r| r.scene == info.name && r.base16 == HEADLINE_PAIRS[0].0)
            .collect();
        if rows.is_empty() {
            continue;
        }
        let list = |verdict: &str, which: &str| {
            rows.iter()
                .filter(|r| r.verdict == verdict && r.which == which)
                .map(|r| format!("N = {} (×{:.2})", r.n, r.ratio))
                .collect::<Vec<_>>()
        };
        let _ = write!(s, "- **{}**: ", info.name);
        let mut parts = Vec::new();
        for which in ["worst", "best"] {
            let (help, hurt) = (list("base 16 helps", which), list("base 16 hurts", which));
            let mut p = format!("{which} layout: ");
            if help.is_empty() && hurt.is_empty() {
                p.push_str("no difference detected");
            } else {
                if !help.is_empty() {
                    let _ = write!(p, "base 16 helps at {}", help.join(", "));
                }
                if !hurt.is_empty() {
                    if !help.is_empty() {
                        p.push_str("; ");
                    }
                    let _ = write!(p, "base 16 hurts at {}", hurt.join(", "));
                }
            }
            parts.push(p);
        }
        let _ = writeln!(s, "{}.", parts.join("; "));
    }
    s
}
