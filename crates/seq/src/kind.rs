//! The built-in sequences by name.

use crate::{sobol, sz, DigitalSequence, SeqError};
use gartowen_core::{PowerOfTwoBase, Width};
use std::str::FromStr;

/// A built-in sequence: `sobol`, `sz4` or `sz16`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SequenceKind {
    /// Sobol with Joe–Kuo 6.21201 direction numbers (base 2).
    Sobol,
    /// SZ-style (0,4)-sequence in base 4, 4 dimensions.
    Sz4,
    /// SZ-style (0,16)-sequence in base 16, 16 dimensions.
    Sz16,
}

impl SequenceKind {
    /// Every built-in sequence.
    pub const ALL: [SequenceKind; 3] = [SequenceKind::Sobol, SequenceKind::Sz4, SequenceKind::Sz16];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            SequenceKind::Sobol => "sobol",
            SequenceKind::Sz4 => "sz4",
            SequenceKind::Sz16 => "sz16",
        }
    }

    /// The base the sequence is built for; scramblers default to it.
    pub fn base(self) -> PowerOfTwoBase {
        match self {
            SequenceKind::Sobol => PowerOfTwoBase::B2,
            SequenceKind::Sz4 => PowerOfTwoBase::B4,
            SequenceKind::Sz16 => PowerOfTwoBase::B16,
        }
    }

    /// The largest number of dimensions defined.
    pub fn max_dims(self) -> usize {
        match self {
            SequenceKind::Sobol => sobol::MAX_DIMS,
            SequenceKind::Sz4 => sz::SZ4_DIMS,
            SequenceKind::Sz16 => sz::SZ16_DIMS,
        }
    }

    /// The first `dims` dimensions with `width`-bit words.
    pub fn build(self, dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
        match self {
            SequenceKind::Sobol => sobol::sequence(dims, width),
            SequenceKind::Sz4 => sz::sz4(dims, width),
            SequenceKind::Sz16 => sz::sz16(dims, width),
        }
    }
}

impl FromStr for SequenceKind {
    type Err = SeqError;
    fn from_str(s: &str) -> Result<Self, SeqError> {
        SequenceKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| SeqError::UnknownSequence(s.to_string()))
    }
}
