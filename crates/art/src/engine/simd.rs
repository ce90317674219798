//! The AVX-512 kernel of the batch path: the eight lanes of [`super::batch::walk_portable`]
//! in one 512-bit register each for the input bits, the symbols and the accumulators, and one
//! gather per step for the eight table entries. Same arithmetic, same words.

use super::{GROUPS, LANES};
use std::arch::x86_64::*;

/// The lanes' state after the whole steps, for the words whose last bits the scalar code
/// finishes: accumulator and symbol per lane.
pub(super) type Walked = [([u64; LANES], [usize; LANES]); GROUPS];

/// [`super::batch::walk_portable`] with AVX-512F on a block of [`GROUPS`] × [`LANES`] words
/// (input shift `a` applied here). When the whole steps leave at most a partial tail digit
/// (r = w − steps·SB < q bits, translation only: its node XORs the top r bits of the pending
/// translations and of the code of the symbol reached, gathered from `codes`), the scrambled
/// words (with output shift `d`) are written to `block` and `None` is returned; otherwise
/// `block` is left as it was and the lanes' state is returned.
///
/// # Safety
/// The CPU must support AVX-512F, and `table` must hold `symbols << SB` entries whose low 16
/// bits (the next symbol) are below `symbols`, with `root < symbols`: then every gathered
/// index `(s << SB) | v` is in bounds. [`super::batch::pack`] builds such tables from the
/// grammar (whose children are symbols), and the constructor checks both.
#[target_feature(enable = "avx512f")]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn walk_avx512<const SB: u32>(
    table: &[u64],
    codes: &[u64],
    q: u32,
    block: &mut [u64],
    a: u64,
    d: u64,
    w: u32,
    steps: u32,
    root: u32,
) -> Option<Walked> {
    assert_eq!(block.len(), GROUPS * LANES, "one block");
    let count = |n: u32| _mm_cvtsi64_si128(n as i64);
    let sb = count(SB);
    let top = count(64 - SB);
    let shift_a = _mm512_set1_epi64(a as i64);
    // SAFETY (loads and stores here and below): unaligned 64-byte accesses inside `block`
    // (GROUPS · 8 words, asserted) and [u64; 8] arrays.
    let mut bits: [__m512i; GROUPS] = std::array::from_fn(|g| {
        // SAFETY: 8 words from g·8 lie inside `block` (GROUPS · 8 words, asserted).
        let x = unsafe { _mm512_loadu_si512(block[g * LANES..].as_ptr().cast()) };
        _mm512_sll_epi64(_mm512_xor_si512(x, shift_a), count(64 - w))
    });
    let mut s = [_mm512_set1_epi64(root as i64); GROUPS];
    let mut acc = [_mm512_setzero_si512(); GROUPS];
    let symbol_mask = _mm512_set1_epi64(0xFFFF);
    for i in 0..steps {
        let shift = count(SB * i);
        for g in 0..GROUPS {
            let v = _mm512_srl_epi64(bits[g], top);
            bits[g] = _mm512_sll_epi64(bits[g], sb);
            let idx = _mm512_or_si512(_mm512_sll_epi64(s[g], sb), v);
            // SAFETY: idx < table.len() in every lane, by the caller's table invariant.
            let e = unsafe { _mm512_i64gather_epi64::<8>(idx, table.as_ptr().cast()) };
            acc[g] = _mm512_xor_si512(acc[g], _mm512_srl_epi64(e, shift));
            s[g] = _mm512_and_si512(e, symbol_mask);
        }
    }
    let consumed = steps * SB;
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
                let x = _mm512_xor_si512(
                    // SAFETY: 8 words from g·8 lie inside `block` (asserted above).
                    unsafe { _mm512_loadu_si512(block[g * LANES..].as_ptr().cast()) },
                    shift_a,
                );
                let tail = _mm512_and_si512(x, _mm512_set1_epi64(((1u64 << r) - 1) as i64));
                y = _mm512_or_si512(_mm512_sll_epi64(y, count(r)), _mm512_xor_si512(tail, t));
            }
            let y = _mm512_xor_si512(y, shift_d);
            // SAFETY: 8 words from g·8 lie inside `block` (asserted above).
            unsafe { _mm512_storeu_si512(block[g * LANES..].as_mut_ptr().cast(), y) };
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

/// Groups of sixteen 32-bit lanes walked together by [`walk_avx512_narrow`]: the same
/// [`GROUPS`] · [`LANES`] words per block as [`walk_avx512`].
const NARROW_GROUPS: usize = GROUPS * LANES / 16;

/// [`walk_avx512`] with 32-bit lanes and the narrow table (see `batch::narrow`): step 0
/// gathers the root's row of `table` (its full 32-bit contribution and next symbol, two
/// gathers of eight lanes), the later steps gather 32-bit entries of `narrow`, sixteen lanes
/// per gather. The narrow table is half the bytes of `table`, so more of it stays in the
/// first-level TLB and the caches. Same words, same return convention as [`walk_avx512`];
/// `codes_top` holds the top 32 bits of each symbol's code (for the tail digit).
///
/// # Safety
/// As for [`walk_avx512`], and `narrow` must hold `symbols << SB` entries whose low SB bits
/// (the next symbol) are below `symbols`, with `codes_top.len() == symbols`.
#[target_feature(enable = "avx512f")]
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn walk_avx512_narrow<const SB: u32>(
    table: &[u64],
    narrow: &[u32],
    codes_top: &[u32],
    q: u32,
    block: &mut [u64],
    a: u64,
    d: u64,
    w: u32,
    steps: u32,
    root: u32,
) -> Option<Walked> {
    assert_eq!(block.len(), GROUPS * LANES, "one block");
    let count = |n: u32| _mm_cvtsi64_si128(n as i64);
    let shift_a = _mm512_set1_epi64(a as i64);
    // Sixteen words of the block, input shift applied, as 32-bit lanes (w ≤ 32).
    let load32 = |block: &[u64], g: usize| {
        // SAFETY: two unaligned 64-byte loads inside `block` (NARROW_GROUPS · 16 words).
        let (lo, hi) = unsafe {
            (
                _mm512_loadu_si512(block[g * 16..].as_ptr().cast()),
                _mm512_loadu_si512(block[g * 16 + 8..].as_ptr().cast()),
            )
        };
        let lo = _mm512_cvtepi64_epi32(_mm512_xor_si512(lo, shift_a));
        let hi = _mm512_cvtepi64_epi32(_mm512_xor_si512(hi, shift_a));
        _mm512_inserti64x4::<1>(_mm512_castsi256_si512(lo), hi)
    };
    let mut bits: [__m512i; NARROW_GROUPS] =
        std::array::from_fn(|g| _mm512_sll_epi32(load32(block, g), count(32 - w)));
    let mut s = [_mm512_set1_epi32(root as i32); NARROW_GROUPS];
    let mut acc = [_mm512_setzero_si512(); NARROW_GROUPS];
    let next_mask = _mm512_set1_epi32(((1u32 << SB) - 1) as i32);
    let sb = count(SB);
    let top = count(32 - SB);
    if steps > 0 {
        // Step 0 reads the root's row of the wide table: full contribution and next symbol.
        let row = _mm512_set1_epi32((root << SB) as i32);
        let join = |l: __m256i, h: __m256i| _mm512_inserti64x4::<1>(_mm512_castsi256_si512(l), h);
        for g in 0..NARROW_GROUPS {
            let idx = _mm512_or_si512(row, _mm512_srl_epi32(bits[g], top));
            bits[g] = _mm512_sll_epi32(bits[g], sb);
            // SAFETY: root < symbols and the digits < 2^SB, so every index < table.len().
            let (lo, hi) = unsafe {
                (
                    _mm512_i32gather_epi64::<8>(_mm512_castsi512_si256(idx), table.as_ptr().cast()),
                    _mm512_i32gather_epi64::<8>(
                        _mm512_extracti64x4_epi64::<1>(idx),
                        table.as_ptr().cast(),
                    ),
                )
            };
            acc[g] = join(
                _mm512_cvtepi64_epi32(_mm512_srli_epi64::<32>(lo)),
                _mm512_cvtepi64_epi32(_mm512_srli_epi64::<32>(hi)),
            );
            s[g] = _mm512_and_si512(
                join(_mm512_cvtepi64_epi32(lo), _mm512_cvtepi64_epi32(hi)),
                _mm512_set1_epi32(0xFFFF),
            );
        }
    }
    for i in 1..steps {
        let shift = count(SB * i);
        for g in 0..NARROW_GROUPS {
            let v = _mm512_srl_epi32(bits[g], top);
            bits[g] = _mm512_sll_epi32(bits[g], sb);
            let idx = _mm512_or_si512(_mm512_sll_epi32(s[g], sb), v);
            // SAFETY: every index < narrow.len(), by the caller's invariant.
            let e = unsafe { _mm512_i32gather_epi32::<4>(idx, narrow.as_ptr().cast()) };
            // A shift of SB or more drops the next symbol's bits.
            acc[g] = _mm512_xor_si512(acc[g], _mm512_srl_epi32(e, shift));
            s[g] = _mm512_and_si512(e, next_mask);
        }
    }
    let consumed = steps * SB;
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
            let lo = _mm512_cvtepu32_epi64(_mm512_castsi512_si256(y));
            let hi = _mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64::<1>(y));
            // SAFETY: two unaligned 64-byte stores inside `block`.
            unsafe {
                _mm512_storeu_si512(block[g * 16..].as_mut_ptr().cast(), lo);
                _mm512_storeu_si512(block[g * 16 + 8..].as_mut_ptr().cast(), hi);
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
