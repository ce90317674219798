//! Every reference against Monte Carlo through its estimator, and the image quadrature
//! against finer lattices; a reference 2% off is caught.

use super::*;

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
