//! Russian roulette: one decision coordinate gates a radiance estimate read from a cosine-
//! sampled bounce direction. A path continues with probability p and is then weighted 1/p, so
//! the estimator is unbiased; whether the decision is independent of the bounce's coordinates
//! is exactly what a sampler's layout decides.

use super::geometry::cosine_direction;
use super::{Scene, Slot};

const SLOTS: &[Slot] = &[
    Slot {
        name: "roulette",
        dims: 1,
    },
    Slot {
        name: "bounce",
        dims: 2,
    },
];

/// Reflected radiance of a Lambertian receiver (albedo ρ) under a sky whose radiance is
/// L(ω) = 1 + a·z³ + b·x² (z = cos θ), estimated with Russian roulette (continue with
/// probability p) and one cosine-sampled bounce.
///
/// Exact value: ρ·(1 + a·E(z³) + b·E(x²)) with E over the cosine law: E(z³) = 2/5 (z² is
/// uniform) and E(x²) = E(sin²θ)·E(cos²φ) = 1/2 · 1/2.
#[derive(Debug, Clone, PartialEq)]
pub struct RouletteScene {
    /// Continuation probability p.
    pub survival: f64,
    /// Albedo ρ.
    pub albedo: f64,
    /// Coefficient a of z³.
    pub zenith: f64,
    /// Coefficient b of x².
    pub side: f64,
}

impl Default for RouletteScene {
    fn default() -> Self {
        RouletteScene {
            survival: 0.3,
            albedo: 0.8,
            zenith: 4.0,
            side: 3.0,
        }
    }
}

impl RouletteScene {
    /// Sky radiance in direction ω.
    pub fn sky(&self, w: [f64; 3]) -> f64 {
        1.0 + self.zenith * w[2].powi(3) + self.side * w[0] * w[0]
    }
}

impl Scene for RouletteScene {
    fn name(&self) -> &'static str {
        "roulette"
    }
    fn summary(&self) -> &'static str {
        "Russian roulette (p = 0.3) gating one cosine-sampled bounce under a smooth sky (3-D)"
    }
    fn slots(&self) -> &'static [Slot] {
        SLOTS
    }
    fn estimate(&self, _pixel: usize, u: &[f64]) -> f64 {
        if u[0] >= self.survival {
            return 0.0;
        }
        // Lambertian: ρ/π · L · cos θ / (cos θ / π) = ρ·L.
        self.albedo * self.sky(cosine_direction(u[1], u[2])) / self.survival
    }
    fn reference(&self, _pixel: usize) -> f64 {
        self.albedo * (1.0 + self.zenith * 0.4 + self.side * 0.25)
    }
    fn reference_error(&self) -> f64 {
        0.0
    }
}
