//! Digital sequences with random access: Sobol (Joe–Kuo 6.21201), SZ-style universal
//! sequences `sz4`/`sz16`, and the Faure-over-GF(2^q) builder they are made from.
//!
//! Conventions (`docs/design.md` §2): generator matrix C_j is stored as columns, each a W-bit word
//! with row 0 in the most significant bit; point n has x_j(n) = XOR of the columns c of C_j
//! over the set bits c of n (bit 0 = least significant bit of the index).

pub mod binary_field;
mod digital;
mod error;
pub mod faure;
pub mod field;
mod gray;
mod kind;
pub mod radix;
pub mod sobol;
pub mod sz;
mod tables;

pub use digital::DigitalSequence;
pub use error::SeqError;
pub use gray::{gray_code, GrayCodeIter};
pub use kind::{Provenance, SequenceKind};
pub use tables::LookupTables;
