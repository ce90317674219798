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
    let seq = SequenceKind::Sz16.build(dims, Width::W32).expect("sz16");
    let s = registry
        .build_with(
            request,
            &BuildContext {
                seed,
                default_base: SequenceKind::Sz16.base(),
            },
        )
        .expect("registry entry");
    (0..n as u64)
        .flat_map(|i| (0..dims).map(move |j| (i, j)))
        .map(|(i, j)| s.scramble(seq.point(i, j), Width::W32, j as u32))
        .collect()
}

/// Seeds per size of the discrepancy curves: as many as a budget of N²·seeds allows (2^18
/// quick, 2^24 full), between 16 and 256 seeds quick and 64 and 4000 full, so the small sizes,
/// where one seed costs little and the means are heavy-tailed, are measured to a few percent.
pub fn curve_seeds(n: usize, quick: bool) -> usize {
    let (budget, lo, hi) = if quick {
        (1usize << 18, 16, 256)
    } else {
        (1usize << 24, 64, 4000)
    };
    (budget / (n * n).max(1)).clamp(lo, hi)
}

/// The scramblers of the discrepancy curves and the largest log2 N of each: binary and base-16
/// ART against the oracles of their bases, and in the full report Q-ART and base 8 against
/// theirs (to N = 1024, which bounds their cost).
fn curve_requests(quick: bool) -> Vec<(&'static str, u32)> {
    let top = if quick { 8 } else { 12 };
    let mut v = vec![
        ("art-owen-2", top),
        ("art-owen-16p", top),
        ("owen-oracle:base=2", top),
        ("owen-oracle:base=16", top),
    ];
    if !quick {
        v.extend([
            ("q-art-4", 10),
            ("owen-oracle:base=4", 10),
            ("art-owen-8p", 10),
            ("owen-oracle:base=8", 10),
        ]);
    }
    v
}

/// Figure 2 data: ART against full-tree Owen scrambling of sz16 in the bases of
/// [`curve_requests`], with [`curve_seeds`] seeds per size.
pub fn discrepancy_curves(registry: &Registry, quick: bool) -> Vec<DiscrepancyCurve> {
    let pairs = curves::pair_list(16, false);
    curve_requests(quick)
        .into_iter()
        .map(|(request, max_log2)| {
            let sizes: Vec<usize> = (4..=max_log2).map(|k| 1usize << k).collect();
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
                        &|seed, n| sz16_words(registry, request, 16, n, seed),
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
        })
        .collect()
}
