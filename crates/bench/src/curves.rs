//! Figure 2 data: the mean L2-star D² of sz16 against N, jointly in 16-D and for every pair
//! (0, j), for ART against the full-tree Owen scramble of the same base, with standard errors.

use gartowen::core::{BuildContext, Registry, Width};
use gartowen::discrepancy::{curves, Kind};
use gartowen::seq::SequenceKind;
use serde::{Deserialize, Serialize};

/// Figure 2 data: mean L2-star D² of sz16 against N, jointly in 16-D and for pairs (0, j).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DiscrepancyCurve {
    /// Scrambler request.
    pub scrambler: String,
    /// Sizes.
    pub n: Vec<usize>,
    /// Mean joint D².
    pub joint: Vec<f64>,
    /// Pairs.
    pub pairs: Vec<[usize; 2]>,
    /// Mean 2-D D² per size, per pair.
    pub pair_values: Vec<Vec<f64>>,
    /// Seeds averaged per point.
    #[serde(default)]
    pub seeds: usize,
    /// Standard error of each mean joint D² (empty in reports written before it existed).
    #[serde(default)]
    pub joint_se: Vec<f64>,
    /// Standard error of each mean pair D², per size, per pair.
    #[serde(default)]
    pub pair_se: Vec<Vec<f64>>,
    /// Seeds averaged per size, where they differ by size (more at small N, where each seed
    /// is cheap and the statistic is heavy-tailed); empty: `seeds` at every size.
    #[serde(default)]
    pub seeds_per_n: Vec<usize>,
}

impl DiscrepancyCurve {
    /// Seeds averaged at the `k`-th size.
    pub fn seeds_at(&self, k: usize) -> usize {
        self.seeds_per_n.get(k).copied().unwrap_or(self.seeds)
    }

    /// The standard error of each [`DiscrepancyCurve::pair_spread`] (delta method on
    /// ln(max / min) with the two extreme pairs' standard errors; it ignores that the extremes
    /// were selected, so it understates the noise when many pairs are alike). NaN without
    /// standard errors.
    pub fn pair_spread_se(&self) -> Vec<f64> {
        self.pair_values
            .iter()
            .enumerate()
            .map(|(k, v)| {
                let arg = |better: fn(f64, f64) -> bool| {
                    (0..v.len()).fold(0, |b, i| if better(v[i], v[b]) { i } else { b })
                };
                let (hi, lo) = (arg(|a, b| a > b), arg(|a, b| a < b));
                let se = |i: usize| self.pair_se.get(k).and_then(|s| s.get(i)).copied();
                match (se(hi), se(lo)) {
                    (Some(sh), Some(sl)) => {
                        (v[hi] / v[lo]) * ((sh / v[hi]).powi(2) + (sl / v[lo]).powi(2)).sqrt()
                    }
                    _ => f64::NAN,
                }
            })
            .collect()
    }

    /// max over pairs / min over pairs of the mean 2-D D², per size: 1 when every pair is as
    /// good as every other (the paper's "consistent quality" in one number per N).
    pub fn pair_spread(&self) -> Vec<f64> {
        self.pair_values
            .iter()
            .map(|v| {
                let max = v.iter().copied().fold(f64::MIN, f64::max);
                let min = v.iter().copied().fold(f64::MAX, f64::min);
                max / min
            })
            .collect()
    }
}

/// Row-major words of the first `dims` dimensions of sz16, scrambled by `request` with `seed`.
pub(crate) fn sz16_words(
    registry: &Registry,
    request: &str,
    dims: usize,
    n: usize,
    seed: u64,
) -> Vec<u64> {
    sequence_words(registry, SequenceKind::Sz16, request, dims, n, seed)
}

/// The first `n` points of `kind` in `dims` dimensions, scrambled by `request` with `seed`, as
/// 32-bit words (row-major).
fn sequence_words(
    registry: &Registry,
    kind: SequenceKind,
    request: &str,
    dims: usize,
    n: usize,
    seed: u64,
) -> Vec<u64> {
    let seq = kind.build(dims, Width::W32).expect("a built-in sequence");
    let s = registry
        .build_with(
            request,
            &BuildContext {
                seed,
                default_base: kind.base(),
            },
        )
        .expect("registry entry");
    (0..n as u64)
        .flat_map(|i| (0..dims).map(move |j| (i, j)))
        .map(|(i, j)| s.scramble(seq.point(i, j), Width::W32, j as u32))
        .collect()
}

/// Seeds per size of the discrepancy curves: as many as a budget of N²·seeds allows (2^17
/// quick, 2^24 full), between 16 and 128 seeds quick and 1000 and 4000 full, so the small
/// sizes, where one seed costs little and the means are heavy-tailed, are measured to a few
/// percent, and every full-report size has the 1,000 seeds that settle binary ART against
/// binary Owen (the quick run's 16 seeds once showed a 1.5–1.9× gap that is not there).
pub fn curve_seeds(n: usize, quick: bool) -> usize {
    let (budget, lo, hi) = if quick {
        (1usize << 17, 16, 128)
    } else {
        (1usize << 24, 1000, 4000)
    };
    (budget / (n * n).max(1)).clamp(lo, hi)
}

/// The sizes of the discrepancy curves up to `max`: the powers of two from 16, and sizes between
/// them that are powers of neither 2 nor 16 (the paper stresses non-powers of 16).
pub fn curve_sizes(quick: bool, max: usize) -> Vec<usize> {
    let extra: &[usize] = if quick {
        &[24, 48, 100]
    } else {
        &[24, 48, 100, 300, 1000, 3000]
    };
    let mut sizes: Vec<usize> = (4..=12)
        .map(|k| 1usize << k)
        .chain(extra.iter().copied())
        .filter(|&n| n <= max)
        .collect();
    sizes.sort_unstable();
    sizes
}

/// The scramblers of the discrepancy curves and the largest N of each: binary and base-16 ART
/// against the oracles of their bases, and in the full report Q-ART (translation-only and with
/// composed linear parts) and base 8 against theirs (to N = 1024, which bounds their cost).
fn curve_requests(quick: bool) -> Vec<(&'static str, usize)> {
    let top = if quick { 256 } else { 4096 };
    let mut v = vec![
        ("art-owen-2", top),
        ("art-owen-16p", top),
        ("owen-oracle:base=2", top),
        ("owen-oracle:base=16", top),
        (FIXED_TABLE, top),
    ];
    if !quick {
        v.extend([
            ("q-art-4", 1024),
            ("q-art-4:compose=linear", 1024),
            ("owen-oracle:base=4", 1024),
            ("art-owen-8p", 1024),
            ("owen-oracle:base=8", 1024),
        ]);
    }
    v
}

/// Figure 2 data: ART against full-tree Owen scrambling of sz16 in the bases of
/// `curve_requests`, with [`curve_seeds`] seeds per size.
pub fn discrepancy_curves(registry: &Registry, quick: bool) -> Vec<DiscrepancyCurve> {
    curve_requests(quick)
        .into_iter()
        .map(|(request, max_n)| measure_curve(registry, SequenceKind::Sz16, request, max_n, quick))
        .collect()
}

/// Figure 2b's baseline: Sobol's first 16 dimensions under exact binary Owen scrambling
/// (`owen-oracle:base=2`), at the sizes and seeds of the sz16 curves.
pub fn sobol_owen_curve(registry: &Registry, quick: bool) -> DiscrepancyCurve {
    let top = curve_requests(quick)[0].1;
    measure_curve(registry, SequenceKind::Sobol, SOBOL_BASELINE, top, quick)
}

/// A renderer's fixed table: one `art-owen-16p` table drawn from seed 7, each curve seed keying
/// only roots and shifts; the report repeats its equivalence verdicts with it (issue 58).
pub const FIXED_TABLE: &str = "art-owen-16p:table-seed=7";

/// The scrambler of [`sobol_owen_curve`].
pub const SOBOL_BASELINE: &str = "owen-oracle:base=2";

/// One curve of Figure 2: `request` scrambling the first 16 dimensions of `kind`, at
/// [`curve_sizes`] up to `max_n` with [`curve_seeds`] seeds per size.
pub fn measure_curve(
    registry: &Registry,
    kind: SequenceKind,
    request: &str,
    max_n: usize,
    quick: bool,
) -> DiscrepancyCurve {
    let pairs = curves::pair_list(16, false);
    let sizes = curve_sizes(quick, max_n);
    let points: Vec<_> = sizes
        .iter()
        .flat_map(|&n| {
            let seeds: Vec<u64> = (0..curve_seeds(n, quick) as u64).collect();
            curves::curve(
                Kind::L2Star,
                16,
                Width::W32,
                &[n],
                &seeds,
                &pairs,
                &|seed, n| sequence_words(registry, kind, request, 16, n, seed),
            )
            .points
        })
        .collect();
    let seeds_per_n: Vec<usize> = sizes.iter().map(|&n| curve_seeds(n, quick)).collect();
    DiscrepancyCurve {
        scrambler: request.to_string(),
        n: points.iter().map(|p| p.n).collect(),
        joint: points.iter().map(|p| p.joint).collect(),
        pairs: pairs.clone(),
        pair_values: points.iter().map(|p| p.pairs.clone()).collect(),
        seeds: seeds_per_n.iter().copied().min().unwrap_or(0),
        joint_se: points.iter().map(|p| p.joint_se).collect(),
        pair_se: points.iter().map(|p| p.pairs_se.clone()).collect(),
        seeds_per_n,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_follow_the_budget_between_their_floors_and_ceilings() {
        // Full: 2^24 / N², between 1,000 and 4,000 (every full-report size has 1,000 seeds).
        assert_eq!(curve_seeds(16, false), 4000);
        assert_eq!(curve_seeds(100, false), (1 << 24) / 10_000);
        assert_eq!(curve_seeds(128, false), 1024);
        assert_eq!(curve_seeds(4096, false), 1000);
        // Quick: 2^17 / N², between 16 and 128.
        assert_eq!(curve_seeds(16, true), 128);
        assert_eq!(curve_seeds(64, true), 32);
        assert_eq!(curve_seeds(256, true), 16);
        // The Figure 2b baseline and the fixed table ride on the same requests.
        let quick = curve_requests(true);
        assert!(quick.contains(&(FIXED_TABLE, 256)) && quick.contains(&("art-owen-2", 256)));
        assert_eq!(curve_requests(false)[0], ("art-owen-2", 4096));
    }
}
