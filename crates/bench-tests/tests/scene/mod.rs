//! Scenes: every reference against an independent computation (Monte Carlo with 2^22 points
//! through the estimator, and finer quadrature for the image), a reference 2% off detected,
//! the harness deterministic and sensitive to a biased reference, and the verdict and
//! baseline rules on synthetic results. One test binary; one file per concern.

use gartowen::core::{derive_seed, Progress, Silent, SplitMix64};
use gartowen_bench::scene::image::ImageScene;
use gartowen_bench::scene::layout::{candidate_layouts, Relation};
use gartowen_bench::scene::measure::{
    measure_scene, LayoutCurve, SceneConfig, SceneMethod, SceneResult,
};
use gartowen_bench::scene::report::{compare_scenes, critical_z, headline, run_scenes, ScenePlan};
use gartowen_bench::scene::{all_scenes, Layout, Scene, Slot};
use rayon::prelude::*;

mod harness;
mod references;
mod report;

fn config(sizes: Vec<usize>, seeds: u64) -> SceneConfig {
    SceneConfig {
        sizes,
        seeds,
        seed: 7,
    }
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
