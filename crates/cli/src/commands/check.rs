//! `gartowen check`: net properties of a point file by elementary-interval counting.

use crate::input::{read_points, InputFormat};
use crate::CliError;
use clap::Args;
use gartowen::certificate::{CertVerdict, Certificate};
use gartowen::netcheck::counting::{
    self, check_net_with_progress, check_sequence_with_progress, histograms, implied_m,
    t_value_with_witness,
};
use gartowen::netcheck::{CheckBase, NetReport, PointSet, ProjectionSpec, SequenceReport};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::{json, Value};
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
}

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

fn net_json(r: &NetReport) -> Value {
    serde_json::to_value(r).expect("serializable")
}

fn seq_json(r: &SequenceReport) -> Value {
    serde_json::to_value(r).expect("serializable")
}

fn describe_failure(f: &gartowen::netcheck::BoxFailure, base: u64) -> String {
    // Only refined dimensions (d_j > 0) restrict the box; the others span [0,1).
    let sides: Vec<String> = f
        .shape
        .iter()
        .zip(&f.box_index)
        .enumerate()
        .filter(|(_, (&d, _))| d > 0)
        .map(|(j, (&d, &a))| format!("dim {j} in [{a}, {})/{base}^{d}", a + 1))
        .collect();
    format!(
        "shape {:?}: the box {} holds {} points, every box must hold {}",
        f.shape,
        if sides.is_empty() {
            "[0,1)^s".to_string()
        } else {
            sides.join(", ")
        },
        f.count,
        f.expected
    )
}

/// Runs `check`.
pub fn run(a: CheckArgs) -> Result<ExitCode, CliError> {
    if let Some(n) = a.threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build_global()
            .map_err(usage)?;
    }
    let base = CheckBase::new(a.base).map_err(usage)?;
    let points = read_points(&a.file, a.format)?;
    let projections = match &a.projections {
        Some(spec) => Some(
            spec.parse::<ProjectionSpec>()
                .map_err(usage)?
                .expand(points.dims())
                .map_err(usage)?,
        ),
        None => None,
    };
    let input = crate::input::file_record(&a.file, &points);
    let (holds, result, text) = if a.sequence {
        run_sequence(&a, base, &points, projections.as_deref())?
    } else {
        run_net(&a, base, &points, projections.as_deref())?
    };
    if let Some(path) = &a.junit {
        crate::output::write_junit(
            path,
            "gartowen check",
            &[junit_suite(&a.file.display().to_string(), &result)],
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
            }),
            vec![],
            vec![input],
            result,
        );
        crate::outln!("{}", cert.to_json());
    } else {
        crate::out!("{text}");
    }
    Ok(if holds {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

type Outcome = (bool, Value, String);

/// A testcase per projection of a check result (one object, or a list for --projections): it
/// fails where the net or sequence property does not hold; t-values alone are measurements.
fn junit_suite(file: &str, result: &Value) -> gartowen::battery::junit::JunitSuite {
    use gartowen::battery::junit::{JunitCase, JunitSuite};
    let items: Vec<&Value> = match result {
        Value::Array(list) => list.iter().collect(),
        one => vec![one],
    };
    JunitSuite {
        name: file.to_string(),
        certificate: None,
        cases: items
            .iter()
            .map(|v| {
                let dims = v
                    .get("projection")
                    .map_or("all".to_string(), |p| p.to_string());
                let holds = v.get("holds").and_then(Value::as_bool);
                JunitCase {
                    name: format!("dims {dims}"),
                    failure: (holds == Some(false)).then(|| {
                        (
                            format!("dims {dims}: the property fails"),
                            v.get("first_failure")
                                .map_or(String::new(), |f| f.to_string()),
                        )
                    }),
                    skipped: false,
                    output: v.to_string(),
                    seconds: 0.0,
                }
            })
            .collect(),
    }
}

/// The sets to check: the whole set, or each requested projection with its dimensions.
fn targets(
    points: &PointSet,
    projections: Option<&[Vec<usize>]>,
) -> Result<Vec<(Vec<usize>, PointSet)>, CliError> {
    match projections {
        None => Ok(vec![((0..points.dims()).collect(), points.clone())]),
        Some(list) => list
            .iter()
            .map(|p| Ok((p.clone(), points.project(p).map_err(usage)?)))
            .collect(),
    }
}

fn run_net(
    a: &CheckArgs,
    base: CheckBase,
    points: &PointSet,
    projections: Option<&[Vec<usize>]>,
) -> Result<Outcome, CliError> {
    let m = match a.m {
        Some(m) => m,
        None => implied_m(points, base).map_err(usage)?,
    };
    let b = base.get();
    let targets = targets(points, projections)?;
    let mut holds = true;
    let mut results = Vec::new();
    let mut text = String::new();
    for (dims, set) in &targets {
        match a.t {
            Some(t) => {
                let total =
                    gartowen::netcheck::shapes::shape_count(m.saturating_sub(t), set.dims()) as u64;
                let bar = progress_bar(total, "shapes");
                let r = check_net_with_progress(set, base, m, t, &|k| bar.inc(k)).map_err(usage)?;
                bar.finish_and_clear();
                holds &= r.holds;
                text += &format!(
                    "dims {dims:?}: ({t},{m},{})-net in base {b}: {} ({} shapes checked)\n",
                    set.dims(),
                    if r.holds { "holds" } else { "FAILS" },
                    r.shapes_checked
                );
                if let Some(f) = &r.first_failure {
                    text += &format!("  first failure: {}\n", describe_failure(f, b));
                }
                let mut v = net_json(&r);
                v["projection"] = json!(dims);
                if a.histograms {
                    v["histograms"] =
                        serde_json::to_value(histograms(set, base, m, t).map_err(usage)?)
                            .expect("json");
                }
                results.push(v);
            }
            None => {
                let (t, witness) = t_value_with_witness(set, base, m).map_err(usage)?;
                text += &format!(
                    "dims {dims:?}: t = {t} (m = {m}, s = {}, base {b})\n",
                    set.dims()
                );
                if let Some(f) = witness.as_ref().and_then(|w| w.first_failure.as_ref()) {
                    text += &format!(
                        "  not a ({},{m},{})-net: {}\n",
                        t - 1,
                        set.dims(),
                        describe_failure(f, b)
                    );
                }
                results.push(json!({
                    "projection": dims, "t": t, "m": m, "s": set.dims(), "b": b,
                    "witness_at_t_minus_1": witness.map(|w| net_json(&w)),
                }));
            }
        }
    }
    let result = if projections.is_none() {
        results.pop().expect("one result")
    } else {
        json!(results)
    };
    Ok((holds, result, text))
}

fn run_sequence(
    a: &CheckArgs,
    base: CheckBase,
    points: &PointSet,
    projections: Option<&[Vec<usize>]>,
) -> Result<Outcome, CliError> {
    let max_m = match a.m {
        Some(m) => m,
        None => (0..=32u32)
            .take_while(|&k| base.pow(k).is_some_and(|p| p <= points.len() as u64))
            .last()
            .unwrap_or(0),
    };
    let b = base.get();
    let targets = targets(points, projections)?;
    let mut holds = true;
    let mut results = Vec::new();
    let mut text = String::new();
    for (dims, set) in &targets {
        let (t, r) = match a.t {
            Some(t) => {
                let bar = progress_bar(0, "block-shapes");
                let r = check_sequence_with_progress(set, base, t, max_m, &|k| bar.inc(k))
                    .map_err(usage)?;
                bar.finish_and_clear();
                (t, r)
            }
            None => {
                // The least t whose sequence check holds.
                let mut t = 0;
                loop {
                    let r = counting::check_sequence(set, base, t, max_m).map_err(usage)?;
                    if r.holds || t == max_m {
                        break (t, r);
                    }
                    t += 1;
                }
            }
        };
        if a.t.is_some() {
            holds &= r.holds;
        }
        text += &format!(
            "dims {dims:?}: ({t},{})-sequence in base {b} over blocks of {b}^k points, k ≤ {max_m}: {} ({} blocks)\n",
            set.dims(),
            if r.holds { "holds" } else { "FAILS" },
            r.blocks_checked
        );
        if let Some(f) = &r.first_failure {
            text += &format!(
                "  first failure: block {} of {b}^{} points, {}\n",
                f.block,
                f.m,
                describe_failure(&f.failure, b)
            );
        }
        let mut v = seq_json(&r);
        v["projection"] = json!(dims);
        results.push(v);
    }
    let result = if projections.is_none() {
        results.pop().expect("one result")
    } else {
        json!(results)
    };
    Ok((holds, result, text))
}
