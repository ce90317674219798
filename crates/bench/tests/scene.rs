//! Scenes: every reference against an independent computation (Monte Carlo with 2^22 points
//! through the estimator, and finer quadrature for the image), a reference 2% off detected,
//! the harness deterministic and sensitive to a biased reference, and the verdict and
//! baseline rules on synthetic results.

use gartowen::core::{derive_seed, SplitMix64};
use gartowen_bench::scene::image::ImageScene;
use gartowen_bench::scene::layout::{candidate_layouts, Relation};
use gartowen_bench::scene::measure::{
    measure_scene, LayoutCurve, SceneConfig, SceneMethod, SceneResult,
};
use gartowen_bench::scene::report::{compare_scenes, critical_z, headline, run_scenes, ScenePlan};
use gartowen_bench::scene::{all_scenes, Layout, Scene, Slot};
use rayon::prelude::*;

/// Monte Carlo mean and standard error of `scene`'s pixel estimator over 2^22 independent
/// uniform samples (fixed seed; 64 chunks reduced in order).
fn monte_carlo(scene: &dyn Scene, pixel: usize, seed: u64) -> (f64, f64) {
    let k = scene.coordinates();
    let chunks = 64u64;
    let per = (1u64 << 22) / chunks;
    let sums: Vec<(f64, f64)> = (0..chunks)
        .into_par_iter()
        .map(|c| {
            let mut rng = SplitMix64::new(derive_seed(seed, c));
            let mut u = vec![0.0; k];
            let (mut s, mut s2) = (0.0, 0.0);
            for _ in 0..per {
                u.iter_mut().for_each(|x| *x = rng.next_f64());
                let v = scene.estimate(pixel, &u);
                s += v;
                s2 += v * v;
            }
            (s, s2)
        })
        .collect();
    let n = (chunks * per) as f64;
    let (s, s2) = sums.iter().fold((0.0, 0.0), |a, b| (a.0 + b.0, a.1 + b.1));
    let mean = s / n;
    (mean, ((s2 / n - mean * mean) / n).sqrt())
}

/// The reference agrees with Monte Carlo within 4 standard errors (false-alarm rate 6e-5 per
/// check) and a reference 2% off is more than 4 standard errors away.
fn check_reference(scene: &dyn Scene, pixel: usize) {
    let (mean, se) = monte_carlo(scene, pixel, 0x5ce7e + pixel as u64);
    let r = scene.reference(pixel);
    let tol = 4.0 * se + scene.reference_error();
    assert!(
        (mean - r).abs() < tol,
        "{} pixel {pixel}: MC {mean} ± {se}, reference {r}",
        scene.name()
    );
    for wrong in [r * 1.02, r * 0.98] {
        assert!(
            (mean - wrong).abs() > tol,
            "{} pixel {pixel}: a 2% error would pass (MC {mean} ± {se})",
            scene.name()
        );
    }
}

#[test]
fn every_single_estimator_reference_matches_monte_carlo_and_a_2_percent_error_is_caught() {
    for scene in all_scenes().iter().filter(|s| s.pixels() == 1) {
        check_reference(scene.as_ref(), 0);
    }
}

#[test]
fn image_pixels_match_monte_carlo_in_light_penumbra_and_shadow() {
    let image = ImageScene::new(32);
    let r = image.reference_image();
    // The brightest, the darkest and the pixel whose value is nearest the middle (penumbra).
    let arg = |f: &dyn Fn(f64, f64) -> bool| {
        (0..r.len()).fold(0, |b, i| if f(r[i], r[b]) { i } else { b })
    };
    let (hi, lo) = (arg(&|a, b| a > b), arg(&|a, b| a < b));
    let mid_value = 0.5 * (r[hi] + r[lo]);
    let mid = arg(&|a, b| (a - mid_value).abs() < (b - mid_value).abs());
    assert!(
        r[hi] > 1.5 * r[lo],
        "the occluder must cast a visible shadow"
    );
    for p in [hi, lo, mid] {
        check_reference(&image, p);
    }
}

#[test]
fn the_image_quadrature_is_converged_far_below_its_stated_error() {
    let image = ImageScene::new(32);
    let base = image.reference_image();
    for (cells, nodes) in [(4, 8), (8, 4)] {
        let finer = image.quadrature(cells, nodes);
        let diff = base
            .iter()
            .zip(&finer)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(
            diff < image.reference_error() / 10.0,
            "({cells}, {nodes}): max difference {diff}"
        );
    }
}

/// A scene whose reference is off by a factor: what the harness shows for a wrong reference.
struct Scaled<S: Scene>(S, f64);

impl<S: Scene> Scene for Scaled<S> {
    fn name(&self) -> &'static str {
        self.0.name()
    }
    fn summary(&self) -> &'static str {
        self.0.summary()
    }
    fn slots(&self) -> &'static [Slot] {
        self.0.slots()
    }
    fn estimate(&self, pixel: usize, u: &[f64]) -> f64 {
        self.0.estimate(pixel, u)
    }
    fn reference(&self, pixel: usize) -> f64 {
        self.0.reference(pixel) * self.1
    }
    fn reference_error(&self) -> f64 {
        0.0
    }
}

fn config(sizes: Vec<usize>, seeds: u64) -> SceneConfig {
    SceneConfig {
        sizes,
        seeds,
        seed: 7,
    }
}

#[test]
fn a_reference_2_percent_off_shows_as_an_rmse_floor() {
    let registry = gartowen::registry();
    let owen = SceneMethod::registry(&registry, gartowen::seq::SequenceKind::Sobol, "owen-oracle")
        .unwrap();
    let scene = gartowen_bench::scene::direct::DirectScene::default();
    let reference = scene.reference(0);
    let layouts = vec![Layout::packed(4)];
    let c = config(vec![4096], 16);
    let right = measure_scene(&scene, &owen, &layouts, &c).unwrap();
    let wrong = measure_scene(&Scaled(scene, 1.02), &owen, &layouts, &c).unwrap();
    let (r, w) = (right.layouts[0].rmse[0], wrong.layouts[0].rmse[0]);
    assert!(r < 0.01 * reference, "RMSE {r} vs reference {reference}");
    assert!(w > 0.018 * reference, "a 2% bias must dominate: {w}");
}

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

fn synthetic(scene: &str, method: &str, rmse: &[f64], rel_se: f64) -> SceneResult {
    SceneResult {
        scene: scene.into(),
        method: method.into(),
        n: vec![64],
        seeds: 64,
        pixels: 1,
        layouts: rmse
            .iter()
            .map(|&r| LayoutCurve {
                layout: String::new(),
                dims: vec![],
                relation: Relation::AcrossQuads,
                rmse: vec![r],
                rmse_se: vec![r * rel_se],
            })
            .collect(),
        pooled_mse: vec![],
        pooled_mse_se: vec![],
        seconds_per_sample: 1e-8,
        render: vec![],
    }
}

#[test]
fn the_headline_says_helps_hurts_or_nothing_by_the_bonferroni_rule() {
    // Best 1 against 1, median 2 against 1, worst 2 against 4.
    let results = vec![
        synthetic("s", "sz16+art-owen-16p", &[2.0, 1.0, 2.0], 0.05),
        synthetic("s", "sz16+art-owen-2", &[1.0, 1.0, 4.0], 0.05),
    ];
    let (rows, z) = headline(&results);
    assert_eq!(rows.len(), 3);
    assert_eq!(z, critical_z(3));
    let get = |w: &str| rows.iter().find(|r| r.which == w).unwrap();
    assert_eq!(get("worst").verdict, "base 16 helps");
    assert!((get("worst").ratio - 0.5).abs() < 1e-15);
    assert_eq!(get("median").verdict, "base 16 hurts");
    assert_eq!(get("best").verdict, "no difference detected");
    // With noisy estimates (SE 40%) the same ratios are not significant.
    let noisy = vec![
        synthetic("s", "sz16+art-owen-16p", &[2.0, 1.0, 2.0], 0.4),
        synthetic("s", "sz16+art-owen-2", &[1.0, 1.0, 4.0], 0.4),
    ];
    assert!(headline(&noisy)
        .0
        .iter()
        .all(|r| r.verdict == "no difference detected"));
    assert!(critical_z(96) > critical_z(3) && (critical_z(1) - 1.959964).abs() < 1e-5);
}

#[test]
fn the_baseline_gate_flags_growth_beyond_factor_and_noise_only() {
    let mut base = run_scenes(
        &ScenePlan {
            scenes: vec![Box::new(
                gartowen_bench::scene::roulette::RouletteScene::default(),
            )],
            methods: vec![SceneMethod::random()],
            layouts: vec![],
            quick: true,
            seed: 1,
            margin: 0.1,
        },
        &|_, _, _| {},
    )
    .unwrap();
    assert!(compare_scenes(&base, &base).is_empty());
    for l in &mut base.results[0].layouts {
        l.rmse_se.iter_mut().for_each(|s| *s = 0.0);
    }
    let now = base.clone();
    // A baseline 30% better everywhere, without noise: every size regresses, twice (median
    // and worst).
    for l in &mut base.results[0].layouts {
        l.rmse.iter_mut().for_each(|r| *r /= 1.3);
    }
    let regs = compare_scenes(&base, &now);
    assert_eq!(regs.len(), 2 * now.results[0].n.len(), "{regs:?}");
    // 5% better is within the ×1.1 factor: no regression.
    let mut close = now.clone();
    for l in &mut close.results[0].layouts {
        l.rmse.iter_mut().for_each(|r| *r /= 1.05);
    }
    assert!(compare_scenes(&close, &now).is_empty());
    // 30% worse but within 3 standard errors: no regression either.
    let mut noisy = now.clone();
    for l in &mut noisy.results[0].layouts {
        let r = l.rmse.clone();
        l.rmse_se = r.iter().map(|x| 0.2 * x).collect();
    }
    assert!(compare_scenes(&base, &noisy).is_empty());
}

/// Two pixels of one coordinate: pixel p estimates p + 1/2 by p + u.
struct TwoPixels;

const ONE: &[Slot] = &[Slot { name: "u", dims: 1 }];

impl Scene for TwoPixels {
    fn name(&self) -> &'static str {
        "two-pixels"
    }
    fn summary(&self) -> &'static str {
        "test"
    }
    fn slots(&self) -> &'static [Slot] {
        ONE
    }
    fn pixels(&self) -> usize {
        2
    }
    fn estimate(&self, pixel: usize, u: &[f64]) -> f64 {
        pixel as f64 + u[0]
    }
    fn reference(&self, pixel: usize) -> f64 {
        pixel as f64 + 0.5
    }
    fn reference_error(&self) -> f64 {
        0.0
    }
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
fn the_scene_report_describes_its_scenes_and_judges_art_against_owen() {
    use gartowen_bench::scene::report::{configs, HEADLINE_SIZES};
    use std::sync::Mutex;
    let registry = gartowen::registry();
    let sz16 = gartowen::seq::SequenceKind::Sz16;
    let methods = ["art-owen-16p", "owen-oracle:base=16", "art-owen-2"]
        .iter()
        .map(|r| SceneMethod::registry(&registry, sz16, r).unwrap())
        .collect();
    let roulette = gartowen_bench::scene::roulette::RouletteScene::default();
    let roulette_reference = roulette.reference(0);
    let plan = ScenePlan {
        scenes: vec![Box::new(TwoPixels), Box::new(roulette)],
        methods,
        layouts: vec![],
        quick: true,
        seed: 4,
        margin: 0.1,
    };
    let calls = Mutex::new(Vec::new());
    let report = run_scenes(&plan, &|done, total, _| {
        calls.lock().unwrap().push((done, total))
    })
    .unwrap();
    assert_eq!(
        calls.into_inner().unwrap(),
        (1..=6).map(|d| (d, 6)).collect::<Vec<_>>()
    );
    let (single, image) = configs(true, 4);
    let two = &report.scenes[0];
    assert_eq!((two.name.as_str(), two.pixels), ("two-pixels", 2));
    assert_eq!(two.reference_mean, 1.0);
    assert_eq!(two.reference_image, vec![0.5, 1.5]);
    assert_eq!(two.slots, vec!["u:1".to_string()]);
    assert_eq!(report.scenes[1].reference_mean, roulette_reference);
    assert!(report.scenes[1].reference_image.is_empty());
    // Multi-pixel scenes use the image sizes and seeds and, in quick mode, one scattered layout.
    assert_eq!(
        (report.results[0].n.clone(), report.results[0].seeds),
        (image.sizes, image.seeds)
    );
    assert_eq!(report.results[0].layouts.len(), 2);
    assert_eq!(
        (report.results[3].n.clone(), report.results[3].seeds),
        (single.sizes.clone(), single.seeds)
    );
    assert_eq!(report.results[3].layouts.len(), 14 + 3);
    // Renders are kept for multi-pixel scenes only.
    assert_eq!(report.results[0].render.len(), 2);
    assert!(report.results[3].render.is_empty());
    // ART against Owen: one row per scene and common headline size, the ratio of pooled MSEs.
    let rows: Vec<(String, usize)> = report
        .equivalence
        .iter()
        .map(|e| (e.scene.clone(), e.n))
        .collect();
    let mut expected = vec![("two-pixels".to_string(), 64)];
    expected.extend(HEADLINE_SIZES.iter().map(|&n| ("roulette".to_string(), n)));
    assert_eq!(rows, expected);
    let (art, owen) = (&report.results[3], &report.results[4]);
    let e = &report.equivalence[1];
    let s = art.n.iter().position(|&n| n == e.n).unwrap();
    assert_eq!(e.judgement.ratio, art.pooled_mse[s] / owen.pooled_mse[s]);
    let log_se = ((art.pooled_mse_se[s] / art.pooled_mse[s]).powi(2)
        + (owen.pooled_mse_se[s] / owen.pooled_mse[s]).powi(2))
    .sqrt();
    assert!((e.judgement.log_se - log_se).abs() < 1e-12);
    // The headline's SE of ln(ratio) from the two layouts' relative standard errors.
    let h = report
        .headline
        .iter()
        .find(|h| h.scene == "roulette" && h.which == "worst" && h.n == 64)
        .unwrap();
    let b2 = &report.results[5];
    let worst = |r: &SceneResult, s: usize| {
        r.layouts
            .iter()
            .max_by(|a, b| a.rmse[s].total_cmp(&b.rmse[s]))
            .map(|l| l.rmse_se[s] / l.rmse[s])
            .unwrap()
    };
    let s = art.n.iter().position(|&n| n == 64).unwrap();
    assert!((h.log_se - worst(art, s).hypot(worst(b2, s))).abs() < 1e-12);

    // A user layout replaces the candidates of its scene only.
    let plan = ScenePlan {
        scenes: vec![Box::new(
            gartowen_bench::scene::roulette::RouletteScene::default(),
        )],
        methods: vec![SceneMethod::random()],
        layouts: vec![
            ("direct".into(), Layout::packed(4)),
            (
                "roulette".into(),
                Layout {
                    dims: vec![3, 9, 12],
                },
            ),
        ],
        quick: true,
        seed: 4,
        margin: 0.1,
    };
    let r = run_scenes(&plan, &|_, _, _| {}).unwrap();
    assert_eq!(r.results[0].layouts.len(), 1);
    assert_eq!(r.results[0].layouts[0].dims, vec![3, 9, 12]);

    // A baseline is comparable only where scene, method and some N meet.
    use gartowen_bench::scene::report::{answer_in_words, comparable_with};
    assert_eq!(
        comparable_with(&r, &plan),
        vec![("roulette".to_string(), "random".to_string())]
    );
    assert!(comparable_with(&report, &plan).is_empty());

    // The words name every significant worst/best verdict of the paper's pair, with its ratio.
    let words = answer_in_words(&report);
    let line = words
        .lines()
        .find(|l| l.starts_with("- **roulette**"))
        .expect("a roulette paragraph");
    let significant: Vec<_> = report
        .headline
        .iter()
        .filter(|h| {
            h.scene == "roulette"
                && h.base16 == "sz16+art-owen-16p"
                && h.which != "median"
                && h.verdict != "no difference detected"
        })
        .collect();
    assert!(!significant.is_empty());
    for h in &significant {
        let needle = format!("N = {} (×{:.2})", h.n, h.ratio);
        assert!(line.contains(&needle), "{needle} missing from {line}");
    }
    assert_eq!(line.matches("N = ").count(), significant.len(), "{line}");
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

#[test]
fn a_baseline_file_must_be_a_scene_report_of_this_version() {
    use gartowen_bench::scene::report::read_scene_baseline;
    let dir = std::env::temp_dir().join(format!("gartowen-scene-baseline-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let report = run_scenes(
        &ScenePlan {
            scenes: vec![Box::new(
                gartowen_bench::scene::defocus::DefocusScene::default(),
            )],
            methods: vec![SceneMethod::random()],
            layouts: vec![("defocus".into(), Layout::packed(5))],
            quick: true,
            seed: 2,
            margin: 0.1,
        },
        &|_, _, _| {},
    )
    .unwrap();
    let mut v = serde_json::to_value(&report).unwrap();
    let good = dir.join("good.json");
    std::fs::write(&good, v.to_string()).unwrap();
    assert_eq!(read_scene_baseline(&good).unwrap(), report);
    for (field, value) in [
        ("schema", serde_json::json!("gartowen-report")),
        ("schema_version", serde_json::json!(2)),
    ] {
        let old = v[field].clone();
        v[field] = value;
        let bad = dir.join("bad.json");
        std::fs::write(&bad, v.to_string()).unwrap();
        let e = read_scene_baseline(&bad).unwrap_err();
        assert!(e.contains("not a gartowen.scene-report version 1"), "{e}");
        v[field] = old;
    }
    std::fs::write(dir.join("junk.json"), "{").unwrap();
    assert!(read_scene_baseline(&dir.join("junk.json"))
        .unwrap_err()
        .contains("not JSON"));
    assert!(read_scene_baseline(&dir.join("missing.json"))
        .unwrap_err()
        .contains("cannot read"));
    std::fs::remove_dir_all(&dir).unwrap();
}
