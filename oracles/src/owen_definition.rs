//! Nested uniform (Owen) scrambling in base 2^q as its definition reads: every node of the
//! tree (depth k, prefix p = the first k input digits) of dimension `dim` has its own
//! permutation σ_{k,p}, a pure function of (seed, dim, k, p), and output digit k is σ_{k,p}
//! applied to input digit k. The node key comes from the path to the node, one hash per node
//! (in base 2 one per tile of six levels, whose 63 node flips are the key's bits), and σ is one
//! draw from the key ([`crate::node_draw`]: Fisher–Yates for the uniform law).
//!
//! Written for reading, not speed: no incremental keys, no batches. The tuned
//! [`crate::FullTreeOwen`] (`owen-oracle`) must equal it bit for bit
//! (`oracles/tests/definition.rs`); the keying constants are `docs/design.md` §3.1's.

use crate::node_draw::node_permutation;
use crate::OwenVariant;
use gartowen_core::{hash_words, mix64, DigitLayout, Permutation, PowerOfTwoBase, Width};

/// Base-2 levels per tile key.
const TILE: u32 = 6;

/// A child's key from its parent's key and the value `v` taken (a digit, or a tile's bits).
fn child(key: u64, v: u64) -> u64 {
    mix64(key ^ (v + 1).wrapping_mul(0x9E6C_63D0_676A_9A99))
}

/// σ_{k,p} of dimension `dim` under `seed`: the permutation of node (depth `k`, prefix `p`:
/// the first k digits of the input word, as an integer).
pub fn node(
    seed: u64,
    base: PowerOfTwoBase,
    variant: OwenVariant,
    width: Width,
    dim: u32,
    k: u32,
    p: u64,
) -> Permutation {
    let layout = DigitLayout::new(width, base);
    let mut key = mix64(hash_words(&[seed, dim as u64]) ^ 0x726f_6f74_6f77_656e); // the root
    if base.q() == 1 {
        // Tiles above the node, each keyed by its parent tile and its six input bits.
        for t in 0..k / TILE {
            key = child(key, (p >> (k - TILE * (t + 1))) & 63);
        }
        let (level, inside) = (k % TILE, p & ((1 << (k % TILE)) - 1));
        let flip = ((key >> ((1 << level) - 1 + inside)) & 1) as u8;
        return Permutation::from_images(&[flip, 1 - flip]).expect("a bijection");
    }
    // Digits of p, most significant first: each one steps the key to the child it names.
    let bits_below = |j: u32| (j + 1..k).map(|i| layout.digit_bits(i)).sum::<u32>();
    for j in 0..k {
        key = child(
            key,
            (p >> bits_below(j)) & ((1 << layout.digit_bits(j)) - 1),
        );
    }
    node_permutation(variant, layout.digit_bits(k), key)
}

/// The scramble of the `width`-bit word `x` in dimension `dim`: digit k through σ_{k,p(x)}.
pub fn scramble(
    seed: u64,
    base: PowerOfTwoBase,
    variant: OwenVariant,
    x: u64,
    width: Width,
    dim: u32,
) -> u64 {
    let layout = DigitLayout::new(width, base);
    (0..layout.num_digits()).fold(0, |out, k| {
        let sigma = node(seed, base, variant, width, dim, k, layout.prefix(x, k));
        layout.set(out, k, sigma.apply(layout.get(x, k)))
    })
}
