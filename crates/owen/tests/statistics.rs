//! Statistical laws of the oracle's keyed draws at large sizes (≥ 10^4 scrambles, fixed seeds).
//!
//! Each family of chi-square tests uses α = 0.001 with Bonferroni over the family, so a correct
//! implementation fails a family with probability ≤ 0.001; seeds are fixed, so the outcome is
//! deterministic. Every statistic is also shown to reject a deliberately biased shuffle that
//! reduces small draws with `% n`.

use gartowen_core::{
    hash_words, DigitLayout, Permutation, PowerOfTwoBase, Scrambler, SplitMix64, Width,
};
use gartowen_oracles::inspector::NodeLaw;
use gartowen_owen::{FullTreeOwen, OwenVariant};
use statrs::distribution::{ChiSquared, ContinuousCDF};

const ALPHA: f64 = 1e-3;
const SCRAMBLES: u64 = 20_000;

fn critical(dof: usize, family: usize) -> f64 {
    ChiSquared::new(dof as f64)
        .unwrap()
        .inverse_cdf(1.0 - ALPHA / family as f64)
}

fn chi_square(counts: &[u64]) -> f64 {
    let total: u64 = counts.iter().sum();
    let e = total as f64 / counts.len() as f64;
    counts.iter().map(|&c| (c as f64 - e).powi(2) / e).sum()
}

/// A shuffle whose draws are 4 random bits reduced with `% (i+1)`: biased for most sizes.
fn biased_permutation(n: usize, rng: &mut SplitMix64) -> Permutation {
    let mut images: Vec<u8> = (0..n as u32).map(|d| d as u8).collect();
    for i in (1..n).rev() {
        let j = ((rng.next_u64() >> 60) as usize) % (i + 1);
        images.swap(i, j);
    }
    Permutation::from_images(&images).unwrap()
}

/// The cell counts of root-node permutations over many seeds: per-node uniformity.
fn root_node_cells(q: u32, perm_of_seed: &dyn Fn(u64) -> Permutation) -> Vec<u64> {
    let b = 1u32 << q;
    let cells = if b <= 4 {
        (1..=b as usize).product()
    } else if b == 256 {
        256
    } else {
        (b * (b - 1)) as usize
    };
    let mut counts = vec![0u64; cells];
    for seed in 0..SCRAMBLES {
        let p = perm_of_seed(seed);
        let cell = if b == 256 {
            p.apply(0) as usize
        } else {
            NodeLaw::cell(&p)
        };
        counts[cell] += 1;
    }
    counts
}

#[test]
fn node_permutations_are_uniform_and_the_biased_shuffle_is_rejected() {
    // Family: b = 4 (24 cells), 8 and 16 ((π(0), π(1)) law), 256 (marginal of π(0)).
    let qs = [2u32, 3, 4, 8];
    for q in qs {
        let base = PowerOfTwoBase::from_q(q).unwrap();
        let oracle = root_node_cells(q, &|seed| {
            FullTreeOwen::new(base, OwenVariant::Uniform, seed).node_permutation(
                Width::W32,
                0,
                1,
                1,
            )
        });
        let biased = root_node_cells(q, &|seed| {
            biased_permutation(1 << q, &mut SplitMix64::new(hash_words(&[seed])))
        });
        let crit = critical(oracle.len() - 1, qs.len());
        assert!(
            chi_square(&oracle) < crit,
            "q={q}: oracle chi2 {} ≥ {crit}",
            chi_square(&oracle)
        );
        assert!(
            chi_square(&biased) > crit,
            "q={q}: biased chi2 {} ≤ {crit}",
            chi_square(&biased)
        );
    }
}

#[test]
fn pairs_split_uniformly_over_distinct_digit_pairs() {
    // Owen's pair law at scale: x, x' share digit 0 and differ in digit 1; over seeds the pair of
    // output digits 1 is uniform over the b(b−1) distinct pairs. Family: b = 4, 16; two variants
    // are also run to show the test separates them (Xor fails, as the exact law predicts).
    let qs = [2u32, 4];
    for q in qs {
        let b = 1u64 << q;
        let base = PowerOfTwoBase::from_q(q).unwrap();
        let layout = DigitLayout::new(Width::W32, base);
        let x = layout.set(layout.set(0, 0, 1), 1, 0);
        let x2 = layout.set(layout.set(0, 0, 1), 1, 1);
        let cells = |variant: OwenVariant| {
            let mut counts = vec![0u64; (b * (b - 1)) as usize];
            for seed in 0..SCRAMBLES {
                let s = FullTreeOwen::new(base, variant, seed);
                let (y, y2) = (s.scramble(x, Width::W32, 0), s.scramble(x2, Width::W32, 0));
                assert_eq!(
                    layout.get(y, 0),
                    layout.get(y2, 0),
                    "shared digit stays shared"
                );
                let (u, v) = (layout.get(y, 1) as u64, layout.get(y2, 1) as u64);
                assert_ne!(u, v);
                counts[(u * (b - 1) + if v > u { v - 1 } else { v }) as usize] += 1;
            }
            counts
        };
        let crit = critical((b * (b - 1) - 1) as usize, qs.len());
        let uniform = cells(OwenVariant::Uniform);
        assert!(
            chi_square(&uniform) < crit,
            "q={q}: {}",
            chi_square(&uniform)
        );
        let xor = cells(OwenVariant::Xor);
        assert!(
            chi_square(&xor) > crit,
            "q={q}: Xor should fail the pair law: {}",
            chi_square(&xor)
        );
    }
}
