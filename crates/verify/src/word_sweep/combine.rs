//! Joining the pieces of one dimension: coverage (every chunk exactly once), the seams between
//! pieces, injectivity of the chunk images π, and the node laws by depth.

use super::chunk_scan::{node_cell, node_cells};
use super::{SweepError, SweepFailure, SweepPiece, SweepPlan};
use crate::stats::chi_square;
use gartowen_core::{PowerOfTwoBase, Width};
use serde::{Deserialize, Serialize};

/// The empirical law of the node permutations of one depth over every node of the dimension
/// (measured, not judged: nodes of one dimension need not be independent for every claim).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DepthLaw {
    /// Depth k.
    pub depth: u32,
    /// Nodes of that depth tallied (b^k).
    pub nodes: u64,
    /// `"S_b ranks"` (b ≤ 4) or `"(pi(0), pi(1))"`, as the inspector's node law.
    pub cells_are: String,
    /// Pearson χ² against equal cell probabilities.
    pub chi_square: f64,
    /// Degrees of freedom.
    pub dof: u64,
    /// P(χ²_dof ≥ statistic) if nodes were independent and uniform over S_b.
    pub p_value: f64,
    /// Total variation distance from the uniform cell law.
    pub total_variation: f64,
    /// The nonzero counts as (cell, count), cells increasing.
    pub counts: Vec<(u32, u64)>,
}

/// The verdict on one dimension from pieces that cover all its chunks.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepVerdict {
    /// Dimension.
    pub dim: u32,
    /// Word width W.
    pub width: u32,
    /// Base b.
    pub base: u32,
    /// Words checked: 2^W when it passed.
    pub words: u64,
    /// Bijective and nested at every depth on all words.
    pub passed: bool,
    /// The first failure in word order.
    pub failure: Option<SweepFailure>,
    /// The verdict in words.
    pub statement: String,
    /// Node laws of depths 0..L (empty on failure).
    pub node_laws: Vec<DepthLaw>,
}

fn incomplete(m: String) -> SweepError {
    SweepError::Incomplete(m)
}

/// Joins the pieces of one dimension (in any order) into its verdict. Refuses pieces that do
/// not cover every chunk exactly once or that disagree on the dimension, width or base.
pub fn combine(pieces: &[SweepPiece]) -> Result<SweepVerdict, SweepError> {
    let first = pieces
        .first()
        .ok_or_else(|| incomplete("no pieces to combine".into()))?;
    let (dim, width, base) = (first.dim, first.width, first.base);
    if let Some(p) = pieces
        .iter()
        .find(|p| (p.dim, p.width, p.base) != (dim, width, base))
    {
        return Err(incomplete(format!(
            "a piece of dimension {} ({}-bit, base {}) among pieces of dimension {dim} \
             ({width}-bit, base {base})",
            p.dim, p.width, p.base
        )));
    }
    let plan = SweepPlan::new(
        Width::new(width).map_err(|e| incomplete(e.to_string()))?,
        PowerOfTwoBase::from_base(base as u64).map_err(|e| incomplete(e.to_string()))?,
    )?;
    let mut order: Vec<&SweepPiece> = pieces.iter().collect();
    order.sort_by_key(|p| p.chunks);
    check_cover(&plan, dim, &order)?;
    let mut failure = None;
    let mut prev_last: Option<u64> = None;
    for p in &order {
        if let Some(prev) = prev_last {
            if let Some(f) = plan.seam_failure(plan.chunk_start(p.chunks[0]), prev, p.first_output)
            {
                failure = Some(f);
                break;
            }
        }
        if let Some(f) = &p.failure {
            failure = Some(f.clone());
            break;
        }
        prev_last = Some(p.last_output);
    }
    let images: Vec<u64> = order
        .iter()
        .flat_map(|p| p.images.iter().copied())
        .collect();
    if failure.is_none() {
        failure = merged_subtrees(&plan, &images)?;
    }
    let words = if failure.is_none() { plan.words() } else { 0 };
    let statement = match &failure {
        None => format!(
            "bijective and nested at every depth on all {} {width}-bit words, dimension {dim}, \
             base {base}",
            plan.words()
        ),
        Some(f) => format!("dimension {dim}: {}", f.describe(base)),
    };
    let node_laws = if failure.is_none() {
        node_laws(&plan, &images, &order)?
    } else {
        Vec::new()
    };
    Ok(SweepVerdict {
        dim,
        width,
        base,
        words,
        passed: failure.is_none(),
        failure,
        statement,
        node_laws,
    })
}

/// Every chunk exactly once; a passing piece has one image per chunk and whole-chunk words.
fn check_cover(plan: &SweepPlan, dim: u32, order: &[&SweepPiece]) -> Result<(), SweepError> {
    let mut next = 0u64;
    for p in order {
        let [lo, hi] = p.chunks;
        if lo >= hi || hi > plan.chunks() {
            return Err(incomplete(format!(
                "dimension {dim}: a piece covers chunks {lo}..{hi}, outside 0..{}",
                plan.chunks()
            )));
        }
        if lo > next {
            return Err(incomplete(format!(
                "dimension {dim}: chunks {next}..{lo} (words {:#x}..{:#x}) are missing",
                plan.chunk_start(next),
                plan.chunk_start(lo)
            )));
        }
        if lo < next {
            return Err(incomplete(format!(
                "dimension {dim}: chunks {lo}..{} are covered twice",
                next.min(hi)
            )));
        }
        if p.failure.is_none()
            && (p.images.len() as u64 != hi - lo || p.words != (hi - lo) * plan.chunk_words())
        {
            return Err(incomplete(format!(
                "dimension {dim}: the piece of chunks {lo}..{hi} holds {} images and {} words, \
                 not {} and {}",
                p.images.len(),
                p.words,
                hi - lo,
                (hi - lo) * plan.chunk_words()
            )));
        }
        next = hi;
    }
    if next != plan.chunks() {
        return Err(incomplete(format!(
            "dimension {dim}: chunks {next}..{} (words {:#x} and up) are missing",
            plan.chunks(),
            plan.chunk_start(next)
        )));
    }
    Ok(())
}

/// The first chunk (in word order) whose image prefix an earlier chunk already has.
fn merged_subtrees(plan: &SweepPlan, images: &[u64]) -> Result<Option<SweepFailure>, SweepError> {
    let mut owner: Vec<Option<u64>> = vec![None; plan.chunks() as usize];
    for (c, &image) in images.iter().enumerate() {
        let slot = owner
            .get_mut(image as usize)
            .ok_or_else(|| incomplete(format!("chunk {c} has image {image:#x}, out of range")))?;
        if let Some(earlier) = *slot {
            return Ok(Some(SweepFailure::SubtreesMerged {
                subtrees: [earlier, c as u64],
                first_words: [plan.chunk_start(earlier), plan.chunk_start(c as u64)],
                image,
                depth: plan.chunk_digits(),
            }));
        }
        *slot = Some(c as u64);
    }
    Ok(None)
}

/// Node laws: depths 0..d read from π, depths d..L summed from the pieces' cell counts.
fn node_laws(
    plan: &SweepPlan,
    images: &[u64],
    order: &[&SweepPiece],
) -> Result<Vec<DepthLaw>, SweepError> {
    let (q, d) = (plan.base().q(), plan.chunk_digits());
    let b = plan.base().base();
    let cells = node_cells(b);
    let mut laws = Vec::new();
    for k in 0..d {
        let mut counts = vec![0u64; cells];
        let mut node = vec![0u8; b as usize];
        for p in 0..(1u64 << (q * k)) {
            for (e, slot) in node.iter_mut().enumerate() {
                let c = (p << q | e as u64) << (q * (d - k - 1));
                *slot = ((images[c as usize] >> (q * (d - 1 - k))) & (b as u64 - 1)) as u8;
            }
            if let Some(cell) = node_cell(&node) {
                counts[cell as usize] += 1;
            }
        }
        laws.push(depth_law(k, b, counts));
    }
    let deeper = (plan.law_depths() - d) as usize;
    let mut sums = vec![vec![0u64; cells]; deeper];
    for p in order {
        if p.node_cells.len() != deeper {
            return Err(incomplete(format!(
                "the piece of chunks {}..{} has node laws for {} depths, not {deeper}",
                p.chunks[0],
                p.chunks[1],
                p.node_cells.len()
            )));
        }
        for (sum, row) in sums.iter_mut().zip(&p.node_cells) {
            for &(cell, n) in row {
                let slot = sum.get_mut(cell as usize).ok_or_else(|| {
                    incomplete(format!("node-law cell {cell} is out of range (< {cells})"))
                })?;
                *slot = slot.saturating_add(n);
            }
        }
    }
    for (i, counts) in sums.into_iter().enumerate() {
        // A passing dimension has a cell for every node: b^k of them at depth k.
        let k = d + i as u32;
        let nodes = 1u64 << (q * k);
        let total = counts.iter().try_fold(0u64, |t, &c| t.checked_add(c));
        if total != Some(nodes) {
            return Err(incomplete(format!(
                "the pieces' node laws count {} nodes at depth {k}, not {nodes}",
                total.map_or("more than 2^64".into(), |t| t.to_string())
            )));
        }
        laws.push(depth_law(k, b, counts));
    }
    Ok(laws)
}

pub(super) fn depth_law(depth: u32, b: u32, counts: Vec<u64>) -> DepthLaw {
    let uniform = vec![1.0 / counts.len() as f64; counts.len()];
    let test = chi_square(&counts, &uniform);
    let n = test.n.max(1) as f64;
    let total_variation = 0.5
        * counts
            .iter()
            .map(|&c| (c as f64 / n - 1.0 / counts.len() as f64).abs())
            .sum::<f64>();
    DepthLaw {
        depth,
        nodes: test.n,
        cells_are: if b <= 4 {
            "S_b ranks"
        } else {
            "(pi(0), pi(1))"
        }
        .into(),
        chi_square: test.statistic,
        dof: test.dof as u64,
        p_value: test.p_value,
        total_variation,
        counts: counts
            .iter()
            .enumerate()
            .filter(|&(_, &n)| n > 0)
            .map(|(cell, &n)| (cell as u32, n))
            .collect(),
    }
}
