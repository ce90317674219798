//! Point files: .npy (float64, uint32, uint64; C or Fortran order), CSV of floats, and hex
//! words, read into a [`PointSet`]. Every error names the file and the offending line, point or
//! dtype; every reader is bounded (a stream is refused at its first bytes when it is of the
//! wrong kind, and nothing past [`MAX_INPUT_BYTES`] is read). The parsers of bytes
//! ([`npy::read_npy`], [`text::read_csv`], [`text::read_hex`]) are public for fuzzing.

pub mod npy;
pub mod text;

use gartowen_core::Width;
use gartowen_netcheck::PointSet;
use std::fmt;
use std::path::Path;

/// Why a point file was not read: the file could not be read (`Io`), or it is not a point set
/// gartowen reads (`Invalid`). The words name the file and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PointFileError {
    /// An OS error reading the file, e.g. `cannot read p.npy: No such file or directory`.
    Io(String),
    /// The content is refused, e.g. `p.npy: unsupported dtype '<i4': …`.
    Invalid(String),
}

impl fmt::Display for PointFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PointFileError::Io(m) | PointFileError::Invalid(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for PointFileError {}

/// The formats of point files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// NumPy .npy: float64 values in [0,1), or uint32/uint64 words.
    Npy,
    /// Comma-separated float values in [0,1), one point per line.
    Csv,
    /// Hex words (8 or 16 digits), whitespace-separated, one point per line.
    Hex,
}

impl Format {
    /// The format a file name's extension says: .npy, .csv, .hex or .txt.
    pub fn from_extension(path: &Path) -> Option<Format> {
        match path.extension().and_then(|e| e.to_str()) {
            Some("npy") => Some(Format::Npy),
            Some("csv") => Some(Format::Csv),
            Some("hex") | Some("txt") => Some(Format::Hex),
            _ => None,
        }
    }
}

/// The largest point file read (2 GiB): the parsed points take at least as much again, and a
/// stream such as /dev/zero would otherwise be read until memory runs out.
pub const MAX_INPUT_BYTES: u64 = 2 << 30;

/// The file's text, refused (exit 2) past `limit` bytes or when it is not UTF-8.
pub fn read_text_bounded(path: &Path, limit: u64) -> Result<String, PointFileError> {
    String::from_utf8(read_limited(path, limit, TEXT_PROBE, text_probe)?)
        .map_err(|_| bad(path, "is not UTF-8 text"))
}

/// The largest stream read (256 MiB): its buffer may double past it while it grows.
pub const MAX_STREAM_BYTES: u64 = 1 << 28;

/// Bytes of a text input looked at before the rest is read.
pub(crate) const TEXT_PROBE: usize = 4096;

/// Refuses binary data where text is expected (a NUL byte), so that a stream such as
/// /dev/zero is refused after a few bytes instead of after the whole read budget.
pub(crate) fn text_probe(first: &[u8]) -> Result<(), String> {
    match first.iter().position(|&b| b == 0) {
        Some(at) => Err(format!(
            "holds binary data (a NUL byte at offset {at}), not text"
        )),
        None => Ok(()),
    }
}

/// The file's bytes, refused (exit 2) past `limit`: by its size when it is a regular file,
/// before reading; by reading at most one byte more for streams. The first `probe` bytes go
/// through `check` before the rest is read, so a stream of the wrong kind is refused early.
/// The file is opened once (a FIFO cannot be read twice).
pub(crate) fn read_limited(
    path: &Path,
    limit: u64,
    probe: usize,
    check: impl Fn(&[u8]) -> Result<(), String>,
) -> Result<Vec<u8>, PointFileError> {
    let file = std::fs::File::open(path).map_err(|e| cannot(path, e))?;
    read_limited_from(file, path, limit, probe, check)
}

/// An OS error reading `path`, in words.
pub(crate) fn cannot(path: &Path, e: std::io::Error) -> PointFileError {
    PointFileError::Io(format!("cannot read {}: {e}", path.display()))
}

/// [`read_limited`] on a file already open (`path` names it in errors).
pub(crate) fn read_limited_from(
    mut file: std::fs::File,
    path: &Path,
    limit: u64,
    probe: usize,
    check: impl Fn(&[u8]) -> Result<(), String>,
) -> Result<Vec<u8>, PointFileError> {
    use std::io::Read;
    let cannot = |e: std::io::Error| cannot(path, e);
    let meta = file.metadata().map_err(cannot)?;
    // A stream (pipe, FIFO, device) has no size to check first and grows its buffer by
    // doubling: it gets a smaller budget, so that reading it stays well inside memory.
    let stream = !meta.is_file();
    let limit = if stream {
        limit.min(MAX_STREAM_BYTES)
    } else {
        limit
    };
    let too_big = || {
        PointFileError::Invalid(format!(
            "{}: larger than {limit} bytes, the most gartowen reads{}",
            path.display(),
            if stream {
                " from a stream (write it to a file for more)"
            } else {
                ""
            }
        ))
    };
    if meta.is_dir() {
        return Err(PointFileError::Invalid(format!(
            "{} is a directory",
            path.display()
        )));
    }
    if meta.is_file() && meta.len() > limit {
        return Err(too_big());
    }
    let mut bytes = Vec::new();
    (&mut file)
        .take(probe as u64)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    check(&bytes).map_err(|e| bad(path, e))?;
    file.take((limit + 1).saturating_sub(bytes.len() as u64))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > limit {
        return Err(too_big());
    }
    Ok(bytes)
}

pub(crate) fn bad(path: &Path, msg: impl std::fmt::Display) -> PointFileError {
    PointFileError::Invalid(format!("{}: {msg}", path.display()))
}

/// How float values become 64-bit words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FloatWords {
    /// Exactly, refusing values that are not multiples of 2^-64 (exact arithmetic needs it).
    Exact,
    /// The word at or below the value: exact for every box of depth ≤ 64 bits (the checker).
    Floor,
}

impl FloatWords {
    /// The 64-bit word of float `v`.
    pub fn word(self, v: f64) -> Result<u64, gartowen_core::CoreError> {
        match self {
            FloatWords::Exact => gartowen_core::word_from_f64(v, Width::W64),
            FloatWords::Floor => gartowen_core::word_from_f64_floor(v),
        }
    }
}

/// Reads a point set as `format` says (by the extension when `None`), and whether its file
/// held floats (CSV values or float64 `.npy`, converted to 64-bit words as `floats` says)
/// rather than words.
pub fn read_points(
    path: &Path,
    format: Option<Format>,
    floats: FloatWords,
) -> Result<(PointSet, bool), PointFileError> {
    let Some(format) = format.or_else(|| Format::from_extension(path)) else {
        return Err(bad(
            path,
            "cannot tell the format from the extension (.npy, .csv, .hex or .txt); name the format",
        ));
    };
    if format == Format::Npy {
        return npy::read_npy_file(path, floats);
    }
    let bytes = read_limited(path, MAX_INPUT_BYTES, TEXT_PROBE, text_probe)?;
    match format {
        Format::Npy => npy::read_npy(path, &bytes, floats),
        Format::Csv => text::read_csv(path, &bytes, floats).map(|p| (p, true)),
        Format::Hex => text::read_hex(path, &bytes).map(|p| (p, false)),
    }
}

#[cfg(test)]
mod fuzz;
