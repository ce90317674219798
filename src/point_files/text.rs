//! The text readers: CSV of float values and hex words, one point per line.

use super::{bad, FloatWords, PointFileError};
use gartowen_core::Width;
use gartowen_netcheck::PointSet;
use std::path::Path;

/// Lines that carry data: trimmed, skipping blank lines and '#' comments, with 1-based numbers.
/// Lines end in LF, CRLF or a lone CR (old Mac files; read as one line they once merged two points into one).
fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.split('\n')
        .flat_map(|l| l.strip_suffix('\r').unwrap_or(l).split('\r'))
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
}

fn utf8<'a>(path: &Path, bytes: &'a [u8]) -> Result<&'a str, PointFileError> {
    std::str::from_utf8(bytes).map_err(|_| bad(path, "not a text file (invalid UTF-8)"))
}

/// Records the first row's width in `dims` and rejects a later row of another width.
fn same_width(
    path: &Path,
    dims: &mut Option<usize>,
    line_no: usize,
    len: usize,
    what: &str,
) -> Result<(), PointFileError> {
    match *dims {
        None => *dims = Some(len),
        Some(d) if d != len => {
            return Err(bad(
                path,
                format!("line {line_no} has {len} {what}, earlier lines have {d}"),
            ))
        }
        _ => {}
    }
    Ok(())
}

/// Reads CSV float values held in `bytes` (`path` names it in errors).
pub fn read_csv(path: &Path, bytes: &[u8], floats: FloatWords) -> Result<PointSet, PointFileError> {
    let text = utf8(path, bytes)?;
    let mut values = Vec::new();
    let mut dims = None;
    for (line_no, line) in data_lines(text) {
        let row: Vec<&str> = line.split(',').map(str::trim).collect();
        same_width(path, &mut dims, line_no, row.len(), "values")?;
        for field in row {
            let v: f64 = field
                .parse()
                .map_err(|_| bad(path, format!("line {line_no}: '{field}' is not a number")))?;
            values.push(v);
        }
    }
    let dims = dims.ok_or_else(|| bad(path, "no data lines"))?;
    match floats {
        FloatWords::Exact => PointSet::from_f64(dims, &values),
        FloatWords::Floor => PointSet::from_f64_floor(dims, &values),
    }
    .map_err(|e| bad(path, e))
}

/// Reads hex words held in `bytes` (`path` names it in errors).
pub fn read_hex(path: &Path, bytes: &[u8]) -> Result<PointSet, PointFileError> {
    let text = utf8(path, bytes)?;
    let mut words = Vec::new();
    let mut dims = None;
    let mut digits = None;
    for (line_no, line) in data_lines(text) {
        let row: Vec<&str> = line.split_whitespace().collect();
        same_width(path, &mut dims, line_no, row.len(), "words")?;
        for tok in row {
            let tok = tok.trim_start_matches("0x");
            match digits {
                None if tok.len() == 8 || tok.len() == 16 => digits = Some(tok.len()),
                None => {
                    return Err(bad(
                        path,
                        format!("line {line_no}: '{tok}' is not an 8- or 16-digit hex word"),
                    ))
                }
                Some(d) if d != tok.len() => {
                    return Err(bad(
                        path,
                        format!(
                            "line {line_no}: '{tok}' has {} digits, earlier words {d}",
                            tok.len()
                        ),
                    ))
                }
                _ => {}
            }
            // from_str_radix alone would take a leading '+' ("+0000001").
            let w = Some(tok)
                .filter(|t| t.bytes().all(|c| c.is_ascii_hexdigit()))
                .and_then(|t| u64::from_str_radix(t, 16).ok())
                .ok_or_else(|| bad(path, format!("line {line_no}: '{tok}' is not hexadecimal")))?;
            words.push(w);
        }
    }
    let dims = dims.ok_or_else(|| bad(path, "no data lines"))?;
    let width = if digits == Some(8) {
        Width::W32
    } else {
        Width::W64
    };
    PointSet::from_flat(width, dims, &words).map_err(|e| bad(path, e))
}
