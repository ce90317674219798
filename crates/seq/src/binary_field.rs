//! GF(2^q) for every q = 1..8 in the polynomial basis, for the Faure sequences in every base
//! 2^q.
//!
//! Element e in 0..2^q is the polynomial Σ e_i x^i (bit i = coefficient of x^i); products are
//! reduced by a fixed primitive polynomial of degree q (the table below, the usual choices:
//! x² + x + 1, x³ + x + 1, x⁴ + x + 1, x⁵ + x² + 1, x⁶ + x + 1, x⁷ + x + 1 and
//! x⁸ + x⁴ + x³ + x² + 1). Primitive means x generates the multiplicative group, which the tests
//! check for every q (x has order exactly 2^q − 1), together with the field axioms.
//!
//! This is not the encoding of `sz4`/`sz16` ([`crate::field::SmallField`], a tower basis); any
//! GF(2)-basis gives digital nets with the same t-values, since a box condition is the
//! bijectivity of a GF(2)-linear map whatever basis writes it.

use crate::field::DigitField;
use crate::SeqError;
use gartowen_core::Gf2Matrix;

/// The primitive polynomial of degree q (bit i = coefficient of x^i, bit q set), q = 1..8.
pub const PRIMITIVE_POLYNOMIALS: [u32; 8] = [
    0b11,        // x + 1
    0b111,       // x² + x + 1
    0b1011,      // x³ + x + 1
    0b1_0011,    // x⁴ + x + 1
    0b10_0101,   // x⁵ + x² + 1
    0b100_0011,  // x⁶ + x + 1
    0b1000_0011, // x⁷ + x + 1
    0x11d,       // x⁸ + x⁴ + x³ + x² + 1
];

/// GF(2^q), q = 1..8, polynomial basis reduced by [`PRIMITIVE_POLYNOMIALS`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BinaryField {
    q: u32,
    poly: u32,
}

impl BinaryField {
    /// The field of 2^q elements; q must be 1..8.
    pub fn new(q: u32) -> Result<Self, SeqError> {
        if !(1..=8).contains(&q) {
            return Err(SeqError::InvalidField(format!(
                "GF(2^{q}): q must be 1..8 (bases 2..256)"
            )));
        }
        Ok(BinaryField {
            q,
            poly: PRIMITIVE_POLYNOMIALS[q as usize - 1],
        })
    }

    /// Number of elements, 2^q.
    pub fn order(self) -> u32 {
        1 << self.q
    }

    /// The reduction polynomial (bit q set).
    pub fn polynomial(self) -> u32 {
        self.poly
    }

    /// The product a·b (a, b < 2^q): carry-less product, reduced.
    #[inline]
    pub fn mul(self, a: u32, b: u32) -> u32 {
        let mut product = 0u32;
        for i in 0..self.q {
            if (b >> i) & 1 == 1 {
                product ^= a << i;
            }
        }
        for bit in (self.q..2 * self.q).rev() {
            if (product >> bit) & 1 == 1 {
                product ^= self.poly << (bit - self.q);
            }
        }
        product
    }
}

impl DigitField for BinaryField {
    fn q(&self) -> u32 {
        self.q
    }

    fn pow(&self, a: u32, n: u64) -> u32 {
        if n == 0 {
            return 1;
        }
        if a == 0 {
            return 0;
        }
        // The multiplicative group has order 2^q − 1.
        let mut e = n % (self.order() as u64 - 1);
        let (mut base, mut r) = (a, 1u32);
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, base);
            }
            base = self.mul(base, base);
            e >>= 1;
        }
        r
    }

    fn mult_matrix(&self, a: u32) -> Gf2Matrix {
        let mut rows = vec![0u8; self.q as usize];
        for j in 0..self.q {
            let col = self.mul(a, 1 << j);
            for (i, r) in rows.iter_mut().enumerate() {
                *r |= (((col >> i) & 1) as u8) << j;
            }
        }
        Gf2Matrix::from_rows(self.q, &rows).expect("q ≤ 8")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_field_satisfies_the_axioms_and_x_is_primitive() {
        for q in 1..=8 {
            let f = BinaryField::new(q).unwrap();
            let b = f.order();
            for a in 0..b {
                assert_eq!(f.mul(a, 1), a);
                assert_eq!(f.mul(a, 0), 0);
                for c in 0..b {
                    let ac = f.mul(a, c);
                    assert!(ac < b);
                    assert_eq!(ac, f.mul(c, a), "q {q}: {a}·{c}");
                    // Distributive over XOR (the field's addition), on a stride of third operands.
                    for d in (0..b).step_by(1 + (b as usize / 16)) {
                        assert_eq!(f.mul(a, c ^ d), ac ^ f.mul(a, d));
                        assert_eq!(f.mul(ac, d), f.mul(a, f.mul(c, d)), "q {q} assoc");
                    }
                }
                if a != 0 {
                    // An inverse exists, so there are no zero divisors.
                    assert!(
                        (1..b).any(|c| f.mul(a, c) == 1),
                        "q {q}: {a} has no inverse"
                    );
                    assert_eq!(f.pow(a, b as u64 - 1), 1, "Fermat");
                }
            }
            // x (= 2, or 1 in GF(2)) has order exactly 2^q − 1: every nonzero element is a power.
            let x = if q == 1 { 1 } else { 2 };
            let mut seen = vec![false; b as usize];
            let mut p = 1;
            for _ in 0..b - 1 {
                assert!(!seen[p as usize], "q {q}: x has order below 2^q − 1");
                seen[p as usize] = true;
                p = f.mul(p, x);
            }
            assert_eq!(p, 1);
            assert_eq!(f.polynomial(), PRIMITIVE_POLYNOMIALS[q as usize - 1]);
            assert_eq!(f.polynomial() >> q, 1, "degree q");
            assert_eq!(DigitField::q(&f), q);
            // The multiplication matrix applies the product.
            for a in 0..b {
                let m = f.mult_matrix(a);
                for c in 0..b {
                    assert_eq!(m.apply(c), f.mul(a, c), "q {q}: M({a})·{c}");
                }
            }
        }
        assert!(BinaryField::new(0).is_err() && BinaryField::new(9).is_err());
    }

    #[test]
    fn powers_match_repeated_products() {
        for q in [3, 5, 8] {
            let f = BinaryField::new(q).unwrap();
            for a in [0, 1, 2, 3, f.order() - 1] {
                let mut p = 1;
                for n in 0..600u64 {
                    assert_eq!(f.pow(a, n), p, "q {q}: {a}^{n}");
                    p = f.mul(p, a);
                }
            }
        }
    }
}
