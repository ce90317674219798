//! The integration tests of this package, one module per concern, built as one test binary
//! (one link instead of one per file).

mod common;
mod figures;
mod harness;
mod integrands;
mod report;
mod report_full_disk;
mod scene;
