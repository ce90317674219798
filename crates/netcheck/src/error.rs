//! The checker's typed error.

use std::fmt;

/// Errors from checker inputs; each names the offending value.
#[derive(Debug, Clone, PartialEq)]
pub enum NetError {
    /// Base below 2.
    BaseTooSmall(u64),
    /// A base that must be 2^q (rank path) but is not.
    NotPowerOfTwo(u64),
    /// The point count is not b^m for the requested or implied m.
    NotAPowerOfBase {
        /// The point count.
        n: usize,
        /// The base b.
        base: u64,
    },
    /// N ≠ b^m for an explicit m.
    WrongCount {
        /// The point count.
        n: usize,
        /// The base b.
        base: u64,
        /// The m asked for.
        m: u32,
    },
    /// t > m.
    TooLargeT {
        /// The t asked for.
        t: u32,
        /// The net's m.
        m: u32,
    },
    /// No points.
    Empty,
    /// Zero dimensions, or rows of differing length.
    BadShape(String),
    /// A coordinate that is NaN, outside [0,1) or not an exact dyadic; names point and dimension.
    BadValue {
        /// Point index.
        point: usize,
        /// Dimension index.
        dim: usize,
        /// What is wrong with the value.
        reason: String,
    },
    /// A dimension index past the point set's dimensions.
    NoSuchDimension {
        /// The dimension asked for.
        dim: usize,
        /// The point set's dimensions.
        dims: usize,
    },
    /// Too many shapes to enumerate.
    TooManyShapes {
        /// Shapes the request needs.
        shapes: u128,
        /// The most allowed.
        limit: u128,
    },
    /// The shapes would take more memory than [`crate::shapes::SHAPE_BYTES_LIMIT`] (each holds
    /// one digit count per dimension).
    ShapesTooLarge {
        /// Shapes the request needs.
        shapes: u128,
        /// Dimensions of each shape.
        dims: usize,
        /// Bytes they would take.
        bytes: u128,
        /// The most allowed, in bytes.
        limit: u128,
    },
    /// Generator matrices too large for the rank path (more than 64 columns or rows used).
    TooManyBits {
        /// Bits the rank path would need.
        bits: u32,
    },
    /// A projection list that could not be parsed.
    BadProjection(String),
}

impl fmt::Display for NetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NetError::BaseTooSmall(b) => write!(f, "base {b} is below 2"),
            NetError::NotPowerOfTwo(b) => {
                write!(
                    f,
                    "base {b} is not 2^q with q in 1..=8, which the rank path needs"
                )
            }
            NetError::NotAPowerOfBase { n, base } => {
                write!(
                    f,
                    "{n} points is not a power of the base {base}; state m (the command line's --m, Python's m=) or use b^m points"
                )
            }
            NetError::WrongCount { n, base, m } => {
                write!(
                    f,
                    "{n} points, but a net with base {base} and m = {m} has {base}^{m} points"
                )
            }
            NetError::TooLargeT { t, m } => write!(f, "t = {t} is larger than m = {m}"),
            NetError::Empty => write!(f, "the point set is empty"),
            NetError::BadShape(s) => write!(f, "{s}"),
            NetError::BadValue { point, dim, reason } => {
                write!(f, "point {point}, dimension {dim}: {reason}")
            }
            NetError::NoSuchDimension { dim, dims } => {
                write!(f, "dimension {dim} does not exist (the set has {dims})")
            }
            NetError::ShapesTooLarge {
                shapes,
                dims,
                bytes,
                limit,
            } => write!(
                f,
                "{shapes} shapes of {dims} dimensions need {bytes} bytes, more than {limit}; \
                 check projections instead"
            ),
            NetError::TooManyShapes { shapes, limit } => write!(
                f,
                "{shapes} shapes to check exceeds the limit {limit}; check projections instead"
            ),
            NetError::TooManyBits { bits } => {
                write!(
                    f,
                    "the rank path handles at most 64 index bits, {bits} requested"
                )
            }
            NetError::BadProjection(s) => write!(f, "bad projection list: {s}"),
        }
    }
}

impl std::error::Error for NetError {}
