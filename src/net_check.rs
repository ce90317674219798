//! The net check of a point set as `gartowen check` reports it: the t-value or a (t,m,s)-net
//! or (t,s)-sequence verdict per projection, with the first failing box in words and as JSON.
//! Shared by the CLI and the Python package, so both report the same result for one input.

use gartowen_netcheck::counting::{
    self, check_net_owned, check_net_with_progress, check_sequence_with_progress, histograms,
    implied_m, t_value_with_witness,
};
use gartowen_netcheck::snap::{snap_to_grid, SnapSummary};
use gartowen_netcheck::{
    BoxFailure, CheckBase, NetReport, PointSet, ProjectionSpec, SequenceReport, ShapeHistogram,
};
use serde_json::{json, Value};
use std::borrow::Cow;

/// What to check.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct NetQuery {
    /// m with N = b^m (None: implied by N; with `sequence`, the largest block exponent).
    pub m: Option<u32>,
    /// Check this t (a verdict) instead of reporting the t-value.
    pub t: Option<u32>,
    /// Check the (t,s)-sequence property over blocks of b^k consecutive points, k ≤ m.
    pub sequence: bool,
    /// Projections: `pairs`, `groups:G`, `blocks:G` or lists like `0,1;2,3` (None: all dims).
    pub projections: Option<String>,
    /// Include per-shape count histograms (with `t`, nets only).
    pub histograms: bool,
}

/// The outcome: whether every verdict holds (true when only t-values were asked), the result
/// of each projection and the text report.
#[derive(Debug, Clone, PartialEq)]
pub struct NetOutcome {
    /// Every checked property holds.
    pub holds: bool,
    /// One result per projection checked (one for the whole set without `projections`).
    pub results: Vec<ProjectionResult>,
    /// Whether the query named projections (the JSON result is then a list).
    pub per_projection: bool,
    /// The text `gartowen check` prints.
    pub text: String,
}

impl NetOutcome {
    /// The JSON result, as the `result` of `gartowen check --json`: one object, or a list with
    /// `projections`.
    pub fn result_json(&self) -> Value {
        if self.per_projection {
            Value::Array(self.results.iter().map(ProjectionResult::to_json).collect())
        } else {
            self.results
                .first()
                .map_or(Value::Null, ProjectionResult::to_json)
        }
    }
}

/// What was found on one projection.
#[derive(Debug, Clone, PartialEq)]
pub enum ProjectionResult {
    /// A (t,m,s)-net verdict, with the per-shape histograms when asked for.
    Net {
        /// The dimensions checked.
        projection: Vec<usize>,
        /// The base.
        b: u64,
        /// The verdict and the first failing box.
        report: NetReport,
        /// Box-count histograms per shape (`histograms`).
        histograms: Option<Vec<ShapeHistogram>>,
    },
    /// The t-value: a measurement, with the box that fails at t − 1 as its witness.
    TValue {
        /// The dimensions checked.
        projection: Vec<usize>,
        /// The base.
        b: u64,
        /// The least t.
        t: u32,
        /// N = b^m.
        m: u32,
        /// The number of dimensions.
        s: usize,
        /// The failed check at t − 1 (None at t = 0).
        witness: Option<NetReport>,
    },
    /// A (t,s)-sequence verdict.
    Sequence {
        /// The dimensions checked.
        projection: Vec<usize>,
        /// The base.
        b: u64,
        /// The verdict and the first failing block and box.
        report: SequenceReport,
    },
}

impl ProjectionResult {
    /// The dimensions checked.
    pub fn projection(&self) -> &[usize] {
        match self {
            ProjectionResult::Net { projection, .. }
            | ProjectionResult::TValue { projection, .. }
            | ProjectionResult::Sequence { projection, .. } => projection,
        }
    }

    /// The verdict: Some(holds) for net and sequence checks, None for a t-value.
    pub fn holds(&self) -> Option<bool> {
        match self {
            ProjectionResult::Net { report, .. } => Some(report.holds),
            ProjectionResult::Sequence { report, .. } => Some(report.holds),
            ProjectionResult::TValue { .. } => None,
        }
    }

    /// The failing property and its first failing box, in words (None when it holds or
    /// nothing was judged).
    pub fn failure(&self) -> Option<String> {
        match self {
            ProjectionResult::Net { report, b, .. } => report.first_failure.as_ref().map(|f| {
                format!(
                    "not a ({},{},{})-net in base {b}: {}",
                    report.t,
                    report.m,
                    report.dims,
                    describe_failure(f, *b)
                )
            }),
            ProjectionResult::Sequence { report, b, .. } => {
                report.first_failure.as_ref().map(|f| {
                    format!(
                        "not a ({},{})-sequence in base {b}: block {} of {b}^{} points, {}",
                        report.t,
                        report.dims,
                        f.block,
                        f.m,
                        describe_failure(&f.failure, *b)
                    )
                })
            }
            ProjectionResult::TValue { .. } => None,
        }
    }

    /// The JSON of this result, as `gartowen check --json` writes it.
    pub fn to_json(&self) -> Value {
        match self {
            ProjectionResult::Net {
                projection,
                report,
                histograms,
                ..
            } => {
                let mut v = serde_json::to_value(report).expect("serializable");
                v["projection"] = json!(projection);
                if let Some(h) = histograms {
                    v["histograms"] = serde_json::to_value(h).expect("serializable");
                }
                v
            }
            ProjectionResult::TValue {
                projection,
                b,
                t,
                m,
                s,
                witness,
            } => json!({
                "projection": projection, "t": t, "m": m, "s": s, "b": b,
                "witness_at_t_minus_1": witness.as_ref().map(|w| serde_json::to_value(w).expect("json")),
            }),
            ProjectionResult::Sequence {
                projection, report, ..
            } => {
                let mut v = serde_json::to_value(report).expect("serializable");
                v["projection"] = json!(projection);
                v
            }
        }
    }
}

/// Progress of a long check: `start` before each projection with the number of units, then
/// `advance` by units done, `finish` after it (the workspace's one progress shape).
pub use gartowen_core::{Progress, Silent};

/// One failing box in words: its shape and the sides of the refined dimensions.
pub fn describe_failure(f: &BoxFailure, base: u64) -> String {
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

/// The error radius [`snap_floats`] allows binary64 values in [0, 1): 2^-46, 64 units in the
/// last place at [1/2, 1). A correctly rounded value is off by half a unit; tools that sum
/// digit terms in floats are off by a few (SciPy's unscrambled Halton by up to about 2.2).
pub const F64_RADIUS_LOG2: u32 = 46;

/// Float input in a base that is not a power of two, snapped to the base's grid at the
/// check's depth (`q.m`, else the largest m with b^m ≤ N) by the rule of
/// [`gartowen_netcheck::snap`]. Powers of two need no snapping (a binary float is exact in
/// them): the set comes back unchanged with `None`. Otherwise the given set is dropped once the
/// snapped one exists. An error names the ambiguous point, or says that the precision does not
/// reach the depth.
pub fn snap_floats(
    points: PointSet,
    base: CheckBase,
    q: &NetQuery,
) -> Result<(PointSet, Option<SnapSummary>), String> {
    if base.log2().is_some() {
        return Ok((points, None));
    }
    let b = base.get();
    let depth = q.m.unwrap_or_else(|| {
        let (mut m, mut bm) = (0u32, 1u128);
        while bm * b as u128 <= points.len() as u128 {
            bm *= b as u128;
            m += 1;
        }
        m
    });
    match snap_to_grid(&points, b, depth.max(1), F64_RADIUS_LOG2).map_err(|e| e.to_string())? {
        Ok((set, summary)) => Ok((set, Some(summary))),
        Err(ambiguous) => Err(format!(
            "{ambiguous}; refused rather than read in a box it may not belong to"
        )),
    }
}

/// The line the text report gains when floats were snapped.
pub fn snap_note(s: &SnapSummary, coordinates: usize) -> String {
    format!(
        "floats snapped to the base-{} grid of depth {}: {} of {coordinates} coordinates \
         moved by at most 2^-{} (a float cannot hold most multiples of {}^-{})\n",
        s.base, s.digits, s.snapped, s.radius_log2, s.base, s.digits
    )
}

/// Runs the check `q` on `points` in base `base`; an error names the bad parameter.
///
/// ```
/// use gartowen::net_check::{check_points, NetQuery, Silent};
/// use gartowen::netcheck::{CheckBase, PointSet};
/// use gartowen::core::Width;
/// // The 4 points (0,0), (1/2,1/2), (1/4,3/4), (3/4,1/4): a (0,2,2)-net in base 2.
/// let p = PointSet::from_flat(Width::W32, 2, &[0, 0, 1 << 31, 1 << 31, 1 << 30, 3 << 30,
///                                              3 << 30, 1 << 30]).unwrap();
/// let base = CheckBase::new(2).unwrap();
/// let out = check_points(&p, base, &NetQuery::default(), &Silent).unwrap();
/// assert_eq!(out.result_json()["t"], 0);
/// assert_eq!(out.results[0].holds(), None, "a t-value is a measurement");
/// ```
pub fn check_points(
    points: &PointSet,
    base: CheckBase,
    q: &NetQuery,
    progress: &dyn Progress,
) -> Result<NetOutcome, String> {
    let projections = match &q.projections {
        Some(spec) => Some(
            spec.parse::<ProjectionSpec>()
                .map_err(|e| e.to_string())?
                .expand(points.dims())
                .map_err(|e| e.to_string())?,
        ),
        None => None,
    };
    // The projections' dimension lists; each projected set is made only when its turn comes,
    // so memory holds one projection at a time (a million pairs of 2^20 points would not fit).
    let targets: Vec<Vec<usize>> = match &projections {
        None => vec![(0..points.dims()).collect()],
        Some(list) => list.clone(),
    };
    let (holds, results, text) = if q.sequence {
        sequences(q, base, points, &targets, progress)?
    } else {
        nets(q, base, points, &targets, progress)?
    };
    Ok(NetOutcome {
        holds,
        results,
        per_projection: projections.is_some(),
        text,
    })
}

/// [`check_points`] on a set it owns. The one-projection net verdict (`t` given, no
/// histograms, no projections, not a sequence) frees each dimension's words once its digits
/// are read ([`check_net_owned`]), which lowers the peak memory; every other query runs as
/// [`check_points`]. The outcome is the same either way.
pub fn check_points_owned(
    points: PointSet,
    base: CheckBase,
    q: &NetQuery,
    progress: &dyn Progress,
) -> Result<NetOutcome, String> {
    let Some(t) =
        q.t.filter(|_| q.projections.is_none() && !q.sequence && !q.histograms)
    else {
        return check_points(&points, base, q, progress);
    };
    let m = match q.m {
        Some(m) => m,
        None => implied_m(&points, base).map_err(|e| e.to_string())?,
    };
    let dims: Vec<usize> = (0..points.dims()).collect();
    let total = gartowen_netcheck::shapes::shape_count(m.saturating_sub(t), dims.len()) as u64;
    progress.start(total, "shapes");
    let r = check_net_owned(points, base, m, t, progress).map_err(|e| e.to_string())?;
    progress.finish();
    let holds = r.holds;
    let result = net_verdict(&dims, r, base.get());
    Ok(NetOutcome {
        holds,
        text: net_text(&result),
        results: vec![result],
        per_projection: false,
    })
}

/// One net verdict on projection `dims`.
fn net_verdict(dims: &[usize], report: NetReport, b: u64) -> ProjectionResult {
    ProjectionResult::Net {
        projection: dims.to_vec(),
        b,
        report,
        histograms: None,
    }
}

/// The text line(s) of a net verdict.
fn net_text(result: &ProjectionResult) -> String {
    let ProjectionResult::Net {
        projection,
        b,
        report: r,
        ..
    } = result
    else {
        return String::new();
    };
    let mut text = format!(
        "dims {projection:?}: ({},{},{})-net in base {b}: {} ({} shapes checked)\n",
        r.t,
        r.m,
        r.dims,
        if r.holds { "holds" } else { "FAILS" },
        r.shapes_checked
    );
    if let Some(f) = &r.first_failure {
        text += &format!("  first failure: {}\n", describe_failure(f, *b));
    }
    text
}

type Parts = (bool, Vec<ProjectionResult>, String);

/// The set restricted to `dims`: the set itself when `dims` is all of it, in order.
fn projected<'a>(points: &'a PointSet, dims: &[usize]) -> Result<Cow<'a, PointSet>, String> {
    if dims.len() == points.dims() && dims.iter().enumerate().all(|(k, &d)| k == d) {
        Ok(Cow::Borrowed(points))
    } else {
        points
            .project(dims)
            .map(Cow::Owned)
            .map_err(|e| e.to_string())
    }
}

fn nets(
    q: &NetQuery,
    base: CheckBase,
    points: &PointSet,
    targets: &[Vec<usize>],
    progress: &dyn Progress,
) -> Result<Parts, String> {
    let err = |e: gartowen_netcheck::NetError| e.to_string();
    let m = match q.m {
        Some(m) => m,
        None => implied_m(points, base).map_err(err)?,
    };
    let b = base.get();
    let mut holds = true;
    let mut results = Vec::new();
    let mut text = String::new();
    for dims in targets {
        let set = projected(points, dims)?;
        let set = set.as_ref();
        match q.t {
            Some(t) => {
                let total =
                    gartowen_netcheck::shapes::shape_count(m.saturating_sub(t), set.dims()) as u64;
                progress.start(total, "shapes");
                let r = check_net_with_progress(set, base, m, t, progress).map_err(err)?;
                progress.finish();
                holds &= r.holds;
                let mut result = net_verdict(dims, r, b);
                text += &net_text(&result);
                if q.histograms {
                    if let ProjectionResult::Net { histograms: h, .. } = &mut result {
                        *h = Some(histograms(set, base, m, t).map_err(err)?);
                    }
                }
                results.push(result);
            }
            None => {
                let (t, witness) = t_value_with_witness(set, base, m).map_err(err)?;
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
                results.push(ProjectionResult::TValue {
                    projection: dims.clone(),
                    b,
                    t,
                    m,
                    s: set.dims(),
                    witness,
                });
            }
        }
    }
    Ok((holds, results, text))
}

fn sequences(
    q: &NetQuery,
    base: CheckBase,
    points: &PointSet,
    targets: &[Vec<usize>],
    progress: &dyn Progress,
) -> Result<Parts, String> {
    let err = |e: gartowen_netcheck::NetError| e.to_string();
    let max_m = match q.m {
        Some(m) => m,
        None => (0..=32u32)
            .take_while(|&k| base.pow(k).is_some_and(|p| p <= points.len() as u64))
            .last()
            .unwrap_or(0),
    };
    let b = base.get();
    let mut holds = true;
    let mut results = Vec::new();
    let mut text = String::new();
    for dims in targets {
        let set = projected(points, dims)?;
        let set = set.as_ref();
        let (t, r) = match q.t {
            Some(t) => {
                progress.start(0, "block-shapes");
                let r = check_sequence_with_progress(set, base, t, max_m, progress).map_err(err)?;
                progress.finish();
                (t, r)
            }
            None => {
                // The least t whose sequence check holds.
                let mut t = 0;
                loop {
                    let r = counting::check_sequence(set, base, t, max_m).map_err(err)?;
                    if r.holds || t == max_m {
                        break (t, r);
                    }
                    t += 1;
                }
            }
        };
        if q.t.is_some() {
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
        results.push(ProjectionResult::Sequence {
            projection: dims.clone(),
            b,
            report: r,
        });
    }
    Ok((holds, results, text))
}
