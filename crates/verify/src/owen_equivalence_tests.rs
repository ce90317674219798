//! Tests of [`super`]: the Owen variances, the diagonal moments and the check's verdicts.
use super::*;
use gartowen_core::Scrambler;
use gartowen_owen::{FullTreeOwen, OwenVariant};

fn oracle(base: PowerOfTwoBase, variant: OwenVariant) -> Box<SeedBuilder<'static>> {
    Box::new(move |seed| Ok(Box::new(FullTreeOwen::new(base, variant, seed)) as Box<dyn Scrambler>))
}

#[test]
fn pair_covariances_follow_the_pair_lemma() {
    // Opposite halves in base 2: each uniform on its half, independent: 3/16 − 1/4.
    let b2 = PowerOfTwoBase::B2;
    assert!((owen_pair_covariance(0, 0x8000_0000, b2) + 1.0 / 16.0).abs() < 1e-15);
    assert_eq!(owen_pair_covariance(7, 7, b2), 1.0 / 12.0);
    // Differing first at base-4 digit 1: prefix grid 1/4, a distinct pair of 4 digits.
    let b4 = PowerOfTwoBase::B4;
    let s: f64 = 0.25;
    let expect = (1.0 - s * s) / 12.0 - (s / 4.0).powi(2) * 5.0 / 12.0;
    assert!((owen_pair_covariance(0, 0x1000_0000, b4) - expect).abs() < 1e-15);
    // Base 8 on 32 bits: the last digit has 2 bits, a base-4 digit after a 2^-30 grid.
    let b8 = PowerOfTwoBase::B8;
    let s = 2f64.powi(-30);
    let expect = (1.0 - s * s) / 12.0 - (s / 4.0).powi(2) * 5.0 / 12.0;
    assert!((owen_pair_covariance(0, 1, b8) - expect).abs() < 1e-18);
    // The mean's variance of N points that are all equal is 1/12; of a base-2 (0,1,1)-net
    // of 2 points, (1/12 + 1/12 − 2/16)/4.
    assert!((owen_mean_variance(&[5, 5, 5], b2) - 1.0 / 12.0).abs() < 1e-15);
    let two = owen_mean_variance(&[0, 0x8000_0000], b2);
    assert!((two - (2.0 / 12.0 - 2.0 / 16.0) / 4.0).abs() < 1e-15);
}

#[test]
fn the_oracle_is_equivalent_and_a_nested_digital_shift_is_not() {
    // Fixed seeds 0..4000, α = 0.05 per one-sided test: the exact oracle's statistics are
    // equivalent within ±10%, while the XOR variant (a uniform translation per node, so
    // y_i ⊕ y_k keeps its top digits' structure) has its coordinate-mean variance different.
    // Its box statistics equal Owen's (the module doc says why), which this also pins.
    let b4 = PowerOfTwoBase::B4;
    let ok = check_equivalent_to_owen(
        oracle(b4, OwenVariant::Uniform).as_ref(),
        b4,
        Width::W32,
        4000,
        0.1,
    );
    assert_eq!(ok.verdict, Verdict::Pass, "{}", ok.detail);
    assert!(
        ok.detail.contains("box level 3: ratio"),
        "4,000 hits are judged"
    );
    let xor = check_equivalent_to_owen(
        oracle(b4, OwenVariant::Xor).as_ref(),
        b4,
        Width::W32,
        4000,
        0.1,
    );
    assert_eq!(xor.verdict, Verdict::Fail);
    assert!(xor.detail.contains("mean dim 0: ratio"), "{}", xor.detail);
    let ratios =
        variance_ratios(oracle(b4, OwenVariant::Xor).as_ref(), b4, Width::W32, 4000).unwrap();
    let judged = judge_statistics(&ratios, 2, 4000, 0.1);
    let verdict = |name: &str| judged.iter().find(|(n, _)| n == name).unwrap().1.verdict;
    assert_eq!(verdict("mean dim 0"), EquivalenceVerdict::Different);
    assert_eq!(verdict("box level 1"), EquivalenceVerdict::Equivalent);
    // 64-bit words see the same statistics (the points in the top half).
    let wide = variance_ratios(
        oracle(b4, OwenVariant::Uniform).as_ref(),
        b4,
        Width::W64,
        500,
    )
    .unwrap();
    assert!(wide
        .means
        .iter()
        .all(|m| (m.ratio - 1.0).abs() < 4.0 * m.ratio_se));
}

#[test]
fn the_fourth_diagonal_moment_tells_affine_nodes_from_owen_where_variances_cannot() {
    // Fixed seeds 0..10,000 (the quick level's), base 16, α = 0.05, margin ±10%: the
    // exact oracle's diagonal moments are equivalent; the affine variant (each node uniform
    // in AGL(4,2), 2-transitive, so every variance is Owen's) has its second moment
    // equivalent and its fourth different (exact ratio 5/4), so the check fails.
    let b16 = PowerOfTwoBase::B16;
    let ratios_of =
        |variant| variance_ratios(oracle(b16, variant).as_ref(), b16, Width::W32, 10_000).unwrap();
    let verdicts = |ratios: &VarianceRatios| {
        let judged = judge_statistics(ratios, 4, 10_000, 0.1);
        let of = |name: &str| judged.iter().find(|(n, _)| n == name).unwrap().1.clone();
        (of("diagonal moment 2"), of("diagonal moment 4"))
    };
    let (m2, m4) = verdicts(&ratios_of(OwenVariant::Uniform));
    assert_eq!(m2.verdict, EquivalenceVerdict::Equivalent, "{m2:?}");
    assert_eq!(m4.verdict, EquivalenceVerdict::Equivalent, "{m4:?}");
    let affine_ratios = ratios_of(OwenVariant::Affine);
    let (m2, m4) = verdicts(&affine_ratios);
    assert_eq!(m2.verdict, EquivalenceVerdict::Equivalent, "{m2:?}");
    assert_eq!(m4.verdict, EquivalenceVerdict::Different, "{m4:?}");
    assert!((1.1..1.4).contains(&m4.ratio), "{m4:?}");
    // The check's verdict on the same ratios (check_equivalent_to_owen measures them, then
    // judges them so; it is run end to end on the uniform oracle below).
    let (verdict, detail, _) = judge_ratios(&affine_ratios, b16, 10_000, 0.1);
    assert_eq!(verdict, Verdict::Fail);
    // AGL holds translations (1 map in 20,160): the detail names the translate pairs it
    // met; the exact oracle meets none (10⁻¹² each) and says nothing of them.
    assert!(
        detail.contains("diagonal diagnosis: ") && detail.contains("of 160000 dimension pairs"),
        "{detail}"
    );
    let uniform = check_equivalent_to_owen(
        oracle(b16, OwenVariant::Uniform).as_ref(),
        b16,
        Width::W32,
        2000,
        0.1,
    );
    assert!(
        !uniform.detail.contains("diagonal diagnosis"),
        "{}",
        uniform.detail
    );
    // Each statistic states the change it detects: the fourth moment's, at 2,000 seeds, a few
    // percent.
    let fourth = uniform
        .detail
        .split("diagonal moment 4: ratio")
        .nth(1)
        .unwrap();
    let detects: f64 = fourth
        .split("(detects ±")
        .nth(1)
        .and_then(|t| t.split('%').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{}", uniform.detail));
    assert!((0.5..10.0).contains(&detects), "{detects}");
    // Base 2: no diagonal moment is read (every permutation of two digits gives them).
    let b2 = PowerOfTwoBase::B2;
    let r = variance_ratios(
        oracle(b2, OwenVariant::Uniform).as_ref(),
        b2,
        Width::W32,
        50,
    )
    .unwrap();
    assert!(r.diagonal.is_empty() && r.translates.is_none(), "{r:?}");
    // Base 4 reads them, without the translate diagnosis (one permutation in six is one).
    let b4 = PowerOfTwoBase::B4;
    let r = variance_ratios(
        oracle(b4, OwenVariant::Uniform).as_ref(),
        b4,
        Width::W32,
        50,
    )
    .unwrap();
    assert!(r.diagonal.len() == 2 && r.translates.is_none(), "{r:?}");
    assert!(detail.contains("diagonal moment 4: ratio"), "{detail}");
    // A nested digital shift in base 16: every point on one diagonal, second moment 15×.
    let (m2, _) = verdicts(&ratios_of(OwenVariant::Xor));
    assert!((m2.ratio - 15.0).abs() < 1e-9, "{m2:?}");
}

#[test]
fn too_few_seeds_is_a_failure_that_says_so() {
    let b16 = PowerOfTwoBase::B16;
    let c = check_equivalent_to_owen(
        oracle(b16, OwenVariant::Uniform).as_ref(),
        b16,
        Width::W32,
        20,
        0.1,
    );
    assert_eq!(c.verdict, Verdict::Fail);
    assert!(c.detail.contains("not judged"), "{}", c.detail);
    assert!(c.detail.contains("seeds needed") || c.detail.contains("different"));
    let broken: Box<SeedBuilder> = Box::new(|seed| Err(format!("seed {seed} refused")));
    let c = check_equivalent_to_owen(broken.as_ref(), b16, Width::W32, 20, 0.1);
    assert_eq!(c.verdict, Verdict::Fail);
    assert!(c.detail.contains("refused"), "{}", c.detail);
}

#[test]
fn hits_variances_and_seed_defaults_are_as_documented() {
    assert_eq!(expected_hits(1000, 2, 3), 1000.0); // 1000 · 64 / 4^3
    assert_eq!(expected_hits(10_000, 4, 2), 2500.0); // 10,000 · 64 / 16^2
                                                     // [0, 0, 0, 4]: s² = 12/3 = 4, m₄ = 84/4 = 21, SE = √((21 − 16)/4 + 2·16/12).
    let (s2, se) = sample_variance(&[0.0, 0.0, 0.0, 4.0]);
    assert_eq!(s2, 4.0);
    assert!((se - (1.25f64 + 32.0 / 12.0).sqrt()).abs() < 1e-12);
    assert_eq!(
        [Level::Quick, Level::Full, Level::Exhaustive].map(equivalence_seeds),
        [10_000, 40_000, 100_000]
    );
}

#[test]
fn rare_boxes_get_no_ratio_and_standard_errors_scale_with_the_seeds() {
    // Base 16 with 20 seeds: level 1 expects 20·64/16 = 80 hits (a ratio), level 3 0.3
    // (none). Base 4 with 4,000 seeds: the level-1 ratio's SE is near √((2 + 1/λ)/R)
    // with λ = 16 hits per seed, about 0.023.
    let b16 = PowerOfTwoBase::B16;
    let r = variance_ratios(
        oracle(b16, OwenVariant::Uniform).as_ref(),
        b16,
        Width::W32,
        20,
    )
    .unwrap();
    assert!(r.boxes[0].ratio.is_some() && r.boxes[2].ratio.is_none());
    assert_eq!(
        r.boxes.iter().map(|l| l.level).collect::<Vec<_>>(),
        [1, 2, 3]
    );
    let b4 = PowerOfTwoBase::B4;
    let r = variance_ratios(
        oracle(b4, OwenVariant::Uniform).as_ref(),
        b4,
        Width::W32,
        4000,
    )
    .unwrap();
    let se = r.boxes[0].ratio_se.unwrap();
    assert!((0.01..0.04).contains(&se), "{se}");
    assert!(
        r.means.iter().all(|m| (0.01..0.04).contains(&m.ratio_se)),
        "{r:?}"
    );
    // 64-bit instances read the points from the top half, boxes included.
    let wide = variance_ratios(
        oracle(b4, OwenVariant::Uniform).as_ref(),
        b4,
        Width::W64,
        2000,
    )
    .unwrap();
    for l in &wide.boxes {
        let (ratio, se) = (l.ratio.unwrap(), l.ratio_se.unwrap());
        assert!(
            (ratio - 1.0).abs() < 4.0 * se,
            "level {}: {ratio} ± {se}",
            l.level
        );
    }
}

#[test]
fn statistics_are_judged_on_the_log_scale_with_their_names() {
    let ratios = VarianceRatios {
        boxes: vec![
            LevelVariance {
                level: 1,
                ratio: Some(2.0),
                ratio_se: Some(0.1),
            },
            LevelVariance {
                level: 3,
                ratio: Some(1.0),
                ratio_se: Some(0.01),
            },
        ],
        means: vec![MeanVariance {
            dim: 0,
            ratio: 0.5,
            ratio_se: 0.01,
        }],
        diagonal: vec![DiagonalMoment {
            order: 4,
            ratio: 1.25,
            ratio_se: 0.05,
        }],
        translates: None,
    };
    // Base 4, 1000 seeds: level 1 expects 16,000 hits (judged), level 3 1,000 (not).
    let judged = judge_statistics(&ratios, 2, 1000, 0.1);
    let names: Vec<&str> = judged.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["mean dim 0", "diagonal moment 4", "box level 1"]);
    assert!((judged[0].1.log_se - 0.02).abs() < 1e-12);
    assert!((judged[1].1.log_se - 0.04).abs() < 1e-12);
    assert!((judged[2].1.log_se - 0.05).abs() < 1e-12);
    assert_eq!(judged[2].1.settings.family, 3);
}
