//! Compensated evaluation: double-double accumulation over the symmetric half of the double
//! sum (Σ_ij = Σ_i p_ii + 2Σ_{i<j} p_ij), in parallel over fixed chunks of rows whose partial
//! sums are combined in chunk order, so the f64 result is bit-identical for any thread count.
//!
//! For d ≤ 4 each product is formed exactly in double-double; for larger d products are plain
//! f64 (at most d − 1 roundings each), which the error bound accounts for.

use crate::dd::Dd;
use crate::{Discrepancy, Kind, Method, Points};
use rayon::prelude::*;

/// Rows per parallel task: fixed, so the combination order never depends on threads.
const ROWS_PER_CHUNK: usize = 32;

/// Dimensions up to which products are formed exactly.
const EXACT_PRODUCT_DIMS: usize = 4;

/// The single factor in double-double: exact for coordinates of ≤ [`crate::EXACT_FLOAT_BITS`] bits (every part below is
/// an exact f64 and the one product is error-free).
#[inline(always)]
fn single_dd(kind: Kind, x: f64) -> Dd {
    match kind {
        Kind::L2Star => Dd::from(1.0 - x).mul_f64(1.0 + x), // 1 − x² = (1 − x)(1 + x)
        Kind::Centered => {
            let a = (x - 0.5).abs(); // 1 + a/2 − a²/2 = 1 + (a/2)(1 − a)
            Dd::from(0.5 * a).mul_f64(1.0 - a).add_f64(1.0)
        }
        Kind::WrapAround => Dd::from(1.0),
        Kind::GeneralizedL2 => Dd::from(x).mul_f64(-0.5 * x).add_f64(1.5), // (3 − x²)/2
    }
}

/// The pair factor in double-double (exact as above; only WD's t(1 − t) needs the product).
#[inline(always)]
fn pair_dd(kind: Kind, x: f64, y: f64) -> Dd {
    match kind {
        Kind::WrapAround => {
            let t = (x - y).abs();
            Dd::from(-t).mul_f64(1.0 - t).add_f64(1.5)
        }
        _ => Dd::from(kind.pair(x, y)),
    }
}

#[inline(always)]
fn product(kind: Kind, a: &[f64], b: &[f64], exact: bool) -> Dd {
    if exact {
        let mut p = pair_dd(kind, a[0], b[0]);
        for k in 1..a.len() {
            p = p.mul(pair_dd(kind, a[k], b[k]));
        }
        p
    } else {
        Dd::from(a.iter().zip(b).map(|(&x, &y)| kind.pair(x, y)).product())
    }
}

/// Columns per product block: products of a row with 256 later points are formed column by
/// column (vectorizable), summed pairwise in f64, and the block sum is added in double-double.
const BLOCK: usize = 256;

/// Pairwise sum (fixed tree, so deterministic); relative error ≤ ⌈log2 len⌉·ε.
fn pairwise(v: &[f64]) -> f64 {
    if v.len() <= 8 {
        v.iter().sum()
    } else {
        let h = v.len() / 2;
        pairwise(&v[..h]) + pairwise(&v[h..])
    }
}

/// Σ_{j > i} Π_k p(x_ik, x_jk) for d > EXACT_PRODUCT_DIMS, from column-major coordinates.
#[inline(always)]
fn off_diagonal_blocks(
    pair: impl Fn(f64, f64) -> f64,
    a: &[f64],
    cols: &[Vec<f64>],
    i: usize,
    n: usize,
    buf: &mut [f64; BLOCK],
) -> Dd {
    let mut off = Dd::default();
    let mut start = i + 1;
    while start < n {
        let len = BLOCK.min(n - start);
        let prod = &mut buf[..len];
        prod.fill(1.0);
        for (k, &ak) in a.iter().enumerate() {
            for (p, &y) in prod.iter_mut().zip(&cols[k][start..start + len]) {
                *p *= pair(ak, y);
            }
        }
        off = off.add_f64(pairwise(prod));
        start += len;
    }
    off
}

/// D² by compensated sums.
pub fn compensated(points: Points, kind: Kind) -> Discrepancy {
    let (n, d) = (points.len(), points.dims);
    let xs = points.to_f64();
    let exact_products = d <= EXACT_PRODUCT_DIMS;
    let cols: Vec<Vec<f64>> = if exact_products {
        Vec::new()
    } else {
        (0..d)
            .map(|k| (0..n).map(|j| xs[j * d + k]).collect())
            .collect()
    };
    let chunks = n.div_ceil(ROWS_PER_CHUNK);
    let partials: Vec<(Dd, Dd)> = (0..chunks)
        .into_par_iter()
        .map(|c| {
            let mut s1 = Dd::default();
            let mut s2 = Dd::default();
            for i in c * ROWS_PER_CHUNK..((c + 1) * ROWS_PER_CHUNK).min(n) {
                let a = &xs[i * d..(i + 1) * d];
                let single = if exact_products {
                    a.iter()
                        .skip(1)
                        .fold(single_dd(kind, a[0]), |p, &x| p.mul(single_dd(kind, x)))
                } else {
                    Dd::from(a.iter().map(|&x| kind.single(x)).product())
                };
                s1 = s1.add(single);
                let off = if exact_products {
                    let mut off = Dd::default();
                    for j in i + 1..n {
                        off = off.add(product(kind, a, &xs[j * d..(j + 1) * d], true));
                    }
                    off
                } else {
                    let mut buf = [0.0; BLOCK];
                    // One monomorphized loop per kind keeps the pair factor branch-free.
                    match kind {
                        Kind::L2Star => off_diagonal_blocks(
                            |x, y| Kind::L2Star.pair(x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                        Kind::Centered => off_diagonal_blocks(
                            |x, y| Kind::Centered.pair(x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                        Kind::WrapAround => off_diagonal_blocks(
                            |x, y| Kind::WrapAround.pair(x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                        Kind::GeneralizedL2 => off_diagonal_blocks(
                            |x, y| Kind::GeneralizedL2.pair(x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                    }
                };
                s2 = s2
                    .add(product(kind, a, a, exact_products))
                    .add(off.add(off));
            }
            (s1, s2)
        })
        .collect();
    let (mut s1, mut s2) = (Dd::default(), Dd::default());
    for (a, b) in partials {
        s1 = s1.add(a);
        s2 = s2.add(b);
    }
    let nf = n as f64;
    // c1·S1/N + S2/N² + c0, all in double-double. The divisions by N are double-double
    // divisions (exact remainder), not divisions of the parts: for N not a power of two a
    // rounded hi/N alone costs ε·|S1/N|, which the cancellation against c0 magnifies far
    // past the bound (seen at N = 24, 3-D: relative error 9e-15 against a claimed 1.1e-16).
    let t1 = s1.div_f64(nf).mul_f64(kind.c1(d));
    let t2 = s2.div_f64(nf).div_f64(nf);
    // c0 = (n/m)^d enters as a double-double from the exact rational: rounding it to one f64
    // would alone cost ~1e-17 absolute, far more than D² can afford.
    let c0 = crate::rational::to_dd(&crate::rational::c0(kind, d));
    let total = t1.add(t2).add(c0);
    let value = total.value();
    let scale = c0.hi.abs() + t1.hi.abs() + t2.hi.abs();
    let eps = f64::EPSILON;
    // Products: exact in double-double up to a few ε² (d ≤ 4), else ≤ d·ε relative each.
    // Double-double sums and the final combination: a few ε² of the scale. Then one rounding.
    let product_err = if exact_products {
        8.0 * eps * eps
    } else {
        d as f64 * eps
    };
    let abs_err = (product_err + 16.0 * eps * eps) * scale;
    let bound = abs_err / value.abs() + 0.5 * eps;
    Discrepancy {
        kind,
        method: Method::Compensated,
        value,
        exact: None,
        rel_error_bound: points.float_bound(value, bound),
    }
}
