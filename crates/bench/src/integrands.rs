//! Integrands on [0,1)^s with exact integrals (`docs/design.md` §7): the speed-against-error test
//! functions. Each [`Family`] yields one [`Integrand`] instance per replicate; most families
//! are a single fixed function, the Heaviside family draws a new random orientation per
//! replicate (so its RMSE averages over orientations, as in the literature).
//!
//! Genz families follow Genz (1984) with difficulty a_i and shift u_i; their exact integrals are
//! closed forms (erf, atan, inclusion–exclusion).

use gartowen::core::{hash_words, SplitMix64};
use statrs::function::erf::erf;
use std::f64::consts::PI;

/// A function with a known integral over [0,1)^dims.
pub trait Integrand: Send + Sync {
    /// Number of coordinates it reads.
    fn dims(&self) -> usize;
    /// f(x) for x of length [`Integrand::dims`] (or longer; extra coordinates are ignored).
    fn eval(&self, x: &[f64]) -> f64;
    /// The exact integral over [0,1)^dims.
    fn exact(&self) -> f64;
}

/// Smoothness class, for the slope the theory predicts under Owen scrambling.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Smoothness {
    /// Smooth: RMSE ~ N^-1.5 at N = b^k.
    Smooth,
    /// Continuous with kinks: between the smooth and discontinuous rates.
    Kinked,
    /// Discontinuous across a curve: RMSE ~ N^-0.75 in 2-D.
    Discontinuous,
}

/// A named family of integrands.
pub trait Family: Send + Sync {
    /// Name used in reports and figures.
    fn name(&self) -> String;
    /// Number of coordinates.
    fn dims(&self) -> usize;
    /// Smoothness class.
    fn smoothness(&self) -> Smoothness;
    /// The instance for replicate `r` (seeded: same r, same function).
    fn instance(&self, r: u64) -> Box<dyn Integrand>;
}

/// The area of {x ∈ \[0,1\]² : n·(x − p) ≥ 0}: clip the unit square by the half-plane
/// (one Sutherland–Hodgman pass) and take the shoelace area.
pub fn half_plane_area(normal: [f64; 2], point: [f64; 2]) -> f64 {
    let side = |v: [f64; 2]| normal[0] * (v[0] - point[0]) + normal[1] * (v[1] - point[1]);
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let mut poly: Vec<[f64; 2]> = Vec::with_capacity(5);
    for i in 0..4 {
        let (a, b) = (square[i], square[(i + 1) % 4]);
        let (sa, sb) = (side(a), side(b));
        if sa >= 0.0 {
            poly.push(a);
        }
        if (sa >= 0.0) != (sb >= 0.0) {
            let t = sa / (sa - sb);
            poly.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }
    let n = poly.len();
    0.5 * (0..n)
        .map(|i| {
            let (p, q) = (poly[i], poly[(i + 1) % n]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum::<f64>()
        .abs()
}

/// Indicator of a half-plane through a point of the square, with a uniformly random normal.
#[derive(Debug, Clone)]
pub struct Heaviside {
    normal: [f64; 2],
    point: [f64; 2],
    area: f64,
}

impl Heaviside {
    /// The half-plane n·(x − p) ≥ 0.
    pub fn new(normal: [f64; 2], point: [f64; 2]) -> Self {
        Heaviside {
            normal,
            point,
            area: half_plane_area(normal, point),
        }
    }
}

impl Integrand for Heaviside {
    fn dims(&self) -> usize {
        2
    }
    fn eval(&self, x: &[f64]) -> f64 {
        let s = self.normal[0] * (x[0] - self.point[0]) + self.normal[1] * (x[1] - self.point[1]);
        (s >= 0.0) as u8 as f64
    }
    fn exact(&self) -> f64 {
        self.area
    }
}

/// Random-orientation Heavisides: replicate r draws the angle and the point from
/// `hash_words([seed, r])`.
#[derive(Debug, Clone)]
pub struct HeavisideFamily {
    /// Family seed.
    pub seed: u64,
}

impl Family for HeavisideFamily {
    fn name(&self) -> String {
        "heaviside".into()
    }
    fn dims(&self) -> usize {
        2
    }
    fn smoothness(&self) -> Smoothness {
        Smoothness::Discontinuous
    }
    fn instance(&self, r: u64) -> Box<dyn Integrand> {
        let mut rng = SplitMix64::new(hash_words(&[self.seed, r]));
        let theta = 2.0 * PI * rng.next_f64();
        let point = [rng.next_f64(), rng.next_f64()];
        Box::new(Heaviside::new([theta.cos(), theta.sin()], point))
    }
}

/// A fixed integrand as a one-member family.
pub struct Fixed<F: Integrand + Clone + 'static> {
    /// Name.
    pub name: String,
    /// Smoothness class.
    pub smoothness: Smoothness,
    /// The function.
    pub f: F,
}

impl<F: Integrand + Clone + 'static> Family for Fixed<F> {
    fn name(&self) -> String {
        self.name.clone()
    }
    fn dims(&self) -> usize {
        self.f.dims()
    }
    fn smoothness(&self) -> Smoothness {
        self.smoothness
    }
    fn instance(&self, _r: u64) -> Box<dyn Integrand> {
        Box::new(self.f.clone())
    }
}

/// exp(−|x − μ|² / (2σ²)) in s dimensions.
#[derive(Debug, Clone)]
pub struct Gaussian {
    /// Centre.
    pub mu: Vec<f64>,
    /// Width.
    pub sigma: f64,
}

impl Integrand for Gaussian {
    fn dims(&self) -> usize {
        self.mu.len()
    }
    fn eval(&self, x: &[f64]) -> f64 {
        let r2: f64 = self.mu.iter().zip(x).map(|(m, v)| (v - m).powi(2)).sum();
        (-r2 / (2.0 * self.sigma * self.sigma)).exp()
    }
    fn exact(&self) -> f64 {
        let s = self.sigma * std::f64::consts::SQRT_2;
        self.mu
            .iter()
            .map(|&m| 0.5 * s * PI.sqrt() * (erf((1.0 - m) / s) + erf(m / s)))
            .product()
    }
}

/// Indicator of the disk |x − c| < r (inside the square): area πr².
#[derive(Debug, Clone)]
pub struct HardDisk {
    /// Centre.
    pub c: [f64; 2],
    /// Radius (the disk must lie in the square).
    pub r: f64,
}

impl Integrand for HardDisk {
    fn dims(&self) -> usize {
        2
    }
    fn eval(&self, x: &[f64]) -> f64 {
        (((x[0] - self.c[0]).powi(2) + (x[1] - self.c[1]).powi(2)) < self.r * self.r) as u8 as f64
    }
    fn exact(&self) -> f64 {
        PI * self.r * self.r
    }
}

/// A soft-edged disk: (1 − |x − c|²/r²)² inside the disk, 0 outside (C¹ across the edge).
/// Integral 2πr²∫₀¹(1 − u²)²u du = πr²/3.
#[derive(Debug, Clone)]
pub struct SoftDisk {
    /// Centre.
    pub c: [f64; 2],
    /// Radius (the disk must lie in the square).
    pub r: f64,
}

impl Integrand for SoftDisk {
    fn dims(&self) -> usize {
        2
    }
    fn eval(&self, x: &[f64]) -> f64 {
        let u = ((x[0] - self.c[0]).powi(2) + (x[1] - self.c[1]).powi(2)) / (self.r * self.r);
        if u < 1.0 {
            (1.0 - u) * (1.0 - u)
        } else {
            0.0
        }
    }
    fn exact(&self) -> f64 {
        PI * self.r * self.r / 3.0
    }
}

/// x₀·x₁: integral 1/4.
#[derive(Debug, Clone)]
pub struct Bilinear;

impl Integrand for Bilinear {
    fn dims(&self) -> usize {
        2
    }
    fn eval(&self, x: &[f64]) -> f64 {
        x[0] * x[1]
    }
    fn exact(&self) -> f64 {
        0.25
    }
}

/// The six Genz families.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GenzKind {
    /// cos(2πu₁ + Σ aᵢxᵢ).
    Oscillatory,
    /// Π 1/(aᵢ⁻² + (xᵢ − uᵢ)²).
    ProductPeak,
    /// (1 + Σ aᵢxᵢ)^−(s+1).
    CornerPeak,
    /// exp(−Σ aᵢ²(xᵢ − uᵢ)²).
    Gaussian,
    /// exp(−Σ aᵢ|xᵢ − uᵢ|).
    Continuous,
    /// exp(Σ aᵢxᵢ) where x₁ ≤ u₁ and x₂ ≤ u₂, else 0.
    Discontinuous,
}

impl GenzKind {
    /// All six.
    pub const ALL: [GenzKind; 6] = [
        GenzKind::Oscillatory,
        GenzKind::ProductPeak,
        GenzKind::CornerPeak,
        GenzKind::Gaussian,
        GenzKind::Continuous,
        GenzKind::Discontinuous,
    ];

    /// Short name.
    pub fn name(self) -> &'static str {
        match self {
            GenzKind::Oscillatory => "genz-oscillatory",
            GenzKind::ProductPeak => "genz-product-peak",
            GenzKind::CornerPeak => "genz-corner-peak",
            GenzKind::Gaussian => "genz-gaussian",
            GenzKind::Continuous => "genz-continuous",
            GenzKind::Discontinuous => "genz-discontinuous",
        }
    }

    /// Smoothness class.
    pub fn smoothness(self) -> Smoothness {
        match self {
            GenzKind::Continuous => Smoothness::Kinked,
            GenzKind::Discontinuous => Smoothness::Discontinuous,
            _ => Smoothness::Smooth,
        }
    }
}

/// A Genz integrand with difficulties `a` and shifts `u` (one per dimension).
#[derive(Debug, Clone)]
pub struct Genz {
    /// Which family.
    pub kind: GenzKind,
    /// Difficulty per dimension (> 0).
    pub a: Vec<f64>,
    /// Shift per dimension, in [0, 1].
    pub u: Vec<f64>,
}

impl Genz {
    /// The standard parameters used in reports: aᵢ = difficulty/s·(1 + i/s) and uᵢ from a
    /// fixed irrational progression, in s dimensions.
    pub fn standard(kind: GenzKind, s: usize, difficulty: f64) -> Genz {
        let a = (0..s)
            .map(|i| difficulty / s as f64 * (1.0 + i as f64 / s as f64))
            .collect();
        let u = (0..s)
            .map(|i| (0.3 + 0.618_033_988_749_895 * i as f64).fract() * 0.8 + 0.1)
            .collect();
        Genz { kind, a, u }
    }
}

impl Integrand for Genz {
    fn dims(&self) -> usize {
        self.a.len()
    }
    fn eval(&self, x: &[f64]) -> f64 {
        let (a, u) = (&self.a, &self.u);
        let it = || a.iter().zip(u).zip(x).map(|((a, u), x)| (*a, *u, *x));
        match self.kind {
            GenzKind::Oscillatory => {
                (2.0 * PI * u[0] + it().map(|(a, _, x)| a * x).sum::<f64>()).cos()
            }
            GenzKind::ProductPeak => it()
                .map(|(a, u, x)| 1.0 / (1.0 / (a * a) + (x - u).powi(2)))
                .product(),
            GenzKind::CornerPeak => {
                (1.0 + it().map(|(a, _, x)| a * x).sum::<f64>()).powi(-(a.len() as i32 + 1))
            }
            GenzKind::Gaussian => (-it().map(|(a, u, x)| (a * (x - u)).powi(2)).sum::<f64>()).exp(),
            GenzKind::Continuous => (-it().map(|(a, u, x)| a * (x - u).abs()).sum::<f64>()).exp(),
            GenzKind::Discontinuous => {
                if x[0] > u[0] || (a.len() > 1 && x[1] > u[1]) {
                    0.0
                } else {
                    it().map(|(a, _, x)| a * x).sum::<f64>().exp()
                }
            }
        }
    }
    fn exact(&self) -> f64 {
        let (a, u) = (&self.a, &self.u);
        let s = a.len();
        match self.kind {
            GenzKind::Oscillatory => {
                // Re[e^{i2πu₁} Π (e^{i aₖ} − 1)/(i aₖ)], in complex pairs (re, im).
                let mul =
                    |p: (f64, f64), q: (f64, f64)| (p.0 * q.0 - p.1 * q.1, p.0 * q.1 + p.1 * q.0);
                let mut z = ((2.0 * PI * u[0]).cos(), (2.0 * PI * u[0]).sin());
                for &ak in a {
                    // (e^{ia} − 1)/(ia) = (sin a)/a + i(1 − cos a)/a
                    z = mul(z, (ak.sin() / ak, (1.0 - ak.cos()) / ak));
                }
                z.0
            }
            GenzKind::ProductPeak => a
                .iter()
                .zip(u)
                .map(|(a, u)| a * ((a * (1.0 - u)).atan() + (a * u).atan()))
                .product(),
            GenzKind::CornerPeak => {
                let fact: f64 = (1..=s).map(|k| k as f64).product();
                let prod_a: f64 = a.iter().product();
                let sum: f64 = (0u32..1 << s)
                    .map(|v| {
                        let sign = if v.count_ones() % 2 == 0 { 1.0 } else { -1.0 };
                        let dot: f64 = (0..s).filter(|k| v >> k & 1 == 1).map(|k| a[k]).sum();
                        sign / (1.0 + dot)
                    })
                    .sum();
                sum / (fact * prod_a)
            }
            GenzKind::Gaussian => a
                .iter()
                .zip(u)
                .map(|(a, u)| PI.sqrt() / (2.0 * a) * (erf(a * (1.0 - u)) + erf(a * u)))
                .product(),
            GenzKind::Continuous => a
                .iter()
                .zip(u)
                .map(|(a, u)| (2.0 - (-a * u).exp() - (-a * (1.0 - u)).exp()) / a)
                .product(),
            GenzKind::Discontinuous => a
                .iter()
                .enumerate()
                .map(|(k, &ak)| {
                    let top = if k < 2 { u[k] } else { 1.0 };
                    ((ak * top).exp() - 1.0) / ak
                })
                .product(),
        }
    }
}

/// The report's integrand families: 2-D Heavisides, Gaussian, hard and soft disks, bilinear,
/// and the six Genz families in 2 and in `genz_dims` dimensions.
pub fn standard_families(genz_dims: usize) -> Vec<Box<dyn Family>> {
    let mut v: Vec<Box<dyn Family>> = vec![
        Box::new(HeavisideFamily { seed: 0x4EAF }),
        Box::new(Fixed {
            name: "gaussian-2d".into(),
            smoothness: Smoothness::Smooth,
            f: Gaussian {
                mu: vec![0.4, 0.55],
                sigma: 0.25,
            },
        }),
        Box::new(Fixed {
            name: "hard-disk".into(),
            smoothness: Smoothness::Discontinuous,
            f: HardDisk {
                c: [0.45, 0.52],
                r: 0.35,
            },
        }),
        Box::new(Fixed {
            name: "soft-disk".into(),
            smoothness: Smoothness::Smooth,
            f: SoftDisk {
                c: [0.45, 0.52],
                r: 0.35,
            },
        }),
        Box::new(Fixed {
            name: "bilinear".into(),
            smoothness: Smoothness::Smooth,
            f: Bilinear,
        }),
    ];
    for s in [2, genz_dims] {
        for kind in GenzKind::ALL {
            v.push(Box::new(Fixed {
                name: format!("{}-{s}d", kind.name()),
                smoothness: kind.smoothness(),
                f: Genz::standard(kind, s, 4.0),
            }));
        }
    }
    v
}
