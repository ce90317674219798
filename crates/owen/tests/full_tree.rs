//! FullTreeOwen: bijective, nested, invertible, keyed as documented; the inspector sees it.

use gartowen_core::Unscramble;
use gartowen_core::{mix64, DigitLayout, PowerOfTwoBase, Scrambler, Width};
use gartowen_oracles::inspector::{inspect_exhaustive, inspect_probes, ViolationKind};
use gartowen_owen::{FullTreeOwen, OwenVariant};

fn base(q: u32) -> PowerOfTwoBase {
    PowerOfTwoBase::from_q(q).unwrap()
}

#[test]
fn every_q_and_variant_is_a_nested_bijection_on_all_16_bit_words() {
    let w16 = Width::new(16).unwrap();
    for q in 1..=8 {
        for variant in OwenVariant::ALL {
            for seed in [0u64, 1, 0xDEAD_BEEF] {
                let s = FullTreeOwen::new(base(q), variant, seed);
                let f = |x: u64| s.scramble(x, w16, 3);
                let r = inspect_exhaustive(&f, w16, base(q), 16);
                assert!(
                    r.nested_scramble,
                    "q={q} {variant:?} seed={seed}: {:?}",
                    r.first_violation
                );
                for x in w16.all_words().step_by(7) {
                    assert_eq!(s.unscramble(s.scramble(x, w16, 3), w16, 3), x);
                }
            }
        }
    }
}

#[test]
fn inspector_reconstruction_equals_node_permutation_queries() {
    // Two paths to the same node permutations: black-box reconstruction versus the direct query.
    let w12 = Width::new(12).unwrap();
    for q in [1u32, 2, 3, 4, 5] {
        let s = FullTreeOwen::new(base(q), OwenVariant::Uniform, 42);
        let layout = DigitLayout::new(w12, base(q));
        for x in (0..4096u64).step_by(37) {
            let y = s.scramble(x, w12, 1);
            for k in 0..layout.num_digits() {
                let sigma = s.node_permutation(w12, 1, k, layout.prefix(x, k));
                assert_eq!(
                    sigma.apply(layout.get(x, k)),
                    layout.get(y, k),
                    "q={q} x={x} k={k}"
                );
                assert_eq!(
                    sigma.len(),
                    1 << layout.digit_bits(k),
                    "tail digit alphabet"
                );
            }
        }
    }
}

#[test]
fn batch_mode_equals_single_queries() {
    for q in [1u32, 2, 3, 4, 8] {
        let s = FullTreeOwen::new(base(q), OwenVariant::Uniform, 5);
        let xs: Vec<u64> = (0..5000u64).map(|i| mix64(i) & 0xFFFF_FFFF).collect();
        let mut batch = xs.clone();
        s.scramble_batch(&mut batch, Width::W32, 2);
        for (x, y) in xs.iter().zip(&batch) {
            assert_eq!(s.scramble(*x, Width::W32, 2), *y);
        }
    }
}

#[test]
fn probes_at_32_and_64_bits_accept_every_variant() {
    for width in [Width::W32, Width::W64] {
        for q in [1u32, 2, 3, 4, 8] {
            for variant in OwenVariant::ALL {
                let s = FullTreeOwen::new(base(q), variant, 9);
                let f = |x: u64| s.scramble(x, width, 0);
                let r = inspect_probes(&f, width, base(q), 64, 200, 1);
                assert!(
                    r.nested_scramble,
                    "{width:?} q={q} {variant:?}: {:?}",
                    r.first_violation
                );
                assert_eq!(r.nodes_checked, 200);
            }
        }
    }
}

#[test]
fn seeds_and_dimensions_give_different_scrambles() {
    let a = FullTreeOwen::new(base(2), OwenVariant::Uniform, 1);
    let b = FullTreeOwen::new(base(2), OwenVariant::Uniform, 2);
    let xs: Vec<u64> = (0..64).map(|i| i << 26).collect();
    let ya: Vec<u64> = xs.iter().map(|&x| a.scramble(x, Width::W32, 0)).collect();
    let yb: Vec<u64> = xs.iter().map(|&x| b.scramble(x, Width::W32, 0)).collect();
    let yd: Vec<u64> = xs.iter().map(|&x| a.scramble(x, Width::W32, 1)).collect();
    assert_ne!(ya, yb);
    assert_ne!(ya, yd);
}

// Deliberately broken maps: the inspector must reject each with the right kind of violation.

#[test]
fn inspector_rejects_a_non_nested_hash() {
    let w16 = Width::new(16).unwrap();
    let f = |x: u64| mix64(x) & 0xFFFF;
    let r = inspect_exhaustive(&f, w16, base(1), 16);
    let v = r.first_violation.expect("a hash is not nested");
    assert_eq!(v.kind, ViolationKind::NotNested);
    assert_eq!(v.depth, 0, "already the top digit depends on lower digits");
    let layout = DigitLayout::new(w16, base(1));
    assert_eq!(layout.get(v.inputs[0], 0), layout.get(v.inputs[1], 0));
    assert_ne!(layout.get(v.outputs[0], 0), layout.get(v.outputs[1], 0));
    let r = inspect_probes(&|x: u64| mix64(x), Width::W64, base(4), 16, 50, 3);
    assert_eq!(r.first_violation.unwrap().kind, ViolationKind::NotNested);
}

#[test]
fn inspector_rejects_a_node_keyed_by_its_own_digit() {
    // Off-by-one keying: the node at depth k is keyed by k+1 digits (its own digit included),
    // so its digit map need not be a bijection.
    let w16 = Width::new(16).unwrap();
    let s = FullTreeOwen::new(base(2), OwenVariant::Xor, 4);
    let layout = DigitLayout::new(w16, base(2));
    let f = |x: u64| {
        let mut y = 0;
        for k in 0..layout.num_digits() {
            let sigma = s.node_permutation(w16, 0, k, layout.prefix(x, k + 1));
            y = layout.set(y, k, sigma.apply(layout.get(x, k)));
        }
        y
    };
    let r = inspect_exhaustive(&f, w16, base(2), 8);
    assert_eq!(
        r.first_violation.expect("broken").kind,
        ViolationKind::NotBijective
    );
}

#[test]
fn inspector_rejects_outputs_wider_than_the_word() {
    let w12 = Width::new(12).unwrap();
    let r = inspect_exhaustive(&|x: u64| x | 0x1000, w12, base(1), 12);
    assert_eq!(r.first_violation.unwrap().kind, ViolationKind::OutOfRange);
}

#[test]
fn a_binary_nested_scramble_is_nested_in_base_4_but_not_conversely() {
    // T4 at a bounded size: a binary Owen scramble is a base-4 nested scramble...
    let w12 = Width::new(12).unwrap();
    let binary = FullTreeOwen::new(base(1), OwenVariant::Uniform, 8);
    let f = |x: u64| binary.scramble(x, w12, 0);
    assert!(inspect_exhaustive(&f, w12, base(2), 6).nested_scramble);
    // ...while a base-4 Owen scramble is generally not binary-nested.
    let quaternary = FullTreeOwen::new(base(2), OwenVariant::Uniform, 8);
    let g = |x: u64| quaternary.scramble(x, w12, 0);
    assert_eq!(
        inspect_exhaustive(&g, w12, base(1), 12)
            .first_violation
            .unwrap()
            .kind,
        ViolationKind::NotNested
    );
}

#[test]
fn float_outputs_computing_only_the_digits_they_keep_equal_the_full_scramble() {
    // scramble_f32 / scramble_f64 stop after the digits inside the top 24 / 53 bits; a nested
    // scramble's other digits cannot reach those bits, so the floats must equal the full
    // scramble's, for every base (tail digits included) and width.
    use gartowen_core::{word_to_f32, word_to_f64};
    for q in 1..=8 {
        for variant in OwenVariant::ALL {
            let s = FullTreeOwen::new(base(q), variant, 77);
            for bits in [8u32, 23, 24, 25, 31, 32, 53, 54, 64] {
                let width = Width::new(bits).unwrap();
                for i in 0..64u64 {
                    let x = mix64(i ^ (q as u64) << 40) & width.mask();
                    let y = s.scramble(x, width, 3);
                    assert_eq!(
                        s.scramble_f32(x, width, 3).to_bits(),
                        word_to_f32(y, width).to_bits(),
                        "f32 q={q} {variant:?} width {bits}"
                    );
                    assert_eq!(
                        s.scramble_f64(x, width, 3).to_bits(),
                        word_to_f64(y, width).to_bits(),
                        "f64 q={q} {variant:?} width {bits}"
                    );
                }
            }
        }
    }
}
