//! The integration tests of this package, one module per concern, built as one test binary
//! (one link instead of one per file).

mod adversarial;
mod art;
mod certificates;
mod check;
mod check_witness;
mod clobbering;
mod containment;
mod discrepancy;
mod generate;
mod inspect_radix;
mod junit;
mod list_requests;
mod oracle;
mod radix_points;
mod readme;
mod render;
mod report;
mod scene;
mod scramble;
mod stdout_errors;
mod support;
mod sweep;
mod verify;
mod verify_bits;
mod verify_declared;
mod verify_dims;
mod verify_external;
mod verify_radix;
