//! Discrepancy of W-bit point sets (`docs/design.md` §5): L2-star (Warnock), centered (CD),
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

mod bound;
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
mod unreduced;

pub use kinds::Kind;

use gartowen_core::Width;
use num_rational::BigRational;
use serde::Serialize;

/// The most significant fractional bits a coordinate may have for the float methods' error
/// bounds to hold (a 52-bit coordinate already rounds in CD's pair factor).
pub const EXACT_FLOAT_BITS: u32 = 50;

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

    /// Whether every coordinate has at most [`EXACT_FLOAT_BITS`] significant fractional bits,
    /// the headroom the float methods' error bounds assume (their factors, such as CD's
    /// 1 + |x − ½|/2 + |y − ½|/2 − |x − y|/2, are then exact in f64). Always true for W ≤ 50;
    /// for 64-bit words, when the low 14 bits are zero. Otherwise the naive and compensated
    /// methods report no bound, and `auto` computes exactly.
    ///
    /// ```
    /// use gartowen_core::Width;
    /// use gartowen_discrepancy::Points;
    /// fn p(w: &[u64]) -> Points<'_> { Points { words: w, dims: 1, width: Width::W64 } }
    /// assert!(p(&[1 << 14, 0]).exact_in_f64());
    /// assert!(!p(&[(1 << 14) | (1 << 12)]).exact_in_f64());
    /// ```
    pub fn exact_in_f64(&self) -> bool {
        let w = self.width.bits();
        w <= EXACT_FLOAT_BITS || {
            let low = (1u64 << (w - EXACT_FLOAT_BITS)) - 1;
            self.words.iter().all(|&x| x & low == 0)
        }
    }

    /// The float methods' `bound` for `value`, when its assumptions hold: exact coordinates
    /// ([`Points::exact_in_f64`]; truncated 64-bit words void it) and a value in f64's normal
    /// range (in high dimensions c0 and the sums overflow or underflow). Else no bound.
    pub(crate) fn float_bound(&self, value: f64, bound: f64) -> Option<f64> {
        (self.exact_in_f64() && value.is_normal() && bound.is_finite()).then_some(bound)
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
