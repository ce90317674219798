//! Core arithmetic of gartowen: W-bit words, base-2^q digits, packed permutations,
//! GF(2) matrices, counter-based hashing, float conversion and the [`Scrambler`] trait.
//!
//! Everything here is dependency-free, and the per-word paths do not allocate.
//! Conventions follow `docs/design.md` §1: a coordinate is a W-bit word `x` whose value is
//! `x · 2^-W`; digit 0 is the most significant digit.

pub mod claim;
pub mod digits;
pub mod error;
pub mod float;
pub mod gf2;
pub mod hash;
pub mod names;
pub mod perm;
pub mod progress;
pub mod radix;
pub mod registry;
pub mod scrambler;
pub mod sha256;
pub mod width;

pub use claim::{Claim, NodeGroup};
pub use digits::{DigitLayout, PowerOfTwoBase};
pub use error::CoreError;
pub use float::{word_from_f64, word_from_f64_floor, word_to_f32, word_to_f64};
pub use gf2::Gf2Matrix;
pub use hash::{derive_seed, hash_words, mix64, SplitMix64};
pub use names::UnknownName;
pub use perm::{fisher_yates, Permutation};
pub use progress::{Progress, Silent};
pub use radix::{Radix, RadixLayout, RadixScrambler};
pub use registry::{BuildContext, Registry, ScramblerRequest, ScramblerSpec};
pub use scrambler::{
    invert_nested, Identity, Scrambler, ScramblerExt, Unscramble, U32_BATCH_CHUNK,
};
pub use width::Width;
