//! The report's speed table and the noise model its baseline gate uses.
//!
//! Times on a shared machine move by ±15% between runs and now and then by 2× for a moment
//! (another job, a frequency step). One timing of `lk-hash` divides every ratio of a run, so a
//! single disturbed reference once turned three rows into "regressions". Hence:
//!
//! - **Repeat and pair.** Every scrambler, `lk-hash` included, is timed in each of R rounds; a
//!   round's ratio divides by the `lk-hash` time of the same round, so a slow stretch of the
//!   machine moves numerator and denominator together. The order rotates by one scrambler per
//!   round, so no entry always runs just after the reference.
//! - **Median.** A row's ratio is the median of its R round ratios: one disturbed round in R
//!   (fewer than half) cannot move it past the undisturbed ones.
//! - **Noise from the run itself.** A row's noise is the standard error of the median of
//!   the log ratios, `se = 1.2533 · σ / √R` with `σ = 1.4826 · MAD` (the normal-consistent
//!   robust scale; 1.2533 = √(π/2) is the median's efficiency loss against the mean).
//! - **Tolerance and test.** A row regresses when `ln(after / before) > ln(factor) + z ·
//!   √(se_before² + se_after²)`: the change must exceed the stated effect size (`factor`,
//!   1.5×) by z standard errors. Under normal log-noise and a true change of at most
//!   `factor`, one row false-alarms with probability at most `1 − Φ(z)` (0.135% at z = 3);
//!   over the report's rows, at most their number times that (Bonferroni). A baseline of an
//!   older version without rounds counts as noise-free (`se = 0`), which leaves the factor.

use gartowen::core::{BuildContext, Registry, Scrambler, SplitMix64, Width};
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Rounds per scrambler in a quick report.
pub const ROUNDS_QUICK: usize = 5;
/// Rounds per scrambler in a full report.
pub const ROUNDS_FULL: usize = 9;

/// The speed of one scrambler.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpeedRow {
    /// Registry request.
    pub scrambler: String,
    /// Base.
    pub base: u32,
    /// Nanoseconds per 32-bit coordinate (this machine, this run): the median over rounds.
    pub ns_per_coord: f64,
    /// The median over rounds of ns_per_coord divided by that of `lk-hash` in the same round.
    pub ratio_to_lk_hash: f64,
    /// Each round's ratio to `lk-hash`, in round order (empty in reports before rounds).
    #[serde(default)]
    pub ratio_rounds: Vec<f64>,
    /// Bytes of tables the scrambler holds.
    pub table_bytes: usize,
}

/// The median of `xs` (the mean of the middle two for an even count); NaN when empty.
pub fn median(xs: &[f64]) -> f64 {
    if xs.is_empty() {
        return f64::NAN;
    }
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    let m = v.len() / 2;
    if v.len() % 2 == 1 {
        v[m]
    } else {
        (v[m - 1] + v[m]) / 2.0
    }
}

/// Standard error of the median of ln(ratio) over `rounds` (see the module doc); 0 for fewer
/// than 3 rounds, where no spread can be estimated.
pub fn log_ratio_standard_error(rounds: &[f64]) -> f64 {
    if rounds.len() < 3 {
        return 0.0;
    }
    let logs: Vec<f64> = rounds.iter().map(|r| r.ln()).collect();
    let mid = median(&logs);
    let deviations: Vec<f64> = logs.iter().map(|l| (l - mid).abs()).collect();
    let sigma = 1.4826 * median(&deviations);
    std::f64::consts::FRAC_PI_2.sqrt() * sigma / (rounds.len() as f64).sqrt()
}

/// The largest `after / before` ratio of ratios that is not a regression: `factor` widened
/// by `z` standard errors of the two medians (see the module doc).
pub fn allowed_growth(before: &SpeedRow, after: &SpeedRow, factor: f64, z: f64) -> f64 {
    let a = log_ratio_standard_error(&before.ratio_rounds);
    let b = log_ratio_standard_error(&after.ratio_rounds);
    (factor.ln() + z * (a * a + b * b).sqrt()).exp()
}

/// Times `passes` passes of `words` through `s`, in ns per coordinate.
fn time_passes(s: &dyn Scrambler, words: &[u64], passes: u32) -> f64 {
    let mut sink = 0u64;
    let t = Instant::now();
    for r in 0..passes {
        for (i, &w) in words.iter().enumerate() {
            sink ^= s.scramble(w, Width::W32, (i as u32 + r) & 7);
        }
    }
    std::hint::black_box(sink);
    t.elapsed().as_secs_f64() * 1e9 / (passes as f64 * words.len() as f64)
}

/// Speeds of every registry entry (oracles in base 16) over `rounds` rounds, with `lk-hash`
/// as the reference of each round. Panics only if a registry entry fails to build with its
/// own defaults (a registry bug).
pub fn measure_speed_rounds(registry: &Registry, passes: u32, rounds: usize) -> Vec<SpeedRow> {
    let entries: Vec<(String, u32, Box<dyn Scrambler>)> = registry
        .specs()
        .iter()
        .map(|spec| {
            let request = if spec.name == "owen-oracle" {
                "owen-oracle:base=16".to_string()
            } else {
                spec.name.to_string()
            };
            // The oracle is ~100× slower than the rest; fewer passes keep the run short.
            let p = if spec.name == "owen-oracle" {
                passes / 8 + 1
            } else {
                passes
            };
            let s = registry
                .build_with(
                    &request,
                    &BuildContext {
                        seed: 1,
                        default_base: spec.default_base,
                    },
                )
                .expect("registry entry builds with its defaults");
            (request, p, s)
        })
        .collect();
    let reference = entries.iter().position(|(r, _, _)| r == "lk-hash");
    let mut rng = SplitMix64::new(9);
    let words: Vec<u64> = (0..4096).map(|_| rng.next_u32() as u64).collect();
    let n = entries.len();
    let mut ns = vec![Vec::with_capacity(rounds); n];
    for round in 0..rounds {
        for k in 0..n {
            let e = (k + round) % n;
            let (_, p, s) = &entries[e];
            ns[e].push(time_passes(s.as_ref(), &words, *p));
        }
    }
    entries
        .iter()
        .enumerate()
        .map(|(e, (request, _, s))| {
            let ratio_rounds: Vec<f64> = match reference {
                Some(r) => ns[e].iter().zip(&ns[r]).map(|(a, b)| a / b).collect(),
                None => ns[e].clone(),
            };
            SpeedRow {
                scrambler: request.clone(),
                base: s.base().base(),
                ns_per_coord: median(&ns[e]),
                ratio_to_lk_hash: median(&ratio_rounds),
                ratio_rounds,
                table_bytes: s.table_bytes(),
            }
        })
        .collect()
}

/// The report's speed table: 8 passes × [`ROUNDS_QUICK`] rounds quick, 64 × [`ROUNDS_FULL`]
/// full.
pub fn measure_speed(registry: &Registry, quick: bool) -> Vec<SpeedRow> {
    if quick {
        measure_speed_rounds(registry, 8, ROUNDS_QUICK)
    } else {
        measure_speed_rounds(registry, 64, ROUNDS_FULL)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(rounds: &[f64]) -> SpeedRow {
        SpeedRow {
            scrambler: "x".into(),
            base: 2,
            ns_per_coord: 1.0,
            ratio_to_lk_hash: median(rounds),
            ratio_rounds: rounds.to_vec(),
            table_bytes: 0,
        }
    }

    #[test]
    fn every_row_has_its_rounds_and_the_reference_divides_each_round() {
        let registry = gartowen::registry();
        let rows = measure_speed_rounds(&registry, 1, 3);
        assert_eq!(rows.len(), registry.specs().len());
        for r in &rows {
            assert_eq!(r.ratio_rounds.len(), 3, "{}", r.scrambler);
            assert_eq!(
                r.ratio_to_lk_hash,
                median(&r.ratio_rounds),
                "{}",
                r.scrambler
            );
            assert!(r.ns_per_coord > 0.0 && r.ratio_to_lk_hash > 0.0);
        }
        let lk = rows.iter().find(|r| r.scrambler == "lk-hash").unwrap();
        assert_eq!(lk.ratio_rounds, vec![1.0; 3]);
        let oracle = rows
            .iter()
            .find(|r| r.scrambler.starts_with("owen-oracle"))
            .unwrap();
        assert_eq!(
            (oracle.scrambler.as_str(), oracle.base),
            ("owen-oracle:base=16", 16)
        );
    }

    #[test]
    fn the_report_table_has_the_stated_rounds() {
        let registry = gartowen::registry();
        let rows = measure_speed(&registry, true);
        assert_eq!(rows.len(), registry.specs().len());
        assert!(rows.iter().all(|r| r.ratio_rounds.len() == ROUNDS_QUICK));
    }

    #[test]
    fn median_of_odd_even_and_empty() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&[]).is_nan());
        // One wild round in five does not move it.
        assert_eq!(median(&[2.0, 2.1, 9.0, 1.9, 2.05]), 2.05);
        assert_eq!(median(&[5.0, 1.0, 50.0, 4.0, 3.0, 2.0, 6.0]), 4.0);
    }

    #[test]
    fn standard_error_matches_the_formula() {
        // ln values 0, ±d, ±2d: median 0, absolute deviations 0, d, d, 2d, 2d: MAD = d.
        let d: f64 = 0.1;
        let r: Vec<f64> = [-2.0, -1.0, 0.0, 1.0, 2.0]
            .iter()
            .map(|k| (k * d).exp())
            .collect();
        let se = log_ratio_standard_error(&r);
        let expect = std::f64::consts::FRAC_PI_2.sqrt() * 1.4826 * d / 5f64.sqrt();
        assert!((se - expect).abs() < 1e-12, "{se} {expect}");
        // Scale-free: multiplying every ratio leaves it.
        let scaled: Vec<f64> = r.iter().map(|x| x * 7.0).collect();
        assert!((log_ratio_standard_error(&scaled) - se).abs() < 1e-12);
        assert_eq!(log_ratio_standard_error(&[1.0, 2.0]), 0.0);
        // Three rounds are enough to estimate a spread.
        assert!(log_ratio_standard_error(&[1.0, 2.0, 4.0]) > 0.0);
        assert_eq!(log_ratio_standard_error(&[2.0; 6]), 0.0);
    }

    #[test]
    fn noisy_rows_widen_the_tolerance_and_quiet_rows_keep_the_factor() {
        let quiet = row(&[2.0; 5]);
        assert!((allowed_growth(&quiet, &quiet, 1.5, 3.0) - 1.5).abs() < 1e-12);
        let noisy = row(&[1.6, 2.0, 2.5, 1.8, 2.2]);
        let widened = allowed_growth(&noisy, &quiet, 1.5, 3.0);
        assert!(widened > 1.6, "{widened}");
        // z = 0 is the bare factor whatever the noise.
        assert!((allowed_growth(&noisy, &noisy, 1.5, 0.0) - 1.5).abs() < 1e-12);
    }
}
