//! `FullTreeOwen`: the exact nested scramble in base 2^q, node by node (`docs/design.md` §3.1).
//!
//! Node (depth k, prefix p = the first k ORIGINAL digits) of dimension `dim` gets a permutation
//! σ_{k,p} of its digit alphabet that is a pure function of (seed, dim, k, p), computed only
//! for the nodes a query visits. Keys are derived incrementally along the path, one mix per
//! node (one per six levels in base 2), and each node draws only what it needs:
//!
//! * `dim_key = hash_words([seed, dim])`, root key `K_root = mix64(dim_key ⊕ ROOT_TWEAK)`.
//! * A child's key from its parent's: `child(K, v) = mix64(K ⊕ (v + 1)·CHILD_MULTIPLIER)`,
//!   v the digit taken. The multiplier is odd, so siblings always get distinct keys.
//! * **Bases 4 … 256** (and every tail digit): node keys follow the digits, `K_{k+1} =
//!   child(K_k, x_k)`, and σ is drawn from `K` by [`crate::node_draw`]: Uniform is
//!   Fisher–Yates with Lemire-unbiased indices (all indices from one word while 2^q ≤ 16, one
//!   word each above), CyclicShift and Xor take u from the key's top bits, Affine draws A
//!   uniform in GL(q,2) and u from the key's stream.
//! * **Base 2** (a node is one uniform bit, and all four laws coincide on S_2): the tree is
//!   cut into tiles of [`TILE_LEVELS`] = 6 levels, and one key T per tile supplies the flips
//!   of its 2^6 − 1 = 63 nodes: the node at level j of the tile with in-tile prefix p (j bits)
//!   flips iff bit 2^j − 1 + p of T is set. Distinct nodes of a tile read distinct bits, so
//!   the flips are independent and uniform as bits of one hash output. The next tile's key is
//!   `child(T, P)`, P the tile's six input bits.
//!
//! Tail rule: when q does not divide W, the last digit has r = W mod q bits and its node draws
//! a permutation of 2^r symbols by the same rules. [`Scrambler::scramble_f32`] and
//! [`Scrambler::scramble_f64`] compute only the digits their output keeps (the top 24 or 53
//! bits): for a nested scramble the other digits cannot change those bits.
//!
//! The keying is frozen by the golden vectors in `crates/owen/tests/golden.rs`, and
//! `gartowen_oracles::owen_definition` writes it out as the definition reads.

use crate::node_draw::{node_image, node_permutation};
use gartowen_core::Unscramble;
use gartowen_core::{
    hash_words, mix64, word_to_f32, word_to_f64, DigitLayout, Permutation, PowerOfTwoBase,
    Scrambler, SplitMix64, Width,
};

/// Odd multiplier spreading a child's digit before mixing (any odd constant is injective
/// mod 2^64).
const CHILD_MULTIPLIER: u64 = 0x9E6C_63D0_676A_9A99;
/// Tweak separating the root key from the dimension key.
const ROOT_TWEAK: u64 = 0x726f_6f74_6f77_656e; // "rootowen"
/// Words walked together by the batch path.
const LANES: usize = 4;

/// Evaluates `$body` with `$image` bound to the forward node map of `$s` (bits, key, digit) →
/// image, chosen once per call: Uniform in bases 4, 8 and 16 takes the constant-size draw of
/// [`crate::node_draw`], every other case (and tail digits) the general one.
macro_rules! with_forward_image {
    ($s:expr, $image:ident => $body:expr) => {{
        use crate::node_draw::uniform_image_small;
        let variant = $s.variant;
        let general = move |bits: u32, key: u64, d: u32| node_image(variant, bits, key, d, false);
        match (variant, $s.base.q()) {
            (OwenVariant::Uniform, 2) => {
                let $image = move |bits: u32, key: u64, d: u32| {
                    if bits == 2 {
                        uniform_image_small::<4>(key, d)
                    } else {
                        general(bits, key, d)
                    }
                };
                $body
            }
            (OwenVariant::Uniform, 3) => {
                let $image = move |bits: u32, key: u64, d: u32| {
                    if bits == 3 {
                        uniform_image_small::<8>(key, d)
                    } else {
                        general(bits, key, d)
                    }
                };
                $body
            }
            (OwenVariant::Uniform, 4) => {
                let $image = move |bits: u32, key: u64, d: u32| {
                    if bits == 4 {
                        uniform_image_small::<16>(key, d)
                    } else {
                        general(bits, key, d)
                    }
                };
                $body
            }
            _ => {
                let $image = general;
                $body
            }
        }
    }};
}

/// Levels of a base-2 tile: 2^6 − 1 = 63 node flips from one 64-bit key.
pub const TILE_LEVELS: u32 = 6;

/// The root key of a dimension.
#[inline(always)]
fn root_key(dim_key: u64) -> u64 {
    mix64(dim_key ^ ROOT_TWEAK)
}

/// The key of the child reached by value `v` (a digit, or a tile's input bits) from `key`.
#[inline(always)]
fn child_key(key: u64, v: u64) -> u64 {
    mix64(key ^ (v + 1).wrapping_mul(CHILD_MULTIPLIER))
}

/// The flip of the node at level `level` (0..TILE_LEVELS) of a tile with key `tile`, reached by
/// the in-tile prefix `p` (`level` bits).
#[inline(always)]
fn tile_flip(tile: u64, level: u32, p: u64) -> u64 {
    (tile >> ((1u64 << level) - 1 + p)) & 1
}

/// Which family the node permutations are drawn from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum OwenVariant {
    /// Uniform over all of S_b: nested uniform (Owen) scrambling.
    Uniform,
    /// d ↦ d + u mod b, u uniform.
    CyclicShift,
    /// d ↦ d ⊕ u, u uniform: a nested random digital shift.
    Xor,
    /// d ↦ A·d ⊕ u, A uniform in GL(q,2), u uniform.
    Affine,
}

impl OwenVariant {
    /// Every variant.
    pub const ALL: [OwenVariant; 4] = [
        OwenVariant::Uniform,
        OwenVariant::CyclicShift,
        OwenVariant::Xor,
        OwenVariant::Affine,
    ];

    /// The option word naming the variant (`owen-oracle:NAME`).
    pub fn name(self) -> &'static str {
        match self {
            OwenVariant::Uniform => "uniform",
            OwenVariant::CyclicShift => "cyclic",
            OwenVariant::Xor => "xor",
            OwenVariant::Affine => "affine",
        }
    }

    /// Draws one node permutation of 2^bits symbols from `rng` (a key drawn from the stream
    /// keys the node, as in the oracle).
    pub fn draw(self, bits: u32, rng: &mut SplitMix64) -> Permutation {
        node_permutation(self, bits, rng.next_u64())
    }
}

/// The exact full-tree Owen scramble in base 2^q with one of the [`OwenVariant`] laws.
#[derive(Debug, Clone)]
pub struct FullTreeOwen {
    seed: u64,
    base: PowerOfTwoBase,
    variant: OwenVariant,
}

impl FullTreeOwen {
    /// The scramble with `seed`, in `base`, drawing node permutations from `variant`.
    pub fn new(base: PowerOfTwoBase, variant: OwenVariant, seed: u64) -> Self {
        FullTreeOwen {
            seed,
            base,
            variant,
        }
    }

    /// The variant.
    pub fn variant(&self) -> OwenVariant {
        self.variant
    }

    /// The seed-and-dimension key every node key of `dim` derives from.
    #[inline]
    fn dim_key(&self, dim: u32) -> u64 {
        hash_words(&[self.seed, dim as u64])
    }

    /// σ_{k,p}: the permutation of node (depth `depth`, original prefix `prefix`) of `dim`
    /// for `width`-bit words. Its size is 2^q, or 2^r at the partial tail digit.
    pub fn node_permutation(&self, width: Width, dim: u32, depth: u32, prefix: u64) -> Permutation {
        let layout = DigitLayout::new(width, self.base);
        let mut key = root_key(self.dim_key(dim));
        if self.base.q() == 1 {
            // Walk the tiles above the node, then read its bit of its tile's key.
            let whole = depth / TILE_LEVELS;
            for t in 0..whole {
                let tile_bits = (prefix >> (depth - TILE_LEVELS * (t + 1))) & 63;
                key = child_key(key, tile_bits);
            }
            let level = depth % TILE_LEVELS;
            let p = prefix & ((1u64 << level) - 1);
            let flip = tile_flip(key, level, p) as u8;
            return Permutation::from_images(&[flip, 1 - flip]).expect("a bijection");
        }
        for k in 0..depth {
            let shift: u32 = (k + 1..depth).map(|j| layout.digit_bits(j)).sum();
            let d = (prefix >> shift) & ((1u64 << layout.digit_bits(k)) - 1);
            key = child_key(key, d);
        }
        node_permutation(self.variant, layout.digit_bits(depth), key)
    }

    /// Applies the scramble (or its inverse) to the first `digits` digits of `x` (the others
    /// are left 0).
    fn run(&self, x: u64, width: Width, dim: u32, inverse: bool, digits: u32) -> u64 {
        let key = root_key(self.dim_key(dim));
        let w = width.bits();
        if self.base.q() == 1 {
            return binary_run(x, w, key, digits);
        }
        if inverse {
            let variant = self.variant;
            return self.walk(x, w, key, digits, true, |bits, key, d| {
                node_image(variant, bits, key, d, true)
            });
        }
        self.forward(x, w, key, digits)
    }

    /// The forward walk with the node draw chosen once (see [`with_forward_image`]).
    #[inline]
    fn forward(&self, x: u64, w: u32, key: u64, digits: u32) -> u64 {
        with_forward_image!(self, image => self.walk(x, w, key, digits, false, image))
    }

    /// The forward scramble of `LANES` words at a time (all digits), each word as
    /// [`Self::forward`]: the lanes' node draws are independent, so they overlap in the core.
    fn forward_batch(&self, xs: &mut [u64], w: u32, root: u64) {
        with_forward_image!(self, image => {
            let mut chunks = xs.chunks_exact_mut(LANES);
            for chunk in &mut chunks {
                let chunk: &mut [u64; LANES] = chunk.try_into().expect("chunks_exact");
                *chunk = self.walk_lanes(*chunk, w, root, image);
            }
            for x in chunks.into_remainder() {
                *x = self.walk(*x, w, root, w.div_ceil(self.base.q()), false, image);
            }
        })
    }

    /// [`Self::walk`] forward over all digits of [`LANES`] words in lock step.
    #[inline(always)]
    fn walk_lanes(
        &self,
        x: [u64; LANES],
        w: u32,
        root: u64,
        image: impl Fn(u32, u64, u32) -> u32,
    ) -> [u64; LANES] {
        let q = self.base.q();
        let mut rest = x.map(|v| v << (64 - w));
        let mut key = [root; LANES];
        let mut out = [0u64; LANES];
        let mut left = w;
        while left > 0 {
            let bits = q.min(left);
            left -= bits;
            for l in 0..LANES {
                let d = (rest[l] >> (64 - bits)) as u32;
                rest[l] <<= bits;
                out[l] = (out[l] << bits) | image(bits, key[l], d) as u64;
                key[l] = child_key(key[l], d as u64);
            }
        }
        out
    }

    /// The tree walk over the first `digits` digits of the `w`-bit word `x` from `key`: digit
    /// k is mapped by `image(bits, node key, digit)`, and the next node's key follows the
    /// ORIGINAL digit (the mapped one when inverting). Digits are read from the top of the
    /// left-aligned word.
    #[inline(always)]
    fn walk(
        &self,
        x: u64,
        w: u32,
        mut key: u64,
        digits: u32,
        inverse: bool,
        image: impl Fn(u32, u64, u32) -> u32,
    ) -> u64 {
        let q = self.base.q();
        let mut rest = x << (64 - w);
        let mut left = w;
        let mut out = 0u64;
        for _ in 0..digits {
            let bits = q.min(left);
            let d = (rest >> (64 - bits)) as u32;
            rest <<= bits;
            left -= bits;
            let y = image(bits, key, d);
            out = (out << bits) | y as u64;
            key = child_key(key, if inverse { y } else { d } as u64);
        }
        // `left` < 64 unless no digit was asked for (then the word is 0).
        out.checked_shl(left).unwrap_or(0)
    }

    /// How many leading digits decide the top `bits` bits of a word.
    fn digits_for_bits(&self, width: Width, bits: u32) -> u32 {
        let layout = DigitLayout::new(width, self.base);
        layout.num_digits().min(bits.div_ceil(self.base.q()))
    }
}

/// The base-2 scramble of the top `digits` bits of the `w`-bit word `x` (the rest left 0) from
/// the root tile key: six levels per key. Its own inverse needs no care: a flip depends only
/// on the input bits above it, which the inverse has recovered by then, so `unscramble` runs
/// the same loop on the recovered bits.
#[inline]
fn binary_run(x: u64, w: u32, root: u64, digits: u32) -> u64 {
    let mut key = root;
    let mut out = 0u64;
    let mut k = 0;
    while k < digits {
        let levels = TILE_LEVELS.min(digits - k);
        // The tile's input bits, most significant first.
        let tile_bits = (x >> (w - k - levels)) & ((1u64 << levels) - 1);
        let mut flips = 0u64;
        for level in 0..levels {
            let p = tile_bits >> (levels - level);
            flips = (flips << 1) | tile_flip(key, level, p);
        }
        out |= (tile_bits ^ flips) << (w - k - levels);
        k += levels;
        if k < digits {
            key = child_key(key, tile_bits);
        }
    }
    out
}

/// The inverse of [`binary_run`] on all `w` bits: each tile's input bits are recovered level
/// by level (a flip reads only the bits above it), then the tile key advances.
#[inline]
fn binary_unrun(y: u64, w: u32, root: u64) -> u64 {
    let mut key = root;
    let mut x = 0u64;
    let mut k = 0;
    while k < w {
        let levels = TILE_LEVELS.min(w - k);
        let out_bits = (y >> (w - k - levels)) & ((1u64 << levels) - 1);
        let mut tile_bits = 0u64;
        for level in 0..levels {
            let flip = tile_flip(key, level, tile_bits);
            let y_bit = (out_bits >> (levels - 1 - level)) & 1;
            tile_bits = (tile_bits << 1) | (y_bit ^ flip);
        }
        x |= tile_bits << (w - k - levels);
        k += levels;
        if k < w {
            key = child_key(key, tile_bits);
        }
    }
    x
}

impl Scrambler for FullTreeOwen {
    fn name(&self) -> String {
        format!(
            "owen-oracle:{}:base={}",
            self.variant.name(),
            self.base.base()
        )
    }

    fn base(&self) -> PowerOfTwoBase {
        self.base
    }

    /// Independent node permutations, uniform over the variant's group.
    fn claim(&self) -> gartowen_core::Claim {
        use gartowen_core::NodeGroup;
        gartowen_core::Claim::independent_over(match self.variant {
            OwenVariant::Uniform => NodeGroup::Symmetric,
            OwenVariant::CyclicShift => NodeGroup::Cyclic,
            OwenVariant::Xor => NodeGroup::Translation,
            OwenVariant::Affine => NodeGroup::Affine,
        })
    }

    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        let digits = DigitLayout::new(width, self.base).num_digits();
        self.run(x, width, dim, false, digits)
    }

    /// The dimension key hashed once per batch, then each word as [`Scrambler::scramble`].
    fn scramble_batch(&self, xs: &mut [u64], width: Width, dim: u32) {
        let root = root_key(self.dim_key(dim));
        let w = width.bits();
        if self.base.q() == 1 {
            for x in xs.iter_mut() {
                *x = binary_run(*x, w, root, w);
            }
            return;
        }
        self.forward_batch(xs, w, root);
    }

    /// Only the digits inside the top 24 bits are scrambled: the others cannot reach them.
    fn scramble_f32(&self, x: u64, width: Width, dim: u32) -> f32 {
        let digits = self.digits_for_bits(width, 24);
        word_to_f32(self.run(x, width, dim, false, digits), width)
    }

    /// Only the digits inside the top 53 bits are scrambled: the others cannot reach them.
    fn scramble_f64(&self, x: u64, width: Width, dim: u32) -> f64 {
        let digits = self.digits_for_bits(width, 53);
        word_to_f64(self.run(x, width, dim, false, digits), width)
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for FullTreeOwen {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        if self.base.q() == 1 {
            return binary_unrun(y, width.bits(), root_key(self.dim_key(dim)));
        }
        let digits = DigitLayout::new(width, self.base).num_digits();
        self.run(y, width, dim, true, digits)
    }
}
