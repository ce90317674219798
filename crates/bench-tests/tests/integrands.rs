//! Every exact integral against an independent Monte Carlo estimate, and hand-computable
//! half-plane areas.
//!
//! The Monte Carlo check: N = 2^20 independent uniform points (SplitMix64, fixed seed); the
//! exact value must lie within 5 estimated standard errors of the mean. The two-sided
//! false-alarm rate per comparison is 5.7e-7 (normal approximation, valid at this N for these
//! bounded integrands), so about 1e-5 over the ~25 comparisons. The same check rejects every
//! exact value moved by 2% of its magnitude (at least 0.005), which shows it can fail.

use gartowen::core::SplitMix64;
use gartowen_bench::integrands::{
    half_plane_area, standard_families, Genz, GenzKind, Heaviside, Integrand,
};

/// (mean, standard error) of f over n uniform points.
fn monte_carlo(f: &dyn Integrand, n: usize, seed: u64) -> (f64, f64) {
    let mut rng = SplitMix64::new(seed);
    let d = f.dims();
    let mut x = vec![0.0; d];
    let (mut s, mut s2) = (0.0, 0.0);
    for _ in 0..n {
        for v in x.iter_mut() {
            *v = rng.next_f64();
        }
        let y = f.eval(&x);
        s += y;
        s2 += y * y;
    }
    let mean = s / n as f64;
    let var = (s2 / n as f64 - mean * mean).max(0.0);
    (mean, (var / n as f64).sqrt())
}

fn agrees(exact: f64, mc: (f64, f64)) -> bool {
    (exact - mc.0).abs() <= 5.0 * mc.1 + 1e-12
}

#[test]
fn exact_integrals_agree_with_monte_carlo_and_wrong_ones_do_not() {
    let n = 1 << 20;
    for fam in standard_families(4) {
        for r in 0..if fam.name() == "heaviside" { 4 } else { 1 } {
            let f = fam.instance(r);
            let mc = monte_carlo(f.as_ref(), n, 77 + r);
            let exact = f.exact();
            assert!(
                agrees(exact, mc),
                "{} (instance {r}): exact {exact}, Monte Carlo {} ± {}",
                fam.name(),
                mc.0,
                mc.1
            );
            let wrong = exact + (0.02 * exact.abs()).max(0.005);
            assert!(
                !agrees(wrong, mc),
                "{}: the check cannot tell {wrong} from {exact} (σ = {})",
                fam.name(),
                mc.1
            );
        }
    }
}

#[test]
fn half_plane_areas_by_hand() {
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    // x ≥ 0.3: a 0.7 × 1 rectangle.
    assert!(close(half_plane_area([1.0, 0.0], [0.3, 0.5]), 0.7));
    // y ≤ 0.25 (normal pointing down).
    assert!(close(half_plane_area([0.0, -1.0], [0.9, 0.25]), 0.25));
    // Any line through the centre halves the square.
    for k in 0..16 {
        let t = k as f64 * 0.39;
        assert!(close(half_plane_area([t.cos(), t.sin()], [0.5, 0.5]), 0.5));
    }
    // x + y ≥ 1.8: the corner triangle with legs 0.2.
    let s = 0.5f64.sqrt();
    assert!(close(half_plane_area([s, s], [0.9, 0.9]), 0.02));
    // Complementary half-planes tile the square.
    let (n, p) = ([0.3, -0.8], [0.2, 0.7]);
    assert!(close(
        half_plane_area(n, p) + half_plane_area([-0.3, 0.8], p),
        1.0
    ));
    let h = Heaviside::new(n, p);
    assert!(close(h.exact(), half_plane_area(n, p)));
}

#[test]
fn genz_closed_forms_in_one_dimension_match_quadrature() {
    // A second path for the closed forms: composite Simpson on 1-D instances (smooth except
    // at u, so the interval is split at u; the right piece starts just past u, where the
    // discontinuous family is already 0).
    for kind in GenzKind::ALL {
        let g = Genz {
            kind,
            a: vec![3.0],
            u: vec![0.35],
        };
        let simpson = |lo: f64, hi: f64| {
            let m = 20_000;
            let h = (hi - lo) / m as f64;
            let f = |x: f64| g.eval(&[x]);
            let mut s = f(lo) + f(hi);
            for i in 1..m {
                s += f(lo + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
            }
            s * h / 3.0
        };
        let q = simpson(0.0, 0.35) + simpson(0.35 + 1e-13, 1.0);
        assert!(
            (q - g.exact()).abs() < 1e-9,
            "{kind:?}: quadrature {q}, closed form {}",
            g.exact()
        );
    }
}
