//! Dimensions (`dimensions`): the scrambles of different dimensions must differ, and under an
//! independence claim they must be independent.
//!
//! * distinct: for each of S seeds, the 256 sampled words scrambled in each of dimensions
//!   0..64; two dimensions with identical outputs fail (a marginal claim includes that distinct
//!   dimensions are scrambled distinctly). Under any claimed law with ≥ 32 bits of randomness
//!   per dimension, a false alarm has probability < C(64,2)·S·2^-32.
//! * root pairs: the root permutations' π(0) of dimension pairs (0,1), (0,2), (1,2), (0,7),
//!   (3,8), (0,63), over independent seeds, against uniform × uniform (χ²).

use crate::expected::uniform;
use crate::family::{LawConfig, LawFamily, OwnPass};
use crate::sampling::{fold, folded_size, Probe};
use crate::stats::chi_square;
use crate::subtest::{Requirement, SubTest};
use gartowen_core::SplitMix64;
use std::collections::HashMap;

const WORDS_SEED: u64 = 0x6469_6d73; // "dims"
/// Dimensions compared for distinctness.
pub const DISTINCT_DIMS: u32 = 64;
/// Sampled words per dimension.
pub const DISTINCT_WORDS: usize = 256;
const ROOT_PAIRS: [(u32, u32); 6] = [(0, 1), (0, 2), (1, 2), (0, 7), (3, 8), (0, 63)];

/// Distinctness probes: the same sampled words in every dimension 0..64.
fn distinct_probes(cfg: &LawConfig) -> Vec<Probe> {
    let mask = cfg.tree.layout.width().mask();
    let mut rng = SplitMix64::new(WORDS_SEED);
    let words: Vec<u64> = (0..DISTINCT_WORDS).map(|_| rng.next_u64() & mask).collect();
    (0..DISTINCT_DIMS)
        .map(|dim| Probe {
            dim,
            words: words.clone(),
            seeds: cfg.plan.distinct_seeds,
        })
        .collect()
}

/// One exact sub-test: the first seed and pair of dimensions that coincide, if any.
fn distinct_analyse(outputs: &[&[Vec<u64>]]) -> SubTest {
    let mut equal_pairs = 0u64;
    let mut first = None;
    for (seed, seed_out) in outputs.iter().enumerate() {
        let mut seen: HashMap<&[u64], u32> = HashMap::new();
        for (dim, out) in seed_out.iter().enumerate() {
            if let Some(&other) = seen.get(out.as_slice()) {
                equal_pairs += 1;
                first.get_or_insert((seed, other, dim));
            } else {
                seen.insert(out.as_slice(), dim as u32);
            }
        }
    }
    SubTest {
        name: match first {
            None => format!(
                "dimensions 0..{DISTINCT_DIMS} pairwise distinct on {DISTINCT_WORDS} words, {} seeds",
                outputs.len()
            ),
            Some((seed, a, b)) => format!(
                "{equal_pairs} coinciding dimension pair(s); first: seed {seed}, dimensions {a} and {b} scramble {DISTINCT_WORDS} words identically"
            ),
        },
        depth: None,
        requires: Requirement::Marginal,
        statistic: equal_pairs as f64,
        p_value: if equal_pairs == 0 { 1.0 } else { 0.0 },
        n: outputs.len() as u64,
        dof: None,
        power: format!("exact: any two of dimensions 0..{DISTINCT_DIMS} equal on the sampled words"),
        deviates: false,
    }
}

/// Root-pair probes: the zero word in both dimensions of each pair.
fn root_probes(cfg: &LawConfig) -> Vec<Probe> {
    ROOT_PAIRS
        .iter()
        .flat_map(|&(a, b)| [a, b])
        .map(|dim| Probe {
            dim,
            words: vec![0],
            seeds: cfg.plan.law_seeds,
        })
        .collect()
}

/// χ² of (π_a(0), π_b(0)) per dimension pair.
fn root_analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let b = cfg.tree.b();
    let f = folded_size(b);
    ROOT_PAIRS
        .iter()
        .enumerate()
        .map(|(i, &(da, db))| {
            let mut counts = vec![0u64; (f * f) as usize];
            for seed_out in outputs {
                let ya = fold(cfg.tree.digit(seed_out[2 * i][0], 0), b);
                let yb = fold(cfg.tree.digit(seed_out[2 * i + 1][0], 0), b);
                counts[(ya * f + yb) as usize] += 1;
            }
            SubTest::chi(
                format!("root permutations of dimensions {da} and {db} independent"),
                Some(0),
                Requirement::Independent,
                chi_square(&counts, &uniform(counts.len())),
            )
        })
        .collect()
}

/// The `dimensions` family: the distinct test in a pass of its own (its own seed count), the
/// root pairs in the shared pass.
pub struct Dimensions;

impl LawFamily for Dimensions {
    fn name(&self) -> &'static str {
        "dimensions"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Marginal, Requirement::Independent]
    }

    fn what(&self) -> &'static str {
        "dimensions 0..64 distinct on 256 words; root permutations of 6 dimension pairs independent"
    }

    fn shared_probes(&self, cfg: &LawConfig) -> Vec<Probe> {
        root_probes(cfg)
    }

    fn analyse_shared(&self, cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
        root_analyse(cfg, outputs)
    }

    fn own_pass(
        &self,
        cfg: &LawConfig,
        pass: &OwnPass,
    ) -> Result<Vec<SubTest>, crate::error::BatteryError> {
        let probes = distinct_probes(cfg);
        let out = pass.evaluate(0, &probes)?;
        let views: Vec<&[Vec<u64>]> = out.iter().map(|o| o.as_slice()).collect();
        Ok(vec![distinct_analyse(&views)])
    }
}
