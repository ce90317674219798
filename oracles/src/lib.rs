//! Exact, readable reference implementations that the fast paths are judged against.
//! Readable before fast: each one is the definition, written out.

pub mod box_counting;
pub mod discrepancy_integral;
pub mod exact_discrepancy;
pub mod exact_laws;
pub mod inspector;
pub mod owen_definition;
pub mod owen_variance;
pub mod radix_inspector;

pub use owen_definition::scramble_with_nodes;
