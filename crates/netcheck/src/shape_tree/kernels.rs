//! The loops of the walk's passes over the points: key extension and the bit passes,
//! each compiled once more for AVX2 and chosen at run time.

use crate::box_keys::CHUNK;
/// `out[i] = f(parent[i], digits[i])`, with parent keys 0 for the empty shape: one branch-free
/// loop per case, so the compiler vectorizes each.
#[inline(always)]
pub(super) fn extend_with<D: Copy>(
    parent: Option<&[u32]>,
    digits: &[D],
    out: &mut [u32],
    f: impl Fn(u32, D) -> u32,
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

/// Defines `fn NAME(args)` that runs `PORTABLE(args)` compiled once more with AVX2 and BMI2
/// (vector variable shifts, BMI2 bit operations), taken when the CPU has them; `PORTABLE` is
/// `#[inline(always)]` so the whole loop is compiled for the wider target.
macro_rules! with_avx2 {
    (
        $(#[$doc:meta])*
        fn $name:ident $(<const $g:ident: usize>)? ($($arg:ident: $ty:ty),* $(,)?)
            => $portable:ident
    ) => {
        $(#[$doc])*
        ///
        /// Compiled once more with AVX2 and BMI2, taken when the CPU has them.
        pub(super) fn $name $(<const $g: usize>)? ($($arg: $ty),*) {
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("bmi2")
            {
                #[target_feature(enable = "avx2,bmi2")]
                fn wide $(<const $g: usize>)? ($($arg: $ty),*) {
                    $portable $(::<$g>)? ($($arg),*)
                }
                // SAFETY: AVX2 and BMI2 were detected on this CPU just above.
                return unsafe { wide $(::<$g>)? ($($arg),*) };
            }
            $portable $(::<$g>)? ($($arg),*)
        }
    };
}

/// Keys (parent << shift) | digit of points start..start + out.len() in base 2^q, the digit
/// (of `shift` bits) read from `column` (parent keys 0 for the empty shape). Always inlined,
/// so each kernel builds its keys with the vector width it was compiled for.
#[inline(always)]
pub(super) fn extend_pow2(
    parent: Option<&[u32]>,
    column: &DigitColumn,
    shift: u32,
    start: usize,
    out: &mut [u32],
) {
    let end = start + out.len();
    let parent = parent.map(|parent| &parent[start..end]);
    match *column {
        DigitColumn::Narrow(digits, cut, mask) => {
            extend_with(parent, &digits[start..end], out, |a, x| {
                (a << shift) | ((u32::from(x) >> cut) & mask)
            })
        }
        DigitColumn::Wide(digits, cut, mask) => {
            extend_with(parent, &digits[start..end], out, |a, x| {
                (a << shift) | ((x >> cut) & mask)
            })
        }
    }
}

with_avx2! {
    /// [`extend_pow2`] over every point into `out`.
    fn extend_all_pow2(parent: Option<&[u32]>, column: &DigitColumn, shift: u32, out: &mut [u32])
        => extend_all_pow2_portable
}

#[inline(always)]
fn extend_all_pow2_portable(
    parent: Option<&[u32]>,
    column: &DigitColumn,
    shift: u32,
    out: &mut [u32],
) {
    for (c, chunk) in out.chunks_mut(CHUNK).enumerate() {
        extend_pow2(parent, column, shift, c * CHUNK, chunk);
    }
}

with_avx2! {
    /// Sets the bit of every key (parent << shift) | digit of points 0..n in `bits` (digits
    /// from `column`), the keys built a chunk at a time.
    fn set_key_bits(
        n: usize,
        bits: &mut [u32],
        parent: Option<&[u32]>,
        column: &DigitColumn,
        shift: u32,
    ) => set_key_bits_portable
}

#[inline(always)]
fn set_key_bits_portable(
    n: usize,
    bits: &mut [u32],
    parent: Option<&[u32]>,
    column: &DigitColumn,
    shift: u32,
) {
    let mut keys = [0u32; CHUNK];
    for start in (0..n).step_by(CHUNK) {
        let keys = &mut keys[..CHUNK.min(n - start)];
        extend_pow2(parent, column, shift, start, keys);
        for &key in keys.iter() {
            bits[(key >> 5) as usize] |= 1u32 << (key & 31);
        }
    }
}

/// A part's digit values of one dimension in base 2^q: a column, the shift that drops the
/// digits below the part and the mask that drops those above it.
pub(super) enum DigitColumn<'a> {
    /// Top 8 bits of each prefix.
    Narrow(&'a [u8], u32, u32),
    /// The prefixes floor(x·b^depth).
    Wide(&'a [u32], u32, u32),
}

/// Points per block of a packed pass: their lane words (at most [`super::MAX_BOX_WORDS`] each) stay
/// in L1 between the column loops and the read-modify-writes.
const LANE_BLOCK: usize = 256;

with_avx2! {
    /// ORs into the `M` words of box K (`masks[K·M..K·M + M]`) the lane bits of points 0..n:
    /// bit `l·lane + d` of the box's words (word-major bits, word 0 first) for lane l, whose
    /// part's digits have value d (from `columns[l]`). K is the `parent` key (0 for the empty
    /// shape), extended as [`extend_pow2`] does by `node`'s digits when given.
    fn set_lane_bits<const M: usize>(
        n: usize,
        masks: &mut [u64],
        parent: Option<&[u32]>,
        node: Option<(&DigitColumn, u32)>,
        columns: &[DigitColumn],
        lane: u32,
    ) => set_lane_bits_portable
}

#[inline(always)]
fn set_lane_bits_portable<const M: usize>(
    n: usize,
    masks: &mut [u64],
    parent: Option<&[u32]>,
    node: Option<(&DigitColumn, u32)>,
    columns: &[DigitColumn],
    lane: u32,
) {
    // Word-major, so each column loop writes one contiguous word array (it vectorizes).
    let mut lanes = [[0u64; LANE_BLOCK]; M];
    let mut node_keys = [0u32; LANE_BLOCK];
    for start in (0..n).step_by(LANE_BLOCK) {
        let end = (start + LANE_BLOCK).min(n);
        let len = end - start;
        lanes.iter_mut().for_each(|w| w[..len].fill(0));
        for (l, column) in columns.iter().enumerate() {
            let bit = l as u32 * lane;
            let (word, offset) = ((bit / 64) as usize, u64::from(bit % 64));
            let lanes = &mut lanes[word][..len];
            match *column {
                DigitColumn::Narrow(digits, cut, mask) => {
                    for (w, &x) in lanes.iter_mut().zip(&digits[start..end]) {
                        *w |= 1u64 << (offset + u64::from((u32::from(x) >> cut) & mask));
                    }
                }
                DigitColumn::Wide(digits, cut, mask) => {
                    for (w, &x) in lanes.iter_mut().zip(&digits[start..end]) {
                        *w |= 1u64 << (offset + u64::from((x >> cut) & mask));
                    }
                }
            }
        }
        let keys = match (node, parent) {
            (Some((column, shift)), _) => {
                extend_pow2(parent, column, shift, start, &mut node_keys[..len]);
                &node_keys[..len]
            }
            (None, Some(parent)) => &parent[start..end],
            (None, None) => {
                for (w, lane_words) in masks[..M].iter_mut().zip(&lanes) {
                    *w |= lane_words[..len].iter().fold(0, |acc, &bits| acc | bits);
                }
                continue;
            }
        };
        for (i, &key) in keys.iter().enumerate() {
            let at = key as usize * M;
            let words = &mut masks[at..at + M];
            for (w, lane_words) in words.iter_mut().zip(&lanes) {
                *w |= lane_words[i];
            }
        }
    }
}
