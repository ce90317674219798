//! The tuned full-tree oracle (`owen-oracle`: incremental keys, base-2 tiles, 4-lane batches,
//! constant-size draws) equals the definition written out (`owen_definition`) bit for bit: in
//! every base 2..256, every node law, 16-, 32- and 64-bit words, word by word, by batch, by
//! float and node by node.

use gartowen_core::Unscramble;
use gartowen_core::{PowerOfTwoBase, Scrambler, SplitMix64, Width};
use gartowen_oracles::owen_definition;
use gartowen_owen::{FullTreeOwen, OwenVariant};

fn widths() -> [Width; 3] {
    [Width::new(16).unwrap(), Width::W32, Width::W64]
}

fn bases() -> impl Iterator<Item = PowerOfTwoBase> {
    (1..=8).map(|q| PowerOfTwoBase::from_q(q).unwrap())
}

#[test]
fn every_word_path_equals_the_definition() {
    let mut rng = SplitMix64::new(0xdef1);
    for base in bases() {
        for variant in OwenVariant::ALL {
            for seed in [0u64, 0x5eed_0000_0000_0007] {
                let tuned = FullTreeOwen::new(base, variant, seed);
                for width in widths() {
                    for dim in [0u32, 3] {
                        let mut xs: Vec<u64> =
                            (0..37).map(|_| rng.next_u64() & width.mask()).collect();
                        xs.extend([0, width.mask()]);
                        let want: Vec<u64> = xs
                            .iter()
                            .map(|&x| owen_definition::scramble(seed, base, variant, x, width, dim))
                            .collect();
                        let one: Vec<u64> =
                            xs.iter().map(|&x| tuned.scramble(x, width, dim)).collect();
                        assert_eq!(one, want, "{} {width:?} dim {dim}", tuned.name());
                        let mut batch = xs.clone();
                        tuned.scramble_batch(&mut batch, width, dim);
                        assert_eq!(batch, want, "batch: {} {width:?}", tuned.name());
                        for (&x, &y) in xs.iter().zip(&want) {
                            assert_eq!(tuned.unscramble(y, width, dim), x);
                            let f = tuned.scramble_f64(x, width, dim);
                            let exact = gartowen_core::word_to_f64(y, width);
                            // The float path scrambles only the digits inside its 53 bits.
                            assert!((f - exact).abs() <= 2f64.powi(-52), "{f} vs {exact}");
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn every_node_equals_the_definition() {
    let mut rng = SplitMix64::new(0x40de);
    for base in bases() {
        for variant in OwenVariant::ALL {
            let tuned = FullTreeOwen::new(base, variant, 11);
            let width = Width::W32;
            let layout = gartowen_core::DigitLayout::new(width, base);
            for k in 0..layout.num_digits() {
                let prefix = layout.prefix(rng.next_u64() & width.mask(), k);
                assert_eq!(
                    tuned.node_permutation(width, 2, k, prefix),
                    owen_definition::node(11, base, variant, width, 2, k, prefix),
                    "{} depth {k} prefix {prefix:#x}",
                    tuned.name()
                );
            }
        }
    }
}

#[test]
fn the_definition_depends_on_seed_dimension_and_every_digit_above() {
    // A definition that ignored any of them would make the comparison above vacuous there.
    let (base, w) = (PowerOfTwoBase::from_q(4).unwrap(), Width::W32);
    let scr = |seed, x, dim| owen_definition::scramble(seed, base, OwenVariant::Uniform, x, w, dim);
    let x = 0x1234_5678;
    assert_ne!(scr(1, x, 0), scr(2, x, 0));
    assert_ne!(scr(1, x, 0), scr(1, x, 1));
    // Inputs equal in their last digit but differing above it: the last output digits differ
    // for some pair (each node above names a different subtree).
    let low = |y: u64| y & 0xf;
    assert!((1..16u64).any(|d| low(scr(1, x, 0)) != low(scr(1, x ^ (d << 28), 0))));
}

/// Keys whose first word is rejected (key 0 for every n ≥ 3: 0·n! mod 2^64 = 0 is below
/// 2^64 mod n!) redraw from the node's stream in both; random keys almost never do.
#[test]
fn every_node_draw_equals_the_tuned_one_rejected_keys_included() {
    let mut rng = SplitMix64::new(0xD5A3);
    let keys: Vec<u64> = [0u64, 1, u64::MAX, 1 << 63]
        .into_iter()
        .chain((0..64).map(|_| rng.next_u64()))
        .collect();
    for bits in 1..=8u32 {
        for variant in OwenVariant::ALL {
            for &key in &keys {
                assert_eq!(
                    owen_definition::draw(variant, bits, key),
                    gartowen_owen::node_draw::node_permutation(variant, bits, key),
                    "{variant:?}, {bits} bits, key {key:#x}"
                );
            }
        }
    }
    // Key 0 is rejected: its draw is not the identity that u = 0 would give.
    let first = owen_definition::draw(OwenVariant::Uniform, 2, 0);
    assert_ne!(first, gartowen_core::Permutation::identity(4).unwrap());
}
