//! 2-D L2-star in O(N log N), in exact integers.
//!
//! Σ_ij (1 − max(x_i, x_j))(1 − max(y_i, y_j)): sort by x; for point j, every earlier point i
//! has x_i ≤ x_j, so the x factor is (1 − x_j), and the y factors of the earlier points sum to
//! cnt(y_i ≤ y_j)·(1 − y_j) + Σ_{y_i > y_j}(1 − y_i), read from a Fenwick tree over the y
//! ranks holding counts and sums of (2^W − Y). Ties are harmless: max is symmetric.

use crate::exact::exact_rational;
use crate::rational::{c0, c1, int, to_f64};
use crate::{Discrepancy, Kind, Method, Points};
use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;

/// A Fenwick tree of (count, sum) over ranks.
struct Fenwick {
    count: Vec<u64>,
    sum: Vec<u128>,
}

impl Fenwick {
    fn new(n: usize) -> Self {
        Fenwick {
            count: vec![0; n + 1],
            sum: vec![0; n + 1],
        }
    }

    fn add(&mut self, rank: usize, v: u128) {
        let mut i = rank + 1;
        while i < self.count.len() {
            self.count[i] += 1;
            self.sum[i] += v;
            i += i & i.wrapping_neg();
        }
    }

    /// (count, sum) over ranks 0..=rank.
    fn prefix(&self, rank: usize) -> (u64, u128) {
        let (mut c, mut s, mut i) = (0u64, 0u128, rank + 1);
        while i > 0 {
            c += self.count[i];
            s += self.sum[i];
            i &= i - 1;
        }
        (c, s)
    }
}

/// The exact pair sum Σ_ij Π (2^W − max) for 2-D points.
fn pair_sum_2d(points: Points) -> BigUint {
    let (n, w) = (points.len(), points.width.bits());
    let one = 1u128 << w;
    let xs: Vec<u64> = (0..n).map(|i| points.point(i)[0]).collect();
    let ys: Vec<u64> = (0..n).map(|i| points.point(i)[1]).collect();
    // y ranks: equal values share a rank, so "≤" counts them.
    let mut sorted_y = ys.clone();
    sorted_y.sort_unstable();
    sorted_y.dedup();
    let rank = |y: u64| sorted_y.partition_point(|&v| v < y);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_unstable_by_key(|&i| xs[i]);
    let mut tree = Fenwick::new(sorted_y.len());
    let mut total_sum = 0u128;
    // u128 accumulators while they cannot overflow (W ≤ 32 and N ≤ 2^30 keep every term below
    // 2^105); otherwise, and on any checked overflow, the terms go to big integers.
    let (mut off_small, mut diag_small) = (0u128, 0u128);
    let (mut off_big, mut diag_big) = (BigUint::default(), BigUint::default());
    for &j in &order {
        let (xj, yj) = (one - xs[j] as u128, one - ys[j] as u128);
        let r = rank(ys[j]);
        let (le_count, le_sum) = tree.prefix(r);
        let greater = total_sum - le_sum;
        // Σ over earlier i of (2^W − max(y_i, y_j)), times (2^W − x_j).
        let small = (le_count as u128)
            .checked_mul(yj)
            .and_then(|v| v.checked_add(greater))
            .and_then(|inner| inner.checked_mul(xj))
            .and_then(|term| off_small.checked_add(term))
            .zip(xj.checked_mul(yj).and_then(|dg| diag_small.checked_add(dg)));
        match small {
            Some((o, d)) => (off_small, diag_small) = (o, d),
            None => {
                let inner = BigUint::from(le_count) * BigUint::from(yj) + BigUint::from(greater);
                off_big += inner * BigUint::from(xj);
                diag_big += BigUint::from(xj) * BigUint::from(yj);
            }
        }
        tree.add(r, yj);
        total_sum += yj;
    }
    let off = off_big + BigUint::from(off_small);
    let diag = diag_big + BigUint::from(diag_small);
    diag + (off << 1usize)
}

/// Exact 2-D L2-star D² in O(N log N); `None` unless the points are 2-D.
pub fn fast_l2star_2d_rational(points: Points) -> Option<BigRational> {
    if points.dims != 2 {
        return None;
    }
    let (n, w) = (points.len(), points.width.bits());
    let nn = BigInt::from(n as u64);
    // Σ_i (2^2W − X_i²)(2^2W − Y_i²): u128 products where they fit (W ≤ 32), carried into a
    // big integer; big integers otherwise.
    let mut s1 = BigUint::default();
    let mut acc = 0u128;
    for i in 0..n {
        let p = points.point(i);
        let one2 = 1u128.checked_shl(2 * w).unwrap_or(0);
        let small = (w <= 32)
            .then(|| (one2 - (p[0] as u128).pow(2)).checked_mul(one2 - (p[1] as u128).pow(2)))
            .flatten();
        match small {
            Some(v) => match acc.checked_add(v) {
                Some(a) => acc = a,
                None => {
                    s1 += BigUint::from(acc);
                    acc = v;
                }
            },
            None => s1 += Kind::L2Star.single_int(p[0], w).0 * Kind::L2Star.single_int(p[1], w).0,
        }
    }
    s1 += BigUint::from(acc);
    let t1 = c1(Kind::L2Star, 2) * BigRational::new(int(s1), &nn << (4 * w as usize));
    let t2 = BigRational::new(int(pair_sum_2d(points)), (&nn * &nn) << (2 * w as usize));
    Some(c0(Kind::L2Star, 2) + t1 + t2)
}

/// Exact 2-D L2-star by the fast path; `None` unless d = 2.
pub fn fast(points: Points) -> Option<Discrepancy> {
    let r = fast_l2star_2d_rational(points)?;
    Some(Discrepancy {
        kind: Kind::L2Star,
        method: Method::Fast,
        value: to_f64(&r),
        exact: Some(r),
        rel_error_bound: Some(0.0),
    })
}

/// The O(N²) exact value, for cross-checks of [`fast`].
pub fn quadratic_reference(points: Points) -> BigRational {
    exact_rational(points, Kind::L2Star)
}
