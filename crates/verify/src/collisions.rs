//! `collisions`: within one seed, the subtree maps of height h below many nodes of a depth,
//! normalized by XOR with the image of the zero path. Two independent Owen subtrees agree (up
//! to that normalization) with probability b^h / |G|^N, N = (b^h − 1)/(b − 1) nodes, so the
//! count of equal pairs is Poisson with a tiny mean; a finite table that reuses one symbol's
//! subtree under many nodes (ART) shows collisions wherever nodes outnumber symbols.

use crate::family::{LawConfig, LawFamily, OwnPass};
use crate::sampling::{prefix_name, Probe};
use crate::stats::poisson_sf;
use crate::subtest::{Requirement, SubTest};
use gartowen_core::SplitMix64;
use std::collections::HashMap;

const COLLISION_SEED: u64 = 0x636f_6c6c; // "coll"

/// The collision plan: subtree height h, nodes per depth, depths, seeds.
#[derive(Debug, Clone)]
pub struct CollisionPlan {
    /// Subtree height.
    pub height: u32,
    /// (depth, prefixes) tested.
    pub depths: Vec<(u32, Vec<Vec<u32>>)>,
    /// Seeds (each a separate instance).
    pub seeds: u64,
    /// log2 of P(two independent subtrees collide) under the claimed law.
    pub log2_pair_probability: f64,
    /// That law, as a claim names it (`independent:symmetric` for Owen).
    pub law: String,
}

/// Words scrambled per depth and seed by the collision test (bounds its memory: seeds are
/// evaluated two at a time).
pub const COLLISION_WORDS_PER_DEPTH: u64 = 1 << 19;

/// Plans the collision test, or None when no subtree height makes collisions rare enough
/// within 4096 words per node, or failing that within 65,536.
pub fn collision_plan(cfg: &LawConfig) -> Option<CollisionPlan> {
    let tree = &cfg.tree;
    let (b, log2_b) = (tree.b() as u64, tree.log2_b());
    let nodes_cap = cfg.plan.collision_nodes;
    let seeds = cfg.plan.collision_seeds;
    let log2_group = cfg.group().log2_order_in_base(tree.b());
    let pairs_log2 = ((nodes_cap * nodes_cap / 2) as f64 * seeds as f64 * 16.0).log2();
    let rare_within = |cap: u64| {
        (1..=12u32).find(|&h| {
            let words = b.checked_pow(h).unwrap_or(u64::MAX);
            let n_nodes = (words - 1) / (b - 1);
            words <= cap
                && n_nodes as f64 * log2_group - h as f64 * log2_b >= 40.0 + pairs_log2
                && h < tree.full_digits()
        })
    };
    // Small subtrees first; where none is rare enough (translations or affine maps in bases
    // 128 and 256, whose one-level subtrees coincide too often), subtrees of up to 2^16 words,
    // with fewer nodes per depth (the memory bound below).
    let height = rare_within(4096).or_else(|| rare_within(1 << 16))?;
    let log2_pair_probability =
        height as f64 * log2_b - ((b.pow(height) - 1) / (b - 1)) as f64 * log2_group;
    // Memory: at most COLLISION_WORDS_PER_DEPTH words per depth and seed.
    let nodes_cap = nodes_cap.min(((COLLISION_WORDS_PER_DEPTH / b.pow(height)) as usize).max(2));
    let mut rng = SplitMix64::new(COLLISION_SEED);
    let last = (tree.full_digits() - height).min(*cfg.depths().end());
    let depths = (1..=last)
        .take(12)
        .map(|k| {
            let count = b
                .checked_pow(k)
                .map_or(nodes_cap, |n| (n as usize).min(nodes_cap));
            let prefixes: Vec<Vec<u32>> =
                if b.checked_pow(k).is_some_and(|n| n as usize <= nodes_cap) {
                    (0..b.pow(k))
                        .map(|idx| {
                            (0..k)
                                .map(|j| ((idx / b.pow(k - 1 - j)) % b) as u32)
                                .collect()
                        })
                        .collect()
                } else {
                    let mut set = std::collections::BTreeSet::new();
                    while set.len() < count {
                        set.insert(tree.random_prefix(k, &mut rng));
                    }
                    set.into_iter().collect()
                };
            (k, prefixes)
        })
        .collect();
    Some(CollisionPlan {
        height,
        depths,
        seeds,
        log2_pair_probability,
        law: format!("independent:{}", cfg.group().name()),
    })
}

/// Collision probes: per node, the b^h words of its subtree (dimension 0).
fn collision_probes(cfg: &LawConfig, plan: &CollisionPlan) -> Vec<Probe> {
    let tree = &cfg.tree;
    let b = tree.b() as u64;
    let h = plan.height;
    plan.depths
        .iter()
        .flat_map(|(_, prefixes)| prefixes.iter())
        .map(|p| Probe {
            dim: 0,
            words: (0..b.pow(h))
                .map(|v| {
                    let mut digits = p.clone();
                    digits.extend((0..h).map(|j| ((v / b.pow(h - 1 - j)) % b) as u32));
                    tree.word(&digits, 0)
                })
                .collect(),
            seeds: plan.seeds,
        })
        .collect()
}

/// Per depth: the number of equal normalized subtrees among the plan's nodes, summed over the
/// seeds in `outputs`, and the first node found in a collision.
fn collision_counts(
    cfg: &LawConfig,
    plan: &CollisionPlan,
    outputs: &[&[Vec<u64>]],
) -> Vec<(u64, Option<String>)> {
    let tree = &cfg.tree;
    let h = plan.height;
    let mut probe = 0usize;
    let mut counts = Vec::new();
    for (k, prefixes) in &plan.depths {
        let mut collisions = 0u64;
        let mut example = None;
        for seed_out in outputs {
            let mut seen: HashMap<Vec<u32>, usize> = HashMap::new();
            for (j, prefix) in prefixes.iter().enumerate() {
                let out = &seed_out[probe + j];
                let sig: Vec<u32> = out
                    .iter()
                    .flat_map(|&y| {
                        (0..h).map(move |l| {
                            tree.digit_difference(tree.digit(y, k + l), tree.digit(out[0], k + l))
                        })
                    })
                    .collect();
                let e = seen.entry(sig).or_insert(0);
                collisions += *e as u64;
                if *e > 0 && example.is_none() {
                    example = Some(prefix_name(prefix));
                }
                *e += 1;
            }
        }
        probe += prefixes.len();
        counts.push((collisions, example));
    }
    counts
}

/// Adds the counts of another chunk of seeds.
fn add_collision_counts(total: &mut [(u64, Option<String>)], more: Vec<(u64, Option<String>)>) {
    for (t, (c, e)) in total.iter_mut().zip(more) {
        t.0 += c;
        if t.1.is_none() {
            t.1 = e;
        }
    }
}

/// Collision counts per depth (over all the plan's seeds) against the Poisson law of
/// independent subtrees.
fn collision_tests(plan: &CollisionPlan, counts: &[(u64, Option<String>)]) -> Vec<SubTest> {
    let h = plan.height;
    plan.depths
        .iter()
        .zip(counts)
        .map(|((k, prefixes), (collisions, example))| {
            let nodes = prefixes.len() as f64;
            let lambda = plan.seeds as f64 * nodes * (nodes - 1.0) / 2.0
                * plan.log2_pair_probability.exp2();
            SubTest {
                name: format!(
                    "depth {k}: {collisions} equal height-{h} subtrees among {} nodes × {} seeds (expected under {}: {lambda:.1e}){}",
                    prefixes.len(),
                    plan.seeds,
                    plan.law,
                    example
                        .as_ref()
                        .map_or(String::new(), |e| format!(", e.g. under node {e}"))
                ),
                depth: Some(*k),
                requires: Requirement::Independent,
                statistic: *collisions as f64,
                p_value: poisson_sf(*collisions, lambda),
                n: prefixes.len() as u64 * plan.seeds,
                dof: None,
                power: "detects any two tested nodes whose subtrees coincide up to a translation"
                    .into(),
                deviates: false,
                not_run: None,
            }
        })
        .collect()
}

/// The `collisions` family. Seeds are evaluated two at a time (one per core), so memory stays
/// at two seeds' subtrees.
pub struct Collisions;

impl LawFamily for Collisions {
    fn name(&self) -> &'static str {
        "collisions"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Independent]
    }

    fn what(&self) -> &'static str {
        "within one seed, normalized subtrees of height h under many nodes per depth: no two equal"
    }

    fn own_pass(
        &self,
        cfg: &LawConfig,
        pass: &OwnPass,
    ) -> Result<Vec<SubTest>, crate::error::BatteryError> {
        let Some(plan) = collision_plan(cfg) else {
            return Ok(Vec::new());
        };
        let mut probes = collision_probes(cfg, &plan);
        let mut totals = vec![(0u64, None); plan.depths.len()];
        for first in (0..plan.seeds).step_by(2) {
            let chunk = (plan.seeds - first).min(2);
            probes.iter_mut().for_each(|p| p.seeds = chunk);
            let out = pass.evaluate(first, &probes)?;
            let views: Vec<&[Vec<u64>]> = out.iter().map(|o| o.as_slice()).collect();
            add_collision_counts(&mut totals, collision_counts(cfg, &plan, &views));
        }
        Ok(collision_tests(&plan, &totals))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::level::Level;
    use crate::sampling::Tree;
    use gartowen_core::{Claim, DigitLayout, PowerOfTwoBase, Width};

    fn config(claim: &str) -> LawConfig {
        LawConfig {
            tree: Tree::new(DigitLayout::new(Width::W32, PowerOfTwoBase::B4)),
            claim: Claim::parse(claim).unwrap(),
            plan: *Level::Quick.plan(),
            max_dims: None,
        }
    }

    #[test]
    fn the_expected_count_is_named_by_the_law_it_assumes() {
        for (claim, law) in [
            ("owen", "independent:symmetric"),
            ("independent:cyclic", "independent:cyclic"),
            ("independent:translation", "independent:translation"),
        ] {
            let plan = collision_plan(&config(claim)).expect("a plan in base 4");
            assert_eq!(plan.law, law);
            let counts = vec![(0u64, None); plan.depths.len()];
            let tests = collision_tests(&plan, &counts);
            assert!(
                tests[0].name.contains(&format!("(expected under {law}: ")),
                "{}",
                tests[0].name
            );
        }
    }
}
