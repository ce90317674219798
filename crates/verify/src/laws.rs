//! Runs the law families on one candidate: plans every family's probes, evaluates the
//! per-seed ones in one pass over the seeds (each instance built once), and hands each family
//! its outputs.

use crate::battery::{Candidate, Level};
use crate::law::{LawConfig, SubTest};
use crate::sampling::{evaluate, Outputs, Probe, Tree};
use crate::{dimensions, joint, marginal, pair_lemma};
use gartowen_core::{DigitLayout, Width};

/// Depth, seed and size settings of a level.
pub fn config(c: &Candidate, level: Level) -> LawConfig {
    let probe = c.probe.as_ref();
    let width = if probe.supports_width(Width::W32) {
        Width::W32
    } else {
        Width::W64
    };
    let (max_depth, scale) = match level {
        Level::Quick => (12, 1),
        Level::Full => (16, 5),
        Level::Exhaustive => (20, 10),
    };
    LawConfig {
        tree: Tree::new(DigitLayout::new(width, probe.base())),
        claim: c.claim,
        seeds: crate::battery::node_law_seeds(level),
        max_depth,
        scale,
    }
}

/// Columns of the flip-rank matrix at `level`.
fn rank_cap(level: Level) -> usize {
    match level {
        Level::Quick => 1024,
        Level::Full => 2048,
        Level::Exhaustive => 4096,
    }
}

/// Slices `outputs[seed][offset..offset + len]` for the seeds that evaluated them.
fn slice(outputs: &Outputs, offset: usize, len: usize, seeds: u64) -> Vec<&[Vec<u64>]> {
    outputs
        .iter()
        .take(seeds as usize)
        .map(|o| &o[offset..offset + len])
        .collect()
}

/// The law families' sub-tests, in the order `node-law`, `pair-law`, `flip-rank`,
/// `collisions`, `pair-lemma`, `dimensions`. Seeds are `seed_base + i`.
pub fn run_laws(
    c: &Candidate,
    level: Level,
    seed_base: u64,
) -> Result<Vec<(&'static str, Vec<SubTest>)>, String> {
    let cfg = config(c, level);
    let width = cfg.tree.layout.width();
    let rank = joint::rank_plan(&cfg, rank_cap(level));
    // One pass over the per-seed families.
    let groups: Vec<Vec<Probe>> = vec![
        marginal::probes(&cfg),
        joint::pair_probes(&cfg),
        joint::rank_probes(&cfg, rank),
        pair_lemma::probes(&cfg),
        dimensions::root_probes(&cfg),
    ];
    let all: Vec<Probe> = groups.iter().flatten().cloned().collect();
    let outputs = evaluate(c.with_seed.as_ref(), width, seed_base, &all)?;
    let mut offset = 0;
    let mut parts = Vec::new();
    for g in &groups {
        let seeds = g.iter().map(|p| p.seeds).max().unwrap_or(0);
        parts.push(slice(&outputs, offset, g.len(), seeds));
        offset += g.len();
    }
    let node_law = marginal::analyse(&cfg, &parts[0]);
    let pair_law = joint::pair_analyse(&cfg, &parts[1]);
    let flip_rank = joint::rank_analyse(&cfg, rank, &parts[2]);
    let lemma = pair_lemma::analyse(&cfg, &parts[3]);
    let mut dims = dimensions::root_analyse(&cfg, &parts[4]);
    drop(parts);
    drop(outputs);

    let collisions = match joint::collision_plan(&cfg) {
        None => Vec::new(),
        Some(plan) => {
            // Two seeds at a time (one per core), so memory stays at two seeds' subtrees.
            let mut probes = joint::collision_probes(&cfg, &plan);
            let mut totals = vec![(0u64, None); plan.depths.len()];
            for first in (0..plan.seeds).step_by(2) {
                let chunk = (plan.seeds - first).min(2);
                probes.iter_mut().for_each(|p| p.seeds = chunk);
                let out = evaluate(
                    c.with_seed.as_ref(),
                    width,
                    seed_base.wrapping_add(first),
                    &probes,
                )?;
                let counts =
                    joint::collision_counts(&cfg, &plan, &slice(&out, 0, probes.len(), chunk));
                joint::add_collision_counts(&mut totals, counts);
            }
            joint::collision_tests(&plan, &totals)
        }
    };
    let distinct = dimensions::distinct_probes(&cfg);
    let out = evaluate(c.with_seed.as_ref(), width, seed_base, &distinct)?;
    dims.insert(
        0,
        dimensions::distinct_analyse(&slice(
            &out,
            0,
            distinct.len(),
            dimensions::distinct_seeds(&cfg),
        )),
    );
    Ok(vec![
        ("node-law", node_law),
        ("pair-law", pair_law),
        ("flip-rank", flip_rank),
        ("collisions", collisions),
        ("pair-lemma", lemma),
        ("dimensions", dims),
    ])
}
