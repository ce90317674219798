//! The sixteen-word scan: a chunk's checks (nested consecutive pairs, injectivity by blocks and
//! node digits, node laws) on aligned groups of sixteen 32-bit outputs, in vector registers
//! where the CPU has them. It decides whether the chunk passes; a chunk it rejects is scanned
//! again word by word ([`ChunkScan::scan`]), which names the failure.
//!
//! **Why groups.** Inside an aligned group of sixteen words, word i (i = 1..15) has i's trailing
//! zeros, so the bits in which its output may differ from its predecessor's are the same for
//! every group: the nested test is one XOR and one AND with a constant per lane. When a block
//! (see [`ChunkScan`]) has 2^B words with B ∈ {4, 5}, its outputs are distinct in their low B
//! bits iff the OR of the one-hot words 1 << (low B bits) over the block is all ones (2^B words,
//! 2^B values), which is one shift per lane and an OR across lanes. What is left per group is
//! the first lane's pair (its predecessor lies in the group before), the node digits at a
//! block's first word and the node laws, all as in the word-by-word scan.

use super::chunk_scan::{block_low_bits, ChunkScan};
use super::SweepPlan;

/// Words per group: one 512-bit register of 32-bit outputs.
pub(super) const GROUP: usize = 16;

/// Whether a plan's chunks can be scanned in groups: blocks of 16 or 32 words (so a group lies
/// in one block and a block's one-hot word fits 32 bits), in a base other than 2 (whose own
/// test needs no bitmap).
pub(super) fn applies(plan: &SweepPlan) -> bool {
    plan.base().q() > 1 && matches!(block_low_bits(plan), 4 | 5)
}

/// Which code runs the group loop; both give the same verdicts (tested).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum GroupKernel {
    /// Plain Rust over arrays of sixteen lanes, as the compiler vectorizes it for the target
    /// (any CPU).
    Portable,
    /// AVX-512 intrinsics, for CPUs with AVX-512F, VL and BW: construct it only through
    /// [`GroupKernel::detect`], whose check the kernel's safety rests on.
    Avx512,
}

impl GroupKernel {
    /// The fastest kernel this CPU runs.
    pub(super) fn detect() -> GroupKernel {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512vl")
            && std::arch::is_x86_feature_detected!("avx512bw")
        {
            return GroupKernel::Avx512;
        }
        GroupKernel::Portable
    }
}

/// The per-lane constants of a plan's groups.
pub(super) struct GroupLanes {
    /// Lane i ≥ 1: the output bits word i must share with word i − 1 (above its free bits);
    /// lane 0 (whose predecessor is in the group before) is checked on its own.
    keep: [u32; GROUP],
    /// Bits no output may have (above the width).
    over: u32,
    /// Low bits of a block, 2^B − 1.
    low: u32,
    /// The one-hot OR of a whole block of distinct outputs: 2^(2^B) − 1.
    full: u32,
    /// Node laws: groups whose first word has these bits zero start children of law depths…
    law_groups: u64,
    /// …at every `law_step`-th lane (16 when only the first lane can).
    law_step: usize,
}

impl GroupLanes {
    /// The constants for `plan` (which [`applies`]) and the scan's law mask.
    pub(super) fn new(plan: &SweepPlan, law_mask: u64) -> GroupLanes {
        let low_bits = block_low_bits(plan);
        debug_assert!(applies(plan));
        let mut keep = [0u32; GROUP];
        for (i, lane) in keep.iter_mut().enumerate().skip(1) {
            // Fewer than 32 free bits: word i has at most 3 trailing zeros.
            *lane = !((1u32 << plan.free_bits_after(i as u64)) - 1);
        }
        GroupLanes {
            keep,
            over: !(plan.width().mask() as u32),
            low: (1 << low_bits) - 1,
            full: (1u64 << (1 << low_bits)).wrapping_sub(1) as u32,
            law_groups: law_mask & !(GROUP as u64 - 1),
            law_step: law_mask.saturating_add(1).min(GROUP as u64) as usize,
        }
    }
}

/// Lanes 0..16 of one group: whether any lane breaks the nested test (`prev` holds each word's
/// predecessor) or the range, and the OR of the one-hot words of the outputs' low block bits.
#[inline(always)]
fn lanes(prev: &[u32; GROUP], y: &[u32; GROUP], c: &GroupLanes) -> (u32, u32) {
    let (mut bad, mut hot) = (0u32, 0u32);
    for i in 0..GROUP {
        bad |= ((prev[i] ^ y[i]) & c.keep[i]) | (y[i] & c.over);
        hot |= 1 << (y[i] & c.low);
    }
    (bad, hot)
}

impl ChunkScan<'_> {
    /// Scans the outputs `out` of words `start..start + out.len()` (`start` and the length
    /// multiples of [`GROUP`]); `first` when `start` is the chunk's first word. False at the
    /// first group where a check fails (the caller rescans the chunk word by word to name it);
    /// otherwise the chunk's state (previous output, block, node digits, laws) carries on.
    pub(super) fn scan_groups(
        &mut self,
        kernel: GroupKernel,
        c: &GroupLanes,
        start: u64,
        out: &[u32],
        first: bool,
        node: &mut [Vec<u8>],
    ) -> bool {
        match kernel {
            #[cfg(target_arch = "x86_64")]
            // SAFETY: `GroupKernel::Avx512` is only chosen by `detect` on CPUs with the
            // features the function enables.
            GroupKernel::Avx512 => unsafe { self.scan_groups_avx512(c, start, out, first, node) },
            _ => self.scan_groups_with(c, start, out, first, node),
        }
    }

    /// [`ChunkScan::scan_groups_with`] in AVX-512 registers: a group's predecessors are its
    /// outputs moved up one lane (the group before's last in lane 0), the lane test is one
    /// ternary-logic instruction and a mask test, and the block's one-hot words are ORed
    /// lane-wise, across lanes only at the block's end.
    ///
    /// # Safety
    /// The CPU must support AVX-512F, VL and BW.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512vl,avx512bw")]
    unsafe fn scan_groups_avx512(
        &mut self,
        c: &GroupLanes,
        start: u64,
        out: &[u32],
        first: bool,
        node: &mut [Vec<u8>],
    ) -> bool {
        use std::arch::x86_64::*;
        debug_assert!(start.is_multiple_of(GROUP as u64) && out.len().is_multiple_of(GROUP));
        // SAFETY: a 64-byte load of the 16 constants.
        let keep = unsafe { _mm512_loadu_si512(c.keep.as_ptr().cast()) };
        let over = _mm512_set1_epi32(c.over as i32);
        let low = _mm512_set1_epi32(c.low as i32);
        let one = _mm512_set1_epi32(1);
        let mut prev = self.prev as u32;
        let mut before_group = _mm512_set1_epi32(prev as i32);
        let mut hot = _mm512_castsi128_si512(_mm_cvtsi32_si128(self.block_hot as i32));
        for (g, lanes) in out.chunks_exact(GROUP).enumerate() {
            let x0 = start + (g * GROUP) as u64;
            if !self.group_head(x0, lanes[0], prev, first && g == 0) {
                return false;
            }
            // SAFETY: a 64-byte load of the group's 16 outputs.
            let y = unsafe { _mm512_loadu_si512(lanes.as_ptr().cast()) };
            // Lane i holds output i − 1; lane 0 the group before's last (masked by `keep`).
            let before = _mm512_alignr_epi32::<15>(y, before_group);
            // (before ⊕ y) ∧ keep, then ∨ (y ∧ over) by one ternary logic: 0xF8 = a ∨ (b ∧ c).
            let nested = _mm512_and_si512(_mm512_xor_si512(before, y), keep);
            let bad = _mm512_ternarylogic_epi32::<0xF8>(nested, y, over);
            if _mm512_test_epi32_mask(bad, bad) != 0 {
                return false;
            }
            hot = _mm512_or_si512(hot, _mm512_sllv_epi32(one, _mm512_and_si512(y, low)));
            if (x0 + GROUP as u64) & self.low_mask == 0 {
                if _mm512_reduce_or_epi32(hot) as u32 != c.full {
                    return false;
                }
                hot = _mm512_setzero_si512();
            }
            self.group_laws(c, x0, lanes, node);
            before_group = y;
            prev = lanes[GROUP - 1];
        }
        self.prev = u64::from(prev);
        self.block_hot = _mm512_reduce_or_epi32(hot) as u32;
        true
    }

    /// The group loop of [`ChunkScan::scan_groups`].
    #[inline(always)]
    fn scan_groups_with(
        &mut self,
        c: &GroupLanes,
        start: u64,
        out: &[u32],
        first: bool,
        node: &mut [Vec<u8>],
    ) -> bool {
        debug_assert!(start.is_multiple_of(GROUP as u64) && out.len().is_multiple_of(GROUP));
        let mut prev = self.prev as u32;
        let mut hot = self.block_hot;
        for (g, y) in out.chunks_exact(GROUP).enumerate() {
            let y: &[u32; GROUP] = y.try_into().expect("whole groups");
            let x0 = start + (g * GROUP) as u64;
            if !self.group_head(x0, y[0], prev, first && g == 0) {
                return false;
            }
            let before: [u32; GROUP];
            let before = if g == 0 {
                before = std::array::from_fn(|i| if i == 0 { prev } else { y[i - 1] });
                &before
            } else {
                let at = g * GROUP - 1;
                (&out[at..at + GROUP]).try_into().expect("one group")
            };
            let (bad, one_hot) = lanes(before, y, c);
            if bad != 0 {
                return false;
            }
            hot |= one_hot;
            if (x0 + GROUP as u64) & self.low_mask == 0 {
                if hot != c.full {
                    return false;
                }
                hot = 0;
            }
            self.group_laws(c, x0, y, node);
            prev = y[GROUP - 1];
        }
        (self.prev, self.block_hot) = (u64::from(prev), hot);
        true
    }

    /// A group's first word `x0` (output `y0`): its pair with the word before (output
    /// `prev`), unless it opens the chunk (that seam is checked when records are joined), and
    /// at a block's first word the node digits. False when either fails.
    #[inline(always)]
    fn group_head(&mut self, x0: u64, y0: u32, prev: u32, opens_chunk: bool) -> bool {
        if !opens_chunk {
            let free = self.free_bits[x0.trailing_zeros() as usize];
            if u64::from(prev ^ y0) >> free != 0 {
                return false;
            }
        }
        x0 & self.low_mask != 0 || self.child_digits(x0, u64::from(y0))
    }

    /// Records the node laws at the child starts among the group from `x0` (outputs `y`):
    /// with law depths, those are the words with the law mask's bits zero, so every
    /// `law_step`-th lane of the groups with the mask's bits above the lanes zero. (Without
    /// them the mask has every bit, so only word 0 is visited, and it records nothing.)
    #[inline(always)]
    fn group_laws(&mut self, c: &GroupLanes, x0: u64, y: &[u32], node: &mut [Vec<u8>]) {
        if x0 & c.law_groups == 0 {
            for i in (0..GROUP).step_by(c.law_step) {
                self.record_law(x0 + i as u64, u64::from(y[i]), node);
            }
        }
    }
}
