//! Power spectra of 2-D point sets: P(f) = |Σⱼ exp(−2πi f·xⱼ)|² / N on the integer frequency
//! grid f ∈ [−F, F]² (the paper's Figure 1 spectra). P(0) = N; for independent uniform points
//! E P(f) = 1 at every f ≠ 0, so values well below 1 near the origin are the blue-noise-like
//! gap that nets show.

/// The phases e^{−2πi k x} of one coordinate of a point set at the frequencies k = −F..=F,
/// point-major: entry `j * (2F + 1) + (k + F)` is point j at frequency k. Computed once per
/// coordinate, they serve every pair that coordinate is part of.
#[derive(Debug, Clone, PartialEq)]
pub struct Phases {
    re: Vec<f64>,
    im: Vec<f64>,
    max_freq: usize,
}

impl Phases {
    /// The phases of `coords` (one coordinate of each point, in [0, 1)) for |k| ≤ `max_freq`.
    /// The negative frequencies are the conjugates of the positive ones, as e^{2πi k x} is.
    pub fn new(coords: impl IntoIterator<Item = f64>, max_freq: usize) -> Self {
        let f = max_freq;
        let side = 2 * f + 1;
        let coords = coords.into_iter();
        let (mut re, mut im) = (
            Vec::with_capacity(coords.size_hint().0 * side),
            Vec::with_capacity(coords.size_hint().0 * side),
        );
        let (mut cos, mut sin) = (vec![0.0; f + 1], vec![0.0; f + 1]);
        for x in coords {
            for k in 0..=f {
                let a = -2.0 * std::f64::consts::PI * k as f64 * x;
                (sin[k], cos[k]) = a.sin_cos();
            }
            re.extend(cos[1..].iter().rev());
            im.extend(sin[1..].iter().rev().map(|v| -v));
            re.extend(&cos);
            im.extend(&sin);
        }
        Phases { re, im, max_freq }
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.re.len() / (2 * self.max_freq + 1)
    }

    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.re.is_empty()
    }
}

/// The spectrum on the (2F+1)² grid, row-major with f₁ (second coordinate) as the row:
/// entry `(f1 + F) * (2F + 1) + (f0 + F)`.
///
/// ```
/// let p = gartowen_bench::spectrum::power_spectrum(&[[0.0, 0.0], [0.5, 0.5]], 1);
/// assert_eq!(p.len(), 9);
/// assert!((p[4] - 2.0).abs() < 1e-12); // P(0) = N
/// ```
pub fn power_spectrum(points: &[[f64; 2]], max_freq: usize) -> Vec<f64> {
    pair_spectrum(
        &Phases::new(points.iter().map(|p| p[0]), max_freq),
        &Phases::new(points.iter().map(|p| p[1]), max_freq),
    )
}

/// The spectrum of the points whose coordinates have the phases `x` (f₀, the columns) and
/// `y` (f₁, the rows), on the grid of [`power_spectrum`].
///
/// # Panics
/// When `x` and `y` differ in their number of points or frequencies.
pub fn pair_spectrum(x: &Phases, y: &Phases) -> Vec<f64> {
    assert_eq!(
        x.max_freq, y.max_freq,
        "phases of different frequency grids"
    );
    assert_eq!(x.len(), y.len(), "phases of different point sets");
    let f = x.max_freq;
    let side = 2 * f + 1;
    let n = x.len() as f64;
    let mut out = vec![0.0; side * side];
    // For each row f₁ ≥ 0, every column's sum runs over the points in order (the same bits as
    // a sum per entry); the columns advance together, so the inner loop is contiguous. The rows
    // f₁ < 0 are the mirror images P(−f) = P(f): with conjugate phases every product and sum
    // is the exact negation of its mirror's, so the mirror is the same bits.
    let (mut re, mut im) = (vec![0.0; side], vec![0.0; side]);
    for r in f..side {
        re.iter_mut().for_each(|v| *v = 0.0);
        im.iter_mut().for_each(|v| *v = 0.0);
        for j in 0..x.len() {
            let (b0, b1) = (y.re[j * side + r], y.im[j * side + r]);
            let row = j * side..(j + 1) * side;
            for (((re, im), &a0), &a1) in re
                .iter_mut()
                .zip(im.iter_mut())
                .zip(&x.re[row.clone()])
                .zip(&x.im[row])
            {
                *re += a0 * b0 - a1 * b1;
                *im += a0 * b1 + a1 * b0;
            }
        }
        for c in 0..side {
            let p = (re[c] * re[c] + im[c] * im[c]) / n;
            out[r * side + c] = p;
            out[(side - 1 - r) * side + (side - 1 - c)] = p;
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
    if sets.is_empty() {
        let side = 2 * max_freq + 1;
        return vec![0.0; side * side];
    }
    let columns: Vec<Vec<Vec<f64>>> = sets
        .iter()
        .map(|s| (0..2).map(|d| s.iter().map(|p| p[d]).collect()).collect())
        .collect();
    mean_pair_spectra(&columns, max_freq)
        .swap_remove(0)
        .swap_remove(1)
}

/// The mean periodogram of every pair of coordinates (a, b), a < b, over several point sets:
/// `sets[s][d]` is coordinate d of set s's points, every set with the same number of
/// coordinates. Entry `[a][b]` is the mean over the sets of [`pair_spectrum`] of coordinates a
/// (columns) and b (rows), the same bits as [`mean_power_spectrum`] of those pairs; entries
/// with a ≥ b are empty. Each coordinate's phases are computed once per set.
///
/// ```
/// use gartowen_bench::spectrum::{mean_pair_spectra, mean_power_spectrum};
/// let sets = vec![vec![vec![0.1, 0.7], vec![0.2, 0.4], vec![0.9, 0.3]]];
/// let all = mean_pair_spectra(&sets, 2);
/// let pair_0_2 = mean_power_spectrum(&[vec![[0.1, 0.9], [0.7, 0.3]]], 2);
/// assert_eq!(all[0][2], pair_0_2);
/// assert!(all[2][0].is_empty());
/// ```
///
/// # Panics
/// When the sets differ in their number of coordinates or points.
pub fn mean_pair_spectra(sets: &[Vec<Vec<f64>>], max_freq: usize) -> Vec<Vec<Vec<f64>>> {
    use rayon::prelude::*;
    let side = 2 * max_freq + 1;
    let dims = sets.first().map_or(0, Vec::len);
    assert!(
        sets.iter().all(|s| s.len() == dims),
        "point sets with different numbers of coordinates"
    );
    let pairs: Vec<(usize, usize)> = (0..dims)
        .flat_map(|a| (a + 1..dims).map(move |b| (a, b)))
        .collect();
    let mut sums = vec![vec![0.0; side * side]; pairs.len()];
    for set in sets {
        let phases: Vec<Phases> = set
            .par_iter()
            .map(|c| Phases::new(c.iter().copied(), max_freq))
            .collect();
        let spectra: Vec<Vec<f64>> = pairs
            .par_iter()
            .map(|&(a, b)| pair_spectrum(&phases[a], &phases[b]))
            .collect();
        // Summed in set order: the same bits for any thread count.
        for (sum, spectrum) in sums.iter_mut().zip(&spectra) {
            for (acc, v) in sum.iter_mut().zip(spectrum) {
                *acc += v;
            }
        }
    }
    let k = sets.len().max(1) as f64;
    let mut out = vec![vec![Vec::new(); dims]; dims];
    for ((a, b), mut sum) in pairs.into_iter().zip(sums) {
        sum.iter_mut().for_each(|v| *v /= k);
        out[a][b] = sum;
    }
    out
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
    fn every_pair_of_the_shared_phases_is_the_spectrum_of_that_pair_alone() {
        // Four coordinates of three sets of 50 points: each pair's mean from the phases
        // computed once per coordinate has the bits of the mean over the 2-D point sets.
        let mut rng = SplitMix64::new(11);
        let sets: Vec<Vec<Vec<f64>>> = (0..3)
            .map(|_| {
                (0..4)
                    .map(|_| (0..50).map(|_| rng.next_f64()).collect())
                    .collect()
            })
            .collect();
        let all = mean_pair_spectra(&sets, 4);
        for a in 0..4 {
            for b in 0..4 {
                if a >= b {
                    assert!(all[a][b].is_empty());
                    continue;
                }
                let pairs: Vec<Vec<[f64; 2]>> = sets
                    .iter()
                    .map(|s| s[a].iter().zip(&s[b]).map(|(x, y)| [*x, *y]).collect())
                    .collect();
                let want = mean_power_spectrum(&pairs, 4);
                // And against the definition, one set at a time.
                let direct_mean =
                    |f0: i64, f1: i64| pairs.iter().map(|p| direct(p, f0, f1)).sum::<f64>() / 3.0;
                assert_eq!(all[a][b], want, "pair ({a}, {b})");
                for r in 0..9 {
                    for c in 0..9 {
                        let d = direct_mean(c as i64 - 4, r as i64 - 4);
                        assert!((want[r * 9 + c] - d).abs() < 1e-9 * d.max(1.0));
                    }
                }
            }
        }
        assert_eq!(mean_power_spectrum(&[], 3), vec![0.0; 49]);
    }

    #[test]
    fn negative_frequencies_are_the_conjugates_and_the_mirror_is_exact() {
        let mut rng = SplitMix64::new(3);
        let xs: Vec<f64> = (0..20).map(|_| rng.next_f64()).collect();
        let ph = Phases::new(xs.iter().copied(), 5);
        assert_eq!(ph.len(), 20);
        for (j, x) in xs.iter().enumerate() {
            for k in -5i64..=5 {
                let at = j * 11 + (k + 5) as usize;
                let a = -2.0 * std::f64::consts::PI * k as f64 * x;
                assert!((ph.re[at] - a.cos()).abs() < 1e-15 && (ph.im[at] - a.sin()).abs() < 1e-15);
                let mirror = j * 11 + (5 - k) as usize;
                assert_eq!(ph.re[at], ph.re[mirror]);
                assert_eq!(ph.im[at], -ph.im[mirror]);
            }
        }
        let ys: Vec<f64> = (0..20).map(|_| rng.next_f64()).collect();
        let p = pair_spectrum(&ph, &Phases::new(ys, 5));
        for (i, v) in p.iter().enumerate() {
            assert_eq!(v.to_bits(), p[120 - i].to_bits());
        }
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
