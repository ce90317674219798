//! `gartowen verify`: the conformance battery over the registry or named implementations.

use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::verify::{merge, verify_shard, ImplReport, Level, Shard, Verdict};
use std::path::PathBuf;
use std::process::ExitCode;

/// Battery size.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum LevelArg {
    /// Under a minute for the whole registry on 2 cores.
    Quick,
    /// Larger samples and deeper nets.
    Full,
    /// Long (minutes); split it with --shard and combine with --merge.
    Exhaustive,
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
///   gartowen verify --level exhaustive --shard 2/4 --json shard2.json     (one CI job of four)
///   gartowen verify --merge shard1.json shard2.json shard3.json shard4.json --json all.json
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
    /// Run only shard I of N (1 ≤ I ≤ N): implementation k goes to shard (k mod N) + 1.
    #[arg(long)]
    pub shard: Option<String>,
    /// Combine shard JSON files (from --json) into one report instead of running checks.
    #[arg(long, num_args = 1.., conflicts_with_all = ["shard", "implementations"])]
    pub merge: Vec<PathBuf>,
}

fn level_name(level: Level) -> &'static str {
    match level {
        Level::Quick => "quick",
        Level::Full => "full",
        Level::Exhaustive => "exhaustive",
    }
}

/// Reads shard files and merges them; all must come from the same level.
fn merged(paths: &[PathBuf]) -> Result<(Level, Vec<ImplReport>), CliError> {
    let mut level = None;
    let mut parts = Vec::new();
    for p in paths {
        let text = std::fs::read_to_string(p)
            .map_err(|e| CliError::Io(format!("cannot read {}: {e}", p.display())))?;
        let doc: serde_json::Value = serde_json::from_str(&text)
            .map_err(|e| CliError::Usage(format!("{}: not JSON: {e}", p.display())))?;
        if doc["command"] != "verify" {
            return Err(CliError::Usage(format!(
                "{} is not a verify report",
                p.display()
            )));
        }
        let l: Level = serde_json::from_value(doc["level"].clone())
            .map_err(|e| CliError::Usage(format!("{}: bad level: {e}", p.display())))?;
        if level.is_some_and(|x| x != l) {
            return Err(CliError::Usage(format!(
                "{} was run at another level",
                p.display()
            )));
        }
        level = Some(l);
        let reports: Vec<ImplReport> = serde_json::from_value(doc["implementations"].clone())
            .map_err(|e| CliError::Usage(format!("{}: bad report: {e}", p.display())))?;
        parts.push(reports);
    }
    let all = merge(parts).map_err(CliError::Usage)?;
    Ok((level.expect("at least one file"), all))
}

/// Runs `verify`.
pub fn run(a: VerifyArgs) -> Result<ExitCode, CliError> {
    let (level, reports) = if !a.merge.is_empty() {
        merged(&a.merge)?
    } else {
        let level = match a.level {
            LevelArg::Quick => Level::Quick,
            LevelArg::Full => Level::Full,
            LevelArg::Exhaustive => Level::Exhaustive,
        };
        let shard = match &a.shard {
            None => Shard::ALL,
            Some(t) => Shard::parse(t).ok_or_else(|| {
                CliError::Usage(format!("--shard '{t}' is not I/N with 1 ≤ I ≤ N"))
            })?,
        };
        let registry = gartowen::registry();
        let total = if a.implementations.is_empty() {
            registry.specs().len()
        } else {
            a.implementations.len()
        };
        let bar = indicatif::ProgressBar::new(total.div_ceil(shard.count) as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("verify {msg} [{bar:30}] {pos}/{len}")
                .expect("template"),
        );
        let reports = verify_shard(&registry, &a.implementations, level, shard, &|name| {
            bar.set_message(name.to_string());
            bar.inc(1);
        })?;
        bar.finish_and_clear();
        (level, reports)
    };
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
    println!(
        "{} implementations, {failed} with failures ({} level)",
        reports.len(),
        level_name(level)
    );
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
