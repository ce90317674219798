//! Owen's pair lemma, end to end (`pair-lemma`): two inputs whose base-b digits first differ at
//! digit r. Under nested uniform scrambling their outputs share digits 0..r exactly (checked by
//! `nested`), their digits r are two distinct uniform digits (the node at depth r is applied to
//! two distinct digits), and their digits r + 1 are independent and uniform (two different
//! nodes). For every r up to the depth tested, one fixed input pair is scrambled over
//! independent seeds:
//!
//! * digit r: (y_r, y'_r) against the law of (π(x_r), π(x'_r)) for π uniform over the claimed
//!   group (distinct uniform pairs for S_b and AGL; a fixed difference for translations and
//!   shifts), folded to ≤ 16 × 16 cells: a marginal claim;
//! * digit r + 1: (y_{r+1}, y'_{r+1}) against uniform × uniform: an independence claim. A digital
//!   shift fails it at every r (y ⊕ y' is the inputs' difference).

use crate::expected::{pair_image_law, uniform};
use crate::family::{LawConfig, LawFamily};
use crate::sampling::{fold, folded_size, Probe};
use crate::stats::chi_square;
use crate::subtest::{Requirement, SubTest};
use gartowen_core::SplitMix64;

const LEMMA_SEED: u64 = 0x6c65_6d6d; // "lemm"

/// The input pair for each r: random words, the second's digit r changed and its later digits
/// redrawn.
fn pairs(cfg: &LawConfig) -> Vec<(u32, u64, u64)> {
    let tree = &cfg.tree;
    let mut rng = SplitMix64::new(LEMMA_SEED);
    cfg.depths()
        .filter(|&r| r + 1 < tree.full_digits())
        .map(|r| {
            let u = tree.random_word(&mut rng);
            let mut v = tree.random_word(&mut rng);
            for k in 0..r {
                v = tree.set(v, k, tree.digit(u, k));
            }
            let ur = tree.digit(u, r);
            v = tree.set(v, r, (ur + 1 + rng.bounded(tree.b() - 1)) % tree.b());
            (r, u, v)
        })
        .collect()
}

/// One probe per r: the two words.
fn probes(cfg: &LawConfig) -> Vec<Probe> {
    pairs(cfg)
        .into_iter()
        .map(|(_, u, v)| Probe {
            dim: 0,
            words: vec![u, v],
            seeds: cfg.plan.law_seeds,
        })
        .collect()
}

/// Two χ² sub-tests per r.
fn analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let tree = &cfg.tree;
    let b = tree.b();
    let f = folded_size(b) as usize;
    let mut tests = Vec::new();
    for (i, (r, u, v)) in pairs(cfg).into_iter().enumerate() {
        let mut at_r = vec![0u64; f * f];
        let mut after = vec![0u64; f * f];
        for seed_out in outputs {
            let (yu, yv) = (seed_out[i][0], seed_out[i][1]);
            let cell = |k: u32| {
                fold(tree.digit(yu, k), b) as usize * f + fold(tree.digit(yv, k), b) as usize
            };
            at_r[cell(r)] += 1;
            after[cell(r + 1)] += 1;
        }
        let (xr, xr2) = (tree.digit(u, r), tree.digit(v, r));
        // Binary words read best in hex; base-b digit integers in decimal.
        let (u, v) = match tree.power_of_two() {
            Some(_) => (format!("{u:#x}"), format!("{v:#x}")),
            None => (u.to_string(), v.to_string()),
        };
        tests.push(SubTest::chi(
            format!("r = {r}: output digits {r} of inputs {u}, {v} (distinct, uniform)"),
            Some(r),
            Requirement::Marginal,
            chi_square(&at_r, &pair_image_law(cfg.group(), b, xr, xr2)),
        ));
        tests.push(SubTest::chi(
            format!(
                "r = {r}: output digits {} of inputs {u}, {v} (independent, uniform)",
                r + 1
            ),
            Some(r + 1),
            Requirement::Independent,
            chi_square(&after, &uniform(f * f)),
        ));
    }
    tests
}

/// The `pair-lemma` family.
pub struct PairLemma;

impl LawFamily for PairLemma {
    fn name(&self) -> &'static str {
        "pair-lemma"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Marginal, Requirement::Independent]
    }

    fn what(&self) -> &'static str {
        "inputs first differing at digit r: digits r distinct and uniform; digits r+1 independent and uniform"
    }

    fn shared_probes(&self, cfg: &LawConfig) -> Vec<Probe> {
        probes(cfg)
    }

    fn analyse_shared(&self, cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
        analyse(cfg, outputs)
    }
}
