//! The RMSE harness: deterministic, recomputable by hand, refusing bad input.

use super::*;

#[test]
fn measurements_are_deterministic_across_thread_counts_and_prefix_consistent() {
    let registry = gartowen::registry();
    let method =
        SceneMethod::registry(&registry, gartowen::seq::SequenceKind::Sz16, "art-owen-16p")
            .unwrap();
    let scene = gartowen_bench::scene::roulette::RouletteScene::default();
    let layouts = candidate_layouts(scene.slots(), 2, 3);
    let c = config(vec![16, 100, 256], 8);
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| measure_scene(&scene, &method, &layouts, &c).unwrap())
    };
    let (one, two) = (run(1), run(2));
    for (a, b) in one.layouts.iter().zip(&two.layouts) {
        assert_eq!(a.rmse, b.rmse);
        assert_eq!(a.rmse_se, b.rmse_se);
    }
    // The N = 100 estimate is the prefix of the N = 256 run: measuring 100 alone agrees.
    let alone = measure_scene(&scene, &method, &layouts, &config(vec![100], 8)).unwrap();
    for (a, b) in one.layouts.iter().zip(&alone.layouts) {
        assert_eq!(a.rmse[1], b.rmse[0]);
    }
    // Layouts read different dimensions, so their errors differ.
    assert_ne!(one.layouts[0].rmse, one.layouts[5].rmse);
}

#[test]
fn bad_measurements_are_refused_with_the_reason() {
    let registry = gartowen::registry();
    let scene = gartowen_bench::scene::roulette::RouletteScene::default();
    let m = SceneMethod::random();
    let e = measure_scene(&scene, &m, &[Layout::packed(4)], &config(vec![16], 2)).unwrap_err();
    assert!(e.contains("3"), "{e}");
    let e = measure_scene(&scene, &m, &[Layout::packed(3)], &config(vec![0], 2)).unwrap_err();
    assert!(e.contains("nonzero"), "{e}");
    let dup = Layout {
        dims: vec![1, 1, 2],
    };
    assert!(measure_scene(&scene, &m, &[dup], &config(vec![16], 2)).is_err());
    let e = SceneMethod::registry(&registry, gartowen::seq::SequenceKind::Sz4, "owen-oracle")
        .err()
        .unwrap();
    assert!(e.contains("16 dimensions"), "{e}");
    assert!(
        SceneMethod::registry(&registry, gartowen::seq::SequenceKind::Sobol, "no-such").is_err()
    );
}

#[test]
fn random_points_converge_at_the_monte_carlo_rate() {
    // RMSE ∝ N^-1/2 for independent points: from N = 64 to 4096 the RMSE falls ×8 (within
    // noise of 64 seeds), far less than the ×64 a QMC N^-1 would give.
    let scene = gartowen_bench::scene::defocus::DefocusScene::default();
    let r = measure_scene(
        &scene,
        &SceneMethod::random(),
        &[Layout::packed(5)],
        &config(vec![64, 4096], 64),
    )
    .unwrap();
    let ratio = r.layouts[0].rmse[0] / r.layouts[0].rmse[1];
    assert!((5.5..11.0).contains(&ratio), "{ratio}");
}

#[test]
fn the_harness_follows_its_documented_seeds_pixels_and_prefixes() {
    // Recomputed by hand: replicate r, pixel k has seed derive_seed(derive_seed(seed, r), k);
    // random dimension d draws from SplitMix64(derive_seed(that, d)).
    let (seeds, sizes, dim) = (3u64, [5usize, 12], 7usize);
    let c = SceneConfig {
        sizes: sizes.to_vec(),
        seeds,
        seed: 99,
    };
    let got = measure_scene(
        &TwoPixels,
        &SceneMethod::random(),
        &[Layout { dims: vec![dim] }],
        &c,
    )
    .unwrap();
    assert_eq!(got.pixels, 2);
    let mut sq = vec![Vec::new(); sizes.len()];
    let mut render = Vec::new();
    for r in 0..seeds {
        for k in 0..2usize {
            let s = derive_seed(derive_seed(99, r), k as u64);
            let mut rng = SplitMix64::new(derive_seed(s, dim as u64));
            let v: Vec<f64> = (0..12).map(|_| k as f64 + rng.next_f64()).collect();
            for (i, &n) in sizes.iter().enumerate() {
                let mean = v[..n].iter().sum::<f64>() / n as f64;
                sq[i].push((mean - (k as f64 + 0.5)).powi(2));
                if r == 0 && i == 0 {
                    render.push(mean);
                }
            }
        }
    }
    for (i, errs) in sq.iter().enumerate() {
        let mse = errs.iter().sum::<f64>() / errs.len() as f64;
        assert_eq!(got.layouts[0].rmse[i], mse.sqrt(), "N = {}", sizes[i]);
        assert!((got.pooled_mse[i] - mse).abs() <= 1e-15 * mse);
        // Standard errors: the sample variance (m − 1) of the squared errors over m cells.
        let m = errs.len() as f64;
        let var = errs.iter().map(|e| (e - mse).powi(2)).sum::<f64>() / (m - 1.0);
        let se = (var / m).sqrt();
        assert!((got.pooled_mse_se[i] - se).abs() <= 1e-12 * se);
        let rmse_se = se / (2.0 * mse.sqrt());
        assert!((got.layouts[0].rmse_se[i] - rmse_se).abs() <= 1e-12 * rmse_se);
    }
    assert_eq!(got.render, render);
}

#[test]
fn the_standard_methods_are_the_six_of_the_issue() {
    let registry = gartowen::registry();
    let labels: Vec<String> = gartowen_bench::scene::measure::standard_methods(&registry)
        .iter()
        .map(|m| m.label.clone())
        .collect();
    assert_eq!(
        labels,
        [
            "sobol+owen-oracle",
            "sobol+lk-hash",
            "sz16+art-owen-2",
            "sz16+art-owen-16p",
            "sz16+owen-oracle:base=16",
            "random"
        ]
    );
}

#[test]
fn the_pooled_mse_is_the_mean_over_layouts() {
    let scene = gartowen_bench::scene::roulette::RouletteScene::default();
    let layouts = candidate_layouts(scene.slots(), 0, 1)[..3].to_vec();
    let r = measure_scene(
        &scene,
        &SceneMethod::random(),
        &layouts,
        &config(vec![16, 64], 4),
    )
    .unwrap();
    for s in 0..2 {
        let mean = r.layouts.iter().map(|l| l.rmse[s].powi(2)).sum::<f64>() / 3.0;
        assert!((r.pooled_mse[s] - mean).abs() <= 1e-12 * mean, "{s}");
    }
}

#[test]
fn extremes_are_best_lower_median_and_worst() {
    use gartowen_bench::scene::measure::extremes;
    let r = synthetic("s", "m", &[4.0, 1.0, 3.0, 2.0], 0.1);
    assert_eq!(extremes(&r, 0), [(1, 1.0), (3, 2.0), (0, 4.0)]);
    let r = synthetic("s", "m", &[5.0, 1.0, 3.0], 0.1);
    assert_eq!(extremes(&r, 0), [(1, 1.0), (2, 3.0), (0, 5.0)]);
}
