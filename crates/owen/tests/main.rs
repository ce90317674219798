//! The integration tests of this package, one module per concern, built as one test binary.

mod full_tree;
mod golden;
mod statistics;
