//! `gartowen verify`: the conformance battery over the registry or named implementations.

use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::verify::{verify, Level, Verdict};
use std::path::PathBuf;
use std::process::ExitCode;

/// Battery size.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum LevelArg {
    /// Under a minute for the whole registry on 2 cores.
    Quick,
    /// Larger samples and deeper nets.
    Full,
}

/// Run the conformance battery: inverse, nestedness (inspector), net preservation in the
/// scrambling base, and the node-permutation law against uniform S_b (a verdict only for
/// implementations that claim nested uniformity; a measured distance for the others).
///
/// Prints a table (implementation × check) and exits 1 if any check fails, 2 on bad usage.
///
/// Examples:
///   gartowen verify --level quick
///   gartowen verify --impl art-owen-16p --impl lk-hash --json verify.json
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct VerifyArgs {
    /// Battery size.
    #[arg(long, value_enum, default_value_t = LevelArg::Quick)]
    pub level: LevelArg,
    /// Implementations to verify (registry names, with options); default: all.
    #[arg(long = "impl")]
    pub implementations: Vec<String>,
    /// Also write the report as JSON to this file.
    #[arg(long)]
    pub json: Option<PathBuf>,
}

/// Runs `verify`.
pub fn run(a: VerifyArgs) -> Result<ExitCode, CliError> {
    let level = match a.level {
        LevelArg::Quick => Level::Quick,
        LevelArg::Full => Level::Full,
    };
    let registry = gartowen::registry();
    let reports = verify(&registry, &a.implementations, level)?;
    println!(
        "{:<26} {:<12} {:<12} {:<12} {:<13} node-law detail",
        "implementation", "inverse", "nested", "nets", "node-law"
    );
    for r in &reports {
        let cell = |i: usize| {
            format!(
                "{:?} {:.0}ms",
                r.checks[i].verdict,
                r.checks[i].seconds * 1e3
            )
            .to_lowercase()
        };
        println!(
            "{:<26} {:<12} {:<12} {:<12} {:<13} {}",
            r.name,
            cell(0),
            cell(1),
            cell(2),
            cell(3),
            r.checks[3].detail
        );
        for c in r.checks.iter().filter(|c| c.verdict == Verdict::Fail) {
            println!("    FAIL {}: {}", c.check, c.detail);
        }
    }
    let failed = reports.iter().filter(|r| r.failed()).count();
    println!("{} implementations, {failed} with failures", reports.len());
    if let Some(path) = &a.json {
        let doc = serde_json::json!({
            "tool": "gartowen", "version": env!("CARGO_PKG_VERSION"), "command": "verify",
            "level": level, "implementations": reports,
        });
        crate::output::write_atomically(Some(path), |out| {
            serde_json::to_writer_pretty(&mut *out, &doc).map_err(|e| CliError::Io(e.to_string()))
        })?;
    }
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
