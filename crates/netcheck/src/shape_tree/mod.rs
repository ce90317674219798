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
//! t = 0 in base 2^q (N = b^k points, one per box) is decided by setting bits only, and by
//! lanes: the leaves of a node all add parts of one width v, so a parent box gets a few 64-bit
//! words (one cache line at most) holding a b^v-bit lane per leaf, and one pass over the
//! points decides a group of leaves with one read-modify-write of a box's words per point.
//! Where one-digit lanes fit (b ≤ 64) the leaves are **delegated** to the nodes of Σd = k − 1:
//! a shape whose last nonzero part is v in dimension p is checked at the node ending in v − 1
//! there, its part's last digit a b-bit lane beside that node's leaves of a first digit in a
//! later dimension. So in base 16 every one of the 3,876 nodes of Σd = 4 decides all its
//! leaves (up to 16 lanes of 16 bits) in one pass, and no shape needs a b^v-bit map of its own.
//! The read-modify-write into a cache-missing table is the cost of a leaf, so sharing it is
//! what pays; digits of up to 8 bits come from a byte column (the top 8 bits of each prefix),
//! and key arrays of finished inner nodes are reused by the next, not zeroed afresh.
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
use crate::counting::Progress;
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
    /// Whether every leaf is checked at its node of Σd = k − 1 (see [`Walk::delegates`]).
    delegate: bool,
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
    /// `first`, or some failing shape's otherwise. `progress(1)` per shape checked.
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
        let mut walk = Walk {
            query: self,
            narrow,
            delegate: false,
        };
        walk.delegate = walk.delegates();
        if self.k == 0 {
            // One shape (all zeros), one box holding every point.
            let shape = vec![0u32; dims];
            let failure = walk.leaf(None, Part::head(0, 0), &shape);
            progress(1);
            return (failure, 1);
        }
        let root = vec![0u32; dims];
        walk.children(&root, 0, 0, NodeKeys::Stored(None), &found, progress);
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

/// The most 64-bit words a parent box's lanes take in a packed pass: one 64-byte cache line, so
/// a point's bits for every leaf of its group are one line's read-modify-write.
const MAX_BOX_WORDS: usize = 8;

/// The packed pass's layout: leaves per pass and 64-bit words per parent box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Packing {
    leaves: usize,
    words: usize,
}

/// One task of a node's children: an inner child (dimension, part), or a group of leaves
/// (dimensions) that share the node's keys and the part that completes Σd = k.
enum Step {
    Inner(usize, u32),
    Leaves(Vec<Part>),
}

/// Where a node's box keys come from.
#[derive(Debug, Clone, Copy)]
enum NodeKeys<'k> {
    /// Stored for every point (None: the empty shape's, all 0).
    Stored(Option<&'k [u32]>),
    /// Not stored: the parent's stored keys extended by the node's last part, built a block
    /// at a time by the pass that reads them (a node of Σd = k − 1 whose keys only its own
    /// leaf pass reads).
    Extended(Option<&'k [u32]>, Part),
}

impl<'k> NodeKeys<'k> {
    /// The stored keys, if they are.
    fn stored(self) -> Option<Option<&'k [u32]>> {
        match self {
            NodeKeys::Stored(keys) => Some(keys),
            NodeKeys::Extended(..) => None,
        }
    }
}

/// Digits `from..from + width` (digit 0 most significant) of dimension `dim`: what a child
/// shape adds to its node's box keys. The child has part `from + width` in `dim`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Part {
    dim: usize,
    from: u32,
    width: u32,
}

impl Walk<'_, '_> {
    /// Checks the subtree below the partial shape `shape` (Σd = `sum`, next part at a
    /// dimension ≥ `next`), whose keys are `keys`.
    fn children(
        &self,
        shape: &[u32],
        next: usize,
        sum: u32,
        keys: NodeKeys,
        found: &Found,
        progress: Progress,
    ) {
        let q = self.query;
        let dims = shape.len();
        let last = q.k - sum;
        let parts = self.leaf_parts(shape, next, sum);
        let lanes = parts
            .first()
            .and_then(|part| self.lanes(sum, part.width, parts.len()));
        let group = lanes.map_or(1, |plan| plan.leaves);
        if let NodeKeys::Extended(..) = keys {
            // A node of Σd = k − 1 whose keys were not stored: its leaves only, one group
            // after another in this task (their lanes fit one pass but for very many dimensions).
            for parts in parts.chunks(group) {
                self.decide(keys, shape, parts.to_vec(), lanes, found, progress);
            }
            return;
        }
        let steps: Vec<Step> = parts
            .chunks(group)
            .map(|g| Step::Leaves(g.to_vec()))
            .chain((next..dims).flat_map(|p| (1..last).map(move |v| Step::Inner(p, v))))
            .collect();
        steps.into_par_iter().for_each(|step| {
            if found.stop.load(Ordering::Relaxed) {
                return;
            }
            match step {
                Step::Leaves(parts) => self.decide(keys, shape, parts, lanes, found, progress),
                Step::Inner(p, v) => {
                    let mut child = shape.to_vec();
                    child[p] = v;
                    if q.skip(&least_completion(&child, q.k), found) {
                        return;
                    }
                    let part = Part::head(p, v);
                    let parent = keys
                        .stored()
                        .expect("only stored nodes have inner children");
                    if self.delegate && sum + v + 1 == q.k {
                        // Leaves only below: their pass extends this node's keys on the fly.
                        let keys = NodeKeys::Extended(parent, part);
                        self.children(&child, p + 1, sum + v, keys, found, progress);
                    } else {
                        let extended = self.extend_all(parent, part);
                        let keys = NodeKeys::Stored(Some(&extended));
                        self.children(&child, p + 1, sum + v, keys, found, progress);
                        KEY_POOL.with(|pool| pool.borrow_mut().push(extended));
                    }
                }
            }
        });
    }

    /// The parts that complete the node `shape` (Σd = `sum`, later parts at dimensions ≥
    /// `next`) to its leaves: the rest of k in each later dimension, or, when leaves are
    /// delegated, one more digit at a node of Σd = k − 1 and none elsewhere.
    fn leaf_parts(&self, shape: &[u32], next: usize, sum: u32) -> Vec<Part> {
        let (dims, last) = (shape.len(), self.query.k - sum);
        if !self.delegate {
            (next..dims).map(|dim| Part::head(dim, last)).collect()
        } else if last == 1 {
            // The node's last nonzero dimension's next digit (the leaf its parent delegated)
            // and the first digit of each dimension after it.
            let own = next.checked_sub(1).filter(|_| sum > 0);
            own.into_iter()
                .chain(next..dims)
                .map(|dim| Part {
                    dim,
                    from: shape[dim],
                    width: 1,
                })
                .collect()
        } else {
            Vec::new()
        }
    }

    /// Decides the leaves `node` + `parts` of one group: by their lanes in one pass when
    /// `lanes` packs them, by one bitmap for a lone leaf of the bit pass, and by the general
    /// count (which finds and describes the first failing box) otherwise or on a collision.
    fn decide(
        &self,
        keys: NodeKeys,
        node: &[u32],
        parts: Vec<Part>,
        lanes: Option<Packing>,
        found: &Found,
        progress: Progress,
    ) {
        let q = self.query;
        let (live, shapes): (Vec<Part>, Vec<Vec<u32>>) = parts
            .into_iter()
            .map(|part| {
                let mut child = node.to_vec();
                child[part.dim] = part.from + part.width;
                (part, child)
            })
            .filter(|(_, child)| !q.skip(child, found))
            .unzip();
        // A node whose keys were not stored builds them once, if a leaf needs them.
        let mut built: Option<Vec<u32>> = None;
        let distinct = match (lanes, live.as_slice()) {
            (_, []) => Vec::new(),
            (Some(plan), _) => self.distinct_packed(keys, &live, plan.words),
            (None, &[part]) if self.bit_pass() => match keys {
                NodeKeys::Stored(keys) => vec![self.distinct_keys(keys, part)],
                NodeKeys::Extended(parent, node_part) => {
                    let keys = built.get_or_insert_with(|| self.extend_all(parent, node_part));
                    vec![self.distinct_keys(Some(keys), part)]
                }
            },
            _ => vec![false; live.len()],
        };
        for ((&part, child), distinct) in live.iter().zip(&shapes).zip(distinct) {
            if !distinct {
                found.general.fetch_add(1, Ordering::Relaxed);
                let failure = match keys {
                    NodeKeys::Stored(keys) => self.leaf(keys, part, child),
                    NodeKeys::Extended(parent, node_part) => {
                        let keys = built.get_or_insert_with(|| self.extend_all(parent, node_part));
                        self.leaf(Some(keys), part, child)
                    }
                };
                if let Some(f) = failure {
                    q.record(f, found);
                }
            }
            progress(1);
        }
        if let Some(keys) = built {
            KEY_POOL.with(|pool| pool.borrow_mut().push(keys));
        }
    }

    /// Whether every leaf is checked one digit past its node of Σd = k − 1: t = 0 in base
    /// 2^q, one-digit lanes (b ≤ 64) and box words that fit [`MAX_MASK_BYTES`]. A shape whose
    /// last nonzero part is v in dimension p is then checked at the node ending in v − 1
    /// there (the part's last digit in a b-bit lane beside the node's other leaves), not by a
    /// b^v-bit map of its own: each node of Σd = k − 1 decides all its leaves in one pass.
    fn delegates(&self) -> bool {
        self.query.k >= 1 && self.lanes(self.query.k - 1, 1, 1).is_some()
    }

    /// Whether leaves are checked by a pass that only sets bits: t = 0 (one point per box) in
    /// base 2^q, where N = b^k points must fill the b^k boxes of every shape.
    fn bit_pass(&self) -> bool {
        self.query.t_count == 1 && self.query.base.log2().is_some()
    }

    /// How the packed pass below a node with Σd = `sum` and `leaves` leaves of part `v` runs:
    /// each parent box gets `words` 64-bit words holding a b^v-bit lane per leaf (bit d for
    /// v-digit value d), so one box's words take every point's bits of up to `leaves` leaves
    /// at once. The words are as few as hold the leaves, at most [`MAX_BOX_WORDS`] (one cache
    /// line) and at most [`MAX_MASK_BYTES`] in all. None when the bit pass does not apply or a
    /// lane would not fit in a word.
    fn lanes(&self, sum: u32, v: u32, leaves: usize) -> Option<Packing> {
        let q = self.query;
        let lane = q.base.pow(v).filter(|&w| w <= 64)? as usize;
        let boxes = q.base.pow(sum).expect("validated") as usize;
        let fit = MAX_MASK_BYTES / boxes.checked_mul(8)?;
        if !self.bit_pass() || fit == 0 || leaves == 0 {
            return None;
        }
        let per_word = 64 / lane;
        let words = leaves
            .div_ceil(per_word)
            .next_power_of_two()
            .min(MAX_BOX_WORDS)
            .min(1 << fit.ilog2());
        Some(Packing {
            leaves: words * per_word,
            words,
        })
    }

    /// Keys of the parent extended by `part`'s digits, for points start..+len (the empty
    /// shape's keys are 0). Always inlined, so the t = 0 pass builds its keys with the vector
    /// width it was compiled for.
    #[inline(always)]
    fn extend(&self, parent: Option<&[u32]>, part: Part, start: usize, out: &mut [u32]) {
        let q = self.query;
        match q.base.log2() {
            Some(log) => extend_pow2(parent, &self.column(part), log * part.width, start, out),
            None => {
                let end = start + out.len();
                let parent = parent.map(|parent| &parent[start..end]);
                let below = q.depth - part.from - part.width;
                let cut = q.base.pow(below).expect("validated") as u32;
                let place = q.base.pow(part.width).expect("validated") as u32;
                let digits = &q.prefix[part.dim][start..end];
                extend_with(parent, digits, out, |a, x| a * place + x / cut % place);
            }
        }
    }

    /// Whether the keys of all points (parent keys extended by `part`) are distinct: the
    /// t = 0 check in base 2^q, one bit per box. N keys below N = b^k are distinct exactly
    /// when N bits end up set, so the pass only sets bits (no test per point) and a popcount
    /// decides. Says only yes or no; a `false` is described by the general check.
    fn distinct_keys(&self, parent: Option<&[u32]>, part: Part) -> bool {
        let q = self.query;
        let cells = q.base.pow(q.k).expect("validated") as usize;
        SCRATCH.with(|scratch| {
            let mut bits = scratch.borrow_mut();
            bits.clear();
            bits.resize(cells.div_ceil(32), 0);
            let log = q.base.log2().expect("the bit pass is for b = 2^q");
            set_key_bits(q.n, &mut bits, parent, &self.column(part), log * part.width);
            bits.iter().map(|w| w.count_ones() as u64).sum::<u64>() == q.n as u64
        })
    }

    /// [`Self::distinct_keys`] for a group of leaves sharing the parent keys (b^Σd parent
    /// boxes) and the width v of their parts, in one pass: lane l of the words of parent box
    /// K gets bit d for each point of that box whose `parts[l]` digits have value d. A leaf's
    /// keys (K, d) are distinct exactly when its lane is full in every box, since its
    /// N = b^Σd · b^v points must then hit all b^Σd · b^v pairs once.
    fn distinct_packed(&self, keys: NodeKeys, parts: &[Part], words: usize) -> Vec<bool> {
        let q = self.query;
        let log = q.base.log2().expect("packed for b = 2^q");
        let v = parts[0].width;
        assert!(parts.iter().all(|part| part.width == v), "one lane width");
        let (boxes, lane) = (q.n >> (log * v), 1u32 << (log * v));
        assert!(
            parts.len() * lane as usize <= words * 64,
            "the lanes fit the box words"
        );
        MASKS.with(|masks| {
            let mut masks = masks.borrow_mut();
            masks.clear();
            masks.resize(boxes * words, 0);
            let columns: Vec<DigitColumn> = parts.iter().map(|&part| self.column(part)).collect();
            let (parent, node) = match keys {
                NodeKeys::Stored(keys) => (keys, None),
                NodeKeys::Extended(parent, part) => (parent, Some(part)),
            };
            let node_column = node.map(|part| (self.column(part), log * part.width));
            let node = node_column.as_ref().map(|(column, shift)| (column, *shift));
            match words {
                1 => set_lane_bits::<1>(q.n, &mut masks, parent, node, &columns, lane),
                2 => set_lane_bits::<2>(q.n, &mut masks, parent, node, &columns, lane),
                4 => set_lane_bits::<4>(q.n, &mut masks, parent, node, &columns, lane),
                8 => set_lane_bits::<8>(q.n, &mut masks, parent, node, &columns, lane),
                _ => unreachable!("box words are 1, 2, 4 or 8"),
            }
            let full = if lane == 64 {
                u64::MAX
            } else {
                (1u64 << lane) - 1
            };
            // A lane is full in every box exactly when it is full in the AND of all boxes.
            let mut every = [u64::MAX; MAX_BOX_WORDS];
            for box_words in masks.chunks_exact(words) {
                for (acc, &w) in every.iter_mut().zip(box_words) {
                    *acc &= w;
                }
            }
            (0..parts.len())
                .map(|l| {
                    let (word, shift) = (l * lane as usize / 64, l as u32 * lane % 64);
                    (every[word] >> shift) & full == full
                })
                .collect()
        })
    }

    /// Where `part`'s digits are read (base 2^q): the narrow column when they lie in its top
    /// 8 bits, else the prefixes.
    fn column(&self, part: Part) -> DigitColumn<'_> {
        let q = self.query;
        let log = q.base.log2().expect("a power-of-two base");
        let (end, mask) = (log * (part.from + part.width), low_bits(log * part.width));
        if end <= 8 && !self.narrow.is_empty() {
            DigitColumn::Narrow(&self.narrow[part.dim], 8 - end, mask)
        } else {
            DigitColumn::Wide(q.prefix[part.dim], log * q.depth - end, mask)
        }
    }

    /// The keys of an inner node, for every point.
    fn extend_all(&self, parent: Option<&[u32]>, part: Part) -> Vec<u32> {
        let n = self.query.n;
        let mut out = KEY_POOL
            .with(|pool| pool.borrow_mut().pop())
            .filter(|keys| keys.len() == n)
            .unwrap_or_else(|| vec![0u32; n]);
        match self.query.base.log2() {
            Some(log) => extend_all_pow2(parent, &self.column(part), log * part.width, &mut out),
            None => {
                for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
                    self.extend(parent, part, c * CHUNK, chunk);
                }
            }
        }
        out
    }

    /// The general box check of a leaf: the parent's keys extended chunk by chunk into the
    /// counters.
    fn leaf(&self, parent: Option<&[u32]>, part: Part, shape: &[u32]) -> Option<BoxFailure> {
        let q = self.query;
        SCRATCH.with(|scratch| {
            let mut scratch = scratch.borrow_mut();
            let fill = |start: usize, keys: &mut [u32]| {
                if part.width == 0 {
                    keys.fill(0);
                } else {
                    self.extend(parent, part, start, keys);
                }
            };
            check_shape(fill, 0, q.n, q.base, q.k, q.t_count, shape, &mut scratch)
        })
    }
}

impl Part {
    /// The first `width` digits of dimension `dim`.
    fn head(dim: usize, width: u32) -> Part {
        Part {
            dim,
            from: 0,
            width,
        }
    }
}

/// The low `bits` bits set (all 32 for 32 or more).
fn low_bits(bits: u32) -> u32 {
    u32::MAX.checked_shr(32 - bits.min(32)).unwrap_or(0)
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
