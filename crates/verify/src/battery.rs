//! The conformance battery behind `gartowen verify`: every check runs on any registered
//! scrambler as a black box, so external and deliberately broken implementations are judged
//! the same way. This module only orchestrates; what runs is declared in two lists:
//!
//! * the structure checks, [`STRUCTURE_CHECKS`] ([`crate::structure`]): `inverse` or
//!   `injective`, `nested`, `nets` and, after the laws, `expect`;
//! * the law families, [`crate::law_runner::FAMILIES`]: `node-law` (marginal, by depth),
//!   `pair-law`, `flip-rank`, `collisions` (joint), `pair-lemma` and `dimensions`. Each
//!   sub-test states what it requires (a marginal law or independence), its p-value, and its
//!   power; a check gets a verdict only when the implementation claims what it tests, and is
//!   `measured` otherwise ([`crate::judge`]). The family-wise level of a run is
//!   [`crate::stats::FAMILY_ALPHA`] = 10^-3, split evenly (Bonferroni) over the implementations
//!   judged and their judged sub-tests.
//!
//! Every size comes from the level's [`LevelPlan`].

pub use crate::candidate::{
    external_candidate, names_or_all, radix_candidate, radix_seeds, registry_candidate,
    registry_seeds, Candidate,
};
pub use crate::judge::{judge_families, profile};
pub use crate::level::{Level, LevelPlan};
pub use crate::structure::{
    Stage, StructureCheck, FUNCTION_SEED, INVERSE_SEED, PROBE_SEED, STRUCTURE_CHECKS, TWIN_SEED,
};
pub use crate::verdict::{CheckResult, ImplReport, Verdict};

use crate::error::MergeError;
use crate::law_runner::run_laws_timed;
use crate::subtest::SubTest;
use gartowen_core::{Claim, CoreError, Progress, Registry, Silent};
use rayon::prelude::*;
use std::time::Instant;

/// Which part of the list to run: shard `index` (1-based) of `count`; implementation k goes to
/// shard (k mod count) + 1, so shards are deterministic and disjoint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// 1-based shard number.
    pub index: usize,
    /// Number of shards.
    pub count: usize,
}

impl Shard {
    /// The whole list.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// Parses `I/N` with 1 ≤ I ≤ N.
    pub fn parse(text: &str) -> Option<Shard> {
        let (i, n) = text.split_once('/')?;
        let (index, count) = (i.trim().parse().ok()?, n.trim().parse().ok()?);
        (count >= 1 && (1..=count).contains(&index)).then_some(Shard { index, count })
    }

    /// Whether implementation k belongs to this shard.
    pub fn contains(&self, k: usize) -> bool {
        k % self.count + 1 == self.index
    }
}

/// Merges shard reports into one list in implementation order: exactly `total`
/// implementations, each once, every one with the same checks in the same order. Errors name
/// the duplicate, the missing implementation or the odd check list.
pub fn merge(parts: Vec<Vec<ImplReport>>, total: usize) -> Result<Vec<ImplReport>, MergeError> {
    let mut all: Vec<ImplReport> = parts.into_iter().flatten().collect();
    all.sort_by_key(|r| r.index);
    if let Some(w) = all.windows(2).find(|w| w[0].index == w[1].index) {
        return Err(MergeError::Duplicate {
            index: w[0].index,
            name: w[0].name.clone(),
        });
    }
    if let Some((k, r)) = all.iter().enumerate().find(|(k, r)| r.index != *k) {
        return Err(MergeError::Missing {
            index: k,
            next: (r.name.clone(), r.index),
        });
    }
    if all.len() != total {
        return Err(MergeError::Short {
            present: all.len(),
            total,
        });
    }
    let names = |r: &ImplReport| r.checks.iter().map(|c| c.check.clone()).collect::<Vec<_>>();
    if let Some(first) = all.first() {
        let want = names(first);
        if let Some(r) = all.iter().find(|r| names(r) != want) {
            return Err(MergeError::Checks {
                index: r.index,
                name: r.name.clone(),
                checks: names(r),
                expected: want,
            });
        }
    }
    Ok(all)
}

/// Every fixed seed the battery uses: the main instance's seed, then the seeds of the inverse
/// sample, the inspector's probes, the twin comparison and the `function` check's words. Law instances use seeds
/// 0..[`LevelPlan::law_seeds`] (and fewer for flip-rank, collisions and dimensions).
pub fn seeds_used(main_seed: u64) -> Vec<u64> {
    vec![
        main_seed,
        INVERSE_SEED,
        PROBE_SEED,
        TWIN_SEED,
        FUNCTION_SEED,
    ]
}

/// Runs a structure check, timed; a transport failure found afterwards turns it into a
/// failure naming it.
fn run_structure(c: &Candidate, check: &StructureCheck, plan: &LevelPlan) -> CheckResult {
    let t = Instant::now();
    let outcome = (check.run)(c, plan);
    CheckResult::from_outcome(check.name, outcome, t.elapsed().as_secs_f64())
}

/// Runs every check on one candidate: the structure checks of [`STRUCTURE_CHECKS`] that apply
/// to it (those of [`Stage::BeforeLaws`] first), the law families of
/// [`crate::law_runner::FAMILIES`], then the [`Stage::AfterLaws`] checks. `judged` is the
/// number of implementations in the whole run whose claims get law verdicts (the Bonferroni
/// divisor of [`crate::stats::FAMILY_ALPHA`]).
pub fn check_candidate(c: &Candidate, level: Level, judged: usize) -> ImplReport {
    let plan = level.plan();
    // A transport failure turns the check that met it into a failure naming it; its
    // sub-tests measured the failure's zeros, not the program, so they count as not run (the
    // profile shows `?` for them, never deviations).
    let guard = |mut r: CheckResult| {
        // A check that did not run (flip-rank outside bases 2^q, a dimension beyond those
        // served) asked the program nothing: its failure is not this check's.
        if r.verdict == Verdict::NotRun {
            return r;
        }
        if let Some(e) = (c.health)() {
            r.verdict = Verdict::Fail;
            r.detail = format!("external program failed: {e}");
            r.value = None;
            r.p_value = None;
            for t in &mut r.tests {
                *t = SubTest::not_run(
                    std::mem::take(&mut t.name),
                    t.depth,
                    t.requires,
                    "external program failed",
                );
            }
        }
        r
    };
    let structure = |stage: Stage| {
        STRUCTURE_CHECKS
            .iter()
            .filter(move |s| s.stage == stage && (s.applies)(c))
            .map(|s| guard(run_structure(c, s, plan)))
    };
    let mut checks: Vec<CheckResult> = structure(Stage::BeforeLaws).collect();
    let started = Instant::now();
    match run_laws_timed(c, level, 0) {
        Ok(runs) => {
            let costs: Vec<(f64, u64)> = runs.iter().map(|f| (f.seconds, f.words)).collect();
            let families = runs.into_iter().map(|f| (f.name, f.tests)).collect();
            let results = judge_families(families, c.claim, judged, 0.0);
            checks.extend(
                results
                    .into_iter()
                    .zip(costs)
                    .map(|(mut r, (seconds, words))| {
                        r.seconds = seconds;
                        r.words = Some(words);
                        guard(r)
                    }),
            );
        }
        Err(e) => checks.push(guard(CheckResult {
            check: "laws".into(),
            verdict: Verdict::Fail,
            detail: format!("the laws could not run: {e}"),
            value: None,
            seconds: started.elapsed().as_secs_f64(),
            words: None,
            p_value: None,
            alpha: None,
            tests: Vec::new(),
        })),
    }
    checks.extend(structure(Stage::AfterLaws));
    let profile = profile(&checks);
    ImplReport {
        index: c.index,
        name: c.name.clone(),
        base: c.base(),
        claims_nested_uniform: c.claim.is_owen(),
        claim: c.claim.to_string(),
        checks,
        profile,
    }
}

/// Runs the battery on the named implementations (all of the registry's when `names` is empty).
pub fn verify(
    registry: &Registry,
    names: &[String],
    level: Level,
) -> Result<Vec<ImplReport>, CoreError> {
    verify_shard(registry, names, level, Shard::ALL, None, &Silent)
}

/// [`verify`] restricted to one shard, judging every implementation on `claim` when given
/// (else on its own claim). `progress` starts with the shard's number of implementations and
/// advances by one after each, its message the implementation's name.
pub fn verify_shard(
    registry: &Registry,
    names: &[String],
    level: Level,
    shard: Shard,
    claim: Option<Claim>,
    progress: &dyn Progress,
) -> Result<Vec<ImplReport>, CoreError> {
    let names = names_or_all(registry, names);
    let judged = names
        .iter()
        .filter_map(|n| registry_candidate(registry, n, 0).ok())
        .filter(|c| claim.unwrap_or(c.claim).marginal.is_some())
        .count();
    let mine = (0..names.len()).filter(|k| shard.contains(*k)).count();
    progress.start(mine as u64, "implementations");
    // Implementations are checked in parallel (each one's seeds too, in the same pool): the
    // analysis between two evaluation passes is serial and leaves a core idle otherwise.
    // Reports come back in list order, and no report depends on another.
    let out = names
        .par_iter()
        .enumerate()
        .filter(|(k, _)| shard.contains(*k))
        .map(|(index, name)| {
            let mut candidate = registry_candidate(registry, name, index)?;
            if let Some(c) = claim {
                candidate.claim = c.in_base(candidate.base())?;
            }
            let report = check_candidate(&candidate, level, judged);
            progress.message(name);
            progress.advance(1);
            Ok(report)
        })
        .collect::<Result<Vec<_>, CoreError>>();
    progress.finish();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verdict::fixtures;

    fn report(index: usize, checks: &[&str]) -> ImplReport {
        let checks = checks
            .iter()
            .map(|c| fixtures::check(c, 0.0, None))
            .collect();
        fixtures::report(index, &format!("impl-{index}"), checks)
    }

    #[test]
    fn merge_restores_order_and_names_what_is_wrong() {
        let ab = &["inverse", "nested"];
        let merged = merge(
            vec![vec![report(2, ab)], vec![report(0, ab), report(1, ab)]],
            3,
        );
        let order: Vec<usize> = merged.unwrap().iter().map(|r| r.index).collect();
        assert_eq!(order, [0, 1, 2]);
        assert_eq!(
            merge(
                vec![vec![report(0, ab), report(1, ab)], vec![report(1, ab)]],
                2
            ),
            Err(MergeError::Duplicate {
                index: 1,
                name: "impl-1".into()
            })
        );
        assert_eq!(
            merge(vec![vec![report(0, ab)], vec![report(2, ab)]], 3),
            Err(MergeError::Missing {
                index: 1,
                next: ("impl-2".into(), 2)
            })
        );
        let short = merge(vec![vec![report(0, ab), report(1, ab)]], 4).unwrap_err();
        assert_eq!(
            short,
            MergeError::Short {
                present: 2,
                total: 4
            }
        );
        assert_eq!(
            short.to_string(),
            "2 of 4 implementations present: 2 to 3 are missing"
        );
        let odd = merge(vec![vec![report(0, ab), report(1, &["inverse"])]], 2).unwrap_err();
        assert_eq!(
            odd,
            MergeError::Checks {
                index: 1,
                name: "impl-1".into(),
                checks: vec!["inverse".into()],
                expected: vec!["inverse".into(), "nested".into()],
            }
        );
    }
}
