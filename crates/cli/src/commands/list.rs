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
            "{:<22} {:>5} {:>12} {:>9} {:>8}  {:<24} summary",
            "name", "base", "table_bytes", "record_B", "B/symbol", "claim"
        )
        .map_err(io_err)?;
        for r in &rows {
            let record = r["record_bytes"]
                .as_u64()
                .map_or(String::new(), |b| b.to_string());
            let per_symbol = r["record_bytes_per_symbol"]
                .as_f64()
                .map_or(String::new(), |b| format!("{b:.3}"));
            writeln!(
                out,
                "{:<22} {:>5} {:>12} {:>9} {:>8}  {:<24} {}",
                r["name"].as_str().unwrap_or_default(),
                r["base"].as_u64().unwrap_or_default(),
                r["table_bytes"].as_u64().unwrap_or_default(),
                record,
                per_symbol,
                r["claim"].as_str().unwrap_or_default(),
                r["summary"].as_str().unwrap_or_default()
            )
            .map_err(io_err)?;
        }
        writeln!(
            out,
            "\nrecord_B: what a renderer ships for 32-bit words (256 symbols, packed; the child \
             table is shared and static); table_bytes adds the acceleration tables."
        )
        .map_err(io_err)?;
        for r in rows
            .iter()
            .filter(|r| r.get("paper_ratio_to_q_art_4").is_some())
        {
            writeln!(
                out,
                "{} / q-art-4 record = {:.2} (the paper: about {}, \"{}\")",
                r["name"].as_str().unwrap_or_default(),
                r["record_ratio_to_q_art_4"].as_f64().unwrap_or_default(),
                r["paper_ratio_to_q_art_4"].as_f64().unwrap_or_default(),
                r["paper_says"].as_str().unwrap_or_default()
            )
            .map_err(io_err)?;
        }
    }
    Ok(ExitCode::SUCCESS)
}
