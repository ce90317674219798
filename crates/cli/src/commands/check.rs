//! `gartowen check`: net properties of a point file by elementary-interval counting.

use crate::input::{read_points_typed, FloatWords, InputFormat};
use crate::CliError;
use clap::Args;
use gartowen::certificate::{CertVerdict, Certificate};
use gartowen::net_check::{
    check_points_owned, snap_floats, snap_note, NetOutcome, NetQuery, Progress,
};
use gartowen::netcheck::witness::net_witness;
use gartowen::netcheck::CheckBase;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;
use std::path::PathBuf;
use std::process::ExitCode;

/// Check net properties of a point set by counting points in elementary intervals.
///
/// Without --t it reports the t-value (exit 0). With --t T it checks the (T,m,s)-net property
/// and exits 1 if it fails, naming the first failing shape and box. With --sequence it checks
/// every block of b^k consecutive points for k ≤ m (the (t,s)-sequence property).
///
/// A shape (d_1..d_s) with Σd = m − t divides [0,1)^s into boxes of side b^-d_j; a (t,m,s)-net
/// has exactly b^t of its b^m points in every box. Exit codes: 0 holds (or report only),
/// 1 violated, 2 bad input.
///
/// Examples:
///   gartowen generate --seq sz16 --dims 16 --log2-n 12 --format npy -o sz16.npy
///   gartowen check sz16.npy --base 16 --t 0
///   gartowen check sobol.npy --base 2 --projections pairs --json
///   gartowen check sz4.hex --base 4 --sequence --t 0
///   gartowen check sz16.npy --base 16 --witness sz16.witness && proofs/revalidate.sh sz16.witness
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct CheckArgs {
    /// Point file: .npy (float64, uint32, uint64), .csv (floats) or .hex (words).
    pub file: PathBuf,
    /// Base b ≥ 2 of the elementary intervals (any integer; 2^q uses a fast path).
    #[arg(long)]
    pub base: u64,
    /// m with N = b^m (default: implied by N; with --sequence, the largest block exponent).
    #[arg(long)]
    pub m: Option<u32>,
    /// Check this t (exit 1 when violated) instead of reporting the t-value.
    #[arg(long)]
    pub t: Option<u32>,
    /// Check the (t,s)-sequence property: every block of b^k consecutive points, k ≤ m.
    #[arg(long)]
    pub sequence: bool,
    /// Projections: pairs, groups:G (sliding windows), blocks:G (aligned), or lists like 0,1;2,3.
    #[arg(long)]
    pub projections: Option<String>,
    /// Include per-shape count histograms (with --t, whole set only).
    #[arg(long)]
    pub histograms: bool,
    /// Input format.
    #[arg(long, value_enum, default_value_t = InputFormat::Auto)]
    pub format: InputFormat,
    /// Print a JSON report on standard output.
    #[arg(long)]
    pub json: bool,
    /// Also write JUnit XML: one testcase per projection checked.
    #[arg(long)]
    pub junit: Option<PathBuf>,
    /// Worker threads (results are identical for any count; default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Also write what the verdict rests on (the words read, the failing box, or the t-value's
    /// box at t − 1) for `proofs/revalidate.sh FILE`, which re-checks it with the checker
    /// extracted from the Coq proofs. Whole sets only (not with --sequence or --projections).
    #[arg(long, value_name = "FILE")]
    pub witness: Option<PathBuf>,
    /// Read floats in a base that is not a power of two as they are (floor), without snapping
    /// them to the base's grid. A float cannot hold 1/3: unsnapped, a base-3 net reads wrong.
    #[arg(long)]
    pub no_snap: bool,
}

/// The most worker threads `--threads` accepts.
pub const MAX_THREADS: usize = 1024;

fn usage(e: impl std::fmt::Display) -> CliError {
    CliError::Usage(e.to_string())
}

/// A progress bar on a terminal (hidden otherwise) for `total` units.
fn progress_bar(total: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::new(total);
    bar.set_style(
        ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} ({eta})")
            .expect("template")
            .progress_chars("=> "),
    );
    bar.set_message(what.to_string());
    bar
}

/// A progress bar on a terminal (hidden otherwise), one per projection.
#[derive(Default)]
struct BarProgress(std::sync::Mutex<Option<ProgressBar>>);

impl Progress for BarProgress {
    fn start(&self, total: u64, what: &str) {
        *self.0.lock().expect("bar") = Some(progress_bar(total, what));
    }
    fn advance(&self, k: u64) {
        if let Some(bar) = self.0.lock().expect("bar").as_ref() {
            bar.inc(k);
        }
    }
    fn finish(&self) {
        if let Some(bar) = self.0.lock().expect("bar").take() {
            bar.finish_and_clear();
        }
    }
}

/// Runs `check`.
pub fn run(a: CheckArgs) -> Result<ExitCode, CliError> {
    {
        use crate::paths::{named, refuse_clobbering};
        let outputs: Vec<_> = [("--junit", &a.junit), ("--witness", &a.witness)]
            .into_iter()
            .filter_map(|(flag, p)| p.as_ref().map(|p| named(flag, p)))
            .collect();
        refuse_clobbering(&[named("FILE", &a.file)], &outputs)?;
    }
    if a.witness.is_some() && (a.sequence || a.projections.is_some()) {
        return Err(usage(
            "--witness covers the whole set's net property or t-value: leave out --sequence \
             and --projections",
        ));
    }
    if let Some(n) = a.threads {
        if n > MAX_THREADS {
            // Spawning 100,000 threads took 14 s before failing: refuse at once.
            return Err(CliError::Usage(format!(
                "--threads {n}: at most {MAX_THREADS}"
            )));
        }
        rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build_global()
            .map_err(|e| {
                CliError::Usage(format!(
                    "--threads {n}: the system refused to start {n} threads ({e}); a limit \
                     on processes or threads (ulimit -u, a container's pids.max) is lower: \
                     ask for fewer, or leave --threads out to use one per core"
                ))
            })?;
    }
    let base = CheckBase::new(a.base).map_err(usage)?;
    let (read, floats) = read_points_typed(&a.file, a.format, FloatWords::Floor)?;
    let input = crate::input::file_record(&a.file, &read);
    let query = NetQuery {
        m: a.m,
        t: a.t,
        sequence: a.sequence,
        projections: a.projections.clone(),
        histograms: a.histograms,
    };
    let coordinates = read.len() * read.dims();
    // Floats in a base that is not a power of two become a snapped set (the read one is
    // dropped); otherwise the read set itself is handed on, not copied.
    let (points, snapped) = if floats && !a.no_snap {
        snap_floats(read, base, &query)
            .map_err(|e| CliError::Usage(format!("{}: {e}", a.file.display())))?
    } else {
        (read, None)
    };
    if let Some(path) = &a.witness {
        let w = net_witness(&points, base, a.m, a.t)
            .map_err(|e| CliError::Usage(format!("--witness: {e}")))?;
        crate::output::write_atomically(Some(path), |out| {
            w.write(out).map_err(crate::output::io_err)
        })?;
    }
    let outcome = check_points_owned(points, base, &query, &BarProgress::default())
        .map_err(CliError::Usage)?;
    let holds = outcome.holds;
    if let Some(path) = &a.junit {
        crate::output::write_junit(
            path,
            "gartowen check",
            &[junit_suite(&a.file.display().to_string(), &outcome)],
        )?;
    }
    if a.json {
        let cert = Certificate::new(
            "check",
            if holds {
                CertVerdict::Pass
            } else {
                CertVerdict::Fail
            },
            json!({
                "base": base.get(), "m": a.m, "t": a.t, "sequence": a.sequence,
                "projections": a.projections, "histograms": a.histograms,
                "snap": snapped, "no_snap": a.no_snap,
            }),
            vec![],
            vec![input],
            outcome.result_json(),
        );
        crate::outln!("{}", cert.to_json());
    } else {
        if let Some(s) = &snapped {
            crate::out!("{}", snap_note(s, coordinates));
        }
        crate::out!("{}", outcome.text);
    }
    Ok(if holds {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// A testcase per projection of a check result: it fails where the net or sequence property
/// does not hold, naming the property and its first failing box; t-values alone are
/// measurements.
fn junit_suite(file: &str, outcome: &NetOutcome) -> gartowen::battery::junit::JunitSuite {
    use gartowen::battery::junit::{JunitCase, JunitSuite};
    JunitSuite {
        name: file.to_string(),
        certificate: None,
        cases: outcome
            .results
            .iter()
            .map(|r| {
                let dims = json!(r.projection()).to_string();
                JunitCase {
                    name: format!("dims {dims}"),
                    failure: (r.holds() == Some(false)).then(|| {
                        let why = r.failure().unwrap_or_else(|| "the property fails".into());
                        (
                            format!("dims {dims}: {why}"),
                            r.to_json()["first_failure"].to_string(),
                        )
                    }),
                    skipped: false,
                    output: r.to_json().to_string(),
                    seconds: 0.0,
                }
            })
            .collect(),
    }
}
