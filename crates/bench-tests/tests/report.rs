//! Baseline comparison and report files, on synthetic reports (the full pipeline runs in the
//! CLI's end-to-end test).

use gartowen_bench::figures::{loglog_lines, panel_grid, Panel, Series};
use gartowen_bench::report::{comparable_rows, compare, markdown, Report};

use crate::common;
use common::report;

#[test]
fn identical_reports_do_not_regress_and_each_kind_of_regression_is_caught() {
    let base = report(-1.5, 1e-5, 2.0);
    assert!(compare(&base, &base).is_empty());
    // Within the noise thresholds: no regression.
    assert!(compare(&base, &report(-1.4, 1.5e-5, 2.9)).is_empty());
    let worse_slope = compare(&base, &report(-1.2, 1e-5, 2.0));
    assert_eq!(worse_slope.len(), 1);
    assert!(worse_slope[0].what.contains("slope"));
    let worse_rmse = compare(&base, &report(-1.5, 2e-5, 2.0));
    assert_eq!(worse_rmse.len(), 1);
    assert!(worse_rmse[0].what.contains("RMSE at N = 1024"));
    let slower = compare(&base, &report(-1.5, 1e-5, 3.5));
    assert_eq!(slower.len(), 1);
    assert!(slower[0].what.contains("relative to lk-hash"));
    // A better run is not a regression.
    assert!(compare(&base, &report(-1.7, 5e-6, 1.0)).is_empty());
}

#[test]
fn a_baseline_sharing_no_row_compares_nothing() {
    let base = report(-1.5, 1e-5, 2.0);
    let rows = base.methods.iter().map(|m| m.curves.len()).sum::<usize>() + base.speed.len();
    assert!(rows > 0);
    assert_eq!(comparable_rows(&base, &base), rows);
    let mut other = base.clone();
    other
        .methods
        .iter_mut()
        .for_each(|m| m.label.push_str(" (renamed)"));
    assert_eq!(comparable_rows(&other, &base), base.speed.len());
    other
        .speed
        .iter_mut()
        .for_each(|s| s.scrambler.push_str("-renamed"));
    assert_eq!(comparable_rows(&other, &base), 0);
    // Another integrand under the same label is not comparable either.
    let mut integrands = base.clone();
    integrands.speed.clear();
    for m in &mut integrands.methods {
        m.curves.iter_mut().for_each(|c| c.integrand.push('!'));
    }
    assert_eq!(comparable_rows(&integrands, &base), 0);
}

/// A report whose one speed row has these per-round ratios (median as its ratio).
fn report_with_rounds(rounds: &[f64]) -> Report {
    let mut r = report(-1.5, 1e-5, gartowen_bench::speed::median(rounds));
    r.speed[0].ratio_rounds = rounds.to_vec();
    r
}

#[test]
fn one_disturbed_round_is_not_a_regression_but_a_slower_scrambler_is() {
    // The false alarm: ratio 1.9 → 3.4 because the reference was timed in a fast
    // moment. With rounds, that is one round in five, and the median stays.
    let base = report_with_rounds(&[1.9, 1.95, 1.85, 1.9, 1.92]);
    let disturbed = report_with_rounds(&[1.9, 3.4, 1.88, 1.93, 1.91]);
    assert!(compare(&base, &disturbed).is_empty());
    // Before rounds existed (one timing), the same disturbance was flagged.
    assert_eq!(
        compare(&report(-1.5, 1e-5, 1.9), &report(-1.5, 1e-5, 3.4)).len(),
        1
    );
    // A scrambler that became 2× slower in every round is caught.
    let slower = report_with_rounds(&[3.8, 3.9, 3.7, 3.85, 3.8]);
    let r = compare(&base, &slower);
    assert_eq!(r.len(), 1);
    assert!(r[0].rule.contains("standard errors"), "{}", r[0].rule);
    // Noisy runs widen the tolerance: 1.7× in medians over very spread rounds passes…
    let spread = report_with_rounds(&[1.2, 1.9, 3.0, 1.5, 2.4]);
    let spread_slow = report_with_rounds(&[2.0, 3.2, 5.1, 2.6, 4.1]);
    assert!(compare(&spread, &spread_slow).is_empty());
    // …and the same medians over quiet rounds fail.
    let quiet_slow = report_with_rounds(&[3.2, 3.25, 3.2, 3.15, 3.2]);
    let quiet = report_with_rounds(&[1.9, 1.9, 1.9, 1.9, 1.9]);
    assert_eq!(compare(&quiet, &quiet_slow).len(), 1);
}

#[test]
fn a_baseline_without_speed_z_reads_with_the_default() {
    let r = report(-1.5, 1e-5, 2.0);
    let mut v = serde_json::to_value(&r).unwrap();
    v["thresholds"].as_object_mut().unwrap().remove("speed_z");
    v["speed"][0]
        .as_object_mut()
        .unwrap()
        .remove("ratio_rounds");
    let back: Report = serde_json::from_value(v).unwrap();
    assert_eq!(back, r);
}

#[test]
fn the_report_round_trips_and_states_its_thresholds() {
    let r = report(-1.5, 1e-5, 2.0);
    let back: Report = serde_json::from_str(&serde_json::to_string(&r).unwrap()).unwrap();
    assert_eq!(back, r);
    let regressions = compare(&r, &report(-1.0, 1e-5, 2.0));
    let md = markdown(&r, &["a.png".into()], Some(&regressions));
    assert!(md.contains("Thresholds: slope +0.15, RMSE ×1.750, speed ratio ×1.5"));
    assert!(md.contains("REGRESSION sobol+art-owen-2 on bilinear: slope"));
    assert!(md.contains("![a.png](a.png)"));
}

#[test]
fn figures_are_png_files() {
    let dir = std::env::temp_dir().join(format!("gartowen-fig-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let lines = dir.join("lines.png");
    loglog_lines(
        &lines,
        "t",
        "N",
        "RMSE",
        &[Series {
            label: "a".into(),
            points: vec![(16.0, 0.1), (256.0, 0.001)],
        }],
        &[-1.0],
    )
    .unwrap();
    let grid = dir.join("grid.png");
    panel_grid(
        &grid,
        "g",
        &["c".into()],
        &[(
            "row".into(),
            vec![
                Panel::Scatter(vec![[0.1, 0.2], [0.7, 0.9]]),
                Panel::Spectrum {
                    values: vec![1.0; 9],
                    max_freq: 1,
                },
            ],
        )],
    )
    .unwrap();
    for f in [lines, grid] {
        let bytes = std::fs::read(&f).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        assert!(bytes.len() > 1000);
    }
    // An unwritable path is an error, not a panic.
    assert!(loglog_lines(
        std::path::Path::new("/nonexistent/dir/x.png"),
        "t",
        "N",
        "y",
        &[],
        &[]
    )
    .is_err());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Each rule says "more than": a run exactly at a threshold is not a regression.
#[test]
fn a_value_exactly_at_a_threshold_is_not_a_regression() {
    let base = report(-1.5, 1e-5, 2.0);
    let t = &base.thresholds;
    let at_slope = report(-1.5 + t.slope, 1e-5, 2.0);
    let at_rmse = report(-1.5, 1e-5 * t.rmse_factor, 2.0);
    let row = &base.speed[0];
    let allowed = gartowen_bench::speed::allowed_growth(row, row, t.speed_factor, t.speed_z);
    let at_speed = report(-1.5, 1e-5, 2.0 * allowed);
    for (what, r) in [("slope", at_slope), ("rmse", at_rmse), ("speed", at_speed)] {
        assert!(compare(&base, &r).is_empty(), "{what}");
    }
}

/// Figure 2c's number: max over pairs / min over pairs of the mean 2-D D², per size.
#[test]
fn pair_spread_is_max_over_min_per_size() {
    let c = gartowen_bench::report::DiscrepancyCurve {
        scrambler: "x".into(),
        n: vec![16, 32],
        joint: vec![1.0, 0.5],
        pairs: vec![[0, 1], [0, 2], [0, 3]],
        pair_values: vec![vec![2.0, 8.0, 4.0], vec![3.0, 3.0, 3.0]],
        seeds: 4,
        joint_se: vec![0.1, 0.1],
        pair_se: vec![vec![0.0; 3]; 2],
        seeds_per_n: vec![],
    };
    assert_eq!(c.pair_spread(), vec![4.0, 1.0]);
    // Its standard error by the delta method on the extreme pairs (8 ± 0.4 over 2 ± 0.1).
    let mut c = c;
    c.pair_se = vec![vec![0.1, 0.4, 0.3], vec![0.0; 3]];
    let se = c.pair_spread_se();
    assert!(
        (se[0] - 4.0 * (0.05f64.powi(2) * 2.0).sqrt()).abs() < 1e-12,
        "{se:?}"
    );
    assert_eq!(se[1], 0.0);
}

/// The report's variance ratios: Owen's oracle sits at 1 within its error at every level, the
/// identity ("none") has zero variance (ratio 0), too few expected hits give no ratio, rows are
/// the same for one and two threads and survive a JSON round trip (a baseline must load).
#[test]
fn owen_variance_ratios_put_the_oracle_at_one_and_the_identity_at_zero() {
    use gartowen_bench::fidelity::{variance_ratios, VarianceRow};
    let registry = gartowen::registry();
    let requests = vec![("owen-oracle".to_string(), 2), ("none".to_string(), 2)];
    let rows = variance_ratios(&registry, &requests, 400);
    let oracle = &rows[0];
    assert_eq!(oracle.levels, vec![1, 2, 3]);
    for (r, se) in oracle.ratio.iter().zip(&oracle.ratio_se) {
        let (r, se) = (r.unwrap(), se.unwrap());
        // 4 SE: two-sided false-alarm rate 6e-5 per level under the CLT.
        assert!((r - 1.0).abs() < 4.0 * se, "oracle ratio {r} ± {se}");
    }
    assert!(
        rows[1].ratio.iter().all(|&r| r == Some(0.0)),
        "{:?}",
        rows[1].ratio
    );
    // Base 256, 3 digits: 64 · 400 · 2^-24 expected hits, far under 10: no ratio.
    let big = variance_ratios(&registry, &[("owen-oracle:base=256".to_string(), 256)], 400);
    assert_eq!(big[0].ratio[2], None);
    assert!(big[0].ratio[0].is_some());
    let json = serde_json::to_string(&rows).unwrap();
    let back: Vec<VarianceRow> = serde_json::from_str(&json).unwrap();
    assert_eq!(back, rows);
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| variance_ratios(&registry, &requests, 400));
    assert_eq!(one, rows);
}
