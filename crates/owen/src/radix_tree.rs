//! `RadixOwen`: the exact full-tree nested scramble in a base b that is not a power of two
//! (3, 5, 6, 7, …), words being integers of m base-b digits ([`RadixLayout`]).
//!
//! Node (depth k, prefix = the first k ORIGINAL digits) of dimension `dim` has a key that is a
//! pure function of (seed, b, dim, k, prefix): `K_0 = mix64(hash_words([seed, dim, b]) ⊕ TWEAK)`
//! and `K_{k+1} = mix64(K_k ⊕ (x_k + 1)·M)` with an odd M, so siblings get distinct keys. Its
//! permutation is drawn from a SplitMix64 stream seeded by the key:
//!
//! * [`RadixVariant::Uniform`]: Fisher–Yates with Lemire-unbiased indices, uniform over S_b
//!   and independent across nodes: Owen's nested uniform scramble;
//! * [`RadixVariant::Cyclic`]: d ↦ d + u mod b, u uniform: independent random shifts (a nested
//!   scramble uniform over Z_b only);
//! * [`RadixVariant::PerDepth`]: one uniform permutation per (dimension, depth), shared by
//!   every node of the depth (the key ignores the prefix): each node is uniform over S_b, but
//!   nodes are not independent; the random digit permutation of scrambled Halton.
//!
//! Permutations of up to 256 digits are drawn on the stack; larger bases allocate one buffer
//! per call.

use gartowen_core::{
    hash_words, mix64, Claim, NodeGroup, Radix, RadixLayout, RadixScrambler, SplitMix64, Width,
};

/// Odd multiplier spreading a child's digit before mixing.
const CHILD_MULTIPLIER: u64 = 0xD6E8_FEB8_6659_FD93;
/// Tweak separating the root key from the dimension key.
const ROOT_TWEAK: u64 = 0x7261_6469_786f_776e; // "radixown"
/// Largest base whose permutations are drawn in a stack buffer.
const STACK_DIGITS: usize = 256;

/// Which law the node permutations follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RadixVariant {
    /// Independent, uniform over S_b (Owen).
    Uniform,
    /// Independent uniform cyclic shifts d ↦ d + u mod b.
    Cyclic,
    /// One uniform permutation per depth and dimension, shared by the depth's nodes.
    PerDepth,
}

impl RadixVariant {
    /// Every variant.
    pub const ALL: [RadixVariant; 3] = [
        RadixVariant::Uniform,
        RadixVariant::Cyclic,
        RadixVariant::PerDepth,
    ];

    /// The option name (`uniform`, `cyclic`, `per-depth`).
    pub fn name(self) -> &'static str {
        match self {
            RadixVariant::Uniform => "uniform",
            RadixVariant::Cyclic => "cyclic",
            RadixVariant::PerDepth => "per-depth",
        }
    }

    /// What the variant promises: Owen, independent cyclic shifts, or marginal S_b only.
    pub fn claim(self) -> Claim {
        match self {
            RadixVariant::Uniform => Claim::OWEN,
            RadixVariant::Cyclic => Claim::independent_over(NodeGroup::Cyclic),
            RadixVariant::PerDepth => Claim::marginal(NodeGroup::Symmetric),
        }
    }
}

/// The full-tree nested scramble in base b with one seed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RadixOwen {
    radix: Radix,
    variant: RadixVariant,
    seed: u64,
}

impl RadixOwen {
    /// The scramble of base `radix`, law `variant`, seed `seed`.
    pub fn new(radix: Radix, variant: RadixVariant, seed: u64) -> RadixOwen {
        RadixOwen {
            radix,
            variant,
            seed,
        }
    }

    /// The variant.
    pub fn variant(&self) -> RadixVariant {
        self.variant
    }

    fn root_key(&self, dim: u32) -> u64 {
        mix64(hash_words(&[self.seed, dim as u64, self.radix.get() as u64]) ^ ROOT_TWEAK)
    }

    /// The key of the node below `key` reached by digit `x_k` at depth `k` (the per-depth
    /// variant's keys depend on the depth only).
    fn next_key(&self, key: u64, x_k: u32) -> u64 {
        let v = match self.variant {
            RadixVariant::PerDepth => 0,
            _ => x_k as u64,
        };
        mix64(key ^ (v + 1).wrapping_mul(CHILD_MULTIPLIER))
    }

    /// Runs `f` on the node permutation of `key` (images of 0..b) for the uniform variants.
    fn with_permutation<T>(&self, key: u64, f: impl FnOnce(&[u16]) -> T) -> T {
        let b = self.radix.get() as usize;
        let mut stack = [0u16; STACK_DIGITS];
        let mut heap = Vec::new();
        let perm: &mut [u16] = if b <= STACK_DIGITS {
            &mut stack[..b]
        } else {
            heap.resize(b, 0);
            &mut heap
        };
        for (i, p) in perm.iter_mut().enumerate() {
            *p = i as u16;
        }
        let mut rng = SplitMix64::new(key);
        for i in (1..b).rev() {
            let j = rng.bounded(i as u32 + 1) as usize;
            perm.swap(i, j);
        }
        f(perm)
    }

    /// The image of digit `d` at the node of `key`.
    fn image(&self, key: u64, d: u32) -> u32 {
        match self.variant {
            RadixVariant::Cyclic => {
                let b = self.radix.get();
                (d + SplitMix64::new(key).bounded(b)) % b
            }
            _ => self.with_permutation(key, |p| p[d as usize] as u32),
        }
    }

    /// The digit whose image at the node of `key` is `y`.
    fn preimage(&self, key: u64, y: u32) -> u32 {
        match self.variant {
            RadixVariant::Cyclic => {
                let b = self.radix.get();
                (y + b - SplitMix64::new(key).bounded(b)) % b
            }
            _ => self.with_permutation(key, |p| {
                p.iter()
                    .position(|&v| v as u32 == y)
                    .expect("a permutation") as u32
            }),
        }
    }

    fn layout(&self, width: Width) -> RadixLayout {
        RadixLayout::new(width, self.radix).expect("the width holds a digit of the base")
    }
}

impl RadixScrambler for RadixOwen {
    fn name(&self) -> String {
        match self.variant {
            RadixVariant::Uniform => format!("owen-oracle:base={}", self.radix.get()),
            v => format!("owen-oracle:{}:base={}", v.name(), self.radix.get()),
        }
    }

    fn radix(&self) -> Radix {
        self.radix
    }

    fn claim(&self) -> Claim {
        self.variant.claim()
    }

    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        let layout = self.layout(width);
        let mut key = self.root_key(dim);
        let mut y = 0u64;
        for k in 0..layout.num_digits() {
            let d = layout.get(x, k);
            y = y * self.radix.get() as u64 + self.image(key, d) as u64;
            key = self.next_key(key, d);
        }
        y
    }

    fn unscramble(&self, y: u64, width: Width, dim: u32) -> Option<u64> {
        let layout = self.layout(width);
        let mut key = self.root_key(dim);
        let mut x = 0u64;
        for k in 0..layout.num_digits() {
            let d = self.preimage(key, layout.get(y, k));
            x = x * self.radix.get() as u64 + d as u64;
            key = self.next_key(key, d);
        }
        Some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn radix(b: u64) -> Radix {
        Radix::new(b).unwrap()
    }

    #[test]
    fn every_variant_is_a_nested_bijection_on_every_small_word() {
        for b in [3u64, 5, 6] {
            let width = Width::new(10).unwrap();
            let layout = RadixLayout::new(width, radix(b)).unwrap();
            for v in RadixVariant::ALL {
                let s = RadixOwen::new(radix(b), v, 7);
                let n = layout.capacity();
                let ys: Vec<u64> = (0..n).map(|x| s.scramble(x, width, 2)).collect();
                let mut sorted = ys.clone();
                sorted.sort_unstable();
                assert_eq!(sorted, (0..n).collect::<Vec<_>>(), "{v:?} base {b}");
                for x in 0..n {
                    assert_eq!(s.unscramble(ys[x as usize], width, 2), Some(x));
                    // Nested: output digits 0..=k depend on input digits 0..=k only.
                    for k in 0..layout.num_digits() {
                        let other = layout.set(x, k, (layout.get(x, k) + 1) % b as u32);
                        let yo = ys[other as usize];
                        for j in 0..k {
                            assert_eq!(layout.get(yo, j), layout.get(ys[x as usize], j));
                        }
                        assert_ne!(layout.get(yo, k), layout.get(ys[x as usize], k));
                    }
                }
            }
        }
    }

    #[test]
    fn per_depth_shares_one_permutation_and_uniform_does_not() {
        let width = Width::W32;
        let layout = RadixLayout::new(width, radix(7)).unwrap();
        let image_at = |s: &RadixOwen, prefix: u32, d: u32| {
            let x = layout.set(layout.set(0, 0, prefix), 1, d);
            layout.get(s.scramble(x, width, 0), 1)
        };
        let shared = RadixOwen::new(radix(7), RadixVariant::PerDepth, 3);
        let owen = RadixOwen::new(radix(7), RadixVariant::Uniform, 3);
        let images = |s: &RadixOwen, p: u32| (0..7).map(|d| image_at(s, p, d)).collect::<Vec<_>>();
        assert!((1..7).all(|p| images(&shared, p) == images(&shared, 0)));
        assert!((1..7).any(|p| images(&owen, p) != images(&owen, 0)));
        // Cyclic nodes are shifts.
        let cyclic = RadixOwen::new(radix(7), RadixVariant::Cyclic, 3);
        for p in 0..7 {
            let im = images(&cyclic, p);
            assert!(NodeGroup::Cyclic.contains(&im), "{im:?}");
        }
    }

    #[test]
    fn root_permutations_are_uniform_over_s3_across_seeds() {
        // 6 cells, 6000 seeds: chi-square with 5 dof; 20.5 is its 0.999 quantile.
        let width = Width::W32;
        let layout = RadixLayout::new(width, radix(3)).unwrap();
        let mut counts = [0u64; 6];
        for seed in 0..6000 {
            let s = RadixOwen::new(radix(3), RadixVariant::Uniform, seed);
            let im: Vec<u32> = (0..3)
                .map(|d| layout.get(s.scramble(layout.set(0, 0, d), width, 0), 0))
                .collect();
            counts[(im[0] * 2 + (im[1] > im[2]) as u32) as usize] += 1;
        }
        let chi: f64 = counts
            .iter()
            .map(|&c| (c as f64 - 1000.0).powi(2) / 1000.0)
            .sum();
        assert!(chi < 20.5, "{counts:?}");
    }

    #[test]
    fn names_and_claims_follow_the_variant_and_large_bases_work() {
        let s = RadixOwen::new(radix(3), RadixVariant::Uniform, 1);
        assert_eq!(
            (s.name(), s.claim()),
            ("owen-oracle:base=3".into(), Claim::OWEN)
        );
        let c = RadixOwen::new(radix(5), RadixVariant::Cyclic, 1);
        assert_eq!(c.name(), "owen-oracle:cyclic:base=5");
        assert_eq!(c.claim().to_string(), "independent:cyclic");
        let p = RadixOwen::new(radix(5), RadixVariant::PerDepth, 1);
        assert_eq!(p.claim().to_string(), "marginal:symmetric");
        // A base above the stack buffer: 1000 words of base 1000 (2 digits in 20 bits).
        let big = RadixOwen::new(radix(1000), RadixVariant::Uniform, 9);
        let width = Width::new(20).unwrap();
        let mut ys: Vec<u64> = (0..1000)
            .map(|x| big.scramble(x * 1000, width, 0) / 1000)
            .collect();
        ys.sort_unstable();
        assert_eq!(ys, (0..1000).collect::<Vec<_>>());
        assert_eq!(
            big.unscramble(big.scramble(123_456, width, 1), width, 1),
            Some(123_456)
        );
    }
}

#[cfg(test)]
mod golden {
    use super::*;

    /// Scrambles of fixed words, per variant and base: they freeze the keying, so a change of
    /// any node key (seed, dimension, depth or digit) shows here.
    fn outputs(b: u64, v: RadixVariant) -> Vec<u64> {
        let s = RadixOwen::new(Radix::new(b).unwrap(), v, 0x5EED);
        let n = RadixLayout::new(Width::W32, Radix::new(b).unwrap())
            .unwrap()
            .capacity();
        [0, 1, n / 3, n / 2, n - 1]
            .iter()
            .flat_map(|&x| [s.scramble(x, Width::W32, 0), s.scramble(x, Width::W32, 5)])
            .collect()
    }

    #[test]
    fn scrambles_of_fixed_words_are_frozen() {
        let want: [(u64, RadixVariant, [u64; 10]); 6] = [
            (
                3,
                RadixVariant::Uniform,
                [
                    0x9bca9cb7, 0x23f58860, 0x9bca9cb9, 0x23f5885f, 0x44b582b7, 0x7667aae7,
                    0x1c8e6cf5, 0x725fe4ab, 0x56d41145, 0x8c9a47b2,
                ],
            ),
            (
                3,
                RadixVariant::Cyclic,
                [
                    0x69c2363e, 0x9b35eb13, 0x69c2363f, 0x9b35eb14, 0x8b4bd4da, 0xdca5062,
                    0xb82aaa1c, 0x21d79cef, 0x3bee0dfd, 0x890cb499,
                ],
            ),
            (
                3,
                RadixVariant::PerDepth,
                [
                    0x9bca9cb7, 0x23f58860, 0x9bca9cb9, 0x23f5885f, 0x113d3501, 0x693c3c3b,
                    0x32315663, 0x7892b5e5, 0x69c2363e, 0x9b35eb13,
                ],
            ),
            (
                5,
                RadixVariant::Uniform,
                [
                    0x3795c300, 0x1e32fad6, 0x3795c2fe, 0x1e32fad5, 0xf26f9d9, 0x383f7111,
                    0x40eca8b5, 0x407b7b8d, 0x27638978, 0x176402ca,
                ],
            ),
            (
                5,
                RadixVariant::Cyclic,
                [
                    0x1e24f480, 0x12bcbd75, 0x1e24f481, 0x12bcbd76, 0x2d7c52fc, 0x2aef06c2,
                    0x4282f67d, 0x31adde3c, 0x1532f8cd, 0x8b2a8e8,
                ],
            ),
            (
                5,
                RadixVariant::PerDepth,
                [
                    0x3795c300, 0x1e32fad6, 0x3795c2fe, 0x1e32fad5, 0x19ae9333, 0x33ee1c47,
                    0x41ecccf1, 0x462954ec, 0x1e24f480, 0x12bcbd75,
                ],
            ),
        ];
        for (b, v, words) in want {
            assert_eq!(outputs(b, v), words, "base {b} {v:?}");
        }
    }
}
