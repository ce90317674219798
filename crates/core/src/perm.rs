//! Permutations of n ≤ 256 digit symbols, stored inline (no allocation), with packed forms.
//!
//! Packed form with `f`-bit fields: entry d sits in field d counted from the top of an
//! `n·f`-bit word, i.e. at bit offset `(n − 1 − d)·f`. The 24-bit form packs 8 symbols in
//! 3-bit fields and the 64-bit form 16 symbols in 4-bit fields.

use crate::{CoreError, SplitMix64};

/// A permutation of `0..n`, n in 1..=256: `apply(d)` is the image of d.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Permutation {
    n: u16,
    map: [u8; 256],
}

impl std::fmt::Debug for Permutation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Permutation{:?}", self.as_slice())
    }
}

impl Permutation {
    /// The identity on `0..n`.
    pub fn identity(n: usize) -> Result<Self, CoreError> {
        if !(1..=256).contains(&n) {
            return Err(CoreError::InvalidPermutationSize(n));
        }
        let mut map = [0u8; 256];
        for (i, m) in map.iter_mut().enumerate().take(n) {
            *m = i as u8;
        }
        Ok(Permutation { n: n as u16, map })
    }

    /// Validates `images` as a permutation of `0..images.len()`.
    ///
    /// ```
    /// use gartowen_core::Permutation;
    /// assert!(Permutation::from_images(&[2, 0, 1]).is_ok());
    /// assert!(Permutation::from_images(&[0, 0, 1]).is_err());
    /// ```
    pub fn from_images(images: &[u8]) -> Result<Self, CoreError> {
        let n = images.len();
        let mut p = Permutation::identity(n)?;
        let mut seen = [false; 256];
        for (d, &img) in images.iter().enumerate() {
            if img as usize >= n {
                return Err(CoreError::NotAPermutation {
                    reason: format!("image {img} of {d} is not below {n}"),
                });
            }
            if seen[img as usize] {
                return Err(CoreError::NotAPermutation {
                    reason: format!("image {img} appears twice"),
                });
            }
            seen[img as usize] = true;
            p.map[d] = img;
        }
        Ok(p)
    }

    /// A uniformly random permutation of `0..n` by Fisher–Yates with unbiased draws.
    pub fn random(n: usize, rng: &mut SplitMix64) -> Result<Self, CoreError> {
        let mut p = Permutation::identity(n)?;
        p.shuffle(rng);
        Ok(p)
    }

    /// Fisher–Yates in place (see [`fisher_yates`]).
    #[inline]
    pub fn shuffle(&mut self, rng: &mut SplitMix64) {
        let n = self.len();
        fisher_yates(&mut self.map[..n], rng);
    }

    /// The number of symbols n.
    #[inline(always)]
    pub fn len(&self) -> usize {
        self.n as usize
    }

    /// Always false: a permutation has at least one symbol.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The image of `d` (d < n).
    #[inline(always)]
    pub fn apply(&self, d: u32) -> u32 {
        debug_assert!((d as usize) < self.len());
        self.map[d as usize] as u32
    }

    /// Images of 0..n.
    pub fn as_slice(&self) -> &[u8] {
        &self.map[..self.len()]
    }

    /// `self ∘ other`: d ↦ self(other(d)). Panics on different sizes.
    pub fn compose(&self, other: &Permutation) -> Permutation {
        assert_eq!(self.n, other.n, "composing permutations of different sizes");
        let mut out = self.clone();
        for d in 0..self.len() {
            out.map[d] = self.map[other.map[d] as usize];
        }
        out
    }

    /// The inverse permutation.
    pub fn inverse(&self) -> Permutation {
        let mut out = self.clone();
        for d in 0..self.len() {
            out.map[self.map[d] as usize] = d as u8;
        }
        out
    }

    /// Packs into `field_bits`-bit fields, entry d in field d from the top of an
    /// `n·field_bits`-bit word. Errors if the word would exceed 64 bits or a field is too narrow.
    pub fn pack(&self, field_bits: u32) -> Result<u64, CoreError> {
        let n = self.len() as u32;
        if field_bits == 0 || n * field_bits > 64 || (n - 1) >> field_bits != 0 {
            return Err(CoreError::NotAPermutation {
                reason: format!("{n} symbols do not pack into {field_bits}-bit fields of 64 bits"),
            });
        }
        let mut w = 0u64;
        for d in 0..n {
            w |= (self.map[d as usize] as u64) << ((n - 1 - d) * field_bits);
        }
        Ok(w)
    }

    /// Unpacks `n` entries of `field_bits` bits (the inverse of [`Permutation::pack`]), validating.
    pub fn unpack(word: u64, n: usize, field_bits: u32) -> Result<Self, CoreError> {
        if n == 0 || n as u32 * field_bits > 64 || field_bits > 8 {
            return Err(CoreError::InvalidPermutationSize(n));
        }
        if (n as u32 * field_bits) < 64 && word >> (n as u32 * field_bits) != 0 {
            return Err(CoreError::NotAPermutation {
                reason: format!("packed word {word:#x} has bits above {n} fields"),
            });
        }
        let mask = (1u64 << field_bits) - 1;
        let mut images = [0u8; 256];
        for (d, img) in images.iter_mut().enumerate().take(n) {
            *img = ((word >> ((n - 1 - d) as u32 * field_bits)) & mask) as u8;
        }
        Permutation::from_images(&images[..n])
    }

    /// The 24-bit form of a permutation of 8 symbols (3-bit fields).
    pub fn pack24(&self) -> Result<u32, CoreError> {
        if self.len() != 8 {
            return Err(CoreError::InvalidPermutationSize(self.len()));
        }
        Ok(self.pack(3)? as u32)
    }

    /// Unpacks the 24-bit form (8 symbols, 3-bit fields).
    pub fn unpack24(word: u32) -> Result<Self, CoreError> {
        Permutation::unpack(word as u64, 8, 3)
    }

    /// The 64-bit form of a permutation of 16 symbols (4-bit fields).
    pub fn pack64(&self) -> Result<u64, CoreError> {
        if self.len() != 16 {
            return Err(CoreError::InvalidPermutationSize(self.len()));
        }
        self.pack(4)
    }

    /// Unpacks the 64-bit form (16 symbols, 4-bit fields).
    pub fn unpack64(word: u64) -> Result<Self, CoreError> {
        Permutation::unpack(word, 16, 4)
    }

    /// Lehmer-code rank in `0..n!` (lexicographic order), for n ≤ 20; used to index
    /// cells of S_n in distribution tests.
    pub fn rank(&self) -> u64 {
        let n = self.len();
        assert!(n <= 20, "rank needs n ≤ 20");
        let mut rank = 0u64;
        for i in 0..n {
            let smaller_later = (i + 1..n).filter(|&j| self.map[j] < self.map[i]).count() as u64;
            rank = rank * (n - i) as u64 + smaller_later;
        }
        rank
    }
}

/// Fisher–Yates in place: for i from len−1 down to 1, swap entry i with a uniform j ≤ i
/// (unbiased draws). Every permutation-drawing path uses this one draw sequence.
#[inline]
pub fn fisher_yates(items: &mut [u8], rng: &mut SplitMix64) {
    for i in (1..items.len()).rev() {
        let j = rng.bounded(i as u32 + 1) as usize;
        items.swap(i, j);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_forms_place_entry_zero_at_the_top() {
        let p = Permutation::from_images(&[7, 6, 5, 4, 3, 2, 1, 0]).unwrap();
        assert_eq!(p.pack24().unwrap(), 0b111_110_101_100_011_010_001_000);
        let id16 = Permutation::identity(16).unwrap();
        assert_eq!(id16.pack64().unwrap(), 0x0123_4567_89AB_CDEF);
        assert_eq!(Permutation::unpack64(0x0123_4567_89AB_CDEF).unwrap(), id16);
        assert!(Permutation::unpack64(0x0023_4567_89AB_CDEF).is_err());
    }

    #[test]
    fn ranks_enumerate_s4_bijectively() {
        let mut seen = [false; 24];
        let mut rng = SplitMix64::new(5);
        for _ in 0..2000 {
            let p = Permutation::random(4, &mut rng).unwrap();
            seen[p.rank() as usize] = true;
        }
        assert!(seen.iter().all(|&s| s));
        assert_eq!(Permutation::identity(4).unwrap().rank(), 0);
        assert_eq!(Permutation::from_images(&[3, 2, 1, 0]).unwrap().rank(), 23);
    }
}
