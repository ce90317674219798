//! Word ↔ float conversion. Word → float truncates (never rounds up, so never 1.0);
//! float → word is exact or an error.

use crate::{CoreError, Width};

/// The value of a W-bit word as f32, truncated to its top 24 bits: always in [0, 1).
///
/// ```
/// use gartowen_core::{word_to_f32, Width};
/// assert!(word_to_f32(0xFFFF_FFFF, Width::W32) < 1.0);
/// assert_eq!(word_to_f32(0x8000_0000, Width::W32), 0.5);
/// ```
#[inline(always)]
pub fn word_to_f32(x: u64, width: Width) -> f32 {
    let w = width.bits();
    if w > 24 {
        ((x >> (w - 24)) as u32) as f32 * (1.0 / 16_777_216.0)
    } else {
        // Exact: a W ≤ 24-bit integer fits the f32 significand; 2^-W built from its bits
        // (a libm power per value would cost more than the rest).
        (x as u32) as f32 * f32::from_bits((127 - w) << 23)
    }
}

/// The value of a W-bit word as f64, truncated to its top 53 bits: always in [0, 1).
///
/// ```
/// use gartowen_core::{word_to_f64, Width};
/// assert!(word_to_f64(u64::MAX, Width::W64) < 1.0);
/// assert_eq!(word_to_f64(0x4000_0000, Width::W32), 0.25);
/// ```
#[inline(always)]
pub fn word_to_f64(x: u64, width: Width) -> f64 {
    let w = width.bits();
    if w > 53 {
        (x >> (w - 53)) as f64 * (1.0 / 9_007_199_254_740_992.0)
    } else {
        x as f64 * f64::from_bits(((1023 - w) as u64) << 52)
    }
}

/// The W-bit word whose value is exactly `v`.
///
/// Errors: NaN, values outside [0, 1) and values that are not multiples of 2^-W.
///
/// ```
/// use gartowen_core::{word_from_f64, Width, CoreError};
/// assert_eq!(word_from_f64(0.75, Width::W32), Ok(0xC000_0000));
/// assert!(matches!(word_from_f64(1.0, Width::W32), Err(CoreError::OutOfUnitInterval(_))));
/// assert!(matches!(word_from_f64(0.1, Width::W32), Err(CoreError::NotRepresentable { .. })));
/// ```
pub fn word_from_f64(v: f64, width: Width) -> Result<u64, CoreError> {
    if v.is_nan() {
        return Err(CoreError::NotANumber);
    }
    if !(0.0..1.0).contains(&v) {
        return Err(CoreError::OutOfUnitInterval(v));
    }
    // Scaling by a power of two is exact for v in [0,1) (no overflow, no subnormal issue
    // that would make a non-integer look like an integer).
    let scaled = v * f64::powi(2.0, width.bits() as i32);
    if scaled.fract() != 0.0 {
        return Err(CoreError::NotRepresentable {
            value: v,
            width: width.bits(),
        });
    }
    Ok(scaled as u64)
}

/// ⌊v · 2^64⌋ for v in [0, 1): the 64-bit word at or below v, exact (scaling by 2^64 is exact
/// in binary64 and the cast truncates). Only values below 2^-11 lose bits, all of them below
/// 2^-64, which no elementary interval of depth ≤ 64 bits can tell apart; the net checker
/// reads floats this way, exact arithmetic (discrepancy) through [`word_from_f64`].
///
/// ```
/// use gartowen_core::word_from_f64_floor;
/// assert_eq!(word_from_f64_floor(0.75), Ok(0xC000_0000_0000_0000));
/// assert_eq!(word_from_f64_floor(1e-300), Ok(0));
/// assert!(word_from_f64_floor(1.0).is_err());
/// ```
pub fn word_from_f64_floor(v: f64) -> Result<u64, CoreError> {
    if v.is_nan() {
        return Err(CoreError::NotANumber);
    }
    if !(0.0..1.0).contains(&v) {
        return Err(CoreError::OutOfUnitInterval(v));
    }
    Ok((v * f64::powi(2.0, 64)) as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_floor_word_agrees_with_the_exact_word_where_that_exists() {
        for v in [0.0, 0.5, 0.75, 2f64.powi(-11), 0.999_999_999_999_999_9] {
            assert_eq!(word_from_f64_floor(v), word_from_f64(v, Width::W64), "{v}");
        }
        let tiny = 2f64.powi(-40) / 3.0;
        assert!(word_from_f64(tiny, Width::W64).is_err());
        let w = word_from_f64_floor(tiny).unwrap();
        // ⌊2^24 / 3⌋ = 5592405.
        assert_eq!(w, 5_592_405);
        assert!(word_from_f64_floor(f64::NAN).is_err() && word_from_f64_floor(-0.5).is_err());
    }

    #[test]
    fn truncation_never_reaches_one() {
        for w in 1..=64 {
            let width = Width::new(w).unwrap();
            assert!(word_to_f32(width.max_word(), width) < 1.0, "f32 W={w}");
            assert!(word_to_f64(width.max_word(), width) < 1.0, "f64 W={w}");
        }
    }

    #[test]
    fn f64_round_trip_of_every_16_bit_word() {
        let w = Width::new(16).unwrap();
        for x in w.all_words() {
            assert_eq!(word_from_f64(word_to_f64(x, w), w), Ok(x));
            assert_eq!(word_to_f32(x, w) as f64, word_to_f64(x, w));
        }
    }

    #[test]
    fn rejects_bad_floats() {
        let w = Width::W32;
        assert_eq!(word_from_f64(f64::NAN, w), Err(CoreError::NotANumber));
        assert_eq!(
            word_from_f64(-0.25, w),
            Err(CoreError::OutOfUnitInterval(-0.25))
        );
        assert!(word_from_f64(f64::INFINITY, w).is_err());
        assert!(word_from_f64(2f64.powi(-33), w).is_err());
        assert_eq!(word_from_f64(2f64.powi(-32), w), Ok(1));
        assert_eq!(
            word_from_f64(1.0 - 2f64.powi(-53), Width::W64),
            Ok(u64::MAX - 2047)
        );
    }
}

#[cfg(test)]
mod scale_tests {
    use super::*;

    #[test]
    fn the_power_of_two_built_from_bits_equals_the_exact_scale_at_every_width() {
        // 2^-W from the exponent bits against powi, for every width and words at both ends.
        for w in 1..=64u32 {
            let width = Width::new(w).unwrap();
            for x in [
                0u64,
                1,
                2,
                3,
                width.mask() >> 1,
                width.mask() - 1,
                width.mask(),
            ] {
                let x = x & width.mask();
                let f64_ref = if w > 53 {
                    (x >> (w - 53)) as f64 * f64::powi(2.0, -53)
                } else {
                    x as f64 * f64::powi(2.0, -(w as i32))
                };
                assert_eq!(
                    word_to_f64(x, width).to_bits(),
                    f64_ref.to_bits(),
                    "f64 W={w}"
                );
                let f32_ref = if w > 24 {
                    ((x >> (w - 24)) as u32) as f32 * f32::powi(2.0, -24)
                } else {
                    (x as u32) as f32 * f32::powi(2.0, -(w as i32))
                };
                assert_eq!(
                    word_to_f32(x, width).to_bits(),
                    f32_ref.to_bits(),
                    "f32 W={w}"
                );
            }
        }
    }
}
