//! The small fields GF(2), GF(4) and GF(16) of `docs/design.md` §2, as used by the SZ construction.
//!
//! * GF(4) = GF(2)\[ω\]/(ω²+ω+1): element e in 0..4, bit 0 = coefficient of 1, bit 1 = of ω.
//! * GF(16) = GF(4)\[y\]/(y²+y+ω): element α+βy encoded as `α | β << 2`, so bit i of the
//!   encoding is the coefficient of the GF(2)-basis element `(1, ω, y, ωy)[i]`.
//!
//! [`SmallField::mult_matrix`] is the binary q×q matrix of x ↦ a·x in that basis: column j is
//! a·(basis j), row i is the coefficient of basis i. That is M4(a) and M16(a) of the design.

use crate::SeqError;
use gartowen_core::Gf2Matrix;

/// A field GF(2^q) in some GF(2)-basis, as far as Pascal/Faure generator matrices need it.
pub trait DigitField {
    /// Bits per element, q.
    fn q(&self) -> u32;
    /// a^n, with a^0 = 1 (also for a = 0).
    fn pow(&self, a: u32, n: u64) -> u32;
    /// The binary q×q matrix of x ↦ a·x: column j = a·(basis j), row i = coefficient of basis i.
    fn mult_matrix(&self, a: u32) -> Gf2Matrix;
}

impl DigitField for SmallField {
    fn q(&self) -> u32 {
        SmallField::q(*self)
    }
    fn pow(&self, a: u32, n: u64) -> u32 {
        SmallField::pow(*self, a, n)
    }
    fn mult_matrix(&self, a: u32) -> Gf2Matrix {
        SmallField::mult_matrix(*self, a)
    }
}

/// One of the fields GF(2^q), q ∈ {1, 2, 4}.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SmallField {
    /// GF(2).
    Gf2,
    /// GF(4) = GF(2)\[ω\]/(ω²+ω+1).
    Gf4,
    /// GF(16) = GF(4)\[y\]/(y²+y+ω).
    Gf16,
}

/// ω in the GF(4) encoding.
pub const OMEGA: u32 = 2;
/// ω² = ω + 1 in the GF(4) encoding.
pub const OMEGA2: u32 = 3;

/// Product in GF(4).
#[inline]
pub fn gf4_mul(a: u32, b: u32) -> u32 {
    let (a0, a1, b0, b1) = (a & 1, (a >> 1) & 1, b & 1, (b >> 1) & 1);
    // (a0 + a1ω)(b0 + b1ω) = a0b0 + a1b1 + (a0b1 + a1b0 + a1b1)ω, using ω² = ω + 1.
    let c0 = (a0 & b0) ^ (a1 & b1);
    let c1 = (a0 & b1) ^ (a1 & b0) ^ (a1 & b1);
    c0 | (c1 << 1)
}

/// Product in GF(16).
#[inline]
pub fn gf16_mul(a: u32, b: u32) -> u32 {
    let (a0, a1, b0, b1) = (a & 3, (a >> 2) & 3, b & 3, (b >> 2) & 3);
    // (a0 + a1 y)(b0 + b1 y) = a0b0 + a1b1 ω + (a0b1 + a1b0 + a1b1) y, using y² = y + ω.
    let prod11 = gf4_mul(a1, b1);
    let c0 = gf4_mul(a0, b0) ^ gf4_mul(prod11, OMEGA);
    let c1 = gf4_mul(a0, b1) ^ gf4_mul(a1, b0) ^ prod11;
    c0 | (c1 << 2)
}

impl SmallField {
    /// The field GF(2^q) for q ∈ {1, 2, 4}.
    pub fn from_q(q: u32) -> Result<Self, SeqError> {
        match q {
            1 => Ok(SmallField::Gf2),
            2 => Ok(SmallField::Gf4),
            4 => Ok(SmallField::Gf16),
            _ => Err(SeqError::InvalidField(format!(
                "GF(2^{q}) is not built in; q must be 1, 2 or 4"
            ))),
        }
    }

    /// Bits per element, q.
    pub fn q(self) -> u32 {
        match self {
            SmallField::Gf2 => 1,
            SmallField::Gf4 => 2,
            SmallField::Gf16 => 4,
        }
    }

    /// Number of elements, 2^q.
    pub fn order(self) -> u32 {
        1 << self.q()
    }

    /// Checks that `a` encodes an element.
    pub fn check(self, a: u32) -> Result<u32, SeqError> {
        if a < self.order() {
            Ok(a)
        } else {
            Err(SeqError::InvalidField(format!(
                "{a} is not an element of GF({})",
                self.order()
            )))
        }
    }

    /// The product a·b.
    #[inline]
    pub fn mul(self, a: u32, b: u32) -> u32 {
        match self {
            SmallField::Gf2 => a & b & 1,
            SmallField::Gf4 => gf4_mul(a, b),
            SmallField::Gf16 => gf16_mul(a, b),
        }
    }

    /// a^n, with a^0 = 1 (also for a = 0).
    pub fn pow(self, a: u32, n: u64) -> u32 {
        if n == 0 {
            return 1;
        }
        if a == 0 {
            return 0;
        }
        // The multiplicative group has order 2^q − 1, so a^n = a^(n mod (2^q − 1)).
        let reduced = n % (self.order() as u64 - 1);
        (0..reduced).fold(1, |r, _| self.mul(r, a))
    }

    /// The binary matrix of x ↦ a·x: column j = a·(basis j), row i = coefficient of basis i.
    pub fn mult_matrix(self, a: u32) -> Gf2Matrix {
        let q = self.q();
        let mut rows = vec![0u8; q as usize];
        for j in 0..q {
            let col = self.mul(a, 1 << j);
            for (i, r) in rows.iter_mut().enumerate() {
                *r |= (((col >> i) & 1) as u8) << j;
            }
        }
        Gf2Matrix::from_rows(q, &rows).expect("q ≤ 4")
    }
}

/// The 4×4 binary expansion of a 2×2 GF(4) matrix `g`: entry (2i+u, 2j+v) is `M4(g[i][j])[u][v]`.
/// Used for E(α) and for M16 in the design's formulation.
pub fn expand_gf4_matrix(g: [[u32; 2]; 2]) -> Gf2Matrix {
    let mut rows = [0u8; 4];
    for (i, g_row) in g.iter().enumerate() {
        for (j, &entry) in g_row.iter().enumerate() {
            let m4 = SmallField::Gf4.mult_matrix(entry);
            for u in 0..2 {
                for v in 0..2 {
                    if m4.get(u, v) {
                        rows[2 * i + u as usize] |= 1 << (2 * j + v as usize);
                    }
                }
            }
        }
    }
    Gf2Matrix::from_rows(4, &rows).expect("4×4")
}
