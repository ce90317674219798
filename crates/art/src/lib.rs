//! ART-Owen scrambling in bases 2^q (`docs/design.md` §3.2–3.4): the Thue–Morse ART grammar, the
//! ART-Owen family (binary, Q-ART, base 8, base 16, matrix, translation-only) and hash-based
//! peers, all behind the shared `Scrambler` trait.
//!
//! This is gartowen's reconstruction from the papers' text, frozen by golden vectors; it is not
//! the authors' code.

pub mod composed;
mod dims;
pub mod engine;
pub mod grammar;
pub mod keyed;
#[cfg(feature = "mutants")]
pub mod mutants;
pub mod pair_law;
pub mod peers;
pub mod record;
pub mod registry;
pub mod variants;

pub use composed::QArtComposed;
pub use engine::{
    ArtOwen, BatchKernel, BATCH_TABLES_AFTER_WORDS, BATCH_TABLE_BYTES, STEP_TABLES_AFTER_WORDS,
};
pub use grammar::Grammar;
pub use keyed::KeyedArt;
#[cfg(feature = "mutants")]
pub use mutants::{ArtMutant, TailUntranslated};
pub use record::ArtRecord;
pub use variants::ArtVariant;
