//! `gartowen generate`: points of a built-in sequence, optionally scrambled.

use super::width_from_bits;
use crate::output::{io_err, write_atomically};
use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::core::{word_to_f64, Width};
use gartowen::generate::{GeneratePlan, GenerateRequest, PointCount, PointOrder};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

/// Output format of point sets.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum PointFormat {
    /// NumPy .npy: float64 values, or uint32/uint64 words with --words.
    Npy,
    /// Comma-separated values: float64 values (shortest exact decimal), or decimal words with --words.
    Csv,
    /// Hex words, zero-padded, space-separated, one point per line.
    Hex,
}

/// Order in which points are written.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum OrderArg {
    /// Point i of the output is index start + i.
    Natural,
    /// Row i is index gray(start + i) = n ^ (n >> 1): scipy.stats.qmc.Sobol's order.
    Gray,
}

/// Generate points of a built-in digital sequence.
///
/// Examples:
///   gartowen generate --seq sobol --dims 2 --log2-n 4 --format hex
///   gartowen generate --seq sz16 --dims 16 --n 4096 --format npy -o sz16.npy
///   gartowen generate --seq sobol --dims 3 --n 8 --order gray --format csv   (scipy's rows)
///   gartowen generate --seq sz16 --dims 16 --log2-n 8 --scramble owen-oracle --seed 7
///   gartowen generate --seq sobol --dims 2 --log2-n 8 --scramble owen-oracle:xor --scramble-base 4
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct GenerateArgs {
    /// Sequence: sobol (base 2, Joe–Kuo 6.21201, 21201 dims), sz4 (base 4, 4 dims), sz16 (base 16, 16 dims).
    #[arg(long)]
    pub seq: String,
    /// Number of dimensions.
    #[arg(long)]
    pub dims: usize,
    /// Number of points as a power of two: N = 2^M.
    #[arg(long = "log2-n", conflicts_with = "n", required_unless_present = "n")]
    pub log2_n: Option<u32>,
    /// Number of points N.
    #[arg(long)]
    pub n: Option<u64>,
    /// Index of the first point.
    #[arg(long, default_value_t = 0)]
    pub start: u64,
    /// Word width W: 32 or 64 bits.
    #[arg(long, default_value_t = 32)]
    pub bits: u32,
    /// Output format.
    #[arg(long, value_enum, default_value_t = PointFormat::Hex)]
    pub format: PointFormat,
    /// Write words (uint32/uint64) instead of float64 values (npy and csv).
    #[arg(long)]
    pub words: bool,
    /// Point order.
    #[arg(long, value_enum, default_value_t = OrderArg::Natural)]
    pub order: OrderArg,
    /// Scrambler from the registry (see `gartowen list`), NAME[:OPTION...].
    #[arg(long, default_value = "none")]
    pub scramble: String,
    /// Seed of the scrambler.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Scrambling base for scramblers whose base is a parameter (default: the sequence's own:
    /// sobol 2, sz4 4, sz16 16). A `:base=B` option in --scramble takes precedence.
    #[arg(long = "scramble-base")]
    pub scramble_base: Option<u64>,
    /// Output file (default: standard output). Written atomically.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
}

fn plan(a: &GenerateArgs) -> Result<GeneratePlan, CliError> {
    let count = match (a.log2_n, a.n) {
        (Some(m), None) => PointCount::Log2(m),
        (None, Some(n)) => PointCount::Exact(n),
        _ => {
            return Err(CliError::Usage(
                "give exactly one of --log2-n and --n".into(),
            ))
        }
    };
    width_from_bits(a.bits)?;
    Ok(GeneratePlan::new(&GenerateRequest {
        seq: a.seq.clone(),
        dims: a.dims,
        count,
        start: a.start,
        bits: a.bits,
        scramble: a.scramble.clone(),
        seed: a.seed,
        scramble_base: a.scramble_base,
    })?)
}

/// Fills row i of a [`RowSource`] into the buffer.
pub type RowFiller<'a> = Box<dyn Fn(u64, &mut [u64]) + 'a>;

/// Rows of words to write: `row(i, buf)` fills point i (0 ≤ i < count) of `dims` words.
pub struct RowSource<'a> {
    /// Word width of the rows.
    pub width: Width,
    /// Coordinates per point.
    pub dims: usize,
    /// Number of points.
    pub count: u64,
    /// Fills one row.
    pub row: RowFiller<'a>,
}

impl RowSource<'_> {
    /// Calls `emit` with each row in order.
    fn for_each(
        &self,
        mut emit: impl FnMut(&[u64]) -> Result<(), CliError>,
    ) -> Result<(), CliError> {
        let mut buf = vec![0u64; self.dims];
        for i in 0..self.count {
            (self.row)(i, &mut buf);
            emit(&buf)?;
        }
        Ok(())
    }
}

/// The generated points (scrambled words) in the requested order.
fn rows(p: &GeneratePlan, order: OrderArg) -> RowSource<'_> {
    let order = match order {
        OrderArg::Natural => PointOrder::Natural,
        OrderArg::Gray => PointOrder::Gray,
    };
    RowSource {
        width: p.width(),
        dims: p.seq.dims(),
        count: p.count,
        row: Box::new(move |i, row| p.row(i, order, row)),
    }
}

/// Writes the rows as an (N, d) .npy array of `T`, converting each word with `conv`.
fn write_npy_as<T: npyz::AutoSerialize>(
    src: &RowSource,
    out: &mut dyn Write,
    conv: impl Fn(u64) -> T,
) -> Result<(), CliError> {
    use npyz::WriterBuilder;
    let npy = |e: std::io::Error| CliError::Io(format!("npy write failed: {e}"));
    let mut w = npyz::WriteOptions::<T>::new()
        .default_dtype()
        .shape(&[src.count, src.dims as u64])
        .writer(out)
        .begin_nd()
        .map_err(npy)?;
    src.for_each(|row| {
        for &x in row {
            w.push(&conv(x)).map_err(npy)?;
        }
        Ok(())
    })?;
    w.finish().map_err(npy)
}

/// Writes rows as .npy: float64 values, or uint32/uint64 words with `words`.
pub fn write_npy(src: &RowSource, words: bool, out: &mut dyn Write) -> Result<(), CliError> {
    let width = src.width;
    match (words, width.bits()) {
        (false, _) => write_npy_as(src, out, |x| word_to_f64(x, width)),
        (true, 32) => write_npy_as(src, out, |x| x as u32),
        (true, _) => write_npy_as(src, out, |x| x),
    }
}

/// Writes rows as CSV (floats, or decimal words with `words`) or hex words.
pub fn write_text(
    src: &RowSource,
    format: PointFormat,
    words: bool,
    out: &mut dyn Write,
) -> Result<(), CliError> {
    let width: Width = src.width;
    let hex_digits = (width.bits() / 4) as usize;
    let mut line = String::new();
    src.for_each(|row| {
        line.clear();
        for (j, &x) in row.iter().enumerate() {
            use std::fmt::Write as _;
            let sep = if j == 0 {
                ""
            } else if format == PointFormat::Csv {
                ","
            } else {
                " "
            };
            line.push_str(sep);
            let _ = match (format, words) {
                (PointFormat::Hex, _) => write!(line, "{x:0hex_digits$x}"),
                (_, true) => write!(line, "{x}"),
                (_, false) => write!(line, "{:?}", word_to_f64(x, width)),
            };
        }
        line.push('\n');
        out.write_all(line.as_bytes()).map_err(io_err)
    })
}

/// Runs `generate`.
pub fn run(a: GenerateArgs) -> Result<ExitCode, CliError> {
    let p = plan(&a)?;
    if a.words && a.format == PointFormat::Hex {
        return Err(CliError::Usage(
            "--words applies to npy and csv; hex is always words".into(),
        ));
    }
    let src = rows(&p, a.order);
    write_atomically(a.output.as_deref(), |out| match a.format {
        PointFormat::Npy => write_npy(&src, a.words, out),
        PointFormat::Csv | PointFormat::Hex => write_text(&src, a.format, a.words, out),
    })?;
    Ok(ExitCode::SUCCESS)
}
