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
        fn $name:ident($($arg:ident: $ty:ty),* $(,)?) => $portable:ident
    ) => {
        $(#[$doc])*
        ///
        /// Compiled once more with AVX2 and BMI2, taken when the CPU has them.
        pub(super) fn $name($($arg: $ty),*) {
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("bmi2")
            {
                #[target_feature(enable = "avx2,bmi2")]
                fn wide($($arg: $ty),*) {
                    $portable($($arg),*)
                }
                // SAFETY: AVX2 and BMI2 were detected on this CPU just above.
                return unsafe { wide($($arg),*) };
            }
            $portable($($arg),*)
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
        DigitColumn::Narrow(digits, cut) => {
            extend_with(parent, &digits[start..end], out, |a, x| {
                (a << shift) | (u32::from(x) >> cut)
            })
        }
        DigitColumn::Wide(digits, cut) => extend_with(parent, &digits[start..end], out, |a, x| {
            (a << shift) | (x >> cut)
        }),
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

/// The v-digit values of one dimension in base 2^q: a column and the shift that cuts its
/// entries to v digits.
pub(super) enum DigitColumn<'a> {
    /// Top 8 bits of each prefix.
    Narrow(&'a [u8], u32),
    /// The prefixes floor(x·b^depth).
    Wide(&'a [u32], u32),
}

with_avx2! {
    /// ORs into `masks[parent key of point i]` (keys 0 for the empty shape) the lane bits of
    /// points 0..n: bit `l·lane + d` for lane l, whose dimension's v-digit value is d (from
    /// `columns[l]`).
    fn set_lane_bits(
        n: usize,
        masks: &mut [u64],
        parent: Option<&[u32]>,
        columns: &[DigitColumn],
        lane: u32,
    ) => set_lane_bits_portable
}

#[inline(always)]
fn set_lane_bits_portable(
    n: usize,
    masks: &mut [u64],
    parent: Option<&[u32]>,
    columns: &[DigitColumn],
    lane: u32,
) {
    let mut lanes = [0u64; CHUNK];
    for start in (0..n).step_by(CHUNK) {
        let end = (start + CHUNK).min(n);
        let lanes = &mut lanes[..end - start];
        lanes.fill(0);
        for (l, column) in columns.iter().enumerate() {
            let offset = u64::from(l as u32 * lane);
            match *column {
                DigitColumn::Narrow(digits, cut) => {
                    for (w, &x) in lanes.iter_mut().zip(&digits[start..end]) {
                        *w |= 1u64 << (offset + u64::from(x >> cut));
                    }
                }
                DigitColumn::Wide(digits, cut) => {
                    for (w, &x) in lanes.iter_mut().zip(&digits[start..end]) {
                        *w |= 1u64 << (offset + u64::from(x >> cut));
                    }
                }
            }
        }
        match parent {
            Some(parent) => {
                for (&key, &bits) in parent[start..end].iter().zip(lanes.iter()) {
                    masks[key as usize] |= bits;
                }
            }
            None => masks[0] |= lanes.iter().fold(0, |acc, &bits| acc | bits),
        }
    }
}

#[cfg(test)]
mod tests {
    //! Each kernel as dispatched (AVX2 + BMI2 where the CPU has them) against its portable
    //! loop called directly, bit for bit, on lengths that end mid-chunk.
    use super::*;
    use gartowen_core::SplitMix64;

    fn columns(rng: &mut SplitMix64, n: usize) -> (Vec<u8>, Vec<u32>) {
        let narrow = (0..n).map(|_| rng.next_u64() as u8).collect();
        let wide = (0..n).map(|_| (rng.next_u64() as u32) >> 12).collect();
        (narrow, wide)
    }

    #[test]
    fn every_kernel_as_dispatched_matches_its_portable_loop() {
        let mut rng = SplitMix64::new(0x6b65726e);
        for n in [1, CHUNK - 1, CHUNK, 3 * CHUNK + 17, 4096 + 5] {
            let (narrow, wide) = columns(&mut rng, n);
            let parent: Vec<u32> = (0..n).map(|_| (rng.next_u64() as u32) & 0x3ff).collect();
            let cols = [
                DigitColumn::Narrow(&narrow, 6),
                DigitColumn::Wide(&wide, 18),
            ];
            for column in &cols {
                for parent in [None, Some(parent.as_slice())] {
                    let (mut a, mut b) = (vec![0u32; n], vec![0u32; n]);
                    extend_all_pow2(parent, column, 2, &mut a);
                    extend_all_pow2_portable(parent, column, 2, &mut b);
                    assert_eq!(a, b, "extend_all_pow2, n = {n}");
                    let (mut a, mut b) = (vec![0u32; 1 << 7], vec![0u32; 1 << 7]);
                    set_key_bits(n, &mut a, parent, column, 2);
                    set_key_bits_portable(n, &mut b, parent, column, 2);
                    assert_eq!(a, b, "set_key_bits, n = {n}");
                    assert!(a.iter().any(|&w| w != 0));
                }
            }
            for parent in [None, Some(parent.as_slice())] {
                let (mut a, mut b) = (vec![0u64; 1 << 10], vec![0u64; 1 << 10]);
                set_lane_bits(n, &mut a, parent, &cols, 4);
                set_lane_bits_portable(n, &mut b, parent, &cols, 4);
                assert_eq!(a, b, "set_lane_bits, n = {n}");
                assert!(a.iter().any(|&w| w != 0));
            }
        }
    }
}
