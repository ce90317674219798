//! Power spectra of 2-D point sets: P(f) = |Σⱼ exp(−2πi f·xⱼ)|² / N on the integer frequency
//! grid f ∈ [−F, F]² (the paper's Figure 1 spectra). P(0) = N; for independent uniform points
//! E P(f) = 1 at every f ≠ 0, so values well below 1 near the origin are the blue-noise-like
//! gap that nets show.

/// The spectrum on the (2F+1)² grid, row-major with f₁ (second coordinate) as the row:
/// entry `(f1 + F) * (2F + 1) + (f0 + F)`.
///
/// ```
/// let p = gartowen_bench::spectrum::power_spectrum(&[[0.0, 0.0], [0.5, 0.5]], 1);
/// assert_eq!(p.len(), 9);
/// assert!((p[4] - 2.0).abs() < 1e-12); // P(0) = N
/// ```
pub fn power_spectrum(points: &[[f64; 2]], max_freq: usize) -> Vec<f64> {
    let f = max_freq as i64;
    let side = (2 * f + 1) as usize;
    // Separable phases e^{−2πi k x} per point and frequency, point-major: row j holds the
    // `side` frequencies of point j (real and imaginary parts apart).
    let phases = |coord: usize| -> (Vec<f64>, Vec<f64>) {
        let (mut re, mut im) = (
            Vec::with_capacity(points.len() * side),
            Vec::with_capacity(points.len() * side),
        );
        for p in points {
            for k in -f..=f {
                let a = -2.0 * std::f64::consts::PI * k as f64 * p[coord];
                re.push(a.cos());
                im.push(a.sin());
            }
        }
        (re, im)
    };
    let ((c0, s0), (c1, s1)) = (phases(0), phases(1));
    let n = points.len() as f64;
    let mut out = vec![0.0; side * side];
    // For each row f₁, every column's sum runs over the points in order (the same bits as a
    // sum per entry); the columns advance together, so the inner loop is contiguous.
    let (mut re, mut im) = (vec![0.0; side], vec![0.0; side]);
    for r in 0..side {
        re.iter_mut().for_each(|v| *v = 0.0);
        im.iter_mut().for_each(|v| *v = 0.0);
        for j in 0..points.len() {
            let (b0, b1) = (c1[j * side + r], s1[j * side + r]);
            let row = j * side..(j + 1) * side;
            for (((re, im), &a0), &a1) in re
                .iter_mut()
                .zip(im.iter_mut())
                .zip(&c0[row.clone()])
                .zip(&s0[row])
            {
                *re += a0 * b0 - a1 * b1;
                *im += a0 * b1 + a1 * b0;
            }
        }
        for c in 0..side {
            out[r * side + c] = (re[c] * re[c] + im[c] * im[c]) / n;
        }
    }
    out
}

/// Radially averaged spectrum: the mean of P over frequencies with ⌊|f| + ½⌋ = k, for
/// k = 1..=F (the DC term is left out).
pub fn radial_average(spectrum: &[f64], max_freq: usize) -> Vec<f64> {
    let f = max_freq as i64;
    let side = (2 * f + 1) as usize;
    let mut sum = vec![0.0; max_freq + 1];
    let mut count = vec![0usize; max_freq + 1];
    for r in 0..side {
        for c in 0..side {
            let (x, y) = (c as i64 - f, r as i64 - f);
            let k = ((x * x + y * y) as f64).sqrt().round() as usize;
            if (1..=max_freq).contains(&k) {
                sum[k] += spectrum[r * side + c];
                count[k] += 1;
            }
        }
    }
    (1..=max_freq).map(|k| sum[k] / count[k] as f64).collect()
}

/// The mean periodogram of several point sets (the same grid as [`power_spectrum`]): one
/// realisation's spectrum is noise around its expectation, the mean over seeds shows the
/// expectation (for independent uniform points, 1 at every f ≠ 0).
///
/// ```
/// use gartowen_bench::spectrum::{mean_power_spectrum, power_spectrum};
/// let (a, b) = (vec![[0.1, 0.2], [0.7, 0.4]], vec![[0.3, 0.9], [0.5, 0.5]]);
/// let m = mean_power_spectrum(&[a.clone(), b.clone()], 2);
/// let (pa, pb) = (power_spectrum(&a, 2), power_spectrum(&b, 2));
/// assert!(m.iter().zip(pa.iter().zip(&pb)).all(|(m, (x, y))| (m - (x + y) / 2.0).abs() < 1e-12));
/// ```
pub fn mean_power_spectrum(sets: &[Vec<[f64; 2]>], max_freq: usize) -> Vec<f64> {
    use rayon::prelude::*;
    let side = 2 * max_freq + 1;
    let spectra: Vec<Vec<f64>> = sets
        .par_iter()
        .map(|s| power_spectrum(s, max_freq))
        .collect();
    // Summed in set order: the same bits for any thread count.
    let mut sum = vec![0.0; side * side];
    for spectrum in &spectra {
        for (acc, v) in sum.iter_mut().zip(spectrum) {
            *acc += v;
        }
    }
    let k = sets.len().max(1) as f64;
    sum.iter_mut().for_each(|v| *v /= k);
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen::core::SplitMix64;

    /// The direct definition, one complex exponential per point and frequency.
    fn direct(points: &[[f64; 2]], f0: i64, f1: i64) -> f64 {
        let (mut re, mut im) = (0.0, 0.0);
        for p in points {
            let a = -2.0 * std::f64::consts::PI * (f0 as f64 * p[0] + f1 as f64 * p[1]);
            re += a.cos();
            im += a.sin();
        }
        (re * re + im * im) / points.len() as f64
    }

    #[test]
    fn the_columns_together_give_the_bits_of_one_sum_per_entry() {
        // One entry at a time, the points in order: the evaluation's own products and sums.
        let mut rng = SplitMix64::new(8);
        let pts: Vec<[f64; 2]> = (0..77).map(|_| [rng.next_f64(), rng.next_f64()]).collect();
        let f = 5i64;
        let phase = |k: i64, x: f64| {
            let a = -2.0 * std::f64::consts::PI * k as f64 * x;
            (a.cos(), a.sin())
        };
        let p = power_spectrum(&pts, f as usize);
        for f1 in -f..=f {
            for f0 in -f..=f {
                let (mut re, mut im) = (0.0, 0.0);
                for q in &pts {
                    let ((a0, a1), (b0, b1)) = (phase(f0, q[0]), phase(f1, q[1]));
                    re += a0 * b0 - a1 * b1;
                    im += a0 * b1 + a1 * b0;
                }
                let at = ((f1 + f) * (2 * f + 1) + f0 + f) as usize;
                assert_eq!(p[at].to_bits(), ((re * re + im * im) / 77.0).to_bits());
            }
        }
    }

    #[test]
    fn separable_evaluation_matches_the_definition_and_is_symmetric() {
        let mut rng = SplitMix64::new(5);
        let pts: Vec<[f64; 2]> = (0..100).map(|_| [rng.next_f64(), rng.next_f64()]).collect();
        let p = power_spectrum(&pts, 6);
        let side = 13;
        for r in 0..side {
            for c in 0..side {
                let want = direct(&pts, c as i64 - 6, r as i64 - 6);
                assert!((p[r * side + c] - want).abs() < 1e-9 * want.max(1.0));
                // P(f) = P(−f) for real points.
                let mirror = p[(side - 1 - r) * side + (side - 1 - c)];
                assert!((p[r * side + c] - mirror).abs() < 1e-9 * mirror.max(1.0));
            }
        }
        assert!((p[6 * side + 6] - 100.0).abs() < 1e-9);
    }

    #[test]
    fn a_regular_grid_cancels_every_frequency_below_its_period() {
        // 8×8 grid: Σ e^{−2πi f·x} vanishes unless both f components are multiples of 8.
        let pts: Vec<[f64; 2]> = (0..64)
            .map(|k| [(k % 8) as f64 / 8.0, (k / 8) as f64 / 8.0])
            .collect();
        let p = power_spectrum(&pts, 9);
        for r in 0..19i64 {
            for c in 0..19i64 {
                let (x, y) = (c - 9, r - 9);
                let v = p[(r * 19 + c) as usize];
                if x % 8 == 0 && y % 8 == 0 {
                    assert!((v - 64.0).abs() < 1e-9, "{x},{y}: {v}");
                } else {
                    assert!(v < 1e-20, "{x},{y}: {v}");
                }
            }
        }
        let radial = radial_average(&p, 9);
        assert!(radial[..7].iter().all(|v| *v < 1e-20));
    }
}
