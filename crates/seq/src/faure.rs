//! Faure/Pascal generator matrices over GF(2^q), expanded to binary columns, and the Faure
//! (0,s)-sequences in every base 2^q, q = 1..8.
//!
//! P(a) has q×q block (R, C) equal to [binom(C, R) odd]·M(a^(C−R)) for C ≥ R, else 0, where
//! R indexes output digits (most significant first) and C index digits (least significant
//! first). Block entry (u, v) is binary row qR+u, column qC+v. An output transform D (q×q)
//! left-multiplies every output-digit block: the matrix becomes blockdiag(D, D, …)·P(a).

use crate::binary_field::BinaryField;
use crate::field::DigitField;
use crate::{DigitalSequence, SeqError};
use gartowen_core::{Gf2Matrix, PowerOfTwoBase, Width};

/// Whether binom(c, r) is odd (Lucas: r's bits are a subset of c's).
#[inline]
pub fn binom_odd(c: u64, r: u64) -> bool {
    r <= c && (r & !c) == 0
}

/// The binary columns of blockdiag(D)·P(a) for `width`-bit output words and `index_bits` index
/// bits. Rows past W (a partial last output digit) and columns past `index_bits` are cut off.
pub fn pascal_columns<F: DigitField>(
    field: F,
    a: u32,
    output_transform: &Gf2Matrix,
    width: Width,
    index_bits: u32,
) -> Vec<u64> {
    let q = field.q();
    assert_eq!(output_transform.size(), q, "output transform must be q×q");
    let w = width.bits();
    let out_digits = w.div_ceil(q);
    (0..index_bits)
        .map(|c| {
            let (big_c, v) = ((c / q) as u64, c % q);
            let mut word = 0u64;
            for big_r in 0..out_digits as u64 {
                if !binom_odd(big_c, big_r) {
                    continue;
                }
                let block = output_transform.mul(&field.mult_matrix(field.pow(a, big_c - big_r)));
                for u in 0..q {
                    let row = q as u64 * big_r + u as u64;
                    if row < w as u64 && block.get(u, v) {
                        word |= 1u64 << (w as u64 - 1 - row);
                    }
                }
            }
            word
        })
        .collect()
}

/// The binary columns of the plain Faure matrix P(a) (no output transform).
pub fn faure_columns<F: DigitField>(field: F, a: u32, width: Width, index_bits: u32) -> Vec<u64> {
    let id = Gf2Matrix::identity(field.q()).expect("q ≤ 8");
    pascal_columns(field, a, &id, width, index_bits)
}

/// Largest dimension count of the Faure sequence in `base`: s ≤ b.
pub fn faure_max_dims(base: PowerOfTwoBase) -> usize {
    base.base() as usize
}

/// The sequence name, `faure:base=B`.
pub fn faure_name(base: PowerOfTwoBase) -> String {
    format!("faure:base={}", base.base())
}

/// The first `dims` (≤ b) dimensions of the Faure (0,s)-sequence in base b = 2^q over
/// [`BinaryField`]: C_j = P(a_j) with a_j = j (the element whose polynomial-basis bits are
/// j), so C_0 = I and every a_j is distinct, which makes every s ≤ b dimensions a
/// (0,s)-sequence (Faure 1982, Niederreiter 1987 for prime powers). W index bits; a last
/// output digit of fewer than q bits is cut off at the word. As in sz4/sz16, bit v of an index
/// digit (least significant first) is basis element v and basis element u of an output digit
/// is its u-th bit from the top, so C_0 is the radical inverse with the bits of each digit
/// reversed: a fixed bijection per digit, which maps boxes to boxes and keeps every t-value.
pub fn faure(base: PowerOfTwoBase, dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
    let name = faure_name(base);
    if dims == 0 {
        return Err(SeqError::NoDimensions);
    }
    let max = faure_max_dims(base);
    if dims > max {
        return Err(SeqError::TooManyDimensions {
            sequence: name,
            requested: dims,
            max,
        });
    }
    let field = BinaryField::new(base.q())?;
    let cols: Vec<Vec<u64>> = (0..dims as u32)
        .map(|a| faure_columns(field, a, width, width.bits()))
        .collect();
    DigitalSequence::from_columns(&name, width, base, &cols)
}

/// The reversal matrix J_m in base b = 2^q: x(i) = Σ_k i_k b^(k−m) for i < b^m, the
/// coordinate i / b^m that turns the first b^m points of a (0,s)-sequence into a
/// (0,m,s+1)-net. Column c (index bit c, digit k = c / q) sets output bit q·(m−1−k) + (q−1−c%q)
/// from the top; columns at or past q·m are zero. Needs q·m ≤ W.
pub fn reversal_columns(base: PowerOfTwoBase, m: u32, width: Width) -> Vec<u64> {
    let (q, w) = (base.q(), width.bits());
    (0..w)
        .map(|c| {
            let (k, v) = (c / q, c % q);
            if k >= m {
                return 0;
            }
            // Index digit k becomes output digit m−1−k; bit v of a digit (LSB first) is row
            // q−1−v within that digit (MSB first).
            let row = q * (m - 1 - k) + (q - 1 - v);
            if row < w {
                1u64 << (w - 1 - row)
            } else {
                0
            }
        })
        .collect()
}

/// The (0,m,s+1)-net in base b = 2^q, s ≤ b: the reversal coordinate i / b^m followed by the
/// first s dimensions of [`faure`], named `faure-net:base=B:m=M`. Only its first b^m points
/// form the net. Needs q·m ≤ W.
pub fn faure_net(
    base: PowerOfTwoBase,
    m: u32,
    dims: usize,
    width: Width,
) -> Result<DigitalSequence, SeqError> {
    if base.q() * m > width.bits() {
        return Err(SeqError::InvalidField(format!(
            "a net of {}^{m} points needs {} index bits; {}-bit words hold {}",
            base.base(),
            base.q() * m,
            width.bits(),
            width.bits()
        )));
    }
    if dims < 2 {
        return Err(SeqError::NoDimensions);
    }
    let seq = faure(base, dims - 1, width)?;
    let mut cols = vec![reversal_columns(base, m, width)];
    for j in 0..dims - 1 {
        cols.push(
            (0..width.bits() as usize)
                .map(|c| seq.column(j, c))
                .collect(),
        );
    }
    DigitalSequence::from_columns(
        &format!("faure-net:base={}:m={m}", base.base()),
        width,
        base,
        &cols,
    )
}
