//! The batch paths (`Scrambler::scramble_batch` and `scramble_batch_u32`) against the scalar
//! path, bit for bit, for every registry entry (the oracle in every base and law, ART tables
//! small and large), at every width an entry supports from a list that covers partial tail
//! digits, word counts that leave a remainder after the interleaved lanes, and dimensions
//! inside and outside the ART's cached root range. Every ART batch kernel (portable and
//! SIMD) against the scalar path is tested in `crates/art/tests/batch.rs`.

use gartowen::core::ScramblerExt;
use gartowen::core::{BuildContext, PowerOfTwoBase, Scrambler, SplitMix64, Width};

/// Every registry entry, plus options that change the code path taken.
fn requests() -> Vec<(String, PowerOfTwoBase)> {
    let registry = gartowen::registry();
    let mut out: Vec<(String, PowerOfTwoBase)> = registry
        .specs()
        .iter()
        .map(|s| (s.name.to_string(), s.default_base))
        .collect();
    for b in [2u64, 4, 8, 16, 32, 256] {
        let base = PowerOfTwoBase::from_base(b).unwrap();
        for law in ["uniform", "cyclic", "xor", "affine"] {
            out.push((format!("owen-oracle:{law}:base={b}"), base));
        }
    }
    for art in [
        "art-owen-2",
        "art-owen-16p",
        "art-owen-8p",
        "art-owen-m8",
        "art-owen-t3",
    ] {
        for table in [2usize, 4, 1024] {
            out.push((format!("{art}:table={table}"), PowerOfTwoBase::B2));
        }
    }
    out
}

fn build(request: &str, base: PowerOfTwoBase) -> Box<dyn Scrambler> {
    gartowen::registry()
        .build_with(
            request,
            &BuildContext {
                seed: 0x5eed,
                default_base: base,
            },
        )
        .unwrap_or_else(|e| panic!("{request}: {e}"))
}

const WIDTHS: [u32; 16] = [1, 2, 3, 5, 7, 8, 12, 13, 16, 24, 31, 32, 33, 48, 63, 64];

#[test]
fn batch_equals_scalar_for_every_registry_entry() {
    let mut rng = SplitMix64::new(42);
    let mut checked = 0usize;
    for (request, base) in requests() {
        let s = build(&request, base);
        for bits in WIDTHS {
            let width = Width::new(bits).unwrap();
            if !s.supports_width(width) {
                continue;
            }
            for (dim, len) in [(0u32, 203usize), (5, 7), (300, 64), (70_000, 9)] {
                let words: Vec<u64> = (0..len).map(|_| rng.next_u64() & width.mask()).collect();
                let mut batch = words.clone();
                s.scramble_batch(&mut batch, width, dim);
                for (i, (&x, &y)) in words.iter().zip(&batch).enumerate() {
                    assert_eq!(
                        y,
                        s.scramble(x, width, dim),
                        "{request}: width {bits}, dim {dim}, word {i} ({x:#x})"
                    );
                }
                checked += len;
            }
        }
        if s.supports_width(Width::W32) {
            let words: Vec<u32> = (0..517).map(|_| rng.next_u32()).collect();
            let mut batch = words.clone();
            s.scramble_batch_u32(&mut batch, 3);
            for (&x, &y) in words.iter().zip(&batch) {
                assert_eq!(y, s.scramble_u32(x, 3), "{request}: u32 batch, word {x:#x}");
            }
        }
    }
    // A guard against a registry that silently shrinks: entries × widths × words.
    assert!(checked > 100_000, "only {checked} words compared");
}

#[test]
fn batch_covers_every_word_of_small_widths() {
    // Exhaustive at 8 and 12 bits: every word in one batch, against the scalar path.
    for (request, base) in requests() {
        let s = build(&request, base);
        for bits in [8u32, 12] {
            let width = Width::new(bits).unwrap();
            if !s.supports_width(width) {
                continue;
            }
            let words: Vec<u64> = (0..1u64 << bits).collect();
            let mut batch = words.clone();
            s.scramble_batch(&mut batch, width, 1);
            let scalar: Vec<u64> = words.iter().map(|&x| s.scramble(x, width, 1)).collect();
            assert_eq!(batch, scalar, "{request} at {bits} bits");
        }
    }
}
