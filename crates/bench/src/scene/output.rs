//! Writing the scene report: scene.md (tables and the answer in words), scene.json and the
//! PNG figures, staged and moved into place only when complete.

use super::measure::extremes;
use super::report::{
    answer_in_words, compare_scenes, SceneRegression, SceneReport, HEADLINE_ALPHA,
    REGRESSION_FACTOR, REGRESSION_Z,
};
use crate::figures::FigureError;
use std::fmt::Write as _;
use std::path::Path;

/// Draws every scene's curves and the image panels into `dir`; returns the file names.
pub fn write_scene_figures(report: &SceneReport, dir: &Path) -> Result<Vec<String>, FigureError> {
    let mut names = Vec::new();
    for info in &report.scenes {
        let name = format!("scene-{}.png", info.name);
        super::figures::curves_figure(&dir.join(&name), report, &info.name)?;
        names.push(name);
        if info.reference_image.is_empty() {
            continue;
        }
        let side = (info.pixels as f64).sqrt().round() as usize;
        let renders: Vec<(String, Vec<f64>)> = report
            .results
            .iter()
            .filter(|r| r.scene == info.name && r.render.len() == info.pixels)
            .map(|r| (r.method.clone(), r.render.clone()))
            .collect();
        let n = report.image_config.sizes.iter().min().copied().unwrap_or(0);
        let name = format!("scene-{}-renders.png", info.name);
        super::figures::image_figure(
            &dir.join(&name),
            &format!(
                "{}: reference and one rendering per method at N = {n} (first layout, seed 0)",
                info.name
            ),
            side,
            &info.reference_image,
            &renders,
        )?;
        names.push(name);
    }
    Ok(names)
}

fn sci(v: f64) -> String {
    format!("{v:.3e}")
}

/// The scene section as markdown; `h` is the heading prefix of its sections (`##` alone,
/// `###` inside the main report).
pub fn scene_markdown(
    report: &SceneReport,
    figures: &[String],
    regressions: Option<&[SceneRegression]>,
    h: &str,
) -> String {
    let mut s = String::new();
    let (c, ic) = (&report.config, &report.image_config);
    let _ = writeln!(
        s,
        "Single-estimator scenes: N ∈ {:?}, {} seeds per point. Image: N ∈ {:?}, {} seed(s) \
         per pixel over {} pixels. Every method reads the same layouts; RMSE is over seeds \
         (and pixels), its standard error by the delta method. {} threads, {:.1} s.\n",
        c.sizes,
        c.seeds,
        ic.sizes,
        ic.seeds,
        report.scenes.iter().map(|x| x.pixels).max().unwrap_or(1),
        report.threads,
        report.seconds
    );
    let _ = writeln!(s, "{h} Scenes\n");
    let _ = writeln!(
        s,
        "| scene | what | slots | reference (mean) | reference error ≤ |\n|---|---|---|---|---|"
    );
    for i in &report.scenes {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {:.6} | {:.0e} |",
            i.name,
            i.summary,
            i.slots.join(" "),
            i.reference_mean,
            i.reference_error
        );
    }
    if !report.headline.is_empty() {
        let _ = writeln!(s, "\n{h} Base 16 against binary: the answer\n");
        let _ = writeln!(
            s,
            "Ratio = RMSE(base 16) / RMSE(binary), each method at its own best, median and \
             worst layout. A verdict needs |ln ratio| / SE > {:.2} (two-sided α = {} with \
             Bonferroni over the {} comparisons); the SE ignores that the extreme layouts were \
             selected, so the worst/best verdicts are somewhat optimistic.\n",
            report.headline_z,
            HEADLINE_ALPHA,
            report.headline.len()
        );
        s.push_str(&answer_in_words(report));
        let _ = writeln!(
            s,
            "\n| scene | N | layout | base 16 | binary | ratio | SE(ln) | verdict |\n|---|---|---|---|---|---|---|---|"
        );
        for r in &report.headline {
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {:.3} | {:.3} | {} |",
                r.scene, r.n, r.which, r.base16, r.binary, r.ratio, r.log_se, r.verdict
            );
        }
    }
    if !report.equivalence.is_empty() {
        let _ = writeln!(s, "\n{h} ART against full-tree Owen in the scenes\n");
        let _ = writeln!(
            s,
            "MSE(ART) / MSE(Owen of the same base), the MSE averaged over the layouts: \
             \"equivalent within ±δ\" when the 90% interval lies inside [1 − δ, 1 + δ] (TOST, \
             α = 0.05), \"different\" when the two-sided interval at α/m (Bonferroni over the \
             sizes) excludes 1. \"detectable\" is the change the difference test finds with 80% \
             power.\n\n| scene | N | ART | Owen | ratio | 90% interval | detectable | verdict |\n\
             |---|---|---|---|---|---|---|---|"
        );
        for e in &report.equivalence {
            let j = &e.judgement;
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {:.3} | [{:.3}, {:.3}] | ±{:.1}% | {} |",
                e.scene,
                e.n,
                e.implementation,
                e.reference,
                j.ratio,
                j.tost_interval[0],
                j.tost_interval[1],
                100.0 * j.detectable,
                j.words()
            );
        }
    }
    for info in &report.scenes {
        let _ = writeln!(s, "\n{h} {}\n\n{}\n", info.name, info.summary);
        let _ = writeln!(
            s,
            "| method | N | best | median | worst (layout) | s/sample | efficiency 1/(MSE·time of N) |\n|---|---|---|---|---|---|---|"
        );
        for r in report.results.iter().filter(|r| r.scene == info.name) {
            for (k, n) in r.n.iter().enumerate() {
                let e = extremes(r, k);
                let cell = |i: usize| {
                    let l = &r.layouts[e[i].0];
                    format!("{} ± {:.1e}", sci(l.rmse[k]), l.rmse_se[k])
                };
                let worst = &r.layouts[e[2].0];
                let _ = writeln!(
                    s,
                    "| {} | {n} | {} | {} | {} (`{}`, {}) | {:.1e} | {:.2e} |",
                    r.method,
                    cell(0),
                    cell(1),
                    cell(2),
                    worst.layout,
                    worst.relation.words(),
                    r.seconds_per_sample,
                    1.0 / (e[1].1.powi(2) * r.seconds_per_sample * *n as f64)
                );
            }
        }
        for f in figures
            .iter()
            .filter(|f| f.starts_with(&format!("scene-{}", info.name)))
        {
            let _ = writeln!(s, "\n![{f}]({f})");
        }
    }
    if let Some(regs) = regressions {
        let _ = writeln!(s, "\n{h} Against the baseline\n");
        let _ = writeln!(
            s,
            "A regression: the median- or worst-layout RMSE grew by more than ×{REGRESSION_FACTOR} \
             and by more than {REGRESSION_Z} combined standard errors.\n"
        );
        if regs.is_empty() {
            s.push_str("No regression.\n");
        }
        for r in regs {
            let _ = writeln!(
                s,
                "- REGRESSION {}: {:.4e} → {:.4e}",
                r.what, r.before, r.after
            );
        }
    }
    s
}

/// Writes scene.json, scene.md and the figures into `dir` (staged first, so a failure leaves
/// an earlier report intact); returns the regressions against `baseline`.
pub fn write_scene_report(
    report: &SceneReport,
    dir: &Path,
    baseline: Option<&SceneReport>,
) -> Result<Vec<SceneRegression>, String> {
    let regressions = baseline.map(|b| compare_scenes(b, report));
    crate::staged::write_staged(dir, |staging| {
        let mut names = write_scene_figures(report, staging).map_err(|e| e.to_string())?;
        let md = format!(
            "# gartowen scene report\n\n{}",
            scene_markdown(report, &names, regressions.as_deref(), "##")
        );
        for (name, text) in [
            (
                "scene.json",
                serde_json::to_string_pretty(report).expect("serializable"),
            ),
            ("scene.md", md),
        ] {
            std::fs::write(staging.join(name), text)
                .map_err(|e| format!("cannot write {name}: {e}"))?;
            names.push(name.into());
        }
        Ok(names)
    })?;
    Ok(regressions.unwrap_or_default())
}
