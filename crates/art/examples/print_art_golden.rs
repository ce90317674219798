//! Prints golden vectors of every ART variant and peer (seed 2024, 256 symbols, dimension 1) for
//! tests/golden.rs. Regenerate only on a deliberate change of the documented construction.
use gartowen_art::peers::{DigitalShift, LinearMatrixScramble, LkFlavor, LkHash, PerBitOwen};
use gartowen_art::{ArtOwen, ArtVariant};
use gartowen_core::{Scrambler, Width};

fn main() {
    let inputs = [0u64, 0x8000_0000, 0x1234_5678, 0xFFFF_FFFF];
    let mut list: Vec<(String, Box<dyn Scrambler>)> = Vec::new();
    let mut variants = vec![
        ArtVariant::ArtOwen2,
        ArtVariant::QArt4,
        ArtVariant::ArtOwen8P,
        ArtVariant::ArtOwen16P,
    ];
    variants.extend((1..=8).map(ArtVariant::Matrix));
    variants.extend((1..=8).map(ArtVariant::Translation));
    for v in variants {
        list.push((v.name(), Box::new(ArtOwen::new(v, 256, 2024).unwrap())));
    }
    list.push((
        "lk-hash".into(),
        Box::new(LkHash::new(LkFlavor::Classic, 2024)),
    ));
    list.push((
        "lk-hash-improved".into(),
        Box::new(LkHash::new(LkFlavor::Improved, 2024)),
    ));
    list.push(("owen-per-bit-hash".into(), Box::new(PerBitOwen::new(2024))));
    list.push(("digital-shift".into(), Box::new(DigitalShift::new(2024))));
    list.push((
        "lms-shift".into(),
        Box::new(LinearMatrixScramble::new(2024)),
    ));
    for (name, s) in list {
        let out: Vec<String> = inputs
            .iter()
            .map(|&x| format!("0x{:08x}", s.scramble(x, Width::W32, 1)))
            .collect();
        let w64 = if s.supports_width(Width::W64) {
            s.scramble(0x0123_4567_89ab_cdef, Width::W64, 5)
        } else {
            0
        };
        println!("    (\"{name}\", [{}], 0x{w64:016x}),", out.join(", "));
    }
}
