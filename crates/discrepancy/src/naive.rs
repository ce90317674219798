//! Plain f64: the full double sum with ordinary accumulation (what common tools do).

use crate::{Discrepancy, Kind, Method, Points};

/// D² in plain f64 over all N² pairs.
pub fn naive(points: Points, kind: Kind) -> Discrepancy {
    let (n, d) = (points.len(), points.dims);
    let xs = points.to_f64();
    let mut s1 = 0.0;
    let mut s2 = 0.0;
    for i in 0..n {
        let a = &xs[i * d..(i + 1) * d];
        s1 += a.iter().map(|&x| kind.single(x)).product::<f64>();
        for j in 0..n {
            let b = &xs[j * d..(j + 1) * d];
            s2 += a
                .iter()
                .zip(b)
                .map(|(&x, &y)| kind.pair(x, y))
                .product::<f64>();
        }
    }
    let nf = n as f64;
    let value = kind.c0_f64(d) + kind.c1(d) * s1 / nf + s2 / (nf * nf);
    // Bound: every term has relative error ≤ γ_(N²+d+3); the terms, not D², set the scale.
    let gamma = |k: f64| k * f64::EPSILON / (1.0 - k * f64::EPSILON);
    let scale = kind.c0_f64(d).abs() + kind.c1(d).abs() * s1 / nf + s2 / (nf * nf);
    let bound = gamma((n * n + d + 3) as f64) * scale / value.abs();
    Discrepancy {
        kind,
        method: Method::Naive,
        value,
        exact: None,
        rel_error_bound: points.float_bound(value, bound),
    }
}
