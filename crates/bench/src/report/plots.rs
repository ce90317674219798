//! The report's PNG figures.

use super::*;

/// The methods each RMSE figure shows (to keep the legend readable).
const FIGURE_METHODS: [&str; 9] = [
    "random",
    "sobol+none",
    "sobol+owen-oracle:base=2",
    "sobol+art-owen-2",
    "sz16+none",
    "sz16+art-owen-2",
    "sz16+art-owen-16p",
    "sz16+owen-oracle:base=16",
    "sz16+art-owen-t4",
];

/// The methods named in the efficiency figures (all methods are drawn).
/// The integrands with RMSE figures.
const FIGURE_INTEGRANDS: [&str; 6] = [
    "heaviside",
    "hard-disk",
    "gaussian-2d",
    "soft-disk",
    "genz-oscillatory-2d",
    "genz-corner-peak-4d",
];

/// Writes every figure into `dir`; returns the file names.
pub fn write_figures(
    report: &Report,
    registry: &Registry,
    dir: &Path,
) -> Result<Vec<String>, ReportError> {
    let mut files = Vec::new();
    let fig = ReportError::Figure;
    for integrand in FIGURE_INTEGRANDS {
        let Some(k) = report.integrands.iter().position(|i| i == integrand) else {
            continue;
        };
        let series: Vec<Series> = FIGURE_METHODS
            .iter()
            .filter_map(|label| report.methods.iter().find(|m| m.label == *label))
            .map(|m| Series {
                label: m.label.clone(),
                points: m.curves[k]
                    .n
                    .iter()
                    .zip(&m.curves[k].rmse)
                    .filter(|(n, _)| crate::harness::is_power_of(**n, 2))
                    .map(|(n, r)| (*n as f64, *r))
                    .collect(),
            })
            .collect();
        let name = format!("rmse_{integrand}.png");
        loglog_lines(
            &dir.join(&name),
            &format!(
                "RMSE against N: {integrand} (R = {})",
                report.harness.replicates
            ),
            "N (points)",
            "RMSE",
            &series,
            &[-0.5, -1.0, -1.5],
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Speed against error: RMSE at the largest N against time per point.
    for integrand in ["gaussian-2d", "heaviside"] {
        let Some(k) = report.integrands.iter().position(|i| i == integrand) else {
            continue;
        };
        let pts: Vec<Series> = report
            .methods
            .iter()
            .map(|m| Series {
                label: m.label.clone(),
                points: vec![(
                    m.seconds_per_point * 1e9,
                    *m.curves[k].rmse.last().expect("sizes"),
                )],
            })
            .collect();
        let name = format!("efficiency_{integrand}.png");
        loglog_points(
            &dir.join(&name),
            &format!(
                "Speed against error: {integrand}, N = {}",
                report.harness.sizes.iter().max().expect("sizes")
            ),
            "time per point (ns, 4 coordinates)",
            "RMSE",
            &pts,
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Figure 1 (the paper's): every one of the 28 pairs of the first 8 dimensions at N = 256
    // and 512, one matrix per method (scatter of seed 1 above the diagonal, the mean
    // periodogram over FIGURE1_SEEDS seeds below, grey key), then the consecutive pairs
    // (j, j+1) side by side across methods. One realisation's spectrum is noise.
    let methods = [
        ("unscrambled", "none"),
        ("art-owen-2", "art-owen-2"),
        ("art-owen-16p", "art-owen-16p"),
    ];
    for n in [256usize, 512] {
        let pairs: Vec<[usize; 2]> = (0..7).map(|j| [j, j + 1]).collect();
        let mut rows = Vec::new();
        for (label, request) in methods {
            // The unscrambled set is the same for every seed.
            let seeds = if request == "none" { 1 } else { FIGURE1_SEEDS };
            let sets: Vec<Vec<u64>> = (1..=seeds)
                .map(|seed| sz16_words(registry, request, 8, n, seed))
                .collect();
            let pair_sets = |a: usize, b: usize| -> Vec<Vec<[f64; 2]>> {
                sets.iter()
                    .map(|w| {
                        let value = |i: usize, j: usize| w[i * 8 + j] as f64 * 2f64.powi(-32);
                        (0..n).map(|i| [value(i, a), value(i, b)]).collect()
                    })
                    .collect()
            };
            // Every pair's mean spectrum once: the matrix and the consecutive pairs share them.
            let columns: Vec<Vec<Vec<f64>>> = sets
                .iter()
                .map(|w| {
                    (0..8)
                        .map(|j| {
                            (0..n)
                                .map(|i| w[i * 8 + j] as f64 * 2f64.powi(-32))
                                .collect()
                        })
                        .collect()
                })
                .collect();
            let spectra = mean_pair_spectra(&columns, 24);
            let name = format!("figure1_sz16_n{n}_pairs_{}.png", file_stem(request));
            pair_matrix(
                &dir.join(&name),
                &format!(
                    "Figure 1: sz16, {label}, N = {n}: all 28 pairs of dims 0..7 (spectra: mean of {seeds} seeds)"
                ),
                8,
                &|a, b| pair_sets(a, b).swap_remove(0),
                &|a, b| spectra[a][b].clone(),
                24,
            )
            .map_err(fig)?;
            files.push(name);
            rows.push((
                format!("{label} points"),
                pairs
                    .iter()
                    .map(|p| Panel::Scatter(pair_sets(p[0], p[1]).swap_remove(0)))
                    .collect(),
            ));
            rows.push((
                format!("{label} spectrum"),
                pairs
                    .iter()
                    .map(|p| Panel::Spectrum {
                        values: spectra[p[0]][p[1]].clone(),
                        max_freq: 24,
                    })
                    .collect(),
            ));
        }
        let name = format!("figure1_sz16_n{n}.png");
        panel_grid(
            &dir.join(&name),
            &format!(
                "Figure 1: sz16, first 8 dimensions, N = {n} (spectra |f| ≤ 24, log grey, mean of {FIGURE1_SEEDS} seeds)"
            ),
            &pairs
                .iter()
                .map(|p| format!("dims {},{}", p[0], p[1]))
                .collect::<Vec<_>>(),
            &rows,
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Figure 2: joint 16-D and pair curves.
    let mut joint: Vec<Series> = report
        .discrepancy
        .iter()
        .map(|c| Series {
            label: format!("{} (16-D)", c.scrambler),
            points: c
                .n
                .iter()
                .zip(&c.joint)
                .map(|(n, v)| (*n as f64, *v))
                .collect(),
        })
        .collect();
    // The paper's baseline: independent uniform points, by their exact expectation.
    let random = |dims: u32| Series {
        label: "random points (exact E[D²])".into(),
        points: report
            .discrepancy
            .iter()
            .max_by_key(|c| c.n.len())
            .map_or(Vec::new(), |c| {
                c.n.iter()
                    .map(|&n| (n as f64, expected_l2star_random(n, dims)))
                    .collect()
            }),
    };
    // ±2 SE bands over seeds (the quick run's 16–128 seeds once showed binary ART 1.5–1.9×
    // binary Owen where the full run's seeds show none: the bands say how far to trust it).
    let mut joint_bands: Vec<Vec<(f64, f64)>> = report
        .discrepancy
        .iter()
        .map(|c| {
            c.joint
                .iter()
                .enumerate()
                .map(|(i, &m)| two_se(m, c.joint_se.get(i).copied()))
                .collect()
        })
        .collect();
    let baseline = random(16);
    joint_bands.push(exact(&baseline));
    joint.push(baseline);
    loglog_lines_banded(
        &dir.join("figure2_joint.png"),
        "Figure 2a: mean L2-star D², sz16 in 16-D: ART against full-tree Owen of its base (±2 SE)",
        "N (points)",
        "mean D²",
        &joint,
        &joint_bands,
        &[-1.0],
    )
    .map_err(fig)?;
    files.push("figure2_joint.png".into());
    // Figure 2b: every pair (0, j), one figure per method, with ±2 SE bands.
    for c in &report.discrepancy {
        let mut pair_series = Vec::new();
        let mut bands = Vec::new();
        for (k, p) in c.pairs.iter().enumerate() {
            let mean: Vec<(f64, f64)> =
                c.n.iter()
                    .zip(&c.pair_values)
                    .map(|(n, v)| (*n as f64, v[k]))
                    .collect();
            bands.push(
                mean.iter()
                    .enumerate()
                    .map(|(i, &(_, m))| two_se(m, c.pair_se.get(i).and_then(|v| v.get(k)).copied()))
                    .collect(),
            );
            pair_series.push(Series {
                label: format!("dims {},{}", p[0], p[1]),
                points: mean,
            });
        }
        let base = random(2);
        bands.push(exact(&base));
        pair_series.push(base);
        if let Some((series, band)) = report.sobol_owen.as_ref().map(sobol_pairs_baseline) {
            pair_series.push(series);
            bands.push(band);
        }
        let name = format!("figure2_pairs_{}.png", file_stem(&c.scrambler));
        loglog_lines_banded(
            &dir.join(&name),
            &format!(
                "Figure 2b: mean 2-D L2-star D² of sz16 pairs (0, j), {} ({}–{} seeds, ±2 SE); baselines: random points, Sobol + binary Owen's pairs",
                c.scrambler,
                c.seeds,
                c.seeds_per_n.iter().max().unwrap_or(&c.seeds)
            ),
            "N (points)",
            "mean D²",
            &pair_series,
            &bands,
            &[-2.0],
        )
        .map_err(fig)?;
        files.push(name);
    }
    // Figure 2c: max/min over the 15 pairs against N, per method.
    let spread: Vec<Series> = report
        .discrepancy
        .iter()
        .map(|c| Series {
            label: c.scrambler.clone(),
            points: c
                .n
                .iter()
                .zip(c.pair_spread())
                .map(|(n, r)| (*n as f64, r))
                .collect(),
        })
        .collect();
    let spread_bands: Vec<Vec<(f64, f64)>> = report
        .discrepancy
        .iter()
        .map(|c| {
            c.pair_spread()
                .iter()
                .zip(c.pair_spread_se())
                .map(|(&r, se)| {
                    let se = if se.is_finite() { se } else { 0.0 };
                    ((r - 2.0 * se).max(1.0), r + 2.0 * se)
                })
                .collect()
        })
        .collect();
    loglog_lines_banded(
        &dir.join("figure2_spread.png"),
        "Figure 2c: max / min over pairs (0, j) of the mean 2-D D² (1 = every pair alike; ±2 SE)",
        "N (points)",
        "max / min",
        &spread,
        &spread_bands,
        &[],
    )
    .map_err(fig)?;
    files.push("figure2_spread.png".into());
    if let Some(scene) = &report.scene {
        files.extend(
            crate::scene::output::write_scene_figures(scene, dir).map_err(ReportError::Figure)?,
        );
    }
    Ok(files)
}

/// A scrambler request as a file-name part: `owen-oracle:base=16` → `owen-oracle_base-16`.
fn file_stem(request: &str) -> String {
    request
        .chars()
        .map(|c| match c {
            ':' => '_',
            '=' | ',' => '-',
            c => c,
        })
        .collect()
}

/// The band of ±2 standard errors around `mean` (none when the SE is unknown).
fn two_se(mean: f64, se: Option<f64>) -> (f64, f64) {
    let se = se.unwrap_or(0.0);
    (mean - 2.0 * se, mean + 2.0 * se)
}

/// Figure 2b's Sobol + Owen baseline: the mean over its pairs (0, j) at each N, banded by the
/// smallest and largest pair (the spread of a good binary sequence's pairs, not an error bar).
pub fn sobol_pairs_baseline(c: &DiscrepancyCurve) -> (Series, Vec<(f64, f64)>) {
    let mut points = Vec::new();
    let mut band = Vec::new();
    for (n, values) in c.n.iter().zip(&c.pair_values) {
        if values.is_empty() {
            continue;
        }
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        points.push((*n as f64, mean));
        band.push((lo, hi));
    }
    (
        Series {
            label: format!("Sobol + {} pairs (0, j): mean, band min–max", c.scrambler),
            points,
        },
        band,
    )
}

/// The band of a series known exactly (an expectation, not an estimate): its own line.
fn exact(series: &Series) -> Vec<(f64, f64)> {
    series.points.iter().map(|&(_, m)| (m, m)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sobol_baseline_is_the_pairs_mean_banded_by_the_extreme_pairs() {
        let c = DiscrepancyCurve {
            scrambler: "owen-oracle:base=2".into(),
            n: vec![16, 32, 64],
            joint: vec![0.0; 3],
            pairs: vec![[0, 1], [0, 2], [0, 3]],
            pair_values: vec![vec![1.0, 2.0, 6.0], vec![], vec![0.5, 0.25, 0.75]],
            seeds: 8,
            joint_se: vec![],
            pair_se: vec![],
            seeds_per_n: vec![],
        };
        let (series, band) = sobol_pairs_baseline(&c);
        // A size without pairs is skipped, not drawn at 0.
        assert_eq!(series.points, [(16.0, 3.0), (64.0, 0.5)]);
        assert_eq!(band, [(1.0, 6.0), (0.25, 0.75)]);
        assert!(series.label.starts_with("Sobol + owen-oracle:base=2 pairs"));
    }
}
