//! report.md.

use super::*;

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
    let misses = report.methods_missing_slopes();
    md += &format!(
        "\nScrambled methods that miss the predicted rate: {}.\n\n",
        if misses.is_empty() {
            "none".to_string()
        } else {
            misses.join(", ")
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
    md += &crate::equivalence::translate_markdown(&report.owen_variance);
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
