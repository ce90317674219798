//! The RMSE harness on known cases: plain random points reach σ/√N (a χ² test), the harness is
//! thread-count independent, and scramblers with known defects show the expected difference.
//!
//! Slope tests use fixed seeds, R = 32 replicates and N = 2^6..2^14, where the fitted slope's
//! standard error is about 0.05; the thresholds separate the predicted rates (−0.5, −1, −1.5)
//! by at least 4 standard errors, so the false-alarm rate is below 1e-4 per assertion.

use gartowen::core::Unscramble;
use gartowen::core::{
    hash_words, BuildContext, CoreError, PowerOfTwoBase, Registry, Scrambler, ScramblerRequest,
    ScramblerSpec, Width,
};
use gartowen_bench::harness::{fit_slope, run_method, HarnessConfig, Method};
use gartowen_bench::integrands::{Bilinear, Family, Fixed, HeavisideFamily, Smoothness};
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// A bijective hash of the whole word: not nested, so it destroys the net.
struct WholeWordHash(u64);

impl Scrambler for WholeWordHash {
    fn name(&self) -> String {
        "whole-word-hash".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    fn claim(&self) -> gartowen::core::Claim {
        gartowen::core::Claim::OWEN
    }
    fn supports_width(&self, width: Width) -> bool {
        width == Width::W32
    }
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        // MurmurHash3's finalizer: a bijection of 32-bit words.
        let mut h = (x ^ self.key(dim)) as u32;
        h ^= h >> 16;
        h = h.wrapping_mul(0x85EB_CA6B);
        h ^= h >> 13;
        h = h.wrapping_mul(0xC2B2_AE35);
        (h ^ (h >> 16)) as u64
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for WholeWordHash {
    fn unscramble(&self, y: u64, _width: Width, dim: u32) -> u64 {
        // Each step undone in reverse: x ^= x >> 16 is an involution on 32 bits, x ^= x >> 13
        // is undone by x ^ (x >> 13) ^ (x >> 26), and the multipliers by their inverses mod 2^32.
        let mut h = y as u32;
        h ^= h >> 16;
        h = h.wrapping_mul(inverse_mod_2_32(0xC2B2_AE35));
        h ^= (h >> 13) ^ (h >> 26);
        h = h.wrapping_mul(inverse_mod_2_32(0x85EB_CA6B));
        h ^= h >> 16;
        (h as u64) ^ (self.key(dim) & 0xFFFF_FFFF)
    }
}

impl WholeWordHash {
    fn key(&self, dim: u32) -> u64 {
        hash_words(&[self.0, dim as u64])
    }
}

/// The inverse of an odd multiplier modulo 2^32 (Newton's iteration doubles the correct bits).
fn inverse_mod_2_32(a: u32) -> u32 {
    let mut x = a; // correct to 3 bits for odd a
    for _ in 0..4 {
        x = x.wrapping_mul(2u32.wrapping_sub(a.wrapping_mul(x)));
    }
    x
}

fn registry() -> Registry {
    fn hash(_: &ScramblerRequest, c: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
        Ok(Box::new(WholeWordHash(c.seed)))
    }
    // The built-in `digital-shift` (one random word per dimension, all points of a stratum
    // move together) is the other defect.
    let mut r = gartowen::registry();
    r.add(ScramblerSpec {
        name: "whole-word-hash",
        default_base: PowerOfTwoBase::B2,
        claim: gartowen::core::Claim::NESTED,
        summary: "test defect",
        build: hash,
    });
    r
}

fn bilinear() -> Vec<Box<dyn Family>> {
    vec![Box::new(Fixed {
        name: "bilinear".into(),
        smoothness: Smoothness::Smooth,
        f: Bilinear,
    })]
}

fn method(seq: &str, scrambler: &str) -> Method {
    Method {
        sequence: seq.into(),
        scrambler: scrambler.into(),
    }
}

fn slope(reg: &Registry, m: &Method, families: &[Box<dyn Family>]) -> f64 {
    let config = HarnessConfig {
        sizes: (6..=14).map(|k| 1usize << k).collect(),
        replicates: 32,
        seed: 11,
    };
    run_method(reg, m, families, &config).unwrap().curves[0]
        .slope
        .unwrap()
}

#[test]
fn random_points_have_the_monte_carlo_error() {
    // R·N·MSE/σ² is χ²_R for independent points (σ² = Var(xy) = 1/9 − 1/16); two-sided
    // test at α = 1e-3. A harness that divided by the wrong N or mixed replicates would fail.
    let reps = 200;
    let config = HarnessConfig {
        sizes: vec![1000],
        replicates: reps,
        seed: 5,
    };
    let r = run_method(&registry(), &method("random", ""), &bilinear(), &config).unwrap();
    let mse = r.curves[0].rmse[0].powi(2);
    let stat = reps as f64 * 1000.0 * mse / (1.0 / 9.0 - 1.0 / 16.0);
    let chi = ChiSquared::new(reps as f64).unwrap();
    let (lo, hi) = (chi.inverse_cdf(5e-4), chi.inverse_cdf(1.0 - 5e-4));
    assert!(
        lo < stat && stat < hi,
        "χ² statistic {stat} outside ({lo}, {hi})"
    );
}

#[test]
fn errors_are_identical_for_any_thread_count() {
    let fams: Vec<Box<dyn Family>> = vec![Box::new(HeavisideFamily { seed: 3 })];
    let config = HarnessConfig {
        sizes: vec![16, 100, 256],
        replicates: 12,
        seed: 9,
    };
    let reg = registry();
    let m = method("sz4", "q-art-4");
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| run_method(&reg, &m, &fams, &config).unwrap().curves)
    };
    let one = run(1);
    assert_eq!(one, run(2));
    assert_eq!(one, run(3));
}

#[test]
fn defective_scramblers_show_the_expected_rates() {
    let reg = registry();
    let fams = bilinear();
    let owen = slope(&reg, &method("sobol", "owen-oracle:base=2"), &fams);
    let none = slope(&reg, &method("sobol", "none"), &fams);
    let shift = slope(&reg, &method("sobol", "digital-shift"), &fams);
    let hash = slope(&reg, &method("sobol", "whole-word-hash"), &fams);
    eprintln!("slopes: owen {owen:.3}, none {none:.3}, shift {shift:.3}, hash {hash:.3}");
    // Nested uniform scrambling: N^-1.5 on a smooth integrand.
    assert!(owen < -1.3, "owen {owen}");
    // Unscrambled and digitally shifted nets keep the deterministic N^-1 rate.
    assert!((-1.2..-0.8).contains(&none), "none {none}");
    assert!((-1.2..-0.8).contains(&shift), "digital shift {shift}");
    // A non-nested hash makes the points independent: the Monte Carlo rate N^-0.5.
    assert!((-0.7..-0.3).contains(&hash), "whole-word hash {hash}");
}

#[test]
fn slopes_of_exact_power_laws_are_recovered() {
    let x: Vec<f64> = (4..12).map(|k| (1u64 << k) as f64).collect();
    let y: Vec<f64> = x.iter().map(|v| 3.0 * v.powf(-1.25)).collect();
    assert!((fit_slope(&x, &y).unwrap() + 1.25).abs() < 1e-12);
    assert_eq!(fit_slope(&x[..1], &y[..1]), None);
    assert_eq!(fit_slope(&x, &vec![0.0; x.len()]), None);
}

#[test]
fn scramblers_without_32_bit_words_are_refused() {
    let config = HarnessConfig {
        sizes: vec![16],
        replicates: 1,
        seed: 0,
    };
    let e = run_method(
        &registry(),
        &method("sobol", "owen-oracle:base=2"),
        &bilinear(),
        &config,
    );
    assert!(e.is_ok());
    let mut reg = gartowen::registry();
    fn wide(_: &ScramblerRequest, _: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
        struct Wide;
        impl Scrambler for Wide {
            fn name(&self) -> String {
                "wide".into()
            }
            fn base(&self) -> PowerOfTwoBase {
                PowerOfTwoBase::B2
            }
            fn claim(&self) -> gartowen::core::Claim {
                gartowen::core::Claim::NESTED
            }
            fn supports_width(&self, w: Width) -> bool {
                w == Width::W64
            }
            fn scramble(&self, x: u64, _: Width, _: u32) -> u64 {
                x
            }
            fn inverse(&self) -> Option<&dyn Unscramble> {
                Some(self)
            }
        }

        impl Unscramble for Wide {
            fn unscramble(&self, y: u64, _: Width, _: u32) -> u64 {
                y
            }
        }
        Ok(Box::new(Wide))
    }
    reg.add(ScramblerSpec {
        name: "wide",
        default_base: PowerOfTwoBase::B2,
        claim: gartowen::core::Claim::NESTED,
        summary: "64-bit only",
        build: wide,
    });
    let e = run_method(&reg, &method("sobol", "wide"), &bilinear(), &config).unwrap_err();
    assert!(e.to_string().contains("32-bit"), "{e}");
}
