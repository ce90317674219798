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

/// The field element and output transform of sz4 dimension j: a = `(0, 1, ω², ω)[j]`,
/// D = I for even j, U for odd j.
pub fn sz4_parameters(j: usize) -> (u32, Gf2Matrix) {
    quad_parameters(&ALPHA, j)
}

/// [`sz4_parameters`] of the earlier reconstruction `sz4-faure`: a = `(0, 1, ω, ω²)[j]`.
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

/// The field element and output transform of sz16 dimension j = 4β + k: member k of quad β
/// of [`SZ16_QUADS`].
pub fn sz16_parameters(j: usize) -> (u32, Gf2Matrix) {
    SZ16_QUADS[j / 4].member(j % 4)
}

/// [`sz16_parameters`] of the earlier reconstruction `sz16-faure`: quad β is the alphabet
/// (0, 1, ω, ω²) in coset γ = β·y, no outer transform.
pub fn sz16_faure_parameters(j: usize) -> (u32, Gf2Matrix) {
    QuadChoice {
        alphabet: ALPHA_FAURE,
        gamma: ((j / 4) as u32) << 2,
        outer: IDENTITY_2,
    }
    .member(j % 4)
}

/// One quad of a 16-D ensemble: a GF(4) alphabet (α_0..α_3), a coset γ of GF(4) in GF(16),
/// and a 2×2 binary matrix g applied to each 2-bit half of every output digit.
///
/// Member k has a = α_k² + γ (addition in GF(16) is XOR of the encodings) and output
/// transform blockdiag(g,g)·D_k, D_k = blockdiag(U,U)·E(α_k) for odd k, else E(α_k), where
/// E(α) is the binary expansion of the GF(4) matrix [[1, α], [0, 1]]. Every γ keeps the
/// quad's properties (its matrices are those of γ = 0 times the same Faure matrix P16(γ) on
/// the right, which keeps the span of every set of leading columns); g keeps base-4 and
/// base-16 nets (a bijection of each base-4 output digit), and the binary pairs are checked.
/// The quads of one ensemble need γ's with distinct y-coefficients.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct QuadChoice {
    /// α_0..α_3 in GF(4): [`SZ_ALPHABET`] or [`FAURE_ALPHABET`].
    pub alphabet: [u32; 4],
    /// γ in GF(16) (the encoding of [`crate::field`]).
    pub gamma: u32,
    /// g, packed as by `Gf2Matrix::packed` (2×2, invertible).
    pub outer: u64,
}

impl QuadChoice {
    /// The GF(16) element and the 4×4 output transform of member k (0..4).
    pub fn member(&self, k: usize) -> (u32, Gf2Matrix) {
        let alpha = self.alphabet[k];
        let a = gf4_mul(alpha, alpha) ^ self.gamma;
        let e = e_matrix(alpha);
        // U on each 2-bit half for the odd member of each binary pair, as in the quad.
        let d = if k % 2 == 1 { uu_matrix().mul(&e) } else { e };
        let g = Gf2Matrix::from_packed(2, self.outer).expect("a 2×2 matrix");
        let gg = Gf2Matrix::from_rows(4, &[g.row(0), g.row(1), g.row(0) << 2, g.row(1) << 2])
            .expect("4×4");
        (a, gg.mul(&d))
    }
}

/// The published quad's alphabet (0, 1, ω², ω).
pub const SZ_ALPHABET: [u32; 4] = ALPHA;
/// The earlier reconstruction's alphabet (0, 1, ω, ω²).
pub const FAURE_ALPHABET: [u32; 4] = ALPHA_FAURE;

/// The identity, packed.
const IDENTITY_2: u64 = 0x0201;
/// β = [[1,1],[1,0]] (multiplication by ω² in GF(4)), packed.
const BETA_2: u64 = 0x0103;

/// sz16's quads. Quad 0 is the published 4-D SZ. Quads 1–3 are gartowen's own, found by
/// `crates/netcheck/examples/sz16_search.rs` over every alphabet, coset and g that keep the
/// stated properties: the worst binary t-value over all 120 pairs and every m ≤ 16 is 5 (the
/// earlier construction had 6), reached by 24 pairs (record/2026-12-03-sz.md).
pub const SZ16_QUADS: [QuadChoice; 4] = [
    QuadChoice {
        alphabet: ALPHA,
        gamma: 0,
        outer: IDENTITY_2,
    },
    QuadChoice {
        alphabet: ALPHA,
        gamma: 6,
        outer: BETA_2,
    },
    QuadChoice {
        alphabet: ALPHA,
        gamma: 9,
        outer: BETA_2,
    },
    QuadChoice {
        alphabet: ALPHA,
        gamma: 15,
        outer: IDENTITY_2,
    },
];

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
