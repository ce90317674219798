//! The integration tests of this package, one module per concern, built as one test binary
//! (one link instead of one per file).

mod art_golden;
mod batch_paths;
mod docs_paths;
mod expected_discrepancy;
mod external;
mod extracted_checker;
mod extracted_checker_large;
mod extracted_differential;
mod extracted_rank;
mod f32_exhaustive;
mod house_check;
mod joint_laws;
mod non_dyadic;
mod owen_variance;
mod owned_check;
mod prerequisites;
mod proof_reuse;
mod radix_battery;
mod randomization_quality;
mod request_table;
mod scrambled_nets;
mod shared_requests;
mod slurm_scripts;
mod theorems;
mod verify;
mod witness;
mod word_sweep;
