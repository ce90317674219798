//! Exact small-tree laws: the joint law of (σ(x), σ(x')) under a nested scramble, computed by
//! enumerating every assignment of node permutations from a variant's whole parameter space,
//! with probabilities as exact integer ratios (count / total).
//!
//! For inputs of `depth` digits, only the nodes on the paths of x and x' influence the pair;
//! every other node multiplies each outcome's count by the same factor, so enumerating the
//! path nodes alone gives the same exact probabilities as enumerating the whole tree.

use gartowen_core::{Gf2Matrix, Permutation};
use gartowen_owen::OwenVariant;
use std::collections::BTreeMap;

/// Every node permutation of the variant's parameter space for base 2^q (one entry per
/// parameter value, so multiplicities are the variant's law): S_b for Uniform, b shifts for
/// CyclicShift and Xor, |GL(q,2)|·b maps for Affine. q ≤ 3.
pub fn parameter_space(variant: OwenVariant, q: u32) -> Vec<Permutation> {
    let b = 1u32 << q;
    let from = |f: &dyn Fn(u32) -> u32| {
        Permutation::from_images(&(0..b).map(|d| f(d) as u8).collect::<Vec<_>>())
            .expect("bijection")
    };
    match variant {
        OwenVariant::Uniform => all_permutations(b as usize),
        OwenVariant::CyclicShift => (0..b).map(|u| from(&|d| (d + u) % b)).collect(),
        OwenVariant::Xor => (0..b).map(|u| from(&|d| d ^ u)).collect(),
        OwenVariant::Affine => Gf2Matrix::all_invertible(q)
            .into_iter()
            .flat_map(|a| (0..b).map(move |u| (a, u)))
            .map(|(a, u)| from(&|d| a.apply(d) ^ u))
            .collect(),
    }
}

/// All n! permutations of 0..n (n ≤ 8), lexicographic.
pub fn all_permutations(n: usize) -> Vec<Permutation> {
    fn rec(prefix: &mut Vec<u8>, used: &mut [bool], out: &mut Vec<Permutation>) {
        if prefix.len() == used.len() {
            out.push(Permutation::from_images(prefix).expect("distinct"));
            return;
        }
        for v in 0..used.len() {
            if !used[v] {
                used[v] = true;
                prefix.push(v as u8);
                rec(prefix, used, out);
                prefix.pop();
                used[v] = false;
            }
        }
    }
    let mut out = Vec::new();
    rec(&mut Vec::new(), &mut vec![false; n], &mut out);
    out
}

/// The exact joint law of (σ(x), σ(x')): counts of each (y, y') digit-string pair out of `total`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PairLaw {
    /// Base b.
    pub base: u32,
    /// Digits per input.
    pub depth: usize,
    /// Leading digits x and x' share.
    pub shared: usize,
    /// Count of each outcome.
    pub counts: BTreeMap<(Vec<u32>, Vec<u32>), u64>,
    /// Number of assignments enumerated.
    pub total: u64,
}

/// Enumerates every assignment of the path nodes of x and x' (digit strings of equal length).
pub fn pair_law(variant: OwenVariant, q: u32, x: &[u32], x2: &[u32]) -> PairLaw {
    assert_eq!(x.len(), x2.len());
    let depth = x.len();
    let shared = x.iter().zip(x2).take_while(|(a, b)| a == b).count();
    let family = parameter_space(variant, q);
    // Path nodes keyed by (depth, prefix): shared nodes appear once.
    let mut nodes: Vec<(usize, Vec<u32>)> = Vec::new();
    for input in [x, x2] {
        for k in 0..depth {
            let key = (k, input[..k].to_vec());
            if !nodes.contains(&key) {
                nodes.push(key);
            }
        }
    }
    let mut counts = BTreeMap::new();
    let mut total = 0u64;
    let mut choice = vec![0usize; nodes.len()];
    loop {
        let apply = |input: &[u32]| -> Vec<u32> {
            (0..depth)
                .map(|k| {
                    let node = nodes
                        .iter()
                        .position(|n| n.0 == k && n.1 == input[..k])
                        .expect("path node");
                    family[choice[node]].apply(input[k])
                })
                .collect()
        };
        *counts.entry((apply(x), apply(x2))).or_insert(0) += 1;
        total += 1;
        // Next assignment (odometer).
        let mut i = 0;
        while i < choice.len() {
            choice[i] += 1;
            if choice[i] < family.len() {
                break;
            }
            choice[i] = 0;
            i += 1;
        }
        if i == choice.len() {
            break;
        }
    }
    PairLaw {
        base: 1 << q,
        depth,
        shared,
        counts,
        total,
    }
}

/// Which parts of Owen's lemma a pair law satisfies, each decided exactly.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LemmaParts {
    /// σ(x) is uniform over all b^depth strings.
    pub marginal_uniform: bool,
    /// σ(x) and σ(x') agree on their first k (shared) digits.
    pub shared_digits_equal: bool,
    /// Digit k (the first differing one) is uniform over the b(b−1) ordered distinct pairs.
    pub split_digit_uniform_on_distinct_pairs: bool,
    /// Deeper digits are independent of the rest and uniform over all b² pairs.
    pub deeper_digits_independent_uniform: bool,
}

impl LemmaParts {
    /// Whether every part holds.
    pub fn all(&self) -> bool {
        self.marginal_uniform
            && self.shared_digits_equal
            && self.split_digit_uniform_on_distinct_pairs
            && self.deeper_digits_independent_uniform
    }
}

/// Checks Owen's lemma on a pair law with x ≠ x' (shared < depth), in integers.
pub fn check_lemma(law: &PairLaw) -> LemmaParts {
    let (b, depth, k, total) = (law.base as u64, law.depth, law.shared, law.total);
    assert!(k < depth, "x and x' must differ");
    let mut marginal: BTreeMap<&Vec<u32>, u64> = BTreeMap::new();
    let mut upper: BTreeMap<(Vec<u32>, Vec<u32>), u64> = BTreeMap::new();
    let mut split: BTreeMap<(u32, u32), u64> = BTreeMap::new();
    let mut shared_equal = true;
    for ((y, y2), &c) in &law.counts {
        *marginal.entry(y).or_insert(0) += c;
        *upper
            .entry((y[..=k].to_vec(), y2[..=k].to_vec()))
            .or_insert(0) += c;
        *split.entry((y[k], y2[k])).or_insert(0) += c;
        shared_equal &= y[..k] == y2[..k];
    }
    let strings = b.pow(depth as u32);
    let marginal_uniform =
        marginal.len() as u64 == strings && marginal.values().all(|&c| c * strings == total);
    let split_ok = split.len() as u64 == b * (b - 1)
        && split
            .iter()
            .all(|(&(u, v), &c)| u != v && c * b * (b - 1) == total);
    // P(y, y') = P(upper digits) · b^-2(depth−k−1) for every outcome, and every deeper
    // combination occurs (so the deeper pairs are uniform and independent of the upper ones).
    let deeper = b.pow(2 * (depth - k - 1) as u32);
    let deeper_ok = law.counts.len() as u64 == upper.len() as u64 * deeper
        && law
            .counts
            .iter()
            .all(|((y, y2), &c)| c * deeper == upper[&(y[..=k].to_vec(), y2[..=k].to_vec())]);
    LemmaParts {
        marginal_uniform,
        shared_digits_equal: shared_equal,
        split_digit_uniform_on_distinct_pairs: split_ok,
        deeper_digits_independent_uniform: deeper_ok,
    }
}
