//! Faure/Pascal generator matrices over GF(2^q), expanded to binary columns.
//!
//! P(a) has q×q block (R, C) equal to [binom(C, R) odd]·M(a^(C−R)) for C ≥ R, else 0, where
//! R indexes output digits (most significant first) and C index digits (least significant
//! first). Block entry (u, v) is binary row qR+u, column qC+v. An output transform D (q×q)
//! left-multiplies every output-digit block: the matrix becomes blockdiag(D, D, …)·P(a).

use crate::field::SmallField;
use gartowen_core::{Gf2Matrix, Width};

/// Whether binom(c, r) is odd (Lucas: r's bits are a subset of c's).
#[inline]
pub fn binom_odd(c: u64, r: u64) -> bool {
    r <= c && (r & !c) == 0
}

/// The binary columns of blockdiag(D)·P(a) for `width`-bit output words and `index_bits` index
/// bits. Rows past W (a partial last output digit) and columns past `index_bits` are cut off.
pub fn pascal_columns(
    field: SmallField,
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
pub fn faure_columns(field: SmallField, a: u32, width: Width, index_bits: u32) -> Vec<u64> {
    let id = Gf2Matrix::identity(field.q()).expect("q ≤ 4");
    pascal_columns(field, a, &id, width, index_bits)
}
