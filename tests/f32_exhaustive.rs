//! Every one of the 2^32 32-bit words converts to an f32 below 1.0, by truncation to its top
//! 24 bits. Runs in the test profile (opt-level 2) in a few seconds on 2 cores; CI runs it.

use gartowen::core::{word_to_f32, word_to_f64, Width};

#[test]
fn every_u32_word_truncates_to_an_f32_below_one() {
    let threads = 4u64;
    let chunk = (1u64 << 32) / threads;
    let handles: Vec<_> = (0..threads)
        .map(|t| {
            std::thread::spawn(move || {
                let mut prev = if t == 0 {
                    0.0
                } else {
                    word_to_f32(t * chunk - 1, Width::W32)
                };
                for x in t * chunk..(t + 1) * chunk {
                    let f = word_to_f32(x, Width::W32);
                    // Truncation: exactly (x >> 8)·2^-24, monotone, never 1.0.
                    let exact = (x >> 8) as f32 * (1.0 / 16_777_216.0);
                    if f != exact || f >= 1.0 || f < prev {
                        return Err(x);
                    }
                    prev = f;
                }
                Ok(())
            })
        })
        .collect();
    for h in handles {
        if let Err(x) = h.join().unwrap() {
            panic!(
                "word {x:#010x} converts wrongly to {}",
                word_to_f32(x, Width::W32)
            );
        }
    }
    assert_eq!(
        word_to_f32(u32::MAX as u64, Width::W32),
        1.0 - f32::EPSILON / 2.0
    );
    // Rounding to nearest would give exactly 1.0 here: the case the truncation rule exists for.
    assert_eq!(u32::MAX as f32 / 4294967296.0, 1.0);
    assert!(word_to_f64(u32::MAX as u64, Width::W32) < 1.0);
}
