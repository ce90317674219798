//! Discrepancy of W-bit point sets (`DESIGN.md` §5): L2-star (Warnock), centered (CD),
//! wrap-around (WD) and generalized L2 (GL2), each by four methods.
//!
//! Every kind has the form D² = c0 + c1·(1/N)Σ_i Π_k s(x_ik) + c2·(1/N²)Σ_i Σ_j Π_k p(x_ik, x_jk).
//! All functions return the **squared** discrepancy D² (`squared: true`); take the square root
//! for D. (SciPy's `qmc.discrepancy` returns the root for L2-star but D² for CD and WD.)
//!
//! * `naive`: plain f64 sums over the full double sum, as the usual tools do.
//! * `compensated`: error-free products and double-double (compensated) accumulation over the
//!   symmetric half of the double sum, in parallel over fixed chunks combined in a fixed order,
//!   so the f64 result is bit-identical for any thread count.
//! * `exact`: points are dyadic, so every term is an integer over a power of two; the sums are
//!   computed in exact integers and combined into an exact rational, with a correctly rounded f64.
//! * `fast`: 2-D L2-star in O(N log N) (sort by x, Fenwick tree over y ranks), in exact integers.

pub mod choice;
pub mod compensated;
pub mod curves;
mod dd;
pub mod exact;
pub mod expected;
pub mod fast2d;
pub mod kinds;
mod limbs;
pub mod naive;
pub mod rational;

pub use kinds::Kind;

use gartowen_core::Width;
use num_rational::BigRational;
use serde::Serialize;

/// Points as W-bit words, row-major: point i, dimension k at `words[i·d + k]`.
#[derive(Debug, Clone, Copy)]
pub struct Points<'a> {
    /// The words.
    pub words: &'a [u64],
    /// Dimensions d.
    pub dims: usize,
    /// Word width.
    pub width: Width,
}

impl<'a> Points<'a> {
    /// Number of points N.
    pub fn len(&self) -> usize {
        self.words.len() / self.dims
    }

    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.words.is_empty()
    }

    /// Every coordinate as f64 (exact for W ≤ 53, truncated to 53 bits above), row-major.
    pub fn to_f64(&self) -> Vec<f64> {
        self.words
            .iter()
            .map(|&w| gartowen_core::word_to_f64(w, self.width))
            .collect()
    }

    /// Point i.
    #[inline(always)]
    pub fn point(&self, i: usize) -> &'a [u64] {
        &self.words[i * self.dims..(i + 1) * self.dims]
    }
}

/// The method that computed a value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Plain f64.
    Naive,
    /// Compensated (double-double) sums.
    Compensated,
    /// Exact rational.
    Exact,
    /// O(N log N) 2-D L2-star, exact integers.
    Fast,
}

/// A computed squared discrepancy.
#[derive(Debug, Clone, PartialEq)]
pub struct Discrepancy {
    /// Kind.
    pub kind: Kind,
    /// Method.
    pub method: Method,
    /// D² as f64 (correctly rounded for exact and fast).
    pub value: f64,
    /// The exact rational D², for exact and fast.
    pub exact: Option<BigRational>,
    /// A bound on |value − D²| / D² where one is known (for exact and fast: 0 when the f64
    /// is D² exactly, else 2^-53, the rounding of a correctly rounded value).
    pub rel_error_bound: Option<f64>,
}
