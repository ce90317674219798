//! The AVX-512 kernels of the batch path: the lanes of [`super::batch::walk_portable`] in
//! 512-bit registers for the input bits, the symbols and the accumulators, and one gather per
//! step for the lanes' table entries. Same arithmetic, same words.
//!
//! **Groups that read one cache line.** A group's lanes that share all of a word's whole steps
//! but the last walk those once (`PrefixMemo`); when they also share all but the last step's
//! lowest 3 (64-bit entries) or 4 (32-bit entries) bits, the last step's entries lie in one
//! aligned 64-byte run of the table row, so one load and a lane permutation replace the
//! gather. Consecutive words (the every-word sweep, index scrambling) are such groups.

use super::lanes::{PrefixMemo, Word};
use super::{GROUPS, LANES};
use std::arch::x86_64::*;

/// The lanes' state after the whole steps, for the words whose last bits the scalar code
/// finishes: accumulator and symbol per lane.
pub(super) type Walked = [([u64; LANES], [usize; LANES]); GROUPS];

/// [`super::batch::walk_portable`] with AVX-512F on a block of [`GROUPS`] × [`LANES`] words
/// (input shift `a` applied here), the steps a group shares walked once (`memo`). When the
/// whole steps leave at most a partial tail digit (r = w − steps·SB < q bits, translation
/// only: its node XORs the top r bits of the pending translations and of the code of the
/// symbol reached, gathered from `codes`), the scrambled words (with output shift `d`) are
/// written to `block` and `None` is returned; otherwise `block` is left as it was and the
/// lanes' state is returned.
///
/// # Safety
/// The CPU must support AVX-512F, and `table` must hold `symbols << SB` entries whose low 16
/// bits (the next symbol) are below `symbols`, with `root < symbols`: then every gathered
/// index `(s << SB) | v` is in bounds. [`super::batch::pack`] builds such tables from the
/// grammar (whose children are symbols), and the constructor checks both.
#[target_feature(enable = "avx512f")]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn walk_avx512<const SB: u32, T: Word>(
    table: &[u64],
    codes: &[u64],
    q: u32,
    block: &mut [T],
    a: u64,
    d: u64,
    w: u32,
    steps: u32,
    root: u32,
    memo: &mut PrefixMemo,
) -> Option<Walked> {
    assert_eq!(block.len(), GROUPS * LANES, "one block");
    let count = |n: u32| _mm_cvtsi64_si128(n as i64);
    let sb = count(SB);
    let top = count(64 - SB);
    let shift_a = _mm512_set1_epi64(a as i64);
    let consumed = steps * SB;
    let zero = _mm512_setzero_si512();
    let (mut bits, mut s, mut acc) = ([zero; GROUPS], [zero; GROUPS], [zero; GROUPS]);
    let mut shared = [0u32; GROUPS];
    let mut one_line = [false; GROUPS];
    for g in 0..GROUPS {
        // SAFETY: 8 words from g·8 lie inside `block` (GROUPS · 8 words, asserted).
        let x = unsafe { load8(block, g) };
        let b = _mm512_sll_epi64(_mm512_xor_si512(x, shift_a), count(64 - w));
        let b0 = _mm_cvtsi128_si64(_mm512_castsi512_si128(b)) as u64;
        let diff = _mm512_reduce_or_epi64(_mm512_xor_si512(b, _mm512_set1_epi64(b0 as i64)));
        let start = memo.start::<SB>(table, b0, diff as u64, steps, root);
        let lz = (diff as u64).leading_zeros();
        // Only the last step's lowest 3 bits differ (so SB ≥ 3): one line of 8 entries.
        one_line[g] = SB >= 3 && lz < consumed && lz + 3 >= consumed;
        shared[g] = start.steps;
        bits[g] = _mm512_sll_epi64(b, count(SB * start.steps));
        s[g] = _mm512_set1_epi64(start.symbol as i64);
        acc[g] = _mm512_set1_epi64(start.acc as i64);
    }
    let symbol_mask = _mm512_set1_epi64(0xFFFF);
    for i in 0..steps {
        let shift = count(SB * i);
        for g in 0..GROUPS {
            if i < shared[g] {
                continue;
            }
            let v = _mm512_srl_epi64(bits[g], top);
            bits[g] = _mm512_sll_epi64(bits[g], sb);
            let idx = _mm512_or_si512(_mm512_sll_epi64(s[g], sb), v);
            let e = if one_line[g] {
                // Every lane's index is in the aligned run of 8 holding lane 0's (SB ≥ 3,
                // so rows are whole runs); the permutation reads each lane's low 3 bits.
                let first = _mm_cvtsi128_si64(_mm512_castsi512_si128(idx)) as usize & !7;
                let run = &table[first..first + 8];
                // SAFETY: an unaligned 64-byte load of the 8 entries checked above.
                _mm512_permutexvar_epi64(idx, unsafe { _mm512_loadu_si512(run.as_ptr().cast()) })
            } else {
                // SAFETY: idx < table.len() in every lane, by the caller's table invariant.
                unsafe { _mm512_i64gather_epi64::<8>(idx, table.as_ptr().cast()) }
            };
            acc[g] = _mm512_xor_si512(acc[g], _mm512_srl_epi64(e, shift));
            s[g] = _mm512_and_si512(e, symbol_mask);
        }
    }
    let r = w - consumed;
    if r < q {
        let shift_d = _mm512_set1_epi64(d as i64);
        for g in 0..GROUPS {
            // Output digits of the whole steps: the top `consumed` bits of the accumulator.
            let mut y = if consumed == 0 {
                _mm512_setzero_si512()
            } else {
                _mm512_srl_epi64(acc[g], count(64 - consumed))
            };
            if r > 0 {
                // The tail: its r input bits XOR the top r bits of (pending ⊕ code[s]); the
                // pending translations are the accumulator's exact top 32 bits moved up.
                // SAFETY: s < symbols = codes.len() in every lane (the table invariant).
                let code = unsafe { _mm512_i64gather_epi64::<8>(s[g], codes.as_ptr().cast()) };
                let pending = _mm512_sll_epi64(acc[g], count(consumed));
                let t = _mm512_srl_epi64(_mm512_xor_si512(pending, code), count(64 - r));
                // SAFETY: 8 words from g·8 lie inside `block` (asserted above).
                let x = _mm512_xor_si512(unsafe { load8(block, g) }, shift_a);
                let tail = _mm512_and_si512(x, _mm512_set1_epi64(((1u64 << r) - 1) as i64));
                y = _mm512_or_si512(_mm512_sll_epi64(y, count(r)), _mm512_xor_si512(tail, t));
            }
            let y = _mm512_xor_si512(y, shift_d);
            // SAFETY: 8 words from g·8 lie inside `block` (asserted above).
            unsafe { store8(block, g, y) };
        }
        return None;
    }
    Some(std::array::from_fn(|g| {
        let mut acc_out = [0u64; LANES];
        let mut s_out = [0u64; LANES];
        // SAFETY: each store writes 8 words into an 8-word array we own.
        unsafe {
            _mm512_storeu_si512(acc_out.as_mut_ptr().cast(), acc[g]);
            _mm512_storeu_si512(s_out.as_mut_ptr().cast(), s[g]);
        }
        (acc_out, s_out.map(|v| v as usize))
    }))
}

/// Words 8g..8g + 8 of `block` as eight 64-bit lanes.
///
/// # Safety
/// AVX-512F, and the words lie inside `block`.
#[inline(always)]
unsafe fn load8<T: Word>(block: &[T], g: usize) -> __m512i {
    let p = block[g * LANES..g * LANES + LANES].as_ptr();
    // SAFETY: the caller's; the slice above checked the 8 words are in bounds.
    unsafe {
        if T::WIDE {
            _mm512_loadu_si512(p.cast())
        } else {
            _mm512_cvtepu32_epi64(_mm256_loadu_si256(p.cast()))
        }
    }
}

/// Stores eight 64-bit lanes (their low 32 bits for `u32` words) as words 8g..8g + 8.
///
/// # Safety
/// AVX-512F, and the words lie inside `block`.
#[inline(always)]
unsafe fn store8<T: Word>(block: &mut [T], g: usize, y: __m512i) {
    let p = block[g * LANES..g * LANES + LANES].as_mut_ptr();
    // SAFETY: the caller's; the slice above checked the 8 words are in bounds.
    unsafe {
        if T::WIDE {
            _mm512_storeu_si512(p.cast(), y)
        } else {
            _mm256_storeu_si256(p.cast(), _mm512_cvtepi64_epi32(y))
        }
    }
}

/// Groups of sixteen 32-bit lanes walked together by [`walk_avx512_narrow`]: the same
/// [`GROUPS`] · [`LANES`] words per block as [`walk_avx512`].
pub(super) const NARROW_GROUPS: usize = GROUPS * LANES / 16;

/// [`walk_avx512`] with 32-bit lanes and the narrow table (see `batch::narrow`): steps
/// 0..`wide` gather `table` (step 0 its root's row: full 32-bit contribution and next symbol,
/// two gathers of eight lanes), the later steps gather 32-bit entries of `narrow`, sixteen
/// lanes per gather. The narrow table is half the bytes of `table`, so more of it stays in the
/// first-level TLB and the caches. Same words, same return convention as [`walk_avx512`];
/// `codes_top` holds the top 32 bits of each symbol's code (for the tail digit).
///
/// # Safety
/// As for [`walk_avx512`], and `narrow` must hold `symbols << SB` entries whose low
/// `wide`·SB bits (the next symbol) are below `symbols`, with `codes_top.len() == symbols`.
#[target_feature(enable = "avx512f")]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn walk_avx512_narrow<const SB: u32, T: Word>(
    table: &[u64],
    narrow: &[u32],
    wide: u32,
    codes_top: &[u32],
    q: u32,
    block: &mut [T],
    a: u64,
    d: u64,
    w: u32,
    steps: u32,
    root: u32,
    memo: &mut PrefixMemo,
) -> Option<Walked> {
    assert_eq!(block.len(), GROUPS * LANES, "one block");
    let count = |n: u32| _mm_cvtsi64_si128(n as i64);
    let shift_a = _mm512_set1_epi64(a as i64);
    // Sixteen words of the block, input shift applied, as 32-bit lanes (w ≤ 32).
    let load32 = |block: &[T], g: usize| {
        let p = block[g * 16..g * 16 + 16].as_ptr();
        if !T::WIDE {
            // SAFETY: one unaligned 64-byte load of the 16 words checked above.
            let x = unsafe { _mm512_loadu_si512(p.cast()) };
            return _mm512_xor_si512(x, _mm512_set1_epi32(a as u32 as i32));
        }
        // SAFETY: two unaligned 64-byte loads of the 16 words checked above.
        let (lo, hi) = unsafe {
            (
                _mm512_loadu_si512(p.cast()),
                _mm512_loadu_si512(p.add(8).cast()),
            )
        };
        let lo = _mm512_cvtepi64_epi32(_mm512_xor_si512(lo, shift_a));
        let hi = _mm512_cvtepi64_epi32(_mm512_xor_si512(hi, shift_a));
        _mm512_inserti64x4::<1>(_mm512_castsi256_si512(lo), hi)
    };
    let consumed = steps * SB;
    let zero = _mm512_setzero_si512();
    let (mut bits, mut s, mut acc) = (
        [zero; NARROW_GROUPS],
        [zero; NARROW_GROUPS],
        [zero; NARROW_GROUPS],
    );
    let mut shared = [0u32; NARROW_GROUPS];
    let mut one_line = [false; NARROW_GROUPS];
    for g in 0..NARROW_GROUPS {
        let b = _mm512_sll_epi32(load32(block, g), count(32 - w));
        let b0 = _mm512_cvtsi512_si32(b) as u32;
        let diff = _mm512_reduce_or_epi32(_mm512_xor_si512(b, _mm512_set1_epi32(b0 as i32))) as u32;
        let start = memo.start::<SB>(
            table,
            u64::from(b0) << 32,
            u64::from(diff) << 32,
            steps,
            root,
        );
        let lz = diff.leading_zeros();
        // Only the last step's lowest 4 bits differ, and that step reads `narrow` (not a
        // wide step): one line of 16 entries.
        one_line[g] = SB >= 4 && steps > wide && lz < consumed && lz + 4 >= consumed;
        shared[g] = start.steps;
        // A shift by 32 (every step shared) leaves no bits, as it should.
        bits[g] = _mm512_sll_epi32(b, count(SB * start.steps));
        s[g] = _mm512_set1_epi32(start.symbol as i32);
        // The narrow accumulator is the top half of the wide one (see `batch::narrow`).
        acc[g] = _mm512_set1_epi32((start.acc >> 32) as u32 as i32);
    }
    let next_mask = _mm512_set1_epi32(((1u32 << (wide * SB)) - 1) as i32);
    let sb = count(SB);
    let top = count(32 - SB);
    // Steps 0..wide read the wide table: full contribution and next symbol.
    let join = |l: __m256i, h: __m256i| _mm512_inserti64x4::<1>(_mm512_castsi256_si512(l), h);
    for i in 0..wide.min(steps) {
        let shift = count(SB * i);
        for g in 0..NARROW_GROUPS {
            if i < shared[g] {
                continue;
            }
            // At step 0 every lane's symbol is the root (no step shared).
            let row = _mm512_sll_epi32(s[g], sb);
            let idx = _mm512_or_si512(row, _mm512_srl_epi32(bits[g], top));
            bits[g] = _mm512_sll_epi32(bits[g], sb);
            // SAFETY: every lane's symbol < symbols and its digits < 2^SB (the table
            // invariant), so every index < table.len().
            let (lo, hi) = unsafe {
                (
                    _mm512_i32gather_epi64::<8>(_mm512_castsi512_si256(idx), table.as_ptr().cast()),
                    _mm512_i32gather_epi64::<8>(
                        _mm512_extracti64x4_epi64::<1>(idx),
                        table.as_ptr().cast(),
                    ),
                )
            };
            let e = join(
                _mm512_cvtepi64_epi32(_mm512_srli_epi64::<32>(lo)),
                _mm512_cvtepi64_epi32(_mm512_srli_epi64::<32>(hi)),
            );
            acc[g] = _mm512_xor_si512(acc[g], _mm512_srl_epi32(e, shift));
            s[g] = _mm512_and_si512(
                join(_mm512_cvtepi64_epi32(lo), _mm512_cvtepi64_epi32(hi)),
                _mm512_set1_epi32(0xFFFF),
            );
        }
    }
    for i in wide..steps {
        let shift = count(SB * i);
        for g in 0..NARROW_GROUPS {
            if i < shared[g] {
                continue;
            }
            let v = _mm512_srl_epi32(bits[g], top);
            bits[g] = _mm512_sll_epi32(bits[g], sb);
            let idx = _mm512_or_si512(_mm512_sll_epi32(s[g], sb), v);
            let e = if one_line[g] {
                // Every lane's index is in the aligned run of 16 holding lane 0's (SB ≥ 4,
                // so rows are whole runs); the permutation reads each lane's low 4 bits.
                let first = _mm512_cvtsi512_si32(idx) as u32 as usize & !15;
                let run = &narrow[first..first + 16];
                // SAFETY: an unaligned 64-byte load of the 16 entries checked above.
                _mm512_permutexvar_epi32(idx, unsafe { _mm512_loadu_si512(run.as_ptr().cast()) })
            } else {
                // SAFETY: every index < narrow.len(), by the caller's invariant.
                unsafe { _mm512_i32gather_epi32::<4>(idx, narrow.as_ptr().cast()) }
            };
            // A shift of wide·SB or more drops the next symbol's bits.
            acc[g] = _mm512_xor_si512(acc[g], _mm512_srl_epi32(e, shift));
            s[g] = _mm512_and_si512(e, next_mask);
        }
    }
    let r = w - consumed;
    if r < q {
        let shift_d = _mm512_set1_epi32(d as u32 as i32);
        for g in 0..NARROW_GROUPS {
            let mut y = if consumed == 0 {
                _mm512_setzero_si512()
            } else {
                _mm512_srl_epi32(acc[g], count(32 - consumed))
            };
            if r > 0 {
                // SAFETY: s < symbols = codes_top.len() in every lane.
                let code = unsafe { _mm512_i32gather_epi32::<4>(s[g], codes_top.as_ptr().cast()) };
                let pending = _mm512_sll_epi32(acc[g], count(consumed));
                let t = _mm512_srl_epi32(_mm512_xor_si512(pending, code), count(32 - r));
                let tail = _mm512_and_si512(
                    load32(block, g),
                    _mm512_set1_epi32(((1u32 << r) - 1) as i32),
                );
                y = _mm512_or_si512(_mm512_sll_epi32(y, count(r)), _mm512_xor_si512(tail, t));
            }
            let y = _mm512_xor_si512(y, shift_d);
            let p = block[g * 16..g * 16 + 16].as_mut_ptr();
            if T::WIDE {
                let lo = _mm512_cvtepu32_epi64(_mm512_castsi512_si256(y));
                let hi = _mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64::<1>(y));
                // SAFETY: two unaligned 64-byte stores of the 16 words checked above.
                unsafe {
                    _mm512_storeu_si512(p.cast(), lo);
                    _mm512_storeu_si512(p.add(8).cast(), hi);
                }
            } else {
                // SAFETY: one unaligned 64-byte store of the 16 words checked above.
                unsafe { _mm512_storeu_si512(p.cast(), y) };
            }
        }
        return None;
    }
    let mut acc_out = [0u32; GROUPS * LANES];
    let mut s_out = [0u32; GROUPS * LANES];
    for g in 0..NARROW_GROUPS {
        // SAFETY: 64-byte stores inside the two arrays.
        unsafe {
            _mm512_storeu_si512(acc_out[g * 16..].as_mut_ptr().cast(), acc[g]);
            _mm512_storeu_si512(s_out[g * 16..].as_mut_ptr().cast(), s[g]);
        }
    }
    Some(std::array::from_fn(|g| {
        (
            std::array::from_fn(|l| (acc_out[g * LANES + l] as u64) << 32),
            std::array::from_fn(|l| s_out[g * LANES + l] as usize),
        )
    }))
}
