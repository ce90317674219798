//! The sequence crate's typed error.

use std::fmt;

/// Errors from building or indexing sequences; each names the bad value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SeqError {
    /// Zero dimensions requested.
    NoDimensions,
    /// More dimensions than the sequence defines.
    TooManyDimensions {
        /// The sequence's name.
        sequence: String,
        /// Dimensions asked for.
        requested: usize,
        /// Dimensions it defines.
        max: usize,
    },
    /// A sequence name that does not exist.
    UnknownSequence(String),
    /// An index at or past 2^(index bits).
    IndexOutOfRange {
        /// The index given.
        index: u64,
        /// Index bits the sequence has.
        index_bits: u32,
    },
    /// A word width that the sequence does not support.
    UnsupportedWidth {
        /// The sequence's name.
        sequence: String,
        /// The width asked for, in bits.
        bits: u32,
    },
    /// An element outside the field, or a field size that is not built in.
    InvalidField(String),
}

impl fmt::Display for SeqError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SeqError::NoDimensions => write!(f, "the number of dimensions must be at least 1"),
            SeqError::TooManyDimensions {
                sequence,
                requested,
                max,
            } => write!(
                f,
                "{sequence} defines at most {max} dimensions, {requested} requested"
            ),
            SeqError::UnknownSequence(name) => {
                write!(
                    f,
                    "unknown sequence '{name}'; known: sobol, sz4, sz16, faure:base=B \
                     (B = 2, 4, …, 256), faure-net:base=B:m=M"
                )
            }
            SeqError::IndexOutOfRange { index, index_bits } => write!(
                f,
                "index {index} is past the last point 2^{index_bits} - 1 of this sequence"
            ),
            SeqError::UnsupportedWidth { sequence, bits } => {
                write!(f, "{sequence} does not support {bits}-bit words")
            }
            SeqError::InvalidField(msg) => write!(f, "{msg}"),
        }
    }
}

impl std::error::Error for SeqError {}
