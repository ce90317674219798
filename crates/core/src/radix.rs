//! Digits in a base b that is not a power of two (3, 5, 6, 7, …: the bases of Halton and prime
//! Faure points), and the trait of scramblers in such a base.
//!
//! A base-b coordinate is an integer `k` of m base-b digits, value `k · b^-m`, digit 0 the most
//! significant (`docs/design.md` §1 for base 2^q). m is the most digits whose b^m fits the word:
//! base 3 has 20 digits in 32 bits and 40 in 64. Power-of-two bases keep their bit layout
//! ([`crate::DigitLayout`]); [`Radix`] refuses them so that one base never has two word layouts.

use crate::{Claim, CoreError, Width};

/// A base b in 3..=65535 that is not a power of two.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Radix(u32);

impl Radix {
    /// The largest base accepted (digits are `u32`s below it; node permutations of larger
    /// alphabets would not fit a scrambler's per-node work).
    pub const MAX: u32 = 65_535;

    /// Base `b`; errors unless 3 ≤ b ≤ 65535 and b is not a power of two.
    ///
    /// ```
    /// use gartowen_core::Radix;
    /// assert_eq!(Radix::new(3).unwrap().get(), 3);
    /// assert!(Radix::new(4).is_err()); // base 4 is a PowerOfTwoBase
    /// assert!(Radix::new(1).is_err());
    /// ```
    pub fn new(b: u64) -> Result<Radix, CoreError> {
        if (3..=Radix::MAX as u64).contains(&b) && !b.is_power_of_two() {
            Ok(Radix(b as u32))
        } else {
            Err(CoreError::InvalidRadix(b))
        }
    }

    /// The base b.
    #[inline(always)]
    pub const fn get(self) -> u32 {
        self.0
    }

    /// m: the most base-b digits whose b^m ≤ 2^W (0 when b > 2^W).
    ///
    /// ```
    /// use gartowen_core::{Radix, Width};
    /// let three = Radix::new(3).unwrap();
    /// assert_eq!((three.digits_in(Width::W32), three.digits_in(Width::W64)), (20, 40));
    /// ```
    pub fn digits_in(self, width: Width) -> u32 {
        let (b, limit) = (self.0 as u128, 1u128 << width.bits());
        let (mut m, mut p) = (0, b);
        while p <= limit {
            m += 1;
            p *= b;
        }
        m
    }
}

/// How a W-bit word holds base-b digits: the integer below b^m in its low bits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct RadixLayout {
    radix: Radix,
    width: Width,
    digits: u32,
}

impl RadixLayout {
    /// The layout of `width`-bit words in base `radix`; errors when not one digit fits.
    ///
    /// ```
    /// use gartowen_core::{Radix, RadixLayout, Width};
    /// let l = RadixLayout::new(Width::W32, Radix::new(3).unwrap()).unwrap();
    /// assert_eq!((l.num_digits(), l.capacity()), (20, 3u64.pow(20)));
    /// assert!(RadixLayout::new(Width::new(2).unwrap(), Radix::new(5).unwrap()).is_err());
    /// ```
    pub fn new(width: Width, radix: Radix) -> Result<RadixLayout, CoreError> {
        let digits = radix.digits_in(width);
        if digits == 0 {
            return Err(CoreError::RadixTooLarge {
                base: radix.get(),
                width: width.bits(),
            });
        }
        Ok(RadixLayout {
            radix,
            width,
            digits,
        })
    }

    /// The base.
    pub const fn radix(self) -> Radix {
        self.radix
    }

    /// The word width.
    pub const fn width(self) -> Width {
        self.width
    }

    /// m, the digits in a word.
    #[inline(always)]
    pub const fn num_digits(self) -> u32 {
        self.digits
    }

    /// b^m: the number of words (every word is below it). Below 2^W since b is not a power
    /// of two.
    #[inline(always)]
    pub fn capacity(self) -> u64 {
        (self.radix.0 as u64).pow(self.digits)
    }

    /// b^(m−1−k): the value of one unit of digit k.
    #[inline(always)]
    pub fn place(self, k: u32) -> u64 {
        assert!(k < self.digits, "digit index out of range");
        (self.radix.0 as u64).pow(self.digits - 1 - k)
    }

    /// Digit k of `x` (0 ≤ digit < b).
    #[inline(always)]
    pub fn get(self, x: u64, k: u32) -> u32 {
        ((x / self.place(k)) % self.radix.0 as u64) as u32
    }

    /// `x` with digit k replaced by `d` (d < b).
    #[inline(always)]
    pub fn set(self, x: u64, k: u32, d: u32) -> u64 {
        debug_assert!(d < self.radix.0, "digit {d} out of base");
        let place = self.place(k);
        x - self.get(x, k) as u64 * place + d as u64 * place
    }

    /// A uniformly random word below b^m (rejection keeps every word equally likely).
    pub fn random_word(self, rng: &mut crate::SplitMix64) -> u64 {
        let n = self.capacity();
        let zone = u64::MAX - u64::MAX % n;
        loop {
            let r = rng.next_u64();
            if r < zone {
                return r % n;
            }
        }
    }

    /// Checks that `word` is below b^m.
    pub fn check(self, word: u64) -> Result<u64, CoreError> {
        if word < self.capacity() {
            Ok(word)
        } else {
            Err(CoreError::RadixWordTooLarge {
                word,
                base: self.radix.0,
                digits: self.digits,
            })
        }
    }

    /// The value `word · b^-m` as f64, truncated onto the 2^-53 grid: always in [0, 1).
    ///
    /// ```
    /// use gartowen_core::{Radix, RadixLayout, Width};
    /// let l = RadixLayout::new(Width::W64, Radix::new(3).unwrap()).unwrap();
    /// assert!(l.to_f64(l.capacity() - 1) < 1.0);
    /// assert!((l.to_f64(l.capacity() / 3) - 1.0 / 3.0).abs() < 1e-15);
    /// ```
    pub fn to_f64(self, word: u64) -> f64 {
        // floor(word · 2^53 / b^m) is exact in 128 bits and below 2^53.
        let grid = ((word as u128) << 53) / self.capacity() as u128;
        grid as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// A random bijection of base-b digit integers, applied per dimension, that claims to be (at
/// least) a nested scramble in base b: output digit k depends only on input digits 0..=k,
/// and each node's map of digit k is a permutation of the b digits.
///
/// The base-b counterpart of [`crate::Scrambler`]: words are integers below b^m for the
/// [`RadixLayout`] of the width (outputs too).
pub trait RadixScrambler: Send + Sync {
    /// The name (kebab-case, with options), e.g. `owen-oracle:cyclic`.
    fn name(&self) -> String;

    /// The base b.
    fn radix(&self) -> Radix;

    /// What it promises beyond nestedness (the groups S_b and Z_b apply in every base).
    fn claim(&self) -> Claim;

    /// The scrambled word for dimension `dim` (`x` below b^m of `width`'s layout).
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64;

    /// Whether it scrambles words of `width` bits (every width that holds a digit, by
    /// default; a program that speaks one frame width answers that one alone).
    fn supports_width(&self, width: Width) -> bool {
        RadixLayout::new(width, self.radix()).is_ok()
    }

    /// Scrambles `words` in place; equal to [`RadixScrambler::scramble`] on each word.
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        for w in words.iter_mut() {
            *w = self.scramble(*w, width, dim);
        }
    }

    /// The inverse map, where the implementation has one (`None` by default).
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> Option<u64> {
        let _ = (y, width, dim);
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radix_refuses_powers_of_two_and_the_bounds() {
        for b in [0u64, 1, 2, 4, 8, 256, 65_536, 65_537, u64::MAX] {
            assert_eq!(Radix::new(b), Err(CoreError::InvalidRadix(b)), "{b}");
        }
        for b in [3u64, 5, 6, 7, 12, 255, 257, 65_535] {
            assert_eq!(Radix::new(b).unwrap().get() as u64, b);
        }
        // Each refusal says which rule the base breaks.
        let why = |b: u64| Radix::new(b).unwrap_err().to_string();
        assert_eq!(why(1), "base 1: a base is at least 2");
        assert!(why(512).contains("power of two above 256"), "{}", why(512));
        assert!(
            why(65_536).contains("power of two above 256"),
            "{}",
            why(65_536)
        );
        assert!(why(65_537).contains("above 65535"), "{}", why(65_537));
        assert!(why(16).contains("digits are bits"), "{}", why(16));
        assert!(why(256).contains("digits are bits"), "{}", why(256));
        // The largest base served is not "above" itself (the error is built by hand here).
        let at_limit = CoreError::InvalidRadix(65_535).to_string();
        assert!(!at_limit.contains("above"), "{at_limit}");
    }

    #[test]
    fn digits_in_is_the_largest_m_with_b_to_the_m_within_the_word() {
        for b in [3u32, 5, 6, 7, 10, 251, 65_535] {
            let r = Radix::new(b as u64).unwrap();
            for w in 1..=64 {
                let m = r.digits_in(Width::new(w).unwrap());
                let limit = 1u128 << w;
                assert!((b as u128).pow(m) <= limit, "b {b} w {w}");
                assert!((b as u128).pow(m + 1) > limit, "b {b} w {w}");
            }
        }
        let five = Radix::new(5).unwrap();
        assert_eq!(
            (five.digits_in(Width::W32), five.digits_in(Width::W64)),
            (13, 27)
        );
    }

    #[test]
    fn get_and_set_agree_with_base_b_expansion_on_every_small_word() {
        let l = RadixLayout::new(Width::new(8).unwrap(), Radix::new(3).unwrap()).unwrap();
        assert_eq!((l.num_digits(), l.capacity()), (5, 243));
        for x in 0..l.capacity() {
            let digits: Vec<u32> = (0..5).map(|k| l.get(x, k)).collect();
            let back = digits.iter().fold(0u64, |v, &d| v * 3 + d as u64);
            assert_eq!(back, x);
            for k in 0..5 {
                for d in 0..3 {
                    let y = l.set(x, k, d);
                    assert_eq!(l.get(y, k), d);
                    assert!((0..5)
                        .filter(|&j| j != k)
                        .all(|j| l.get(y, j) == l.get(x, j)));
                }
            }
        }
        assert!(l.check(242).is_ok());
        assert_eq!(
            l.check(243),
            Err(CoreError::RadixWordTooLarge {
                word: 243,
                base: 3,
                digits: 5
            })
        );
    }

    /// Adds 1 to the last digit mod b: only the required methods.
    struct LastDigitPlusOne(Radix);

    impl RadixScrambler for LastDigitPlusOne {
        fn name(&self) -> String {
            "last-digit-plus-one".into()
        }
        fn radix(&self) -> Radix {
            self.0
        }
        fn claim(&self) -> Claim {
            Claim::NESTED
        }
        fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 {
            let l = RadixLayout::new(width, self.0).unwrap();
            let k = l.num_digits() - 1;
            l.set(x, k, (l.get(x, k) + 1) % self.0.get())
        }
    }

    #[test]
    fn the_batch_default_scrambles_each_word_and_no_inverse_is_offered() {
        let s = LastDigitPlusOne(Radix::new(3).unwrap());
        let words: Vec<u64> = vec![0, 1, 2, 5, 3u64.pow(20) - 1];
        let mut batch = words.clone();
        s.scramble_batch(&mut batch, Width::W32, 0);
        let one_by_one: Vec<u64> = words
            .iter()
            .map(|&x| s.scramble(x, Width::W32, 0))
            .collect();
        assert_eq!(batch, one_by_one);
        assert_eq!(batch[..3], [1, 2, 0]);
        assert_eq!(s.unscramble(1, Width::W32, 0), None);
    }

    #[test]
    fn to_f64_truncates_and_is_monotone() {
        let l = RadixLayout::new(Width::W32, Radix::new(7).unwrap()).unwrap();
        let n = l.capacity();
        assert_eq!(l.to_f64(0), 0.0);
        for k in [1, 2, n / 7, n / 2, n - 2, n - 1] {
            let v = l.to_f64(k);
            assert!(v <= k as f64 / n as f64 && v < 1.0, "{k}");
            assert!(l.to_f64(k - 1) < v);
        }
    }
}
