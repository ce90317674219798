//! Running the report's measurements: the harness, speeds, quality, curves, variance ratios, scenes.

use super::*;
use gartowen::core::{Progress, Silent};

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

/// Runs everything. `progress` starts with the number of parts (one per method, then speed,
/// randomization quality, discrepancy curves and the rest); its message names the part
/// running, and it advances as each finishes.
pub fn build_report(
    registry: &Registry,
    config: &ReportConfig,
    progress: &dyn Progress,
) -> Result<Report, ReportError> {
    let start = Instant::now();
    let families = standard_families(4);
    let harness = harness_config(config.quick, config.seed);
    let mut methods = methods_for(registry, &SequenceKind::ALL);
    if config.quick {
        methods = quick_methods(methods);
    }
    progress.start(methods.len() as u64 + 4, "parts");
    let mut results = Vec::with_capacity(methods.len());
    for m in &methods {
        progress.message(&m.label());
        results.push(run_method(registry, m, &families, &harness).map_err(ReportError::Harness)?);
        progress.advance(1);
    }
    progress.message("speed");
    let speed = measure_speed(registry, config.quick);
    progress.advance(1);
    progress.message("randomization quality");
    let requests: Vec<String> = speed.iter().map(|s| s.scrambler.clone()).collect();
    let quality = measure_quality(registry, &requests);
    progress.advance(1);
    progress.message("discrepancy curves");
    let discrepancy = discrepancy_curves(registry, config.quick);
    let sobol_owen = crate::curves::sobol_owen_curve(registry, config.quick);
    progress.advance(1);
    progress.message("Owen variance, trade-off, scenes");
    let mut with_base: Vec<(String, u32)> = speed
        .iter()
        .map(|s| (s.scrambler.clone(), s.base))
        .collect();
    // The Q-ART paper's variant, judged against translation-only Q-ART as well as Owen.
    with_base.push(("q-art-4:compose=linear".into(), 4));
    with_base.push((crate::curves::FIXED_TABLE.into(), 16));
    for (control, base) in crate::equivalence::CONTROLS {
        if !with_base.iter().any(|(r, _)| r == control) {
            with_base.push((control.into(), base));
        }
    }
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
        &Silent,
    )
    .map_err(|e| ReportError::Harness(HarnessError::Method(e)))?;
    progress.advance(1);
    progress.finish();
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
        sobol_owen: Some(sobol_owen),
        owen_variance,
        tradeoff,
        equivalence,
        scene: Some(scene),
        threads: rayon::current_num_threads(),
        seconds: start.elapsed().as_secs_f64(),
    })
}
