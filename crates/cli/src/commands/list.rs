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
    let registry = gartowen::registry();
    let mut rows = Vec::new();
    for spec in registry.specs() {
        // Table sizes are reported for the default configuration (seed 0).
        let ctx = gartowen::core::BuildContext {
            seed: 0,
            default_base: spec.default_base,
        };
        let s = (spec.build)(&gartowen::core::ScramblerRequest::parse(spec.name)?, &ctx)?;
        rows.push((spec, s.base().base(), s.table_bytes()));
    }
    let mut out = std::io::stdout().lock();
    if a.json {
        let doc: Vec<_> = rows
            .iter()
            .map(|(spec, base, bytes)| {
                serde_json::json!({
                    "name": spec.name, "base": base, "table_bytes": bytes,
                    "claims_nested_uniform": spec.claim.is_owen(), "claim": spec.claim.to_string(),
                    "summary": spec.summary,
                })
            })
            .collect();
        writeln!(out, "{}", serde_json::to_string_pretty(&doc).expect("json")).map_err(io_err)?;
    } else {
        writeln!(
            out,
            "{:<22} {:>5} {:>12}  {:<24} summary",
            "name", "base", "table_bytes", "claim"
        )
        .map_err(io_err)?;
        for (spec, base, bytes) in rows {
            writeln!(
                out,
                "{:<22} {:>5} {:>12}  {:<24} {}",
                spec.name,
                base,
                bytes,
                spec.claim.to_string(),
                spec.summary
            )
            .map_err(io_err)?;
        }
    }
    Ok(ExitCode::SUCCESS)
}
