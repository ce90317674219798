//! The report: verdicts, equivalence rows, words and baselines.

use super::*;

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
        &Silent,
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
    struct Recorder(Mutex<Vec<String>>);
    impl Progress for Recorder {
        fn start(&self, total: u64, _: &str) {
            self.0.lock().unwrap().push(format!("start {total}"));
        }
        fn advance(&self, k: u64) {
            self.0.lock().unwrap().push(format!("+{k}"));
        }
        fn message(&self, what: &str) {
            self.0.lock().unwrap().push(what.to_string());
        }
        fn finish(&self) {
            self.0.lock().unwrap().push("finish".into());
        }
    }
    let calls = Recorder(Mutex::new(Vec::new()));
    let report = run_scenes(&plan, &calls).unwrap();
    let calls = calls.0.into_inner().unwrap();
    // One start with every scene × method, each pair named before it runs and counted after.
    assert_eq!(calls.len(), 2 + 2 * 6, "{calls:?}");
    assert_eq!(
        (calls[0].as_str(), calls[13].as_str()),
        ("start 6", "finish")
    );
    assert!(calls[1].starts_with("two-pixels "), "{calls:?}");
    let named: std::collections::BTreeSet<&String> = calls[1..13].iter().step_by(2).collect();
    assert_eq!(named.len(), 6, "every pair named once: {calls:?}");
    assert!(
        calls[2..13].iter().step_by(2).all(|c| c == "+1"),
        "{calls:?}"
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
    assert_eq!(e.judgement.seeds, art.seeds * art.pixels as u64);
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
    let r = run_scenes(&plan, &Silent).unwrap();
    assert_eq!(r.results[0].layouts.len(), 1);
    assert_eq!(r.results[0].layouts[0].dims, vec![3, 9, 12]);

    // A baseline is comparable only where scene, method and some N meet.
    use gartowen_bench::scene::report::{answer_in_words, comparable_with};
    assert_eq!(
        comparable_with(&r, &plan),
        vec![("roulette".to_string(), "random".to_string())]
    );
    assert!(comparable_with(&report, &plan).is_empty());
    // A single-estimator scene is compared at its own sizes, not the image's.
    let mut late = r.clone();
    let last = late.results[0].n.len() - 1;
    late.results[0].n = vec![late.results[0].n[last]];
    assert_eq!(late.results[0].n, vec![4096]);
    assert_eq!(comparable_with(&late, &plan).len(), 1);

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
        &Silent,
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

#[test]
fn a_regression_is_named_by_its_own_scene_and_method() {
    let registry = gartowen::registry();
    let lk =
        SceneMethod::registry(&registry, gartowen::seq::SequenceKind::Sobol, "lk-hash").unwrap();
    let mut now = run_scenes(
        &ScenePlan {
            scenes: vec![Box::new(
                gartowen_bench::scene::defocus::DefocusScene::default(),
            )],
            methods: vec![SceneMethod::random(), lk],
            layouts: vec![("defocus".into(), Layout::packed(5))],
            quick: true,
            seed: 3,
            margin: 0.1,
        },
        &Silent,
    )
    .unwrap();
    for r in &mut now.results {
        for l in &mut r.layouts {
            l.rmse_se.iter_mut().for_each(|s| *s = 0.0);
        }
    }
    // The baseline was 30% better for random points only.
    let mut base = now.clone();
    for l in &mut base.results[0].layouts {
        l.rmse.iter_mut().for_each(|r| *r /= 1.3);
    }
    let regs = compare_scenes(&base, &now);
    assert_eq!(regs.len(), 2 * now.results[0].n.len(), "{regs:?}");
    assert!(
        regs.iter().all(|r| r.what.starts_with("defocus random:")),
        "{regs:?}"
    );
}
