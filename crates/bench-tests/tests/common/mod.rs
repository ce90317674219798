//! A small synthetic report the report tests share.

use gartowen_bench::harness::{ErrorCurve, HarnessConfig, Method, MethodResult};
use gartowen_bench::integrands::Smoothness;
use gartowen_bench::report::{Report, SpeedRow, Thresholds};

/// One method on one integrand with this slope and last RMSE, one speed row with this ratio.
pub fn report(slope: f64, rmse_last: f64, ratio: f64) -> Report {
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
            ratio_rounds: vec![],
            table_bytes: 0,
        }],
        quality: vec![],
        discrepancy: vec![],
        sobol_owen: None,
        owen_variance: vec![],
        tradeoff: vec![],
        equivalence: vec![],
        scene: None,
        thresholds: Thresholds {
            slope: 0.15,
            rmse_factor: 1.75,
            speed_factor: 1.5,
            speed_z: 3.0,
        },
        threads: 2,
        seconds: 1.0,
    }
}
