//! Q-ART with the linear part composed along the tree: a bijection, the same as Q-ART at depth
//! 0 and different below, and reachable from the registry.

use gartowen_art::{ArtOwen, ArtVariant, QArtComposed};
use gartowen_core::Unscramble;
use gartowen_core::{DigitLayout, PowerOfTwoBase, Scrambler, SplitMix64, Width};

#[test]
fn it_inverts_on_every_width_and_is_a_bijection_at_12_bits() {
    let c = QArtComposed::new(256, 4).unwrap();
    let mut rng = SplitMix64::new(1);
    for bits in [7u32, 8, 13, 32, 33, 64] {
        let w = Width::new(bits).unwrap();
        for dim in [0u32, 5, 400] {
            for _ in 0..300 {
                let x = rng.next_u64() & w.mask();
                let y = c.scramble(x, w, dim);
                assert_eq!(y & !w.mask(), 0);
                assert_eq!(c.unscramble(y, w, dim), x, "W={bits} dim {dim}");
            }
        }
    }
    let w12 = Width::new(12).unwrap();
    let mut seen = vec![false; 1 << 12];
    for x in w12.all_words() {
        let y = c.scramble(x, w12, 1) as usize;
        assert!(!seen[y], "collision at {x:#x}");
        seen[y] = true;
    }
}

#[test]
fn depth_zero_is_q_arts_and_deeper_digits_differ() {
    // Same table, root and shifts: M_0 = ψ_{s_0}, so digit 0 agrees with translation-only
    // Q-ART on every word; from digit 1 on the composed product differs for some words.
    let c = QArtComposed::new(256, 9).unwrap();
    let q = ArtOwen::new(ArtVariant::QArt4, 256, 9).unwrap();
    let layout = DigitLayout::new(Width::W32, PowerOfTwoBase::B4);
    let mut rng = SplitMix64::new(2);
    let mut differ_at = [0u32; 16];
    for _ in 0..2000 {
        let x = rng.next_u64() >> 32;
        for dim in [0u32, 3] {
            let (a, b) = (
                c.scramble(x, Width::W32, dim),
                q.scramble(x, Width::W32, dim),
            );
            assert_eq!(layout.get(a, 0), layout.get(b, 0));
            if let Some(k) = (0..16).find(|&k| layout.get(a, k) != layout.get(b, k)) {
                differ_at[k as usize] += 1;
            }
        }
    }
    assert!(differ_at[1] > 100, "{differ_at:?}");
    assert!(differ_at.iter().sum::<u32>() > 2000, "{differ_at:?}");
}

#[test]
fn the_registry_builds_it_and_refuses_other_compositions() {
    let specs = gartowen_art::registry::specs();
    let spec = specs.iter().find(|s| s.name == "q-art-4").unwrap();
    let ctx = gartowen_core::registry::BuildContext {
        seed: 9,
        default_base: PowerOfTwoBase::B4,
    };
    let build = |r: &str| (spec.build)(&gartowen_core::ScramblerRequest::parse(r).unwrap(), &ctx);
    let s = build("q-art-4:compose=linear").unwrap();
    let direct = QArtComposed::new(256, 9).unwrap();
    assert_eq!(
        s.scramble(0x1234_5678, Width::W32, 2),
        direct.scramble(0x1234_5678, Width::W32, 2)
    );
    assert!(s.name().starts_with("q-art-4:compose=linear"));
    let plain = build("q-art-4:compose=translation").unwrap();
    let q = ArtOwen::new(ArtVariant::QArt4, 256, 9).unwrap();
    assert_eq!(
        plain.scramble(0xdead_beef, Width::W32, 1),
        q.scramble(0xdead_beef, Width::W32, 1)
    );
    for bad in ["q-art-4:compose=affine", "q-art-4:compose"] {
        let e = build(bad).err().expect(bad).to_string();
        assert!(e.contains("compose"), "{e}");
    }
    let other = specs.iter().find(|s| s.name == "art-owen-2").unwrap();
    let req = gartowen_core::ScramblerRequest::parse("art-owen-2:compose=linear").unwrap();
    assert!((other.build)(&req, &ctx).is_err());
}

#[test]
fn on_words_with_one_nonzero_digit_it_differs_from_q_art_at_that_digit_only() {
    // After the input shift A, a word with a single nonzero digit k walks the same symbols as
    // Q-ART, and every other digit is 0, which every linear map fixes: both outputs are the
    // composed translations F ⊕ D there. Only digit k sees M_k instead of ψ_{s_k}. This pins
    // the translation composition to Q-ART's (frozen by golden vectors).
    let c = QArtComposed::new(256, 21).unwrap();
    let q = ArtOwen::new(ArtVariant::QArt4, 256, 21).unwrap();
    for bits in [32u32, 64, 13] {
        let w = Width::new(bits).unwrap();
        let layout = DigitLayout::new(w, PowerOfTwoBase::B4);
        for dim in [0u32, 2, 300] {
            let (a, _) = q.dimension_shifts(dim, w);
            assert_eq!(
                c.scramble(a, w, dim),
                q.scramble(a, w, dim),
                "all-zero digits"
            );
            for k in 0..layout.num_digits() {
                for d in 1..1u32 << layout.digit_bits(k) {
                    let x = a ^ layout.set(0, k, d);
                    let (y, z) = (c.scramble(x, w, dim), q.scramble(x, w, dim));
                    for j in (0..layout.num_digits()).filter(|&j| j != k) {
                        assert_eq!(layout.get(y, j), layout.get(z, j), "W={bits} k={k} j={j}");
                    }
                }
            }
        }
    }
}

#[test]
fn table_bytes_count_the_record_and_the_matrix_pairs() {
    // The Q-ART record for 64-bit words, 256 × (3 + 64) bits = 2144 bytes, plus ψ and ψ⁻¹ as
    // matrices (16 bytes each: a size byte and the packed rows, padded) per symbol.
    let c = QArtComposed::new(256, 1).unwrap();
    assert_eq!(std::mem::size_of::<gartowen_core::Gf2Matrix>(), 16);
    assert_eq!(c.table_bytes(), 2144 + 256 * 2 * 16);
}
