//! `gartowen matrices`: the generator matrices of a sequence as column words.

use super::width_from_bits;
use crate::output::{io_err, write_atomically};
use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::seq::SequenceKind;
use std::path::PathBuf;
use std::process::ExitCode;

/// Output format of matrices.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum MatrixFormat {
    /// One line per dimension: its columns (column 0 first) as zero-padded hex words.
    Hex,
    /// A JSON object with the sequence, widths and per-dimension hex columns.
    Json,
}

/// Print generator matrices: column c of dimension j is a W-bit word whose top bit is row 0.
///
/// Point n of dimension j is the XOR of columns c over the set bits c of n (bit 0 = LSB).
/// sz4 is the published 4-D SZ (dimensions I, P, P4(β), P·P4(β)); sz16's first quad is sz4,
/// its other three quads and the ensemble are gartowen's own construction (searched for the
/// best binary pairs across quads). `gartowen list --sequences` shows every sequence's
/// provenance. Example: gartowen matrices --seq sz4 --dims 4 --format hex
#[derive(Args, Debug)]
pub struct MatricesArgs {
    /// Sequence: sobol, sz4, sz16, faure:base=B or faure-net:base=B:m=M (sz4-faure and
    /// sz16-faure: the earlier reconstructions, for reproducing older results).
    #[arg(long)]
    pub seq: String,
    /// Number of dimensions.
    #[arg(long)]
    pub dims: usize,
    /// Word width W: 32 or 64 bits.
    #[arg(long, default_value_t = 32)]
    pub bits: u32,
    /// Output format.
    #[arg(long, value_enum, default_value_t = MatrixFormat::Hex)]
    pub format: MatrixFormat,
    /// Output file (default: standard output).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
}

/// Runs `matrices`.
pub fn run(a: MatricesArgs) -> Result<ExitCode, CliError> {
    let kind: SequenceKind = a.seq.parse()?;
    let width = width_from_bits(a.bits)?;
    let seq = kind.build(a.dims, width)?;
    let digits = (width.bits() / 4) as usize;
    let hex_columns = |j: usize| -> Vec<String> {
        seq.columns(j)
            .iter()
            .map(|c| format!("{c:0digits$x}"))
            .collect()
    };
    write_atomically(a.output.as_deref(), |out| match a.format {
        MatrixFormat::Hex => {
            for j in 0..seq.dims() {
                writeln!(out, "{}", hex_columns(j).join(" ")).map_err(io_err)?;
            }
            Ok(())
        }
        MatrixFormat::Json => {
            let doc = serde_json::json!({
                "sequence": kind.name(),
                "base": kind.base().base(),
                "bits": width.bits(),
                "index_bits": seq.index_bits(),
                "provenance": {"kind": kind.provenance().label(), "source": kind.provenance().source()},
                "convention": "column c of dimension j is a W-bit word, row 0 in the most significant bit; x_j(n) = XOR of columns c over set bits c of n",
                "dims": (0..seq.dims()).map(|j| serde_json::json!({"dim": j, "columns": hex_columns(j)})).collect::<Vec<_>>(),
            });
            serde_json::to_writer_pretty(&mut *out, &doc)
                .map_err(|e| CliError::Io(e.to_string()))?;
            writeln!(out).map_err(io_err)
        }
    })?;
    Ok(ExitCode::SUCCESS)
}
