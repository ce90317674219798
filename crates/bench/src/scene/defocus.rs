//! Pixel footprint × defocus × motion blur over an edge (5-D). A pixel of unit width sees a
//! half-plane edge through a square aperture while the edge moves along x during the shutter:
//! the point seen is y = p + c·(2l − 1) − v·t·e_x, and the pixel value is the fraction of
//! (p, l, t) with n·y ≥ d.
//!
//! n·y is a linear form in five independent uniforms, so the reference is a probability of a
//! weighted sum of uniforms: the volume of a hypercube cut by a hyperplane, computed exactly in
//! rationals from the f64 parameters.

use super::{Scene, Slot};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

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
];

/// The most nonzero terms [`probability_at_least`] takes (its cost is 2^terms rational
/// powers).
pub const MAX_TERMS: usize = 16;

/// P(Σ a_i U_i ≥ t) for independent uniforms U_i on [0, 1), exactly in rationals
/// (inclusion–exclusion over the cube's vertices: Vol{Σ b_i x_i ≤ s} =
/// Σ_S (−1)^|S| (s − Σ_S b)₊ⁿ / (n! Π b) for b_i > 0; negative coefficients are flipped,
/// U ↦ 1 − U, and zero ones dropped). `None` for non-finite input or more than
/// [`MAX_TERMS`] nonzero terms.
pub fn probability_at_least(coefficients: &[f64], threshold: f64) -> Option<f64> {
    let q = |x: f64| BigRational::from_float(x);
    let mut s = q(threshold)?;
    let mut b: Vec<BigRational> = Vec::new();
    for &a in coefficients {
        let a = q(a)?;
        if a.is_negative() {
            // a·U = a + |a|·(1 − U), and 1 − U is uniform too.
            s -= &a;
            b.push(-a);
        } else if !a.is_zero() {
            b.push(a);
        }
    }
    if b.len() > MAX_TERMS {
        return None;
    }
    let n = b.len();
    if n == 0 {
        return Some(if s.is_positive() { 0.0 } else { 1.0 });
    }
    let mut volume = BigRational::zero();
    for subset in 0u32..(1 << n) {
        let corner: BigRational = (0..n)
            .filter(|i| subset >> i & 1 == 1)
            .fold(BigRational::zero(), |acc, i| acc + &b[i]);
        let r = &s - corner;
        if r.is_positive() {
            let term = num_traits::pow(r, n);
            if subset.count_ones() % 2 == 1 {
                volume -= term;
            } else {
                volume += term;
            }
        }
    }
    let factorial: BigInt = (1..=n as u64).map(BigInt::from).product();
    let denominator = b
        .iter()
        .fold(BigRational::from_integer(factorial), |acc, x| acc * x);
    let below = volume / denominator;
    let below = below.clamp(BigRational::zero(), BigRational::one());
    (BigRational::one() - below).to_f64()
}

/// A pixel [0,1)² looking at the edge n·y ≥ d through a square aperture of half-width c
/// (in pixels at the edge's depth) while the edge moves v pixels along −x during the shutter.
#[derive(Debug, Clone, PartialEq)]
pub struct DefocusScene {
    /// Edge normal angle (radians from +x).
    pub angle: f64,
    /// Edge offset d.
    pub offset: f64,
    /// Aperture half-width c.
    pub blur: f64,
    /// Motion v over the shutter.
    pub motion: f64,
}

impl Default for DefocusScene {
    fn default() -> Self {
        DefocusScene {
            angle: 0.5,
            offset: 0.55,
            blur: 0.35,
            motion: 0.6,
        }
    }
}

impl DefocusScene {
    fn normal(&self) -> [f64; 2] {
        [self.angle.cos(), self.angle.sin()]
    }

    /// The linear form's coefficients on (p0, p1, l0, l1, t) and its threshold: n·y ≥ d with
    /// y = p + c(2l − 1) − v t e_x.
    pub fn linear_form(&self) -> ([f64; 5], f64) {
        let n = self.normal();
        let c = self.blur;
        (
            [
                n[0],
                n[1],
                2.0 * c * n[0],
                2.0 * c * n[1],
                -self.motion * n[0],
            ],
            self.offset + c * (n[0] + n[1]),
        )
    }
}

impl Scene for DefocusScene {
    fn name(&self) -> &'static str {
        "defocus"
    }
    fn summary(&self) -> &'static str {
        "pixel footprint × square-aperture defocus × motion blur over an edge (5-D)"
    }
    fn slots(&self) -> &'static [Slot] {
        SLOTS
    }
    fn estimate(&self, _pixel: usize, u: &[f64]) -> f64 {
        let n = self.normal();
        let c = self.blur;
        let y0 = u[0] + c * (2.0 * u[2] - 1.0) - self.motion * u[4];
        let y1 = u[1] + c * (2.0 * u[3] - 1.0);
        if n[0] * y0 + n[1] * y1 >= self.offset {
            1.0
        } else {
            0.0
        }
    }
    fn reference(&self, _pixel: usize) -> f64 {
        let (a, t) = self.linear_form();
        probability_at_least(&a, t).unwrap_or(f64::NAN)
    }
    fn reference_error(&self) -> f64 {
        // Exact rationals from the f64 form; the form itself carries a few ulps.
        1e-14
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_uniform_is_its_own_tail() {
        assert_eq!(probability_at_least(&[1.0], 0.25), Some(0.75));
        assert_eq!(probability_at_least(&[-1.0], -0.25), Some(0.25));
        assert_eq!(probability_at_least(&[2.0], 1.0), Some(0.5));
        assert_eq!(probability_at_least(&[0.0], 0.5), Some(0.0));
        assert_eq!(probability_at_least(&[1.0], 2.0), Some(0.0));
        assert_eq!(probability_at_least(&[1.0], -1.0), Some(1.0));
        assert_eq!(probability_at_least(&[f64::NAN], 0.0), None);
    }

    #[test]
    fn sums_of_uniforms_follow_irwin_hall() {
        // P(U1 + U2 ≥ 1.5) = 0.5²/2; P(U1 + U2 + U3 ≥ 1.5) = 1/2 by symmetry.
        assert_eq!(probability_at_least(&[1.0, 1.0], 1.5), Some(0.125));
        assert_eq!(probability_at_least(&[1.0, 1.0, 1.0], 1.5), Some(0.5));
        // P(U1 − U2 ≥ 0) = 1/2, P(U1 − U2 ≥ 0.5) = 1/8.
        assert_eq!(probability_at_least(&[1.0, -1.0], 0.0), Some(0.5));
        assert_eq!(probability_at_least(&[1.0, -1.0], 0.5), Some(0.125));
    }

    #[test]
    fn at_most_max_terms_nonzero_terms_are_taken() {
        // Sixteen halves: P(Σ U/2 ≥ 4) = 1/2 by symmetry; zero terms do not count.
        let mut a = vec![0.5; MAX_TERMS];
        a.push(0.0);
        assert_eq!(probability_at_least(&a, 4.0), Some(0.5));
        a.push(0.5);
        assert_eq!(probability_at_least(&a, 4.0), None);
    }

    #[test]
    fn the_linear_form_follows_the_geometry() {
        // n = (cos 0.5, sin 0.5); y = p + c(2l − 1) − v t e_x with c = 0.35, v = 0.6.
        let (a, t) = DefocusScene::default().linear_form();
        let (cs, sn) = (0.5f64.cos(), 0.5f64.sin());
        let expect = [cs, sn, 0.7 * cs, 0.7 * sn, -0.6 * cs];
        for (x, y) in a.iter().zip(expect) {
            assert!((x - y).abs() < 1e-15, "{a:?}");
        }
        assert!((t - (0.55 + 0.35 * (cs + sn))).abs() < 1e-15);
        // The estimator is the indicator of that form.
        let s = DefocusScene::default();
        for u in [
            [0.9, 0.9, 0.5, 0.5, 0.0],
            [0.1, 0.1, 0.5, 0.5, 1.0],
            [0.6, 0.3, 0.9, 0.2, 0.4],
        ] {
            let lhs: f64 = a.iter().zip(&u).map(|(a, u)| a * u).sum();
            assert_eq!(s.estimate(0, &u), if lhs >= t { 1.0 } else { 0.0 }, "{u:?}");
        }
    }

    #[test]
    fn the_scene_reference_is_a_proper_probability_away_from_0_and_1() {
        let r = DefocusScene::default().reference(0);
        assert!(r > 0.2 && r < 0.8, "{r}");
    }
}
