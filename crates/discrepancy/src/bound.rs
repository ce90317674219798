//! The error bound of [`crate::compensated`], evaluated in exact rationals from the theorems
//! of `proofs/DdSum.v` (Coq + Flocq, binary64 with ties to even), and the run-time checks of
//! their hypotheses.
//!
//! The proof's pieces and where the code instantiates them (u = 2^-53):
//! * `dd_add_correct`: `Dd::add` of two non-negative normalized double-doubles errs by at most
//!   10u² of the exact sum; `dd_mul_correct`: `Dd::mul` by at most 20u² of the exact product,
//!   when hi·hi is 0 or at least 2^-900.
//! * `dd_sum_error` / `f64_sum_error`: additions in any order (a binary tree of depth h) over
//!   terms known within ρ are within (1 + ρ)(1 + δ)^h − 1, δ = 10u² (double-double) or u (f64).
//! * `dd_product_error` / `f64_product_error`: a left-to-right product of n factors known within
//!   φ, the first within K − 1, is within K((1 + φ)(1 + δ))^n − 1, δ = 20u² or u.
//! * `pow_gamma`: (1 + δ)^h ≤ 1/(1 − hδ), so no power is formed here.
//! * `to_computed` and `combine_error`: bounds on the exact sums become bounds on the computed
//!   ones, and D² = c0 + c1·S1/N + S2/N² is combined exactly in rationals, so the relative
//!   error of the returned f64 is (|value − Vq| + E)/(|Vq| − E).
//!
//! Not in Coq, argued here and checked by exact rationals in `crates/discrepancy/tests/exactness.rs`: which
//! factor computations are exact. For coordinates of at most [`crate::EXACT_FLOAT_BITS`] = 50
//! fractional bits every ingredient (1 − x, 1 + x, x − ½, |x − y|, 1 − max, CD's pair factor,
//! |x − y| − ½) is a multiple of 2^-51 below 4 in magnitude, hence a double, so the rounded
//! operation returns it exactly; the remaining factor errors are the proved ones below.

use crate::dd::Dd;
use crate::unreduced::Unreduced;
use crate::{Kind, Points};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// How the compensated sum is organized: what the depths and term counts of the proof are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Layout {
    /// Points N.
    pub n: usize,
    /// Dimensions d.
    pub d: usize,
    /// Products formed in double-double (d ≤ 4) rather than in f64.
    pub dd_products: bool,
    /// Rows per parallel chunk.
    pub rows_per_chunk: usize,
    /// Columns per f64 block sum (f64 products only).
    pub block: usize,
}

fn q(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

fn int(n: usize) -> BigRational {
    BigRational::from_integer(BigInt::from(n))
}

/// u = 2^-53, the unit roundoff of binary64.
fn unit() -> BigRational {
    BigRational::new(BigInt::one(), BigInt::one() << 53usize)
}

/// 1/(1 − nδ) ≥ (1 + δ)^n (`pow_gamma`), or None when nδ ≥ 1.
fn gamma(n: usize, delta: &BigRational) -> Option<BigRational> {
    let denom = BigRational::one() - int(n) * delta;
    denom.is_positive().then(|| denom.recip())
}

/// Depth of the f64 addition tree of `pairwise` over `len` values (`len` ≤ 8: a left fold
/// from −0.0, one addition per value).
pub(crate) fn pairwise_depth(len: usize) -> usize {
    if len <= 8 {
        len
    } else {
        let h = len / 2;
        1 + pairwise_depth(h).max(pairwise_depth(len - h))
    }
}

/// The relative factor errors φ the proof takes as input, per kind, for the double-double
/// factors and for the f64 pair factors.
struct FactorErrors {
    single_dd: BigRational,
    pair_dd: BigRational,
    pair_f64: BigRational,
}

fn factor_errors(kind: Kind) -> FactorErrors {
    let u = unit();
    let u2 = &u * &u;
    // dd_add(dd_mul(exact, exact), exact): a product within 20u² summed once (depth 1).
    let mul_then_add = (BigRational::one() + int(20) * &u2) * (BigRational::one() + int(10) * &u2)
        - BigRational::one();
    let zero = BigRational::zero();
    match kind {
        // 1 − max(x, y) exact; (1 − x)(1 + x) one dd_mul (≤ mul_then_add).
        Kind::L2Star => FactorErrors {
            single_dd: mul_then_add,
            pair_dd: zero.clone(),
            pair_f64: zero,
        },
        // CD's pair factor exact; 1 + (a/2)(1 − a) is mul then add.
        Kind::Centered => FactorErrors {
            single_dd: mul_then_add,
            pair_dd: zero.clone(),
            pair_f64: zero,
        },
        // 1.25 + (|x − y| − ½)²: in dd mul then add; in f64 two roundings of which the
        // product's is relative to c² ≤ F, so |f̂ − F| ≤ 2u·F (`wd_pair_f64_error`).
        Kind::WrapAround => FactorErrors {
            single_dd: zero,
            pair_dd: mul_then_add,
            pair_f64: int(2) * u,
        },
        // 2 − max exact; 1 + (½(1 − x))(1 + x) mul then add.
        Kind::GeneralizedL2 => FactorErrors {
            single_dd: mul_then_add,
            pair_dd: zero.clone(),
            pair_f64: zero,
        },
    }
}

/// Largest factor value of a kind (pair factors dominate singles): for the overflow check.
fn max_factor_log2_ceil(kind: Kind) -> usize {
    match kind {
        Kind::L2Star => 0,
        Kind::Centered | Kind::WrapAround => 1, // ≤ 1.5
        Kind::GeneralizedL2 => 1,               // ≤ 2
    }
}

/// The run-time hypotheses of the proved bound: exact coordinates (≤ 50 fractional bits), no
/// overflow (every sum and product below 2^1000) and no underflow in any product (every
/// double-double product step has hi·hi ≥ 2^-900, every f64 product ≥ 2^-1022). Factors are
/// at least f_lo = min(1, 1 − max x) (L2-star) or 1 (the other kinds), every running product
/// stays within a factor 2 of its exact value (ε ≤ ½ is checked with the bound), so
/// f_lo^d ≥ 2^-880 suffices.
pub(crate) fn hypotheses_hold(points: Points, kind: Kind) -> bool {
    if !points.exact_in_f64() {
        return false;
    }
    let (n, d) = (points.len(), points.dims);
    let log2_n = usize::BITS - n.leading_zeros(); // ≥ log2 N
    let overflow_bits = 2 * log2_n as usize + d.saturating_mul(max_factor_log2_ceil(kind)) + 4;
    if overflow_bits > 1000 {
        return false;
    }
    let underflow_bits_per_factor = match kind {
        Kind::L2Star => {
            // 1 − x_max = m·2^-W with m ≥ 1: log2(1/(1 − x_max)) ≤ W − floor(log2 m).
            let w = points.width.bits();
            let max = points.words.iter().copied().max().unwrap_or(0);
            let m = if w == 64 {
                (u64::MAX - max) as u128 + 1
            } else {
                (1u128 << w) - max as u128
            };
            (w - (127 - m.leading_zeros())) as usize
        }
        _ => 0,
    };
    d.saturating_mul(underflow_bits_per_factor) <= 880
}

/// Relative error bounds (ε1, ε2) of the computed S1 = Σ_i Π s and S2 = Σ_ij Π p against the
/// exact sums of the true factors, for this layout; None when a γ does not exist or an ε
/// exceeds ½ (outside the hypotheses).
pub(crate) fn sum_bounds(kind: Kind, l: Layout) -> Option<(BigRational, BigRational)> {
    let u = unit();
    let u2 = &u * &u;
    let one = BigRational::one();
    let (add_dd, mul_dd) = (int(10) * &u2, int(20) * &u2);
    let phi = factor_errors(kind);
    let chunks = l.n.div_ceil(l.rows_per_chunk);
    // Singles: d dd factors, the first one the chain's start (K = 1 + φ), then d − 1 dd_mul.
    let rho_single = gamma(l.d, &phi.single_dd)? * gamma(l.d - 1, &mul_dd)? - &one;
    let (rho_pairs, off_depth) = if l.dd_products {
        let rho = gamma(l.d, &phi.pair_dd)? * gamma(l.d - 1, &mul_dd)? - &one;
        (rho, l.n) // off = a left fold of ≤ N − 1 products from 0
    } else {
        // f64 products from 1.0 (K = 1): d factors, d roundings.
        let term = gamma(l.d, &phi.pair_f64)? * gamma(l.d, &u)? - &one;
        let h_block = (1..=l.block).map(pairwise_depth).max().unwrap_or(0);
        let block = (&one + &term) * gamma(h_block, &u)? - &one;
        (block.max(term), l.n.div_ceil(l.block))
    };
    // s1: a fold of ≤ rows_per_chunk singles per chunk, then a fold over the chunks.
    let h1 = l.rows_per_chunk + chunks + 1;
    // s2: per row (s2 + diag) + (off + off); rows per chunk, then the chunks.
    let h2 = 2 * l.rows_per_chunk + off_depth + chunks + 3;
    let eps1 = (&one + rho_single) * gamma(h1, &add_dd)? - &one;
    let eps2 = (&one + rho_pairs) * gamma(h2, &add_dd)? - &one;
    let half = BigRational::new(BigInt::one(), BigInt::from(2));
    (eps1 <= half && eps2 <= half).then_some((eps1, eps2))
}

/// What [`combine`] needs of one (kind, layout) besides the sums: c0, c1 and the factors
/// ε/(1 − ε) of `to_computed` for S1 and S2 (None where [`sum_bounds`] is None). A pure
/// function of its key, computed in exact rationals and kept in the form `combine` uses.
#[derive(Debug)]
pub(crate) struct LayoutConstants {
    c0: Unreduced,
    c1: Unreduced,
    to_computed: Option<(Unreduced, Unreduced)>,
}

/// Layouts whose constants are kept: replicate runs (a mean D² over seeds) ask for one layout
/// thousands of times, and the rationals of its bound cost more than the sums at small N.
const KNOWN_LAYOUTS: usize = 64;

/// [`LayoutConstants`] of `(kind, l)`, computed once and kept (at most [`KNOWN_LAYOUTS`]; when
/// full, the oldest is dropped). The values do not depend on what is kept, so results are
/// bit-identical either way.
pub(crate) fn layout_constants(kind: Kind, l: Layout) -> std::sync::Arc<LayoutConstants> {
    use std::sync::{Arc, Mutex};
    type Known = Vec<((Kind, Layout), Arc<LayoutConstants>)>;
    static KNOWN: Mutex<Known> = Mutex::new(Vec::new());
    let key = (kind, l);
    let lock = || KNOWN.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, c)) = lock().iter().find(|(k, _)| *k == key) {
        return c.clone();
    }
    let one = BigRational::one();
    let factor = |eps: BigRational| Unreduced::of(&(&eps / (&one - &eps)));
    let computed = Arc::new(LayoutConstants {
        c0: Unreduced::of(&crate::rational::c0(kind, l.d)),
        c1: Unreduced::of(&crate::rational::c1(kind, l.d)),
        to_computed: (l.n > 0 && l.d > 0)
            .then(|| sum_bounds(kind, l))
            .flatten()
            .map(|(e1, e2)| (factor(e1), factor(e2))),
    });
    let mut known = lock();
    if known.len() >= KNOWN_LAYOUTS {
        known.remove(0);
    }
    known.push((key, computed.clone()));
    computed
}

/// D² combined exactly from the computed sums, and its proved relative error bound
/// (`combine_error`), rounded up to f64; the bound is None when E ≥ |Vq|, or when
/// `bounded` is false (the run-time hypotheses do not hold) or the layout has no ε.
pub(crate) fn combine(
    kind: Kind,
    constants: &LayoutConstants,
    bounded: bool,
    n: usize,
    d: usize,
    s1: Dd,
    s2: Dd,
) -> (f64, Option<f64>) {
    if n == 0 {
        return (f64::NAN, None); // D² of no points is undefined (0/0)
    }
    let (c0, c1) = (&constants.c0, &constants.c1);
    if ![s1.hi, s1.lo, s2.hi, s2.lo].iter().all(|x| x.is_finite()) {
        // The sums overflowed (outside the hypotheses): the f64 combination, no bound.
        let nf = n as f64;
        let value =
            crate::rational::to_f64(&c0.to_ratio()) + kind.c1(d) * s1.hi / nf + s2.hi / nf / nf;
        return (value, None);
    }
    // Exact, without a gcd per step (the values are those of the reduced rationals).
    let (nn, n2) = (Unreduced::int(n), Unreduced::int(n).mul(&Unreduced::int(n)));
    let dyadic = |x: f64| Unreduced::of(&q(x));
    let s1q = dyadic(s1.hi).add(&dyadic(s1.lo));
    let s2q = dyadic(s2.hi).add(&dyadic(s2.lo));
    let vq = c0.add(&c1.mul(&s1q).div(&nn)).add(&s2q.div(&n2));
    let value = crate::rational::to_f64(&vq.to_ratio());
    let Some((k1, k2)) = constants.to_computed.as_ref().filter(|_| bounded) else {
        return (value, None);
    };
    if !value.is_finite() {
        return (value, None);
    }
    // to_computed: |Ŝ − S| ≤ ε/(1 − ε)·Ŝ.
    let e1 = k1.mul(&s1q.abs());
    let e2 = k2.mul(&s2q.abs());
    let e = c1.abs().mul(&e1).div(&nn).add(&e2.div(&n2));
    if e >= vq.abs() {
        return (value, None);
    }
    let rel = dyadic(value).sub(&vq).abs().add(&e).div(&vq.abs().sub(&e));
    (value, Some(round_up(&rel.to_ratio())))
}

/// The smallest f64 at or above the non-negative rational `r`.
fn round_up(r: &BigRational) -> f64 {
    let f = crate::rational::to_f64(r);
    if f.is_finite() && &q(f) < r {
        f.next_up()
    } else {
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairwise_depth_counts_the_longest_chain() {
        assert_eq!(pairwise_depth(1), 1);
        assert_eq!(pairwise_depth(8), 8);
        assert_eq!(pairwise_depth(9), 6); // 4 + 5 values: 1 + max(4, 5)
        assert_eq!(pairwise_depth(16), 9);
        assert_eq!(pairwise_depth(256), 13);
        assert_eq!((1..=256).map(pairwise_depth).max(), Some(13));
    }

    #[test]
    fn gamma_bounds_the_power() {
        let d = BigRational::new(BigInt::one(), BigInt::from(100));
        let g = gamma(10, &d).unwrap();
        let mut p = BigRational::one();
        for _ in 0..10 {
            p *= BigRational::one() + &d;
        }
        assert!(p <= g && g < &p * BigRational::new(BigInt::from(101), BigInt::from(100)));
        assert!(gamma(100, &d).is_none());
        assert!(gamma(99, &d).is_some());
    }

    #[test]
    fn round_up_never_rounds_down() {
        let third = BigRational::new(BigInt::one(), BigInt::from(3));
        let f = round_up(&third);
        assert!(q(f) >= third && q(f.next_down()) < third);
        let exact = q(0.375);
        assert_eq!(round_up(&exact), 0.375);
    }

    fn pow(x: &BigRational, n: usize) -> BigRational {
        (0..n).fold(BigRational::one(), |p, _| p * x)
    }

    /// The bound evaluated with the theorems' powers, (1 + ρ)(1 + δ)^h − 1 and
    /// K((1 + φ)(1 + δ))^n − 1, for the same layout: the γ form used by the code must be at or
    /// above it (sound) and within 1% of its excess (not loose).
    fn power_form(kind: Kind, l: Layout) -> (BigRational, BigRational) {
        let (u, one) = (unit(), BigRational::one());
        let u2 = &u * &u;
        let (add, mul) = (int(10) * &u2, int(20) * &u2);
        let phi = factor_errors(kind);
        let chunks = l.n.div_ceil(l.rows_per_chunk);
        let chain = |phi: &BigRational, delta: &BigRational, n: usize, k: BigRational| {
            k * pow(&((&one + phi) * (&one + delta)), n) - &one
        };
        let single = chain(&phi.single_dd, &mul, l.d - 1, &one + &phi.single_dd);
        let (pairs, off) = if l.dd_products {
            (chain(&phi.pair_dd, &mul, l.d - 1, &one + &phi.pair_dd), l.n)
        } else {
            let term = chain(&phi.pair_f64, &u, l.d, one.clone());
            let block = (&one + &term) * pow(&(&one + &u), 13) - &one;
            (block.max(term), l.n.div_ceil(l.block))
        };
        let h1 = l.rows_per_chunk + chunks + 1;
        let h2 = 2 * l.rows_per_chunk + off + chunks + 3;
        (
            (&one + single) * pow(&(&one + &add), h1) - &one,
            (&one + pairs) * pow(&(&one + &add), h2) - &one,
        )
    }

    #[test]
    fn the_gamma_form_is_the_proved_power_bound_rounded_up_slightly() {
        for (n, d, dd) in [
            (64, 3, true),
            (100, 1, true),
            (50, 7, false),
            (300, 16, false),
        ] {
            for kind in Kind::ALL {
                let l = Layout {
                    n,
                    d,
                    dd_products: dd,
                    rows_per_chunk: 32,
                    block: 256,
                };
                let (e1, e2) = sum_bounds(kind, l).unwrap();
                let (p1, p2) = power_form(kind, l);
                for (e, p) in [(&e1, &p1), (&e2, &p2)] {
                    assert!(e >= p, "{kind:?} n = {n}, d = {d}: {e} < {p}");
                    let slack = BigRational::new(BigInt::from(101), BigInt::from(100));
                    assert!(e <= &(p * slack), "{kind:?} n = {n}, d = {d}");
                }
            }
        }
    }
}
