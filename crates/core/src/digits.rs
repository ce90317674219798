//! Base-2^q digits of W-bit words.
//!
//! Digit k (k = 0 most significant) occupies bits `[W − q(k+1), W − qk)`. When q does not
//! divide W the last digit is partial: it holds the r = W mod q lowest bits and is a digit in
//! base 2^r. Scramblers treat that tail digit as a digit of the smaller alphabet (tail rule).

use crate::{CoreError, Width};

/// A base b = 2^q with q in 1..=8.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PowerOfTwoBase(u8);

impl PowerOfTwoBase {
    /// Base 2.
    pub const B2: PowerOfTwoBase = PowerOfTwoBase(1);
    /// Base 4.
    pub const B4: PowerOfTwoBase = PowerOfTwoBase(2);
    /// Base 8.
    pub const B8: PowerOfTwoBase = PowerOfTwoBase(3);
    /// Base 16.
    pub const B16: PowerOfTwoBase = PowerOfTwoBase(4);
    /// Base 256.
    pub const B256: PowerOfTwoBase = PowerOfTwoBase(8);

    /// Base 2^q; errors unless `1 <= q <= 8`.
    pub const fn from_q(q: u32) -> Result<Self, CoreError> {
        if q >= 1 && q <= 8 {
            Ok(PowerOfTwoBase(q as u8))
        } else {
            Err(CoreError::InvalidDigitBits(q))
        }
    }

    /// The base-2^q value for base `b`; errors unless b is 2, 4, …, 256.
    pub fn from_base(b: u64) -> Result<Self, CoreError> {
        if b.is_power_of_two() && (2..=256).contains(&b) {
            Ok(PowerOfTwoBase(b.trailing_zeros() as u8))
        } else {
            Err(CoreError::NotPowerOfTwoBase(b))
        }
    }

    /// The digit size q in bits.
    #[inline(always)]
    pub const fn q(self) -> u32 {
        self.0 as u32
    }

    /// The base b = 2^q.
    #[inline(always)]
    pub const fn base(self) -> u32 {
        1 << self.0
    }
}

/// How a W-bit word splits into base-2^q digits, tail digit included.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct DigitLayout {
    width: Width,
    base: PowerOfTwoBase,
}

impl DigitLayout {
    /// The layout of `width`-bit words in base 2^q.
    pub const fn new(width: Width, base: PowerOfTwoBase) -> Self {
        DigitLayout { width, base }
    }

    /// The word width.
    pub const fn width(self) -> Width {
        self.width
    }

    /// The base.
    pub const fn base(self) -> PowerOfTwoBase {
        self.base
    }

    /// Number of full q-bit digits, floor(W/q).
    #[inline(always)]
    pub const fn full_digits(self) -> u32 {
        self.width.bits() / self.base.q()
    }

    /// Bits in the partial tail digit, r = W mod q (0 when q divides W).
    #[inline(always)]
    pub const fn tail_bits(self) -> u32 {
        self.width.bits() % self.base.q()
    }

    /// Total number of digits, ceil(W/q), tail digit included.
    #[inline(always)]
    pub const fn num_digits(self) -> u32 {
        self.full_digits() + (self.tail_bits() != 0) as u32
    }

    /// Bits in digit k: q for full digits, r for the tail digit. Panics if k is out of range.
    #[inline(always)]
    pub const fn digit_bits(self, k: u32) -> u32 {
        assert!(k < self.num_digits(), "digit index out of range");
        if k < self.full_digits() {
            self.base.q()
        } else {
            self.tail_bits()
        }
    }

    /// Right shift that brings digit k to the low bits.
    #[inline(always)]
    pub const fn digit_shift(self, k: u32) -> u32 {
        let top = self.base.q() * (k + 1);
        if top <= self.width.bits() {
            self.width.bits() - top
        } else {
            0
        }
    }

    /// Digit k of `x` (0 ≤ digit < 2^digit_bits(k)).
    #[inline(always)]
    pub const fn get(self, x: u64, k: u32) -> u32 {
        let bits = self.digit_bits(k);
        ((x >> self.digit_shift(k)) & ((1u64 << bits) - 1)) as u32
    }

    /// `x` with digit k replaced by `d` (bits of `d` above the digit size are ignored).
    #[inline(always)]
    pub const fn set(self, x: u64, k: u32, d: u32) -> u64 {
        let bits = self.digit_bits(k);
        let shift = self.digit_shift(k);
        let m = ((1u64 << bits) - 1) << shift;
        (x & !m) | (((d as u64) << shift) & m)
    }

    /// The prefix of `x` made of its first k digits, as an integer (digit 0 most significant).
    #[inline(always)]
    pub const fn prefix(self, x: u64, k: u32) -> u64 {
        if k == 0 {
            return 0;
        }
        let kept = if k >= self.num_digits() {
            self.width.bits()
        } else {
            self.base.q() * k
        };
        (x & self.width.mask()) >> (self.width.bits() - kept)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tail_digit_of_a_32_bit_word_in_base_8() {
        let l = DigitLayout::new(Width::W32, PowerOfTwoBase::B8);
        assert_eq!(l.num_digits(), 11);
        assert_eq!(l.digit_bits(10), 2);
        assert_eq!(l.get(0xFFFF_FFFF, 10), 3);
        assert_eq!(l.get(0b101 << 29, 0), 5);
        assert_eq!(l.set(0, 10, 7), 3, "tail digit keeps only its 2 bits");
    }

    #[test]
    fn base_validation() {
        assert!(PowerOfTwoBase::from_base(3).is_err());
        assert!(PowerOfTwoBase::from_base(512).is_err());
        assert!(PowerOfTwoBase::from_base(1).is_err());
        assert_eq!(PowerOfTwoBase::from_base(16).unwrap().q(), 4);
    }

    #[test]
    fn digits_reassemble_every_12_bit_word() {
        let w = Width::new(12).unwrap();
        for q in 1..=8 {
            let l = DigitLayout::new(w, PowerOfTwoBase::from_q(q).unwrap());
            for x in w.all_words() {
                let mut y = 0u64;
                for k in 0..l.num_digits() {
                    y = (y << l.digit_bits(k)) | l.get(x, k) as u64;
                }
                assert_eq!(y, x, "q={q}");
            }
        }
    }
}
