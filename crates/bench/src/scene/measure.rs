//! RMSE of each scene against N, for each method (a sequence with a scrambler, or independent
//! random points) and each layout.
//!
//! Replicate r, pixel k uses the scrambler seed `derive_seed(derive_seed(seed, r), k)`; the
//! estimates for all N are prefixes of one run of the largest N; all layouts read the same
//! points (each its own dimensions). Work runs in parallel over (replicate, pixel) and is reduced
//! in that order, so every error figure is bit-identical for any thread count. Times are the
//! only non-deterministic output.

use super::layout::{Layout, Relation, SEQUENCE_DIMS};
use super::Scene;
use gartowen::core::{derive_seed, BuildContext, Registry, Scrambler, SplitMix64, Width};
use gartowen::seq::SequenceKind;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Makes the scrambler of one seed.
pub type ScramblerFactory<'a> = Box<dyn Fn(u64) -> Result<Box<dyn Scrambler>, String> + Sync + 'a>;

/// How a scene's samples are produced.
pub struct SceneMethod<'a> {
    /// `sequence+scrambler`, or `random`.
    pub label: String,
    /// The sequence; `None` for independent uniform points.
    pub sequence: Option<SequenceKind>,
    /// The scrambler per seed (unused for random points).
    pub make: ScramblerFactory<'a>,
}

impl<'a> SceneMethod<'a> {
    /// Independent uniform points (SplitMix64 per seed and dimension).
    pub fn random() -> SceneMethod<'a> {
        SceneMethod {
            label: "random".into(),
            sequence: None,
            make: Box::new(|_| Err("random points have no scrambler".into())),
        }
    }

    /// `sequence` scrambled by the registry `request`; checked by building seed 0.
    pub fn registry(
        registry: &'a Registry,
        sequence: SequenceKind,
        request: &str,
    ) -> Result<SceneMethod<'a>, String> {
        let request = request.to_string();
        let label = format!("{}+{request}", sequence.name());
        let make: ScramblerFactory<'a> = Box::new(move |seed| {
            registry
                .build_with(
                    &request,
                    &BuildContext {
                        seed,
                        default_base: sequence.base(),
                    },
                )
                .map_err(|e| format!("{request}: {e}"))
        });
        SceneMethod::custom(label, sequence, make)
    }

    /// `sequence` with any scrambler factory (an external program, say); checked by building
    /// seed 0 and asking for 32-bit words.
    pub fn custom(
        label: String,
        sequence: SequenceKind,
        make: ScramblerFactory<'a>,
    ) -> Result<SceneMethod<'a>, String> {
        let probe = make(0)?;
        if !probe.supports_width(Width::W32) {
            return Err(format!("{label}: the scrambler does not take 32-bit words"));
        }
        sequence
            .build(SEQUENCE_DIMS, Width::W32)
            .map_err(|e| format!("{label}: scenes need {SEQUENCE_DIMS} dimensions: {e}"))?;
        Ok(SceneMethod {
            label,
            sequence: Some(sequence),
            make,
        })
    }
}

/// The methods the scene report compares: what binary renderers ship and the base-16 family.
pub fn standard_methods(registry: &Registry) -> Vec<SceneMethod<'_>> {
    let mut out: Vec<SceneMethod> = [
        (SequenceKind::Sobol, "owen-oracle"),
        (SequenceKind::Sobol, "lk-hash"),
        (SequenceKind::Sz16, "art-owen-2"),
        (SequenceKind::Sz16, "art-owen-16p"),
        (SequenceKind::Sz16, "owen-oracle:base=16"),
    ]
    .iter()
    .map(|(s, r)| SceneMethod::registry(registry, *s, r).expect("built-in method"))
    .collect();
    out.push(SceneMethod::random());
    out
}

/// Sizes, replicates and layouts of a measurement.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SceneConfig {
    /// Sample sizes N.
    pub sizes: Vec<usize>,
    /// Independent replicates (seeds) per pixel.
    pub seeds: u64,
    /// Master seed.
    pub seed: u64,
}

/// RMSE against N of one layout.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LayoutCurve {
    /// The layout, `slot=d,d;…`.
    pub layout: String,
    /// Sequence dimension of each coordinate.
    pub dims: Vec<usize>,
    /// Where the other slots sit relative to the first.
    pub relation: Relation,
    /// RMSE at each N (over replicates and pixels).
    pub rmse: Vec<f64>,
    /// Standard error of each RMSE (delta method: SE(MSE) / (2·RMSE)).
    pub rmse_se: Vec<f64>,
}

/// One scene under one method, every layout.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SceneResult {
    /// Scene name.
    pub scene: String,
    /// Method label.
    pub method: String,
    /// Sample sizes.
    pub n: Vec<usize>,
    /// Replicates per pixel.
    pub seeds: u64,
    /// Pixels (estimators) per replicate.
    pub pixels: usize,
    /// One curve per layout, in layout order.
    pub layouts: Vec<LayoutCurve>,
    /// Seconds per sample (the layout's coordinates and one estimate), measured in this run.
    pub seconds_per_sample: f64,
    /// The squared error averaged over layouts, then over replicates and pixels, per N: one
    /// number per N for the whole layout set.
    #[serde(default)]
    pub pooled_mse: Vec<f64>,
    /// Standard error of each [`SceneResult::pooled_mse`] (over replicates and pixels; the
    /// layouts' shared points are inside each replicate's average, so this is exact).
    #[serde(default)]
    pub pooled_mse_se: Vec<f64>,
    /// The first replicate's per-pixel estimates at the smallest N with the first layout
    /// (multi-pixel scenes only; empty otherwise).
    #[serde(default)]
    pub render: Vec<f64>,
}

/// Per (replicate, pixel): squared errors [layout][size], the first layout's estimate at the
/// smallest size, and seconds generating and evaluating.
struct Cell {
    sq: Vec<Vec<f64>>,
    /// Mean over layouts of `sq`, per size.
    pooled: Vec<f64>,
    first: f64,
    generate: f64,
    evaluate: f64,
}

/// The values of sequence dimensions `dims` for points 0..n under one seed, row-major
/// (`out[i * dims.len() + c]` is point i's value in dimension `dims[c]`).
fn sample_rows(
    source: Option<(&gartowen::seq::DigitalSequence, &dyn Scrambler)>,
    dims: &[usize],
    n: usize,
    seed: u64,
) -> Vec<f64> {
    let m = dims.len();
    let mut out = vec![0.0; n * m];
    let Some((seq, scrambler)) = source else {
        for (c, &d) in dims.iter().enumerate() {
            let mut rng = SplitMix64::new(derive_seed(seed, d as u64));
            out.iter_mut()
                .skip(c)
                .step_by(m)
                .for_each(|x| *x = rng.next_f64());
        }
        return out;
    };
    let mut words = vec![0u64; n];
    for (c, &d) in dims.iter().enumerate() {
        seq.fill_points(d, 0, &mut words);
        scrambler.scramble_batch(&mut words, Width::W32, d as u32);
        for (x, &w) in out.iter_mut().skip(c).step_by(m).zip(&words) {
            *x = gartowen::core::word_to_f64(w, Width::W32);
        }
    }
    out
}

/// Measures `scene` under `method` over `layouts` (each validated against the scene's slots).
pub fn measure_scene(
    scene: &dyn Scene,
    method: &SceneMethod,
    layouts: &[Layout],
    config: &SceneConfig,
) -> Result<SceneResult, String> {
    let k = scene.coordinates();
    if config.sizes.is_empty() || config.sizes.contains(&0) || config.seeds == 0 {
        return Err(format!(
            "sizes {:?} and {} seeds: need nonzero sizes and seeds",
            config.sizes, config.seeds
        ));
    }
    for l in layouts {
        if l.dims.len() != k {
            return Err(format!(
                "layout {:?} has {} coordinates; {} reads {k}",
                l.dims,
                l.dims.len(),
                scene.name()
            ));
        }
        l.validate().map_err(|e| e.to_string())?;
    }
    let mut sizes = config.sizes.clone();
    sizes.sort_unstable();
    sizes.dedup();
    let n_max = *sizes.last().expect("nonempty");
    let mut needed: Vec<usize> = layouts.iter().flat_map(|l| l.dims.clone()).collect();
    needed.sort_unstable();
    needed.dedup();
    // Column index of each layout coordinate.
    let maps: Vec<Vec<usize>> = layouts
        .iter()
        .map(|l| {
            l.dims
                .iter()
                .map(|d| needed.binary_search(d).expect("needed"))
                .collect()
        })
        .collect();
    let seq = match method.sequence {
        Some(kind) => Some(
            kind.build(SEQUENCE_DIMS, Width::W32)
                .map_err(|e| format!("{}: {e}", method.label))?,
        ),
        None => None,
    };
    let pixels = scene.pixels();
    let cells: Vec<Result<Cell, String>> = (0..config.seeds as usize * pixels)
        .into_par_iter()
        .map(|c| {
            let (r, pixel) = (c / pixels, c % pixels);
            let seed = derive_seed(derive_seed(config.seed, r as u64), pixel as u64);
            // Building the scrambler is per seed, not per sample: it is not timed.
            let scrambler = match &seq {
                Some(_) => Some((method.make)(seed)?),
                None => None,
            };
            let source = seq.as_ref().zip(scrambler.as_deref());
            let t0 = Instant::now();
            let rows = sample_rows(source, &needed, n_max, seed);
            let generate = t0.elapsed().as_secs_f64();
            let t1 = Instant::now();
            let reference = scene.reference(pixel);
            let mut sq = vec![vec![0.0; sizes.len()]; layouts.len()];
            let mut first = f64::NAN;
            let mut u = vec![0.0; k];
            for (li, map) in maps.iter().enumerate() {
                let (mut sum, mut s) = (0.0, 0);
                for (i, row) in rows.chunks_exact(needed.len()).enumerate() {
                    for (slot, &col) in u.iter_mut().zip(map) {
                        *slot = row[col];
                    }
                    sum += scene.estimate(pixel, &u);
                    if i + 1 == sizes[s] {
                        let mean = sum / sizes[s] as f64;
                        if li == 0 && s == 0 {
                            first = mean;
                        }
                        sq[li][s] = (mean - reference).powi(2);
                        s += 1;
                    }
                }
            }
            let pooled = (0..sizes.len())
                .map(|s| sq.iter().map(|l| l[s]).sum::<f64>() / layouts.len() as f64)
                .collect();
            Ok(Cell {
                sq,
                pooled,
                first,
                generate,
                evaluate: t1.elapsed().as_secs_f64(),
            })
        })
        .collect();
    let cells: Vec<Cell> = cells.into_iter().collect::<Result<_, _>>()?;
    let m = cells.len() as f64;
    let mean_and_se = |get: &dyn Fn(&Cell) -> f64| {
        let mean = cells.iter().map(get).sum::<f64>() / m;
        let var = if m > 1.0 {
            cells.iter().map(|c| (get(c) - mean).powi(2)).sum::<f64>() / (m - 1.0)
        } else {
            f64::NAN
        };
        (mean, (var / m).sqrt())
    };
    let (pooled_mse, pooled_mse_se) = (0..sizes.len())
        .map(|s| mean_and_se(&|c: &Cell| c.pooled[s]))
        .unzip();
    let curves = layouts
        .iter()
        .enumerate()
        .map(|(li, l)| {
            let (rmse, rmse_se) = (0..sizes.len())
                .map(|s| {
                    let (mse, se) = mean_and_se(&|c: &Cell| c.sq[li][s]);
                    (mse.sqrt(), se / (2.0 * mse.sqrt()))
                })
                .unzip();
            LayoutCurve {
                layout: l.describe(scene.slots()),
                dims: l.dims.clone(),
                relation: l.relation(scene.slots()),
                rmse,
                rmse_se,
            }
        })
        .collect();
    // A sample costs its k coordinates' share of the generated columns and one estimate.
    let per_cell =
        |c: &Cell| c.generate * k as f64 / needed.len() as f64 + c.evaluate / layouts.len() as f64;
    let seconds_per_sample = cells.iter().map(per_cell).sum::<f64>() / (m * n_max as f64);
    let render = if pixels > 1 {
        cells[..pixels].iter().map(|c| c.first).collect()
    } else {
        Vec::new()
    };
    Ok(SceneResult {
        scene: scene.name().into(),
        method: method.label.clone(),
        n: sizes,
        seeds: config.seeds,
        pixels,
        layouts: curves,
        pooled_mse,
        pooled_mse_se,
        seconds_per_sample,
        render,
    })
}

/// The layouts' RMSE at size index `s`, sorted: (best, median, worst) with their layout
/// indices.
pub fn extremes(result: &SceneResult, s: usize) -> [(usize, f64); 3] {
    let mut v: Vec<(usize, f64)> = result
        .layouts
        .iter()
        .enumerate()
        .map(|(i, l)| (i, l.rmse[s]))
        .collect();
    v.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
    [v[0], v[(v.len() - 1) / 2], v[v.len() - 1]]
}
