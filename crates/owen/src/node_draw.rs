//! One node's permutation from its 64-bit key, drawing only what the node needs.
//!
//! **Uniform over S_n for n ≤ 16 from one word.** Fisher–Yates on n symbols takes one index
//! j_i uniform in 0..=i for i = n−1 down to 1: a uniform point of a product space of
//! N = n! outcomes (16! < 2^45). Lemire's method draws it from one 64-bit word r without
//! bias: with m = r·N, r is rejected (and the next word of the node's stream taken) when
//! m mod 2^64 < 2^64 mod N, which leaves u = ⌊m / 2^64⌋ exactly uniform on 0..N. The indices
//! are u's mixed-radix digits, read off r by multiplying: j_{n−1} = ⌊r·n / 2^64⌋, then r ← r·n
//! mod 2^64 and the next radix n−1, and so on. (Induction: r·N = j·2^64·(n−1)! + r'·(n−1)!,
//! so u = j·(n−1)! + ⌊r'·(n−1)! / 2^64⌋ with the second term below (n−1)!.) Rejection happens
//! with probability below N / 2^64 ≤ 1.2·10^-6, so a node costs one word and n−1 multiplies
//! instead of n−1 words. [`mixed_radix_draw`] is generic in the word size so that tests
//! enumerate every word of a small size and count each outcome.
//!
//! **Larger alphabets** (n = 32 … 256) draw each index with [`SplitMix64::bounded`] from the
//! node's stream, as Fisher–Yates always did.
//!
//! **One image without the array.** The node permutation is σ(d) = the position where the
//! symbol starting at position d ends after the swaps (i, j_i): following one symbol through
//! the swaps in draw order needs no array, so a query costs the draws and n−1 compares.
//! The inverse (needed only by `unscramble`) replays the swaps on an array.

use gartowen_core::{Gf2Matrix, Permutation, SplitMix64};

use crate::OwenVariant;

/// The largest alphabet whose Fisher–Yates indices come from one 64-bit word (16! < 2^64).
pub const ONE_WORD_SYMBOLS: u32 = 16;

/// n! for n ≤ 16.
const fn factorial(n: u32) -> u64 {
    let mut f = 1u64;
    let mut i = 2;
    while i <= n {
        f *= i as u64;
        i += 1;
    }
    f
}

/// n! for n ≤ 16, as a table (the draw reads it once per node).
const FACTORIALS: [u64; 17] = {
    let mut t = [0u64; 17];
    let mut n = 0;
    while n <= 16 {
        t[n] = factorial(n as u32);
        n += 1;
    }
    t
};

/// 2^64 mod n! for n ≤ 16: the rejection thresholds of 64-bit product draws, computed at
/// compile time (a 128-bit remainder per node would cost more than the draw).
const THRESHOLDS_64: [u64; 17] = {
    let mut t = [0u64; 17];
    let mut n = 1;
    while n <= 16 {
        let f = factorial(n as u32);
        t[n] = f.wrapping_neg() % f;
        n += 1;
    }
    t
};

/// 2^bits mod n!.
#[inline(always)]
fn threshold(n: u32, bits: u32) -> u128 {
    if bits == 64 {
        THRESHOLDS_64[n as usize] as u128
    } else {
        (1u128 << bits) % FACTORIALS[n as usize] as u128
    }
}

/// The Fisher–Yates indices (j_{n−1}, …, j_1), j_i uniform in 0..=i, drawn jointly from
/// `bits`-bit words by Lemire's method on the product N = n!: `next` supplies words, the
/// first accepted one is decoded. Returns the indices in draw order (i = n−1 first) through
/// `visit(i, j)`. Requires n! ≤ 2^bits and 1 ≤ bits ≤ 64.
#[inline]
pub fn mixed_radix_draw(
    n: u32,
    bits: u32,
    mut next: impl FnMut() -> u64,
    mut visit: impl FnMut(u32, u32),
) {
    assert!(
        (1..=ONE_WORD_SYMBOLS).contains(&n) && (1..=64).contains(&bits),
        "bad product draw"
    );
    let total = FACTORIALS[n as usize] as u128;
    let mask = (1u128 << bits) - 1;
    assert!(total <= mask + 1, "n! above 2^bits");
    let threshold = threshold(n, bits);
    let mut r = next() as u128 & mask;
    while (r * total) & mask < threshold {
        r = next() as u128 & mask;
    }
    for i in (1..n).rev() {
        let m = r * (i as u128 + 1);
        visit(i, (m >> bits) as u32);
        r = m & mask;
    }
}

/// Where the symbol at position `d` ends after the swaps (i, j) in the order given.
#[inline(always)]
fn follow(pos: u32, i: u32, j: u32) -> u32 {
    // Two selects (compiled to conditional moves): the position is data, so a branch would be
    // mispredicted often.
    let moved = if pos == i { j } else { pos };
    if pos == j {
        i
    } else {
        moved
    }
}

/// The image of `d` under the uniform permutation of `N` ≤ 16 symbols keyed by `key`, equal
/// to following `d` through [`uniform_swaps`]: [`mixed_radix_draw`] on 64-bit words with the
/// constants of `N` folded in (factorial, threshold, loop bounds).
#[inline(always)]
pub(crate) fn uniform_image_small<const N: u32>(key: u64, d: u32) -> u32 {
    let total = FACTORIALS[N as usize] as u128;
    let threshold = THRESHOLDS_64[N as usize] as u128;
    let mut r = key as u128;
    // Rejected for under a 1.2e-6 fraction of keys: then the node's stream, as in the draw.
    if (((r * total) as u64) as u128) < threshold {
        let mut rng = SplitMix64::new(key);
        while (((r * total) as u64) as u128) < threshold {
            r = rng.next_u64() as u128;
        }
    }
    let mut pos = d;
    let mut i = N - 1;
    while i >= 1 {
        let m = r * (i as u128 + 1);
        pos = follow(pos, i, (m >> 64) as u32);
        r = m as u64 as u128;
        i -= 1;
    }
    pos
}

/// The Fisher–Yates swaps of a uniform permutation of `n` symbols from `key`: the first word
/// is the key itself (a well-mixed hash output), later words come from `SplitMix64::new(key)`.
#[inline]
fn uniform_swaps(n: u32, key: u64, visit: impl FnMut(u32, u32)) {
    let mut rng = SplitMix64::new(key);
    if n <= ONE_WORD_SYMBOLS {
        let mut first = Some(key);
        mixed_radix_draw(
            n,
            64,
            || first.take().unwrap_or_else(|| rng.next_u64()),
            visit,
        );
    } else {
        let mut visit = visit;
        for i in (1..n).rev() {
            visit(i, rng.bounded(i + 1));
        }
    }
}

/// The image of `d` (or, with `inverse`, its preimage) under the node permutation of
/// `variant` on 2^`bits` symbols keyed by `key`.
#[inline]
pub fn node_image(variant: OwenVariant, bits: u32, key: u64, d: u32, inverse: bool) -> u32 {
    let n = 1u32 << bits;
    match variant {
        OwenVariant::Uniform if !inverse => match n {
            2 => uniform_image_small::<2>(key, d),
            4 => uniform_image_small::<4>(key, d),
            8 => uniform_image_small::<8>(key, d),
            16 => uniform_image_small::<16>(key, d),
            _ => {
                let mut pos = d;
                uniform_swaps(n, key, |i, j| pos = follow(pos, i, j));
                pos
            }
        },
        OwenVariant::Uniform => node_permutation(variant, bits, key).inverse().apply(d),
        // The key's top bits: exactly uniform on 0..2^bits.
        OwenVariant::CyclicShift => {
            let u = (key >> (64 - bits)) as u32;
            if inverse {
                (d + n - u) % n
            } else {
                (d + u) % n
            }
        }
        OwenVariant::Xor => d ^ (key >> (64 - bits)) as u32,
        OwenVariant::Affine => {
            let (a, u) = affine_parts(bits, key);
            if inverse {
                a.inverse().expect("invertible").apply(d ^ u)
            } else {
                a.apply(d) ^ u
            }
        }
    }
}

/// A ∈ GL(bits, 2) uniform and the translation u, from the node's stream.
fn affine_parts(bits: u32, key: u64) -> (Gf2Matrix, u32) {
    let mut rng = SplitMix64::new(key);
    let a = Gf2Matrix::random_invertible(bits, &mut rng).expect("bits ≤ 8");
    let u = rng.bounded(1 << bits);
    (a, u)
}

/// The whole node permutation (images of 0..2^bits), by the same draws as [`node_image`].
pub fn node_permutation(variant: OwenVariant, bits: u32, key: u64) -> Permutation {
    let n = 1u32 << bits;
    let images: Vec<u8> = match variant {
        OwenVariant::Uniform => {
            // Replay the swaps on the array of symbols, then read where each symbol went.
            let mut at: Vec<u8> = (0..n).map(|v| v as u8).collect();
            uniform_swaps(n, key, |i, j| at.swap(i as usize, j as usize));
            let mut images = vec![0u8; n as usize];
            for (pos, &symbol) in at.iter().enumerate() {
                images[symbol as usize] = pos as u8;
            }
            images
        }
        _ => (0..n)
            .map(|d| node_image(variant, bits, key, d, false) as u8)
            .collect(),
    };
    Permutation::from_images(&images).expect("a bijection by construction")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_product_draw_is_exactly_uniform_on_every_word_of_small_sizes() {
        // Every 12-bit word, n = 2..=6 (6! = 720 ≤ 4096): the accepted words give every index
        // tuple the same count ⌊2^12 / n!⌋, and the rejected ones are exactly 2^12 mod n!.
        for n in 2..=6u32 {
            let total = factorial(n) as usize;
            let mut counts = std::collections::HashMap::new();
            let mut rejected = 0usize;
            for r in 0..1u64 << 12 {
                let mut used = 0;
                let mut tuple = Vec::new();
                let mut words = [r, u64::MAX].into_iter();
                mixed_radix_draw(
                    n,
                    12,
                    || {
                        used += 1;
                        words.next().unwrap()
                    },
                    |i, j| {
                        assert!(j <= i, "index {j} above {i}");
                        tuple.push(j)
                    },
                );
                if used > 1 {
                    rejected += 1;
                } else {
                    *counts.entry(tuple).or_insert(0usize) += 1;
                }
            }
            assert_eq!(counts.len(), total, "n = {n}: every tuple reached");
            assert!(
                counts.values().all(|&c| c == 4096 / total),
                "n = {n}: equal counts"
            );
            assert_eq!(rejected, 4096 % total, "n = {n}: rejections");
        }
    }

    #[test]
    fn the_compile_time_tables_hold_n_factorial_and_2_to_the_64_mod_it() {
        let mut f = 1u128;
        for n in 1..=16u32 {
            f *= n as u128;
            assert_eq!(FACTORIALS[n as usize] as u128, f, "{n}!");
            assert_eq!(
                THRESHOLDS_64[n as usize] as u128,
                (1u128 << 64) % f,
                "2^64 mod {n}!"
            );
        }
        assert_eq!(FACTORIALS[0], 1);
        // Key 0 is rejected for every n ≥ 3 (0 · n! mod 2^64 = 0 < threshold), so the
        // following test exercises the redraw from the node's stream.
        assert!((3..=16).all(|n| THRESHOLDS_64[n] > 0));
    }

    #[test]
    fn following_one_symbol_equals_replaying_the_swaps() {
        for bits in 1..=8u32 {
            for key in [0u64, 1, 0xDEAD_BEEF_0123_4567, u64::MAX] {
                for variant in OwenVariant::ALL {
                    let sigma = node_permutation(variant, bits, key);
                    let inv = sigma.inverse();
                    for d in 0..1u32 << bits {
                        assert_eq!(node_image(variant, bits, key, d, false), sigma.apply(d));
                        assert_eq!(node_image(variant, bits, key, d, true), inv.apply(d));
                    }
                }
            }
        }
    }
}
