//! Exact rationals without a gcd per operation: [`crate::compensated`]'s bound combines a dozen
//! rationals per call, and reducing each intermediate (num-rational's arithmetic does) cost
//! more than the sums themselves at small N. The values are exact, so every comparison and
//! rounding is that of the reduced rationals.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// num/den with den > 0, not reduced.
#[derive(Debug, Clone)]
pub(crate) struct Unreduced {
    num: BigInt,
    den: BigInt,
}

impl Unreduced {
    /// The value of `r`.
    pub(crate) fn of(r: &BigRational) -> Self {
        Unreduced {
            num: r.numer().clone(),
            den: r.denom().clone(),
        }
    }

    /// The integer `n`.
    pub(crate) fn int(n: usize) -> Self {
        Unreduced {
            num: BigInt::from(n),
            den: BigInt::from(1u8),
        }
    }

    /// self + other.
    pub(crate) fn add(&self, other: &Self) -> Self {
        Unreduced {
            num: &self.num * &other.den + &other.num * &self.den,
            den: &self.den * &other.den,
        }
    }

    /// self − other.
    pub(crate) fn sub(&self, other: &Self) -> Self {
        Unreduced {
            num: &self.num * &other.den - &other.num * &self.den,
            den: &self.den * &other.den,
        }
    }

    /// self · other.
    pub(crate) fn mul(&self, other: &Self) -> Self {
        Unreduced {
            num: &self.num * &other.num,
            den: &self.den * &other.den,
        }
    }

    /// self / other; panics when other is zero.
    pub(crate) fn div(&self, other: &Self) -> Self {
        assert!(!other.num.is_zero(), "division by zero");
        let (num, den) = (&self.num * &other.den, &self.den * &other.num);
        if den.is_negative() {
            Unreduced {
                num: -num,
                den: -den,
            }
        } else {
            Unreduced { num, den }
        }
    }

    /// |self|.
    pub(crate) fn abs(&self) -> Self {
        Unreduced {
            num: self.num.abs(),
            den: self.den.clone(),
        }
    }

    /// The same value as a [`BigRational`] (not reduced; num-rational compares and
    /// [`crate::rational::to_f64`] rounds by value).
    pub(crate) fn to_ratio(&self) -> BigRational {
        BigRational::new_raw(self.num.clone(), self.den.clone())
    }
}

impl PartialEq for Unreduced {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Unreduced {}

impl PartialOrd for Unreduced {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Unreduced {
    /// By cross-multiplication (both denominators are positive).
    fn cmp(&self, other: &Self) -> Ordering {
        (&self.num * &other.den).cmp(&(&other.num * &self.den))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::SplitMix64;

    fn random_ratio(rng: &mut SplitMix64) -> BigRational {
        let num = BigInt::from(rng.next_u64() as i64) << (rng.next_u64() % 90) as usize;
        let den = BigInt::from(rng.next_u64() % 1_000_000 + 1) << (rng.next_u64() % 90) as usize;
        BigRational::new(num, den)
    }

    #[test]
    fn every_operation_equals_num_rationals_reduced_one() {
        let mut rng = SplitMix64::new(17);
        for _ in 0..2000 {
            let (a, b) = (random_ratio(&mut rng), random_ratio(&mut rng));
            let (ua, ub) = (Unreduced::of(&a), Unreduced::of(&b));
            // num-rational's Eq compares values, so an unreduced result equals the reduced one.
            assert_eq!(ua.add(&ub).to_ratio(), &a + &b);
            assert_eq!(ua.sub(&ub).to_ratio(), &a - &b);
            assert_eq!(ua.mul(&ub).to_ratio(), &a * &b);
            assert_eq!(ua.abs().to_ratio(), a.abs());
            assert_eq!(ua.cmp(&ub), a.cmp(&b));
            assert_eq!(ua == ub, a == b);
            if !b.is_zero() {
                let q = ua.div(&ub);
                assert_eq!(q.to_ratio(), &a / &b);
                assert!(q.den.is_positive(), "the denominator stays positive");
            }
        }
        // Equal values in different forms are equal, and order by value.
        let half = Unreduced::of(&BigRational::new(1.into(), 2.into()));
        let two_quarters = Unreduced::int(2).div(&Unreduced::int(4));
        assert_eq!(half, two_quarters);
        assert!(Unreduced::int(1) > half && half.sub(&Unreduced::int(1)) < Unreduced::int(0));
    }
}
