//! Runs the declared law families ([`FAMILIES`]) on one candidate: plans every family's
//! shared probes, evaluates them in one pass over the seeds (each instance built once), hands
//! each family its outputs, drops them, then runs the families' own passes.
//!
//! Adding a family is one module implementing [`LawFamily`] and one line in [`FAMILIES`].

use crate::candidate::Candidate;
use crate::collisions::Collisions;
use crate::dimensions::Dimensions;
use crate::family::{LawConfig, LawFamily, OwnPass};
use crate::flip_rank::FlipRank;
use crate::level::Level;
use crate::marginal::NodeLaw;
use crate::pair_law::PairLaw;
use crate::pair_lemma::PairLemma;
use crate::sampling::{evaluate, Probe, Tree};
use crate::structure::working_width;
use crate::subtest::SubTest;
use gartowen_core::DigitLayout;

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
    let probe = c.probe.as_ref();
    LawConfig {
        tree: Tree::new(DigitLayout::new(working_width(probe), probe.base())),
        claim: c.claim,
        plan: *level.plan(),
    }
}

/// The sub-tests of every family in [`FAMILIES`], named by family, in that order. Seeds are
/// `seed_base + i`.
pub fn run_laws(
    c: &Candidate,
    level: Level,
    seed_base: u64,
) -> Result<Vec<(&'static str, Vec<SubTest>)>, crate::error::BatteryError> {
    let cfg = config(c, level);
    let width = cfg.tree.layout.width();
    let groups: Vec<Vec<Probe>> = FAMILIES.iter().map(|f| f.shared_probes(&cfg)).collect();
    let all: Vec<Probe> = groups.iter().flatten().cloned().collect();
    let outputs = evaluate(c.with_seed.as_ref(), width, seed_base, &all)?;
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
        shared.push(family.analyse_shared(&cfg, &parts));
        offset += probes.len();
    }
    drop(outputs);
    let pass = OwnPass {
        with_seed: c.with_seed.as_ref(),
        width,
        seed_base,
    };
    FAMILIES
        .iter()
        .zip(shared)
        .map(|(family, shared_tests)| {
            let mut tests = family.own_pass(&cfg, &pass)?;
            tests.extend(shared_tests);
            Ok((family.name(), tests))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

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
