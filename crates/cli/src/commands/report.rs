//! `gartowen report`: speed against error, with figures.

use crate::CliError;
use clap::Args;
use gartowen_bench::report::{
    build_report, read_baseline, write_report, Regression, Report, ReportConfig, ReportError,
};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Write the speed-against-error report: report.md, report.json and PNG figures.
///
/// Runs every sequence × compatible scrambler (plus unscrambled and plain random points) on
/// integrands with exact integrals (Heavisides, Gaussian, disks, bilinear, Genz families),
/// fits RMSE slopes at N = b^k, times every scrambler against lk-hash, tabulates the
/// randomization quality from the verify battery, and draws the RMSE, efficiency, point-set
/// (Figure 1) and discrepancy (Figure 2) figures.
///
/// The paper's claims as verdicts: every ART variant's record (what a renderer ships) and
/// acceleration bytes with the record-only and batch paths' speeds, and an equivalence
/// verdict against the Owen scramble of its base on each statistic (estimator variance at box
/// levels 1-3, mean L2-star D² of sz16 jointly and per pair): "equivalent within ±δ",
/// "different", or "inconclusive: about K seeds needed".
///
/// With --baseline, compares with an earlier report.json and exits 1 when a slope, an RMSE
/// or a speed ratio regresses beyond the noise threshold stated in the report. With
/// --compare, compares a stored report.json with the baseline instead of running (a CI gate
/// on the report job's artifact): the same rules and exit codes, nothing written.
///
/// Examples:
///   gartowen report --out report --quick           (under a minute on 2 cores)
///   gartowen report --out report                   (the full report, about 13 min on 2 cores)
///   gartowen report --out new --baseline old/report.json
///   gartowen report --compare new/report.json --baseline old/report.json
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct ReportArgs {
    /// Output directory (created if missing).
    #[arg(long, required_unless_present = "compare")]
    pub out: Option<PathBuf>,
    /// Smaller N, fewer replicates and methods.
    #[arg(long)]
    pub quick: bool,
    /// An earlier report.json to compare with (exit 1 on a regression).
    #[arg(long)]
    pub baseline: Option<PathBuf>,
    /// A stored report.json to compare with --baseline instead of running a report (exit 1
    /// on a regression, 0 without one; writes nothing).
    #[arg(long, value_name = "REPORT_JSON", requires = "baseline",
          conflicts_with_all = ["out", "quick", "seed", "margin"])]
    pub compare: Option<PathBuf>,
    /// Master seed of the replicates.
    #[arg(long, default_value_t = 2026)]
    pub seed: u64,
    /// Equivalence margin δ on ratios: an ART variant is "equivalent" to Owen on a statistic
    /// when the 90% interval of the ratio lies inside [1 − δ, 1 + δ] (0 < δ < 1).
    #[arg(long, default_value_t = gartowen::battery::equivalence::DEFAULT_MARGIN,
          value_parser = super::parse_margin)]
    pub margin: f64,
}

fn cli_error(e: ReportError) -> CliError {
    match e {
        ReportError::Io(m) => CliError::Io(m),
        other => CliError::Usage(other.to_string()),
    }
}

/// Runs `report`.
pub fn run(a: ReportArgs) -> Result<ExitCode, CliError> {
    // clap requires --out unless --compare, and --compare requires --baseline.
    let out = match (&a.out, &a.compare, &a.baseline) {
        (Some(out), _, _) => out,
        (None, Some(current), Some(baseline)) => return compare_stored(current, baseline),
        _ => {
            return Err(CliError::Usage(
                "report needs --out, or --compare with --baseline".into(),
            ))
        }
    };
    if let Some(b) = &a.baseline {
        use crate::paths::{named, refuse_input_inside};
        refuse_input_inside(named("--baseline", b), named("--out", out))?;
    }
    // Read the baseline first: a bad one is a usage error before minutes of work.
    let baseline = match &a.baseline {
        Some(p) => Some(read_baseline(p).map_err(cli_error)?),
        None => None,
    };
    std::fs::create_dir_all(out)
        .map_err(|e| CliError::Io(format!("cannot create {}: {e}", out.display())))?;
    let registry = gartowen::registry();
    let report = build_report(
        &registry,
        &ReportConfig {
            quick: a.quick,
            seed: a.seed,
            margin: a.margin,
        },
        &crate::progress::Bar::new("report [{bar:30}] {pos}/{len} {msg}"),
    )
    .map_err(cli_error)?;
    if let (Some(b), Some(path)) = (&baseline, &a.baseline) {
        refuse_incomparable(b, &report, path)?;
    }
    let staging = gartowen_bench::report::staging_dir(out);
    crate::cleanup::register(&staging);
    let written = write_report(&report, &registry, out, baseline.as_ref());
    crate::cleanup::unregister(&staging);
    let regressions = written.map_err(cli_error)?;
    let (methods, fits) = (report.methods_missing_slopes(), report.missed_slopes());
    crate::outln!(
        "report in {} ({} methods, {:.1} s); scrambled methods missing the predicted slope: {}",
        out.display(),
        report.methods.len(),
        report.seconds,
        if methods.is_empty() {
            "none".into()
        } else {
            format!(
                "{} ({} fits; listed in report.md)",
                methods.len(),
                fits.len()
            )
        }
    );
    regression_status(&regressions)
}

/// `report --compare CURRENT --baseline BASELINE`: the baseline gate on two stored reports.
fn compare_stored(current: &Path, baseline: &Path) -> Result<ExitCode, CliError> {
    let old = read_baseline(baseline).map_err(cli_error)?;
    let now = read_baseline(current).map_err(|e| match e {
        ReportError::Baseline(m) => CliError::Usage(format!("--compare: {m}")),
        other => cli_error(other),
    })?;
    let rows = refuse_incomparable(&old, &now, baseline)?;
    let regressions = gartowen_bench::report::compare(&old, &now);
    crate::outln!(
        "{} against {}: {rows} comparable rows, {} regressions",
        current.display(),
        baseline.display(),
        regressions.len()
    );
    regression_status(&regressions)
}

/// The rows `report` shares with `baseline`; none is a usage error (such a baseline would pass
/// every run).
fn refuse_incomparable(baseline: &Report, report: &Report, path: &Path) -> Result<usize, CliError> {
    match gartowen_bench::report::comparable_rows(baseline, report) {
        0 => Err(CliError::Usage(format!(
            "--baseline {}: no method, integrand or scrambler of it is in this run, so \
             nothing can be compared (a report of another --quick setting or version?)",
            path.display()
        ))),
        rows => Ok(rows),
    }
}

/// Prints one line per regression; exit 1 with any, 0 without.
fn regression_status(regressions: &[Regression]) -> Result<ExitCode, CliError> {
    for r in regressions {
        crate::outln!(
            "REGRESSION {}: {:.4e} -> {:.4e} ({})",
            r.what,
            r.before,
            r.after,
            r.rule
        );
    }
    Ok(if regressions.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
