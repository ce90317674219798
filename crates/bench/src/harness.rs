//! The RMSE harness: for each method (a sequence with a scrambler, or plain random points) and
//! each integrand family, the root-mean-square integration error over R independent
//! replicates at every requested N, fitted convergence slopes, and the sampling time per point
//! measured in the same run.
//!
//! Replicate r uses scrambler seed `derive_seed(seed, r)` and integrand instance r; the
//! estimates for all N come from prefixes of one point set of the largest N. Replicates run in
//! parallel and are reduced in replicate order, so every error figure is bit-identical for any
//! thread count. Times are measured per replicate and are the only non-deterministic output.

use crate::integrands::{Family, Smoothness};
use gartowen::core::{derive_seed, BuildContext, Registry, Scrambler, SplitMix64, Width};
use gartowen::seq::SequenceKind;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// How points are produced.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Method {
    /// Sequence name, or `random` for independent uniform points.
    pub sequence: String,
    /// Registry request of the scrambler (`none` for the unscrambled sequence; empty for random).
    pub scrambler: String,
}

impl Method {
    /// `sequence+scrambler`, or `random`.
    pub fn label(&self) -> String {
        if self.sequence == "random" {
            "random".into()
        } else {
            format!("{}+{}", self.sequence, self.scrambler)
        }
    }

    /// The base whose powers are the natural sample sizes (2 for random).
    pub fn base(&self) -> u64 {
        self.sequence
            .parse::<SequenceKind>()
            .map_or(2, |k| k.base().base() as u64)
    }
}

/// Harness settings.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct HarnessConfig {
    /// Sample sizes (any; powers of the method's base are used for slopes).
    pub sizes: Vec<usize>,
    /// Independent replicates R.
    pub replicates: u64,
    /// Master seed.
    pub seed: u64,
}

/// RMSE against N for one integrand family.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ErrorCurve {
    /// Integrand family.
    pub integrand: String,
    /// Its smoothness class.
    pub smoothness: Smoothness,
    /// Sample sizes.
    pub n: Vec<usize>,
    /// RMSE at each size.
    pub rmse: Vec<f64>,
    /// Least-squares slope of log RMSE against log N over powers of the base with N ≥ 64.
    pub slope: Option<f64>,
}

/// All curves of one method, with its speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MethodResult {
    /// The method.
    pub method: Method,
    /// Label (`sequence+scrambler`).
    pub label: String,
    /// Base of the sizes used for slopes.
    pub base: u64,
    /// Curves, one per family, in family order.
    pub curves: Vec<ErrorCurve>,
    /// Seconds to produce one point (all coordinates), averaged over replicates.
    pub seconds_per_point: f64,
}

/// Errors the harness reports.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum HarnessError {
    /// Unknown sequence or scrambler, or too many dimensions.
    Method(String),
    /// No sizes, a zero size or zero replicates.
    Config(String),
}

impl std::fmt::Display for HarnessError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            HarnessError::Method(m) | HarnessError::Config(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for HarnessError {}

/// Least-squares slope of ln y against ln x (None with fewer than 2 points or a zero y).
pub fn fit_slope(x: &[f64], y: &[f64]) -> Option<f64> {
    if x.len() < 2 || y.iter().any(|v| *v <= 0.0 || !v.is_finite()) {
        return None;
    }
    let lx: Vec<f64> = x.iter().map(|v| v.ln()).collect();
    let ly: Vec<f64> = y.iter().map(|v| v.ln()).collect();
    let n = lx.len() as f64;
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx).powi(2)).sum();
    Some(sxy / sxx)
}

/// Whether n is a power of `base`.
pub fn is_power_of(n: usize, base: u64) -> bool {
    let mut m = 1u64;
    while (m as usize) < n {
        m *= base;
    }
    m as usize == n
}

/// Produces the `n × dims` points of replicate `r` (row-major values) and the seconds it took.
fn points(
    registry: &Registry,
    method: &Method,
    dims: usize,
    n: usize,
    seed: u64,
) -> Result<(Vec<f64>, f64), HarnessError> {
    let start = Instant::now();
    if method.sequence == "random" {
        let mut rng = SplitMix64::new(seed);
        let v = (0..n * dims).map(|_| rng.next_f64()).collect();
        return Ok((v, start.elapsed().as_secs_f64()));
    }
    let kind: SequenceKind = method
        .sequence
        .parse()
        .map_err(|e| HarnessError::Method(format!("sequence '{}': {e}", method.sequence)))?;
    let seq = kind
        .build(dims, Width::W32)
        .map_err(|e| HarnessError::Method(format!("{}: {e}", method.sequence)))?;
    let scrambler: Box<dyn Scrambler> = registry
        .build_with(
            &method.scrambler,
            &BuildContext {
                seed,
                default_base: kind.base(),
            },
        )
        .map_err(|e| HarnessError::Method(format!("{}: {e}", method.scrambler)))?;
    if !scrambler.supports_width(Width::W32) {
        return Err(HarnessError::Method(format!(
            "{} does not scramble 32-bit words",
            method.scrambler
        )));
    }
    // Each dimension's column through the batch path, then row-major values.
    let mut v = vec![0.0; n * dims];
    let mut column = vec![0u64; n];
    for j in 0..dims {
        seq.fill_points(j, 0, &mut column);
        scrambler.scramble_batch(&mut column, Width::W32, j as u32);
        for (i, &x) in column.iter().enumerate() {
            v[i * dims + j] = gartowen::core::word_to_f64(x, Width::W32);
        }
    }
    Ok((v, start.elapsed().as_secs_f64()))
}

/// One replicate's squared errors, [family][size], and its sampling seconds.
type ReplicateErrors = (Vec<Vec<f64>>, f64);

/// Runs one method over the families.
pub fn run_method(
    registry: &Registry,
    method: &Method,
    families: &[Box<dyn Family>],
    config: &HarnessConfig,
) -> Result<MethodResult, HarnessError> {
    if config.sizes.is_empty() || config.sizes.contains(&0) || config.replicates == 0 {
        return Err(HarnessError::Config(format!(
            "sizes {:?} and {} replicates: need nonzero sizes and replicates",
            config.sizes, config.replicates
        )));
    }
    let mut sizes = config.sizes.clone();
    sizes.sort_unstable();
    sizes.dedup();
    let n_max = *sizes.last().expect("nonempty");
    let dims = families.iter().map(|f| f.dims()).max().unwrap_or(1);
    // Per replicate: squared errors [family][size] and the sampling time.
    let per_rep: Vec<Result<ReplicateErrors, HarnessError>> = (0..config.replicates)
        .into_par_iter()
        .map(|r| {
            let seed = derive_seed(config.seed, r);
            let (x, secs) = points(registry, method, dims, n_max, seed)?;
            let errs = families
                .iter()
                .map(|fam| {
                    let f = fam.instance(r);
                    let exact = f.exact();
                    // Neumaier summation: the error of a 2^16-term sum stays far below the RMSE.
                    let (mut sum, mut comp) = (0.0f64, 0.0f64);
                    let mut out = Vec::with_capacity(sizes.len());
                    let mut next = 0;
                    for i in 0..n_max {
                        let v = f.eval(&x[i * dims..(i + 1) * dims]);
                        let t = sum + v;
                        comp += if sum.abs() >= v.abs() {
                            (sum - t) + v
                        } else {
                            (v - t) + sum
                        };
                        sum = t;
                        while next < sizes.len() && sizes[next] == i + 1 {
                            let e = (sum + comp) / (i + 1) as f64 - exact;
                            out.push(e * e);
                            next += 1;
                        }
                    }
                    out
                })
                .collect();
            Ok((errs, secs))
        })
        .collect();
    let mut mse = vec![vec![0.0; sizes.len()]; families.len()];
    let mut seconds = 0.0;
    for rep in per_rep {
        let (errs, secs) = rep?;
        seconds += secs;
        for (m, e) in mse.iter_mut().zip(&errs) {
            for (a, b) in m.iter_mut().zip(e) {
                *a += b;
            }
        }
    }
    let base = method.base();
    let curves = families
        .iter()
        .zip(&mse)
        .map(|(fam, m)| {
            let rmse: Vec<f64> = m
                .iter()
                .map(|s| (s / config.replicates as f64).sqrt())
                .collect();
            let (xs, ys): (Vec<f64>, Vec<f64>) = sizes
                .iter()
                .zip(&rmse)
                .filter(|(n, _)| **n >= 64 && is_power_of(**n, base))
                .map(|(n, r)| (*n as f64, *r))
                .unzip();
            ErrorCurve {
                integrand: fam.name(),
                smoothness: fam.smoothness(),
                n: sizes.clone(),
                rmse,
                slope: fit_slope(&xs, &ys),
            }
        })
        .collect();
    Ok(MethodResult {
        label: method.label(),
        base,
        method: method.clone(),
        curves,
        seconds_per_point: seconds / (config.replicates as f64 * n_max as f64),
    })
}

/// The methods for `sequences`: every registry scrambler whose base 2^p is compatible with the
/// sequence's base 2^q (p divides q, so the scramble is nested in the sequence's base, T4),
/// the exact oracle in each compatible base, the unscrambled sequence, and plain random points.
pub fn methods_for(registry: &Registry, sequences: &[SequenceKind]) -> Vec<Method> {
    let mut out = Vec::new();
    for &kind in sequences {
        let q = kind.base().q();
        for spec in registry.specs() {
            if spec.name == "owen-oracle" {
                for p in (1..=q).filter(|p| q % p == 0) {
                    out.push(Method {
                        sequence: kind.name(),
                        scrambler: format!("owen-oracle:base={}", 1u32 << p),
                    });
                }
                continue;
            }
            if q % spec.default_base.q() == 0 {
                out.push(Method {
                    sequence: kind.name(),
                    scrambler: spec.name.to_string(),
                });
            }
        }
    }
    out.push(Method {
        sequence: "random".into(),
        scrambler: String::new(),
    });
    out
}
