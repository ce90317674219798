//! The integration tests of this package, one module per concern, built as one test binary
//! (one link instead of one per file).

mod batch;
mod composed;
mod grammar;
mod nets;
mod pair_law;
mod record;
mod scramblers;
