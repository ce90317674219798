//! The expected L2-star D² under nested uniform (Owen) scrambling of a binary digital net.
//!
//! Derivation (`docs/design.md` §5). Write D*² = 3^-d − (2^(1−d)/N)·A + (1/N²)·P with
//! A = Σ_i Π_k (1 − x_ik²) and P = Σ_ij Π_k (1 − max(x_ik, x_jk)).
//!
//! After a nested uniform scramble each point is uniform on [0,1)^d, so E[1 − x²] = 2/3 and the
//! A term contributes −2^(1−d)·(2/3)^d = −2·3^-d. The diagonal of P gives (1/N)·E[Π(1 − x)] =
//! 2^-d/N. For i ≠ j, write h = x_i ⊕ x_j. A coordinate with h_k ≠ 0 agrees on exactly
//! r = lz(h_k) leading bits; after scrambling the two values are uniform on the two halves of a
//! common dyadic interval of length 2^-r, so E[1 − max] = 1/2 − 2^(−r−2). A coordinate with
//! h_k = 0 has equal values, uniform on [0,1), so E[1 − max] = E[1 − x] = 1/2. For a digital
//! net the multiset {x_i ⊕ x_j : j} is the net itself, so the off-diagonal part is
//! N·Σ over the net's points h ≠ 0. Altogether
//!
//! E\[D*²\] = −3^-d + 2^-d/N + (1/N)·Σ_{h ≠ 0} Π_k (1/2 − 2^(−lz(h_k)−2)),
//!
//! with a zero coordinate contributing 1/2.

use crate::Points;

/// The per-coordinate factor E[1 − max] for coordinates differing first at bit lz (h ≠ 0).
#[inline]
fn factor(h: u64, w: u32) -> f64 {
    if h == 0 {
        0.5
    } else {
        let lz = h.leading_zeros() - (64 - w);
        0.5 - 2f64.powi(-(lz as i32) - 2)
    }
}

/// E\[D*²\] for the N points of a binary digital net (closed under XOR), O(N·d).
pub fn expected_l2star_owen(net: Points) -> f64 {
    let (n, d, w) = (net.len(), net.dims, net.width.bits());
    let mut sum = 0.0;
    for i in 0..n {
        let p = net.point(i);
        if p.iter().all(|&x| x == 0) {
            continue;
        }
        sum += p.iter().map(|&h| factor(h, w)).product::<f64>();
    }
    -(3f64.powi(-(d as i32))) + 2f64.powi(-(d as i32)) / n as f64 + sum / n as f64
}

/// E\[D*²\] for `n` independent uniform points in \[0,1)^`dims` (the random-points baseline
/// of the paper's figures): every point is uniform, and two distinct points are independent,
/// so E\[Π(1 − max)\] = 3^-d off the diagonal and 2^-d on it, which leaves
/// E\[D*²\] = (2^-d − 3^-d) / N. `n` = 0 gives infinity.
///
/// ```
/// use gartowen_discrepancy::expected::expected_l2star_random;
/// assert!((expected_l2star_random(10, 1) - 1.0 / 60.0).abs() < 1e-15); // (1/2 − 1/3)/10
/// ```
pub fn expected_l2star_random(n: usize, dims: u32) -> f64 {
    let d = dims as i32;
    (2f64.powi(-d) - 3f64.powi(-d)) / n as f64
}

#[cfg(test)]
mod random_tests {
    use super::*;
    use crate::Points;
    use gartowen_core::{SplitMix64, Width};

    #[test]
    fn the_random_baseline_matches_an_average_over_random_sets() {
        // 4,000 sets of 8 uniform 32-bit points in 3-D: the sample mean of the compensated D²
        // lies within 4 standard errors of (2^-3 − 3^-3)/8 (false alarm ~6e-5); a formula off
        // by 20% is outside.
        let (n, d) = (8usize, 3usize);
        let mut rng = SplitMix64::new(77);
        let values: Vec<f64> = (0..4000)
            .map(|_| {
                let words: Vec<u64> = (0..n * d).map(|_| rng.next_u64() >> 32).collect();
                let p = Points {
                    words: &words,
                    dims: d,
                    width: Width::W32,
                };
                crate::compensated::compensated(p, crate::Kind::L2Star).value
            })
            .collect();
        let (mean, se) = crate::curves::mean_and_se(&values);
        let expect = expected_l2star_random(n, d as u32);
        assert!(
            (mean - expect).abs() < 4.0 * se,
            "{mean} ± {se} vs {expect}"
        );
        assert!(
            (mean - 1.2 * expect).abs() > 4.0 * se,
            "a 20% error is seen: {se}"
        );
        assert!(expected_l2star_random(0, 2).is_infinite());
    }
}
