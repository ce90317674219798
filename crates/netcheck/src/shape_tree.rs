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
//! Parallel: children of a node are checked by rayon tasks; a worker holds at most one key
//! array per level of the walk (k − 1 arrays of N keys, 4 bytes each) besides its box
//! counters. Early exit: the first-failure search skips every subtree whose least shape is
//! after the best failure found so far, and the any-failure search stops at the first one.

use crate::box_keys::{check_shape, CHUNK};
use crate::counting::Progress;
use crate::{BoxFailure, CheckBase};
use rayon::prelude::*;
use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
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

/// What a walk has found so far.
struct Found {
    /// The least failing shape so far (lexicographic) and its box.
    best: Mutex<Option<BoxFailure>>,
    /// Set when any failure is enough and one was found.
    stop: AtomicBool,
    /// Whether the least failing shape is wanted (else any).
    first: bool,
}

thread_local! {
    /// Box counters of the worker (reused across shapes).
    static SCRATCH: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
}

impl ShapeWalk<'_> {
    /// Checks every shape; returns the lexicographically least failing shape's first box when
    /// `first`, or some failing shape's otherwise. `progress(1)` per shape checked.
    pub(crate) fn run(&self, first: bool, progress: Progress) -> Option<BoxFailure> {
        let found = Found {
            best: Mutex::new(None),
            stop: AtomicBool::new(false),
            first,
        };
        let dims = self.prefix.len();
        if self.k == 0 {
            // One shape (all zeros), one box holding every point.
            let shape = vec![0u32; dims];
            let failure = self.leaf(None, 0, 0, &shape);
            progress(1);
            return failure;
        }
        let root = vec![0u32; dims];
        self.children(&root, 0, 0, None, &found, progress);
        found.best.into_inner().expect("no worker panicked")
    }

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
        let dims = shape.len();
        let options: Vec<(usize, u32)> = (next..dims)
            .flat_map(|p| (1..=self.k - sum).map(move |v| (p, v)))
            .collect();
        options.into_par_iter().for_each(|(p, v)| {
            if found.stop.load(Ordering::Relaxed) {
                return;
            }
            let mut child = shape.to_vec();
            child[p] = v;
            if sum + v == self.k {
                if self.skip(&child, found) {
                    return;
                }
                let failure = self.leaf(keys, p, v, &child);
                progress(1);
                if let Some(f) = failure {
                    self.record(f, found);
                }
            } else {
                if self.skip(&least_completion(&child, self.k), found) {
                    return;
                }
                let extended = self.extend_all(keys, p, v);
                self.children(&child, p + 1, sum + v, Some(&extended), found, progress);
            }
        });
    }

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

    /// Keys of the parent extended by part `v` in dimension `p`, for points start..+len
    /// (the empty shape's keys are 0). Always inlined, so the t = 0 pass builds its keys with
    /// the vector width it was compiled for.
    #[inline(always)]
    fn extend(&self, parent: Option<&[u32]>, p: usize, v: u32, start: usize, out: &mut [u32]) {
        let digits = &self.prefix[p][start..start + out.len()];
        let parent = parent.map(|parent| &parent[start..start + out.len()]);
        match self.base.log2() {
            Some(q) => {
                let (cut, shift) = (q * (self.depth - v), q * v);
                extend_with(parent, digits, out, |a, x| (a << shift) | (x >> cut));
            }
            None => {
                let cut = self.base.pow(self.depth - v).expect("validated") as u32;
                let place = self.base.pow(v).expect("validated") as u32;
                extend_with(parent, digits, out, |a, x| a * place + x / cut);
            }
        }
    }

    /// Whether the keys (parent << shift) | (prefix_p >> cut) of all points are distinct: the
    /// t = 0 check in base 2^q, one bit per box. N keys below N = b^k are distinct exactly
    /// when N bits end up set, so the pass only sets bits (no test per point) and a popcount
    /// decides. Keys are built a chunk at a time (vectorized) and the bit loop is compiled
    /// with BMI2 where the CPU has it. Says only yes or no; a `false` is described by the
    /// general check.
    fn distinct_keys(&self, parent: &[u32], p: usize, v: u32, bits: &mut Vec<u32>) -> bool {
        let cells = self.base.pow(self.k).expect("validated") as usize;
        bits.clear();
        bits.resize(cells.div_ceil(32), 0);
        set_key_bits(self.n, bits, |start, keys| {
            self.extend(Some(parent), p, v, start, keys)
        });
        bits.iter().map(|w| w.count_ones() as u64).sum::<u64>() == self.n as u64
    }

    /// The keys of an inner node, for every point.
    fn extend_all(&self, parent: Option<&[u32]>, p: usize, v: u32) -> Vec<u32> {
        let mut out = vec![0u32; self.n];
        for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
            self.extend(parent, p, v, c * CHUNK, chunk);
        }
        out
    }

    /// The box check of a leaf: the parent's keys extended chunk by chunk into the counters.
    fn leaf(&self, parent: Option<&[u32]>, p: usize, v: u32, shape: &[u32]) -> Option<BoxFailure> {
        SCRATCH.with(|scratch| {
            let mut scratch = scratch.borrow_mut();
            if let (1, true, Some(parent), true) =
                (self.t_count, self.base.log2().is_some(), parent, v > 0)
            {
                if self.distinct_keys(parent, p, v, &mut scratch) {
                    return None;
                }
                // A collision: the general check below finds and describes the first one.
            }
            let fill = |start: usize, keys: &mut [u32]| {
                if v == 0 {
                    keys.fill(0);
                } else {
                    self.extend(parent, p, v, start, keys);
                }
            };
            check_shape(
                fill,
                0,
                self.n,
                self.base,
                self.k,
                self.t_count,
                shape,
                &mut scratch,
            )
        })
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

/// `out[i] = f(parent[i], digits[i])`, with parent keys 0 for the empty shape: one branch-free
/// loop per case, so the compiler vectorizes each.
#[inline(always)]
fn extend_with(
    parent: Option<&[u32]>,
    digits: &[u32],
    out: &mut [u32],
    f: impl Fn(u32, u32) -> u32,
) {
    match parent {
        Some(parent) => {
            for ((o, &a), &x) in out.iter_mut().zip(parent).zip(digits) {
                *o = f(a, x);
            }
        }
        None => {
            for (o, &x) in out.iter_mut().zip(digits) {
                *o = f(0, x);
            }
        }
    }
}

/// Sets the bit of every key of points 0..n in `bits`, the keys written a chunk at a time by
/// `fill(start, keys)`; compiled once more with AVX2 and BMI2, taken when the CPU has them.
fn set_key_bits(n: usize, bits: &mut [u32], fill: impl Fn(usize, &mut [u32])) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("bmi2") {
        #[target_feature(enable = "avx2,bmi2")]
        fn wide(n: usize, bits: &mut [u32], fill: impl Fn(usize, &mut [u32])) {
            set_key_bits_portable(n, bits, fill)
        }
        // SAFETY: AVX2 and BMI2 were detected on this CPU just above.
        return unsafe { wide(n, bits, fill) };
    }
    set_key_bits_portable(n, bits, fill)
}

#[inline(always)]
fn set_key_bits_portable(n: usize, bits: &mut [u32], fill: impl Fn(usize, &mut [u32])) {
    let mut keys = [0u32; CHUNK];
    for start in (0..n).step_by(CHUNK) {
        let keys = &mut keys[..CHUNK.min(n - start)];
        fill(start, keys);
        for &key in keys.iter() {
            bits[(key >> 5) as usize] |= 1u32 << (key & 31);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::least_completion;

    #[test]
    fn the_least_completion_of_a_partial_shape_is_the_least_of_all() {
        // Brute force: every shape of Σd = k over 4 dimensions that agrees with a partial
        // shape up to its last nonzero part; the least in lexicographic order must be ours.
        let k = 4u32;
        let all: Vec<Vec<u32>> = (0..5u32.pow(4))
            .map(|c| {
                (0..4)
                    .map(|j| (c / 5u32.pow(3 - j)) % 5)
                    .collect::<Vec<u32>>()
            })
            .filter(|s: &Vec<u32>| s.iter().sum::<u32>() == k)
            .collect();
        for partial in &all {
            for cut in 0..4 {
                // The partial shape: the first `cut + 1` parts, zeros after (sum ≤ k).
                let mut p = partial.clone();
                p[cut + 1..].iter_mut().for_each(|d| *d = 0);
                if p[cut] == 0 {
                    continue;
                }
                let least = all
                    .iter()
                    .filter(|s| s[..=cut] == p[..=cut])
                    .min()
                    .expect("the partial shape extends");
                assert_eq!(&least_completion(&p, k), least, "{p:?}");
            }
        }
    }
}
