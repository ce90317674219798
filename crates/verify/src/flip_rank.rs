//! `flip-rank`: the bits of π(0) of every node at depths 0..=D in dimensions 0 and 1, as
//! columns over n seeds, with a constant column: under independence they are i.i.d. fair bits,
//! so the n × (c + 1) matrix has full rank over GF(2) except with probability < 2^(c + 1 − n).
//! A rank deficiency is an exact affine relation between node flips (the LK hashes have many);
//! the relation found is named.

use crate::family::{LawConfig, LawFamily};
use crate::sampling::{prefix_name, Probe, Tree};
use crate::subtest::{Requirement, SubTest};
use std::collections::HashMap;

/// The flip-rank plan: depth D and the number of seeds.
#[derive(Debug, Clone, Copy)]
pub struct RankPlan {
    /// Deepest depth whose nodes are columns.
    pub depth: u32,
    /// Columns (node bits of both dimensions), the constant column excluded.
    pub columns: usize,
    /// Seeds (rows): columns + 1 + 40.
    pub seeds: u64,
}

/// Dimensions whose node bits share one rank matrix.
const RANK_DIMS: [u32; 2] = [0, 1];
/// Why the rank matrix cannot be built: a dimension of [`RANK_DIMS`] is not served.
fn unserved(cfg: &LawConfig) -> Option<String> {
    RANK_DIMS.iter().find_map(|&dim| cfg.beyond(dim))
}

/// Why the test does not apply: node bits are GF(2) coordinates only in a base 2^q.
fn not_applicable(cfg: &LawConfig) -> Option<String> {
    cfg.tree.power_of_two().is_none().then(|| {
        format!(
            "not applicable in base {}: node bits are GF(2) coordinates only in a base 2^q",
            cfg.tree.b()
        )
    })
}

/// The digit size q (the tree's base is 2^q here: see [`not_applicable`]).
fn digit_bits(tree: &Tree) -> u32 {
    tree.power_of_two().map_or(1, |b| b.q())
}

/// Rows beyond the column count: a full-rank matrix is then missed with probability < 2^-40.
const RANK_MARGIN: u64 = 40;

/// The deepest D with at most `cap` columns over both dimensions.
pub fn rank_plan(cfg: &LawConfig, cap: usize) -> RankPlan {
    let (b, q) = (cfg.tree.b() as usize, digit_bits(&cfg.tree) as usize);
    let cols = |d: u32| RANK_DIMS.len() * q * (b.pow(d + 1) - 1) / (b - 1);
    let mut depth = 0;
    while depth < *cfg.depths().end() && cols(depth + 1) <= cap {
        depth += 1;
    }
    RankPlan {
        depth,
        columns: cols(depth),
        seeds: (cols(depth) as u64) + 1 + RANK_MARGIN,
    }
}

/// Every prefix of `depth` digits, as the word (prefix, 0, …), in lexicographic order.
fn all_prefix_words(tree: &Tree, depth: u32) -> Vec<u64> {
    let b = tree.b() as u64;
    (0..b.pow(depth))
        .map(|idx| {
            let digits: Vec<u32> = (0..depth)
                .map(|j| ((idx / b.pow(depth - 1 - j)) % b) as u32)
                .collect();
            tree.word(&digits, 0)
        })
        .collect()
}

/// `flip-rank` probes: per dimension, every word (prefix of D digits, 0, …).
fn rank_probes(cfg: &LawConfig, plan: RankPlan) -> Vec<Probe> {
    RANK_DIMS
        .iter()
        .map(|&dim| Probe {
            dim,
            words: all_prefix_words(&cfg.tree, plan.depth),
            seeds: plan.seeds,
        })
        .collect()
}

/// A column of the rank matrix: which node bit it is.
#[derive(Debug, Clone)]
struct Column {
    dim: u32,
    depth: u32,
    prefix: u64,
    bit: u32,
}

/// What a practitioner would call a relation among node flips (`None` is the constant
/// column): two nodes of one depth and dimension that always flip alike are what a digital
/// shift does (one flip per depth for every node); flips tied across depths are what a hash
/// of the path or a matrix scramble does.
fn relation_diagnosis(terms: &[Option<Column>]) -> Option<&'static str> {
    let nodes: Vec<&Column> = terms.iter().flatten().collect();
    let first = nodes.first()?;
    let same_depth = nodes
        .iter()
        .all(|c| c.depth == first.depth && c.dim == first.dim && c.bit == first.bit);
    if nodes.len() == 2 && terms.len() == 2 && same_depth {
        Some("two nodes of one depth always flip alike, as when all nodes of a depth share one flip (a digital shift)")
    } else if nodes.iter().any(|c| c.depth != first.depth) {
        Some("flips of different depths are tied linearly (a hash of the path or a matrix scramble, not independent nodes)")
    } else {
        None
    }
}

/// GF(2) rank of node bits over seeds; one sub-test per depth (the relations that first
/// appear when that depth's columns join).
fn rank_analyse(cfg: &LawConfig, plan: RankPlan, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let tree = &cfg.tree;
    let (b, q) = (tree.b() as u64, digit_bits(tree));
    let n = outputs.len();
    let row_words = n.div_ceil(64);
    // Columns in depth order (constant column first), each a bit vector over seeds.
    let mut columns: Vec<(Option<Column>, Vec<u64>)> = vec![(None, {
        let mut v = vec![u64::MAX; row_words];
        if !n.is_multiple_of(64) {
            v[row_words - 1] = (1u64 << (n % 64)) - 1;
        }
        v
    })];
    for depth in 0..=plan.depth {
        for (di, &dim) in RANK_DIMS.iter().enumerate() {
            for prefix in 0..b.pow(depth) {
                let word_index = (prefix * b.pow(plan.depth - depth)) as usize;
                for bit in 0..q {
                    let mut v = vec![0u64; row_words];
                    for (s, seed_out) in outputs.iter().enumerate() {
                        let d = tree.digit(seed_out[di][word_index], depth);
                        v[s / 64] |= (((d >> bit) & 1) as u64) << (s % 64);
                    }
                    columns.push((
                        Some(Column {
                            dim,
                            depth,
                            prefix,
                            bit,
                        }),
                        v,
                    ));
                }
            }
        }
    }
    let total = columns.len();
    let combo_words = total.div_ceil(64);
    // Basis with pivots; each vector remembers which original columns it combines.
    let mut basis: Vec<(usize, Vec<u64>, Vec<u64>)> = Vec::new();
    let mut dependent_at: HashMap<u32, (u64, Vec<usize>)> = HashMap::new();
    let mut rank_before = vec![0usize; plan.depth as usize + 2];
    for (ci, (col, v)) in columns.iter().enumerate() {
        let mut v = v.clone();
        let mut combo = vec![0u64; combo_words];
        combo[ci / 64] |= 1 << (ci % 64);
        for (pivot, bv, bc) in &basis {
            if (v[pivot / 64] >> (pivot % 64)) & 1 == 1 {
                v.iter_mut().zip(bv).for_each(|(a, b)| *a ^= b);
                combo.iter_mut().zip(bc).for_each(|(a, b)| *a ^= b);
            }
        }
        let depth = col.as_ref().map_or(0, |c| c.depth);
        match v.iter().position(|&w| w != 0) {
            Some(w) => {
                let pivot = w * 64 + v[w].trailing_zeros() as usize;
                basis.push((pivot, v, combo));
            }
            None => {
                let e = dependent_at.entry(depth).or_insert((0, Vec::new()));
                e.0 += 1;
                if e.1.is_empty() {
                    e.1 = (0..total)
                        .filter(|&k| (combo[k / 64] >> (k % 64)) & 1 == 1)
                        .collect();
                }
            }
        }
        rank_before[depth as usize + 1] = basis.len();
    }
    let name_col = |k: usize| match &columns[k].0 {
        None => "1".to_string(),
        Some(c) => {
            let digits: Vec<u32> = (0..c.depth)
                .map(|j| ((c.prefix / b.pow(c.depth - 1 - j)) % b) as u32)
                .collect();
            format!(
                "dim {} node {}{}",
                c.dim,
                prefix_name(&digits),
                if q > 1 {
                    format!(" bit {}", c.bit)
                } else {
                    String::new()
                }
            )
        }
    };
    let mut cols_so_far = 1usize;
    (0..=plan.depth)
        .map(|depth| {
            let here = RANK_DIMS.len() * (q as usize) * b.pow(depth) as usize;
            cols_so_far += here;
            let (deficient, relation) = dependent_at.remove(&depth).unwrap_or_default();
            let shown: Vec<String> = relation.iter().take(6).map(|&k| name_col(k)).collect();
            let more = relation.len().saturating_sub(6);
            SubTest {
                name: if deficient == 0 {
                    format!(
                        "π(0) bits of depths ≤ {depth}, dims 0-1: rank {} of {cols_so_far} columns",
                        rank_before[depth as usize + 1]
                    )
                } else {
                    format!(
                        "π(0) bits of depths ≤ {depth}, dims 0-1: {deficient} exact relation(s), e.g. {} = 0{}{}",
                        shown.join(" ⊕ "),
                        if more > 0 { format!(" (+{more} more terms)") } else { String::new() },
                        relation_diagnosis(&relation.iter().map(|&k| columns[k].0.clone()).collect::<Vec<_>>())
                            .map_or(String::new(), |d| format!(": {d}"))
                    )
                },
                depth: Some(depth),
                requires: Requirement::Independent,
                statistic: deficient as f64,
                p_value: if deficient == 0 {
                    1.0
                } else {
                    (cols_so_far as f64 - n as f64).exp2().min(1.0)
                },
                n: n as u64,
                dof: None,
                power: format!(
                    "exact: any GF(2) affine relation among {cols_so_far} node bits (false alarm < 2^-{})",
                    n - cols_so_far.min(n)
                ),
                deviates: false,
                not_run: None,
            }
        })
        .collect()
}

/// The `flip-rank` family.
pub struct FlipRank;

impl LawFamily for FlipRank {
    fn name(&self) -> &'static str {
        "flip-rank"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Independent]
    }

    fn what(&self) -> &'static str {
        "π(0) bits of every node at depths ≤ D (dims 0, 1) and a constant, over columns + 41 seeds: full GF(2) rank"
    }

    fn shared_probes(&self, cfg: &LawConfig) -> Vec<Probe> {
        if unserved(cfg).or_else(|| not_applicable(cfg)).is_some() {
            return Vec::new();
        }
        rank_probes(cfg, rank_plan(cfg, cfg.plan.rank_columns))
    }

    fn analyse_shared(&self, cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
        if let Some(why) = not_applicable(cfg) {
            let name = "π(0) bits of every node, dims 0-1: full GF(2) rank".to_string();
            return vec![SubTest::not_run(name, None, Requirement::Independent, why)];
        }
        let plan = rank_plan(cfg, cfg.plan.rank_columns);
        match unserved(cfg) {
            None => rank_analyse(cfg, plan, outputs),
            Some(why) => (0..=plan.depth)
                .map(|depth| {
                    let name = format!("π(0) bits of depths ≤ {depth}, dims 0-1: full rank");
                    SubTest::not_run(name, Some(depth), Requirement::Independent, why.clone())
                })
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(dim: u32, depth: u32, prefix: u64) -> Option<Column> {
        Some(Column {
            dim,
            depth,
            prefix,
            bit: 0,
        })
    }

    #[test]
    fn relations_are_diagnosed_as_a_practitioner_would() {
        let shift = relation_diagnosis(&[node(0, 1, 0), node(0, 1, 1)]).unwrap();
        assert!(shift.contains("a digital shift"), "{shift}");
        let across = relation_diagnosis(&[node(0, 0, 0), node(0, 1, 0), node(0, 1, 1)]).unwrap();
        assert!(across.contains("different depths"), "{across}");
        // Two nodes of one depth in different dimensions, or with the constant: no name.
        assert_eq!(relation_diagnosis(&[node(0, 1, 0), node(1, 1, 0)]), None);
        assert_eq!(
            relation_diagnosis(&[None, node(0, 1, 0), node(0, 1, 1)]),
            None
        );
        assert_eq!(relation_diagnosis(&[]), None);
    }
}
