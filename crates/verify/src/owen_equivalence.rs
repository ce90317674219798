//! How close to Owen, by the estimator's variance, and the `verify --equivalent-to owen` check.
//!
//! For instances from seeds 0..R: the variance over seeds of the box-volume estimate
//! μ̂ = (points in E)/N, divided by its exact value under Owen's nested uniform scrambling in the
//! implementation's base (`gartowen_oracles::owen_variance`), at box levels 1, 2 and 3 (total
//! digits over two coordinates: shapes (1,0), (1,1), (2,1)), on a fixed pseudo-random set of 64
//! points in 2-D (dimensions 0 and 1). A ratio of 1 is Owen's law; too small, the scramble keeps
//! structure; too large, it moves points together. Each ratio carries its standard error
//! (SE of the sample variance: √((m₄ − s⁴)/R + 2s⁴/(R(R − 1))) / V). The reference is exact, so
//! only the implementation's sampling error enters the equivalence test
//! ([`crate::equivalence`]).
//!
//! **What the box statistic cannot see.** Two points are both in a box anchored at the origin
//! only if they share the box's leading digits, and a nested scramble keeps exactly those pairs
//! together; so the box variance depends only on nestedness, uniform output strings and
//! independent dimensions. A nested digital shift (`digital-shift`, `art-owen-t4`) has Owen's
//! box variance at every level. The **coordinate mean** sees the joint law inside a dimension:
//! the variance over seeds of the mean of y_j over the 64 points, against its exact Owen value
//! (1/N²) Σ_{i,k} Cov(y_i, y_k), where two inputs first differing at digit r of base b (the
//! prefix grid has spacing s = b^-r) have, by Owen's pair lemma,
//! Cov = (1 − s²)/12 − (s/b)²·(b + 1)/12 (the common prefix uniform on the grid, digit r a
//! uniform pair of distinct digits, the rest independent and uniform), and Cov = 1/12 for equal
//! inputs. A digital shift keeps y_i ⊕ y_k fixed and misses it by far.
//!
//! **What no variance can see.** Every statistic above reads pairs of points, and a node
//! permutation uniform over AGL(q,2) has S_b's pair law. The diagonal-cell moments
//! ([`crate::diagonal_cells`]) read the fourth moment of an estimate's error, which tells them
//! apart (exactly 5/4 of Owen's value in every base ≥ 8).

use crate::diagonal_cells::{
    diagonal_moments, diagonal_probes, diagonal_samples, translate_diagnosis, DiagonalMoment,
    TranslateDiagnosis,
};
use crate::equivalence::{judge, Equivalence, EquivalenceSettings, EquivalenceVerdict};
use crate::error::BatteryError;
use crate::level::Level;
use crate::sampling::{evaluate, Probe, SeedBuilder};
use crate::verdict::{CheckResult, Verdict};
use gartowen_core::{DigitLayout, PowerOfTwoBase, SplitMix64, Width};
use gartowen_oracles::owen_variance::owen_box_variance;
use std::time::Instant;

/// The box shapes, in digits of the base, whose levels (sums) are 1, 2, 3.
pub const SHAPES: [[u32; 2]; 3] = [[1, 0], [1, 1], [2, 1]];

/// Points in the fixed set.
pub const POINTS: usize = 64;

/// Seeds of the `--equivalent-to owen` check at each level.
pub fn equivalence_seeds(level: Level) -> u64 {
    level.plan().equivalence_seeds
}

/// The fewest expected points in the box, summed over seeds, for a level to be judged for
/// equivalence. The sample variance of a rare count is heavy-tailed and its standard error
/// unreliable (the exact oracle itself once read 0.45 at 16 expected hits); at 2,000 hits the
/// relative standard error is about √((2 + 1/λ)/R) ≤ 0.025 for λ ≥ 1/4 hit per seed, where the
/// 90% interval of an exact Owen scramble fits a ±10% margin with probability about 0.9.
pub const MIN_EXPECTED_HITS: f64 = 2000.0;

/// Expected points in a box of `level` digits of base 2^`q`, over `seeds` seeds of the fixed set.
pub fn expected_hits(seeds: u64, q: u32, level: u32) -> f64 {
    seeds as f64 * POINTS as f64 * 2f64.powi(-((level * q) as i32))
}

/// The fixed 2-D point set (32-bit coordinates).
pub fn fixed_points() -> Vec<Vec<u64>> {
    let mut rng = SplitMix64::new(0x0077_656e); // "wen"
    (0..POINTS)
        .map(|_| vec![rng.next_u64() >> 32, rng.next_u64() >> 32])
        .collect()
}

/// (sample variance, its standard error) of `values`.
pub fn sample_variance(values: &[f64]) -> (f64, f64) {
    let r = values.len() as f64;
    let mean = values.iter().sum::<f64>() / r;
    let s2 = values.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / (r - 1.0);
    let m4 = values.iter().map(|e| (e - mean).powi(4)).sum::<f64>() / r;
    let se = ((m4 - s2 * s2).max(0.0) / r + 2.0 * s2 * s2 / (r * (r - 1.0))).sqrt();
    (s2, se)
}

/// One box level's variance ratio to Owen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelVariance {
    /// Total digits of the box.
    pub level: u32,
    /// Sample variance / exact Owen variance (`None` when the exact variance is 0 or fewer than
    /// 10 points are expected in the box over all seeds).
    pub ratio: Option<f64>,
    /// Standard error of the ratio.
    pub ratio_se: Option<f64>,
}

/// Owen's covariance of the scrambled values of 32-bit words `a` and `b` in base `base` (the
/// pair lemma; see the module doc), with a partial last digit counted in its own base.
pub fn owen_pair_covariance(a: u64, b: u64, base: PowerOfTwoBase) -> f64 {
    let h = (a ^ b) & 0xFFFF_FFFF;
    if h == 0 {
        return 1.0 / 12.0;
    }
    let layout = DigitLayout::new(Width::W32, base);
    let lz = h.leading_zeros() - 32;
    let r = lz / base.q();
    let spacing = 2f64.powi(-((r * base.q()) as i32));
    let digit_base = f64::from(1u32 << layout.digit_bits(r));
    let scale = spacing / digit_base;
    (1.0 - spacing * spacing) / 12.0 - scale * scale * (digit_base + 1.0) / 12.0
}

/// The exact variance under Owen scrambling in `base` of the mean of the scrambled values of
/// `words` (32-bit): (1/N²) Σ_{i,k} Cov(y_i, y_k).
pub fn owen_mean_variance(words: &[u64], base: PowerOfTwoBase) -> f64 {
    let n = words.len() as f64;
    let sum: f64 = words
        .iter()
        .map(|&a| {
            words
                .iter()
                .map(|&b| owen_pair_covariance(a, b, base))
                .sum::<f64>()
        })
        .sum();
    sum / (n * n)
}

/// The variance of the coordinate mean of one dimension, against Owen's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeanVariance {
    /// The dimension (0 or 1).
    pub dim: u32,
    /// Sample variance / exact Owen variance.
    pub ratio: f64,
    /// Its standard error.
    pub ratio_se: f64,
}

/// The statistics of one implementation.
#[derive(Debug, Clone, PartialEq)]
pub struct VarianceRatios {
    /// Box levels 1, 2, 3.
    pub boxes: Vec<LevelVariance>,
    /// The coordinate means of dimensions 0 and 1.
    pub means: Vec<MeanVariance>,
    /// The diagonal-cell moments of orders 2 and 4 ([`crate::diagonal_cells`]).
    pub diagonal: Vec<DiagonalMoment>,
    /// Their translate-pair diagnosis (base ≥ 8).
    pub translates: Option<TranslateDiagnosis>,
}

/// The variance ratios of the instances `with_seed(0..seeds)` in `base`, on 32-bit words
/// (`width` 32; 64-bit instances get the points in their top 32 bits). Errors name the seed
/// whose instance failed.
pub fn variance_ratios(
    with_seed: &SeedBuilder,
    base: PowerOfTwoBase,
    width: Width,
    seeds: u64,
) -> Result<VarianceRatios, BatteryError> {
    let points = fixed_points();
    let q = base.q();
    let up = width.bits().saturating_sub(32);
    let mut probes: Vec<Probe> = (0..2u32)
        .map(|dim| Probe {
            dim,
            words: points.iter().map(|p| p[dim as usize] << up).collect(),
            seeds,
        })
        .collect();
    // In base 2 every node permutation gives the diagonal moments exactly (1 and 1): nothing
    // to read.
    let first_diagonal = probes.len();
    if base.base() > 2 {
        probes.extend(diagonal_probes(base, width, seeds));
    }
    let outputs = evaluate(with_seed, width, 0, &probes)?;
    let (diagonal, translates) = if base.base() > 2 {
        let samples = diagonal_samples(&outputs, first_diagonal, base, width);
        (
            diagonal_moments(&samples, base),
            translate_diagnosis(&samples, base),
        )
    } else {
        (Vec::new(), None)
    };
    let columns = |n: usize| -> Vec<Vec<f64>> {
        (0..n).map(|_| Vec::with_capacity(seeds as usize)).collect()
    };
    let (mut per_shape, mut per_mean) = (columns(SHAPES.len()), columns(2));
    for per_seed in &outputs {
        for (j, means) in per_mean.iter_mut().enumerate() {
            let sum: f64 = per_seed[j].iter().map(|&y| (y >> up) as f64).sum();
            means.push(sum / POINTS as f64 * 2f64.powi(-32));
        }
        for (k, shape) in SHAPES.iter().enumerate() {
            let inside = (0..POINTS)
                .filter(|&i| {
                    (0..2).all(|j| {
                        let top = per_seed[j][i] >> up;
                        shape[j] == 0 || top >> (32 - shape[j] * q) == 0
                    })
                })
                .count();
            per_shape[k].push(inside as f64 / POINTS as f64);
        }
    }
    let means = (0..2u32)
        .map(|dim| {
            let column: Vec<u64> = points.iter().map(|p| p[dim as usize]).collect();
            let v = owen_mean_variance(&column, base);
            let (s2, se) = sample_variance(&per_mean[dim as usize]);
            MeanVariance {
                dim,
                ratio: s2 / v,
                ratio_se: se / v,
            }
        })
        .collect();
    let boxes = SHAPES
        .iter()
        .enumerate()
        .map(|(k, shape)| {
            let v = owen_box_variance(&points, 32, q, shape)
                .map(|v| rational_to_f64(&v))
                .unwrap_or(f64::NAN);
            let (s2, se) = sample_variance(&per_shape[k]);
            // Under 10 expected hits over all seeds the sample variance says nothing (a ratio of
            // 0 would read as "no variance"): no ratio.
            let level = shape[0] + shape[1];
            let hits = seeds as f64 * POINTS as f64 * 2f64.powi(-((level * q) as i32));
            let known = v > 0.0 && hits >= 10.0;
            LevelVariance {
                level,
                ratio: known.then_some(s2 / v),
                ratio_se: known.then_some(se / v),
            }
        })
        .collect();
    Ok(VarianceRatios {
        boxes,
        means,
        diagonal,
        translates,
    })
}

fn rational_to_f64(v: &num_rational::BigRational) -> f64 {
    use num_traits::ToPrimitive;
    v.to_f64().unwrap_or(f64::NAN)
}

/// The equivalence judgement of every statistic that can be judged: the coordinate means, the
/// diagonal-cell moments, and each box level with a ratio and at least [`MIN_EXPECTED_HITS`]
/// expected hits in base 2^`q` (family: the statistics judged). Names: `mean dim J`,
/// `diagonal moment K`, `box level K`.
pub fn judge_statistics(
    ratios: &VarianceRatios,
    q: u32,
    seeds: u64,
    margin: f64,
) -> Vec<(String, Equivalence)> {
    let mut known: Vec<(String, f64, f64)> = ratios
        .means
        .iter()
        .map(|m| (format!("mean dim {}", m.dim), m.ratio, m.ratio_se))
        .collect();
    known.extend(
        ratios
            .diagonal
            .iter()
            .map(|m| (format!("diagonal moment {}", m.order), m.ratio, m.ratio_se)),
    );
    known.extend(
        ratios
            .boxes
            .iter()
            .filter(|l| expected_hits(seeds, q, l.level) >= MIN_EXPECTED_HITS)
            .filter_map(|l| Some((format!("box level {}", l.level), l.ratio?, l.ratio_se?))),
    );
    let settings = EquivalenceSettings::new(
        margin,
        crate::equivalence::DEFAULT_ALPHA,
        known.len().max(1),
    )
    .expect("a margin in (0, 1)");
    known
        .into_iter()
        .map(|(name, r, se)| (name, judge(r, se / r, seeds, settings)))
        .collect()
}

/// The `equivalent-to-owen` check: passes when every box level's variance ratio is equivalent
/// to 1 within ±`margin` (TOST at α = 0.05, the 90% interval inside the margin), fails when
/// one is different or inconclusive (equivalence not shown), naming the seeds that would
/// decide it.
pub fn check_equivalent_to_owen(
    with_seed: &SeedBuilder,
    base: PowerOfTwoBase,
    width: Width,
    seeds: u64,
    margin: f64,
) -> CheckResult {
    let started = Instant::now();
    let (verdict, detail, value) = match variance_ratios(with_seed, base, width, seeds) {
        Err(e) => (Verdict::Fail, format!("could not scramble: {e}"), None),
        Ok(ratios) => judge_ratios(&ratios, base, seeds, margin),
    };
    CheckResult {
        check: "equivalent-to-owen".into(),
        verdict,
        detail,
        value,
        seconds: started.elapsed().as_secs_f64(),
        words: None,
        p_value: None,
        alpha: Some(crate::equivalence::DEFAULT_ALPHA),
        tests: Vec::new(),
    }
}

/// The verdict of [`check_equivalent_to_owen`] on ratios already measured over `seeds` seeds:
/// (verdict, detail, the ratio farthest from 1).
fn judge_ratios(
    ratios: &VarianceRatios,
    base: PowerOfTwoBase,
    seeds: u64,
    margin: f64,
) -> (Verdict, String, Option<f64>) {
    let judged = judge_statistics(ratios, base.q(), seeds, margin);
    let unjudged: Vec<String> = ratios
        .boxes
        .iter()
        .filter(|l| {
            let name = format!("box level {}", l.level);
            judged.iter().all(|(k, _)| *k != name)
        })
        .map(|l| {
            format!(
                "box level {} not judged ({:.0} expected hits, fewer than {MIN_EXPECTED_HITS})",
                l.level,
                expected_hits(seeds, base.q(), l.level)
            )
        })
        .collect();
    if judged.is_empty() {
        (
            Verdict::Fail,
            format!(
                "equivalence not shown: {} at {seeds} seeds (add --equivalence-seeds)",
                unjudged.join("; ")
            ),
            None,
        )
    } else {
        let all_equivalent = judged
            .iter()
            .all(|(_, e)| e.verdict == EquivalenceVerdict::Equivalent);
        let worst = judged
            .iter()
            .map(|(_, e)| e.ratio)
            .max_by(|a, b| (a.ln().abs()).total_cmp(&b.ln().abs()));
        let mut parts: Vec<String> = judged
            .iter()
            .map(|(name, e)| {
                format!(
                    "{name}: ratio {:.3}, 90% [{:.3}, {:.3}], {} (detects ±{:.1}% at power 0.8)",
                    e.ratio,
                    e.tost_interval[0],
                    e.tost_interval[1],
                    e.words(),
                    e.detectable * 100.0
                )
            })
            .collect();
        parts.extend(unjudged);
        if let Some(d) = ratios.translates.as_ref().filter(|d| d.translate_pairs > 0) {
            parts.push(format!("diagonal diagnosis: {}", d.words()));
        }
        (
            if all_equivalent {
                Verdict::Pass
            } else {
                Verdict::Fail
            },
            format!(
                "estimator variances and diagonal-cell error moments / exact Owen values (base {}, {seeds} seeds, margin ±{:.0}%, α = {}, 'different' Bonferroni over {} statistics): {}",
                base.base(),
                margin * 100.0,
                crate::equivalence::DEFAULT_ALPHA,
                judged.len(),
                parts.join("; ")
            ),
            worst,
        )
    }
}

#[cfg(test)]
#[path = "owen_equivalence_tests.rs"]
mod tests;
