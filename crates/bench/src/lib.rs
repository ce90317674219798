//! Speed against error: integrands with exact integrals, the RMSE harness over every sequence
//! and scrambler, point-set spectra, and the `gartowen report` figures and tables.

pub mod curves;
pub mod equivalence;
pub mod fidelity;
pub mod figures;
pub mod harness;
pub mod integrands;
pub mod report;
pub mod scene;
pub mod spectrum;
pub mod speed;
pub mod staged;
pub mod tradeoff;
