//! `gartowen generate`: points of a built-in sequence, optionally scrambled.

use super::width_from_bits;
use crate::output::{io_err, write_atomically};
use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::core::{word_to_f64, RadixLayout, Width};
use gartowen::generate::{GeneratePlan, GenerateRequest, PointCount, PointOrder};
use gartowen::radix_points::{self, RadixPoints};
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
///   gartowen generate --seq sz16 --dims 16 --n 4096 -o sz16.npy   (npy from the extension)
///   gartowen generate --seq sobol --dims 3 --n 8 --order gray --format csv   (scipy's rows)
///   gartowen generate --seq sz16 --dims 16 --log2-n 8 --scramble owen-oracle --seed 7
///   gartowen generate --seq sobol --dims 2 --log2-n 8 --scramble owen-oracle:xor --scramble-base 4
///   gartowen generate --seq faure:base=3 --dims 3 --n 243 --scramble owen-oracle --seed 1
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct GenerateArgs {
    /// Sequence: sobol (base 2, Joe–Kuo 6.21201, 21201 dims), sz4 (base 4, 4 dims), sz16 (base 16,
    /// 16 dims), faure:base=B (B = 2, 4, …, 256; B dims, a (0,B)-sequence over GF(B); or B a
    /// prime other than 2: the (0,B)-sequence of Pascal matrices mod B, held as base-B digit
    /// words and scrambled in base B) or faure-net:base=B:m=M (the (0,M,B+1)-net of its first
    /// B^M points).
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
    /// Output format (default: from the extension of -o, .npy/.csv/.hex/.txt; hex otherwise).
    #[arg(long, value_enum)]
    pub format: Option<PointFormat>,
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
    /// sobol 2, sz4 4, sz16 16, faure:base=3 3). A base the scrambler does not take (a fixed
    /// base, or its `:base=B` option) is refused; a base that is not a power of two needs a
    /// sequence of that base.
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

/// Fills rows `first..first + buf.len() / dims` of a [`RowSource`] into `buf` (row-major).
pub type BlockFiller<'a> = Box<dyn Fn(u64, &mut [u64]) + Sync + 'a>;

/// Words per block (2 MiB of words): enough rows for batch scrambling to pay at a few
/// dimensions, and a bounded buffer at thousands (a block of 16,384 rows of 21,201
/// dimensions once needed 2.8 GB and aborted).
const BLOCK_WORDS: usize = 1 << 18;
/// The fewest rows in a block, whatever the dimension (64 rows of Sobol's 21,201 dimensions
/// are 10.9 MB).
const MIN_BLOCK_ROWS: usize = 64;

/// Rows per block for points of `dims` coordinates: [`BLOCK_WORDS`] words, at least
/// [`MIN_BLOCK_ROWS`] rows.
fn block_rows(dims: usize) -> u64 {
    (BLOCK_WORDS / dims.max(1)).max(MIN_BLOCK_ROWS) as u64
}

/// Rows of words to write: `block(first, buf)` fills points first.. (< count) of `dims` words.
pub struct RowSource<'a> {
    /// Word width of the rows.
    pub width: Width,
    /// How words hold values: `None` binary (value word·2^-W), else base-b digit words
    /// (value word·b^-m).
    pub radix: Option<RadixLayout>,
    /// Coordinates per point.
    pub dims: usize,
    /// Number of points.
    pub count: u64,
    /// Fills a block of rows.
    pub block: BlockFiller<'a>,
}

impl RowSource<'_> {
    /// The value a word stands for.
    fn value(&self, x: u64) -> f64 {
        match self.radix {
            None => word_to_f64(x, self.width),
            Some(layout) => layout.to_f64(x),
        }
    }

    /// Calls `emit` with each block of rows (row-major words) in order.
    fn for_each_block(
        &self,
        mut emit: impl FnMut(&[u64]) -> Result<(), CliError>,
    ) -> Result<(), CliError> {
        let mut buf = Vec::new();
        let mut first = 0u64;
        let block = block_rows(self.dims);
        while first < self.count {
            let rows = block.min(self.count - first) as usize;
            buf.resize(rows * self.dims, 0);
            (self.block)(first, &mut buf);
            emit(&buf)?;
            first += rows as u64;
        }
        Ok(())
    }

    /// Calls `emit` with each row in order.
    fn for_each(
        &self,
        mut emit: impl FnMut(&[u64]) -> Result<(), CliError>,
    ) -> Result<(), CliError> {
        self.for_each_block(|block| block.chunks_exact(self.dims).try_for_each(&mut emit))
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
        radix: None,
        dims: p.seq.dims(),
        count: p.count,
        block: Box::new(move |first, buf| p.block(first, order, buf)),
    }
}

/// The .npy (format 1.0) header of a C-order little-endian array of dtype `descr` and
/// shape (rows, dims): magic, version, header length, the dict padded with spaces to a
/// multiple of 64 bytes and ending in a newline (as NumPy writes it).
fn npy_header(descr: &str, rows: u64, dims: usize) -> Vec<u8> {
    let mut dict =
        format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': ({rows}, {dims}), }}");
    let unpadded = 10 + dict.len() + 1;
    dict.push_str(&" ".repeat(unpadded.next_multiple_of(64) - unpadded));
    dict.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out
}

/// Writes the rows as an (N, d) .npy array of `item`-byte little-endian elements, `encode`
/// writing one word's bytes. Blocks are encoded in parallel (bytes do not depend on the
/// thread count) and written whole. With two or more threads the writing overlaps the
/// computing: a producer fills and encodes the next block while this thread writes the last
/// one (at most three blocks of bytes alive), so a slow disk and the scrambling share the
/// time instead of adding up.
fn write_npy_as(
    src: &RowSource,
    out: &mut dyn Write,
    descr: &str,
    item: usize,
    encode: impl Fn(u64, &mut [u8]) + Sync,
) -> Result<(), CliError> {
    use rayon::prelude::*;
    out.write_all(&npy_header(descr, src.count, src.dims))
        .map_err(io_err)?;
    let encode_block = |block: &[u64], bytes: &mut Vec<u8>| {
        bytes.resize(block.len() * item, 0);
        bytes
            .par_chunks_mut(item * 4096)
            .zip(block.par_chunks(4096))
            .for_each(|(b, w)| {
                for (b, &x) in b.chunks_exact_mut(item).zip(w) {
                    encode(x, b);
                }
            });
    };
    if rayon::current_num_threads() < 2 {
        let mut bytes = Vec::new();
        return src.for_each_block(|block| {
            encode_block(block, &mut bytes);
            out.write_all(&bytes).map_err(io_err)
        });
    }
    std::thread::scope(|scope| {
        let (full_tx, full_rx) = std::sync::mpsc::sync_channel::<Vec<u8>>(1);
        let (empty_tx, empty_rx) = std::sync::mpsc::channel::<Vec<u8>>();
        let producer = scope.spawn(move || {
            src.for_each_block(|block| {
                let mut bytes = empty_rx.try_recv().unwrap_or_default();
                encode_block(block, &mut bytes);
                // A closed channel means the writer stopped on an error it reports itself.
                full_tx
                    .send(bytes)
                    .map_err(|_| CliError::Usage(String::new()))
            })
        });
        let mut written = Ok(());
        for bytes in full_rx {
            written = out.write_all(&bytes).map_err(io_err);
            if written.is_err() {
                break; // dropping the receiver stops the producer
            }
            let _ = empty_tx.send(bytes);
        }
        let produced = producer
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        written.and(produced)
    })
}

/// Writes rows as .npy: float64 values, or uint32/uint64 words with `words`.
pub fn write_npy(src: &RowSource, words: bool, out: &mut dyn Write) -> Result<(), CliError> {
    let width = src.width;
    match (words, width.bits()) {
        (false, _) => write_npy_as(src, out, "<f8", 8, |x, b| {
            b.copy_from_slice(&src.value(x).to_le_bytes())
        }),
        (true, 32) => write_npy_as(src, out, "<u4", 4, |x, b| {
            b.copy_from_slice(&(x as u32).to_le_bytes())
        }),
        (true, _) => write_npy_as(src, out, "<u8", 8, |x, b| {
            b.copy_from_slice(&x.to_le_bytes())
        }),
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
                (_, false) => write!(line, "{:?}", src.value(x)),
            };
        }
        line.push('\n');
        out.write_all(line.as_bytes()).map_err(io_err)
    })
}

/// The point format a file name's extension names, if any.
pub fn format_of(path: &std::path::Path) -> Option<PointFormat> {
    match path.extension().and_then(|e| e.to_str()) {
        Some("npy") => Some(PointFormat::Npy),
        Some("csv") => Some(PointFormat::Csv),
        Some("hex") | Some("txt") => Some(PointFormat::Hex),
        _ => None,
    }
}

/// The rows of a point set held as columns of equal length (column j is dimension j).
pub fn column_rows(
    width: Width,
    radix: Option<RadixLayout>,
    columns: &[Vec<u64>],
) -> RowSource<'_> {
    RowSource {
        width,
        radix,
        dims: columns.len(),
        count: columns.first().map_or(0, Vec::len) as u64,
        block: Box::new(move |first, buf| {
            for (i, row) in buf.chunks_exact_mut(columns.len()).enumerate() {
                for (j, x) in row.iter_mut().enumerate() {
                    *x = columns[j][first as usize + i];
                }
            }
        }),
    }
}

/// The rows of a base-b point set: its digit words, written as values k·b^-m or as words.
pub fn radix_rows(p: &RadixPoints) -> RowSource<'_> {
    column_rows(p.layout.width(), Some(p.layout), &p.columns)
}

/// The base-p Faure points of `generate --seq faure:base=P` (P prime, not a power of two),
/// scrambled in base P when asked.
fn radix_points(a: &GenerateArgs, p: u64) -> Result<RadixPoints, CliError> {
    if let Some(b) = a.scramble_base.filter(|&b| b != p) {
        return Err(CliError::Usage(format!(
            "--scramble-base {b} differs from the base {p} of {}: a base-b scramble acts on \
             base-b digits",
            a.seq
        )));
    }
    if a.order == OrderArg::Gray {
        return Err(CliError::Usage(format!(
            "--order gray is a base-2 order; {} is generated in natural order",
            a.seq
        )));
    }
    let count = match (a.log2_n, a.n) {
        (Some(m), None) if m < 64 => 1u64 << m,
        (None, Some(n)) if n > 0 => n,
        _ => {
            return Err(CliError::Usage(
                "give one of --log2-n (below 64) and --n (at least 1)".into(),
            ))
        }
    };
    let width = width_from_bits(a.bits)?;
    let mut points = radix_points::faure_points(p, a.start, count, a.dims, width)?;
    if let Some(s) = radix_points::radix_scrambler(&a.scramble, points.layout.radix(), a.seed)? {
        points.scramble(&s);
    }
    Ok(points)
}

/// What to say when the scrambler's base was taken from the sequence, not asked for: a
/// scrambler whose base is a parameter, given neither `:base=` nor `--scramble-base`, on a
/// sequence whose base is not 2 (`--seq sz16 --scramble owen-oracle` is base-16 Owen, which a
/// user asking for "Owen" may not expect).
fn default_base_note(a: &GenerateArgs, used: gartowen::core::PowerOfTwoBase) -> Option<String> {
    if a.scramble == "none" || a.scramble_base.is_some() || used.base() == 2 {
        return None;
    }
    let request = gartowen::core::registry::ScramblerRequest::parse(&a.scramble).ok()?;
    if request.option("base").is_some() {
        return None;
    }
    // A base that is a parameter: in base 2 when asked.
    let ctx = gartowen::core::BuildContext {
        seed: a.seed,
        default_base: gartowen::core::PowerOfTwoBase::B2,
    };
    let binary = gartowen::registry().build_with(&a.scramble, &ctx).ok()?;
    (binary.base().base() == 2).then(|| {
        format!(
            "{} scrambles in base {b}, the base of {}, as no base was asked for; binary \
             (base-2) Owen is `--scramble {}:base=2` (or `--scramble-base 2`)",
            a.scramble,
            a.seq,
            a.scramble,
            b = used.base()
        )
    })
}

/// Runs `generate`.
pub fn run(a: GenerateArgs) -> Result<ExitCode, CliError> {
    let format = a
        .format
        .or_else(|| a.output.as_deref().and_then(format_of))
        .unwrap_or(PointFormat::Hex);
    if a.words && format == PointFormat::Hex {
        return Err(CliError::Usage(
            "--words applies to npy and csv; hex is always words".into(),
        ));
    }
    if let Some(p) = radix_points::radix_sequence(&a.seq) {
        let points = radix_points(&a, p)?;
        let src = radix_rows(&points);
        write_atomically(a.output.as_deref(), |out| match format {
            PointFormat::Npy => write_npy(&src, a.words, out),
            PointFormat::Csv | PointFormat::Hex => write_text(&src, format, a.words, out),
        })?;
        return Ok(ExitCode::SUCCESS);
    }
    let p = plan(&a)?;
    if let Some(note) = default_base_note(&a, p.scrambler.base()) {
        eprintln!("note: {note}");
    }
    let src = rows(&p, a.order);
    write_atomically(a.output.as_deref(), |out| match format {
        PointFormat::Npy => write_npy(&src, a.words, out),
        PointFormat::Csv | PointFormat::Hex => write_text(&src, format, a.words, out),
    })?;
    Ok(ExitCode::SUCCESS)
}
