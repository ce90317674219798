//! The diagonal-cell moments: a statistic that sees what every variance is blind to.
//!
//! **Why variances cannot tell AGL(q,2) from S_b.** The variance of a linear estimate
//! (1/N) Σ f(y_i) is a sum over pairs of points of E[f(y_i) f(y_k)], so it depends on the
//! scramble's pair law alone. A node permutation uniform over a 2-transitive group has the pair
//! law of one uniform over S_b, and AGL(q,2) (x ↦ A·x ⊕ u, A invertible over GF(2)) is even
//! 3-transitive. So no variance, box or coordinate mean, and no mean L2 discrepancy (also a sum
//! over pairs) separates `art-owen-m{q}` or `owen-oracle:affine` from Owen. The fourth moment of
//! the error of a linear estimate reads 4-point laws, where they differ: AGL(q,2) keeps every
//! affine plane {a, b, c, a ⊕ b ⊕ c} an affine plane.
//!
//! **The statistic.** For each dimension pair (2j, 2j + 1), j < [`DIAGONAL_PAIRS`], a set of b
//! points: point a has top digit a in both coordinates (pseudo-random lower digits, which no
//! statistic here reads). For each c in 0..b, the integrand f_c(x, y) = [top digit of x ⊕ top
//! digit of y = c] (the b cells of a translated diagonal; integral 1/b) is estimated by
//! F_c / b, where F_c counts the points whose scrambled top digits π(a), π'(a) have
//! π(a) ⊕ π'(a) = c; its error is (F_c − 1)/b. The moments read are
//! E[(F_c − 1)^k], k = 2 and 4, averaged over c and the pairs (one value per seed). Under Owen
//! the two root permutations are independent and uniform, so x ↦ π'(π⁻¹(x)) ⊕ c is a uniform
//! permutation and F_c is its number of fixed points; its factorial moments E[(F)_j] are 1 for
//! j ≤ b and 0 beyond, which gives E[(F − 1)²] = 1 and E[(F − 1)^4] = [b ≥ 2] + 2[b ≥ 3] +
//! [b ≥ 4] (4 in every base ≥ 4). A uniform AGL(q,2) has two orbits on 4-tuples of distinct
//! digits when q ≥ 3 (coplanar or not), so E[(F)_4] = 2 and E[(F − 1)^4] = 5: a 25% excess in
//! every base ≥ 8, with the second moment exactly Owen's. A translation-only node (a nested
//! digital shift in base b) has F_c = b for one c and 0 for the rest: second moment b − 1.
//! In base 2 both permutations of a digit give the same moments, so base 2 is not read.

use crate::sampling::{Outputs, Probe};
use gartowen_core::{PowerOfTwoBase, SplitMix64, Width};

/// Dimension pairs read: (0, 1), (2, 3), …, (2·DIAGONAL_PAIRS − 2, 2·DIAGONAL_PAIRS − 1).
/// Sixteen pairs make the fourth moment's standard error near 0.02 at 10,000 seeds under Owen.
pub const DIAGONAL_PAIRS: u32 = 16;

/// The moment orders read.
pub const ORDERS: [u32; 2] = [2, 4];

/// E[(F − 1)^`order`] for F the fixed points of a uniform permutation of `base` digits, the
/// exact Owen value of the statistic (orders 2 and 4; other orders are `None`).
pub fn owen_diagonal_moment(base: u32, order: u32) -> Option<f64> {
    let at_least = |j: u32| f64::from(u8::from(base >= j));
    match order {
        2 => Some(at_least(2)),
        4 => Some(at_least(2) + 2.0 * at_least(3) + at_least(4)),
        _ => None,
    }
}

/// The probes: for each dimension 0..2·[`DIAGONAL_PAIRS`], b words whose top digit is their
/// index, with lower digits from a fixed pseudo-random stream, evaluated for `seeds` seeds.
pub fn diagonal_probes(base: PowerOfTwoBase, width: Width, seeds: u64) -> Vec<Probe> {
    let q = base.q();
    let w = width.bits();
    // w − q ≤ 63: the shift is in range.
    let low_mask = (1u64 << (w - q)) - 1;
    let mut rng = SplitMix64::new(0x6469_6167); // "diag"
    (0..2 * DIAGONAL_PAIRS)
        .map(|dim| Probe {
            dim,
            words: (0..u64::from(base.base()))
                .map(|a| (a << (w - q)) | (rng.next_u64() & low_mask))
                .collect(),
            seeds,
        })
        .collect()
}

/// One seed's reading: the moments [`ORDERS`] averaged over c and the pairs, and the pairs
/// whose two scrambles were translates of each other at the top digit (π(a) ⊕ π'(a) the same
/// for every a: all b points on one diagonal) with the fourth-moment sum of the others.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiagonalSample {
    /// E[(F_c − 1)²] and E[(F_c − 1)^4] over c and the pairs.
    pub moments: [f64; 2],
    /// Pairs whose scrambles were translates at the top digit.
    pub translate_pairs: u32,
    /// Σ (F_c − 1)^4 over c and the other pairs.
    pub fourth_sum_others: f64,
}

/// Per seed, the [`DiagonalSample`] read from `outputs` (`[seed][probe]`, probes
/// `first..first + 2·DIAGONAL_PAIRS` being [`diagonal_probes`]).
pub fn diagonal_samples(
    outputs: &Outputs,
    first: usize,
    base: PowerOfTwoBase,
    width: Width,
) -> Vec<DiagonalSample> {
    let q = base.q();
    let b = base.base() as usize;
    let shift = width.bits() - q;
    let mut counts = vec![0u32; b];
    outputs
        .iter()
        .map(|per_seed| {
            let mut sums = [0.0; 2];
            let (mut translate_pairs, mut fourth_sum_others) = (0, 0.0);
            for pair in 0..DIAGONAL_PAIRS as usize {
                counts.fill(0);
                let (x, y) = (&per_seed[first + 2 * pair], &per_seed[first + 2 * pair + 1]);
                for (&u, &v) in x.iter().zip(y) {
                    counts[((u ^ v) >> shift) as usize] += 1;
                }
                let mut fourth = 0.0;
                for &f in &counts {
                    let e = f64::from(f) - 1.0;
                    sums[0] += e * e;
                    fourth += e * e * e * e;
                }
                sums[1] += fourth;
                if counts.iter().any(|&f| f as usize == b) {
                    translate_pairs += 1;
                } else {
                    fourth_sum_others += fourth;
                }
            }
            let n = (b * DIAGONAL_PAIRS as usize) as f64;
            DiagonalSample {
                moments: [sums[0] / n, sums[1] / n],
                translate_pairs,
                fourth_sum_others,
            }
        })
        .collect()
}

/// One moment's ratio to Owen's exact value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiagonalMoment {
    /// The moment order (2 or 4).
    pub order: u32,
    /// Mean over seeds / exact Owen value.
    pub ratio: f64,
    /// Its standard error (the seeds' spread / √seeds, over the exact value).
    pub ratio_se: f64,
}

/// The ratios of both moments to Owen's values in `base` from per-seed `samples`.
pub fn diagonal_moments(samples: &[DiagonalSample], base: PowerOfTwoBase) -> Vec<DiagonalMoment> {
    let r = samples.len() as f64;
    ORDERS
        .iter()
        .enumerate()
        .map(|(k, &order)| {
            let exact = owen_diagonal_moment(base.base(), order).expect("orders 2 and 4");
            let mean = samples.iter().map(|s| s.moments[k]).sum::<f64>() / r;
            let var = samples
                .iter()
                .map(|s| (s.moments[k] - mean).powi(2))
                .sum::<f64>()
                / (r - 1.0);
            DiagonalMoment {
                order,
                ratio: mean / exact,
                ratio_se: (var / r).sqrt() / exact,
            }
        })
        .collect()
}

/// Why a fourth moment is off: how many pairs were translates, what Owen expects, and the
/// moment of the other pairs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TranslateDiagnosis {
    /// Pairs read (seeds × [`DIAGONAL_PAIRS`]).
    pub pairs: u64,
    /// Pairs whose scrambles were translates of each other at the top digit.
    pub translate_pairs: u64,
    /// Owen's probability of one: b translations among b! permutations.
    pub owen_rate: f64,
    /// The fourth moment of the other pairs / Owen's value.
    pub fourth_ratio_others: f64,
}

/// Owen's probability that a dimension pair's scrambles are translates at the top digit in
/// base `b`: b translations among b! permutations, 1/(b − 1)! (a product, so that it
/// underflows to 0 gracefully).
pub fn owen_translate_rate(b: u32) -> f64 {
    (1..b).fold(1.0, |r, k| r / f64::from(k))
}

/// The [`TranslateDiagnosis`] of `samples` in `base`: meaningful from base 8 on (in base 2
/// every permutation is a translation, in base 4 one in six), so `None` below.
pub fn translate_diagnosis(
    samples: &[DiagonalSample],
    base: PowerOfTwoBase,
) -> Option<TranslateDiagnosis> {
    let b = base.base();
    if b < 8 {
        return None;
    }
    let pairs = samples.len() as u64 * u64::from(DIAGONAL_PAIRS);
    let translate_pairs: u64 = samples.iter().map(|s| u64::from(s.translate_pairs)).sum();
    let others = (pairs - translate_pairs) as f64 * f64::from(b);
    let fourth: f64 = samples.iter().map(|s| s.fourth_sum_others).sum();
    let owen_rate = owen_translate_rate(b);
    Some(TranslateDiagnosis {
        pairs,
        translate_pairs,
        owen_rate,
        fourth_ratio_others: fourth / others / owen_diagonal_moment(b, 4).expect("order 4"),
    })
}

impl TranslateDiagnosis {
    /// The diagnosis in words, for a check's detail: the translate pairs against Owen's
    /// expectation, and the fourth moment of the other pairs.
    pub fn words(&self) -> String {
        let others = if self.translate_pairs == self.pairs {
            "no other pair was read".to_string()
        } else {
            format!(
                "the other pairs' fourth moment is {:.3} of Owen's",
                self.fourth_ratio_others
            )
        };
        format!(
            "{} of {} dimension pairs were translates of each other at the top digit (all b \
             points on one diagonal; Owen expects {:.2e}), {others}",
            self.translate_pairs,
            self.pairs,
            self.owen_rate * self.pairs as f64,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The moments of the fixed points of every permutation of `b` digits (b ≤ 6), exactly.
    fn by_enumeration(b: usize) -> [f64; 2] {
        fn permutations(rest: &mut Vec<usize>, k: usize, out: &mut Vec<Vec<usize>>) {
            if k == rest.len() {
                out.push(rest.clone());
                return;
            }
            for i in k..rest.len() {
                rest.swap(k, i);
                permutations(rest, k + 1, out);
                rest.swap(k, i);
            }
        }
        let mut all = Vec::new();
        permutations(&mut (0..b).collect(), 0, &mut all);
        let mut m = [0.0; 2];
        for p in &all {
            let e = p.iter().enumerate().filter(|(i, v)| i == *v).count() as f64 - 1.0;
            m[0] += e * e;
            m[1] += e.powi(4);
        }
        [m[0] / all.len() as f64, m[1] / all.len() as f64]
    }

    #[test]
    fn owen_values_are_the_fixed_point_moments_of_uniform_permutations() {
        for b in 2..=6 {
            let [m2, m4] = by_enumeration(b);
            assert_eq!(owen_diagonal_moment(b as u32, 2), Some(m2), "b = {b}");
            assert!((owen_diagonal_moment(b as u32, 4).unwrap() - m4).abs() < 1e-12);
        }
        assert_eq!(owen_diagonal_moment(256, 4), Some(4.0));
        assert_eq!(owen_diagonal_moment(16, 3), None);
    }

    #[test]
    fn affine_permutations_have_owens_second_moment_and_a_quarter_more_fourth() {
        // Every x ↦ A·x ⊕ u of GF(2)^3 (168 · 8 maps): the statistic's per-map value averaged
        // over the group is 1 and 5, where a uniform S_8 gives 1 and 4.
        let apply = |cols: &[usize; 3], x: usize| {
            (0..3)
                .filter(|j| x >> j & 1 == 1)
                .fold(0, |r, j| r ^ cols[j])
        };
        let mut m = [0.0; 2];
        let mut maps = 0.0;
        for a in 0..8 {
            for b in 0..8 {
                for c in 0..8 {
                    let cols = [a, b, c];
                    let images: Vec<usize> = (0..8).map(|x| apply(&cols, x)).collect();
                    let mut seen = images.clone();
                    seen.sort_unstable();
                    seen.dedup();
                    if seen.len() != 8 {
                        continue;
                    }
                    for u in 0..8 {
                        let f = (0..8).filter(|&x| images[x] ^ u == x).count() as f64 - 1.0;
                        m[0] += f * f;
                        m[1] += f.powi(4);
                        maps += 1.0;
                    }
                }
            }
        }
        assert_eq!(maps, 168.0 * 8.0);
        assert_eq!([m[0] / maps, m[1] / maps], [1.0, 5.0]);
    }

    #[test]
    fn samples_count_each_translated_diagonal() {
        let b8 = PowerOfTwoBase::B8;
        let probes = diagonal_probes(b8, Width::W32, 1);
        assert_eq!(probes.len(), 2 * DIAGONAL_PAIRS as usize);
        assert!(probes.iter().all(|p| p
            .words
            .iter()
            .enumerate()
            .all(|(a, w)| (w >> 29) as usize == a)));
        // The lower digits are pseudo-random over all 29 bits, not zero or a narrower range.
        let tails = probes
            .iter()
            .flat_map(|p| p.words.iter())
            .fold(0, |acc, w| acc | (w & ((1 << 29) - 1)));
        assert_eq!(tails, (1 << 29) - 1);
        // Identity in every dimension: all 8 points on the diagonal c = 0, so F_0 = 8 and
        // F_c = 0 otherwise: (49 + 7) / 8 = 7 and (2401 + 7) / 8 = 301.
        let identity: Outputs = vec![probes.iter().map(|p| p.words.clone()).collect()];
        let all_translates = DiagonalSample {
            moments: [7.0, 301.0],
            translate_pairs: DIAGONAL_PAIRS,
            fourth_sum_others: 0.0,
        };
        assert_eq!(
            diagonal_samples(&identity, 0, b8, Width::W32),
            [all_translates]
        );
        // The second dimension of each pair mapped by a bijection whose XOR with the first is
        // a bijection too: one point on each diagonal, F_c = 1, moments 0.
        let mut spread = identity.clone();
        for pair in 0..DIAGONAL_PAIRS as usize {
            for (a, w) in spread[0][2 * pair + 1].iter_mut().enumerate() {
                // a ↦ 2a in GF(8) (x³ + x + 1): a ⊕ 2a = 3a is a bijection too.
                let doubled = (a << 1) ^ if a & 4 != 0 { 0b1011 } else { 0 };
                *w = (*w & ((1 << 29) - 1)) | ((doubled as u64) << 29);
            }
        }
        let spread_sample = DiagonalSample {
            moments: [0.0, 0.0],
            translate_pairs: 0,
            fourth_sum_others: 0.0,
        };
        assert_eq!(
            diagonal_samples(&spread, 0, b8, Width::W32),
            [spread_sample]
        );
        // One pair spread, the rest translates: the others' sum is that pair's (zero) alone,
        // and the diagnosis reads 15 translates in 16 with Owen's rate 1/7!.
        let mut mixed = identity.clone();
        mixed[0][1] = spread[0][1].clone();
        let sample = diagonal_samples(&mixed, 0, b8, Width::W32)[0];
        assert_eq!(sample.translate_pairs, DIAGONAL_PAIRS - 1);
        assert_eq!(sample.fourth_sum_others, 0.0);
        let d = translate_diagnosis(&[sample], b8).unwrap();
        assert_eq!((d.pairs, d.translate_pairs), (16, 15));
        assert!((d.owen_rate - 1.0 / 5040.0).abs() < 1e-18);
        assert_eq!(d.fourth_ratio_others, 0.0);
        assert!(
            d.words()
                .starts_with("15 of 16 dimension pairs were translates")
                && d.words().contains("Owen expects 3.17e-3")
                && d.words().ends_with("0.000 of Owen's"),
            "{}",
            d.words()
        );
        assert_eq!(translate_diagnosis(&[sample], PowerOfTwoBase::B4), None);
        // A pair with points 0 and 1 swapped in its second dimension is no translate: F_0 = 6,
        // F_1 = 2, the rest 0, so its fourth-moment sum is 5^4 + 1 + 6 = 632; the second
        // moment over all 16 pairs is (15·56 + 25 + 1 + 6) / 128.
        let mut swapped = identity.clone();
        swapped[0][1].swap(0, 1);
        let t = diagonal_samples(&swapped, 0, b8, Width::W32)[0];
        assert_eq!((t.translate_pairs, t.fourth_sum_others), (15, 632.0));
        assert_eq!(t.moments[0], (15.0 * 56.0 + 32.0) / 128.0);
        // Its diagnosis: 632 over the 8 cells of the one other pair, against Owen's 4.
        let d = translate_diagnosis(&[t, t, t], b8).unwrap();
        assert_eq!((d.pairs, d.translate_pairs), (48, 45));
        assert_eq!(d.fourth_ratio_others, 632.0 / 8.0 / 4.0);
        let all = translate_diagnosis(&[all_translates], b8).unwrap();
        assert!(
            all.words().ends_with("no other pair was read"),
            "{}",
            all.words()
        );
        // The probes after `first` are read, at 64 bits too.
        let wide = diagonal_probes(b8, Width::W64, 1);
        let mut outputs: Outputs = vec![vec![vec![0; 3]]];
        outputs[0].extend(wide.iter().map(|p| p.words.clone()));
        assert_eq!(
            diagonal_samples(&outputs, 1, b8, Width::W64),
            [all_translates]
        );
    }

    #[test]
    fn ratios_divide_by_the_exact_value_with_the_seeds_spread() {
        let b16 = PowerOfTwoBase::B16;
        let sample = |m2, m4| DiagonalSample {
            moments: [m2, m4],
            translate_pairs: 0,
            fourth_sum_others: 0.0,
        };
        let m = diagonal_moments(&[sample(1.0, 2.0), sample(3.0, 6.0)], b16);
        assert_eq!(m[0].order, 2);
        assert_eq!(m[0].ratio, 2.0);
        // Spread of [1, 3]: variance 2, SE 1 over the exact value 1.
        assert!((m[0].ratio_se - 1.0).abs() < 1e-12);
        assert_eq!(m[1].order, 4);
        assert_eq!(m[1].ratio, 1.0);
        // Spread of [2, 6]: variance 8, SE 2 over the exact value 4.
        assert!((m[1].ratio_se - 0.5).abs() < 1e-12);
        // Three seeds: [0, 3, 6] has variance 9 (divisor 2), SE √3.
        let m = diagonal_moments(&[sample(0.0, 0.0), sample(3.0, 0.0), sample(6.0, 0.0)], b16);
        assert!((m[0].ratio_se - 3f64.sqrt()).abs() < 1e-12, "{m:?}");
    }
}
