//! `gartowen list`: the scrambler registry, or the built-in sequences with their provenance.

use crate::output::io_err;
use crate::CliError;
use clap::Args;
use std::io::Write;
use std::process::ExitCode;

/// List every registered scrambler: name, base, table bytes, whether it claims nested
/// uniformity. With --sequences: every built-in sequence, its base, dimensions and where its
/// matrices come from (published, third-party-derived or gartowen's own).
#[derive(Args, Debug)]
pub struct ListArgs {
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    /// List the built-in sequences instead of the scramblers.
    #[arg(long)]
    pub sequences: bool,
}

/// The built-in sequences (the Faure family once, as `faure:base=B`).
fn sequence_rows() -> Vec<serde_json::Value> {
    use gartowen::seq::SequenceKind;
    let mut kinds: Vec<(String, SequenceKind)> =
        SequenceKind::NAMED.iter().map(|k| (k.name(), *k)).collect();
    kinds.push((
        "faure:base=B".into(),
        SequenceKind::Faure(gartowen::core::PowerOfTwoBase::B2),
    ));
    let mut rows: Vec<serde_json::Value> = kinds
        .into_iter()
        .map(|(name, k)| {
            let p = k.provenance();
            let (base, dims) = if matches!(k, SequenceKind::Faure(_)) {
                ("2^q".to_string(), "B".to_string())
            } else {
                (k.base().base().to_string(), k.max_dims().to_string())
            };
            serde_json::json!({
                "name": name, "base": base, "max_dims": dims,
                "provenance": p.label(), "source": p.source(),
            })
        })
        .collect();
    // Generated as base-P digit words (`generate` only), not as a binary digital sequence.
    rows.push(serde_json::json!({
        "name": "faure:base=P", "base": "P", "max_dims": "P", "provenance": "published",
        "source": "Faure (1982) in an odd prime base P (Pascal matrices mod P), as base-P digit \
                   words: `generate` and base-P scrambling only",
    }));
    rows
}

fn list_sequences(json: bool) -> Result<ExitCode, CliError> {
    let rows = sequence_rows();
    let mut out = std::io::stdout().lock();
    if json {
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(&rows).expect("json")
        )
        .map_err(io_err)?;
        return Ok(ExitCode::SUCCESS);
    }
    writeln!(
        out,
        "{:<14} {:>5} {:>6}  {:<20} source",
        "name", "base", "dims", "provenance"
    )
    .map_err(io_err)?;
    for r in &rows {
        writeln!(
            out,
            "{:<14} {:>5} {:>6}  {:<20} {}",
            r["name"].as_str().unwrap_or_default(),
            r["base"].as_str().unwrap_or_default(),
            r["max_dims"].as_str().unwrap_or_default(),
            r["provenance"].as_str().unwrap_or_default(),
            r["source"].as_str().unwrap_or_default()
        )
        .map_err(io_err)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Runs `list`.
pub fn run(a: ListArgs) -> Result<ExitCode, CliError> {
    if a.sequences {
        return list_sequences(a.json);
    }
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
