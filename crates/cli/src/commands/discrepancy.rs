//! `gartowen discrepancy`: squared discrepancy of a point file, by a chosen or automatic method.

use crate::input::{read_points, InputFormat};
use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::certificate::{CertVerdict, Certificate};
use gartowen::discrepancy::choice::MethodChoice;
use gartowen::discrepancy::{Kind, Points};
use gartowen::reports::{discrepancy_json, discrepancy_pairs, timed_discrepancy};
use serde_json::json;
use std::path::PathBuf;
use std::process::ExitCode;

/// How to compute.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum MethodArg {
    /// The fastest method whose relative error bound is at most 1e-12.
    Auto,
    /// Plain f64 (what most tools do; shown for comparison).
    Naive,
    /// Double-double compensated sums (deterministic for any thread count) with the error bound
    /// proved in proofs/DdSum.v; exact where the bound's run-time hypotheses fail.
    Compensated,
    /// Exact rational.
    Exact,
    /// O(N log N) exact 2-D L2-star.
    Fast,
}

/// Which pairs of dimensions to report besides the joint value.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum PairsArg {
    /// Dimension 0 with every other dimension.
    First,
    /// Every pair.
    All,
}

/// Squared discrepancy D² of a point set: L2-star, centered, wrap-around or generalized L2.
///
/// All values are D² (squared). Note: scipy.stats.qmc.discrepancy returns D (the root) for
/// L2-star but D² for CD and WD; pass --root for D. Plain f64 sums cancel catastrophically
/// (terms near 3^-d, D² near 1e-10), so `auto` picks the fastest method whose error bound is at
/// most 1e-12: fast for 2-D L2-star, else compensated, else exact when it takes at most about
/// 10 s, else compensated with its proven (looser) bound. Jobs are estimated first: over 5 s
/// the estimate is printed, over --max-seconds the job is refused.
///
/// Examples:
///   gartowen discrepancy sobol.npy --kind l2star
///   gartowen discrepancy sobol.npy --kind cd --method exact --json
///   gartowen discrepancy sz16.npy --pairs first --json
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct DiscrepancyArgs {
    /// Point file: .npy (float64, uint32, uint64), .csv (floats) or .hex (words).
    pub file: PathBuf,
    /// Kind: l2star, cd, wd or gl2.
    #[arg(long, default_value = "l2star")]
    pub kind: String,
    /// Method.
    #[arg(long, value_enum, default_value_t = MethodArg::Auto)]
    pub method: MethodArg,
    /// Also report 2-D values of pairs of dimensions.
    #[arg(long, value_enum)]
    pub pairs: Option<PairsArg>,
    /// Report D instead of D².
    #[arg(long)]
    pub root: bool,
    /// Input format.
    #[arg(long, value_enum, default_value_t = InputFormat::Auto)]
    pub format: InputFormat,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
    /// Refuse a job estimated to take longer than this many seconds (estimates are for a
    /// 2-core machine; jobs over 5 s print theirs first). The pair sums cost N² × d.
    #[arg(long, default_value_t = 600.0)]
    pub max_seconds: f64,
}

/// Jobs estimated past this many seconds announce their estimate on stderr.
const ANNOUNCE_SECONDS: f64 = 5.0;

/// A progress bar on a terminal (hidden otherwise) that advances with the clock against the
/// estimate, since the pair sums report no progress of their own; it stops short of the end
/// until the job ends, and is cleared when dropped.
struct ClockBar {
    bar: indicatif::ProgressBar,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    ticker: Option<std::thread::JoinHandle<()>>,
}

impl ClockBar {
    fn start(estimate_seconds: f64) -> ClockBar {
        use std::sync::atomic::{AtomicBool, Ordering};
        let total = (estimate_seconds * 1000.0) as u64;
        let bar = indicatif::ProgressBar::new(total.max(1));
        bar.set_style(
            indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {elapsed} of about {prefix}")
                .expect("template")
                .progress_chars("=> "),
        );
        bar.set_message("discrepancy");
        bar.set_prefix(format!("{estimate_seconds:.0} s (estimated)"));
        let stop = std::sync::Arc::new(AtomicBool::new(false));
        let (b, s) = (bar.clone(), stop.clone());
        let started = std::time::Instant::now();
        let ticker = std::thread::spawn(move || {
            while !s.load(Ordering::Relaxed) {
                let ms = started.elapsed().as_millis() as u64;
                b.set_position(ms.min(total.saturating_sub(total / 100)));
                std::thread::sleep(std::time::Duration::from_millis(200));
            }
        });
        ClockBar {
            bar,
            stop,
            ticker: Some(ticker),
        }
    }
}

impl Drop for ClockBar {
    fn drop(&mut self) {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        if let Some(t) = self.ticker.take() {
            let _ = t.join();
        }
        self.bar.finish_and_clear();
    }
}

/// The estimated seconds of the whole job on `n` points in `d` dimensions: the joint value and
/// the pairs asked for.
fn estimate(n: usize, d: usize, kind: Kind, choice: MethodChoice, pairs: Option<PairsArg>) -> f64 {
    use gartowen::discrepancy::choice::estimated_choice_seconds_for;
    let joint = estimated_choice_seconds_for(n, d, kind, choice);
    let count = match pairs {
        None => 0,
        Some(PairsArg::First) => d.saturating_sub(1),
        Some(PairsArg::All) => d * d.saturating_sub(1) / 2,
    };
    joint + count as f64 * estimated_choice_seconds_for(n, 2, kind, choice)
}

fn method_choice(method: MethodArg) -> MethodChoice {
    match method {
        MethodArg::Auto => MethodChoice::Auto,
        MethodArg::Naive => MethodChoice::Naive,
        MethodArg::Compensated => MethodChoice::Compensated,
        MethodArg::Exact => MethodChoice::Exact,
        MethodArg::Fast => MethodChoice::Fast,
    }
}

/// Runs `discrepancy`.
pub fn run(a: DiscrepancyArgs) -> Result<ExitCode, CliError> {
    let kind: Kind = a
        .kind
        .parse()
        .map_err(|e| CliError::Usage(format!("{e}")))?;
    if a.max_seconds.is_nan() || a.max_seconds <= 0.0 {
        return Err(CliError::Usage(format!(
            "--max-seconds {} is not a positive number of seconds",
            a.max_seconds
        )));
    }
    let set = read_points(&a.file, a.format)?;
    let (n, d) = (set.len(), set.dims());
    let choice = method_choice(a.method);
    // Estimated before the row-major copy of the words is made: a job refused for its length
    // never allocates it (a 1 GiB file once aborted here).
    let seconds = estimate(n, d, kind, choice, a.pairs);
    let what = format!(
        "{} by method {:?} on {n} points in {d} dimensions{}: estimated {seconds:.0} s on a 2-core machine",
        kind.name(),
        a.method,
        if a.pairs.is_some() { " with pairs" } else { "" }
    )
    .to_lowercase();
    if seconds > a.max_seconds {
        return Err(CliError::Usage(format!(
            "{what}, over --max-seconds {}; raise --max-seconds to run it, or use fewer points{}",
            a.max_seconds,
            if a.method == MethodArg::Exact {
                ", or --method compensated (it reports its proven error bound)"
            } else {
                ""
            }
        )));
    }
    if seconds > ANNOUNCE_SECONDS {
        eprintln!("gartowen: {what}");
    }
    // Fallible: a set that fits memory once may not fit twice; say so instead of aborting.
    let mut words: Vec<u64> = Vec::new();
    words.try_reserve_exact(n * d).map_err(|_| {
        CliError::Usage(format!(
            "{}: {n} points in {d} dimensions need {} more bytes for their words, which this \
             process cannot allocate; use fewer points",
            a.file.display(),
            n * d * 8
        ))
    })?;
    words.extend((0..n).flat_map(|i| set.point(i)));
    let points = Points {
        words: &words,
        dims: d,
        width: set.width(),
    };
    let usage = |e: String| CliError::Usage(format!("--{e}"));
    let clock = (seconds > ANNOUNCE_SECONDS).then(|| ClockBar::start(seconds));
    let computed = timed_discrepancy(points, kind, choice).and_then(|(joint, secs)| {
        Ok((
            joint,
            secs,
            match a.pairs {
                Some(which) => {
                    discrepancy_pairs(points, kind, choice, a.root, which == PairsArg::All)?
                }
                None => Vec::new(),
            },
        ))
    });
    drop(clock);
    let (joint, secs, pair_reports) = computed.map_err(usage)?;
    if a.json {
        let mut result = discrepancy_json(&joint, secs, a.root);
        result["pairs"] = json!(pair_reports);
        let doc = Certificate::new(
            "discrepancy",
            CertVerdict::Measured,
            json!({ "kind": kind.name(), "method": format!("{:?}", a.method).to_lowercase(),
                    "pairs": a.pairs.map(|p| format!("{p:?}").to_lowercase()), "root": a.root }),
            vec![],
            vec![crate::input::file_record(&a.file, &set)],
            result,
        );
        crate::outln!("{}", doc.to_json());
    } else {
        let label = if a.root { "D" } else { "D^2" };
        crate::outln!(
            "{} {label} = {:.17e} ({:?}, {n} points, {d} dims, {:.3} s{})",
            kind.name(),
            if a.root {
                joint.value.sqrt()
            } else {
                joint.value
            },
            joint.method,
            secs,
            match (joint.rel_error_bound, &joint.exact) {
                (Some(b), _) => format!(", rel. error ≤ {b:.1e}"),
                // Exact, but the f64 overflowed or underflowed: say where the value is.
                (None, Some(_)) => ", outside the f64 range: --json has the exact rational".into(),
                (None, None) => ", no error bound for this input".into(),
            }
        );
        for p in &pair_reports {
            crate::outln!(
                "  pair {}: {label} = {:.17e}",
                p["pair"],
                p["value"].as_f64().unwrap_or(f64::NAN)
            );
        }
    }
    Ok(ExitCode::SUCCESS)
}
