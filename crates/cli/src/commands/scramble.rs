//! `gartowen scramble`: scramble the user's own points or words with a registry scrambler.

use super::generate::{column_rows, format_of, radix_rows, write_npy, write_text, PointFormat};
use crate::input::{read_points, read_points_typed, FloatWords, InputFormat};
use crate::output::write_atomically;
use crate::CliError;
use clap::Args;
use gartowen::core::{Radix, RadixLayout};
use gartowen::radix_points;
use std::path::PathBuf;
use std::process::ExitCode;

/// Scramble a point set from a file: column j is scrambled as dimension j, row order kept.
///
/// Reads .npy (float64, uint32, uint64), CSV floats or hex words, as `check` does (floats must
/// be exact multiples of 2^-W). Writes the same kinds: .npy and CSV hold float64 values unless
/// --words, hex holds words. The output format follows -o's extension, else the input's.
///
/// Examples:
///   gartowen scramble pts.npy --scramble owen-oracle --seed 3 -o scrambled.npy
///   gartowen scramble words.hex --scramble art-owen-16p --seed 1 --format hex
///   gartowen scramble pts.csv --scramble owen-oracle:xor --scramble-base 4 --seed 9
///   gartowen scramble faure3.npy --scramble owen-oracle --scramble-base 3 -o owen3.npy
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct ScrambleArgs {
    /// Input file.
    pub file: PathBuf,
    /// Input format (default: by extension).
    #[arg(long = "input-format", value_enum, default_value_t = InputFormat::Auto)]
    pub input_format: InputFormat,
    /// Scrambler from the registry (see `gartowen list`), NAME[:OPTION...].
    #[arg(long)]
    pub scramble: String,
    /// Seed of the scrambler.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Scrambling base for scramblers whose base is a parameter (default 2). A base the
    /// scrambler does not take (a fixed base, or its `:base=B` option) is refused. A base that
    /// is not a power of two (3..65535, `owen-oracle[:cyclic|:per-depth]`) reads each
    /// coordinate as base-b digits: floats are snapped to the base-b grid (see --digits),
    /// words are base-b digit integers (below b^m, value word·b^-m), and --words/hex output
    /// writes such digit words.
    #[arg(long = "scramble-base")]
    pub scramble_base: Option<u64>,
    /// In a base that is not a power of two: the base-b digits the float values carry; each
    /// is snapped to the nearest multiple of b^-DIGITS within 2^-46 (a float cannot hold
    /// 1/3) and refused when it is too near to read safely. Default: the fewest digits that
    /// index every point, ⌈log_b N⌉ (the digits of the first N points of a base-b sequence).
    #[arg(long)]
    pub digits: Option<u32>,
    /// In a base that is not a power of two: the width of the digit words float values are
    /// read into, 32 or 64 (default 32, as `generate`'s): m digits with b^m ≤ 2^bits, every
    /// one scrambled, so the output equals `generate --bits B --scramble …` of the same points.
    #[arg(long)]
    pub bits: Option<u32>,
    /// Output format (default: by -o's extension, else the input's).
    #[arg(long, value_enum)]
    pub format: Option<PointFormat>,
    /// Write words (uint32/uint64) instead of float64 values (npy and csv).
    #[arg(long)]
    pub words: bool,
    /// Output file (default: standard output). Written atomically.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
}

/// Runs `scramble`.
pub fn run(a: ScrambleArgs) -> Result<ExitCode, CliError> {
    if let Some(out) = &a.output {
        use crate::paths::{named, refuse_clobbering};
        refuse_clobbering(&[named("FILE", &a.file)], &[named("-o", out)])?;
    }
    let format = a
        .format
        .or_else(|| a.output.as_deref().and_then(format_of))
        .or_else(|| match a.input_format {
            InputFormat::Npy => Some(PointFormat::Npy),
            InputFormat::Csv => Some(PointFormat::Csv),
            InputFormat::Hex => Some(PointFormat::Hex),
            InputFormat::Auto => format_of(&a.file),
        })
        .ok_or_else(|| CliError::Usage("cannot tell the output format; pass --format".into()))?;
    if a.words && format == PointFormat::Hex {
        return Err(CliError::Usage(
            "--words applies to npy and csv; hex is always words".into(),
        ));
    }
    if let Some(radix) = radix_points::radix_of_request(&a.scramble, a.scramble_base)? {
        return run_in_radix(&a, radix, format);
    }
    if a.digits.is_some() || a.bits.is_some() {
        return Err(CliError::Usage(
            "--digits and --bits apply to bases that are not powers of two (floats hold \
             base-2^q digits exactly, and words keep the file's width)"
                .into(),
        ));
    }
    let scrambler = gartowen::generate::build_scrambler(
        &a.scramble,
        a.seed,
        a.scramble_base,
        gartowen::core::PowerOfTwoBase::B2,
    )?;
    let points = read_points(&a.file, a.input_format)?;
    let width = points.width();
    if !scrambler.supports_width(width) {
        return Err(CliError::Usage(format!(
            "scrambler {} does not support the {}-bit words of {}",
            scrambler.name(),
            width.bits(),
            a.file.display()
        )));
    }
    let columns: Vec<Vec<u64>> = (0..points.dims())
        .map(|j| {
            let mut col = points.column(j).to_vec();
            scrambler.scramble_batch(&mut col, width, j as u32);
            col
        })
        .collect();
    let src = column_rows(width, None, &columns);
    write_atomically(a.output.as_deref(), |out| match format {
        PointFormat::Npy => write_npy(&src, a.words, out),
        PointFormat::Csv | PointFormat::Hex => write_text(&src, format, a.words, out),
    })?;
    Ok(ExitCode::SUCCESS)
}

/// `scramble` in a base b that is not a power of two: the coordinates as base-b digit words,
/// scrambled dimension by dimension, written as values or digit words.
fn run_in_radix(a: &ScrambleArgs, radix: Radix, format: PointFormat) -> Result<ExitCode, CliError> {
    let scrambler = radix_points::radix_scrambler(&a.scramble, radix, a.seed)?;
    let (points, floats) = read_points_typed(&a.file, a.input_format, FloatWords::Exact)?;
    let width = gartowen::generate::width_from_bits(a.bits.unwrap_or(32))
        .map_err(|e| CliError::Usage(format!("--bits: {e}")))?;
    let mut digits = if floats {
        radix_points::from_floats(&points, RadixLayout::new(width, radix)?, a.digits)?
    } else if a.bits.is_some() {
        return Err(CliError::Usage(format!(
            "--bits reads float values; the words of {} keep their own width",
            a.file.display()
        )));
    } else if a.digits.is_some() {
        return Err(CliError::Usage(format!(
            "--digits reads float values; the words of {} are base-{} digit integers already",
            a.file.display(),
            radix.get()
        )));
    } else {
        radix_points::from_digit_words(&points, RadixLayout::new(points.width(), radix)?)?
    };
    if let Some(s) = &scrambler {
        digits.scramble(s);
    }
    let src = radix_rows(&digits);
    write_atomically(a.output.as_deref(), |out| match format {
        PointFormat::Npy => write_npy(&src, a.words, out),
        PointFormat::Csv | PointFormat::Hex => write_text(&src, format, a.words, out),
    })?;
    Ok(ExitCode::SUCCESS)
}
