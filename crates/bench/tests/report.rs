//! Baseline comparison and report files, on synthetic reports (the full pipeline runs in the
//! CLI's end-to-end test).

use gartowen_bench::figures::{loglog_lines, panel_grid, Panel, Series};
use gartowen_bench::harness::{ErrorCurve, HarnessConfig, Method, MethodResult};
use gartowen_bench::integrands::Smoothness;
use gartowen_bench::report::{compare, markdown, Report, SpeedRow, Thresholds};

fn report(slope: f64, rmse_last: f64, ratio: f64) -> Report {
    Report {
        schema: "gartowen-report".into(),
        schema_version: 1,
        tool_version: "0".into(),
        quick: true,
        harness: HarnessConfig {
            sizes: vec![64, 256, 1024],
            replicates: 8,
            seed: 1,
        },
        integrands: vec!["bilinear".into()],
        methods: vec![MethodResult {
            method: Method {
                sequence: "sobol".into(),
                scrambler: "art-owen-2".into(),
            },
            label: "sobol+art-owen-2".into(),
            base: 2,
            curves: vec![ErrorCurve {
                integrand: "bilinear".into(),
                smoothness: Smoothness::Smooth,
                n: vec![64, 256, 1024],
                rmse: vec![1e-3, 1e-4, rmse_last],
                slope: Some(slope),
            }],
            seconds_per_point: 1e-8,
        }],
        slopes: vec![],
        speed: vec![SpeedRow {
            scrambler: "art-owen-2".into(),
            base: 2,
            ns_per_coord: 10.0,
            ratio_to_lk_hash: ratio,
            table_bytes: 0,
        }],
        quality: vec![],
        discrepancy: vec![],
        thresholds: Thresholds {
            slope: 0.15,
            rmse_factor: 1.75,
            speed_factor: 1.5,
        },
        threads: 2,
        seconds: 1.0,
    }
}

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
