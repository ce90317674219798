//! `FullTreeOwen`: the exact nested scramble in base 2^q, node by node (`DESIGN.md` §3.1).
//!
//! Node (depth k, prefix p = the first k ORIGINAL digits) of dimension `dim` gets a permutation
//! σ_{k,p} of its digit alphabet that is a pure function of (seed, dim, k, p):
//!
//! * `dim_key   = hash_words([seed, dim])`
//! * `level_key = mix64(dim_key + (k+1)·γ)` (output k+1 of the SplitMix64 stream of dim_key)
//! * `node_key  = mix64(level_key ⊕ p·0x9E6C63D0676A9A99)` (injective in p for fixed k)
//! * σ_{k,p} is drawn from `SplitMix64::new(node_key)` with unbiased draws (Lemire):
//!   Uniform: Fisher–Yates over all 2^bits symbols; CyclicShift: d ↦ d + u mod 2^bits;
//!   Xor: d ↦ d ⊕ u; Affine: d ↦ A·d ⊕ u with A uniform in GL(bits, 2), then u.
//!
//! Tail rule: when q does not divide W, the last digit has r = W mod q bits and its node draws a
//! permutation of 2^r symbols by the same rule. Only the nodes a query visits are computed.

use gartowen_core::{
    fisher_yates, hash_words, mix64, DigitLayout, Gf2Matrix, Permutation, PowerOfTwoBase,
    Scrambler, SplitMix64, Width,
};

/// Odd multiplier spreading the prefix before mixing (any odd constant is injective mod 2^64).
const PREFIX_MULTIPLIER: u64 = 0x9E6C_63D0_676A_9A99;

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

    /// Draws one node permutation of 2^bits symbols from `rng`.
    pub fn draw(self, bits: u32, rng: &mut SplitMix64) -> Permutation {
        let n = 1usize << bits;
        match self {
            OwenVariant::Uniform => Permutation::random(n, rng).expect("n ≤ 256"),
            OwenVariant::CyclicShift => {
                let u = rng.bounded(n as u32);
                images(n, |d| (d + u) % n as u32)
            }
            OwenVariant::Xor => {
                let u = rng.bounded(n as u32);
                images(n, |d| d ^ u)
            }
            OwenVariant::Affine => {
                let a = Gf2Matrix::random_invertible(bits, rng).expect("bits ≤ 8");
                let u = rng.bounded(n as u32);
                images(n, |d| a.apply(d) ^ u)
            }
        }
    }
}

impl OwenVariant {
    /// The image (or preimage) of digit `d` under the node map drawn from `rng`: the same draws
    /// as [`OwenVariant::draw`], without building a `Permutation`.
    #[inline]
    pub fn map_digit(self, bits: u32, rng: &mut SplitMix64, d: u32, inverse: bool) -> u32 {
        let n = 1u32 << bits;
        match self {
            OwenVariant::Uniform => match n {
                // Fisher–Yates on 2 symbols is one draw j: swap(1, j) swaps iff j = 0.
                2 => d ^ (rng.bounded(2) == 0) as u32,
                3..=16 => shuffled_image::<16>(n, rng, d, inverse),
                _ => shuffled_image::<256>(n, rng, d, inverse),
            },
            OwenVariant::CyclicShift => {
                let u = rng.bounded(n);
                if inverse {
                    (d + n - u) % n
                } else {
                    (d + u) % n
                }
            }
            OwenVariant::Xor => d ^ rng.bounded(n),
            OwenVariant::Affine => {
                let a = Gf2Matrix::random_invertible(bits, rng).expect("bits ≤ 8");
                let u = rng.bounded(n);
                if inverse {
                    a.inverse().expect("invertible").apply(d ^ u)
                } else {
                    a.apply(d) ^ u
                }
            }
        }
    }
}

/// Image (or preimage) of `d` under a Fisher–Yates shuffle of 0..n on an N-byte stack array.
#[inline]
fn shuffled_image<const N: usize>(n: u32, rng: &mut SplitMix64, d: u32, inverse: bool) -> u32 {
    let mut buf = [0u8; N];
    let items = &mut buf[..n as usize];
    for (i, v) in items.iter_mut().enumerate() {
        *v = i as u8;
    }
    fisher_yates(items, rng);
    if inverse {
        items
            .iter()
            .position(|&v| v as u32 == d)
            .expect("a permutation") as u32
    } else {
        items[d as usize] as u32
    }
}

fn images(n: usize, f: impl Fn(u32) -> u32) -> Permutation {
    let v: Vec<u8> = (0..n as u32).map(|d| f(d) as u8).collect();
    Permutation::from_images(&v).expect("a bijection by construction")
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

    #[inline]
    fn node_key(dim_key: u64, depth: u32, prefix: u64) -> u64 {
        let level_key = mix64(
            dim_key
                .wrapping_add((depth as u64 + 1).wrapping_mul(gartowen_core::hash::GOLDEN_GAMMA)),
        );
        mix64(level_key ^ prefix.wrapping_mul(PREFIX_MULTIPLIER))
    }

    /// σ_{k,p}: the permutation of node (depth `depth`, original prefix `prefix`) of `dim`
    /// for `width`-bit words. Its size is 2^q, or 2^r at the partial tail digit.
    pub fn node_permutation(&self, width: Width, dim: u32, depth: u32, prefix: u64) -> Permutation {
        let layout = DigitLayout::new(width, self.base);
        let bits = layout.digit_bits(depth);
        let mut rng = SplitMix64::new(Self::node_key(self.dim_key(dim), depth, prefix));
        self.variant.draw(bits, &mut rng)
    }

    /// Applies the scramble (or its inverse) digit by digit.
    fn run(&self, x: u64, width: Width, dim: u32, inverse: bool) -> u64 {
        let layout = DigitLayout::new(width, self.base);
        let dim_key = self.dim_key(dim);
        let mut out = 0u64;
        let mut prefix = 0u64;
        for k in 0..layout.num_digits() {
            let bits = layout.digit_bits(k);
            let mut rng = SplitMix64::new(Self::node_key(dim_key, k, prefix));
            let d_in = layout.get(x, k);
            let d_out = self.variant.map_digit(bits, &mut rng, d_in, inverse);
            let (original, mapped) = if inverse {
                (d_out, d_out)
            } else {
                (d_in, d_out)
            };
            out = layout.set(out, k, mapped);
            // Navigate by the ORIGINAL digit (recovered first when inverting).
            prefix = (prefix << bits) | original as u64;
        }
        out
    }

    /// Scrambles a batch in place, caching each visited node's permutation: nodes near the root
    /// are shared by many points, so they are drawn once per batch. The cache holds at most
    /// [`MAX_CACHED_NODES`] nodes (about 17 MB) and starts over when full, so memory does not
    /// grow with the batch (node maps are pure functions: the output does not change).
    pub fn scramble_batch(&self, xs: &mut [u64], width: Width, dim: u32) {
        let layout = DigitLayout::new(width, self.base);
        let dim_key = self.dim_key(dim);
        let mut cache: std::collections::HashMap<(u32, u64), Permutation> =
            std::collections::HashMap::new();
        for x in xs.iter_mut() {
            if cache.len() >= MAX_CACHED_NODES {
                cache.clear();
            }
            let mut out = 0u64;
            let mut prefix = 0u64;
            for k in 0..layout.num_digits() {
                let bits = layout.digit_bits(k);
                let sigma = cache.entry((k, prefix)).or_insert_with(|| {
                    self.variant.draw(
                        bits,
                        &mut SplitMix64::new(Self::node_key(dim_key, k, prefix)),
                    )
                });
                let d = layout.get(*x, k);
                out = layout.set(out, k, sigma.apply(d));
                prefix = (prefix << bits) | d as u64;
            }
            *x = out;
        }
    }
}

/// The most node permutations one [`FullTreeOwen::scramble_batch`] call keeps cached.
pub const MAX_CACHED_NODES: usize = 1 << 16;

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
        self.run(x, width, dim, false)
    }

    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        self.run(y, width, dim, true)
    }

    /// The memoizing batch path (each node drawn once per batch).
    fn scramble_batch(&self, xs: &mut [u64], width: Width, dim: u32) {
        FullTreeOwen::scramble_batch(self, xs, width, dim)
    }
}

/// Applies the nested scramble whose node (depth k, original prefix p) permutation is
/// `node(k, p)`: the plain tree walk, digit by digit, that every fast scrambler must equal when
/// driven by its own node permutations (the explicit-tree bridge).
pub fn scramble_with_nodes(
    x: u64,
    width: Width,
    base: PowerOfTwoBase,
    node: impl Fn(u32, u64) -> Permutation,
) -> u64 {
    let layout = DigitLayout::new(width, base);
    let mut out = 0u64;
    for k in 0..layout.num_digits() {
        let sigma = node(k, layout.prefix(x, k));
        out = layout.set(out, k, sigma.apply(layout.get(x, k)));
    }
    out
}
