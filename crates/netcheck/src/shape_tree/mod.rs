//! Every shape with Σd = k, checked by walking the tree of shape prefixes.
//!
//! A shape's box key is built dimension by dimension (dimension 1 most significant), so the
//! key of a shape whose last nonzero part is d_p in dimension p extends its parent's (the shape
//! without that part): key = parent · b^(d_p) + a_p, a shift and an OR for b = 2^q. The walk
//! visits partial shapes depth-first by their nonzero parts; an inner node (Σd < k) stores its
//! N keys once, and each leaf (Σd = k) extends its parent's keys chunk by chunk straight into
//! the box check, without storing them. A leaf costs one pass over the points instead of one
//! per nonzero part, and inner nodes are few: for k = 5 in 16 dimensions, 4,844 inner nodes
//! serve 15,504 shapes.
//!
//! t = 0 in base 2^q (N = b^k points, one per box) is decided by setting bits only. The
//! leaves of a node all add the same part v = k − Σd (in different dimensions), so when a
//! lane of b^v bits fits in a 64-bit word they share one pass: one word per parent box, one
//! lane per leaf, one read-modify-write per point for 64 / b^v leaves (4 in base 16, where
//! 11,628 of the 15,504 shapes of k = 5 end in a part of 1). The read-modify-write into a
//! cache-missing table is the cost of a leaf, so sharing it is what pays; digits of up to 8
//! bits come from a byte column (the top 8 bits of each prefix), and key arrays of finished
//! inner nodes are reused by the next, not zeroed afresh.
//!
//! Parallel: children of a node are checked by rayon tasks; a worker holds at most one key
//! array per level of the walk (k − 1 arrays of N keys, 4 bytes each) besides its box
//! counters and lane words (at most [`MAX_MASK_BYTES`]); the byte columns add s·N bytes.
//! Early exit: the first-failure search skips every subtree whose least shape is after the
//! best failure found so far, and the any-failure search stops at the first one.

mod kernels;
#[cfg(test)]
mod tests;

use crate::box_keys::{check_shape, CHUNK};
use crate::Progress;
use crate::{BoxFailure, CheckBase};
use kernels::{
    extend_all_pow2, extend_pow2, extend_with, set_key_bits, set_lane_bits, DigitColumn,
};
use rayon::prelude::*;
use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;

/// One level's query: prefixes floor(x·b^depth) per dimension, shapes with Σd = k, boxes of
/// b^t points.
pub(crate) struct ShapeWalk<'a> {
    pub(crate) prefix: &'a [&'a [u32]],
    pub(crate) depth: u32,
    pub(crate) base: CheckBase,
    pub(crate) k: u32,
    pub(crate) t_count: u64,
    pub(crate) n: usize,
}

/// A walk with its narrow digit columns: the top 8 bits of every prefix (b = 2^q, q·depth ≥
/// 8, k ≥ 2), so a part of q·v ≤ 8 bits is read from 1 byte per point instead of 4. Leaves
/// and inner nodes stream their digit column from memory once per pass, so a pass over a
/// narrow column moves about half the bytes.
struct Walk<'a, 'b> {
    query: &'b ShapeWalk<'a>,
    narrow: Vec<Vec<u8>>,
}

/// What a walk has found so far.
struct Found {
    /// The least failing shape so far (lexicographic) and its box.
    best: Mutex<Option<BoxFailure>>,
    /// Set when any failure is enough and one was found.
    stop: AtomicBool,
    /// Whether the least failing shape is wanted (else any).
    first: bool,
    /// Leaves decided by the general count (no bit pass applies, or one said no).
    general: AtomicU64,
}

thread_local! {
    /// Box counters of the worker (reused across shapes).
    static SCRATCH: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
    /// Lane masks of the worker's packed leaf pass (reused across groups).
    static MASKS: RefCell<Vec<u64>> = const { RefCell::new(Vec::new()) };
    /// Inner nodes' key arrays the worker has finished with, reused (no zeroing, no fresh
    /// pages) by the next inner node: every key is overwritten.
    static KEY_POOL: RefCell<Vec<Vec<u32>>> = const { RefCell::new(Vec::new()) };
}

impl ShapeWalk<'_> {
    /// Checks every shape; returns the lexicographically least failing shape's first box when
    /// `first`, or some failing shape's otherwise. `progress.advance(1)` per shape checked.
    pub(crate) fn run(&self, first: bool, progress: Progress) -> Option<BoxFailure> {
        self.run_counted(first, progress).0
    }

    /// [`Self::run`], and how many leaves the general count decided: none on a t = 0 net in
    /// base 2^q, where the bit passes decide every shape (tested).
    fn run_counted(&self, first: bool, progress: Progress) -> (Option<BoxFailure>, u64) {
        let found = Found {
            best: Mutex::new(None),
            stop: AtomicBool::new(false),
            first,
            general: AtomicU64::new(0),
        };
        let dims = self.prefix.len();
        let narrow = match self.base.log2() {
            Some(q) if q * self.depth >= 8 && self.k >= 2 => {
                let cut = q * self.depth - 8;
                self.prefix
                    .par_iter()
                    .map(|column| column.iter().map(|&x| (x >> cut) as u8).collect())
                    .collect()
            }
            _ => Vec::new(),
        };
        let walk = Walk {
            query: self,
            narrow,
        };
        if self.k == 0 {
            // One shape (all zeros), one box holding every point.
            let shape = vec![0u32; dims];
            let failure = walk.leaf(None, 0, 0, &shape);
            progress.advance(1);
            return (failure, 1);
        }
        let root = vec![0u32; dims];
        walk.children(&root, 0, 0, None, &found, progress);
        let general = found.general.into_inner();
        (
            found.best.into_inner().expect("no worker panicked"),
            general,
        )
    }
}

/// The largest lane-mask array (bytes) a packed leaf pass may use per worker: a leaf group
/// needs one 64-bit word per parent box, which is more than a bitmap's b^k bits when lanes
/// are narrow (base 2), so deep binary levels keep the one-bitmap-per-leaf pass.
const MAX_MASK_BYTES: usize = 4 << 20;

/// One task of a node's children: an inner child (dimension, part), or a group of leaves
/// (dimensions) that share the node's keys and the part that completes Σd = k.
enum Step {
    Inner(usize, u32),
    Leaves(Vec<usize>),
}

impl Walk<'_, '_> {
    /// Checks the subtree below the partial shape `shape` (Σd = `sum`, next part at a
    /// dimension ≥ `next`), whose keys are `keys` (None for the empty shape).
    fn children(
        &self,
        shape: &[u32],
        next: usize,
        sum: u32,
        keys: Option<&[u32]>,
        found: &Found,
        progress: Progress,
    ) {
        let q = self.query;
        let dims = shape.len();
        let last = q.k - sum;
        let lanes = self.lanes(sum, last);
        let group = lanes.unwrap_or(1);
        let leaves: Vec<usize> = (next..dims).collect();
        let steps: Vec<Step> = leaves
            .chunks(group)
            .map(|g| Step::Leaves(g.to_vec()))
            .chain((next..dims).flat_map(|p| (1..last).map(move |v| Step::Inner(p, v))))
            .collect();
        steps.into_par_iter().for_each(|step| {
            if found.stop.load(Ordering::Relaxed) {
                return;
            }
            match step {
                Step::Leaves(ps) => {
                    let (live, shapes): (Vec<usize>, Vec<Vec<u32>>) = ps
                        .into_iter()
                        .map(|p| {
                            let mut child = shape.to_vec();
                            child[p] = last;
                            (p, child)
                        })
                        .filter(|(_, child)| !q.skip(child, found))
                        .unzip();
                    let distinct = match (lanes, live.as_slice()) {
                        (_, []) => Vec::new(),
                        (Some(_), _) => self.distinct_packed(keys, &live, last),
                        (None, &[p]) if self.bit_pass() => vec![self.distinct_keys(keys, p, last)],
                        _ => vec![false; live.len()],
                    };
                    for ((&p, child), distinct) in live.iter().zip(&shapes).zip(distinct) {
                        if !distinct {
                            // No bit pass, or a collision: the general check finds and
                            // describes the first failing box.
                            found.general.fetch_add(1, Ordering::Relaxed);
                            if let Some(f) = self.leaf(keys, p, last, child) {
                                q.record(f, found);
                            }
                        }
                        progress.advance(1);
                    }
                }
                Step::Inner(p, v) => {
                    let mut child = shape.to_vec();
                    child[p] = v;
                    if q.skip(&least_completion(&child, q.k), found) {
                        return;
                    }
                    let extended = self.extend_all(keys, p, v);
                    self.children(&child, p + 1, sum + v, Some(&extended), found, progress);
                    KEY_POOL.with(|pool| pool.borrow_mut().push(extended));
                }
            }
        });
    }

    /// Whether leaves are checked by a pass that only sets bits: t = 0 (one point per box) in
    /// base 2^q, where N = b^k points must fill the b^k boxes of every shape.
    fn bit_pass(&self) -> bool {
        self.query.t_count == 1 && self.query.base.log2().is_some()
    }

    /// Leaves per packed pass below a node with Σd = `sum` whose leaves add part `v`: each
    /// parent box gets one 64-bit word holding a b^v-bit lane per leaf (bit d for v-digit
    /// value d), so 64 / b^v leaves share one read-modify-write per point. None when the bit
    /// pass does not apply, a lane would not fit in a word, or the words would exceed
    /// [`MAX_MASK_BYTES`]. (Wider lanes sharing a cache line were measured no faster than
    /// one bitmap per leaf: the cost is the read-modify-write, not the line.)
    fn lanes(&self, sum: u32, v: u32) -> Option<usize> {
        let q = self.query;
        let lane = q.base.pow(v).filter(|&w| w <= 64)? as usize;
        let words = q.base.pow(sum).expect("validated") as usize;
        (self.bit_pass() && words.checked_mul(8)? <= MAX_MASK_BYTES).then_some(64 / lane)
    }

    /// Keys of the parent extended by part `v` in dimension `p`, for points start..+len
    /// (the empty shape's keys are 0). Always inlined, so the t = 0 pass builds its keys with
    /// the vector width it was compiled for.
    #[inline(always)]
    fn extend(&self, parent: Option<&[u32]>, p: usize, v: u32, start: usize, out: &mut [u32]) {
        let q = self.query;
        match q.base.log2() {
            Some(log) => extend_pow2(parent, &self.column(p, v), log * v, start, out),
            None => {
                let end = start + out.len();
                let parent = parent.map(|parent| &parent[start..end]);
                let cut = q.base.pow(q.depth - v).expect("validated") as u32;
                let place = q.base.pow(v).expect("validated") as u32;
                let digits = &q.prefix[p][start..end];
                extend_with(parent, digits, out, |a, x| a * place + x / cut);
            }
        }
    }

    /// Whether the keys of all points (parent keys extended by part `v` in dimension `p`)
    /// are distinct: the t = 0 check in base 2^q, one bit per box. N keys below N = b^k are
    /// distinct exactly when N bits end up set, so the pass only sets bits (no test per point)
    /// and a popcount decides. Says only yes or no; a `false` is described by the general
    /// check.
    fn distinct_keys(&self, parent: Option<&[u32]>, p: usize, v: u32) -> bool {
        let q = self.query;
        let cells = q.base.pow(q.k).expect("validated") as usize;
        SCRATCH.with(|scratch| {
            let mut bits = scratch.borrow_mut();
            bits.clear();
            bits.resize(cells.div_ceil(32), 0);
            let log = q.base.log2().expect("the bit pass is for b = 2^q");
            set_key_bits(q.n, &mut bits, parent, &self.column(p, v), log * v);
            bits.iter().map(|w| w.count_ones() as u64).sum::<u64>() == q.n as u64
        })
    }

    /// [`Self::distinct_keys`] for a group of leaves sharing the parent keys (b^Σd parent
    /// boxes) and part `v`, in one pass: lane l of the word of parent box K gets bit d for
    /// each point of that box whose dimension `dims[l]` has v-digit value d. A leaf's keys
    /// (K, d) are distinct exactly when its lane is full in every word, since its N = b^Σd ·
    /// b^v points must then hit all b^Σd · b^v pairs once.
    fn distinct_packed(&self, parent: Option<&[u32]>, dims: &[usize], v: u32) -> Vec<bool> {
        let q = self.query;
        let log = q.base.log2().expect("packed for b = 2^q");
        let (boxes, lane) = (q.n >> (log * v), 1u32 << (log * v));
        MASKS.with(|masks| {
            let mut masks = masks.borrow_mut();
            masks.clear();
            masks.resize(boxes, 0);
            let columns: Vec<DigitColumn> = dims.iter().map(|&p| self.column(p, v)).collect();
            set_lane_bits(q.n, &mut masks, parent, &columns, lane);
            let full = if lane == 64 {
                u64::MAX
            } else {
                (1u64 << lane) - 1
            };
            (0..dims.len())
                .map(|l| {
                    let shift = l as u32 * lane;
                    masks.iter().all(|&w| (w >> shift) & full == full)
                })
                .collect()
        })
    }

    /// Where the v-digit values of dimension `p` are read (base 2^q): the narrow column when
    /// q·v ≤ 8 bits fit in it, else the prefixes.
    fn column(&self, p: usize, v: u32) -> DigitColumn<'_> {
        let q = self.query;
        let log = q.base.log2().expect("a power-of-two base");
        if log * v <= 8 && !self.narrow.is_empty() {
            DigitColumn::Narrow(&self.narrow[p], 8 - log * v)
        } else {
            DigitColumn::Wide(q.prefix[p], log * (q.depth - v))
        }
    }

    /// The keys of an inner node, for every point.
    fn extend_all(&self, parent: Option<&[u32]>, p: usize, v: u32) -> Vec<u32> {
        let n = self.query.n;
        let mut out = KEY_POOL
            .with(|pool| pool.borrow_mut().pop())
            .filter(|keys| keys.len() == n)
            .unwrap_or_else(|| vec![0u32; n]);
        match self.query.base.log2() {
            Some(log) => extend_all_pow2(parent, &self.column(p, v), log * v, &mut out),
            None => {
                for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
                    self.extend(parent, p, v, c * CHUNK, chunk);
                }
            }
        }
        out
    }

    /// The general box check of a leaf: the parent's keys extended chunk by chunk into the
    /// counters.
    fn leaf(&self, parent: Option<&[u32]>, p: usize, v: u32, shape: &[u32]) -> Option<BoxFailure> {
        let q = self.query;
        SCRATCH.with(|scratch| {
            let mut scratch = scratch.borrow_mut();
            let fill = |start: usize, keys: &mut [u32]| {
                if v == 0 {
                    keys.fill(0);
                } else {
                    self.extend(parent, p, v, start, keys);
                }
            };
            check_shape(fill, 0, q.n, q.base, q.k, q.t_count, shape, &mut scratch)
        })
    }
}

impl ShapeWalk<'_> {
    /// Whether a shape (or a subtree whose least shape it is) can be skipped.
    fn skip(&self, shape: &[u32], found: &Found) -> bool {
        if found.stop.load(Ordering::Relaxed) {
            return true;
        }
        found.first
            && found
                .best
                .lock()
                .expect("no worker panicked")
                .as_ref()
                .is_some_and(|b| b.shape.as_slice() < shape)
    }

    fn record(&self, failure: BoxFailure, found: &Found) {
        let mut best = found.best.lock().expect("no worker panicked");
        if best.as_ref().is_none_or(|b| failure.shape < b.shape) {
            *best = Some(failure);
        }
        if !found.first {
            found.stop.store(true, Ordering::Relaxed);
        }
    }
}

/// The lexicographically least shape with Σd = k that extends the partial shape `partial`
/// (whose parts after its last nonzero one are free): the rest of k in the last dimension. The
/// first-failure search skips a subtree when this is already after the best failure.
fn least_completion(partial: &[u32], k: u32) -> Vec<u32> {
    let mut least = partial.to_vec();
    let sum: u32 = partial.iter().sum();
    if let Some(last) = least.last_mut() {
        *last += k - sum;
    }
    least
}
