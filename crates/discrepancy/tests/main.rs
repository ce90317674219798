//! The integration tests of this package, one module per concern, built as one test binary
//! (one link instead of one per file).

mod bound;
mod choice;
mod curves;
mod definition;
mod exactness;
