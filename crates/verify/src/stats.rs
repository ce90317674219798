//! The statistics behind the battery's laws: χ² goodness of fit with exact cell
//! probabilities, its power (the smallest Cohen's w detected at power 0.9, from the noncentral
//! χ² law), Poisson tails for collision counts, and Bonferroni thresholds.
//!
//! Every verdict compares a p-value with a per-test level α' = α / (number of tests judged), so
//! the family-wise false-alarm rate of a run is at most α (Bonferroni).

use statrs::distribution::{ChiSquared, ContinuousCDF};
use std::collections::BTreeMap;
use std::sync::Mutex;

/// The family-wise significance level of one `verify` run (all implementations, all tests).
pub const FAMILY_ALPHA: f64 = 1e-3;

/// The power at which [`min_detectable_w`] states the detectable effect size.
pub const POWER: f64 = 0.9;

/// A χ² goodness-of-fit result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChiSquare {
    /// The statistic Σ (O − E)² / E over cells with E > 0.
    pub statistic: f64,
    /// Degrees of freedom: cells with E > 0, minus one.
    pub dof: usize,
    /// P(χ²_dof ≥ statistic); 0 when an observation fell in a cell of probability 0.
    pub p_value: f64,
    /// The number of observations.
    pub n: u64,
}

/// χ² test of `counts` against cell probabilities `probs` (same length, summing to 1). An
/// observation in a cell of probability 0 is impossible under the null law: p = 0.
///
/// ```
/// use gartowen_verify::stats::chi_square;
/// let fair = chi_square(&[500, 500], &[0.5, 0.5]);
/// assert_eq!(fair.statistic, 0.0);
/// assert!(fair.p_value > 0.99);
/// let biased = chi_square(&[600, 400], &[0.5, 0.5]);
/// assert!(biased.p_value < 1e-9);
/// ```
pub fn chi_square(counts: &[u64], probs: &[f64]) -> ChiSquare {
    assert_eq!(counts.len(), probs.len(), "one probability per cell");
    let n: u64 = counts.iter().sum();
    let mut statistic = 0.0;
    let mut cells = 0usize;
    let mut impossible = false;
    for (&c, &p) in counts.iter().zip(probs) {
        if p > 0.0 {
            let e = p * n as f64;
            statistic += (c as f64 - e).powi(2) / e;
            cells += 1;
        } else if c > 0 {
            impossible = true;
        }
    }
    let dof = cells.saturating_sub(1);
    let p_value = if impossible {
        0.0
    } else if dof == 0 || n == 0 {
        1.0
    } else {
        ChiSquared::new(dof as f64).expect("dof ≥ 1").sf(statistic)
    };
    ChiSquare {
        statistic,
        dof,
        p_value,
        n,
    }
}

/// P(X > x) for a noncentral χ² with `dof` degrees of freedom and noncentrality `lambda`: the
/// Poisson(λ/2) mixture of central χ² laws with dof + 2j degrees of freedom.
pub fn noncentral_chi_square_sf(x: f64, dof: usize, lambda: f64) -> f64 {
    let half = lambda / 2.0;
    // Sum outward from the Poisson mode so that large λ loses nothing.
    let mode = half.floor() as u64;
    let log_weight = |j: u64| -half + j as f64 * half.ln() - ln_factorial(j);
    let term = |j: u64| {
        let w = if half == 0.0 {
            if j == 0 {
                1.0
            } else {
                0.0
            }
        } else {
            log_weight(j).exp()
        };
        w * ChiSquared::new((dof + 2 * j as usize) as f64)
            .expect("dof ≥ 1")
            .sf(x)
    };
    let mut total = term(mode);
    let mut j = mode + 1;
    loop {
        let t = term(j);
        total += t;
        // Poisson weights fall off past the mode; 10^5 terms bound the loop whatever happens.
        if (t < 1e-14 && j > mode + 5) || j > mode + 100_000 {
            break;
        }
        j += 1;
    }
    let mut j = mode;
    while j > 0 {
        j -= 1;
        let t = term(j);
        total += t;
        if t < 1e-14 && j + 5 < mode {
            break;
        }
    }
    total.min(1.0)
}

fn ln_factorial(n: u64) -> f64 {
    statrs::function::gamma::ln_gamma(n as f64 + 1.0)
}

/// The smallest Cohen's effect size w = sqrt(Σ (p1 − p0)² / p0) that a χ² test with `dof`
/// degrees of freedom on `n` observations detects with probability [`POWER`] at level `alpha`.
///
/// ```
/// use gartowen_verify::stats::min_detectable_w;
/// // The textbook value: 1 dof, α = 0.05, power 0.9 needs λ ≈ 10.5, so w ≈ 0.10 at n = 1000.
/// let w = min_detectable_w(1, 1000, 0.05);
/// assert!((w - 0.1025).abs() < 0.002, "{w}");
/// ```
pub fn min_detectable_w(dof: usize, n: u64, alpha: f64) -> f64 {
    if dof == 0 || n == 0 {
        return f64::INFINITY;
    }
    // A run asks for the same (dof, n, α) for every implementation and depth, and each answer
    // costs about a hundred noncentral tails (an eighth of a quick run's time before), so
    // answers are remembered: a pure function of its key, the same bits either way.
    static KNOWN: Mutex<BTreeMap<(usize, u64, u64), f64>> = Mutex::new(BTreeMap::new());
    let key = (dof, n, alpha.to_bits());
    let table = || {
        KNOWN
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    };
    if let Some(&w) = table().get(&key) {
        return w;
    }
    let w = detectable_w_uncached(dof, n, alpha);
    let mut known = table();
    if known.len() < KNOWN_CAPACITY {
        known.insert(key, w);
    }
    w
}

/// At most this many answers of [`min_detectable_w`] are remembered (a run uses a few dozen
/// keys; an entry is 32 bytes).
const KNOWN_CAPACITY: usize = 4096;

/// [`min_detectable_w`] computed afresh: bisection on the noncentrality λ.
fn detectable_w_uncached(dof: usize, n: u64, alpha: f64) -> f64 {
    let critical = ChiSquared::new(dof as f64)
        .expect("dof ≥ 1")
        .inverse_cdf(1.0 - alpha);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    // The power grows with λ; past 2^50 nothing is detectable at this size (a safeguard).
    while noncentral_chi_square_sf(critical, dof, hi) < POWER {
        hi *= 2.0;
        if hi > 1e15 {
            return f64::INFINITY;
        }
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if noncentral_chi_square_sf(critical, dof, mid) < POWER {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (hi / n as f64).sqrt()
}

/// P(X ≥ k) for X ~ Poisson(λ), accurate for tiny λ (no 1 − cdf cancellation).
///
/// ```
/// use gartowen_verify::stats::poisson_sf;
/// assert_eq!(poisson_sf(0, 3.0), 1.0);
/// assert!((poisson_sf(1, 1e-20) - 1e-20).abs() < 1e-30);
/// assert!((poisson_sf(2, 1.0) - (1.0 - 2.0 / std::f64::consts::E)).abs() < 1e-12);
/// ```
pub fn poisson_sf(k: u64, lambda: f64) -> f64 {
    if k == 0 {
        return 1.0;
    }
    if lambda <= 0.0 {
        return 0.0;
    }
    if (k as f64) <= lambda {
        // Near or below the mean: the complement is well conditioned.
        let mut cdf = 0.0;
        let mut term = (-lambda).exp();
        for j in 0..k {
            cdf += term;
            term *= lambda / (j + 1) as f64;
        }
        return (1.0 - cdf).clamp(0.0, 1.0);
    }
    // Upper tail: sum terms from k up, in log space for the first one.
    let mut term = (-lambda + k as f64 * lambda.ln() - ln_factorial(k)).exp();
    let mut total = 0.0;
    let mut j = k;
    while term > total * 1e-17 && j < k + 10_000 {
        total += term;
        j += 1;
        term *= lambda / j as f64;
    }
    total.min(1.0)
}

/// The per-test level that spreads `family_alpha` over `tests` tests (Bonferroni).
pub fn bonferroni(family_alpha: f64, tests: usize) -> f64 {
    family_alpha / tests.max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noncentral_with_zero_lambda_is_central() {
        let c = ChiSquared::new(7.0).unwrap();
        for x in [0.5, 3.0, 7.0, 20.0] {
            assert!((noncentral_chi_square_sf(x, 7, 0.0) - c.sf(x)).abs() < 1e-12);
        }
    }

    #[test]
    fn noncentral_mean_is_dof_plus_lambda() {
        // E[X] = ∫ sf: integrate numerically.
        for (dof, lambda) in [(3usize, 5.0), (10, 40.0)] {
            let (mut mean, dx) = (0.0, 0.01);
            let mut x = dx / 2.0;
            while x < 400.0 {
                mean += noncentral_chi_square_sf(x, dof, lambda) * dx;
                x += dx;
            }
            assert!((mean - (dof as f64 + lambda)).abs() < 0.05, "{mean}");
        }
    }

    #[test]
    fn nothing_is_detectable_without_cells_or_observations() {
        assert_eq!(min_detectable_w(0, 1000, 0.05), f64::INFINITY);
        assert_eq!(min_detectable_w(3, 0, 0.05), f64::INFINITY);
    }

    #[test]
    fn detectable_effect_shrinks_with_the_sample() {
        let a = min_detectable_w(15, 1000, 1e-5);
        let b = min_detectable_w(15, 4000, 1e-5);
        assert!((a / b - 2.0).abs() < 1e-6, "{a} {b}");
    }

    #[test]
    fn chi_square_statistic_dof_and_p_by_hand() {
        // (600 − 500)²/500 + (400 − 500)²/500 = 40 on 1 dof.
        let c = chi_square(&[600, 400], &[0.5, 0.5]);
        assert!((c.statistic - 40.0).abs() < 1e-12);
        assert_eq!((c.dof, c.n), (1, 1000));
        assert!((c.p_value - ChiSquared::new(1.0).unwrap().sf(40.0)).abs() < 1e-20);
        // Unequal cells: E = (250, 750); χ² = 50²/250 + 50²/750 = 13.33…, zero-probability
        // cells are left out of the dof.
        let c = chi_square(&[300, 700, 0], &[0.25, 0.75, 0.0]);
        assert!((c.statistic - 40.0 / 3.0).abs() < 1e-12, "{}", c.statistic);
        assert_eq!(c.dof, 1);
        assert_eq!(bonferroni(1e-3, 4), 2.5e-4);
        assert_eq!(bonferroni(1e-3, 0), 1e-3);
    }

    #[test]
    fn impossible_cells_give_p_zero() {
        assert_eq!(chi_square(&[5, 1], &[1.0, 0.0]).p_value, 0.0);
        assert_eq!(chi_square(&[5, 0], &[1.0, 0.0]).p_value, 1.0);
    }

    #[test]
    fn poisson_tail_matches_direct_sum() {
        for lambda in [0.3, 2.0, 9.5] {
            for k in 0..15u64 {
                let direct: f64 = (k..200)
                    .map(|j| (-lambda + j as f64 * f64::ln(lambda) - ln_factorial(j)).exp())
                    .sum();
                assert!(
                    (poisson_sf(k, lambda) - direct).abs() < 1e-12,
                    "{lambda} {k}"
                );
            }
        }
    }
}
