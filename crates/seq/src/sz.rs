//! SZ-style universal sequences (`docs/design.md` §2): gartowen's own binary-constructed
//! (0,2^q)-sequences, not the published SZ matrices (which are not public).
//!
//! * `sz4`: dimensions a = 0, 1, ω, ω² of the GF(4) Faure sequence, output transforms
//!   D = I, U, I, U with U = `[[1,1],[0,1]]` per 2-bit output digit.
//! * `sz16`: dimension j = 4β + k uses a_j = α_k² + β·y with α_k = `(0, 1, ω, ω²)[k]` and
//!   D_j = blockdiag(U,U)·E(α_k) when α_k ∈ {1, ω²}, else E(α_k), where E(α) is the binary
//!   expansion of the GF(4) matrix [[1, α], [0, 1]].

use crate::faure::pascal_columns;
use crate::field::{expand_gf4_matrix, gf4_mul, SmallField, OMEGA, OMEGA2};
use crate::{DigitalSequence, SeqError};
use gartowen_core::{Gf2Matrix, PowerOfTwoBase, Width};

/// U = `[[1,1],[0,1]]` on a 2-bit digit (row 0 = x0 + x1, row 1 = x1).
pub fn u_matrix() -> Gf2Matrix {
    Gf2Matrix::from_rows(2, &[0b11, 0b10]).expect("2×2")
}

/// E(α): the 4×4 binary expansion of the GF(4) matrix [[1, α], [0, 1]], entry (2i+u, 2j+v) =
/// `M4(G[i][j])[u][v]`.
pub fn e_matrix(alpha: u32) -> Gf2Matrix {
    expand_gf4_matrix([[1, alpha], [0, 1]])
}

/// blockdiag(U, U) on a 4-bit digit.
fn uu_matrix() -> Gf2Matrix {
    Gf2Matrix::from_rows(4, &[0b0011, 0b0010, 0b1100, 0b1000]).expect("4×4")
}

/// The four GF(4) elements (0, 1, ω, ω²) indexed by k.
const ALPHA: [u32; 4] = [0, 1, OMEGA, OMEGA2];

/// Maximum dimensions of sz4.
pub const SZ4_DIMS: usize = 4;
/// Maximum dimensions of sz16.
pub const SZ16_DIMS: usize = 16;

/// The field element and output transform of sz4 dimension j.
pub fn sz4_parameters(j: usize) -> (u32, Gf2Matrix) {
    let d = if j % 2 == 1 {
        u_matrix()
    } else {
        Gf2Matrix::identity(2).expect("2×2")
    };
    (ALPHA[j], d)
}

/// The field element a_j = α_k² + β·y and output transform D_j of sz16 dimension j = 4β + k.
pub fn sz16_parameters(j: usize) -> (u32, Gf2Matrix) {
    let (beta, k) = ((j / 4) as u32, j % 4);
    let alpha = ALPHA[k];
    let a = gf4_mul(alpha, alpha) | (beta << 2);
    let e = e_matrix(alpha);
    let d = if alpha == 1 || alpha == OMEGA2 {
        uu_matrix().mul(&e)
    } else {
        e
    };
    (a, d)
}

fn build(
    name: &str,
    field: SmallField,
    params: fn(usize) -> (u32, Gf2Matrix),
    max: usize,
    dims: usize,
    width: Width,
) -> Result<DigitalSequence, SeqError> {
    if dims == 0 {
        return Err(SeqError::NoDimensions);
    }
    if dims > max {
        return Err(SeqError::TooManyDimensions {
            sequence: name.into(),
            requested: dims,
            max,
        });
    }
    let cols: Vec<Vec<u64>> = (0..dims)
        .map(|j| {
            let (a, d) = params(j);
            pascal_columns(field, a, &d, width, width.bits())
        })
        .collect();
    let base = PowerOfTwoBase::from_q(field.q()).expect("q ≤ 4");
    DigitalSequence::from_columns(name, width, base, &cols)
}

/// The first `dims` (≤ 4) dimensions of sz4 with W-bit words and W index bits.
pub fn sz4(dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
    build(
        "sz4",
        SmallField::Gf4,
        sz4_parameters,
        SZ4_DIMS,
        dims,
        width,
    )
}

/// The first `dims` (≤ 16) dimensions of sz16 with W-bit words and W index bits.
pub fn sz16(dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
    build(
        "sz16",
        SmallField::Gf16,
        sz16_parameters,
        SZ16_DIMS,
        dims,
        width,
    )
}
