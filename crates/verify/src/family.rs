//! The protocol every law family follows ([`LawFamily`]), and the settings they share
//! ([`LawConfig`]). The declared list of families is [`crate::law_runner::FAMILIES`].
//!
//! A family plans probes (words to scramble in one dimension for the first n seeds). Probes of
//! the shared pass are evaluated once for all families, each seed's instance built once; a
//! family whose evaluation must be bounded or arranged otherwise (two seeds at a time, other
//! seed counts) runs a pass of its own through [`OwnPass`], after the shared outputs are
//! dropped. A family's sub-tests are its own pass's, then the shared pass's.

use crate::error::BatteryError;
use crate::level::LevelPlan;
use crate::sampling::{evaluate_with, ManySeeds, Outputs, Probe, SeedBuilder, Tree};
use crate::subtest::{Requirement, SubTest};
use gartowen_core::{Claim, NodeGroup, Width};

/// Settings shared by the law families.
#[derive(Debug, Clone, Copy)]
pub struct LawConfig {
    /// Layout of the words the battery sends.
    pub tree: Tree,
    /// The claim being judged (or, when nothing is claimed, the law measured against: Owen).
    pub claim: Claim,
    /// The level's sizes (seeds, depths, columns).
    pub plan: LevelPlan,
    /// The implementation serves dimensions 0..N only (`--max-dims N`); `None`: every one.
    pub max_dims: Option<u32>,
}

impl LawConfig {
    /// The group node permutations are tested against: the claimed one, else S_b.
    pub fn group(&self) -> NodeGroup {
        self.claim.marginal.unwrap_or(NodeGroup::Symmetric)
    }

    /// Why a sub-test using dimension `dim` cannot run, if the implementation does not serve
    /// it (see [`needs_dimension`]).
    pub fn beyond(&self, dim: u32) -> Option<String> {
        needs_dimension(self.max_dims, dim)
    }

    /// Depths 0..=max_depth that have a full digit.
    pub fn depths(&self) -> std::ops::RangeInclusive<u32> {
        0..=self
            .plan
            .max_depth
            .min(self.tree.full_digits().saturating_sub(1))
    }
}

/// Why a check using dimension `dim` cannot run when only dimensions 0..`max_dims` are served
/// (`needs dimension 63, beyond the 4 served`); `None` when it can.
pub fn needs_dimension(max_dims: Option<u32>, dim: u32) -> Option<String> {
    max_dims
        .filter(|&n| dim >= n)
        .map(|n| format!("needs dimension {dim}, beyond the {n} served"))
}

/// The number of dimensions `0..want` a check can use when `max_dims` are served.
pub fn usable_dims(max_dims: Option<u32>, want: u32) -> u32 {
    max_dims.map_or(want, |n| n.min(want))
}

/// A family's own evaluation: instances of the candidate for seeds `seed_base + i`.
pub struct OwnPass<'a, 'b> {
    /// Instances per seed.
    pub with_seed: &'a SeedBuilder<'b>,
    /// Many seeds per call, where the implementation offers it.
    pub many: Option<&'a ManySeeds<'b>>,
    /// The width words are scrambled at.
    pub width: Width,
    /// The run's first seed.
    pub seed_base: u64,
    /// Words scrambled through this pass so far (for the time profile).
    pub words: std::cell::Cell<u64>,
}

impl OwnPass<'_, '_> {
    /// Scrambles `probes` for seeds `seed_base + first + i`, i in `0..max(probe.seeds)`.
    pub fn evaluate(&self, first: u64, probes: &[Probe]) -> Result<Outputs, BatteryError> {
        self.words.set(self.words.get() + words_of(probes));
        evaluate_with(
            self.with_seed,
            self.many,
            self.width,
            self.seed_base.wrapping_add(first),
            probes,
        )
    }
}

/// The words a pass over `probes` scrambles: each probe's words for each of its seeds.
pub fn words_of(probes: &[Probe]) -> u64 {
    probes.iter().map(|p| p.words.len() as u64 * p.seeds).sum()
}

/// One family of law sub-tests.
pub trait LawFamily {
    /// The check's name in reports (`node-law`, `pair-law`, …).
    fn name(&self) -> &'static str;

    /// What its sub-tests require of a claim to be judged (distinct requirements, in the order
    /// they appear).
    fn requires(&self) -> &'static [Requirement];

    /// What it tests, in one line (for listings).
    fn what(&self) -> &'static str;

    /// Probes evaluated in the pass shared by every family.
    fn shared_probes(&self, _cfg: &LawConfig) -> Vec<Probe> {
        Vec::new()
    }

    /// Sub-tests from this family's shared-pass outputs: `outputs[seed][k]` answers probe k of
    /// [`LawFamily::shared_probes`], for the seeds those probes asked for.
    fn analyse_shared(&self, _cfg: &LawConfig, _outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
        Vec::new()
    }

    /// Sub-tests from a pass of the family's own, run after the shared outputs are dropped.
    fn own_pass(&self, _cfg: &LawConfig, _pass: &OwnPass) -> Result<Vec<SubTest>, BatteryError> {
        Ok(Vec::new())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dimension_is_served_below_the_count_and_checks_use_at_most_it() {
        assert_eq!(needs_dimension(None, 1000), None);
        assert_eq!(needs_dimension(Some(4), 3), None);
        assert_eq!(
            needs_dimension(Some(4), 4).as_deref(),
            Some("needs dimension 4, beyond the 4 served")
        );
        assert_eq!(usable_dims(None, 64), 64);
        assert_eq!(usable_dims(Some(4), 64), 4);
        assert_eq!(usable_dims(Some(100), 64), 64);
    }
}
