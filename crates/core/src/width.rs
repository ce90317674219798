//! Word widths. Words are stored in `u64`; a [`Width`] says how many low bits are in use,
//! so 8-, 12- and 16-bit words can be enumerated exhaustively with the same code as 32/64.

use crate::CoreError;

/// A word width W in 1..=64 bits. A W-bit word `x` has value `x · 2^-W` in [0, 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Width(u8);

impl Width {
    /// 32-bit words.
    pub const W32: Width = Width(32);
    /// 64-bit words.
    pub const W64: Width = Width(64);

    /// A width of `bits` bits; errors unless `1 <= bits <= 64`.
    pub const fn new(bits: u32) -> Result<Width, CoreError> {
        if bits >= 1 && bits <= 64 {
            Ok(Width(bits as u8))
        } else {
            Err(CoreError::InvalidWidth(bits))
        }
    }

    /// The number of bits W.
    #[inline(always)]
    pub const fn bits(self) -> u32 {
        self.0 as u32
    }

    /// The mask of the W low bits (all ones for W = 64).
    #[inline(always)]
    pub const fn mask(self) -> u64 {
        if self.0 == 64 {
            u64::MAX
        } else {
            (1u64 << self.0) - 1
        }
    }

    /// The largest W-bit word, 2^W − 1.
    #[inline(always)]
    pub const fn max_word(self) -> u64 {
        self.mask()
    }

    /// Checks that `word` fits in W bits.
    pub fn check(self, word: u64) -> Result<u64, CoreError> {
        if word & !self.mask() == 0 {
            Ok(word)
        } else {
            Err(CoreError::WordTooWide {
                word,
                width: self.bits(),
            })
        }
    }

    /// Every W-bit word in increasing order; meant for exhaustive tests at small W.
    pub fn all_words(self) -> impl Iterator<Item = u64> {
        0..=self.mask()
    }
}
