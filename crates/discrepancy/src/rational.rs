//! Exact rationals: the constants c0, and a correctly rounded (round-half-even) f64 conversion.

use crate::dd::Dd;
use crate::Kind;
use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// c0 of `kind` in d dimensions, exactly.
pub fn c0(kind: Kind, d: usize) -> BigRational {
    let (n, m, s) = kind.c0();
    let r = BigRational::new(BigInt::from(n).pow(d as u32), BigInt::from(m).pow(d as u32));
    if s < 0 {
        -r
    } else {
        r
    }
}

/// c1 of `kind` in d dimensions, exactly.
pub fn c1(kind: Kind, d: usize) -> BigRational {
    match kind {
        Kind::L2Star => -BigRational::new(BigInt::from(2), BigInt::one() << d),
        Kind::Centered | Kind::GeneralizedL2 => BigRational::from_integer(BigInt::from(-2)),
        Kind::WrapAround => BigRational::zero(),
    }
}

/// The relative error bound of `value`, the correctly rounded f64 of `r`: 0 when it is `r`
/// exactly, the unit roundoff 2^-53 when `r` lies in f64's normal range, and None outside it
/// (an overflow to ±inf or an underflow has no relative bound).
pub fn rounding_bound(r: &BigRational, value: f64) -> Option<f64> {
    if BigRational::from_float(value).is_some_and(|v| &v == r) {
        Some(0.0)
    } else if value.is_normal() {
        Some(f64::EPSILON / 2.0)
    } else {
        None
    }
}

/// The f64 nearest to `r` (ties to even) for |r| in the normal range; ±inf above it, and
/// below it a subnormal or zero (there the scaling may round twice).
pub fn to_f64(r: &BigRational) -> f64 {
    if r.is_zero() {
        return 0.0;
    }
    let (num, den) = (r.numer().magnitude(), r.denom().magnitude());
    // q = floor(|r|·2^s) with exactly 54 bits: 53 kept bits and one rounding bit.
    let quotient = |s: i64| -> (BigUint, BigUint) {
        let (n, d) = if s >= 0 {
            (num << s as usize, den.clone())
        } else {
            (num.clone(), den << (-s) as usize)
        };
        let q = &n / &d;
        let rem = n - &q * &d;
        (q, rem)
    };
    let mut s = 54 - (num.bits() as i64 - den.bits() as i64);
    let (mut q, mut rem) = quotient(s);
    while q.bits() > 54 {
        s -= 1;
        (q, rem) = quotient(s);
    }
    while q.bits() < 54 {
        s += 1;
        (q, rem) = quotient(s);
    }
    let q: u64 = (&q).try_into().expect("54 bits");
    let (mut mant, round_bit) = (q >> 1, q & 1);
    if round_bit == 1 && (!rem.is_zero() || mant & 1 == 1) {
        mant += 1;
    }
    // mant < 2^54, so the value is mant · 2^(1 − s); scale in two steps so that neither
    // factor overflows or underflows on its own.
    // The first product is exact whenever the result is normal; past the range the second
    // product gives inf, or rounds into the subnormals.
    let e = (1 - s).clamp(-4000, 4000) as i32;
    let magnitude = mant as f64 * 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
    if r.is_negative() {
        -magnitude
    } else {
        magnitude
    }
}

/// `r` as a double-double (hi = nearest f64, lo = nearest f64 of the remainder).
pub fn to_dd(r: &BigRational) -> Dd {
    let hi = to_f64(r);
    let Some(h) = BigRational::from_float(hi) else {
        // |r| overflows f64: there is nothing finite to refine.
        return Dd { hi, lo: 0.0 };
    };
    let rest = r - h;
    Dd {
        hi,
        lo: to_f64(&rest),
    }
}

/// A BigUint as a BigInt.
pub fn int(v: BigUint) -> BigInt {
    BigInt::from_biguint(Sign::Plus, v)
}
