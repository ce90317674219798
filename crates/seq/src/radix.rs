//! Sequences in any integer base b ≥ 2, exact in integers: the Halton sequence (van der Corput
//! in the first s primes) and the Faure sequence in a prime base. They are the references for
//! checking points in bases that are not powers of two: each point is an exact fraction
//! k / b^n, and its binary64 value is the correctly rounded quotient (b^n < 2^53, so both
//! operands are exact and IEEE division rounds once).

use crate::SeqError;

/// The first 32 primes, the bases of Halton dimensions 0..32.
pub const PRIMES: [u64; 32] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
    101, 103, 107, 109, 113, 127, 131,
];

/// An exact coordinate k / b^n (k < b^n < 2^53).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fraction {
    /// Numerator k.
    pub numer: u64,
    /// Denominator b^n.
    pub denom: u64,
}

impl Fraction {
    /// The correctly rounded binary64 value.
    pub fn to_f64(self) -> f64 {
        self.numer as f64 / self.denom as f64
    }
}

/// Base-b digits of i, least significant first, exactly `n` of them.
fn digits(mut i: u64, b: u64, n: u32) -> Vec<u64> {
    (0..n)
        .map(|_| {
            let d = i % b;
            i /= b;
            d
        })
        .collect()
}

/// The number of base-b digits needed for every index below `count` (at least 1), with the
/// check that b^n < 2^53.
fn digit_count(count: u64, b: u64) -> Result<(u32, u64), SeqError> {
    if b < 2 {
        return Err(SeqError::InvalidField(format!(
            "base {b}: must be at least 2"
        )));
    }
    let (mut n, mut bn) = (0u32, 1u64);
    while bn < count.max(2) {
        bn = bn.checked_mul(b).filter(|&x| x < 1 << 53).ok_or_else(|| {
            SeqError::InvalidField(format!(
                "{count} points in base {b} need more digits than a binary64 holds exactly"
            ))
        })?;
        n += 1;
    }
    Ok((n, bn))
}

/// The radical inverse of i in base b over n digits: Σ_k i_k b^(n−1−k) / b^n.
pub fn radical_inverse(i: u64, b: u64, n: u32) -> Fraction {
    let numer = digits(i, b, n).iter().fold(0u64, |acc, &d| acc * b + d);
    Fraction {
        numer,
        denom: b.pow(n),
    }
}

/// The first `count` points of the `dims`-dimensional Halton sequence (index 0 first, so
/// point 0 is the origin), row-major, exact. Dimension j is the radical inverse in `PRIMES[j]`.
pub fn halton(count: u64, dims: usize) -> Result<Vec<Fraction>, SeqError> {
    if dims == 0 {
        return Err(SeqError::NoDimensions);
    }
    if dims > PRIMES.len() {
        return Err(SeqError::TooManyDimensions {
            sequence: "halton".into(),
            requested: dims,
            max: PRIMES.len(),
        });
    }
    let plans: Vec<(u64, u32)> = PRIMES[..dims]
        .iter()
        .map(|&p| digit_count(count, p).map(|(n, _)| (p, n)))
        .collect::<Result<_, _>>()?;
    Ok((0..count)
        .flat_map(|i| plans.iter().map(move |&(p, n)| radical_inverse(i, p, n)))
        .collect())
}

/// Whether `p` is prime (trial division: meant for bases, p below about 2^40).
///
/// ```
/// use gartowen_seq::radix::is_prime;
/// assert!(is_prime(2) && is_prime(3) && is_prime(65521));
/// assert!(!is_prime(0) && !is_prime(1) && !is_prime(9) && !is_prime(65535));
/// ```
pub fn is_prime(p: u64) -> bool {
    p >= 2
        && (2..)
            .take_while(|d| d * d <= p)
            .all(|d| !p.is_multiple_of(d))
}

/// The first `count` points of the Faure (0,s)-sequence in the prime base p, s = `dims` ≤ p,
/// row-major, exact: output digit r of dimension j is Σ_{c ≥ r} C(c, r) j^(c−r) i_c mod p
/// (the Pascal matrix to the power j; dimension 0 is van der Corput in base p).
pub fn faure_prime(p: u64, count: u64, dims: usize) -> Result<Vec<Fraction>, SeqError> {
    if !is_prime(p) {
        return Err(SeqError::InvalidField(format!(
            "Faure base {p}: not a prime"
        )));
    }
    if dims == 0 {
        return Err(SeqError::NoDimensions);
    }
    if dims as u64 > p {
        return Err(SeqError::TooManyDimensions {
            sequence: format!("faure base {p}"),
            requested: dims,
            max: p as usize,
        });
    }
    let (n, denom) = digit_count(count, p)?;
    let n_us = n as usize;
    // Binomials mod p up to n.
    let mut binom = vec![vec![0u64; n_us]; n_us];
    for c in 0..n_us {
        binom[c][0] = 1;
        for r in 1..=c {
            binom[c][r] = (binom[c - 1][r - 1] + if r < c { binom[c - 1][r] } else { 0 }) % p;
        }
    }
    let mut out = Vec::with_capacity(count as usize * dims);
    for i in 0..count {
        let d = digits(i, p, n);
        for j in 0..dims as u64 {
            let mut numer = 0u64;
            for r in 0..n_us {
                let mut y = 0u64;
                let mut power = 1u64; // j^(c−r)
                for (row, &digit) in binom.iter().zip(&d).skip(r) {
                    y = (y + row[r] * power % p * digit) % p;
                    power = power * j % p;
                }
                numer = numer * p + y;
            }
            out.push(Fraction { numer, denom });
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radical_inverses_are_exact_fractions() {
        assert_eq!(radical_inverse(1, 3, 2), Fraction { numer: 3, denom: 9 });
        assert_eq!(radical_inverse(5, 3, 2), Fraction { numer: 7, denom: 9 }); // 5 = 12₃ → 0.21₃
        assert_eq!(radical_inverse(6, 2, 3).to_f64(), 0.375); // 110₂ → 0.011₂
        let h = halton(4, 2).unwrap();
        assert_eq!(h[2].to_f64(), 0.5);
        // Four points need exactly two base-2 digits: point 1 is 1/2 as 2/4.
        assert_eq!((h[2].numer, h[2].denom), (2, 4));
        assert_eq!(halton(10, 32).unwrap().len(), 320);
        // Four points need two base-3 digits: point 1 is 0.10₃ = 3/9, point 3 = 10₃ is 0.01₃.
        assert_eq!((h[3].numer, h[3].denom), (3, 9));
        assert_eq!((h[7].numer, h[7].denom), (1, 9));
    }

    #[test]
    fn every_block_is_one_point_per_interval_in_its_own_base() {
        // b^m consecutive radical inverses from 0: one per interval [k/b^m, (k+1)/b^m).
        for (p, m) in [(2u64, 10u32), (3, 6), (5, 4), (7, 3)] {
            let n = p.pow(m);
            let mut seen = vec![false; n as usize];
            for i in 0..n {
                let f = radical_inverse(i, p, m);
                assert!(!std::mem::replace(&mut seen[f.numer as usize], true));
            }
        }
    }

    /// Every elementary box of volume p^-m holds one of the first p^m points, counted on the
    /// exact numerators (every dimension, so every Pascal power j is exercised).
    #[test]
    fn prime_faure_points_are_0_m_s_nets_on_their_exact_digits() {
        for (p, m) in [(3u64, 3u32), (5, 2), (7, 2)] {
            let n = p.pow(m);
            let dims = p as usize;
            let f = faure_prime(p, n, dims).unwrap();
            let digits = f[0].denom.ilog(p);
            // Every pair of dimensions (a, b) and split k + (m − k).
            for a in 0..dims {
                for b in a + 1..dims {
                    for k in 0..=m {
                        let mut seen = std::collections::HashSet::new();
                        for i in 0..n as usize {
                            let x = f[i * dims + a].numer / p.pow(digits - k);
                            let y = f[i * dims + b].numer / p.pow(digits - (m - k));
                            assert!(seen.insert((x, y)), "p {p} dims ({a},{b}) k {k}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn faure_dimension_0_is_van_der_corput_and_bad_bases_are_refused() {
        let f = faure_prime(3, 27, 3).unwrap();
        for i in 0..27u64 {
            assert_eq!(f[i as usize * 3], radical_inverse(i, 3, 3));
        }
        assert!(faure_prime(4, 9, 2).is_err());
        assert!(faure_prime(3, 9, 4).is_err());
        assert!(halton(10, 0).is_err() && halton(10, 33).is_err());
        assert!(halton(u64::MAX, 32).is_err());
    }
}
