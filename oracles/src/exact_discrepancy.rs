//! Squared discrepancies by the defining formulas, term by term in exact rationals: the
//! straightforward reference (O(N²·d) big-rational operations, for tiny sets only).

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// The four kinds, named as in `gartowen-discrepancy`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReferenceKind {
    /// L2-star (Warnock).
    L2Star,
    /// Centered (Hickernell's CD).
    Centered,
    /// Wrap-around (WD).
    WrapAround,
    /// Generalized L2 (GL2).
    GeneralizedL2,
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// D² of the points (each coordinate a W-bit word, value X/2^W), exactly.
pub fn reference_discrepancy(
    points: &[Vec<u64>],
    width_bits: u32,
    kind: ReferenceKind,
) -> BigRational {
    let n = points.len();
    let d = points[0].len();
    let scale = BigInt::one() << width_bits as usize;
    let xs: Vec<Vec<BigRational>> = points
        .iter()
        .map(|p| {
            p.iter()
                .map(|&x| BigRational::new(BigInt::from(x), scale.clone()))
                .collect()
        })
        .collect();
    let half = q(1, 2);
    let one = BigRational::one();
    let pow = |base: BigRational| (0..d).fold(BigRational::one(), |acc, _| acc * &base);
    let nn = BigRational::from_integer(BigInt::from(n as u64));
    let mut single = BigRational::zero();
    let mut pair = BigRational::zero();
    for a in &xs {
        let mut s = BigRational::one();
        for x in a {
            s *= match kind {
                ReferenceKind::L2Star => &one - x * x,
                ReferenceKind::Centered => {
                    let t = (x - &half).abs();
                    &one + &half * &t - &half * &t * &t
                }
                ReferenceKind::WrapAround => one.clone(),
                ReferenceKind::GeneralizedL2 => (q(3, 1) - x * x) * &half,
            };
        }
        single += s;
        for b in &xs {
            let mut p = BigRational::one();
            for (x, y) in a.iter().zip(b) {
                let max = if x > y { x } else { y };
                p *= match kind {
                    ReferenceKind::L2Star => &one - max,
                    ReferenceKind::Centered => {
                        &one + &half * (x - &half).abs() + &half * (y - &half).abs()
                            - &half * (x - y).abs()
                    }
                    ReferenceKind::WrapAround => {
                        let t = (x - y).abs();
                        q(3, 2) - &t * (&one - &t)
                    }
                    ReferenceKind::GeneralizedL2 => q(2, 1) - max,
                };
            }
            pair += p;
        }
    }
    let (c0, c1) = match kind {
        ReferenceKind::L2Star => (pow(q(1, 3)), -(q(2, 1) / pow(q(2, 1)))),
        ReferenceKind::Centered => (pow(q(13, 12)), q(-2, 1)),
        ReferenceKind::WrapAround => (-pow(q(4, 3)), BigRational::zero()),
        ReferenceKind::GeneralizedL2 => (pow(q(4, 3)), q(-2, 1)),
    };
    c0 + c1 * single / &nn + pair / (&nn * &nn)
}
