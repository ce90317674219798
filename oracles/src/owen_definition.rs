//! Nested uniform (Owen) scrambling in base 2^q as its definition reads: every node of the
//! tree (depth k, prefix p = the first k input digits) of dimension `dim` has its own
//! permutation σ_{k,p}, a pure function of (seed, dim, k, p), and output digit k is σ_{k,p}
//! applied to input digit k. The node key comes from the path to the node, one hash per node
//! (in base 2 one per tile of six levels, whose 63 node flips are the key's bits), and σ is one
//! draw of the node's law from the key ([`draw`]: one Fisher–Yates shuffle for the uniform
//! law).
//!
//! Written for reading, not speed: no incremental keys, no batches, no shared code with the
//! tuned `gartowen_owen::FullTreeOwen` (`owen-oracle`), which must equal it bit for bit
//! (`oracles/tests/definition.rs`); the keying constants are `docs/design.md` §3.1's.

use gartowen_core::{
    hash_words, mix64, DigitLayout, Gf2Matrix, Permutation, PowerOfTwoBase, SplitMix64, Width,
};
use gartowen_owen::OwenVariant;

/// Base-2 levels per tile key.
const TILE: u32 = 6;

/// A child's key from its parent's key and the value `v` taken (a digit, or a tile's bits).
fn child(key: u64, v: u64) -> u64 {
    mix64(key ^ (v + 1).wrapping_mul(0x9E6C_63D0_676A_9A99))
}

/// The Fisher–Yates swaps (i, j_i), i = n−1 down to 1, j_i uniform in 0..=i, from the node's
/// key. For n ≤ 16 all indices come from one 64-bit word r (the key, or the next word of
/// `SplitMix64::new(key)` while r is rejected): u = ⌊r·n!/2^64⌋ is exactly uniform on 0..n!
/// once the r with (r·n! mod 2^64) < (2^64 mod n!) are rejected, and the j_i are u's
/// mixed-radix digits, j_{n−1} the most significant. Larger n draw each j_i from the stream.
fn fisher_yates_swaps(n: u32, key: u64) -> Vec<(u32, u32)> {
    let mut stream = SplitMix64::new(key);
    if n > 16 {
        return (1..n).rev().map(|i| (i, stream.bounded(i + 1))).collect();
    }
    let factorial = |m: u32| (1..=m as u128).product::<u128>();
    let total = factorial(n);
    let mut r = key as u128;
    while (r * total) % (1 << 64) < (1 << 64) % total {
        r = stream.next_u64() as u128;
    }
    let mut u = (r * total) >> 64;
    (1..n)
        .rev()
        .map(|i| {
            let below = factorial(i); // the weight of digit j_i is i!
            let j = u / below;
            u %= below;
            (i, j as u32)
        })
        .collect()
}

/// One draw of `variant`'s law on 2^`bits` symbols from a node key.
pub fn draw(variant: OwenVariant, bits: u32, key: u64) -> Permutation {
    let n = 1u32 << bits;
    let top = (key >> (64 - bits)) as u32; // the key's top bits: uniform on 0..n
    let images: Vec<u32> = match variant {
        OwenVariant::Uniform => {
            // Shuffle the symbols; the symbol that ends at position `pos` maps to `pos`.
            let mut at: Vec<u32> = (0..n).collect();
            for (i, j) in fisher_yates_swaps(n, key) {
                at.swap(i as usize, j as usize);
            }
            let mut images = vec![0; n as usize];
            for (pos, &symbol) in at.iter().enumerate() {
                images[symbol as usize] = pos as u32;
            }
            images
        }
        OwenVariant::CyclicShift => (0..n).map(|d| (d + top) % n).collect(),
        OwenVariant::Xor => (0..n).map(|d| d ^ top).collect(),
        OwenVariant::Affine => {
            let mut stream = SplitMix64::new(key);
            let a = Gf2Matrix::random_invertible(bits, &mut stream).expect("bits ≤ 8");
            let u = stream.bounded(n);
            (0..n).map(|d| a.apply(d) ^ u).collect()
        }
    };
    let images: Vec<u8> = images.into_iter().map(|d| d as u8).collect();
    Permutation::from_images(&images).expect("a bijection")
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
    draw(variant, layout.digit_bits(k), key)
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
    scramble_with_nodes(x, width, base, |k, p| {
        node(seed, base, variant, width, dim, k, p)
    })
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
