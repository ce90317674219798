//! The streaming pass over a range of chunks: frames of consecutive words through the batch
//! path, each chunk checked by [`ChunkScan`] (nestedness, injectivity, node laws), and the
//! records of the chunks joined into a piece.

use super::chunk_scan::{block_low_bits, node_cells, ChunkScan};
use super::group_scan::{self, GroupKernel, GroupLanes};
use super::{SweepError, SweepFailure, SweepPlan};
use gartowen_core::{Progress, Scrambler, Silent};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::ops::Range;
use std::sync::atomic::{AtomicU64, Ordering};

/// Words per evaluation frame: the external protocol's largest request.
const FRAME: usize = 1 << 20;

/// The result of sweeping a contiguous range of chunks of one dimension: what [`super::combine`]
/// needs to join it with the pieces around it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SweepPiece {
    /// Word width W.
    pub width: u32,
    /// Base b.
    pub base: u32,
    /// Dimension.
    pub dim: u32,
    /// The chunk range [start, end) this piece covers.
    pub chunks: [u64; 2],
    /// Words checked (whole chunks up to the first failure).
    pub words: u64,
    /// Image prefix π(c) of each chunk checked, in chunk order (d digits as an integer).
    pub images: Vec<u64>,
    /// Output of the piece's first word.
    pub first_output: u64,
    /// Output of the piece's last word (of the last chunk checked).
    pub last_output: u64,
    /// The first failure in word order, if any.
    pub failure: Option<SweepFailure>,
    /// Node-law cell counts for depths d..L (one sparse list of (cell, count) per depth).
    pub node_cells: Vec<Vec<(u32, u64)>>,
    /// Chunks scanned twice: the bitmap-free base-2 test or the sixteen-word scan found
    /// something there and the word-by-word scan named it (0 when everything passed; a
    /// diagnostic, not part of the verdict).
    #[serde(default)]
    pub rescanned_chunks: u64,
}

/// One chunk's record.
struct ChunkRecord {
    first: u64,
    last: u64,
    failure: Option<SweepFailure>,
    cells: Vec<Vec<u64>>,
    /// The binary test or the group scan found something, so the chunk was scanned again word
    /// by word.
    rescanned: bool,
}

/// Buffers one worker reuses from chunk to chunk.
struct Scratch {
    frame32: Vec<u32>,
    frame64: Vec<u64>,
    bitmap: Vec<u64>,
    node: Vec<Vec<u8>>,
}

impl Scratch {
    fn new(plan: &SweepPlan) -> Scratch {
        let frame = FRAME.min(plan.chunk_words() as usize);
        let laws = (plan.law_depths() - plan.chunk_digits()) as usize;
        let narrow = plan.width().bits() == 32 || group_scan::applies(plan);
        Scratch {
            frame32: Vec::with_capacity(if narrow { frame } else { 0 }),
            frame64: Vec::with_capacity(if plan.width().bits() == 32 { 0 } else { frame }),
            bitmap: vec![0; (1usize << block_low_bits(plan)).div_ceil(64)],
            node: vec![vec![0; plan.base().base() as usize]; laws],
        }
    }
}

/// Evaluates words `start..start + len` into the worker's frame and runs `f` on the outputs.
fn with_frame<R>(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    start: u64,
    len: usize,
    scratch: &mut Scratch,
    f: impl FnOnce(FrameOut<'_>, &mut [u64], &mut [Vec<u8>]) -> R,
) -> R {
    let Scratch {
        frame32,
        frame64,
        bitmap,
        node,
    } = scratch;
    if plan.width().bits() == 32 {
        frame32.resize(len, 0);
        for (i, x) in frame32.iter_mut().enumerate() {
            *x = start as u32 + i as u32;
        }
        s.scramble_batch_u32(frame32, dim);
        f(FrameOut::U32(frame32), bitmap, node)
    } else {
        frame64.resize(len, 0);
        for (i, x) in frame64.iter_mut().enumerate() {
            *x = start + i as u64;
        }
        s.scramble_batch(frame64, plan.width(), dim);
        f(FrameOut::U64(frame64), bitmap, node)
    }
}

/// A frame's outputs at their native width.
enum FrameOut<'a> {
    U32(&'a [u32]),
    U64(&'a [u64]),
}

impl FrameOut<'_> {
    fn get(&self, i: usize) -> u64 {
        match self {
            FrameOut::U32(v) => v[i] as u64,
            FrameOut::U64(v) => v[i],
        }
    }
    fn position(&self, y: u64) -> Option<usize> {
        match self {
            FrameOut::U32(v) => v.iter().position(|&o| o as u64 == y),
            FrameOut::U64(v) => v.iter().position(|&o| o == y),
        }
    }
}

/// Sweeps chunk `c`: in base 2 by the bitmap-free test, elsewhere in groups of sixteen words
/// where the blocks allow, and again word by word (with the bitmap) when those find something,
/// so that failures are named exactly as in the general scan.
fn scan_chunk(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    c: u64,
    scratch: &mut Scratch,
    progress: &dyn Progress,
    kernel: GroupKernel,
) -> ChunkRecord {
    let fast = if plan.base().q() == 1 {
        let r = scan_chunk_with::<true>(s, plan, dim, c, scratch, progress);
        r.failure.is_none().then_some(r)
    } else if group_scan::applies(plan) {
        scan_chunk_groups(s, plan, dim, c, scratch, progress, kernel)
    } else {
        return scan_chunk_with::<false>(s, plan, dim, c, scratch, progress);
    };
    fast.unwrap_or_else(|| {
        let mut again = scan_chunk_with::<false>(s, plan, dim, c, scratch, &Silent);
        again.rescanned = true;
        again
    })
}

/// Sweeps chunk `c` in groups of sixteen words; `None` when a check fails (to be named by the
/// word-by-word scan).
fn scan_chunk_groups(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    c: u64,
    scratch: &mut Scratch,
    progress: &dyn Progress,
    kernel: GroupKernel,
) -> Option<ChunkRecord> {
    let mut st = ChunkScan::new(plan);
    let lanes = GroupLanes::new(plan, st.law_mask);
    let start = plan.chunk_start(c);
    let total = plan.chunk_words();
    let mut first = 0;
    let mut done = 0u64;
    while done < total {
        let len = (total - done).min(FRAME as u64) as usize;
        let at = start + done;
        let (out, node) = frame_u32(s, plan, dim, at, len, scratch);
        if done == 0 {
            first = u64::from(out[0]);
        }
        if !st.scan_groups(kernel, &lanes, at, out, done == 0, node) {
            return None;
        }
        done += len as u64;
        progress.advance(len as u64);
    }
    Some(ChunkRecord {
        first,
        last: st.prev,
        failure: None,
        cells: st.cells,
        rescanned: false,
    })
}

/// Evaluates words `start..start + len` as 32-bit outputs (for widths below 32, outputs above
/// `u32::MAX` read as `u32::MAX`, which is out of range too) and the node-law scratch.
fn frame_u32<'s>(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    start: u64,
    len: usize,
    scratch: &'s mut Scratch,
) -> (&'s [u32], &'s mut [Vec<u8>]) {
    let Scratch {
        frame32,
        frame64,
        node,
        ..
    } = scratch;
    frame32.resize(len, 0);
    if plan.width().bits() == 32 {
        for (i, x) in frame32.iter_mut().enumerate() {
            *x = start as u32 + i as u32;
        }
        s.scramble_batch_u32(frame32, dim);
    } else {
        frame64.resize(len, 0);
        for (i, x) in frame64.iter_mut().enumerate() {
            *x = start + i as u64;
        }
        s.scramble_batch(frame64, plan.width(), dim);
        for (n, &y) in frame32.iter_mut().zip(frame64.iter()) {
            *n = y.min(u64::from(u32::MAX)) as u32;
        }
    }
    (frame32, node)
}

/// Sweeps chunk `c` with the binary test or the general one.
fn scan_chunk_with<const BINARY: bool>(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    c: u64,
    scratch: &mut Scratch,
    progress: &dyn Progress,
) -> ChunkRecord {
    let mut st = ChunkScan::new(plan);
    scratch.bitmap.fill(0);
    let start = plan.chunk_start(c);
    let total = plan.chunk_words();
    let mut first = 0;
    let mut failure = None;
    let mut done = 0u64;
    while done < total {
        let len = (total - done).min(FRAME as u64) as usize;
        let at = start + done;
        let result = with_frame(s, plan, dim, at, len, scratch, |out, bitmap, node| {
            let mut from = 0;
            if done == 0 {
                // The chunk's first word: no predecessor inside the chunk (the seam with the
                // chunk before is checked when records are joined).
                first = out.get(0);
                if first > plan.width().mask() {
                    return Err((
                        start,
                        SweepFailure::OutOfRange {
                            input: start,
                            output: first,
                        },
                    ));
                }
                if !BINARY {
                    st.child_start(start, first, bitmap)?;
                }
                st.mark(start, first, bitmap)?;
                if !st.cells.is_empty() {
                    st.record_law(start, first, node);
                }
                st.prev = first;
                from = 1;
            }
            match out {
                FrameOut::U32(v) => {
                    st.scan::<_, BINARY>(at + from as u64, &v[from..], bitmap, node)
                }
                FrameOut::U64(v) => {
                    st.scan::<_, BINARY>(at + from as u64, &v[from..], bitmap, node)
                }
            }
        });
        if let Err((x, f)) = result {
            failure = Some(match f {
                // The binary test only locates; the general rescan names.
                f if BINARY => f,
                SweepFailure::Collision { output, .. } => {
                    let other = find_input(s, plan, dim, start, x, output, scratch);
                    SweepFailure::Collision {
                        inputs: [other, x],
                        output,
                    }
                }
                f => f,
            });
            break;
        }
        done += len as u64;
        progress.advance(len as u64);
    }
    ChunkRecord {
        first,
        last: st.prev,
        failure,
        cells: st.cells,
        rescanned: false,
    }
}

/// The first input in `from..before` whose output is `y` (a collision's earlier partner).
fn find_input(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    from: u64,
    before: u64,
    y: u64,
    scratch: &mut Scratch,
) -> u64 {
    let mut at = from;
    while at < before {
        let len = (before - at).min(FRAME as u64) as usize;
        if let Some(i) = with_frame(s, plan, dim, at, len, scratch, |out, _, _| out.position(y)) {
            return at + i as u64;
        }
        at += len as u64;
    }
    unreachable!("a collision's partner lies before it in its chunk")
}

/// Sweeps chunks `chunks` of dimension `dim` of `s` under `plan`, in parallel on the current
/// rayon pool; `progress` advances by the number of words after each frame. The piece is the
/// same for any thread count. Scanning stops at the first failure (chunks after a failed one are
/// not needed to name it).
pub fn sweep(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    chunks: Range<u64>,
    progress: &dyn Progress,
) -> Result<SweepPiece, SweepError> {
    sweep_with(s, plan, dim, chunks, progress, GroupKernel::detect())
}

/// [`sweep`] with groups of sixteen words scanned by `kernel` (the piece is the same for every
/// kernel).
pub(super) fn sweep_with(
    s: &dyn Scrambler,
    plan: &SweepPlan,
    dim: u32,
    chunks: Range<u64>,
    progress: &dyn Progress,
    kernel: GroupKernel,
) -> Result<SweepPiece, SweepError> {
    plan.check_range(&chunks)?;
    let failed_at = AtomicU64::new(u64::MAX);
    let indices: Vec<u64> = chunks.clone().collect();
    let records: Vec<Option<ChunkRecord>> = indices
        .par_iter()
        .map_init(
            || Scratch::new(plan),
            |scratch, &c| {
                if c > failed_at.load(Ordering::Relaxed) {
                    return None;
                }
                let r = scan_chunk(s, plan, dim, c, scratch, progress, kernel);
                if r.failure.is_some() {
                    failed_at.fetch_min(c, Ordering::Relaxed);
                }
                Some(r)
            },
        )
        .collect();
    let cells = node_cells(plan.base().base());
    let laws = (plan.law_depths() - plan.chunk_digits()) as usize;
    let mut dense = vec![vec![0u64; cells]; laws];
    let mut piece = SweepPiece {
        width: plan.width().bits(),
        base: plan.base().base(),
        dim,
        chunks: [chunks.start, chunks.end],
        words: 0,
        images: Vec::new(),
        first_output: records[0].as_ref().map_or(0, |r| r.first),
        last_output: 0,
        failure: None,
        node_cells: Vec::new(),
        rescanned_chunks: records.iter().flatten().filter(|r| r.rescanned).count() as u64,
    };
    let shift = plan.width().bits() - plan.chunk_prefix_bits();
    for (c, record) in chunks.zip(&records) {
        // A chunk is skipped only after a failure in an earlier one, which ends this loop.
        let r = record
            .as_ref()
            .expect("chunks before the first failure are scanned");
        if c > piece.chunks[0] {
            if let Some(f) = plan.seam_failure(plan.chunk_start(c), piece.last_output, r.first) {
                piece.failure = Some(f);
                break;
            }
        }
        if let Some(f) = &r.failure {
            piece.failure = Some(f.clone());
            break;
        }
        piece.images.push(r.first >> shift);
        for (sum, add) in dense.iter_mut().zip(&r.cells) {
            for (a, b) in sum.iter_mut().zip(add) {
                *a += b;
            }
        }
        piece.words += plan.chunk_words();
        piece.last_output = r.last;
    }
    piece.node_cells = dense
        .into_iter()
        .map(|row| {
            row.into_iter()
                .enumerate()
                .filter(|&(_, n)| n > 0)
                .map(|(cell, n)| (cell as u32, n))
                .collect()
        })
        .collect();
    Ok(piece)
}
