//! The gartowen conformance battery: is this sampler really an Owen scramble, and how close is
//! an imitation?
//!
//! One module per test family, each stating its claim, statistic, level and power in its doc:
//! * structure ([`battery`]): inverse or injectivity, nestedness, net preservation, `--expect`;
//! * [`marginal`]: each node permutation uniform over the claimed group, by depth;
//! * [`joint`]: pairs of nodes, GF(2) relations between node flips, subtree collisions;
//! * [`pair_lemma`]: Owen's pair lemma, end to end;
//! * [`dimensions`]: distinct and independent dimensions.
//!
//! [`word_sweep`] checks bijectivity and nestedness on every word of a dimension (W ≤ 32).
//!
//! [`laws`] runs the law families on a candidate, [`stats`] holds the tests' distributions,
//! [`external`] speaks to external programs, and [`certificate`] is the JSON envelope.

pub mod battery;
pub mod certificate;
pub mod dimensions;
pub mod equivalence;
pub mod external;
pub mod external_pool;
pub mod joint;
pub mod junit;
pub mod law;
pub mod laws;
pub mod marginal;
pub mod nets;
pub mod owen_equivalence;
pub mod pair_lemma;
pub mod pipe_holders;
pub mod sampling;
pub mod stats;
pub mod word_sweep;

pub use gartowen_core::{Claim, NodeGroup};
