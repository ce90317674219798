//! The four kinds: constants, f64 factors, and the same factors as integer numerators.
//!
//! For a coordinate x = X/2^W the single factor s(x) = S(X)/2^(σW+a) and the pair factor
//! p(x, y) = P(X, Y)/2^(πW+b) with integer numerators S, P (exponents per kind below).

use serde::Serialize;

/// A discrepancy kind (all computed squared).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// L2-star (Warnock): 3^-d − (2^(1−d)/N)Σ Π(1 − x²) + (1/N²)ΣΣ Π(1 − max(x, y)).
    L2Star,
    /// Centered: (13/12)^d − (2/N)Σ Π(1 + |x−½|/2 − |x−½|²/2)
    ///   + (1/N²)ΣΣ Π(1 + |x−½|/2 + |y−½|/2 − |x−y|/2).
    Centered,
    /// Wrap-around: −(4/3)^d + (1/N²)ΣΣ Π(3/2 − |x−y|(1 − |x−y|)).
    WrapAround,
    /// Generalized L2 (Hickernell): (4/3)^d − (2/N)Σ Π((3 − x²)/2) + (1/N²)ΣΣ Π(2 − max(x, y)).
    GeneralizedL2,
}

impl Kind {
    /// Every kind.
    pub const ALL: [Kind; 4] = [
        Kind::L2Star,
        Kind::Centered,
        Kind::WrapAround,
        Kind::GeneralizedL2,
    ];

    /// Command-line name.
    pub fn name(self) -> &'static str {
        Kind::NAMES[self as usize]
    }

    /// Parses a command-line name.
    pub fn parse(s: &str) -> Option<Kind> {
        s.parse().ok()
    }

    /// The command-line names of [`Kind::ALL`], in that order.
    pub const NAMES: [&'static str; 4] = ["l2star", "cd", "wd", "gl2"];

    /// (c0 numerator base, c0 denominator base, sign): c0 = sign·(num/den)^d.
    pub fn c0(self) -> (u64, u64, i64) {
        match self {
            Kind::L2Star => (1, 3, 1),
            Kind::Centered => (13, 12, 1),
            Kind::WrapAround => (4, 3, -1),
            Kind::GeneralizedL2 => (4, 3, 1),
        }
    }

    /// c1, the coefficient of (1/N)Σ Π s: L2-star −2^(1−d); CD and GL2 −2; WD 0.
    pub fn c1(self, d: usize) -> f64 {
        match self {
            Kind::L2Star => -(2f64.powi(1 - d as i32)),
            Kind::Centered | Kind::GeneralizedL2 => -2.0,
            Kind::WrapAround => 0.0,
        }
    }

    /// c0 as f64.
    pub fn c0_f64(self, d: usize) -> f64 {
        let (n, m, s) = self.c0();
        s as f64 * (n as f64 / m as f64).powi(d as i32)
    }

    /// The single factor s(x).
    #[inline(always)]
    pub fn single(self, x: f64) -> f64 {
        match self {
            Kind::L2Star => 1.0 - x * x,
            Kind::Centered => {
                let a = (x - 0.5).abs();
                1.0 + 0.5 * a - 0.5 * a * a
            }
            Kind::WrapAround => 1.0,
            Kind::GeneralizedL2 => 0.5 * (3.0 - x * x),
        }
    }

    /// The pair factor p(x, y).
    #[inline(always)]
    pub fn pair(self, x: f64, y: f64) -> f64 {
        match self {
            Kind::L2Star => 1.0 - x.max(y),
            Kind::Centered => {
                1.0 + 0.5 * (x - 0.5).abs() + 0.5 * (y - 0.5).abs() - 0.5 * (x - y).abs()
            }
            Kind::WrapAround => {
                let t = (x - y).abs();
                1.5 - t * (1.0 - t)
            }
            Kind::GeneralizedL2 => 2.0 - x.max(y),
        }
    }

    /// Single factor as (numerator, log2 denominator) for a W-bit word X: s = num / 2^den.
    /// Numerators have up to 2W + 3 bits, so they are big integers (only N of them are formed).
    pub fn single_int(self, x: u64, w: u32) -> (num_bigint::BigUint, u32) {
        use num_bigint::BigUint;
        let (x, one) = (BigUint::from(x), BigUint::from(1u8) << w as usize);
        let one2 = &one * &one;
        match self {
            // (2^2W − X²)/2^2W
            Kind::L2Star => (one2 - &x * &x, 2 * w),
            // a = |X − 2^(W−1)|: (2·2^2W + a·2^W − a²)/(2·2^2W)
            Kind::Centered => {
                let half = &one >> 1usize;
                let a = if x >= half { &x - &half } else { &half - &x };
                (one2 * 2u8 + &a * &one - &a * &a, 2 * w + 1)
            }
            Kind::WrapAround => (BigUint::from(1u8), 0),
            // (3·2^2W − X²)/(2·2^2W)
            Kind::GeneralizedL2 => (one2 * 3u8 - &x * &x, 2 * w + 1),
        }
    }

    /// Pair factor as (numerator limbs, log2 denominator): p = num / 2^den. The numerator can
    /// exceed 128 bits for WD at W = 64, so it is returned as three little-endian u64 limbs.
    #[inline]
    pub fn pair_int(self, x: u64, y: u64, w: u32) -> ([u64; 3], u32) {
        let (xx, yy, one) = (x as u128, y as u128, 1u128 << w);
        let small = |v: u128| [v as u64, (v >> 64) as u64, 0];
        match self {
            // (2^W − max)/2^W
            Kind::L2Star => (small(one - xx.max(yy)), w),
            // (2·2^W + a + b − |X − Y|)/(2·2^W)
            Kind::Centered => {
                let (a, b) = (xx.abs_diff(one / 2), yy.abs_diff(one / 2));
                (small(2 * one + a + b - xx.abs_diff(yy)), w + 1)
            }
            // (3·2^2W − 2Δ(2^W − Δ))/(2·2^2W), computed in 192-bit limbs.
            Kind::WrapAround => {
                let t = xx.abs_diff(yy);
                let prod = t * (one - t); // ≤ 2^(2W−2): fits u128
                                          // 3·2^(2W) − 2·prod as a 192-bit number
                let three = crate::limbs::shl_small(3, 2 * w);
                let twice = crate::limbs::shl_limbs(crate::limbs::from_u128(prod), 1);
                (crate::limbs::sub3(three, twice), 2 * w + 1)
            }
            // (2·2^W − max)/2^W
            Kind::GeneralizedL2 => (small(2 * one - xx.max(yy)), w),
        }
    }
}

impl std::str::FromStr for Kind {
    type Err = gartowen_core::UnknownName;

    /// The kind called `s` (`l2star`, `cd`, `wd`, `gl2`); the error names the choices.
    fn from_str(s: &str) -> Result<Kind, Self::Err> {
        gartowen_core::names::parse_name("kind", s, &Kind::NAMES, &Kind::ALL)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_the_error_lists_every_kind() {
        for k in Kind::ALL {
            assert_eq!(k.name().parse::<Kind>(), Ok(k));
        }
        assert_eq!(Kind::WrapAround.name(), "wd");
        assert_eq!(
            "l3".parse::<Kind>().unwrap_err().to_string(),
            "unknown kind 'l3'; use l2star, cd, wd or gl2"
        );
    }
}
