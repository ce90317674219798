//! Runs the declared law families ([`FAMILIES`]) on one candidate: plans every family's
//! shared probes, evaluates them in one pass over the seeds (each instance built once), hands
//! each family its outputs, drops them, then runs the families' own passes.
//!
//! Adding a family is one module implementing [`LawFamily`] and one line in [`FAMILIES`].

use crate::candidate::Candidate;
use crate::collisions::Collisions;
use crate::dimensions::Dimensions;
use crate::family::{words_of, LawConfig, LawFamily, OwnPass};
use crate::flip_rank::FlipRank;
use crate::level::Level;
use crate::marginal::NodeLaw;
use crate::pair_law::PairLaw;
use crate::pair_lemma::PairLemma;
use crate::sampling::{evaluate_with, Probe};
use crate::structure::{candidate_tree, working_width};
use crate::subtest::SubTest;
use std::cell::Cell;
use std::time::Instant;

/// Every law family the battery runs, in report order.
pub const FAMILIES: [&dyn LawFamily; 6] = [
    &NodeLaw,
    &PairLaw,
    &FlipRank,
    &Collisions,
    &PairLemma,
    &Dimensions,
];

/// The law settings of candidate `c` at `level`: its working width and base, its claim, the
/// level's plan.
pub fn config(c: &Candidate, level: Level) -> LawConfig {
    LawConfig {
        tree: candidate_tree(c, working_width(c.probe.as_ref())),
        claim: c.claim,
        plan: *level.plan(),
        max_dims: c.max_dims,
    }
}

/// One family's sub-tests with what they cost.
#[derive(Debug, Clone)]
pub struct FamilyRun {
    /// The family's name.
    pub name: &'static str,
    /// Its sub-tests: its own pass's, then the shared pass's.
    pub tests: Vec<SubTest>,
    /// Wall seconds: its share of the shared evaluation (by words), its analysis and its own
    /// pass.
    pub seconds: f64,
    /// Words scrambled for it, shared pass and own pass.
    pub words: u64,
}

/// The sub-tests of every family in [`FAMILIES`], named by family, in that order. Seeds are
/// `seed_base + i`.
pub fn run_laws(
    c: &Candidate,
    level: Level,
    seed_base: u64,
) -> Result<Vec<(&'static str, Vec<SubTest>)>, crate::error::BatteryError> {
    Ok(run_laws_timed(c, level, seed_base)?
        .into_iter()
        .map(|f| (f.name, f.tests))
        .collect())
}

/// [`run_laws`] with each family's seconds and words scrambled.
pub fn run_laws_timed(
    c: &Candidate,
    level: Level,
    seed_base: u64,
) -> Result<Vec<FamilyRun>, crate::error::BatteryError> {
    let cfg = config(c, level);
    let width = cfg.tree.width();
    let groups: Vec<Vec<Probe>> = FAMILIES.iter().map(|f| f.shared_probes(&cfg)).collect();
    let all: Vec<Probe> = groups.iter().flatten().cloned().collect();
    let started = Instant::now();
    let outputs = evaluate_with(
        c.with_seed.as_ref(),
        c.many.as_deref(),
        width,
        seed_base,
        &all,
    )?;
    let evaluation = started.elapsed().as_secs_f64();
    let total_words = words_of(&all).max(1);
    let mut shared = Vec::with_capacity(FAMILIES.len());
    let mut offset = 0;
    for (family, probes) in FAMILIES.iter().zip(&groups) {
        // A family sees the seeds its probes asked for, and only its own probes.
        let seeds = probes.iter().map(|p| p.seeds).max().unwrap_or(0) as usize;
        let parts: Vec<&[Vec<u64>]> = outputs
            .iter()
            .take(seeds)
            .map(|o| &o[offset..offset + probes.len()])
            .collect();
        let started = Instant::now();
        let tests = family.analyse_shared(&cfg, &parts);
        let words = words_of(probes);
        let share = evaluation * words as f64 / total_words as f64;
        shared.push((tests, share + started.elapsed().as_secs_f64(), words));
        offset += probes.len();
    }
    drop(outputs);
    FAMILIES
        .iter()
        .zip(shared)
        .map(|(family, (shared_tests, seconds, words))| {
            let pass = OwnPass {
                with_seed: c.with_seed.as_ref(),
                many: c.many.as_deref(),
                width,
                seed_base,
                words: Cell::new(0),
            };
            let started = Instant::now();
            let mut tests = family.own_pass(&cfg, &pass)?;
            tests.extend(shared_tests);
            Ok(FamilyRun {
                name: family.name(),
                tests,
                seconds: seconds + started.elapsed().as_secs_f64(),
                words: words + pass.words.get(),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, Width};
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::Arc;

    /// A base-4 nested scramble (a per-seed XOR) that counts every word it is asked for.
    struct Counting {
        seed: u64,
        words: Arc<AtomicU64>,
    }

    impl Scrambler for Counting {
        fn name(&self) -> String {
            "counting".into()
        }
        fn base(&self) -> PowerOfTwoBase {
            PowerOfTwoBase::B4
        }
        fn claim(&self) -> Claim {
            Claim::NESTED
        }
        fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 {
            self.words.fetch_add(1, Ordering::Relaxed);
            (x ^ self.seed.wrapping_mul(0x9E37_79B9_7F4A_7C15)) & width.mask()
        }
    }

    #[test]
    fn the_words_each_family_reports_add_up_to_the_words_scrambled() {
        let words = Arc::new(AtomicU64::new(0));
        let counter = words.clone();
        let c = Candidate::from_builder(
            "counting",
            Claim::NESTED,
            Box::new(move |seed| {
                Ok(Box::new(Counting {
                    seed,
                    words: counter.clone(),
                }))
            }),
        )
        .unwrap();
        let before = words.load(Ordering::Relaxed);
        let runs = run_laws_timed(&c, Level::Quick, 0).unwrap();
        let scrambled = words.load(Ordering::Relaxed) - before;
        let reported: u64 = runs.iter().map(|f| f.words).sum();
        assert_eq!(reported, scrambled);
        assert!(
            runs.iter().all(|f| f.words > 0 && f.seconds >= 0.0),
            "{runs:?}"
        );
        let names: Vec<&str> = runs.iter().map(|f| f.name).collect();
        let declared: Vec<&str> = FAMILIES.iter().map(|f| f.name()).collect();
        assert_eq!(names, declared);
        // The untimed form returns the same sub-tests.
        let plain = run_laws(&c, Level::Quick, 0).unwrap();
        for (f, (name, tests)) in runs.iter().zip(&plain) {
            assert_eq!((f.name, f.tests.len()), (*name, tests.len()));
        }
    }

    /// A per-seed XOR (nested) that refuses, by panicking, any dimension from 4 on.
    struct FourDims(u64);

    impl Scrambler for FourDims {
        fn name(&self) -> String {
            "four-dims".into()
        }
        fn base(&self) -> PowerOfTwoBase {
            PowerOfTwoBase::B2
        }
        fn claim(&self) -> Claim {
            Claim::OWEN
        }
        fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
            assert!(dim < 4, "asked for dimension {dim}");
            let key = gartowen_core::hash_words(&[self.0, u64::from(dim)]);
            (x ^ key) & width.mask()
        }
    }

    #[test]
    fn served_dimensions_bound_every_request_and_the_rest_is_not_run() {
        let mut c = Candidate::from_builder(
            "four-dims",
            Claim::OWEN,
            Box::new(|seed| Ok(Box::new(FourDims(seed)))),
        )
        .unwrap();
        c.max_dims = Some(4);
        let runs = run_laws(&c, Level::Quick, 0).unwrap();
        let not_run: Vec<(&str, &str)> = runs
            .iter()
            .flat_map(|(family, tests)| tests.iter().map(move |t| (*family, t)))
            .filter_map(|(family, t)| t.not_run.as_deref().map(|why| (family, why)))
            .collect();
        assert_eq!(
            not_run,
            [
                ("dimensions", "needs dimension 7, beyond the 4 served"),
                ("dimensions", "needs dimension 8, beyond the 4 served"),
                ("dimensions", "needs dimension 63, beyond the 4 served"),
            ]
        );
        let distinct = &runs.iter().find(|(f, _)| *f == "dimensions").unwrap().1[0];
        assert!(distinct
            .name
            .starts_with("dimensions 0..4 pairwise distinct"));
        // One dimension: flip-rank and distinctness need a second one; the rest runs.
        c.max_dims = Some(1);
        for (family, tests) in run_laws(&c, Level::Quick, 0).unwrap() {
            let skipped = tests.iter().filter(|t| !t.ran()).count();
            match family {
                "flip-rank" => assert!(skipped == tests.len() && skipped > 0),
                "dimensions" => assert_eq!(skipped, tests.len()),
                _ => assert_eq!(skipped, 0, "{family}"),
            }
        }
    }

    #[test]
    fn families_have_distinct_names_and_state_what_they_require() {
        let mut names: Vec<&str> = FAMILIES.iter().map(|f| f.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), FAMILIES.len());
        assert!(FAMILIES.iter().all(|f| !f.requires().is_empty()));
        assert!(FAMILIES.iter().all(|f| !f.what().is_empty()));
    }
}
