//! The one trait every scrambler implements, the exact oracle included.

use crate::{word_to_f32, word_to_f64, Claim, DigitLayout, PowerOfTwoBase, Width};

/// A random bijection of W-bit words, applied per dimension, that claims to be (at least)
/// a nested scramble in base 2^q.
///
/// Instances are built with their seed (see [`crate::Registry`]); `scramble` is then a pure
/// function of (word, width, dimension), so it is random-access and thread-safe.
/// Bits of the input above `width` must be zero; outputs keep them zero.
///
/// Four methods are required (name, base, claim, scramble); the batch paths, the float
/// forms, the widths and the table size have defaults an implementation overrides where they
/// pay. Inversion is the
/// sub-trait [`Unscramble`], reached through [`Scrambler::inverse`]; the 32-/64-bit
/// conveniences are [`ScramblerExt`], implemented for every scrambler.
///
/// ```
/// use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, ScramblerExt, Width};
/// struct Shift(u64);
/// impl Scrambler for Shift {
///     fn name(&self) -> String { "shift".into() }
///     fn base(&self) -> PowerOfTwoBase { PowerOfTwoBase::B2 }
///     fn claim(&self) -> Claim { Claim::NESTED }
///     fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 { (x ^ self.0) & width.mask() }
/// }
/// assert_eq!(Shift(0xF).scramble_u32(0x3, 0), 0xC);
/// assert!(Shift(0xF).inverse().is_none());
/// ```
pub trait Scrambler: Send + Sync {
    /// The registry name (kebab-case), with options, e.g. `owen-oracle:xor`.
    fn name(&self) -> String;

    /// The scrambling base 2^q.
    fn base(&self) -> PowerOfTwoBase;

    /// What the implementation promises beyond nestedness: the group its node permutations
    /// are marginally uniform over, and whether distinct nodes are independent.
    fn claim(&self) -> Claim;

    /// The scrambled word for dimension `dim`.
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64;

    /// Scrambles `words` in place for dimension `dim`; equal to calling
    /// [`Scrambler::scramble`] on each word (implementations override it where a batch pays:
    /// one request for an external program, interleaved chains for table scramblers).
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        for w in words.iter_mut() {
            *w = self.scramble(*w, width, dim);
        }
    }

    /// Scrambles 32-bit `words` in place for dimension `dim` (width 32); equal to
    /// [`ScramblerExt::scramble_u32`] on each word. The default widens chunks of
    /// [`U32_BATCH_CHUNK`] words on the stack and calls [`Scrambler::scramble_batch`], so
    /// every batch override serves it.
    fn scramble_batch_u32(&self, words: &mut [u32], dim: u32) {
        let mut wide = [0u64; U32_BATCH_CHUNK];
        for chunk in words.chunks_mut(U32_BATCH_CHUNK) {
            let wide = &mut wide[..chunk.len()];
            for (w, &x) in wide.iter_mut().zip(chunk.iter()) {
                *w = x as u64;
            }
            self.scramble_batch(wide, Width::W32, dim);
            for (x, &w) in chunk.iter_mut().zip(wide.iter()) {
                *x = w as u32;
            }
        }
    }

    /// The scrambled value as f32 in [0, 1), truncated (never 1.0); an implementation may
    /// override it to scramble only the digits the float keeps.
    fn scramble_f32(&self, x: u64, width: Width, dim: u32) -> f32 {
        word_to_f32(self.scramble(x, width, dim), width)
    }

    /// The scrambled value as f64 in [0, 1), truncated (never 1.0); an implementation may
    /// override it to scramble only the digits the float keeps.
    fn scramble_f64(&self, x: u64, width: Width, dim: u32) -> f64 {
        word_to_f64(self.scramble(x, width, dim), width)
    }

    /// Whether `width`-bit words are supported (32 and 64 always; small widths for tests).
    fn supports_width(&self, width: Width) -> bool {
        let _ = width;
        true
    }

    /// Bytes of tables the scrambler holds (0 for stateless ones).
    fn table_bytes(&self) -> usize {
        0
    }

    /// The inverse map, for implementations that have one (`None` by default: external
    /// programs and user scramblers under test are checked for injectivity instead).
    fn inverse(&self) -> Option<&dyn Unscramble> {
        None
    }
}

/// A scrambler with an inverse: `unscramble(scramble(x)) == x`. Implementations return
/// `Some(self)` from [`Scrambler::inverse`] so the battery finds it behind `dyn Scrambler`.
pub trait Unscramble: Scrambler {
    /// The inverse of [`Scrambler::scramble`] for dimension `dim`.
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64;
}

/// Conveniences every [`Scrambler`] has: fixed widths and the Owen claim as a test.
pub trait ScramblerExt: Scrambler {
    /// Whether the implementation claims to be a nested uniform (Owen) scramble: every node
    /// permutation independent and uniform over S_b.
    fn claims_nested_uniform(&self) -> bool {
        self.claim().is_owen()
    }

    /// 32-bit form of [`Scrambler::scramble`].
    #[inline]
    fn scramble_u32(&self, x: u32, dim: u32) -> u32 {
        self.scramble(x as u64, Width::W32, dim) as u32
    }

    /// 64-bit form of [`Scrambler::scramble`].
    #[inline]
    fn scramble_u64(&self, x: u64, dim: u32) -> u64 {
        self.scramble(x, Width::W64, dim)
    }
}

impl<S: Scrambler + ?Sized> ScramblerExt for S {}

/// Words per chunk of the default [`Scrambler::scramble_batch_u32`] (3 KiB of stack): a
/// multiple of 48, 16 and 8, so the batch kernels' blocks (ART's AVX-512 blocks are 48 words)
/// divide every whole chunk and only the slice's last chunk leaves a remainder.
pub const U32_BATCH_CHUNK: usize = 384;

/// The identity map: the "unscrambled" reference. It is trivially a nested scramble (every
/// node permutation is the identity) but of course not a uniform one.
#[derive(Debug, Clone, Copy, Default)]
pub struct Identity;

impl Scrambler for Identity {
    fn name(&self) -> String {
        "none".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    fn claim(&self) -> Claim {
        Claim::NESTED
    }
    #[inline]
    fn scramble(&self, x: u64, _width: Width, _dim: u32) -> u64 {
        x
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for Identity {
    #[inline]
    fn unscramble(&self, y: u64, _width: Width, _dim: u32) -> u64 {
        y
    }
}

/// Inverts a nested scramble `f` in base `base` from its forward map alone, digit by digit
/// (at most b evaluations per digit): the inverse for implementations that have none (external
/// programs, user scramblers under test). Only right when `f` is nested; the battery checks
/// that separately.
///
/// ```
/// use gartowen_core::{invert_nested, PowerOfTwoBase, Width};
/// let f = |x: u64| x ^ 0xA5A5_A5A5; // a digital shift is nested in every base
/// assert_eq!(invert_nested(&f, 0x1234_5678 ^ 0xA5A5_A5A5, Width::W32, PowerOfTwoBase::B16), 0x1234_5678);
/// ```
pub fn invert_nested(f: &dyn Fn(u64) -> u64, y: u64, width: Width, base: PowerOfTwoBase) -> u64 {
    let layout = DigitLayout::new(width, base);
    let mut x = 0u64;
    for k in 0..layout.num_digits() {
        let want = layout.get(y, k);
        for d in 0..(1u32 << layout.digit_bits(k)) {
            let c = layout.set(x, k, d);
            if layout.get(f(c), k) == want {
                x = c;
                break;
            }
        }
    }
    x
}
