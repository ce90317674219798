//! The command line's view of point files: the `--format` choice and the certificate record;
//! the readers themselves are the library's ([`gartowen::point_files`]).

use crate::CliError;
use gartowen::netcheck::PointSet;
use gartowen::point_files::{Format, PointFileError};
use std::path::Path;

pub use gartowen::point_files::FloatWords;

/// Input formats.
#[derive(Clone, Copy, Debug, clap::ValueEnum, PartialEq, Eq)]
pub enum InputFormat {
    /// By file extension: .npy, .csv, .hex/.txt.
    Auto,
    /// NumPy .npy: float64 values in [0,1), or uint32/uint64 words.
    Npy,
    /// Comma-separated float values in [0,1), one point per line.
    Csv,
    /// Hex words (8 or 16 digits), whitespace-separated, one point per line.
    Hex,
}

impl InputFormat {
    /// The library's format; `None` for "by the extension".
    fn format(self) -> Option<Format> {
        match self {
            InputFormat::Auto => None,
            InputFormat::Npy => Some(Format::Npy),
            InputFormat::Csv => Some(Format::Csv),
            InputFormat::Hex => Some(Format::Hex),
        }
    }
}

impl From<PointFileError> for CliError {
    fn from(e: PointFileError) -> CliError {
        match e {
            PointFileError::Io(m) => CliError::Io(m),
            PointFileError::Invalid(m) => CliError::Usage(m),
        }
    }
}

/// The certificate record of a point file: its path, the FNV-1a checksum of its words
/// (row-major, little-endian) and its shape.
pub fn file_record(path: &Path, points: &PointSet) -> gartowen::certificate::InputRecord {
    gartowen::reports::point_set_record("file", &path.display().to_string(), points)
}

/// The file's text, refused (exit 2) past `limit` bytes or when it is not UTF-8 text.
pub fn read_text_bounded(path: &Path, limit: u64) -> Result<String, CliError> {
    Ok(gartowen::point_files::read_text_bounded(path, limit)?)
}

/// Reads a point set.
pub fn read_points(path: &Path, format: InputFormat) -> Result<PointSet, CliError> {
    read_points_typed(path, format, FloatWords::Exact).map(|(p, _)| p)
}

/// Reads a point set and whether its file held floats (CSV values or float64 `.npy`,
/// converted to 64-bit words as `floats` says) rather than words.
pub fn read_points_typed(
    path: &Path,
    format: InputFormat,
    floats: FloatWords,
) -> Result<(PointSet, bool), CliError> {
    Ok(gartowen::point_files::read_points(
        path,
        format.format(),
        floats,
    )?)
}
