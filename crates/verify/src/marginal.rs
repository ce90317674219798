//! Marginal laws (`node-law`): at every depth 0..=D, one node of dimension 0 (a fixed
//! pseudo-random prefix), its permutation observed over independent seeds and tested against
//! the claimed group G (S_b when nothing is claimed):
//!
//! * membership: every observed permutation lies in G (exact: one outsider fails);
//! * uniformity: b ≤ 4 and G = S_b: the whole permutation (b! cells); otherwise (π(0), π(1))
//!   folded to ≤ 16 × 16 cells with the exact law of a uniform element of G (2-transitive groups
//!   give distinct pairs, translations and shifts a fixed difference);
//! * G = S_b with b ≥ 8: the affine fraction, the share of nodes with π(3) = π(0)⊕π(1)⊕π(2),
//!   which is 1/(b − 3) under S_b and 1 for affine families (one-sided binomial test).

use crate::expected::pair_image_law;
use crate::family::{LawConfig, LawFamily};
use crate::sampling::{prefix_name, Probe};
use crate::stats::chi_square;
use crate::subtest::{Requirement, SubTest};
use gartowen_core::{NodeGroup, SplitMix64};
use statrs::distribution::{Binomial, DiscreteCDF};

const PREFIX_SEED: u64 = 0x6d61_7267; // "marg"

/// The digits whose images are observed: all of them up to b = 16, else 0..4.
fn observed(b: u32) -> Vec<u32> {
    if b <= 16 {
        (0..b).collect()
    } else {
        vec![0, 1, 2, 3]
    }
}

/// One node per depth: its prefix.
fn nodes(cfg: &LawConfig) -> Vec<Vec<u32>> {
    let mut rng = SplitMix64::new(PREFIX_SEED);
    cfg.depths()
        .map(|k| cfg.tree.random_prefix(k, &mut rng))
        .collect()
}

/// The probes: for each depth, the words (prefix, d) for the observed digits d, dimension 0.
fn probes(cfg: &LawConfig) -> Vec<Probe> {
    let ds = observed(cfg.tree.b());
    nodes(cfg)
        .into_iter()
        .map(|p| Probe {
            dim: 0,
            words: ds.iter().map(|&d| cfg.tree.word(&p, d)).collect(),
            seeds: cfg.plan.law_seeds,
        })
        .collect()
}

/// Whether the observed images (of the digits [`observed`]) can come from an element of `g`.
fn member(g: NodeGroup, b: u32, imgs: &[u32]) -> bool {
    if b <= 16 {
        return g.contains(imgs);
    }
    let distinct = (0..4).all(|i| (0..i).all(|j| imgs[i] != imgs[j]));
    distinct
        && match g {
            NodeGroup::Symmetric => true,
            NodeGroup::Translation => (0..4).all(|d| imgs[d as usize] == d ^ imgs[0]),
            NodeGroup::Cyclic => (0..4).all(|d| imgs[d as usize] == (d + imgs[0]) % b),
            NodeGroup::Affine => imgs[3] ^ imgs[0] == (imgs[1] ^ imgs[0]) ^ (imgs[2] ^ imgs[0]),
        }
}

/// The Lehmer index of a permutation of b ≤ 4 digits (0..b!).
fn lehmer(imgs: &[u32]) -> usize {
    let n = imgs.len();
    let mut index = 0usize;
    for i in 0..n {
        let smaller = (i + 1..n).filter(|&j| imgs[j] < imgs[i]).count();
        index = index * (n - i) + smaller;
    }
    index
}

/// The sub-tests, from `outputs[seed][probe]` of this family's probes.
fn analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let (b, g) = (cfg.tree.b(), cfg.group());
    let f = crate::sampling::folded_size(b);
    let mut tests = Vec::new();
    for (i, (k, prefix)) in cfg.depths().zip(nodes(cfg)).enumerate() {
        let node = format!("depth {k}, node {}", prefix_name(&prefix));
        let mut outsiders = 0u64;
        let mut first_outsider = None;
        let full_perm = b <= 4 && g == NodeGroup::Symmetric;
        let cells = if full_perm {
            (1..=b as usize).product()
        } else {
            (f * f) as usize
        };
        let mut counts = vec![0u64; cells];
        let mut affine_hits = 0u64;
        let mut members = 0u64;
        // π(3) = π(0)⊕π(1)⊕π(2) has probability 1/(b − 3) under S_b only in a base 2^q.
        let affine_test = b >= 8 && cfg.tree.power_of_two().is_some();
        for seed_out in outputs {
            let imgs: Vec<u32> = seed_out[i].iter().map(|&y| cfg.tree.digit(y, k)).collect();
            if !member(g, b, &imgs) {
                outsiders += 1;
                first_outsider.get_or_insert(imgs);
                continue;
            }
            members += 1;
            let cell = if full_perm {
                lehmer(&imgs)
            } else {
                (crate::sampling::fold(imgs[0], b) * f + crate::sampling::fold(imgs[1], b)) as usize
            };
            counts[cell] += 1;
            if affine_test {
                affine_hits += (imgs[3] == imgs[0] ^ imgs[1] ^ imgs[2]) as u64;
            }
        }
        tests.push(SubTest {
            name: format!(
                "{node}: every permutation in {}{}",
                g.symbol_in_base(b),
                first_outsider.map_or(String::new(), |p| format!(
                    " (first outsider: images {p:?})"
                ))
            ),
            depth: Some(k),
            requires: Requirement::Marginal,
            statistic: outsiders as f64,
            p_value: if outsiders == 0 { 1.0 } else { 0.0 },
            n: outputs.len() as u64,
            dof: None,
            power: "exact: one permutation outside the group fails".into(),
            deviates: false,
            not_run: None,
        });
        let law = if full_perm {
            crate::expected::uniform(cells)
        } else {
            pair_image_law(g, b, 0, 1)
        };
        tests.push(SubTest::chi(
            format!(
                "{node}: {} uniform over {}",
                if full_perm {
                    "permutation"
                } else {
                    "(π(0), π(1))"
                },
                g.symbol_in_base(b)
            ),
            Some(k),
            Requirement::Marginal,
            chi_square(&counts, &law),
        ));
        if affine_test && g == NodeGroup::Symmetric && members > 0 {
            let p0 = 1.0 / (b - 3) as f64;
            let tail = if affine_hits == 0 {
                1.0
            } else {
                Binomial::new(p0, members)
                    .expect("p in [0,1]")
                    .sf(affine_hits - 1)
            };
            tests.push(SubTest {
                name: format!(
                    "{node}: affine fraction {:.3} (S_{b}: {p0:.3})",
                    affine_hits as f64 / members as f64
                ),
                depth: Some(k),
                requires: Requirement::Marginal,
                statistic: affine_hits as f64,
                p_value: tail,
                n: members,
                dof: None,
                power: "one-sided binomial: detects affine families (fraction 1)".into(),
                deviates: false,
                not_run: None,
            });
        }
    }
    tests
}

/// The `node-law` family.
pub struct NodeLaw;

impl LawFamily for NodeLaw {
    fn name(&self) -> &'static str {
        "node-law"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Marginal]
    }

    fn what(&self) -> &'static str {
        "one node per depth 0..D (dim 0): every permutation in the claimed group, uniform over it"
    }

    fn shared_probes(&self, cfg: &LawConfig) -> Vec<Probe> {
        probes(cfg)
    }

    fn analyse_shared(&self, cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
        analyse(cfg, outputs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lehmer_indexes_every_permutation_of_four_once() {
        let mut seen = [false; 24];
        for a in 0..4u32 {
            for b in 0..4 {
                for c in 0..4 {
                    for d in 0..4 {
                        let p = [a, b, c, d];
                        if NodeGroup::Symmetric.contains(&p) {
                            assert!(!std::mem::replace(&mut seen[lehmer(&p)], true));
                        }
                    }
                }
            }
        }
        assert!(seen.iter().all(|&s| s));
    }

    #[test]
    fn partial_membership_for_large_bases() {
        assert!(member(NodeGroup::Translation, 32, &[5, 4, 7, 6]));
        assert!(!member(NodeGroup::Translation, 32, &[5, 6, 7, 8]));
        assert!(member(NodeGroup::Cyclic, 32, &[31, 0, 1, 2]));
        assert!(member(NodeGroup::Affine, 32, &[9, 3, 17, 9 ^ 3 ^ 17]));
        assert!(!member(NodeGroup::Affine, 32, &[9, 3, 17, 1]));
        assert!(!member(NodeGroup::Symmetric, 32, &[9, 3, 9, 1]));
    }
}
