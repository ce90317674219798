//! Every ART variant is a nested scramble (inspector, every root symbol of a small table),
//! agrees bit for bit with the oracle's tree walk driven by its own node permutations, and
//! inverts; the hash peers are checked the same way.

use gartowen_art::peers::{LkFlavor, LkHash, PerBitOwen};
use gartowen_art::{ArtOwen, ArtVariant};
use gartowen_core::Unscramble;
use gartowen_core::{mix64, PowerOfTwoBase, Scrambler, Width};
use gartowen_oracles::inspector::{inspect_exhaustive, inspect_probes};
use gartowen_oracles::scramble_with_nodes;

fn all_variants() -> Vec<ArtVariant> {
    ArtVariant::all()
}

fn base(v: ArtVariant) -> PowerOfTwoBase {
    PowerOfTwoBase::from_q(v.q()).unwrap()
}

#[test]
fn every_variant_and_root_symbol_is_a_nested_scramble_at_16_bits() {
    let w16 = Width::new(16).unwrap();
    for v in all_variants() {
        let s = ArtOwen::new(v, 6, 11).unwrap(); // L = 3: 6 symbols
        for root in 0..6 {
            let f = |x: u64| s.scramble_from_root(x, w16, root, false);
            let r = inspect_exhaustive(&f, w16, base(v), 16);
            assert!(
                r.nested_scramble,
                "{v:?} root {root}: {:?}",
                r.first_violation
            );
            for x in (0..1u64 << 16).step_by(97) {
                assert_eq!(s.scramble_from_root(f(x), w16, root, true), x);
            }
        }
    }
}

#[test]
fn probes_at_32_and_64_bits() {
    for v in all_variants() {
        let s = ArtOwen::new(v, 256, 3).unwrap();
        for width in [Width::W32, Width::W64] {
            let f = |x: u64| s.scramble(x, width, 7);
            let r = inspect_probes(&f, width, base(v), 64, 300, 5);
            assert!(
                r.nested_scramble,
                "{v:?} {width:?}: {:?}",
                r.first_violation
            );
        }
    }
}

#[test]
fn explicit_tree_bridge_agrees_bit_for_bit() {
    for v in all_variants() {
        let s = ArtOwen::new(v, 44, 21).unwrap();
        for width in [Width::new(12).unwrap(), Width::W32, Width::W64] {
            for i in 0..200u64 {
                let x = mix64(i) & width.mask();
                let dim = (i % 3) as u32;
                let walked = scramble_with_nodes(x, width, base(v), |k, p| {
                    s.node_permutation(width, dim, k, p)
                });
                let y = s.scramble(x, width, dim);
                assert_eq!(walked, y, "{v:?} {width:?} x={x:#x}");
                assert_eq!(s.unscramble(y, width, dim), x);
            }
        }
    }
}

#[test]
fn narrow_words_are_the_top_digits_of_wide_ones() {
    // Nestedness across widths: when q divides 32, a 32-bit word's scramble is the top half of
    // the 64-bit scramble of the same value.
    for v in all_variants().into_iter().filter(|v| 32 % v.q() == 0) {
        let s = ArtOwen::new(v, 256, 8).unwrap();
        for i in 0..500u64 {
            let x = mix64(i) & 0xFFFF_FFFF;
            assert_eq!(
                s.scramble(x << 32, Width::W64, 2) >> 32,
                s.scramble(x, Width::W32, 2),
                "{v:?}"
            );
        }
    }
}

#[test]
fn seeds_and_table_sizes_change_the_scramble() {
    let a = ArtOwen::new(ArtVariant::ArtOwen16P, 256, 1).unwrap();
    let b = ArtOwen::new(ArtVariant::ArtOwen16P, 256, 2).unwrap();
    let c = ArtOwen::new(ArtVariant::ArtOwen16P, 44, 1).unwrap();
    let xs: Vec<u64> = (0..64).map(|i| mix64(i) & 0xFFFF_FFFF).collect();
    let run = |s: &ArtOwen| {
        xs.iter()
            .map(|&x| s.scramble(x, Width::W32, 0))
            .collect::<Vec<_>>()
    };
    assert_ne!(run(&a), run(&b));
    assert_ne!(run(&a), run(&c));
    assert!(
        ArtOwen::new(ArtVariant::ArtOwen2, 45, 1).is_err(),
        "45 is no alphabet size"
    );
    assert!(a.table_bytes() > c.table_bytes());
}

#[test]
fn peers_are_binary_nested_bijections() {
    for flavor in [LkFlavor::Classic, LkFlavor::Improved] {
        let s = LkHash::new(flavor, 99);
        let f = |x: u64| s.scramble(x, Width::W32, 1);
        let r = inspect_probes(&f, Width::W32, PowerOfTwoBase::B2, 32, 2000, 2);
        assert!(r.nested_scramble, "{flavor:?}: {:?}", r.first_violation);
        for i in 0..1000u64 {
            let x = mix64(i) & 0xFFFF_FFFF;
            assert_eq!(s.unscramble(s.scramble(x, Width::W32, 1), Width::W32, 1), x);
        }
        assert!(!s.supports_width(Width::W64));
    }
    let p = PerBitOwen::new(5);
    let w16 = Width::new(16).unwrap();
    let f = |x: u64| p.scramble(x, w16, 0);
    assert!(inspect_exhaustive(&f, w16, PowerOfTwoBase::B2, 16).nested_scramble);
    for i in 0..1000u64 {
        let x = mix64(i);
        assert_eq!(p.unscramble(p.scramble(x, Width::W64, 3), Width::W64, 3), x);
    }
}

#[test]
fn imitation_peers_are_nested_with_translation_nodes_of_the_stated_structure() {
    use gartowen_art::peers::{DigitalShift, LinearMatrixScramble};
    let w16 = Width::new(16).unwrap();
    let shift = DigitalShift::new(3);
    let lms = LinearMatrixScramble::new(3);
    for s in [&shift as &dyn Unscramble, &lms] {
        let f = |x: u64| s.scramble(x, w16, 2);
        assert!(inspect_exhaustive(&f, w16, PowerOfTwoBase::B2, 16).nested_scramble);
        for i in 0..1000u64 {
            let x = mix64(i);
            assert_eq!(s.unscramble(s.scramble(x, Width::W64, 2), Width::W64, 2), x);
        }
    }
    // The shift is one XOR word; LMS is affine over GF(2): f(x ⊕ y ⊕ z) = f(x) ⊕ f(y) ⊕ f(z).
    for i in 0..500u64 {
        let (x, y, z) = (mix64(i), mix64(i + 7777), mix64(i + 99999));
        let l = |v: u64| lms.scramble(v, Width::W64, 1);
        assert_eq!(l(x ^ y ^ z), l(x) ^ l(y) ^ l(z));
        let d = |v: u64| shift.scramble(v, Width::W64, 1);
        assert_eq!(d(x) ^ x, d(y) ^ y);
    }
    // ...and LMS is not a mere shift: some input bit feeds a later output bit.
    assert!((0..64u64)
        .any(|i| lms.scramble(1 << i, Width::W64, 1) ^ lms.scramble(0, Width::W64, 1) != 1 << i));
}

#[test]
fn step_table_path_equals_the_digit_by_digit_loop() {
    for v in all_variants() {
        for symbols in [6usize, 256] {
            let s = ArtOwen::new(v, symbols, 31).unwrap().with_step_tables();
            assert!(s.step_tables_built());
            for width in [
                Width::new(12).unwrap(),
                Width::new(13).unwrap(),
                Width::W32,
                Width::W64,
            ] {
                for i in 0..300u64 {
                    let x = mix64(i ^ 0x55) & width.mask();
                    let dim = (i % 300) as u32; // past the cached roots too
                    assert_eq!(
                        s.scramble(x, width, dim),
                        s.scramble_digit_by_digit(x, width, dim),
                        "{v:?} symbols={symbols} {width:?} x={x:#x}"
                    );
                }
            }
        }
    }
}

#[test]
fn table_bytes_count_every_table() {
    // The count the speed reports print, against the layout worked out by hand for q = 4:
    // codes (8 B per symbol), ψ and ψ^{-1} images (one byte per symbol and digit, only for
    // variants with ψ), scalar step tables of one digit (next 4 B, local 2 B, carry 8 B per
    // entry), the batch table of two digits (8 B), and, when the symbols fit in its 8 bits,
    // the narrow table (4 B) with the codes' top halves (4 B per symbol). 1024 symbols
    // overflow the batch budget at two digits, so their batch step is one digit (4 bits) and
    // there is no narrow table.
    for (name, psi) in [("art-owen-t4", false), ("art-owen-m4", true)] {
        let variant = gartowen_art::registry::variant_of(name).unwrap();
        for (symbols, batch_bits, narrow) in [(256usize, 8u32, true), (1024, 4, false)] {
            let art = ArtOwen::new(variant, symbols, 1).unwrap();
            let n = art.grammar().symbols() as usize;
            assert_eq!(n, symbols);
            assert_eq!(art.batch_step_bits(), batch_bits);
            assert_eq!(art.has_narrow_table(), narrow);
            let psi_bytes = if psi { 2 * (n << 4) } else { 0 };
            let narrow_bytes = if narrow {
                (n << batch_bits) * 4 + n * 4
            } else {
                0
            };
            let expected = art.grammar().table_bytes()
                + n * 8
                + psi_bytes
                + (n << 4) * (4 + 8)
                + (n << batch_bits) * 8
                + narrow_bytes;
            assert_eq!(art.table_bytes(), expected, "{name} with {symbols} symbols");
        }
    }
}
