//! Exact D²: the single and pair sums in exact integers (each factor is an integer over a
//! power of two), assembled into an exact rational. Rows run in parallel; integer sums are
//! exact, so the order does not matter.

use crate::limbs::{add_assign, add_shifted, mul_assign, to_biguint};
use crate::rational::{c0, c1, int, to_f64};
use crate::{Discrepancy, Kind, Method, Points};
use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;
use num_traits::One;
use rayon::prelude::*;

/// Σ_i Π_k S(X_ik) and its per-factor denominator exponent.
fn single_sum(points: Points, kind: Kind) -> (BigUint, u32) {
    let w = points.width.bits();
    let mut total = BigUint::default();
    let mut den = 0;
    for i in 0..points.len() {
        let mut prod = BigUint::one();
        for &x in points.point(i) {
            let (num, e) = kind.single_int(x, w);
            prod *= num;
            den = e;
        }
        total += prod;
    }
    (total, den)
}

/// Σ_i Σ_j Π_k P(X_ik, X_jk) over the symmetric half, and its per-factor denominator exponent.
fn pair_sum(points: Points, kind: Kind) -> (BigUint, u32) {
    let (n, w) = (points.len(), points.width.bits());
    let den = kind.pair_int(0, 0, w).1;
    let rows_per_task = 16;
    let partial: Vec<Vec<u64>> = (0..n.div_ceil(rows_per_task))
        .into_par_iter()
        .map(|c| {
            let (mut sum, mut acc, mut scratch) = (vec![0u64], Vec::new(), Vec::new());
            for i in c * rows_per_task..((c + 1) * rows_per_task).min(n) {
                let a = points.point(i);
                for j in i..n {
                    let b = points.point(j);
                    acc.clear();
                    acc.push(1);
                    for (&x, &y) in a.iter().zip(b) {
                        mul_assign(&mut acc, &kind.pair_int(x, y, w).0, &mut scratch);
                    }
                    // Off-diagonal pairs count twice (shift by one bit).
                    add_shifted(&mut sum, &acc, (j > i) as u32);
                }
            }
            sum
        })
        .collect();
    let mut total = vec![0u64];
    for p in partial {
        add_assign(&mut total, &p);
    }
    (to_biguint(&total), den)
}

/// The exact rational D² from the integer sums.
pub fn exact_rational(points: Points, kind: Kind) -> BigRational {
    let (n, d) = (points.len(), points.dims);
    let nn = BigInt::from(n as u64);
    let (s1, e1) = single_sum(points, kind);
    let (s2, e2) = pair_sum(points, kind);
    let t1 = c1(kind, d) * BigRational::new(int(s1), &nn << (e1 as usize * d));
    let t2 = BigRational::new(int(s2), (&nn * &nn) << (e2 as usize * d));
    c0(kind, d) + t1 + t2
}

/// D² exactly, with its correctly rounded f64.
pub fn exact(points: Points, kind: Kind) -> Discrepancy {
    let r = exact_rational(points, kind);
    let value = to_f64(&r);
    let bound = crate::rational::rounding_bound(&r, value);
    Discrepancy {
        kind,
        method: Method::Exact,
        value,
        exact: Some(r),
        rel_error_bound: bound,
    }
}
