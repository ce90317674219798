//! The SZ sequences (`docs/design.md` §2).
//!
//! * `sz4`: the published 4-D SZ sequence (Ahmed, Pharr, Ostromoukhov, Huang, "SZ Sequences:
//!   Binary-Based (0,2^q)-Sequences", ACM TOG 44(6), 2025), bit for bit as public sources fix
//!   it: dimension 0 the identity, dimension 1 the binary Pascal matrix P, dimension 2 P4(β)
//!   (2×2 blocks β^(J−I) where binom(J, I) is odd, β = `[[1,1],[1,0]]`), dimension 3
//!   P·P4(β) = diag(U)·P4(α), α = `[[0,1],[1,1]]`, U = `[[1,1],[0,1]]`. In GF(4) terms: the
//!   Faure matrices of a = 0, 1, ω², ω with output transforms D = I, U, I, U (β is the matrix
//!   of ω², α of ω).
//! * `sz16`: a (0,16)-sequence in base 16 whose first quad is `sz4`. How the paper ensembles
//!   four quads is not public; the other quads are gartowen's own: dimension j = 4β + k uses
//!   a_j = α_k² + β·y with α_k = `(0, 1, ω², ω)[k]` and D_j = blockdiag(U,U)·E(α_k) for odd k,
//!   else E(α_k), where E(α) is the binary expansion of the GF(4) matrix [[1, α], [0, 1]].
//! * `sz4-faure`, `sz16-faure`: gartowen's earlier reconstructions (α_k = `(0, 1, ω, ω²)[k]`),
//!   kept so that older results can be reproduced. Their dimensions 2 and 3 use the other
//!   generator of GF(4)* and differ from the published SZ from point 4 on.

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

/// The GF(4) elements of the published SZ quad, indexed by k: (0, 1, ω², ω).
const ALPHA: [u32; 4] = [0, 1, OMEGA2, OMEGA];
/// The GF(4) elements of the earlier reconstruction (`sz4-faure`, `sz16-faure`): (0, 1, ω, ω²).
const ALPHA_FAURE: [u32; 4] = [0, 1, OMEGA, OMEGA2];

/// Maximum dimensions of sz4.
pub const SZ4_DIMS: usize = 4;
/// Maximum dimensions of sz16.
pub const SZ16_DIMS: usize = 16;

/// The field element and output transform of sz4 dimension j: a = (0, 1, ω², ω)[j],
/// D = I for even j, U for odd j.
pub fn sz4_parameters(j: usize) -> (u32, Gf2Matrix) {
    quad_parameters(&ALPHA, j)
}

/// [`sz4_parameters`] of the earlier reconstruction `sz4-faure`: a = (0, 1, ω, ω²)[j].
pub fn sz4_faure_parameters(j: usize) -> (u32, Gf2Matrix) {
    quad_parameters(&ALPHA_FAURE, j)
}

fn quad_parameters(alpha: &[u32; 4], j: usize) -> (u32, Gf2Matrix) {
    let d = if j % 2 == 1 {
        u_matrix()
    } else {
        Gf2Matrix::identity(2).expect("2×2")
    };
    (alpha[j], d)
}

/// The field element a_j = α_k² + β·y and output transform D_j of sz16 dimension j = 4β + k,
/// α_k = (0, 1, ω², ω)[k].
pub fn sz16_parameters(j: usize) -> (u32, Gf2Matrix) {
    ensemble_parameters(&ALPHA, j)
}

/// [`sz16_parameters`] of the earlier reconstruction `sz16-faure`: α_k = (0, 1, ω, ω²)[k].
pub fn sz16_faure_parameters(j: usize) -> (u32, Gf2Matrix) {
    ensemble_parameters(&ALPHA_FAURE, j)
}

fn ensemble_parameters(alphas: &[u32; 4], j: usize) -> (u32, Gf2Matrix) {
    let (beta, k) = ((j / 4) as u32, j % 4);
    let alpha = alphas[k];
    let a = gf4_mul(alpha, alpha) | (beta << 2);
    let e = e_matrix(alpha);
    // U on each 2-bit half for the odd dimensions of a quad (the Pascal-image member of each
    // binary pair), as in the quad.
    let d = if k % 2 == 1 { uu_matrix().mul(&e) } else { e };
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

/// The first `dims` (≤ 4) dimensions of sz4 (the published 4-D SZ) with W-bit words and W
/// index bits.
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

/// The earlier reconstruction of sz4 (`sz4-faure`).
pub fn sz4_faure(dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
    build(
        "sz4-faure",
        SmallField::Gf4,
        sz4_faure_parameters,
        SZ4_DIMS,
        dims,
        width,
    )
}

/// The earlier reconstruction of sz16 (`sz16-faure`).
pub fn sz16_faure(dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
    build(
        "sz16-faure",
        SmallField::Gf16,
        sz16_faure_parameters,
        SZ16_DIMS,
        dims,
        width,
    )
}
