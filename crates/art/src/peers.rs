//! Hash-based peers (`docs/design.md` §3.4), for comparison and not as references: Laine–Karras
//! hashing on reversed bits, the improved LK hash, and a per-bit hashed binary Owen scramble.
//! Each dimension's seed is `hash_words([seed, dim])`.
//!
//! The LK-style hashes mix only from low to high bits of the bit-reversed word, so output bit k
//! depends only on input bits 0..=k: they are binary nested scrambles, but their node
//! permutations are not independent uniform flips. They act on 32-bit words (the constants are
//! 32-bit); the per-bit Owen scramble works at any width.

use gartowen_core::Unscramble;
use gartowen_core::{hash_words, mix64, Claim, NodeGroup, PowerOfTwoBase, Scrambler, Width};

/// Laine–Karras style permutation of a bit-reversed 32-bit word (the classic constants).
#[inline(always)]
pub fn laine_karras(mut x: u32, seed: u32) -> u32 {
    x = x.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6c50_b47c);
    x ^= x.wrapping_mul(0xb82f_1e52);
    x ^= x.wrapping_mul(0xc7af_e638);
    x ^= x.wrapping_mul(0x8d22_f6e6);
    x
}

/// The improved LK hash (better avalanche among low bits), on a bit-reversed 32-bit word.
#[inline(always)]
pub fn improved_lk(mut x: u32, seed: u32) -> u32 {
    x ^= x.wrapping_mul(0x3d20_adea);
    x = x.wrapping_add(seed);
    x = x.wrapping_mul((seed >> 16) | 1);
    x ^= x.wrapping_mul(0x0552_6c56);
    x ^= x.wrapping_mul(0x53a2_2864);
    x
}

/// Which LK hash a [`LkHash`] uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LkFlavor {
    /// The original Laine–Karras constants.
    Classic,
    /// The improved hash.
    Improved,
}

/// y = reverse(hash(reverse(x), seed_dim)): a binary nested scramble of 32-bit words.
#[derive(Debug, Clone)]
pub struct LkHash {
    seed: u64,
    flavor: LkFlavor,
}

impl LkHash {
    /// The LK scrambler with `seed`.
    pub fn new(flavor: LkFlavor, seed: u64) -> Self {
        LkHash { seed, flavor }
    }

    #[inline(always)]
    fn dim_seed(&self, dim: u32) -> u32 {
        hash_words(&[self.seed, dim as u64]) as u32
    }

    /// The scramble of one word with the dimension's seed already drawn.
    #[inline(always)]
    fn apply(flavor: LkFlavor, x: u32, seed: u32) -> u32 {
        let r = x.reverse_bits();
        match flavor {
            LkFlavor::Classic => laine_karras(r, seed),
            LkFlavor::Improved => improved_lk(r, seed),
        }
        .reverse_bits()
    }
}

/// `f` on every word: a branch-free loop the compiler vectorizes (see [`lk_batch32`]).
#[inline(always)]
fn lk_lanes32(words: &mut [u32], f: impl Fn(u32) -> u32) {
    for w in words.iter_mut() {
        *w = f(*w);
    }
}

/// [`lk_lanes32`] on 32-bit words held in `u64`.
#[inline(always)]
fn lk_lanes64(words: &mut [u64], f: impl Fn(u32) -> u32) {
    for w in words.iter_mut() {
        *w = f(*w as u32) as u64;
    }
}

/// [`lk_lanes32`] for an LK flavor, compiled for the baseline target and once more with AVX2
/// (taken when the CPU has it): vectorized where the hardware allows, the same bits either way.
fn lk_batch32(words: &mut [u32], flavor: LkFlavor, seed: u32) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        #[target_feature(enable = "avx2")]
        fn avx2(words: &mut [u32], flavor: LkFlavor, seed: u32) {
            lk_lanes32(words, |x| LkHash::apply(flavor, x, seed))
        }
        // SAFETY: AVX2 was detected on this CPU just above.
        return unsafe { avx2(words, flavor, seed) };
    }
    lk_lanes32(words, |x| LkHash::apply(flavor, x, seed))
}

/// [`lk_batch32`] on 32-bit words held in `u64`.
fn lk_batch64(words: &mut [u64], flavor: LkFlavor, seed: u32) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        #[target_feature(enable = "avx2")]
        fn avx2(words: &mut [u64], flavor: LkFlavor, seed: u32) {
            lk_lanes64(words, |x| LkHash::apply(flavor, x, seed))
        }
        // SAFETY: AVX2 was detected on this CPU just above.
        return unsafe { avx2(words, flavor, seed) };
    }
    lk_lanes64(words, |x| LkHash::apply(flavor, x, seed))
}

impl Scrambler for LkHash {
    fn name(&self) -> String {
        match self.flavor {
            LkFlavor::Classic => "lk-hash".into(),
            LkFlavor::Improved => "lk-hash-improved".into(),
        }
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    /// Nested (triangular in reversed bits); no law is claimed.
    fn claim(&self) -> Claim {
        Claim::NESTED
    }
    fn supports_width(&self, width: Width) -> bool {
        width == Width::W32
    }
    #[inline]
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        Self::apply(self.flavor, x as u32, self.dim_seed(dim)) as u64
    }
    /// The dimension's seed drawn once, then a vectorizable loop over the words.
    fn scramble_batch(&self, words: &mut [u64], _width: Width, dim: u32) {
        lk_batch64(words, self.flavor, self.dim_seed(dim))
    }
    fn scramble_batch_u32(&self, words: &mut [u32], dim: u32) {
        lk_batch32(words, self.flavor, self.dim_seed(dim))
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for LkHash {
    fn unscramble(&self, y: u64, _width: Width, dim: u32) -> u64 {
        // The hash is a bijection that is triangular in reversed bits: recover input bits from
        // the lowest reversed bit up, each fixed by the bits below it.
        let target = (y as u32).reverse_bits();
        let s = self.dim_seed(dim);
        let h = |v: u32| match self.flavor {
            LkFlavor::Classic => laine_karras(v, s),
            LkFlavor::Improved => improved_lk(v, s),
        };
        let mut v = 0u32;
        for bit in 0..32 {
            let mask = if bit == 31 {
                u32::MAX
            } else {
                (1u32 << (bit + 1)) - 1
            };
            if h(v) & mask != target & mask {
                v |= 1 << bit;
            }
        }
        v.reverse_bits() as u64
    }
}

/// Flips bit k (k = 0 the most significant of `width`) of `x` when `flip(k, prefix)` is 1,
/// prefix being the top k bits of the input: a binary nested scramble given by its flips.
#[inline]
fn apply_bit_flips(x: u64, width: Width, flip: impl Fn(u32, u64) -> u64) -> u64 {
    let w = width.bits();
    let mut y = x;
    for k in 0..w {
        let prefix = if k == 0 { 0 } else { x >> (w - k) };
        y ^= flip(k, prefix) << (w - 1 - k);
    }
    y
}

/// The inverse of [`apply_bit_flips`]: recovers the input bits from the top, each prefix first.
#[inline]
fn invert_bit_flips(y: u64, width: Width, flip: impl Fn(u32, u64) -> u64) -> u64 {
    let w = width.bits();
    let mut x = 0u64;
    for k in 0..w {
        let prefix = if k == 0 { 0 } else { x >> (w - k) };
        x |= (((y >> (w - 1 - k)) & 1) ^ flip(k, prefix)) << (w - 1 - k);
    }
    x
}

/// A per-bit hashed binary Owen scramble: bit k flips iff the low bit of
/// mix64(dim_key ⊕ mix64((k << 58) ⊕ prefix_k)) is set, where prefix_k is the input's top k bits.
#[derive(Debug, Clone)]
pub struct PerBitOwen {
    seed: u64,
}

impl PerBitOwen {
    /// The scrambler with `seed`.
    pub fn new(seed: u64) -> Self {
        PerBitOwen { seed }
    }

    #[inline(always)]
    fn flip(dim_key: u64, k: u32, prefix: u64) -> u64 {
        mix64(dim_key ^ mix64(((k as u64) << 58) ^ prefix)) & 1
    }
}

impl Scrambler for PerBitOwen {
    fn name(&self) -> String {
        "owen-per-bit-hash".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    fn claim(&self) -> Claim {
        Claim::OWEN
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        let key = hash_words(&[self.seed, dim as u64]);
        apply_bit_flips(x, width, |k, prefix| Self::flip(key, k, prefix))
    }
    /// Eight words at a time, bit by bit across the lanes: the 64-bit multiplies vectorize
    /// (AVX-512DQ where the CPU has it), the same bits either way.
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        let key = hash_words(&[self.seed, dim as u64]);
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx512dq") {
            #[target_feature(enable = "avx512f,avx512dq")]
            fn wide(words: &mut [u64], width: Width, key: u64) {
                per_bit_chunks(words, width, key)
            }
            // SAFETY: AVX-512F and DQ were detected on this CPU just above (DQ implies F).
            return unsafe { wide(words, width, key) };
        }
        per_bit_chunks(words, width, key)
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for PerBitOwen {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        let key = hash_words(&[self.seed, dim as u64]);
        invert_bit_flips(y, width, |k, prefix| Self::flip(key, k, prefix))
    }
}

/// Words per chunk of [`per_bit_chunks`]: one 512-bit register of lanes.
const PER_BIT_LANES: usize = 8;

/// The per-bit scramble of `words` with dimension key `key`, [`PER_BIT_LANES`] words at a time
/// (the loop over lanes is innermost, so it vectorizes); the rest one by one.
#[inline(always)]
fn per_bit_chunks(words: &mut [u64], width: Width, key: u64) {
    let w = width.bits();
    let mut chunks = words.chunks_exact_mut(PER_BIT_LANES);
    for chunk in &mut chunks {
        let x: [u64; PER_BIT_LANES] = chunk.try_into().expect("chunks_exact");
        let mut y = x;
        for k in 0..w {
            for l in 0..PER_BIT_LANES {
                // The prefix of k bits (0 for k = 0, without a shift by 64).
                let prefix = (x[l] >> 1) >> (w - 1 - k) >> (k == 0) as u32;
                y[l] ^= PerBitOwen::flip(key, k, prefix) << (w - 1 - k);
            }
        }
        chunk.copy_from_slice(&y);
    }
    for x in chunks.into_remainder() {
        *x = apply_bit_flips(*x, width, |k, prefix| PerBitOwen::flip(key, k, prefix));
    }
}

/// A random digital shift: y = x ⊕ S_dim, with S_dim = hash_words([seed, dim]) (its top W
/// bits for W-bit words). Every node permutation is a uniform translation, but all nodes of a
/// depth share it: the cheapest imitation of Owen scrambling, kept to show that the verify
/// battery tells it apart.
#[derive(Debug, Clone)]
pub struct DigitalShift {
    seed: u64,
}

impl DigitalShift {
    /// The shift with `seed`.
    pub fn new(seed: u64) -> Self {
        DigitalShift { seed }
    }

    #[inline(always)]
    fn shift(&self, width: Width, dim: u32) -> u64 {
        hash_words(&[self.seed, dim as u64]) >> (64 - width.bits())
    }
}

impl Scrambler for DigitalShift {
    fn name(&self) -> String {
        "digital-shift".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    /// Node permutations are uniform translations; they are not independent.
    fn claim(&self) -> Claim {
        Claim::marginal(NodeGroup::Translation)
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        x ^ self.shift(width, dim)
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for DigitalShift {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        y ^ self.shift(width, dim)
    }
}

/// Matoušek's random linear matrix scramble with a digital shift (LMS + shift, the scrambling
/// `scipy.stats.qmc.Sobol` applies): output bit k is x_k ⊕ ⟨L_k, x_0..x_{k−1}⟩ ⊕ s_k, with
/// the strictly lower part of each row L_k and the shift s drawn from `hash_words([seed, dim,
/// k])`. Nested, and every node permutation is a uniform translation, but node flips are affine
/// in the prefix bits: an imitation with exact GF(2) relations by construction.
#[derive(Debug, Clone)]
pub struct LinearMatrixScramble {
    seed: u64,
}

impl LinearMatrixScramble {
    /// The scramble with `seed`.
    pub fn new(seed: u64) -> Self {
        LinearMatrixScramble { seed }
    }

    /// The flip of bit k for a word whose top k bits are `prefix` (right-aligned).
    #[inline]
    fn flip(&self, dim: u32, k: u32, prefix: u64) -> u64 {
        // k < 64: the row uses bits 0..k of the hash, the shift its bit 63 (disjoint).
        let h = hash_words(&[self.seed, dim as u64, k as u64]);
        let row = h & ((1u64 << k) - 1);
        (((row & prefix).count_ones() as u64) ^ (h >> 63)) & 1
    }
}

impl Scrambler for LinearMatrixScramble {
    fn name(&self) -> String {
        "lms-shift".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    /// Node permutations are uniform translations; they are affinely dependent.
    fn claim(&self) -> Claim {
        Claim::marginal(NodeGroup::Translation)
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        apply_bit_flips(x, width, |k, prefix| self.flip(dim, k, prefix))
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for LinearMatrixScramble {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        invert_bit_flips(y, width, |k, prefix| self.flip(dim, k, prefix))
    }
}
