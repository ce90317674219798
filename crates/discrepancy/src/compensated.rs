//! Compensated evaluation: double-double accumulation over the symmetric half of the double
//! sum (Σ_ij = Σ_i p_ii + 2Σ_{i<j} p_ij), in parallel over fixed chunks of rows whose partial
//! sums are combined in chunk order, so the f64 result is bit-identical for any thread count.
//!
//! For d ≤ 4 each product is formed in double-double; for larger d products are plain f64 (d
//! roundings each), summed in blocks by f64 pairwise sums and the blocks in double-double.
//! Every addition and product sees non-negative operands, the case `proofs/DdSum.v` proves;
//! `crate::bound` evaluates that theorem's bound for exactly this summation order, after
//! checking its hypotheses at run time, and the final combination is exact in rationals.

use crate::bound::{self, Layout};
use crate::dd::Dd;
use crate::{Discrepancy, Kind, Method, Points};
use rayon::prelude::*;

/// Rows per parallel task: fixed, so the combination order never depends on threads.
const ROWS_PER_CHUNK: usize = 32;

/// Dimensions up to which products are formed exactly.
const EXACT_PRODUCT_DIMS: usize = 4;

/// The single factor in double-double. Every double-double operation sees non-negative
/// normalized operands, the case `proofs/DdSum.v` bounds; the f64 ingredients are exact for
/// coordinates of ≤ [`crate::EXACT_FLOAT_BITS`] bits (see [`crate::bound`]).
#[inline(always)]
fn single_dd(kind: Kind, x: f64) -> Dd {
    match kind {
        Kind::L2Star => Dd::from(1.0 - x).mul(Dd::from(1.0 + x)), // 1 − x² = (1 − x)(1 + x)
        Kind::Centered => {
            let a = (x - 0.5).abs(); // 1 + a/2 − a²/2 = 1 + (a/2)(1 − a)
            Dd::from(0.5 * a).mul(Dd::from(1.0 - a)).add(Dd::from(1.0))
        }
        Kind::WrapAround => Dd::from(1.0),
        // (3 − x²)/2 = 1 + (½(1 − x))(1 + x)
        Kind::GeneralizedL2 => Dd::from(0.5 * (1.0 - x))
            .mul(Dd::from(1.0 + x))
            .add(Dd::from(1.0)),
    }
}

/// WD's pair factor 3/2 − t(1 − t) in the form 5/4 + (t − ½)², whose terms are non-negative.
#[inline(always)]
fn wd_center(x: f64, y: f64) -> f64 {
    ((x - y).abs() - 0.5).abs()
}

/// The pair factor in double-double (exact as an f64 except WD's square).
#[inline(always)]
fn pair_dd(kind: Kind, x: f64, y: f64) -> Dd {
    match kind {
        Kind::WrapAround => {
            let c = Dd::from(wd_center(x, y));
            c.mul(c).add(Dd::from(1.25))
        }
        _ => Dd::from(kind.pair(x, y)),
    }
}

/// The pair factor in f64 for the products of d > 4 (WD: two roundings, within 2u).
#[inline(always)]
fn pair_f64(kind: Kind, x: f64, y: f64) -> f64 {
    match kind {
        Kind::WrapAround => {
            let c = wd_center(x, y);
            1.25 + c * c
        }
        _ => kind.pair(x, y),
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
        Dd::from(
            a.iter()
                .zip(b)
                .map(|(&x, &y)| pair_f64(kind, x, y))
                .product(),
        )
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
        off = off.add(Dd::from(pairwise(prod)));
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
                let single = a
                    .iter()
                    .skip(1)
                    .fold(single_dd(kind, a[0]), |p, &x| p.mul(single_dd(kind, x)));
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
                            |x, y| pair_f64(Kind::L2Star, x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                        Kind::Centered => off_diagonal_blocks(
                            |x, y| pair_f64(Kind::Centered, x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                        Kind::WrapAround => off_diagonal_blocks(
                            |x, y| pair_f64(Kind::WrapAround, x, y),
                            a,
                            &cols,
                            i,
                            n,
                            &mut buf,
                        ),
                        Kind::GeneralizedL2 => off_diagonal_blocks(
                            |x, y| pair_f64(Kind::GeneralizedL2, x, y),
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
    let layout = Layout {
        n,
        d,
        dd_products: exact_products,
        rows_per_chunk: ROWS_PER_CHUNK,
        block: BLOCK,
    };
    let bounded = n > 0 && bound::hypotheses_hold(points, kind);
    let constants = bound::layout_constants(kind, layout);
    let (value, rel_error_bound) = bound::combine(kind, &constants, bounded, n, d, s1, s2);
    Discrepancy {
        kind,
        method: Method::Compensated,
        value,
        exact: None,
        rel_error_bound,
    }
}

/// The second path for the factor claims the proof takes as hypotheses (`bound.rs`): at
/// coordinates of ≤ 50 bits, the f64 pair factors of L2-star, CD and GL2 are exact, WD's is
/// within 2u, and every double-double factor is within (1 + 20u²)(1 + 10u²) − 1, checked
/// against the exact integer factors of [`Kind::single_int`] and [`Kind::pair_int`].
#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::SplitMix64;
    use num_bigint::BigUint;
    use num_rational::BigRational;
    use num_traits::Signed;

    fn q(x: f64) -> BigRational {
        BigRational::from_float(x).expect("finite")
    }

    fn ratio(num: BigUint, den: u32) -> BigRational {
        BigRational::new(num.into(), (BigUint::from(1u8) << den as usize).into())
    }

    fn pair_exact(kind: Kind, x: u64, y: u64) -> BigRational {
        let (limbs, den) = kind.pair_int(x, y, 50);
        let num = BigUint::from(limbs[0])
            + (BigUint::from(limbs[1]) << 64usize)
            + (BigUint::from(limbs[2]) << 128usize);
        ratio(num, den)
    }

    /// 50-bit coordinates: the edges (0, ½ ± 2^-50, 1 − 2^-50, …) and random ones.
    fn coordinates() -> Vec<u64> {
        let top = 1u64 << 50;
        let mut v = vec![
            0,
            1,
            2,
            top / 4,
            top / 2 - 1,
            top / 2,
            top / 2 + 1,
            top - 2,
            top - 1,
        ];
        let mut rng = SplitMix64::new(9);
        v.extend((0..60).map(|_| rng.next_u64() >> 14));
        v
    }

    fn to_f64(x: u64) -> f64 {
        x as f64 * 2f64.powi(-50)
    }

    #[test]
    fn factors_at_fifty_bit_coordinates_are_within_their_stated_errors() {
        let u = q(f64::EPSILON / 2.0);
        let phi_dd = (q(1.0) + q(20.0) * &u * &u) * (q(1.0) + q(10.0) * &u * &u) - q(1.0);
        let xs = coordinates();
        for kind in Kind::ALL {
            for &x in &xs {
                let (num, den) = kind.single_int(x, 50);
                let exact = ratio(num, den);
                let s = single_dd(kind, to_f64(x));
                assert!(
                    s.hi >= 0.0 && s.lo.abs() <= s.hi * f64::EPSILON,
                    "{kind:?} {x}"
                );
                let err = (q(s.hi) + q(s.lo) - &exact).abs();
                assert!(err <= &phi_dd * &exact, "{kind:?} single at {x}");
                for &y in &xs {
                    let exact = pair_exact(kind, x, y);
                    let (fx, fy) = (to_f64(x), to_f64(y));
                    let f = q(pair_f64(kind, fx, fy));
                    let p = pair_dd(kind, fx, fy);
                    let dd_err = (q(p.hi) + q(p.lo) - &exact).abs();
                    if kind == Kind::WrapAround {
                        assert!((f - &exact).abs() <= q(2.0) * &u * &exact, "WD at {x}, {y}");
                        assert!(dd_err <= &phi_dd * &exact, "WD dd at {x}, {y}");
                    } else {
                        assert_eq!(f, exact, "{kind:?} f64 pair at {x}, {y}");
                        assert_eq!(p, Dd::from(pair_f64(kind, fx, fy)));
                    }
                }
            }
        }
    }

    #[test]
    fn cd_pair_factor_rounds_past_fifty_bits() {
        // Two 53-bit coordinates (the first random pair tried): the sum 1 + |x − ½|/2 + …
        // needs more than 53 bits, so the f64 factor rounds; 50 bits keep it exact.
        let (x, y): (f64, f64) = (
            f64::from_bits(0x3fe236eb2265b1f5),
            f64::from_bits(0x3fe9ac27d8f16adf),
        );
        let half = q(0.5);
        let exact = q(1.0) + (q(x) - &half).abs() / q(2.0) + (q(y) - &half).abs() / q(2.0)
            - (q(x) - q(y)).abs() / q(2.0);
        assert_ne!(q(pair_f64(Kind::Centered, x, y)), exact);
    }

    /// The proof (`wd_pair_f64_error`) is about the operation sequence 1.25 + c·c with
    /// c = ||x − y| − ½|, not about WD's textbook 1.5 − t(1 − t), which rounds differently.
    #[test]
    fn wd_f64_pair_factor_is_the_proved_operation_sequence() {
        let xs = coordinates();
        let mut differs = 0;
        for &x in &xs {
            for &y in &xs {
                let (fx, fy) = (to_f64(x), to_f64(y));
                let c = ((fx - fy).abs() - 0.5).abs();
                let proved = 1.25 + c * c;
                assert_eq!(
                    pair_f64(Kind::WrapAround, fx, fy).to_bits(),
                    proved.to_bits()
                );
                differs += (Kind::WrapAround.pair(fx, fy) != proved) as usize;
            }
        }
        assert!(
            differs > 0,
            "the two forms should round differently somewhere"
        );
    }
}
