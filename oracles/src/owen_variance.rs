//! The exact variance, under nested uniform (Owen) scrambling, of the equal-weight estimator of
//! an elementary box's volume: the Haar-indicator case of Owen's gain-coefficient formula.
//!
//! **Derivation.** Let x_1..x_N be points with W-bit coordinates, base b = 2^q, and E a box
//! whose coordinate j is a b-adic interval of level k_j (its first k_j digits fixed), volume
//! b^-K with K = Σ k_j. The estimator is μ̂ = (1/N) Σ_i 1{σ(x_i) ∈ E}, σ an Owen scramble:
//! independent node permutations, uniform over S_b, independent across dimensions. Then
//!
//! ```text
//! Var μ̂ = (1/N²) Σ_{i,i'} P(σ(x_i) ∈ E, σ(x_i') ∈ E) − b^-2K.
//! ```
//!
//! For one coordinate, let γ be the number of leading base-b digits x_ij and x_i'j share. By
//! Owen's pair lemma (proved exactly in `proofs/Laws.v`, `pair_lemma`) the scrambled
//! coordinates share exactly γ digits, the shared digits uniform, and the first differing
//! digits an ordered pair of distinct digits, uniform. So both lie in E_j only if γ ≥ k_j, and
//! then with probability b^-k_j (the shared prefix is uniform). Dimensions are independent,
//! hence P(both in E) = b^-K · 1{x_i, x_i' in the same cell of shape k}: the cells being the
//! b^K boxes of shape (k_1..k_s). With n_c points of the set in cell c,
//!
//! ```text
//! Var μ̂ = b^-K · (Σ_c n_c²) / N² − b^-2K.
//! ```
//!
//! It is the same for every box of the shape, zero when every cell holds N·b^-K points (a
//! (0,m,s)-net and K ≤ m: the estimator is exact), and b^-K/N − b^-2K when every cell holds at
//! most one point (a (0,m,s)-net and K ≥ m). This is Owen's
//! Var = (1/N) Σ_{u,κ} Γ_{u,κ} σ²_{u,κ} with the Haar variance components of an indicator,
//! σ²_κ = (b − 1) b^(κ − 2k) for κ < k, summed in closed form.

use num_bigint::BigInt;
use num_rational::BigRational;
use std::collections::HashMap;

/// The exact Var μ̂ of the box-volume estimator for boxes of `shape` (levels k_j in base
/// 2^`q`), for the rows of `points` (each a point of `width_bits`-bit coordinates) under Owen
/// scrambling. `None` when a level needs more digits than the words hold or the set is empty.
pub fn owen_box_variance(
    points: &[Vec<u64>],
    width_bits: u32,
    q: u32,
    shape: &[u32],
) -> Option<BigRational> {
    let n = points.len();
    if n == 0 || shape.iter().any(|&k| k * q > width_bits) {
        return None;
    }
    let mut cells: HashMap<Vec<u64>, u64> = HashMap::new();
    for p in points {
        let key: Vec<u64> = p
            .iter()
            .zip(shape)
            .map(|(&x, &k)| if k == 0 { 0 } else { x >> (width_bits - k * q) })
            .collect();
        *cells.entry(key).or_insert(0) += 1;
    }
    let pairs: BigInt = cells.values().map(|&c| BigInt::from(c) * c).sum();
    let levels: u32 = shape.iter().sum();
    let b_k = BigInt::from(1) << (levels * q) as usize; // b^K
    let nn = BigInt::from(n) * n;
    let first = BigRational::new(pairs, &b_k * &nn);
    Some(first - BigRational::new(BigInt::from(1), &b_k * &b_k))
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::Zero;

    fn r(a: i64, b: i64) -> BigRational {
        BigRational::new(a.into(), b.into())
    }

    #[test]
    fn variance_of_simple_sets_by_hand() {
        // One point, one coordinate, level 1 in base 2: μ̂ ∈ {0, 1} with P = 1/2: Var = 1/4.
        assert_eq!(owen_box_variance(&[vec![0]], 8, 1, &[1]), Some(r(1, 4)));
        // Two points in different halves: exactly one lands in any half: Var = 0.
        assert_eq!(
            owen_box_variance(&[vec![0], vec![0x80]], 8, 1, &[1]).unwrap(),
            BigRational::zero()
        );
        // Two points in the same half: μ̂ ∈ {0, 1}, P = 1/2: Var = 1/4.
        assert_eq!(
            owen_box_variance(&[vec![0], vec![0x40]], 8, 1, &[1]),
            Some(r(1, 4))
        );
        // The same two points at level 2: they split at digit 2, so at most one lands in a
        // quarter; μ̂ = 1/2 with probability 1/4 + 1/4: Var = (1/4)(1/2) − 1/16 = 1/16.
        assert_eq!(
            owen_box_variance(&[vec![0], vec![0x40]], 8, 1, &[2]),
            Some(r(1, 16))
        );
        // Base 4 (q = 2), one point, level 1: Var = 1/4 − 1/16 = 3/16.
        assert_eq!(owen_box_variance(&[vec![0]], 8, 2, &[1]), Some(r(3, 16)));
        // Level 0 everywhere: the estimator is 1 exactly.
        assert_eq!(
            owen_box_variance(&[vec![3, 5]], 8, 1, &[0, 0]).unwrap(),
            BigRational::zero()
        );
        // Base 4: 0x00 and 0x40 differ in their first base-4 digit (00 | 01): Var = 1/16;
        // one level deeper in base 2 they would share it.
        assert_eq!(
            owen_box_variance(&[vec![0], vec![0x40]], 8, 2, &[1]),
            Some(r(1, 16))
        );
        assert_eq!(
            owen_box_variance(&[vec![0], vec![0x40]], 8, 1, &[1]),
            Some(r(1, 4))
        );
        // The deepest box the words allow (q·k = W) is accepted; one digit more is not.
        assert_eq!(
            owen_box_variance(&[vec![0]], 8, 2, &[4]),
            Some(r(255, 65536))
        );
        assert_eq!(owen_box_variance(&[vec![0]], 8, 3, &[3]), None);
    }
}
