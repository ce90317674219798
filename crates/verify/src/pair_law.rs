//! `pair-law`: for node pairs at depth k (siblings, parent–child, cousins, distant nodes),
//! over independent seeds, the pair (π_A(0), π_B(0)) (digits folded to ≤ 16 values) against
//! the product of uniform marginals: χ² on ≤ 256 cells. A digital shift fails at siblings.
//! One of the joint laws that tell a true Owen scramble from imitations whose nodes are each
//! fair but not independent.

use crate::expected::uniform;
use crate::family::{LawConfig, LawFamily};
use crate::sampling::{fold, folded_size, prefix_name, Probe};
use crate::stats::chi_square;
use crate::subtest::{Requirement, SubTest};
use gartowen_core::SplitMix64;

const PAIR_SEED: u64 = 0x7061_6972; // "pair"

/// Relations between the two nodes of a pair.
const RELATIONS: [&str; 4] = ["siblings", "parent-child", "cousins", "distant"];

/// One planned node pair: its name, the two (depth, prefix) nodes.
struct NodePair {
    relation: &'static str,
    depth: u32,
    a: (u32, Vec<u32>),
    b: (u32, Vec<u32>),
}

fn other_digit(d: u32, b: u32, rng: &mut SplitMix64) -> u32 {
    (d + 1 + rng.bounded(b - 1)) % b
}

fn node_pairs(cfg: &LawConfig) -> Vec<NodePair> {
    let tree = &cfg.tree;
    let b = tree.b();
    let mut rng = SplitMix64::new(PAIR_SEED);
    let mut out = Vec::new();
    for k in cfg.depths().filter(|&k| k >= 1) {
        for relation in RELATIONS {
            let (a, c) = match relation {
                "siblings" => {
                    let mut p = tree.random_prefix(k, &mut rng);
                    let mut q = p.clone();
                    q[k as usize - 1] = other_digit(p[k as usize - 1], b, &mut rng);
                    ((k, std::mem::take(&mut p)), (k, q))
                }
                "parent-child" => {
                    let p = tree.random_prefix(k, &mut rng);
                    ((k - 1, p[..k as usize - 1].to_vec()), (k, p))
                }
                "cousins" if k >= 2 => {
                    let p = tree.random_prefix(k, &mut rng);
                    let mut q = p.clone();
                    q[k as usize - 2] = other_digit(p[k as usize - 2], b, &mut rng);
                    q[k as usize - 1] = rng.bounded(b);
                    ((k, p), (k, q))
                }
                "distant" if k >= 2 => {
                    let p = tree.random_prefix(k, &mut rng);
                    let mut q = tree.random_prefix(k, &mut rng);
                    q[0] = other_digit(p[0], b, &mut rng);
                    ((k, p), (k, q))
                }
                _ => continue,
            };
            out.push(NodePair {
                relation,
                depth: k,
                a,
                b: c,
            });
        }
    }
    out
}

/// `pair-law` probes: per pair, the words reaching π_A(0) and π_B(0) (dimension 0).
fn pair_probes(cfg: &LawConfig) -> Vec<Probe> {
    node_pairs(cfg)
        .into_iter()
        .map(|p| Probe {
            dim: 0,
            words: vec![cfg.tree.word(&p.a.1, 0), cfg.tree.word(&p.b.1, 0)],
            seeds: cfg.plan.law_seeds,
        })
        .collect()
}

/// χ² independence of the pair (π_A(0), π_B(0)) against uniform × uniform, per pair.
fn pair_analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let b = cfg.tree.b();
    let f = folded_size(b);
    node_pairs(cfg)
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let mut counts = vec![0u64; (f * f) as usize];
            for seed_out in outputs {
                let ya = fold(cfg.tree.digit(seed_out[i][0], p.a.0), b);
                let yb = fold(cfg.tree.digit(seed_out[i][1], p.b.0), b);
                counts[(ya * f + yb) as usize] += 1;
            }
            SubTest::chi(
                format!(
                    "{} at depth {}: node {} vs node {}",
                    p.relation,
                    p.depth,
                    prefix_name(&p.a.1),
                    prefix_name(&p.b.1)
                ),
                Some(p.depth),
                Requirement::Independent,
                chi_square(&counts, &uniform(counts.len())),
            )
        })
        .collect()
}

/// The `pair-law` family.
pub struct PairLaw;

impl LawFamily for PairLaw {
    fn name(&self) -> &'static str {
        "pair-law"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Independent]
    }

    fn what(&self) -> &'static str {
        "node pairs at depths 1..D (siblings, parent-child, cousins, distant): (π_A(0), π_B(0)) uniform × uniform"
    }

    fn shared_probes(&self, cfg: &LawConfig) -> Vec<Probe> {
        pair_probes(cfg)
    }

    fn analyse_shared(&self, cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
        pair_analyse(cfg, outputs)
    }
}
