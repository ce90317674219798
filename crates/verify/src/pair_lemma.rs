//! Owen's pair lemma, end to end (`pair-lemma`): two inputs whose base-b digits first differ at
//! digit r. Under nested uniform scrambling their outputs share digits 0..r exactly (checked by
//! `nested`), their digits r are two distinct uniform digits (the node at depth r is applied to
//! two distinct digits), and their digits r + 1 are independent and uniform (two different
//! nodes). For every r up to the depth tested, one fixed input pair is scrambled over
//! independent seeds:
//!
//! * digit r: (y_r, y'_r) against the law of (π(x_r), π(x'_r)) for π uniform over the claimed
//!   group (distinct uniform pairs for S_b and AGL; a fixed difference for translations and
//!   shifts), folded to ≤ 16 × 16 cells: a marginal claim;
//! * digit r + 1: (y_{r+1}, y'_{r+1}) against uniform × uniform: an independence claim. A digital
//!   shift fails it at every r (y ⊕ y' is the inputs' difference).
//!
//! And inputs that differ **only** at digit r (u, and u with digit r changed to each other
//! value, at most 255 of them): under Owen the nodes below r are independent, so the outputs
//! agree on all full digits below r with probability b^-(digits below r) per instance. A
//! scrambler whose sibling subtrees can be one map (an ART grammar that gives two children of
//! a node one symbol: `proofs/ArtPair.v`, `gartowen_art::pair_law`) agrees far more often:
//! art-owen-m8's table, for digits differing by 0xc0, in about a quarter of instances.

use crate::expected::{pair_image_law, uniform};
use crate::family::{LawConfig, LawFamily};
use crate::sampling::{fold, folded_size, Probe};
use crate::stats::{chi_square, poisson_sf};
use crate::subtest::{Requirement, SubTest};
use gartowen_core::SplitMix64;

const LEMMA_SEED: u64 = 0x6c65_6d6d; // "lemm"
const SIBLING_SEED: u64 = 0x7369_626c; // "sibl"

/// Instances of the equal-suffix probes: each is b words per depth.
pub const SIBLING_SEEDS: u64 = 200;

/// The most changed values of digit r per depth (all of them up to base 256).
const SIBLING_VALUES: u32 = 255;

/// For each r with at least two full digits below it: a random word and the words that differ
/// from it only at digit r: every other value up to base 256, else 255 of them, in order from
/// a random offset.
fn sibling_sets(cfg: &LawConfig) -> Vec<(u32, Vec<u64>)> {
    let tree = &cfg.tree;
    let b = tree.b();
    let mut rng = SplitMix64::new(SIBLING_SEED);
    cfg.depths()
        .filter(|&r| r + 2 < tree.full_digits())
        .map(|r| {
            let u = tree.random_word(&mut rng);
            let ur = tree.digit(u, r);
            // A random rotation of the other values (all of them up to base 256).
            let start = rng.bounded(b - 1);
            let mut words = vec![u];
            words.extend(
                (0..(b - 1).min(SIBLING_VALUES))
                    .map(|i| tree.set(u, r, (ur + 1 + (start + i) % (b - 1)) % b)),
            );
            (r, words)
        })
        .collect()
}

/// The input pair for each r: random words, the second's digit r changed and its later digits
/// redrawn.
fn pairs(cfg: &LawConfig) -> Vec<(u32, u64, u64)> {
    let tree = &cfg.tree;
    let mut rng = SplitMix64::new(LEMMA_SEED);
    cfg.depths()
        .filter(|&r| r + 1 < tree.full_digits())
        .map(|r| {
            let u = tree.random_word(&mut rng);
            let mut v = tree.random_word(&mut rng);
            for k in 0..r {
                v = tree.set(v, k, tree.digit(u, k));
            }
            let ur = tree.digit(u, r);
            v = tree.set(v, r, (ur + 1 + rng.bounded(tree.b() - 1)) % tree.b());
            (r, u, v)
        })
        .collect()
}

/// One probe per r: the two words; then one per r for the equal-suffix words.
fn probes(cfg: &LawConfig) -> Vec<Probe> {
    let mut probes: Vec<Probe> = pairs(cfg)
        .into_iter()
        .map(|(_, u, v)| Probe {
            dim: 0,
            words: vec![u, v],
            seeds: cfg.plan.law_seeds,
        })
        .collect();
    probes.extend(sibling_sets(cfg).into_iter().map(|(_, words)| Probe {
        dim: 0,
        words,
        seeds: cfg.plan.law_seeds.min(SIBLING_SEEDS),
    }));
    probes
}

/// Whether y and y' agree on the full digits below r.
fn agree_below(tree: &crate::sampling::Tree, y: u64, y2: u64, r: u32) -> bool {
    (r + 1..tree.full_digits()).all(|k| tree.digit(y, k) == tree.digit(y2, k))
}

/// The coincidence rate ρ per instance that one tested word reaches with power 0.9 at
/// per-test level 1e-5: the least count a whose Bonferroni-adjusted Poisson tail is below the
/// level, then the least ρ with P(Poisson(n·ρ) ≥ a) ≥ 0.9 (by bisection; 1 when none).
fn detectable_rate(n: u64, lambda: f64, others: f64) -> f64 {
    let Some(a) = (1..=n).find(|&a| poisson_sf(a, lambda) * others <= 1e-5) else {
        return 1.0;
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if poisson_sf(a, lambda + n as f64 * mid) >= 0.9 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// One sub-test per r: the most instances in which a changed word's outputs agree with the
/// first word's below r, against Poisson(n·b^-(digits below r)), Bonferroni over the words.
fn sibling_tests(cfg: &LawConfig, outputs: &[&[Vec<u64>]], first: usize) -> Vec<SubTest> {
    let tree = &cfg.tree;
    let b = f64::from(tree.b());
    sibling_sets(cfg)
        .into_iter()
        .enumerate()
        .map(|(j, (r, words))| {
            let runs: Vec<&Vec<u64>> = outputs
                .iter()
                .map(|seed_out| &seed_out[first + j])
                .filter(|ys| !ys.is_empty())
                .collect();
            let n = runs.len() as u64;
            let agreements: Vec<u64> = (1..words.len())
                .map(|w| {
                    runs.iter()
                        .filter(|ys| agree_below(tree, ys[0], ys[w], r))
                        .count() as u64
                })
                .collect();
            let (worst, most) = agreements
                .iter()
                .enumerate()
                .max_by_key(|&(_, &a)| a)
                .map(|(w, &a)| (w + 1, a))
                .unwrap_or((0, 0));
            let below = tree.full_digits() - 1 - r;
            let lambda = n as f64 * b.powi(-(below as i32));
            let others = (words.len() - 1) as f64;
            let p_value = (poisson_sf(most, lambda) * others).min(1.0);
            let digit = |w: u64| tree.digit(w, r);
            SubTest {
                name: format!(
                    "r = {r}: inputs differing only at digit {r} ({} values): outputs agreeing on \
                     all {below} later digits in at most {most} of {n} instances (digit {} vs {}; \
                     expected under Owen: {lambda:.1e})",
                    words.len(),
                    digit(words[0]),
                    digit(words[worst.max(1).min(words.len() - 1)])
                ),
                depth: Some(r + 1),
                requires: Requirement::Independent,
                statistic: most as f64,
                p_value,
                n,
                dof: None,
                power: format!(
                    "detects two inputs differing at one digit whose later outputs coincide in \
                     {:.1} % of instances (power 0.9 at per-test level 1e-5)",
                    100.0 * detectable_rate(n, lambda, others)
                ),
                deviates: false,
                not_run: None,
            }
        })
        .collect()
}

/// Two χ² sub-tests per r.
fn analyse(cfg: &LawConfig, outputs: &[&[Vec<u64>]]) -> Vec<SubTest> {
    let tree = &cfg.tree;
    let b = tree.b();
    let f = folded_size(b) as usize;
    let mut tests = Vec::new();
    for (i, (r, u, v)) in pairs(cfg).into_iter().enumerate() {
        let mut at_r = vec![0u64; f * f];
        let mut after = vec![0u64; f * f];
        for seed_out in outputs {
            let (yu, yv) = (seed_out[i][0], seed_out[i][1]);
            let cell = |k: u32| {
                fold(tree.digit(yu, k), b) as usize * f + fold(tree.digit(yv, k), b) as usize
            };
            at_r[cell(r)] += 1;
            after[cell(r + 1)] += 1;
        }
        let (xr, xr2) = (tree.digit(u, r), tree.digit(v, r));
        // Binary words read best in hex; base-b digit integers in decimal.
        let (u, v) = match tree.power_of_two() {
            Some(_) => (format!("{u:#x}"), format!("{v:#x}")),
            None => (u.to_string(), v.to_string()),
        };
        tests.push(SubTest::chi(
            format!("r = {r}: output digits {r} of inputs {u}, {v} (distinct, uniform)"),
            Some(r),
            Requirement::Marginal,
            chi_square(&at_r, &pair_image_law(cfg.group(), b, xr, xr2)),
        ));
        tests.push(SubTest::chi(
            format!(
                "r = {r}: output digits {} of inputs {u}, {v} (independent, uniform)",
                r + 1
            ),
            Some(r + 1),
            Requirement::Independent,
            chi_square(&after, &uniform(f * f)),
        ));
    }
    tests.extend(sibling_tests(cfg, outputs, pairs(cfg).len()));
    tests
}

/// The `pair-lemma` family.
pub struct PairLemma;

impl LawFamily for PairLemma {
    fn name(&self) -> &'static str {
        "pair-lemma"
    }

    fn requires(&self) -> &'static [Requirement] {
        &[Requirement::Marginal, Requirement::Independent]
    }

    fn what(&self) -> &'static str {
        "inputs first differing at digit r: digits r distinct and uniform; digits r+1 independent and uniform; inputs differing only at r: later digits agree as rarely as b^-(digits below)"
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
    use crate::level::Level;
    use crate::sampling::Tree;
    use gartowen_core::{Claim, DigitLayout, PowerOfTwoBase, Width};

    fn config(q: u32) -> LawConfig {
        LawConfig {
            tree: Tree::new(DigitLayout::new(
                Width::W32,
                PowerOfTwoBase::from_q(q).unwrap(),
            )),
            claim: Claim::OWEN,
            plan: *Level::Quick.plan(),
            max_dims: None,
        }
    }

    #[test]
    fn sibling_words_differ_from_the_first_at_digit_r_only_each_value_once() {
        for q in [1, 4, 8] {
            let cfg = config(q);
            let tree = &cfg.tree;
            let sets = sibling_sets(&cfg);
            assert!(!sets.is_empty());
            assert!(sets.iter().all(|(r, _)| r + 2 < tree.full_digits()));
            let last = cfg.depths().filter(|&r| r + 2 < tree.full_digits()).max();
            assert_eq!(sets.last().map(|s| s.0), last);
            for (r, words) in sets {
                assert_eq!(words.len() as u32, tree.b(), "q = {q}");
                let mut values: Vec<u32> = words.iter().map(|&w| tree.digit(w, r)).collect();
                values.sort_unstable();
                values.dedup();
                assert_eq!(
                    values.len() as u32,
                    tree.b(),
                    "every value of digit {r} once"
                );
                for &w in &words[1..] {
                    // Only digit r differs (the tail bits too are equal).
                    let diff = w ^ words[0];
                    let k = (0..tree.full_digits()).find(|&k| tree.digit(diff, k) != 0);
                    assert_eq!(k, Some(r));
                    assert!(agree_below(tree, w, words[0], r));
                    assert!(!agree_below(tree, w, words[0], r.saturating_sub(1)) || r == 0);
                }
            }
        }
    }

    #[test]
    fn above_base_256_the_changed_values_are_255_distinct_ones() {
        use gartowen_core::radix::{Radix, RadixLayout};
        for b in [300u64, 1000] {
            let tree = Tree::radix(RadixLayout::new(Width::W64, Radix::new(b).unwrap()).unwrap());
            let cfg = LawConfig { tree, ..config(1) };
            let tree = &cfg.tree;
            for (r, words) in sibling_sets(&cfg) {
                assert_eq!(words.len(), 256, "b = {b}");
                let u = tree.digit(words[0], r);
                let mut values: Vec<u32> = words[1..].iter().map(|&w| tree.digit(w, r)).collect();
                assert!(values.iter().all(|&v| v != u && v < b as u32));
                // Consecutive values from a random start (mod b, skipping u's own).
                assert!(values
                    .windows(2)
                    .all(|p| p[1] == (p[0] + 1) % b as u32 || p[1] == (p[0] + 2) % b as u32));
                values.sort_unstable();
                values.dedup();
                assert_eq!(values.len(), 255);
                for &w in &words[1..] {
                    assert!(agree_below(tree, w, words[0], r));
                    assert!((0..r).all(|k| tree.digit(w, k) == tree.digit(words[0], k)));
                }
            }
        }
    }

    #[test]
    fn agreements_below_r_are_counted_per_word_against_owens_rate() {
        let cfg = config(4);
        let tree = &cfg.tree;
        let sets = sibling_sets(&cfg);
        let first = 3; // probes before the sibling ones
                       // The second set (r = 1), so that r enters the number of digits below it.
        let (r, words) = &sets[1];
        assert_eq!(*r, 1);
        let n = 200;
        // Instance i: word 5's output equals word 0's below r in the first 30 instances;
        // word 9's in the first 2; every other word's differs at the last digit.
        let outputs: Vec<Vec<Vec<u64>>> = (0..n)
            .map(|i| {
                let mut probes = vec![Vec::new(); first + sets.len()];
                probes[first + 1] = words
                    .iter()
                    .enumerate()
                    .map(|(w, &x)| {
                        let same = (w == 5 && i < 30) || (w == 9 && i < 2) || w == 0;
                        let last = tree.full_digits() - 1;
                        if same {
                            words[0]
                        } else {
                            tree.set(x, last, (tree.digit(words[0], last) + 1) % 16)
                        }
                    })
                    .collect();
                probes
            })
            .collect();
        let views: Vec<&[Vec<u64>]> = outputs.iter().map(|o| o.as_slice()).collect();
        let tests = sibling_tests(&cfg, &views, first);
        let t = &tests[1];
        assert_eq!((t.statistic, t.n, t.depth), (30.0, n, Some(r + 1)));
        let below = tree.full_digits() - 1 - r;
        let lambda = n as f64 * 16f64.powi(-(below as i32));
        assert_eq!(t.p_value, (poisson_sf(30, lambda) * 15.0).min(1.0));
        assert!(
            t.name.contains(&format!(
                "digit {} vs {}",
                tree.digit(words[0], *r),
                tree.digit(words[5], *r)
            )),
            "{}",
            t.name
        );
        assert!(
            t.name.contains("in at most 30 of 200 instances"),
            "{}",
            t.name
        );
        // Instances where the probe was not evaluated do not count; no agreement gives p = 1.
        let quiet: Vec<Vec<Vec<u64>>> = outputs
            .iter()
            .map(|o| {
                let mut o = o.clone();
                o[first + 1] = words.iter().map(|&x| x ^ 1).collect();
                o[first + 1][0] = words[0];
                o
            })
            .collect();
        let views: Vec<&[Vec<u64>]> = quiet.iter().map(|o| o.as_slice()).collect();
        let t = &sibling_tests(&cfg, &views, first)[1];
        assert_eq!((t.statistic, t.p_value), (0.0, 1.0));
        assert!(PairLemma.what().contains("differing only at r"));
    }

    #[test]
    fn the_detectable_rate_is_the_power_point_of_the_first_significant_count() {
        // λ negligible: one agreement is significant, so P(Poisson(nρ) ≥ 1) = 0.9 gives
        // ρ = ln 10 / n.
        let rho = detectable_rate(200, 1e-12, 15.0);
        assert!((rho - 10f64.ln() / 200.0).abs() < 1e-9, "{rho}");
        // λ = 1 (a base with few digits below r): more agreements are needed, so ρ is larger.
        let a = (1..).find(|&a| poisson_sf(a, 1.0) * 15.0 <= 1e-5).unwrap();
        let rho1 = detectable_rate(200, 1.0, 15.0);
        assert!(
            (poisson_sf(a, 1.0 + 200.0 * rho1) - 0.9).abs() < 1e-6,
            "{rho1}"
        );
        assert!(rho1 > rho);
        // Too few instances to ever reach the level: nothing is detectable below certainty.
        assert_eq!(detectable_rate(2, 5.0, 15.0), 1.0);
    }
}
