//! Exact, readable reference implementations that the fast paths are judged against.
//! Readable before fast: each one is the definition, written out.

pub mod box_counting;
pub mod exact_discrepancy;
pub mod exact_laws;
pub mod full_tree;
pub mod inspector;
pub mod node_draw;
pub mod owen_definition;
pub mod owen_variance;
pub mod registry;

pub use full_tree::{scramble_with_nodes, FullTreeOwen, OwenVariant};
