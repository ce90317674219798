//! `gartowen list`: the scrambler registry.

use crate::output::io_err;
use crate::CliError;
use clap::Args;
use std::io::Write;
use std::process::ExitCode;

/// List every registered scrambler: name, base, table bytes, whether it claims nested uniformity.
#[derive(Args, Debug)]
pub struct ListArgs {
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// Runs `list`.
pub fn run(a: ListArgs) -> Result<ExitCode, CliError> {
    let rows = gartowen::registry_listing()?;
    let mut out = std::io::stdout().lock();
    if a.json {
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(&rows).expect("json")
        )
        .map_err(io_err)?;
    } else {
        writeln!(
            out,
            "{:<22} {:>5} {:>12}  {:<24} summary",
            "name", "base", "table_bytes", "claim"
        )
        .map_err(io_err)?;
        for r in &rows {
            writeln!(
                out,
                "{:<22} {:>5} {:>12}  {:<24} {}",
                r["name"].as_str().unwrap_or_default(),
                r["base"].as_u64().unwrap_or_default(),
                r["table_bytes"].as_u64().unwrap_or_default(),
                r["claim"].as_str().unwrap_or_default(),
                r["summary"].as_str().unwrap_or_default()
            )
            .map_err(io_err)?;
        }
    }
    Ok(ExitCode::SUCCESS)
}
