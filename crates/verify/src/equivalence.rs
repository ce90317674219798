//! Equivalence verdicts on a ratio: is an implementation's statistic the same as the reference's
//! within a stated margin, different, or is the sample too small to say?
//!
//! A statistic is summarized as a ratio r = (implementation) / (reference) with a standard error
//! on ln r (delta method: `se = √((se_a/a)² + (se_b/b)²)` for two independent means, `se_a/a`
//! against an exact reference). With margin δ and level α:
//!
//! - **equivalent within ±δ** (two one-sided tests, TOST): the (1 − 2α) confidence interval of
//!   r lies inside [1 − δ, 1 + δ]. Each one-sided test has level α, and the intersection-union
//!   principle gives the whole verdict level α without correction, also for a claim that
//!   several statistics are all equivalent.
//! - **different**: the two-sided (1 − α/m) interval excludes 1, with m the number of
//!   statistics judged together (Bonferroni), so a family of m verdicts calls "different"
//!   falsely with probability at most α.
//! - **inconclusive**: neither; the verdict names about how many seeds would decide it at the
//!   current estimate (the standard error shrinks as 1/√seeds): enough for the TOST interval
//!   to fit inside the margin when the estimate lies inside it, else enough for the difference
//!   interval to exclude 1.
//!
//! The detectable effect is stated with every verdict: the smallest |ln r| that the difference
//! test finds with 80% power at this standard error, `(z_{1−α/2m} + z_{0.8}) · se`.

use serde::{Deserialize, Serialize};
use statrs::distribution::{ContinuousCDF, Normal};

/// The default margin δ: ±10% on a ratio.
pub const DEFAULT_MARGIN: f64 = 0.10;
/// The default level α of each one-sided test and of the difference family.
pub const DEFAULT_ALPHA: f64 = 0.05;
/// The most seeds an "inconclusive" verdict names (beyond it: "more than").
pub const MAX_SEEDS_NAMED: f64 = 1e9;

/// What an equivalence test concluded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum EquivalenceVerdict {
    /// The (1 − 2α) interval lies inside [1 − δ, 1 + δ].
    Equivalent,
    /// The (1 − α/m) two-sided interval excludes 1.
    Different,
    /// Neither.
    Inconclusive,
}

/// The settings of an equivalence judgement.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct EquivalenceSettings {
    /// The margin δ on the ratio (0 < δ < 1).
    pub margin: f64,
    /// The level α (0 < α < 0.5).
    pub alpha: f64,
    /// Statistics judged together (the Bonferroni divisor of the difference test, ≥ 1).
    pub family: usize,
}

impl EquivalenceSettings {
    /// Settings with `margin` and `alpha` for a family of `family` statistics; `None` unless
    /// 0 < margin < 1, 0 < alpha < 0.5 and family ≥ 1.
    pub fn new(margin: f64, alpha: f64, family: usize) -> Option<Self> {
        (margin > 0.0 && margin < 1.0 && alpha > 0.0 && alpha < 0.5 && family >= 1).then_some(
            EquivalenceSettings {
                margin,
                alpha,
                family,
            },
        )
    }
}

/// One statistic's equivalence judgement. JSON writes a value that is not finite (z of a
/// statistic with no spread, an unusable ratio) as `null`, and reads `null` back as NaN.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Equivalence {
    /// The estimated ratio implementation / reference.
    #[serde(deserialize_with = "null_as_nan")]
    pub ratio: f64,
    /// Standard error of ln(ratio).
    #[serde(deserialize_with = "null_as_nan")]
    pub log_se: f64,
    /// The (1 − 2α) interval of the ratio (the TOST interval).
    #[serde(deserialize_with = "nulls_as_nan")]
    pub tost_interval: [f64; 2],
    /// The (1 − α/m) two-sided interval of the ratio (the difference interval).
    #[serde(deserialize_with = "nulls_as_nan")]
    pub difference_interval: [f64; 2],
    /// z = ln(ratio) / se (infinite when every seed gave the same value and it is not 1).
    #[serde(deserialize_with = "null_as_nan")]
    pub z: f64,
    /// The verdict.
    pub verdict: EquivalenceVerdict,
    /// Seeds the estimate rests on.
    pub seeds: u64,
    /// For an inconclusive verdict: about how many seeds would decide it at this estimate
    /// (`None` when decided, or when the estimate is exactly at the margin or at 1).
    pub seeds_needed: Option<u64>,
    /// The smallest relative change (r − 1, as a fraction) the difference test detects with
    /// 80% power at this standard error.
    #[serde(deserialize_with = "null_as_nan")]
    pub detectable: f64,
    /// The settings judged under.
    pub settings: EquivalenceSettings,
}

/// Reads a JSON number, or `null` (what serde_json writes for NaN and ±∞) as NaN.
fn null_as_nan<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

/// [`null_as_nan`] for an interval.
fn nulls_as_nan<'de, D: serde::Deserializer<'de>>(d: D) -> Result<[f64; 2], D::Error> {
    let [a, b] = <[Option<f64>; 2]>::deserialize(d)?;
    Ok([a.unwrap_or(f64::NAN), b.unwrap_or(f64::NAN)])
}

fn z_upper(p: f64) -> f64 {
    Normal::new(0.0, 1.0)
        .expect("standard normal")
        .inverse_cdf(1.0 - p)
}

/// Judges a ratio estimate `ratio` with standard error `log_se` of its logarithm, from `seeds`
/// seeds. A ratio that is not positive and finite, or a standard error that is not finite
/// and non-negative, is inconclusive with no seeds named.
pub fn judge(ratio: f64, log_se: f64, seeds: u64, settings: EquivalenceSettings) -> Equivalence {
    let z_tost = z_upper(settings.alpha);
    let z_diff = z_upper(settings.alpha / (2.0 * settings.family as f64));
    let z_power = z_upper(0.2);
    let usable = ratio.is_finite() && ratio > 0.0 && log_se.is_finite() && log_se >= 0.0;
    let lr = if usable { ratio.ln() } else { f64::NAN };
    let (lo, hi) = ((1.0 - settings.margin).ln(), (1.0 + settings.margin).ln());
    let interval = |z: f64| [(lr - z * log_se).exp(), (lr + z * log_se).exp()];
    let tost_interval = interval(z_tost);
    let difference_interval = interval(z_diff);
    let verdict = if !usable {
        EquivalenceVerdict::Inconclusive
    } else if lr - z_tost * log_se >= lo && lr + z_tost * log_se <= hi {
        EquivalenceVerdict::Equivalent
    } else if lr.abs() > z_diff * log_se {
        EquivalenceVerdict::Different
    } else {
        EquivalenceVerdict::Inconclusive
    };
    let seeds_needed = if verdict != EquivalenceVerdict::Inconclusive || !usable {
        None
    } else {
        // The standard error needed, then seeds ∝ 1/se².
        let room = (hi - lr).min(lr - lo);
        let target = if room > 0.0 {
            room / z_tost
        } else {
            lr.abs() / z_diff
        };
        let k = seeds as f64 * (log_se / target).powi(2);
        (target > 0.0 && k.is_finite()).then(|| k.min(MAX_SEEDS_NAMED).ceil() as u64)
    };
    Equivalence {
        ratio,
        log_se,
        tost_interval,
        difference_interval,
        z: lr / log_se,
        verdict,
        seeds,
        seeds_needed,
        detectable: ((z_diff + z_power) * log_se).exp() - 1.0,
        settings,
    }
}

/// ln(mean_a / mean_b) and its standard error for two independent sample means with standard
/// errors `se_a`, `se_b` (delta method); `None` unless both means are positive and finite.
pub fn ratio_of_means(mean_a: f64, se_a: f64, mean_b: f64, se_b: f64) -> Option<(f64, f64)> {
    (mean_a > 0.0 && mean_b > 0.0 && mean_a.is_finite() && mean_b.is_finite()).then(|| {
        (
            mean_a / mean_b,
            ((se_a / mean_a).powi(2) + (se_b / mean_b).powi(2)).sqrt(),
        )
    })
}

impl Equivalence {
    /// The verdict in words: "equivalent within ±10%", "different", or "inconclusive: about
    /// K seeds needed".
    pub fn words(&self) -> String {
        let pct = self.settings.margin * 100.0;
        match self.verdict {
            EquivalenceVerdict::Equivalent => format!("equivalent within ±{pct:.0}%"),
            EquivalenceVerdict::Different => "different".into(),
            EquivalenceVerdict::Inconclusive => match self.seeds_needed {
                Some(k) if k as f64 >= MAX_SEEDS_NAMED => {
                    format!("inconclusive: more than {MAX_SEEDS_NAMED:.0e} seeds needed")
                }
                Some(k) => format!("inconclusive: about {k} seeds needed"),
                None => "inconclusive".into(),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_statistic_without_spread_is_judged_and_its_json_reads_back() {
        let settings = EquivalenceSettings::new(0.1, 0.05, 3).unwrap();
        // Every seed gave 15× Owen's value (a translation-only scramble): different, z = ∞.
        let off = judge(15.0, 0.0, 100, settings);
        assert_eq!(off.verdict, EquivalenceVerdict::Different);
        assert_eq!(off.z, f64::INFINITY);
        // Every seed gave Owen's value exactly: equivalent, z = 0/0.
        let on = judge(1.0, 0.0, 100, settings);
        assert_eq!(on.verdict, EquivalenceVerdict::Equivalent);
        for e in [off, on, judge(f64::NAN, 0.1, 100, settings)] {
            let text = serde_json::to_string(&e).unwrap();
            let back: Equivalence = serde_json::from_str(&text).unwrap();
            assert_eq!(back.verdict, e.verdict, "{text}");
            assert!(back.ratio == e.ratio || (back.ratio.is_nan() && e.ratio.is_nan()));
            assert!(back.z.is_nan() || back.z == e.z);
        }
    }

    fn settings(family: usize) -> EquivalenceSettings {
        EquivalenceSettings::new(0.10, 0.05, family).unwrap()
    }

    #[test]
    fn verdicts_follow_the_intervals() {
        // z_{0.95} = 1.645: a ratio of 1.02 with se 0.03 has TOST interval
        // [e^{0.0198-0.0493}, e^{0.0198+0.0493}] = [0.971, 1.072] ⊂ [0.9, 1.1].
        let e = judge(1.02, 0.03, 1000, settings(1));
        assert_eq!(e.verdict, EquivalenceVerdict::Equivalent);
        assert!((e.tost_interval[0] - 0.9709).abs() < 1e-3, "{e:?}");
        assert!((e.tost_interval[1] - 1.0716).abs() < 1e-3, "{e:?}");
        assert_eq!(e.words(), "equivalent within ±10%");
        assert_eq!(e.seeds_needed, None, "a decided verdict names no seeds");
        assert!((e.z - 1.02f64.ln() / 0.03).abs() < 1e-12);
        // Detectable with 80% power: exp((z_{0.975} + z_{0.8})·se) − 1.
        assert!((e.detectable - ((1.959964 + 0.841621) * 0.03f64).exp() + 1.0).abs() < 1e-5);
        let d = judge(1.5, 0.03, 1000, settings(1));
        assert_eq!(
            (d.verdict, d.seeds_needed),
            (EquivalenceVerdict::Different, None)
        );
        // The same se with the estimate near the margin: the interval pokes out.
        let near = judge(1.08, 0.03, 1000, settings(1));
        assert_eq!(near.verdict, EquivalenceVerdict::Different); // |ln 1.08|/0.03 = 2.57 > 1.96
        assert_eq!(
            judge(1.05, 0.03, 1000, settings(1)).verdict,
            EquivalenceVerdict::Inconclusive
        );
        // Bonferroni: with 20 statistics the difference needs |z| > 3.02.
        assert_eq!(
            judge(1.08, 0.03, 1000, settings(20)).verdict,
            EquivalenceVerdict::Inconclusive
        );
        assert_eq!(
            judge(1.5, 0.03, 1000, settings(20)).verdict,
            EquivalenceVerdict::Different
        );
        // Below 1: the lower bound fails the TOST (ln 0.92 − 1.645·0.03 < ln 0.9), |z| = 2.78.
        assert_eq!(
            judge(0.92, 0.03, 1000, settings(1)).verdict,
            EquivalenceVerdict::Different
        );
        assert_eq!(
            judge(0.95, 0.02, 1000, settings(1)).verdict,
            EquivalenceVerdict::Equivalent
        );
        // The difference level is α/2 two-sided for one statistic: |z| = 2.05 > 1.96 differs.
        let z205 = (2.05f64 * 0.03).exp();
        assert_eq!(
            judge(z205, 0.03, 1000, settings(1)).verdict,
            EquivalenceVerdict::Different
        );
        // Garbage in: inconclusive, nothing named.
        for (r, se) in [
            (0.0, 0.1),
            (f64::NAN, 0.1),
            (1.0, f64::INFINITY),
            (-1.0, 0.1),
        ] {
            let e = judge(r, se, 10, settings(1));
            assert_eq!(e.verdict, EquivalenceVerdict::Inconclusive);
            assert_eq!(e.seeds_needed, None);
        }
    }

    #[test]
    fn seeds_needed_decide_the_verdict_when_used() {
        // Inside the margin: the named K makes the TOST interval fit (se·√(R/K)).
        let e = judge(1.03, 0.05, 100, settings(1));
        assert_eq!(e.verdict, EquivalenceVerdict::Inconclusive);
        let k = e.seeds_needed.unwrap();
        let se_k = 0.05 * (100.0 / k as f64).sqrt();
        assert_eq!(
            judge(1.03, se_k, k, settings(1)).verdict,
            EquivalenceVerdict::Equivalent
        );
        let se_less = 0.05 * (100.0 / (k as f64 * 0.9)).sqrt();
        assert_ne!(
            judge(1.03, se_less, k, settings(1)).verdict,
            EquivalenceVerdict::Equivalent
        );
        // Outside the margin: K makes the difference interval exclude 1.
        let e = judge(1.15, 0.1, 64, settings(4));
        assert_eq!(e.verdict, EquivalenceVerdict::Inconclusive);
        let k = e.seeds_needed.unwrap();
        let se_k = 0.1 * (64.0 / k as f64).sqrt();
        assert_eq!(
            judge(1.15, se_k, k, settings(4)).verdict,
            EquivalenceVerdict::Different
        );
        assert_eq!(e.words(), format!("inconclusive: about {k} seeds needed"));
        // An estimate a hair inside the margin needs more seeds than are named.
        let edge = judge(1.1 * (-1e-6f64).exp(), 0.05, 100, settings(1));
        assert_eq!(edge.verdict, EquivalenceVerdict::Inconclusive);
        assert_eq!(edge.words(), "inconclusive: more than 1e9 seeds needed");
    }

    #[test]
    fn ratio_of_means_uses_the_delta_method() {
        let (r, se) = ratio_of_means(3.0, 0.3, 2.0, 0.1).unwrap();
        assert_eq!(r, 1.5);
        assert!((se - (0.01f64 + 0.0025).sqrt()).abs() < 1e-12);
        assert!(ratio_of_means(1.0, 0.1, 0.0, 0.1).is_none());
        assert!(ratio_of_means(0.0, 0.1, 1.0, 0.1).is_none());
        assert!(ratio_of_means(1.0, 0.1, -1.0, 0.1).is_none());
        assert!(EquivalenceSettings::new(0.0, 0.05, 1).is_none());
        assert!(EquivalenceSettings::new(0.1, 0.5, 1).is_none());
        assert!(EquivalenceSettings::new(0.1, 0.05, 0).is_none());
    }

    #[test]
    fn false_alarm_and_power_on_simulated_estimates() {
        // Level: 2,000 simulated means of 64 normal draws with equal true means, judged with a
        // family of 1 at α = 0.05: "different" at most about 5% (binomial SE 0.5%), so ≤ 7%.
        // Power: a true ratio of 1.02 with 4,000 draws per side is "equivalent" almost always.
        use gartowen_core::SplitMix64;
        let mut rng = SplitMix64::new(17);
        let mut normal = move || {
            // Box–Muller from two uniforms in (0, 1].
            let (u, v) = (1.0 - rng.next_f64(), rng.next_f64());
            (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
        };
        let mut sample = |n: usize, mean: f64| {
            let xs: Vec<f64> = (0..n).map(|_| mean + 0.3 * normal()).collect();
            let m = xs.iter().sum::<f64>() / n as f64;
            let var = xs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n as f64 - 1.0);
            (m, (var / n as f64).sqrt())
        };
        let mut different = 0;
        for _ in 0..2000 {
            let (a, sa) = sample(64, 1.0);
            let (b, sb) = sample(64, 1.0);
            let (r, se) = ratio_of_means(a, sa, b, sb).unwrap();
            different +=
                (judge(r, se, 64, settings(1)).verdict == EquivalenceVerdict::Different) as u32;
        }
        assert!(different <= 140, "{different} of 2000 false 'different'");
        assert!(
            different >= 40,
            "{different} of 2000: the test never rejects"
        );
        let mut equivalent = 0;
        for _ in 0..50 {
            let (a, sa) = sample(4000, 1.02);
            let (b, sb) = sample(4000, 1.0);
            let (r, se) = ratio_of_means(a, sa, b, sb).unwrap();
            equivalent +=
                (judge(r, se, 4000, settings(1)).verdict == EquivalenceVerdict::Equivalent) as u32;
        }
        assert_eq!(equivalent, 50);
        // A 20% difference with 4,000 draws is found every time.
        let (a, sa) = sample(4000, 1.2);
        let (b, sb) = sample(4000, 1.0);
        let (r, se) = ratio_of_means(a, sa, b, sb).unwrap();
        assert_eq!(
            judge(r, se, 4000, settings(1)).verdict,
            EquivalenceVerdict::Different
        );
    }
}
