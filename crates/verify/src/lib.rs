//! The gartowen conformance battery: is this sampler really an Owen scramble, and how close is
//! an imitation?
//!
//! What the battery runs is declared in two lists, each module stating its claim, statistic,
//! level and power in its doc:
//! * [`structure::STRUCTURE_CHECKS`]: inverse or injectivity, nestedness, net preservation
//!   ([`nets`]), `--expect`;
//! * [`law_runner::FAMILIES`], each a [`family::LawFamily`]: [`marginal`] (each node
//!   permutation uniform over the claimed group, by depth), [`pair_law`], [`flip_rank`] and
//!   [`collisions`] (joint laws of nodes), [`pair_lemma`] (Owen's pair lemma, end to end) and
//!   [`dimensions`] (distinct and independent dimensions).
//!
//! Every size comes from the level's plan ([`level::LEVEL_PLANS`]). [`battery`] orchestrates,
//! [`judge`] turns sub-tests into verdicts, [`verdict`] and [`subtest`] are the vocabulary.
//! [`word_sweep`] checks bijectivity and nestedness on every word of a dimension (W ≤ 32).
//! [`stats`] holds the tests' distributions, [`external`] speaks to external programs, and
//! [`certificate`] is the JSON envelope.

pub mod audit;
pub mod battery;
pub mod candidate;
pub mod certificate;
pub mod collisions;
pub mod diagonal_cells;
pub mod dimensions;
pub mod equivalence;
pub mod error;
pub mod expected;
pub mod family;
pub mod flip_rank;
pub mod judge;
pub mod junit;
pub mod law_runner;
pub mod level;
pub mod listing;
pub mod marginal;
pub mod nets;
pub mod owen_equivalence;
pub mod pair_law;
pub mod pair_lemma;
pub mod radix_nets;
pub mod radix_words;
pub mod request_log;
pub mod sampling;
pub mod stats;
pub mod structure;
pub mod subtest;
pub mod time_profile;
pub mod top_bits;
pub mod verdict;
pub mod word_sweep;

pub use gartowen_core::{Claim, NodeGroup};
/// External programs speaking the scrambling protocol (the `gartowen-external` crate).
pub use gartowen_external as external;
pub use gartowen_external::pool as external_pool;
