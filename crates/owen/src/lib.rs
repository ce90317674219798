//! The exact full-tree Owen scramble in base 2^q, tuned for speed, and in every other base
//! ([`radix_tree`]): the `owen-oracle` registry
//! entries. Every node permutation is drawn independently from its node's key, so this is an
//! Owen scramble by construction; the speed comes from how keys and draws are computed
//! (incremental keys, base-2 tiles of six levels, one-word Fisher–Yates, 4-lane batches).
//! `gartowen_oracles::owen_definition` is the same scramble written as its definition reads,
//! and the two are tested equal bit for bit.

pub mod full_tree;
pub mod node_draw;
pub mod radix_tree;
pub mod registry;

pub use full_tree::{FullTreeOwen, OwenVariant};
pub use radix_tree::{RadixOwen, RadixVariant};
