//! A tiny scene image: a plane lit by a rectangular area light past a triangular occluder,
//! under a coloured sky, seen by an orthographic camera from above through a square aperture
//! while the lamp assembly (light and occluder) moves along x during the shutter. The occluder
//! casts shadows but is invisible to camera rays, so the camera sees only the plane.
//!
//! Each pixel is an estimator of a 13-coordinate sample: pixel (2), lens (2), time (1),
//! wavelength (1: picks one of three colour channels), light (2) and BSDF (2) for MIS direct
//! lighting, roulette (1) gating one sky bounce (2). The value is luminance.
//!
//! The reference: the point seen is y = p + c(2l − 1) − v t e_x, a sum of independent uniforms
//! per axis, so a pixel's value is ∫ Lo(y) K(y) dy with K the product of two piecewise-
//! polynomial densities and Lo exact by Lambert's formula ([`Room::direct_exact`],
//! [`Room::sky_exact`]). The integral is computed by Gauss–Legendre on a lattice aligned with
//! K's breakpoints; the tests bound its error by comparing finer lattices.

use super::direct::Room;
use super::{Scene, Slot};
use std::f64::consts::PI;

/// Pixels per side of the built-in image.
pub const IMAGE_SIDE: usize = 32;

const SLOTS: &[Slot] = &[
    Slot {
        name: "pixel",
        dims: 2,
    },
    Slot {
        name: "lens",
        dims: 2,
    },
    Slot {
        name: "time",
        dims: 1,
    },
    Slot {
        name: "wavelength",
        dims: 1,
    },
    Slot {
        name: "light",
        dims: 2,
    },
    Slot {
        name: "bsdf",
        dims: 2,
    },
    Slot {
        name: "roulette",
        dims: 1,
    },
    Slot {
        name: "bounce",
        dims: 2,
    },
];

/// Luminance weights of the three channels (Rec. 709).
const LUMINANCE: [f64; 3] = [0.2126, 0.7152, 0.0722];
/// Plane albedo per channel.
const ALBEDO: [f64; 3] = [0.8, 0.6, 0.4];
/// Light radiance per channel.
const LIGHT: [f64; 3] = [9.0, 7.0, 5.0];
/// Sky radiance per channel.
const SKY: [f64; 3] = [0.3, 0.45, 0.7];
/// Russian roulette survival probability of the sky bounce.
const SURVIVAL: f64 = 0.5;
/// Lattice cells per pixel and Gauss–Legendre nodes per cell of the reference.
const QUADRATURE: (usize, usize) = (4, 4);

/// The image scene (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct ImageScene {
    /// Pixels per side.
    pub side: usize,
    /// Geometry.
    pub room: Room,
    /// Lower-left corner (x, y) of the imaged region of the plane.
    pub corner: [f64; 2],
    /// Side of the imaged region (scene units).
    pub width: f64,
    reference: Vec<f64>,
}

impl ImageScene {
    /// The `side` × `side` image of the region [−1.5, 1.5]², with its reference.
    pub fn new(side: usize) -> ImageScene {
        let mut s = ImageScene {
            side,
            room: Room::default(),
            corner: [-1.5, -1.5],
            width: 3.0,
            reference: Vec::new(),
        };
        s.reference = s.quadrature(QUADRATURE.0, QUADRATURE.1);
        s
    }

    /// Pixel width.
    fn pixel(&self) -> f64 {
        self.width / self.side as f64
    }

    /// Aperture half-width c and motion v: half a pixel and one pixel (their breakpoints fall
    /// on multiples of half a pixel, which the quadrature lattice honours).
    fn blur_and_motion(&self) -> (f64, f64) {
        (0.5 * self.pixel(), self.pixel())
    }

    /// Exact luminance leaving plane point (x, y) towards the camera.
    pub fn radiance(&self, x: f64, y: f64) -> f64 {
        let p = [x, y, 0.0];
        let (d, s) = (self.room.direct_exact(p), self.room.sky_exact(p));
        (0..3)
            .map(|c| LUMINANCE[c] * ALBEDO[c] * (LIGHT[c] * d + SKY[c] * s) / PI)
            .sum()
    }

    /// The reference image, row-major (row = y index), computed with `cells` lattice cells per
    /// pixel and `nodes` Gauss–Legendre nodes per cell and axis.
    pub fn quadrature(&self, cells: usize, nodes: usize) -> Vec<f64> {
        let w = self.pixel();
        let (c, v) = self.blur_and_motion();
        let h = w / cells as f64;
        let (gx, gw) = gauss_legendre(nodes);
        // The lattice spans every pixel's kernel: x from corner − c − v, y from corner − c.
        let (x_start, y_start) = (self.corner[0] - c - v, self.corner[1] - c);
        let x_cells = ((self.width + c + v + c) / h).round() as usize;
        let y_cells = ((self.width + 2.0 * c) / h).round() as usize;
        let axis = |start: f64, n: usize| -> Vec<(f64, f64)> {
            (0..n)
                .flat_map(|k| {
                    let a = start + k as f64 * h;
                    gx.iter()
                        .zip(&gw)
                        .map(move |(x, wt)| (a + 0.5 * h * (x + 1.0), 0.5 * h * wt))
                })
                .collect()
        };
        let (xs, ys) = (axis(x_start, x_cells), axis(y_start, y_cells));
        let lo: Vec<f64> = ys
            .iter()
            .flat_map(|&(y, _)| xs.iter().map(move |&(x, _)| (x, y)))
            .map(|(x, y)| self.radiance(x, y))
            .collect();
        let per = nodes * cells;
        let mut out = Vec::with_capacity(self.side * self.side);
        for j in 0..self.side {
            // Pixel j's y kernel: widths (w, 2c) from its lower edge − c; nonzero on the
            // lattice rows j·per .. (j + 3)·per (in cells: 2 pixels' worth from y_start + j·w).
            let y_origin = self.corner[1] + j as f64 * w - c;
            let y_rows: Vec<(usize, f64)> = (j * per..((j + 2) * per).min(ys.len()))
                .map(|r| {
                    (
                        r,
                        ys[r].1 * uniform_sum_density(ys[r].0 - y_origin, &[w, 2.0 * c]),
                    )
                })
                .collect();
            for i in 0..self.side {
                let x_origin = self.corner[0] + i as f64 * w - c - v;
                let x_cols: Vec<(usize, f64)> = (i * per..((i + 3) * per).min(xs.len()))
                    .map(|q| {
                        let k = uniform_sum_density(xs[q].0 - x_origin, &[w, 2.0 * c, v]);
                        (q, xs[q].1 * k)
                    })
                    .collect();
                let mut sum = 0.0;
                for &(r, wy) in &y_rows {
                    let row = &lo[r * xs.len()..(r + 1) * xs.len()];
                    sum += wy * x_cols.iter().map(|&(q, wx)| wx * row[q]).sum::<f64>();
                }
                out.push(sum);
            }
        }
        out
    }

    /// The reference image, row-major.
    pub fn reference_image(&self) -> &[f64] {
        &self.reference
    }
}

/// The density at s of Σ b_i U_i (U_i uniform on [0, 1), b_i > 0):
/// Σ_S (−1)^|S| (s − Σ_S b)₊ⁿ⁻¹ / ((n − 1)! Π b).
pub fn uniform_sum_density(s: f64, widths: &[f64]) -> f64 {
    let n = widths.len();
    let total: f64 = widths.iter().sum();
    if n == 0 || s <= 0.0 || s >= total {
        return 0.0;
    }
    let mut sum = 0.0;
    for subset in 0u32..(1 << n) {
        let corner: f64 = (0..n)
            .filter(|i| subset >> i & 1 == 1)
            .map(|i| widths[i])
            .sum();
        let r = s - corner;
        if r > 0.0 {
            let sign = if subset.count_ones() % 2 == 1 {
                -1.0
            } else {
                1.0
            };
            sum += sign * r.powi(n as i32 - 1);
        }
    }
    let factorial: f64 = (1..n).map(|k| k as f64).product();
    (sum / (factorial * widths.iter().product::<f64>())).max(0.0)
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on the Legendre recurrence).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 0 { 1.0 } else { p1 };
            let pm = if n <= 1 { 1.0 } else { p0 };
            dp = n as f64 * (z * pn - pm) / (z * z - 1.0);
            let dz = pn / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

impl Scene for ImageScene {
    fn name(&self) -> &'static str {
        "image"
    }
    fn summary(&self) -> &'static str {
        "32×32 image: plane, area light, moving occluder, square-aperture defocus, MIS, sky bounce with roulette (13 of 16 dims per pixel)"
    }
    fn slots(&self) -> &'static [Slot] {
        SLOTS
    }
    fn pixels(&self) -> usize {
        self.side * self.side
    }
    fn estimate(&self, pixel: usize, u: &[f64]) -> f64 {
        let w = self.pixel();
        let (c, v) = self.blur_and_motion();
        let (i, j) = ((pixel % self.side) as f64, (pixel / self.side) as f64);
        let p = [
            self.corner[0] + (i + u[0]) * w + c * (2.0 * u[2] - 1.0) - v * u[4],
            self.corner[1] + (j + u[1]) * w + c * (2.0 * u[3] - 1.0),
            0.0,
        ];
        let ch = ((u[5] * 3.0) as usize).min(2);
        let direct = self.room.direct_mis(p, [u[6], u[7]], [u[8], u[9]]);
        let sky = if u[10] < SURVIVAL && self.room.escapes(p, [u[11], u[12]]) {
            1.0 / SURVIVAL
        } else {
            0.0
        };
        // Picking the channel with probability 1/3 weights it by 3; the sky bounce's
        // cosine-sampled estimator of ρ/π ∫ S cos dω is ρ·S per escaping sample.
        3.0 * LUMINANCE[ch] * ALBEDO[ch] * (LIGHT[ch] / PI * direct + SKY[ch] * sky)
    }
    fn reference(&self, pixel: usize) -> f64 {
        self.reference[pixel]
    }
    fn reference_error(&self) -> f64 {
        // The tests hold the quadrature to a tenth of this against finer lattices.
        1e-5
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        for n in [1, 2, 4, 8] {
            let (x, w) = gauss_legendre(n);
            assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
            // Degree 2n − 1 is exact; ∫ x^k over [−1, 1] = 2/(k+1) for even k.
            let k = 2 * n - 2;
            let q: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(k as i32)).sum();
            assert!((q - 2.0 / (k as f64 + 1.0)).abs() < 1e-13, "n {n}: {q}");
        }
    }

    #[test]
    fn uniform_sum_densities_integrate_to_one_and_match_the_triangle() {
        // U[0,1) + U[0,1): the triangle, 1 at s = 1, 0.5 at s = 0.5.
        assert!((uniform_sum_density(1.0, &[1.0, 1.0]) - 1.0).abs() < 1e-15);
        assert!((uniform_sum_density(0.5, &[1.0, 1.0]) - 0.5).abs() < 1e-15);
        assert_eq!(uniform_sum_density(-0.1, &[1.0, 1.0]), 0.0);
        assert_eq!(uniform_sum_density(2.1, &[1.0, 1.0]), 0.0);
        let widths = [0.3, 0.7, 0.5];
        let m = 20_000;
        let total: f64 = (0..m)
            .map(|k| uniform_sum_density((k as f64 + 0.5) / m as f64 * 1.5, &widths))
            .sum::<f64>()
            * 1.5
            / m as f64;
        assert!((total - 1.0).abs() < 1e-6, "{total}");
    }
}
