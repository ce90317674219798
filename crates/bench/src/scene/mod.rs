//! Rendering-style estimators whose dimensions come from a declared sampler layout: does
//! base-2^q decorrelation pay off in a scene?
//!
//! A [`Scene`] declares named [`Slot`]s (pixel, lens, time, light, BSDF, roulette …), each a
//! few coordinates; a [`Layout`] says which sequence dimension serves each coordinate. The
//! estimator reads only the coordinates its slots name, in slot order, and every scene has an
//! exact reference (closed forms, exact rationals, or a quadrature whose error the tests bound).
//! [`measure`] runs every method over every layout that matters and reports RMSE against N.

pub mod defocus;
pub mod direct;
pub mod figures;
pub mod geometry;
pub mod image;
pub mod layout;
pub mod measure;
pub mod output;
pub mod report;
pub mod roulette;

pub use layout::{Layout, LayoutError};

/// A named group of coordinates an estimator reads (for example `light`, 2 coordinates).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Slot {
    /// Name used in layouts (`light=4,5`).
    pub name: &'static str,
    /// Number of coordinates.
    pub dims: usize,
}

/// A rendering-style estimator with an exact reference.
///
/// An estimator is a function of one sample `u` (its coordinates in slot order, each in
/// [0, 1)); its mean over the unit cube is [`Scene::reference`]. Scenes with several pixels
/// have one estimator per pixel, each fed from its own seed.
pub trait Scene: Send + Sync {
    /// Short name (`roulette`, `direct`, `defocus`, `image`).
    fn name(&self) -> &'static str;
    /// One line: what is estimated.
    fn summary(&self) -> &'static str;
    /// The slots, in the order their coordinates appear in a sample.
    fn slots(&self) -> &'static [Slot];
    /// Number of estimators (pixels); 1 for a single estimator.
    fn pixels(&self) -> usize {
        1
    }
    /// One sample's estimate of pixel `pixel`.
    fn estimate(&self, pixel: usize, u: &[f64]) -> f64;
    /// The exact mean of [`Scene::estimate`] over the unit cube.
    fn reference(&self, pixel: usize) -> f64;
    /// A bound on |reference − true value| (0 for closed forms up to rounding).
    fn reference_error(&self) -> f64;
    /// Number of coordinates a sample has.
    fn coordinates(&self) -> usize {
        self.slots().iter().map(|s| s.dims).sum()
    }
}

/// Every built-in scene, in report order (the image computes its reference on construction,
/// about a tenth of a second).
pub fn all_scenes() -> Vec<Box<dyn Scene>> {
    vec![
        Box::new(roulette::RouletteScene::default()),
        Box::new(direct::DirectScene::default()),
        Box::new(defocus::DefocusScene::default()),
        Box::new(image::ImageScene::new(image::IMAGE_SIDE)),
    ]
}

/// The built-in scene called `name`, or an error listing the names.
pub fn scene_by_name(name: &str) -> Result<Box<dyn Scene>, String> {
    let names = ["roulette", "direct", "defocus", "image"];
    match name {
        "roulette" => Ok(Box::new(roulette::RouletteScene::default())),
        "direct" => Ok(Box::new(direct::DirectScene::default())),
        "defocus" => Ok(Box::new(defocus::DefocusScene::default())),
        "image" => Ok(Box::new(image::ImageScene::new(image::IMAGE_SIDE))),
        other => Err(format!(
            "unknown scene '{other}' (scenes: {})",
            names.join(", ")
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_scene_is_found_by_its_name_and_says_what_it_estimates() {
        let scenes = all_scenes();
        let names: Vec<&str> = scenes.iter().map(|s| s.name()).collect();
        assert_eq!(names, ["roulette", "direct", "defocus", "image"]);
        for s in &scenes {
            let again = scene_by_name(s.name()).unwrap();
            assert_eq!((again.name(), again.slots()), (s.name(), s.slots()));
            assert!(s.summary().len() > 20, "{}", s.name());
        }
        let summaries: std::collections::HashSet<&str> =
            scenes.iter().map(|s| s.summary()).collect();
        assert_eq!(summaries.len(), scenes.len());
        let e = scene_by_name("teapot").err().unwrap();
        assert!(e.contains("roulette, direct, defocus, image"), "{e}");
    }
}
