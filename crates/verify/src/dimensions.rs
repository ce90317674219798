//! Dimensions (`dimensions`): the scrambles of different dimensions must differ, and under an
//! independence claim they must be independent.
//!
//! * distinct: for each of S seeds, the 256 sampled words scrambled in each of dimensions
//!   0..64 (0..N when only N are served); two dimensions with identical outputs fail (a marginal claim includes that distinct
//!   dimensions are scrambled distinctly). Under any claimed law with ≥ 32 bits of randomness
//!   per dimension, a false alarm has probability < C(64,2)·S·2^-32.
//! * root pairs: the root permutations' π(0) of dimension pairs (0,1), (0,2), (1,2), (0,7),
//!   (3,8), (0,63), over independent seeds, against uniform × uniform (χ²); a pair beyond the
//!   dimensions served is not run.

use crate::expected::uniform;
use crate::family::{usable_dims, LawConfig, LawFamily, OwnPass};
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

/// Distinctness probes: the same sampled words in every dimension 0..64 that is served.
fn distinct_probes(cfg: &LawConfig) -> Vec<Probe> {
    let mut rng = SplitMix64::new(WORDS_SEED);
    let words: Vec<u64> = (0..DISTINCT_WORDS)
        .map(|_| cfg.tree.random_word(&mut rng))
        .collect();
    (0..usable_dims(cfg.max_dims, DISTINCT_DIMS))
        .map(|dim| Probe {
            dim,
            words: words.clone(),
            seeds: cfg.plan.distinct_seeds,
        })
        .collect()
}

/// One exact sub-test: the first seed and pair of dimensions that coincide, if any
/// (`outputs[seed][dim]`, dimensions 0..`dims`).
fn distinct_analyse(outputs: &[&[Vec<u64>]], dims: u32) -> SubTest {
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
                "dimensions 0..{dims} pairwise distinct on {DISTINCT_WORDS} words, {} seeds",
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
        power: format!("exact: any two of dimensions 0..{dims} equal on the sampled words"),
        deviates: false,
        not_run: None,
    }
}

/// The root pairs within the dimensions served.
fn served_pairs(cfg: &LawConfig) -> impl Iterator<Item = (u32, u32)> + '_ {
    ROOT_PAIRS
        .into_iter()
        .filter(|&(a, b)| cfg.beyond(a.max(b)).is_none())
}

/// Root-pair probes: the zero word in both dimensions of each pair served.
fn root_probes(cfg: &LawConfig) -> Vec<Probe> {
    served_pairs(cfg)
        .flat_map(|(a, b)| [a, b])
        .map(|dim| Probe {
            dim,
            words: vec![0],
            seeds: cfg.plan.law_seeds,
        })
        .collect()
}

/// χ² of (π_a(0), π_b(0)) per dimension pair; a pair beyond the dimensions served is not run.
fn root_analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let b = cfg.tree.b();
    let f = folded_size(b);
    let mut served = 0;
    ROOT_PAIRS
        .iter()
        .map(|&(da, db)| {
            let name = format!("root permutations of dimensions {da} and {db} independent");
            if let Some(why) = cfg.beyond(da.max(db)) {
                return SubTest::not_run(name, Some(0), Requirement::Independent, why);
            }
            let i = served;
            served += 1;
            let mut counts = vec![0u64; (f * f) as usize];
            for seed_out in outputs {
                let ya = fold(cfg.tree.digit(seed_out[2 * i][0], 0), b);
                let yb = fold(cfg.tree.digit(seed_out[2 * i + 1][0], 0), b);
                counts[(ya * f + yb) as usize] += 1;
            }
            SubTest::chi(
                name,
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
        let dims = probes.len() as u32;
        if dims < 2 {
            let name = format!("dimensions 0..{DISTINCT_DIMS} pairwise distinct");
            let why = cfg.beyond(dims).unwrap_or_default();
            return Ok(vec![SubTest::not_run(
                name,
                None,
                Requirement::Marginal,
                why,
            )]);
        }
        let out = pass.evaluate(0, &probes)?;
        let views: Vec<&[Vec<u64>]> = out.iter().map(|o| o.as_slice()).collect();
        Ok(vec![distinct_analyse(&views, dims)])
    }
}
