//! The every-word sweep: bijectivity and nestedness at every depth, checked on all 2^W words of
//! one dimension (W ≤ 32) in one streaming pass, in chunks that can run on different threads or
//! machines and be combined afterwards.
//!
//! # What one pass proves
//!
//! Write `shared(a, b)` for the number of leading base-2^q digits two W-bit words have in common
//! (digit k is bits [W − q(k+1), W − qk); a partial last digit of W mod q bits counts as a digit).
//! For a ≠ b it is ⌊clz_W(a ⊕ b) / q⌋. A map f is nested at every depth when output digit k
//! depends on input digits 0..=k only, that is when `shared(f a, f b) ≥ shared(a, b)` for all a, b.
//!
//! **Consecutive inputs suffice.** Suppose `shared(f(x−1), f(x)) ≥ shared(x−1, x)` for every
//! x in 1..2^W. Take a < b and s = shared(a, b). The words with a given s-digit prefix form an
//! interval, which holds a and b and therefore every word between them, so every consecutive pair
//! (x−1, x) with a < x ≤ b shares at least s digits, and by hypothesis so do their outputs.
//! "Shares the first s digits" is an equivalence relation (equal s-digit prefixes), so following
//! the chain f(a), f(a+1), …, f(b) gives shared(f a, f b) ≥ s. ∎ For x − 1 and x the inputs share
//! ⌊(W − tz(x) − 1) / q⌋ digits (tz: trailing zeros), so the check is one shift and one compare.
//!
//! **Bijectivity without a 2^W-bit bitmap.** The words are cut into the 2^(qd) subtrees of depth
//! d (the chunks: words with one d-digit prefix c). In a nested f all outputs of chunk c share their
//! first d digits, its image prefix π(c). Then f is a bijection iff it is nested, injective on each
//! chunk and π is injective. (If: f maps chunk c injectively into the words with prefix π(c), a set
//! of the same size, hence onto it; distinct chunks have distinct image sets, which therefore
//! partition the words. Only if: a nested bijection maps chunk c onto the prefix-π(c) words, so two
//! chunks with one image prefix would collide.) The same argument one level down decides a
//! chunk's injectivity: its blocks (a deeper depth d′: at most 32 words, or one digit's worth)
//! each need a bitmap of at most 256 bits, and the nodes between depths d and d′ must send their
//! children to distinct digits (checked at the children's first words). Where blocks have 16 or
//! 32 words, sixteen words are checked at a time (`group_scan`).
//!
//! **Node permutations come for free.** The node permutation σ_{k,p} maps digit e to digit k of
//! f(p, e, 0, …, 0), the output of the first word of child (p, e). For depths k < d those words
//! are chunk starts, so π holds every node permutation of depths 0..d; for deeper depths the scan
//! records the law of each node (its cell, as the inspector's [`gartowen_oracles::inspector::NodeLaw`]
//! defines it) as it passes the child starts, down to depth [`SweepPlan::law_depths`].
//!
//! Chunks are processed in parallel; records come back in chunk order, so results are identical
//! for any thread count. [`sweep`] checks a range of chunks and [`combine`] joins the pieces of a
//! dimension (from one run or many shards), checking the seams between pieces and π.

mod chunk_scan;
mod combine;
mod group_scan;
mod scan;

pub use combine::{combine, DepthLaw, SweepVerdict};
pub use scan::{sweep, SweepPiece};

use gartowen_core::{PowerOfTwoBase, Scrambler, Width};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::ops::Range;

/// Widest words the sweep enumerates: 2^32 words take seconds per dimension; 2^64 cannot be
/// enumerated (the sampled checks of `verify --level quick|full|exhaustive` apply there).
pub const MAX_SWEEP_BITS: u32 = 32;

/// The width a scrambler that lacks 32-bit support is swept at.
pub const FALLBACK_SWEEP_BITS: u32 = 24;

/// Most prefix bits of a chunk (2^12 chunks at most where the base allows).
const CHUNK_PREFIX_BITS: u32 = 12;
/// Node laws are recorded down to the depth with at most 2^22 child starts.
const LAW_PREFIX_BITS: u32 = 22;

/// Why a sweep cannot be planned or its pieces cannot be combined.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SweepError {
    /// Words wider than [`MAX_SWEEP_BITS`] cannot be enumerated.
    TooWide(u32),
    /// The scrambler supports neither 32- nor 24-bit words.
    NoSweepableWidth(String),
    /// A chunk range past the plan's chunks.
    BadRange {
        /// Requested range.
        start: u64,
        /// Requested end (exclusive).
        end: u64,
        /// Chunks the plan has.
        chunks: u64,
    },
    /// The pieces of a dimension do not cover every chunk exactly once, or disagree.
    Incomplete(String),
}

impl fmt::Display for SweepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SweepError::TooWide(w) => write!(
                f,
                "{w}-bit words cannot be enumerated (2^{w} words); every-word sweeps take at most \
                 {MAX_SWEEP_BITS} bits, and the sampled levels apply to wider words"
            ),
            SweepError::NoSweepableWidth(n) => write!(
                f,
                "{n} supports neither 32- nor 24-bit words, so no width can be swept"
            ),
            SweepError::BadRange { start, end, chunks } => {
                write!(f, "chunks {start}..{end} are not inside 0..{chunks}")
            }
            SweepError::Incomplete(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for SweepError {}

/// The geometry of a sweep: word width, base, chunk depth and the depths whose node laws are
/// recorded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct SweepPlan {
    width: u32,
    q: u32,
}

impl SweepPlan {
    /// The plan for `width`-bit words in `base`; refuses widths above [`MAX_SWEEP_BITS`].
    pub fn new(width: Width, base: PowerOfTwoBase) -> Result<SweepPlan, SweepError> {
        if width.bits() > MAX_SWEEP_BITS {
            return Err(SweepError::TooWide(width.bits()));
        }
        Ok(SweepPlan {
            width: width.bits(),
            q: base.q(),
        })
    }

    /// The plan for a scrambler: 32-bit words where supported, else 24-bit ones.
    pub fn for_scrambler(s: &dyn Scrambler) -> Result<SweepPlan, SweepError> {
        for bits in [MAX_SWEEP_BITS, FALLBACK_SWEEP_BITS] {
            let w = Width::new(bits).expect("valid width");
            if s.supports_width(w) {
                return SweepPlan::new(w, s.base());
            }
        }
        Err(SweepError::NoSweepableWidth(s.name()))
    }

    /// Word width W in bits.
    pub fn width(&self) -> Width {
        Width::new(self.width).expect("checked at construction")
    }

    /// The base b = 2^q.
    pub fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::from_q(self.q).expect("checked at construction")
    }

    /// Whole digits of a word (the partial tail digit, if any, not counted).
    pub fn full_digits(&self) -> u32 {
        self.width / self.q
    }

    /// Depth d of a chunk's subtree: its words share their first d digits.
    pub fn chunk_digits(&self) -> u32 {
        self.width.min(CHUNK_PREFIX_BITS) / self.q
    }

    /// Prefix bits q·d of a chunk.
    pub fn chunk_prefix_bits(&self) -> u32 {
        self.q * self.chunk_digits()
    }

    /// Number of chunks, b^d.
    pub fn chunks(&self) -> u64 {
        1u64 << self.chunk_prefix_bits()
    }

    /// Words per chunk, 2^(W − qd).
    pub fn chunk_words(&self) -> u64 {
        1u64 << (self.width - self.chunk_prefix_bits())
    }

    /// Words of the whole dimension, 2^W.
    pub fn words(&self) -> u64 {
        1u64 << self.width
    }

    /// Depths 0..L whose node laws a sweep reports (whole digits with at most 2^22 child starts).
    pub fn law_depths(&self) -> u32 {
        self.full_digits().min(LAW_PREFIX_BITS / self.q)
    }

    /// Digits two distinct words share, or all digits for equal words.
    pub fn shared_digits(&self, a: u64, b: u64) -> u32 {
        let diff = a ^ b;
        if diff == 0 {
            return self.width.div_ceil(self.q);
        }
        // An output wider than the word shares nothing with an in-range one.
        let clz = diff.leading_zeros().saturating_sub(64 - self.width);
        clz / self.q
    }

    /// The low bits in which f(x−1) and f(x) may differ: W − q·shared(x−1, x), for x ≥ 1.
    pub(crate) fn free_bits_after(&self, x: u64) -> u32 {
        let shared = (self.width - x.trailing_zeros() - 1) / self.q;
        self.width - self.q * shared
    }

    /// The failure, if any, of the consecutive pair (x−1, x) with outputs (prev, y).
    pub(crate) fn step_failure(&self, x: u64, prev: u64, y: u64) -> Option<SweepFailure> {
        if (prev ^ y) >> self.free_bits_after(x) == 0 {
            return None;
        }
        Some(SweepFailure::NotNested {
            inputs: [x - 1, x],
            outputs: [prev, y],
            input_digits: self.shared_digits(x - 1, x),
            output_digits: self.shared_digits(prev, y),
        })
    }

    /// The failure, if any, at the seam between a chunk ending in output `prev` and the next
    /// one, whose first word `x` gives `first`. An out-of-range `first` is left to the chunk's
    /// own record, which names it as such.
    pub(crate) fn seam_failure(&self, x: u64, prev: u64, first: u64) -> Option<SweepFailure> {
        if first > self.width().mask() {
            return None;
        }
        self.step_failure(x, prev, first)
    }

    /// The first word of chunk `c`.
    pub fn chunk_start(&self, c: u64) -> u64 {
        c << (self.width - self.chunk_prefix_bits())
    }

    /// Checks that `chunks` lies inside the plan.
    pub fn check_range(&self, chunks: &Range<u64>) -> Result<(), SweepError> {
        if chunks.start >= chunks.end || chunks.end > self.chunks() {
            return Err(SweepError::BadRange {
                start: chunks.start,
                end: chunks.end,
                chunks: self.chunks(),
            });
        }
        Ok(())
    }
}

/// The first thing wrong, named by the words that show it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SweepFailure {
    /// An output has bits above the width.
    OutOfRange {
        /// The input.
        input: u64,
        /// Its output.
        output: u64,
    },
    /// Consecutive inputs whose outputs share fewer leading digits than they do.
    NotNested {
        /// x − 1 and x.
        inputs: [u64; 2],
        /// Their outputs.
        outputs: [u64; 2],
        /// Leading digits the inputs share.
        input_digits: u32,
        /// Leading digits the outputs share.
        output_digits: u32,
    },
    /// Two inputs of one chunk with one output.
    Collision {
        /// The two inputs (increasing).
        inputs: [u64; 2],
        /// Their common output.
        output: u64,
    },
    /// Two chunks (depth-d subtrees) mapped onto the same subtree: not injective.
    SubtreesMerged {
        /// The chunks' d-digit prefixes.
        subtrees: [u64; 2],
        /// Their first words.
        first_words: [u64; 2],
        /// The common image prefix.
        image: u64,
        /// Depth d.
        depth: u32,
    },
}

impl SweepFailure {
    /// The failure in words, with the base for digit counts.
    pub fn describe(&self, base: u32) -> String {
        match self {
            SweepFailure::OutOfRange { input, output } => {
                format!("input {input:#x} gives {output:#x}, wider than the word")
            }
            SweepFailure::NotNested {
                inputs,
                outputs,
                input_digits,
                output_digits,
            } => format!(
                "not nested: inputs {:#x} and {:#x} share {input_digits} digit(s) in base {base}, \
                 their outputs {:#x} and {:#x} only {output_digits}",
                inputs[0], inputs[1], outputs[0], outputs[1]
            ),
            SweepFailure::Collision { inputs, output } => format!(
                "nested but not injective: inputs {:#x} and {:#x} both give {output:#x}",
                inputs[0], inputs[1]
            ),
            SweepFailure::SubtreesMerged {
                subtrees,
                first_words,
                image,
                depth,
            } => format!(
                "not injective: the depth-{depth} subtrees {:#x} and {:#x} (from words {:#x} and \
                 {:#x}) both map onto subtree {image:#x} in base {base}",
                subtrees[0], subtrees[1], first_words[0], first_words[1]
            ),
        }
    }
}

/// Splits `total` units into `count` contiguous runs and returns run `index` (1-based): units
/// ⌊(I−1)·T/N⌋ .. ⌊I·T/N⌋. Every unit lands in exactly one run.
pub fn shard_range(total: u64, index: u64, count: u64) -> Range<u64> {
    assert!(index >= 1 && index <= count, "shard index in 1..=count");
    let cut = |i: u64| ((i as u128 * total as u128) / count as u128) as u64;
    cut(index - 1)..cut(index)
}

/// Cuts a run of units across consecutive segments of the given sizes: for each segment the run
/// touches, its position and the unit range inside it.
pub fn split_run(segments: &[u64], run: Range<u64>) -> Vec<(usize, Range<u64>)> {
    let mut out = Vec::new();
    let mut offset = 0u64;
    for (k, &size) in segments.iter().enumerate() {
        let (lo, hi) = (run.start.max(offset), run.end.min(offset + size));
        if lo < hi {
            out.push((k, lo - offset..hi - offset));
        }
        offset += size;
    }
    out
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_collisions;
#[cfg(test)]
mod tests_groups;
#[cfg(test)]
mod tests_laws;
