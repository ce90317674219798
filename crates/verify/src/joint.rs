//! Joint laws of node permutations (`pair-law`, `flip-rank`, `collisions`): what tells a true
//! Owen scramble from imitations whose nodes are each fair but not independent.
//!
//! * `pair-law`: for node pairs at depth k (siblings, parent–child, cousins, distant nodes),
//!   over independent seeds, the pair (π_A(0), π_B(0)) (digits folded to ≤ 16 values) against
//!   the product of uniform marginals: χ² on ≤ 256 cells. A digital shift fails at siblings.
//! * `flip-rank`: the bits of π(0) of every node at depths 0..=D in dimensions 0 and 1, as
//!   columns over n seeds, with a constant column: under independence they are i.i.d. fair
//!   bits, so the n × (c + 1) matrix has full rank over GF(2) except with probability
//!   < 2^(c + 1 − n). A rank deficiency is an exact affine relation between node flips (the
//!   LK hashes have many); the relation found is named.
//! * `collisions`: within one seed, the subtree maps of height h below many nodes of a depth,
//!   normalized by XOR with the image of the zero path. Two independent Owen subtrees agree
//!   (up to that normalization) with probability b^h / |G|^N, N = (b^h − 1)/(b − 1) nodes,
//!   so the count of equal pairs is Poisson with a tiny mean; a finite table that reuses one
//!   symbol's subtree under many nodes (ART) shows collisions wherever nodes outnumber symbols.

use crate::law::{uniform, LawConfig, Requirement, SubTest};
use crate::sampling::{fold, folded_size, prefix_name, Probe, Tree};
use crate::stats::{chi_square, poisson_sf};
use gartowen_core::SplitMix64;
use std::collections::HashMap;

const PAIR_SEED: u64 = 0x7061_6972; // "pair"
const COLLISION_SEED: u64 = 0x636f_6c6c; // "coll"

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
pub fn pair_probes(cfg: &LawConfig) -> Vec<Probe> {
    node_pairs(cfg)
        .into_iter()
        .map(|p| Probe {
            dim: 0,
            words: vec![cfg.tree.word(&p.a.1, 0), cfg.tree.word(&p.b.1, 0)],
            seeds: cfg.seeds,
        })
        .collect()
}

/// χ² independence of the pair (π_A(0), π_B(0)) against uniform × uniform, per pair.
pub fn pair_analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
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
                    "{} at depth {} ({} | {})",
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
/// Rows beyond the column count: a full-rank matrix is then missed with probability < 2^-40.
const RANK_MARGIN: u64 = 40;

/// The deepest D with at most `cap` columns over both dimensions.
pub fn rank_plan(cfg: &LawConfig, cap: usize) -> RankPlan {
    let (b, q) = (cfg.tree.b() as usize, cfg.tree.q() as usize);
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
pub fn rank_probes(cfg: &LawConfig, plan: RankPlan) -> Vec<Probe> {
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

/// GF(2) rank of node bits over seeds; one sub-test per depth (the relations that first
/// appear when that depth's columns join).
pub fn rank_analyse(cfg: &LawConfig, plan: RankPlan, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let tree = &cfg.tree;
    let (b, q) = (tree.b() as u64, tree.q());
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
                        "π(0) bits of depths ≤ {depth}, dims 0-1: {deficient} exact relation(s), e.g. {} = 0{}",
                        shown.join(" ⊕ "),
                        if more > 0 { format!(" (+{more} more terms)") } else { String::new() }
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
            }
        })
        .collect()
}

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
}

/// Words scrambled per depth and seed by the collision test (bounds its memory: seeds are
/// evaluated two at a time).
pub const COLLISION_WORDS_PER_DEPTH: u64 = 1 << 19;

/// Plans the collision test, or None when no subtree height makes collisions rare enough
/// within 4096 words per node, or failing that within 65,536.
pub fn collision_plan(cfg: &LawConfig) -> Option<CollisionPlan> {
    let tree = &cfg.tree;
    let (b, q) = (tree.b() as u64, tree.q());
    let nodes_cap = 320 * cfg.scale.min(4) as usize;
    let seeds = 2 * cfg.scale.min(4);
    let log2_group = cfg.group().log2_order(q);
    let pairs_log2 = ((nodes_cap * nodes_cap / 2) as f64 * seeds as f64 * 16.0).log2();
    let rare_within = |cap: u64| {
        (1..=12u32).find(|&h| {
            let words = b.checked_pow(h).unwrap_or(u64::MAX);
            let n_nodes = (words - 1) / (b - 1);
            words <= cap
                && n_nodes as f64 * log2_group - (h * q) as f64 >= 40.0 + pairs_log2
                && h < tree.full_digits()
        })
    };
    // Small subtrees first; where none is rare enough (translations or affine maps in bases
    // 128 and 256, whose one-level subtrees coincide too often), subtrees of up to 2^16 words,
    // with fewer nodes per depth (the memory bound below).
    let height = rare_within(4096).or_else(|| rare_within(1 << 16))?;
    let log2_pair_probability =
        (height * q) as f64 - ((b.pow(height) - 1) / (b - 1)) as f64 * log2_group;
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
    })
}

/// Collision probes: per node, the b^h words of its subtree (dimension 0).
pub fn collision_probes(cfg: &LawConfig, plan: &CollisionPlan) -> Vec<Probe> {
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
pub fn collision_counts(
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
                        (0..h).map(move |l| tree.digit(y, k + l) ^ tree.digit(out[0], k + l))
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
pub fn add_collision_counts(total: &mut [(u64, Option<String>)], more: Vec<(u64, Option<String>)>) {
    for (t, (c, e)) in total.iter_mut().zip(more) {
        t.0 += c;
        if t.1.is_none() {
            t.1 = e;
        }
    }
}

/// Collision counts per depth (over all the plan's seeds) against the Poisson law of
/// independent subtrees.
pub fn collision_tests(plan: &CollisionPlan, counts: &[(u64, Option<String>)]) -> Vec<SubTest> {
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
                    "depth {k}: {collisions} equal height-{h} subtrees among {} nodes × {} seeds (Owen: {lambda:.1e}){}",
                    prefixes.len(),
                    plan.seeds,
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
            }
        })
        .collect()
}
