//! Helpers every test module of this binary shares.

use std::process::{Command, Output};

/// Runs the `gartowen` binary built for these tests with `args`, capturing its output.
pub fn gartowen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .output()
        .expect("the gartowen binary runs")
}
