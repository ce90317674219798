//! The counting path: per shape, every point's box key from its top digits, histogrammed.
//!
//! Digit prefixes are computed once per query: P_j(i) = floor(x_ij · b^K) at the deepest level
//! K the query needs; a shape's digit a_j = floor(x_ij · b^(d_j)) is then P_j(i) / b^(K − d_j)
//! (a shift for b = 2^q). A box must hold exactly b^t points. Since the total is b^K · b^t,
//! no box can hold fewer unless another holds more, so only overflow is searched for.

use crate::box_keys::{check_shape, key_parts, keys_of, parts_filler, views, KeyPart, CHUNK};
use crate::shape_tree::ShapeWalk;
use crate::shapes::shapes;
use crate::{CheckBase, NetError, PointSet};
use rayon::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;

/// The first box (in shape order, then point order) holding more than b^t points.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct BoxFailure {
    /// The shape (d_1..d_s): box side b^-d_j in dimension j.
    pub shape: Vec<u32>,
    /// The box: in dimension j it is [a_j·b^-d_j, (a_j+1)·b^-d_j).
    pub box_index: Vec<u64>,
    /// Points in that box.
    pub count: u64,
    /// Points every box must hold, b^t.
    pub expected: u64,
}

/// The verdict of a (t,m,s)-net check.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct NetReport {
    /// Base b.
    pub base: u64,
    /// m (N = b^m).
    pub m: u32,
    /// t checked.
    pub t: u32,
    /// Dimensions s.
    pub dims: usize,
    /// Whether every box of every shape holds b^t points.
    pub holds: bool,
    /// Shapes examined (all of them when the net holds).
    pub shapes_checked: u64,
    /// The first failing shape and box.
    pub first_failure: Option<BoxFailure>,
}

/// How many boxes of a shape hold each count.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct ShapeHistogram {
    /// The shape.
    pub shape: Vec<u32>,
    /// count → number of boxes holding exactly that many points (boxes with 0 included).
    pub boxes_by_count: BTreeMap<u64, u64>,
}

/// A (t,s)-sequence failure: which block of b^m consecutive points failed, and how.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct SequenceFailure {
    /// The block size exponent: the block holds b^m points.
    pub m: u32,
    /// The block number k: points [k·b^m, (k+1)·b^m).
    pub block: u64,
    /// The failing shape and box within that block.
    pub failure: BoxFailure,
}

/// The verdict of a (t,s)-sequence check over every block of b^k points, t ≤ k ≤ max_m.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct SequenceReport {
    /// Base b.
    pub base: u64,
    /// t checked.
    pub t: u32,
    /// Largest block exponent checked.
    pub max_m: u32,
    /// Dimensions s.
    pub dims: usize,
    /// Whether every block is a (t,k,s)-net.
    pub holds: bool,
    /// Blocks examined over all k.
    pub blocks_checked: u64,
    /// (block, shape) pairs examined.
    pub shapes_checked: u64,
    /// The first failure in (k, block, shape) order.
    pub first_failure: Option<SequenceFailure>,
}

pub use crate::Progress;

/// Digit prefixes floor(x·b^K) of points `range` in every dimension.
/// Values are below b^k ≤ N ≤ 2^32, so they fit u32 (validated by the callers).
fn prefixes(
    points: &PointSet,
    base: CheckBase,
    k: u32,
    range: std::ops::Range<usize>,
) -> Vec<Vec<u32>> {
    let w = points.width().bits();
    (0..points.dims())
        .into_par_iter()
        .map(|j| {
            points.column(j)[range.clone()]
                .iter()
                .map(|&x| base.top_digits(x, w, k) as u32)
                .collect()
        })
        .collect()
}

/// Validates (N, m, t) and returns b^t.
fn validate(points: &PointSet, base: CheckBase, m: u32, t: u32) -> Result<u64, NetError> {
    if points.len() as u64 > 1 << 32 {
        return Err(NetError::BadShape(format!(
            "{} points is more than the checker's 2^32",
            points.len()
        )));
    }
    if t > m {
        return Err(NetError::TooLargeT { t, m });
    }
    match base.pow(m) {
        Some(p) if p == points.len() as u64 => Ok(base.pow(t).unwrap()),
        _ => Err(NetError::WrongCount {
            n: points.len(),
            base: base.get(),
            m,
        }),
    }
}

/// The m with N = b^m for this set, or an error naming N.
pub fn implied_m(points: &PointSet, base: CheckBase) -> Result<u32, NetError> {
    base.exact_log(points.len())
        .ok_or(NetError::NotAPowerOfBase {
            n: points.len(),
            base: base.get(),
        })
}

/// Whether the b^m points form a (t,m,s)-net in base b; stops at the first failing shape.
///
/// ```
/// use gartowen_core::Width;
/// use gartowen_netcheck::{counting::check_net, CheckBase, PointSet};
/// // The 4-point (0,2,2)-net in base 2: {(0,0), (1/2,1/2), (1/4,3/4), (3/4,1/4)}.
/// let rows = vec![vec![0, 0], vec![128, 128], vec![64, 192], vec![192, 64]];
/// let p = PointSet::from_rows(Width::new(8).unwrap(), &rows).unwrap();
/// assert!(check_net(&p, CheckBase::new(2).unwrap(), 2, 0).unwrap().holds);
/// ```
pub fn check_net(
    points: &PointSet,
    base: CheckBase,
    m: u32,
    t: u32,
) -> Result<NetReport, NetError> {
    check_net_with_progress(points, base, m, t, &gartowen_core::Silent)
}

/// [`check_net`] with a progress callback (called with the number of shapes finished).
pub fn check_net_with_progress(
    points: &PointSet,
    base: CheckBase,
    m: u32,
    t: u32,
    progress: Progress,
) -> Result<NetReport, NetError> {
    validate(points, base, m, t)?;
    let prefix = prefixes(points, base, m - t, 0..points.len());
    check_level(
        (points.len(), points.dims()),
        &views(&prefix),
        m - t,
        base,
        m,
        t,
        progress,
        Search::First,
    )
}

/// [`check_net_with_progress`] on a set it owns: each dimension's words are freed as soon as
/// its digit prefixes exist, so the peak holds the words and one column of prefixes instead of
/// both in full (for 16-D N = 2^20: 134 MB of words plus 4 MB, not plus 64 MB). The same report.
pub fn check_net_owned(
    points: PointSet,
    base: CheckBase,
    m: u32,
    t: u32,
    progress: Progress,
) -> Result<NetReport, NetError> {
    validate(&points, base, m, t)?;
    let (n, dims) = (points.len(), points.dims());
    let (width, columns) = points.into_columns();
    let w = width.bits();
    let mut prefix: Vec<Vec<u32>> = Vec::with_capacity(dims);
    for column in columns {
        prefix.push(
            column
                .par_iter()
                .map(|&x| base.top_digits(x, w, m - t) as u32)
                .collect(),
        );
        // `column` is dropped here, before the next dimension's prefixes are made.
    }
    check_level(
        (n, dims),
        &views(&prefix),
        m - t,
        base,
        m,
        t,
        progress,
        Search::First,
    )
}

/// [`check_net`] by the plain path: every shape in order, its keys built from scratch from
/// its parts, one thread, no shape tree. The reference the tree walk is tested and
/// benchmarked against (same report, field for field).
pub fn check_net_per_shape(
    points: &PointSet,
    base: CheckBase,
    m: u32,
    t: u32,
) -> Result<NetReport, NetError> {
    let t_count = validate(points, base, m, t)?;
    let k = m - t;
    let prefix = prefixes(points, base, k, 0..points.len());
    let views = views(&prefix);
    let shape_list = shapes(k, points.dims())?;
    let mut scratch = Vec::new();
    for (i, shape) in shape_list.iter().enumerate() {
        let parts = key_parts(&views, base, k, shape);
        let filler = parts_filler(&parts, base);
        let failure = check_shape(
            filler,
            0,
            points.len(),
            base,
            k,
            t_count,
            shape,
            &mut scratch,
        );
        if failure.is_some() {
            return Ok(NetReport {
                base: base.get(),
                m,
                t,
                dims: points.dims(),
                holds: false,
                shapes_checked: i as u64 + 1,
                first_failure: failure,
            });
        }
    }
    Ok(NetReport {
        base: base.get(),
        m,
        t,
        dims: points.dims(),
        holds: true,
        shapes_checked: shape_list.len() as u64,
        first_failure: None,
    })
}

/// Which failure a level check reports.
#[derive(Clone, Copy)]
enum Search {
    /// The first failing shape in lexicographic order (deterministic reports).
    First,
    /// Any failing shape (enough to reject a t; stops soonest).
    Any,
}

/// Checks every shape with Σd = m − t over the prefixes (at `depth` ≥ m − t) of a set of
/// `size` = (N, s).
#[allow(clippy::too_many_arguments)]
fn check_level(
    size: (usize, usize),
    prefix: &[&[u32]],
    depth: u32,
    base: CheckBase,
    m: u32,
    t: u32,
    progress: Progress,
    search: Search,
) -> Result<NetReport, NetError> {
    let k = m - t;
    let (n, dims) = size;
    let t_count = base.pow(t).unwrap();
    let shape_list = shapes(k, dims)?;
    if let Search::Any = search {
        // Sound quick rejection: counts only grow with more points, so a box that overflows
        // among the first n/64 points overflows in the whole set.
        let probe = n / 64;
        if probe >= 64 {
            let hit = shape_list.par_iter().map_init(Vec::new, |scratch, shape| {
                let parts = key_parts(prefix, base, depth, shape);
                check_shape(
                    parts_filler(&parts, base),
                    0,
                    probe,
                    base,
                    k,
                    t_count,
                    shape,
                    scratch,
                )
            });
            if let Some(f) = hit.find_any(|r| r.is_some()).flatten() {
                return Ok(NetReport {
                    base: base.get(),
                    m,
                    t,
                    dims,
                    holds: false,
                    shapes_checked: shape_list.iter().position(|s| *s == f.shape).unwrap() as u64
                        + 1,
                    first_failure: Some(f),
                });
            }
        }
    }
    let walk = ShapeWalk {
        prefix,
        depth,
        base,
        k,
        t_count,
        n,
    };
    let failure = walk.run(matches!(search, Search::First), progress);
    // Shapes checked is reported deterministically: all of them when the net holds, and the
    // failing shape's position + 1 otherwise (parallel workers may have looked further).
    let shapes_checked = match &failure {
        None => shape_list.len() as u64,
        Some(f) => shape_list.iter().position(|s| *s == f.shape).unwrap() as u64 + 1,
    };
    Ok(NetReport {
        base: base.get(),
        m,
        t,
        dims,
        holds: failure.is_none(),
        shapes_checked,
        first_failure: failure,
    })
}

/// The t-value of a b^m-point set: the least t for which it is a (t,m,s)-net.
///
/// Levels below the answer are rejected by any failing shape, so only the passing level is
/// checked in full. [`t_value_with_witness`] also reports the first failure at t − 1.
pub fn t_value(points: &PointSet, base: CheckBase, m: u32) -> Result<u32, NetError> {
    validate(points, base, m, 0)?;
    // Digit prefixes at depth m serve every t.
    let prefix = prefixes(points, base, m, 0..points.len());
    let views = views(&prefix);
    for t in 0..=m {
        if check_level(
            (points.len(), points.dims()),
            &views,
            m,
            base,
            m,
            t,
            &gartowen_core::Silent,
            Search::Any,
        )?
        .holds
        {
            return Ok(t);
        }
    }
    unreachable!("t = m always holds: one box holds all b^m points")
}

/// The t-value and, when t > 0, the (t−1, m, s) check's report with its first failing shape
/// and box: the witness that t is least.
pub fn t_value_with_witness(
    points: &PointSet,
    base: CheckBase,
    m: u32,
) -> Result<(u32, Option<NetReport>), NetError> {
    let t = t_value(points, base, m)?;
    let witness = if t > 0 {
        Some(check_net(points, base, m, t - 1)?)
    } else {
        None
    };
    Ok((t, witness))
}

/// Count histograms of every shape with Σd = m − t.
pub fn histograms(
    points: &PointSet,
    base: CheckBase,
    m: u32,
    t: u32,
) -> Result<Vec<ShapeHistogram>, NetError> {
    validate(points, base, m, t)?;
    let k = m - t;
    let shape_list = shapes(k, points.dims())?;
    let prefix = prefixes(points, base, k, 0..points.len());
    let views = views(&prefix);
    let pow2 = base.log2().is_some();
    let cells = base.pow(k).unwrap() as usize;
    Ok(shape_list
        .par_iter()
        .map(|shape| {
            let parts = key_parts(&views, base, k, shape);
            let mut counts = vec![0u64; cells];
            let mut keys = [0u32; CHUNK];
            for start in (0..points.len()).step_by(CHUNK) {
                let keys = &mut keys[..CHUNK.min(points.len() - start)];
                keys_of(&parts, pow2, start, keys);
                for &key in keys.iter() {
                    counts[key as usize] += 1;
                }
            }
            let mut boxes_by_count = BTreeMap::new();
            for c in counts {
                *boxes_by_count.entry(c).or_insert(0) += 1;
            }
            ShapeHistogram {
                shape: shape.clone(),
                boxes_by_count,
            }
        })
        .collect())
}

/// The (t,s)-sequence check: every block of b^k consecutive points, t ≤ k ≤ max_m (blocks that
/// fit in N), is a (t,k,s)-net.
pub fn check_sequence(
    points: &PointSet,
    base: CheckBase,
    t: u32,
    max_m: u32,
) -> Result<SequenceReport, NetError> {
    check_sequence_with_progress(points, base, t, max_m, &gartowen_core::Silent)
}

/// [`check_sequence`] with a progress callback (units: block-shapes finished).
pub fn check_sequence_with_progress(
    points: &PointSet,
    base: CheckBase,
    t: u32,
    max_m: u32,
    progress: Progress,
) -> Result<SequenceReport, NetError> {
    if t > max_m {
        return Err(NetError::TooLargeT { t, m: max_m });
    }
    let n = points.len();
    let mut blocks_checked = 0u64;
    let mut shapes_checked = 0u64;
    let mut first_failure = None;
    for m in t..=max_m {
        let size = match base.pow(m) {
            Some(p) if p <= n as u64 => p as usize,
            _ => {
                return Err(NetError::WrongCount {
                    n,
                    base: base.get(),
                    m: max_m,
                })
            }
        };
        let blocks = n / size;
        let t_count = base.pow(t).unwrap();
        let k = m - t;
        let shape_list = shapes(k, points.dims())?;
        let prefix = prefixes(points, base, k, 0..blocks * size);
        let views = views(&prefix);
        let plans: Vec<Vec<KeyPart>> = shape_list
            .iter()
            .map(|sh| key_parts(&views, base, k, sh))
            .collect();
        let tasks = blocks * shape_list.len();
        // Blocks in parallel (runs of small blocks per task); shapes in order inside a block,
        // so the first failure in (block, shape) order is found deterministically.
        let failure = if k == 0 {
            None // the single box of a block holds all b^t points
        } else {
            (0..blocks)
                .into_par_iter()
                .with_min_len((1 << 14) / size.min(1 << 14))
                .map_init(Vec::new, |scratch, block| {
                    let found = shape_list.iter().zip(&plans).find_map(|(shape, parts)| {
                        check_shape(
                            parts_filler(parts, base),
                            block * size,
                            size,
                            base,
                            k,
                            t_count,
                            shape,
                            scratch,
                        )
                    });
                    progress.advance(shape_list.len() as u64);
                    found.map(|f| (block, f))
                })
                .find_first(|r| r.is_some())
                .flatten()
        };
        match failure {
            None => {
                blocks_checked += blocks as u64;
                shapes_checked += tasks as u64;
            }
            Some((block, f)) => {
                let pos = block * shape_list.len()
                    + shape_list.iter().position(|s| *s == f.shape).unwrap();
                blocks_checked += block as u64 + 1;
                shapes_checked += pos as u64 + 1;
                first_failure = Some(SequenceFailure {
                    m,
                    block: block as u64,
                    failure: f,
                });
                break;
            }
        }
    }
    Ok(SequenceReport {
        base: base.get(),
        t,
        max_m,
        dims: points.dims(),
        holds: first_failure.is_none(),
        blocks_checked,
        shapes_checked,
        first_failure,
    })
}
