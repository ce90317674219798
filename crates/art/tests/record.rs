//! The record-only path (what a GPU kernel would run) against the accelerated paths, and the
//! record's size against the layouts worked out by hand from the paper's text.

use gartowen_art::{ArtOwen, ArtRecord, ArtVariant};
use gartowen_core::{Permutation, Scrambler, SplitMix64, Width};

fn words(seed: u64, len: usize, width: Width) -> Vec<u64> {
    let mut rng = SplitMix64::new(seed);
    (0..len).map(|_| rng.next_u64() & width.mask()).collect()
}

#[test]
fn the_record_path_equals_the_scalar_and_batch_paths_on_every_variant() {
    // Widths where q divides W and where it leaves a tail digit, 64-bit words (whose codes
    // need more than a 32-bit record holds for some variants), two alphabet sizes.
    for variant in ArtVariant::all() {
        for symbols in [44usize, 256] {
            let art = ArtOwen::new(variant, symbols, 0x5eed ^ symbols as u64).unwrap();
            for bits in [8u32, 13, 16, 31, 32, 48, 64] {
                let width = Width::new(bits).unwrap();
                let record = art.record(width);
                assert_eq!(record.width(), width);
                for dim in [0u32, 1, 7, 300] {
                    let xs = words(u64::from(bits) * 1000 + u64::from(dim), 200, width);
                    let mut batch = xs.clone();
                    art.scramble_batch(&mut batch, width, dim);
                    for (&x, &b) in xs.iter().zip(&batch) {
                        let r = record.scramble(x, dim);
                        assert_eq!(
                            r,
                            art.scramble(x, width, dim),
                            "{variant:?} W={bits} dim {dim} x={x:#x}"
                        );
                        assert_eq!(r, b, "batch {variant:?} W={bits} dim {dim}");
                    }
                }
            }
        }
    }
}

#[test]
fn the_record_decodes_to_the_engines_codes_and_psi() {
    for variant in ArtVariant::all() {
        let art = ArtOwen::new(variant, 256, 11).unwrap();
        let record = art.record(Width::W64);
        let b = 1usize << variant.q();
        for s in 0..256u32 {
            assert_eq!(
                record.code(s),
                art.codes()[s as usize],
                "{variant:?} symbol {s}"
            );
            let images = art.psi_images();
            match record.psi(s) {
                None => assert!(images.is_empty()),
                Some(p) => assert_eq!(p.as_slice()[..b], images[s as usize * b..][..b]),
            }
        }
    }
}

#[test]
fn the_8p_record_word_is_the_packed_permutation_and_the_code() {
    // The paper's layout: the top 24 bits pack ψ (entry d in 3-bit field d from the top); the
    // same word's fields 1.. are the code. Rebuilt here from the engine's ψ and code alone.
    let art = ArtOwen::new(ArtVariant::ArtOwen8P, 256, 5).unwrap();
    let record = art.record(Width::W32);
    assert_eq!(record.entry_bits(), 32);
    for s in 0..256u32 {
        let images = &art.psi_images()[s as usize * 8..][..8];
        let packed = Permutation::from_images(images).unwrap().pack24().unwrap();
        let code_word = (art.codes()[s as usize] >> 32) as u32;
        assert_eq!(code_word >> 29, 0, "field 0 of the code is cleared");
        assert_eq!(
            code_word >> 8,
            packed & 0x1F_FFFF,
            "fields 1..7 of the code are ψ's"
        );
        assert_eq!(record.code(s), art.codes()[s as usize]);
    }
}

/// Record bytes of `name` with 256 symbols for `width`-bit words.
fn record_bytes(variant: ArtVariant, width: Width) -> usize {
    ArtRecord::draw(variant, 256, 1, width).unwrap().bytes()
}

#[test]
fn record_sizes_follow_the_papers_layouts() {
    // Worked out by hand, 256 symbols, 32-bit words: a 32-bit code (1024 B); Q-ART adds a
    // 3-bit matrix index (96 B); 8p one 32-bit word; 16p a 64-bit permutation and a 32-bit
    // code; M8 a 64-bit matrix and a 32-bit code; M3 9 bits and 32; T4 32.
    let w32 = Width::W32;
    assert_eq!(record_bytes(ArtVariant::ArtOwen2, w32), 1024);
    assert_eq!(record_bytes(ArtVariant::QArt4, w32), 1024 + 96);
    assert_eq!(record_bytes(ArtVariant::ArtOwen8P, w32), 1024);
    assert_eq!(record_bytes(ArtVariant::ArtOwen16P, w32), 3072);
    assert_eq!(record_bytes(ArtVariant::Matrix(8), w32), 3072);
    assert_eq!(record_bytes(ArtVariant::Matrix(3), w32), 256 * 41 / 8);
    assert_eq!(record_bytes(ArtVariant::Translation(4), w32), 1024);
    // 64-bit words: full 64-bit codes, except 8p (one word) and 16p (a 32-bit code by design).
    let w64 = Width::W64;
    assert_eq!(record_bytes(ArtVariant::ArtOwen2, w64), 2048);
    assert_eq!(record_bytes(ArtVariant::ArtOwen8P, w64), 1024);
    assert_eq!(record_bytes(ArtVariant::ArtOwen16P, w64), 3072);
    // The bound: art-owen-m8's record is at most 16 bytes per symbol.
    let m8 = ArtRecord::draw(ArtVariant::Matrix(8), 256, 1, w64).unwrap();
    assert_eq!(m8.bytes_per_symbol(), 16.0);
    // The paper's ratios: 8p about Q-ART's size, 16p about three times it.
    let qart = record_bytes(ArtVariant::QArt4, w32) as f64;
    let r8 = record_bytes(ArtVariant::ArtOwen8P, w32) as f64 / qart;
    let r16 = record_bytes(ArtVariant::ArtOwen16P, w32) as f64 / qart;
    assert!((0.85..=1.0).contains(&r8), "8p / q-art-4 = {r8}");
    assert!((2.5..=3.0).contains(&r16), "16p / q-art-4 = {r16}");
}

#[test]
fn acceleration_bytes_are_everything_but_the_child_table() {
    for variant in ArtVariant::all() {
        let art = ArtOwen::new(variant, 256, 3).unwrap();
        assert_eq!(
            art.acceleration_bytes() + art.grammar().table_bytes(),
            art.table_bytes()
        );
        // The accelerated tables are far larger than the record they are derived from.
        assert!(art.acceleration_bytes() > 4 * art.record(Width::W64).bytes());
    }
}

#[test]
fn a_record_differs_across_seeds_and_variants() {
    // A record that ignored its seed (or drew every symbol alike) would still equal the engine
    // built from it; this checks that the data really varies.
    let a = ArtRecord::draw(ArtVariant::ArtOwen16P, 256, 1, Width::W32).unwrap();
    let b = ArtRecord::draw(ArtVariant::ArtOwen16P, 256, 2, Width::W32).unwrap();
    assert!((0..256).any(|s| a.code(s) != b.code(s)));
    assert!((0..256).any(|s| a.psi(s) != a.psi(0)));
    assert!((0..100u64).any(|x| a.scramble(x << 20, 0) != b.scramble(x << 20, 0)));
}

#[test]
fn linear_psi_is_given_as_its_matrix() {
    // Q-ART and every matrix variant: the matrix applies as ψ does, digit by digit; the
    // permutation variants have no matrix.
    for variant in [ArtVariant::QArt4]
        .into_iter()
        .chain((1..=8).map(ArtVariant::Matrix))
    {
        let record = ArtRecord::draw(variant, 44, 6, Width::W32).unwrap();
        let q = variant.q();
        for s in 0..44u32 {
            let m = record.psi_matrix(s).unwrap();
            assert_eq!(m.size(), q);
            for d in 0..1u32 << q {
                assert_eq!(
                    m.apply(d),
                    record.psi_apply(s, d),
                    "{variant:?} s={s} d={d}"
                );
            }
        }
        // Not every symbol's matrix is the identity (a decoder returning I would pass above
        // only if ψ were the identity too).
        assert!(
            (0..44).any(|s| record.psi_matrix(s).unwrap().packed()
                != gartowen_core::Gf2Matrix::identity(q).unwrap().packed())
                || q == 1
        );
    }
    for variant in [
        ArtVariant::ArtOwen2,
        ArtVariant::ArtOwen8P,
        ArtVariant::ArtOwen16P,
        ArtVariant::Translation(3),
    ] {
        assert!(ArtRecord::draw(variant, 44, 6, Width::W32)
            .unwrap()
            .psi_matrix(0)
            .is_none());
    }
}
