//! Double-double arithmetic (about 106 significant bits) from error-free transformations:
//! Knuth's TwoSum and Dekker's TwoProduct (no FMA needed, so results do not depend on the CPU).

/// An unevaluated sum hi + lo with |lo| ≤ ulp(hi)/2.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

#[inline(always)]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let t = 134_217_729.0 * a; // 2^27 + 1
    let hi = t - (t - a);
    (hi, a - hi)
}

/// a·b = p + e exactly.
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    /// The value x.
    #[inline(always)]
    pub fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// self + b.
    #[inline(always)]
    pub fn add_f64(self, b: f64) -> Dd {
        let (s, e) = two_sum(self.hi, b);
        let (hi, lo) = quick_two_sum(s, e + self.lo);
        Dd { hi, lo }
    }

    /// self + o.
    #[inline(always)]
    pub fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (hi, lo) = quick_two_sum(s, e + self.lo + o.lo);
        Dd { hi, lo }
    }

    /// self · b.
    #[inline(always)]
    pub fn mul_f64(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi, b);
        let (hi, lo) = quick_two_sum(p, e + self.lo * b);
        Dd { hi, lo }
    }

    /// self · o (the lo·lo term is below the result's precision).
    #[inline(always)]
    pub fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        let (hi, lo) = quick_two_sum(p, e + (self.hi * o.lo + self.lo * o.hi));
        Dd { hi, lo }
    }

    /// self / b for finite nonzero b, to double-double precision (a few ε² relative): the
    /// remainder of the first quotient is formed exactly by an error-free product.
    #[inline(always)]
    pub fn div_f64(self, b: f64) -> Dd {
        let q1 = self.hi / b;
        let (p, e) = two_prod(q1, b);
        let r = ((self.hi - p) - e) + self.lo;
        let (hi, lo) = quick_two_sum(q1, r / b);
        Dd { hi, lo }
    }

    /// −self.
    #[inline(always)]
    pub fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// The nearest f64.
    #[inline(always)]
    pub fn value(self) -> f64 {
        self.hi + self.lo
    }
}

/// The error-free transformations proved exact in `proofs/Float.v` (`two_sum_exact`,
/// `quick_two_sum_exact`, `two_prod_exact`), checked here by the second path: exact rational
/// arithmetic on adversarial and random doubles, with each hypothesis shown to matter.
#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::SplitMix64;
    use num_rational::BigRational;
    use num_traits::Signed;

    fn q(x: f64) -> BigRational {
        BigRational::from_float(x).expect("finite")
    }

    /// Doubles spread over magnitudes 2^-600..2^600 with random signs and mantissas, plus the
    /// awkward ones (ties, neighbours of powers of two, 2^27 ± 1 multiples).
    fn doubles(n: usize, seed: u64) -> Vec<f64> {
        let mut rng = SplitMix64::new(seed);
        let mut v = vec![
            0.0,
            1.0,
            -1.0,
            0.5,
            1.0 + f64::EPSILON,
            1.0 - f64::EPSILON / 2.0,
        ];
        v.extend([
            134_217_729.0,
            134_217_727.0,
            3.0 * 2f64.powi(-60),
            f64::MIN_POSITIVE,
        ]);
        while v.len() < n {
            let mant = 1.0 + (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
            let exp = (rng.next_u64() % 1201) as i32 - 600;
            let sign = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
            v.push(sign * mant * 2f64.powi(exp));
        }
        v
    }

    #[test]
    fn two_sum_is_exact_for_any_two_doubles() {
        let xs = doubles(400, 1);
        for &a in &xs {
            for &b in xs.iter().step_by(7) {
                let (s, e) = two_sum(a, b);
                assert!(s.is_finite() && e.is_finite());
                assert_eq!(q(s) + q(e), q(a) + q(b), "a = {a:e}, b = {b:e}");
            }
        }
    }

    #[test]
    fn quick_two_sum_is_exact_when_the_first_is_larger_and_needs_it() {
        let xs = doubles(400, 2);
        for &a in &xs {
            for &b in xs.iter().step_by(7) {
                let (a, b) = if a.abs() >= b.abs() { (a, b) } else { (b, a) };
                let (s, e) = quick_two_sum(a, b);
                assert_eq!(q(s) + q(e), q(a) + q(b), "a = {a:e}, b = {b:e}");
            }
        }
        // The hypothesis |b| ≤ |a| matters: 1 + 2^100 loses the 1 when the order is swapped.
        let (s, e) = quick_two_sum(1.0, 2f64.powi(100));
        assert_ne!(q(s) + q(e), q(1.0) + q(2f64.powi(100)));
    }

    #[test]
    fn split_halves_a_double_and_two_prod_is_exact_above_underflow() {
        let xs = doubles(300, 3);
        for &a in &xs {
            let (hi, lo) = split(a);
            assert_eq!(q(hi) + q(lo), q(a));
            // hi keeps at most 26 significant bits (Veltkamp with 2^27 + 1).
            if hi != 0.0 {
                let m = hi.abs() / 2f64.powi(hi.abs().log2().floor() as i32);
                assert_eq!((m * 2f64.powi(25)).fract(), 0.0, "hi of {a:e} = {hi:e}");
            }
            for &b in xs.iter().step_by(5) {
                let p = a * b;
                // The hypothesis is on the exact product: 0, or at least 2^-969 in magnitude.
                if p.is_finite() && (a == 0.0 || b == 0.0 || p.abs() >= 2f64.powi(-968)) {
                    let (p, e) = two_prod(a, b);
                    assert_eq!(q(p) + q(e), q(a) * q(b), "a = {a:e}, b = {b:e}");
                }
            }
        }
        // Below 2^-969 the error term underflows and exactness fails (the theorem's hypothesis).
        let (a, b) = (
            1.0 + f64::EPSILON,
            2f64.powi(-1000) * (1.0 + 2.0 * f64::EPSILON),
        );
        let (p, e) = two_prod(a, b);
        assert_ne!(q(p) + q(e), q(a) * q(b));
    }

    /// Non-negative normalized double-doubles (hi ≥ 0, |lo| ≤ 2u·hi: the invariant `Inv` of
    /// `proofs/DdSum.v`), over 2^-400..2^400, with the extremes of lo.
    fn normalized(n: usize, seed: u64) -> Vec<Dd> {
        let mut rng = SplitMix64::new(seed);
        let mut v = vec![Dd::from(0.0), Dd::from(1.0)];
        while v.len() < n {
            let mant = 1.0 + (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
            let hi = mant * 2f64.powi((rng.next_u64() % 801) as i32 - 400);
            let room = hi * f64::EPSILON; // 2u·hi
            let lo = match rng.next_u64() % 4 {
                0 => room,
                1 => -room,
                2 => 0.0,
                _ => room * ((rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0),
            };
            v.push(Dd { hi, lo });
        }
        v
    }

    fn value(a: Dd) -> BigRational {
        q(a.hi) + q(a.lo)
    }

    fn is_normalized(a: Dd) -> bool {
        a.hi >= 0.0 && a.lo.abs() <= a.hi * f64::EPSILON
    }

    /// The second path for `dd_add_correct`: exact rationals on adversarial operands.
    #[test]
    fn dd_add_of_nonnegative_pairs_is_within_10_u2_and_normalized() {
        let u2 = q(f64::EPSILON / 2.0) * q(f64::EPSILON / 2.0);
        let xs = normalized(300, 4);
        let mut worst = BigRational::from_integer(0.into());
        for &a in &xs {
            for &b in xs.iter().step_by(3) {
                let s = a.add(b);
                let exact = value(a) + value(b);
                let err = (value(s) - &exact).abs();
                assert!(is_normalized(s), "{a:?} + {b:?} = {s:?}");
                assert!(err <= q(10.0) * &u2 * &exact, "{a:?} + {b:?}");
                if exact > BigRational::from_integer(0.into()) {
                    worst = worst.max(err / (&u2 * exact));
                }
            }
        }
        // The bound is not vacuous: some sums err by more than u²/4.
        assert!(worst > q(0.25), "worst error {worst} u²");
        // The hypothesis hi ≥ 0 matters: with b.hi = −1 the his cancel exactly and the lo sum
        // rounds a tie (2^-53 − 2^-105 + 2^-107 to even), losing 2^-107 of a 1.5·2^-52 result,
        // a relative error of 2^-55, far above 10u² = 10·2^-106.
        let a = Dd {
            hi: 1.0 + f64::EPSILON,
            lo: 2f64.powi(-53) - 2f64.powi(-105),
        };
        let b = Dd {
            hi: -1.0,
            lo: 2f64.powi(-107),
        };
        let exact = value(a) + value(b);
        let err = (value(a.add(b)) - &exact).abs();
        assert_eq!(err, q(2f64.powi(-107)));
        assert!(err > q(10.0) * &u2 * exact.abs());
    }

    /// The second path for `dd_mul_bound`: within 20u² when hi·hi is 0 or ≥ 2^-900.
    #[test]
    fn dd_mul_of_nonnegative_pairs_is_within_20_u2_and_normalized() {
        let u2 = q(f64::EPSILON / 2.0) * q(f64::EPSILON / 2.0);
        let xs = normalized(200, 5);
        let mut checked = 0;
        for &a in &xs {
            for &b in xs.iter().step_by(3) {
                let p = a.hi * b.hi;
                if !(p == 0.0 || p >= 2f64.powi(-900)) {
                    continue;
                }
                let m = a.mul(b);
                let exact = value(a) * value(b);
                assert!(is_normalized(m), "{a:?} · {b:?} = {m:?}");
                assert!(
                    (value(m) - &exact).abs() <= q(20.0) * &u2 * &exact,
                    "{a:?} · {b:?}"
                );
                checked += 1;
            }
        }
        assert!(checked > 10_000, "{checked}");
    }
}
