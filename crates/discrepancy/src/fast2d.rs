//! 2-D L2-star in O(N log N), in exact integers.
//!
//! Σ_ij (1 − max(x_i, x_j))(1 − max(y_i, y_j)): sort by x; for a point j, every earlier point i
//! has x_i ≤ x_j, so the x factor is (1 − x_j), and the earlier points' y factors sum to
//! cnt(y_i ≤ y_j)·(1 − y_j) + Σ_{y_i > y_j}(1 − y_i). Those per-point counts and sums come from a
//! merge sort by y over the x order (divide and conquer): when the two sorted halves merge, each
//! right-half point sees the left-half points below and above it in one sequential sweep. Ties
//! are harmless: max is symmetric. Everything is in integers (words scaled by 2^W).

use crate::exact::exact_rational;
use crate::rational::{c0, c1, int, to_f64};
use crate::{Discrepancy, Kind, Method, Points};
use num_bigint::{BigInt, BigUint};
use num_rational::BigRational;

/// Exact sum of u128 terms: u128 until it would overflow, then carried into a big integer.
#[derive(Default)]
struct WideSum {
    small: u128,
    big: BigUint,
}

impl WideSum {
    fn add(&mut self, v: u128) {
        match self.small.checked_add(v) {
            Some(s) => self.small = s,
            None => {
                self.big += BigUint::from(self.small);
                self.small = v;
            }
        }
    }

    fn add_product(&mut self, a: u128, b: u128) {
        match a.checked_mul(b) {
            Some(p) => self.add(p),
            None => self.big += BigUint::from(a) * BigUint::from(b),
        }
    }

    fn total(self) -> BigUint {
        self.big + BigUint::from(self.small)
    }
}

/// A point in the sweep: its y word and its x weight 2^W − x.
#[derive(Clone, Copy)]
struct Item {
    y: u64,
    wx: u128,
}

/// The exact pair sum Σ_ij Π (2^W − max) for 2-D points.
fn pair_sum_2d(points: Points) -> BigUint {
    let (n, w) = (points.len(), points.width.bits());
    let one = 1u128 << w;
    let mut items: Vec<Item> = (0..n)
        .map(|i| {
            let p = points.point(i);
            Item {
                y: p[1],
                wx: one - p[0] as u128,
            }
        })
        .collect();
    // Order by x (the weight 2^W − x decreases with x).
    items.sort_unstable_by_key(|it| std::cmp::Reverse(it.wx));
    let mut diag = WideSum::default();
    for it in &items {
        diag.add_product(it.wx, one - it.y as u128);
    }
    let mut off = WideSum::default();
    let mut buf = items.clone();
    // Bottom-up merge sort by y; at each merge, left-half points precede right-half points in x.
    let mut width = 1;
    while width < n {
        let mut lo = 0;
        while lo < n {
            let mid = (lo + width).min(n);
            let hi = (lo + 2 * width).min(n);
            if mid < hi {
                merge_count(
                    &items[lo..mid],
                    &items[mid..hi],
                    &mut buf[lo..hi],
                    one,
                    &mut off,
                );
            } else {
                buf[lo..hi].copy_from_slice(&items[lo..hi]);
            }
            lo = hi;
        }
        std::mem::swap(&mut items, &mut buf);
        width *= 2;
    }
    diag.total() + (off.total() << 1usize)
}

/// Merges two y-sorted runs into `out`, adding Σ_{j in right} wx_j·(cnt_le·(2^W − y_j) + Σ_{i in
/// left, y_i > y_j}(2^W − y_i)) to `off`.
fn merge_count(left: &[Item], right: &[Item], out: &mut [Item], one: u128, off: &mut WideSum) {
    let left_total: u128 = left.iter().map(|i| one - i.y as u128).sum();
    let (mut a, mut k) = (0usize, 0usize);
    let mut le_sum = 0u128; // Σ over the left items already passed (y ≤ current y_j)
    for r in right {
        while a < left.len() && left[a].y <= r.y {
            le_sum += one - left[a].y as u128;
            out[k] = left[a];
            a += 1;
            k += 1;
        }
        let greater = left_total - le_sum;
        let inner = (a as u128) * (one - r.y as u128) + greater;
        off.add_product(r.wx, inner);
        out[k] = *r;
        k += 1;
    }
    out[k..].copy_from_slice(&left[a..]);
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
    let value = to_f64(&r);
    let bound = crate::rational::rounding_bound(&r, value);
    Some(Discrepancy {
        kind: Kind::L2Star,
        method: Method::Fast,
        value,
        exact: Some(r),
        rel_error_bound: bound,
    })
}

/// The O(N²) exact value, for cross-checks of [`fast`].
pub fn quadratic_reference(points: Points) -> BigRational {
    exact_rational(points, Kind::L2Star)
}
