//! Point-set readers: .npy (float64, uint32, uint64; C or Fortran order), CSV of floats, and
//! hex words. Every error names the file and the offending line, point or dtype.

use crate::CliError;
use gartowen::core::Width;
use gartowen::netcheck::PointSet;
use std::path::Path;

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

/// The certificate record of a point file: its path, the FNV-1a checksum of its words
/// (row-major, little-endian) and its shape.
pub fn file_record(path: &Path, points: &PointSet) -> gartowen::certificate::InputRecord {
    gartowen::reports::point_set_record("file", &path.display().to_string(), points)
}

/// The largest point file read (2 GiB): the parsed points take at least as much again, and a
/// stream such as /dev/zero would otherwise be read until memory runs out.
pub const MAX_INPUT_BYTES: u64 = 2 << 30;

/// The file's text, refused (exit 2) past `limit` bytes or when it is not UTF-8.
pub fn read_text_bounded(path: &Path, limit: u64) -> Result<String, CliError> {
    String::from_utf8(read_limited(path, limit, TEXT_PROBE, text_probe)?)
        .map_err(|_| bad(path, "is not UTF-8 text"))
}

/// Bytes of a text input looked at before the rest is read.
const TEXT_PROBE: usize = 4096;

/// Refuses binary data where text is expected (a NUL byte), so that a stream such as
/// /dev/zero is refused after a few bytes instead of after the whole read budget.
fn text_probe(first: &[u8]) -> Result<(), String> {
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
fn read_limited(
    path: &Path,
    limit: u64,
    probe: usize,
    check: impl Fn(&[u8]) -> Result<(), String>,
) -> Result<Vec<u8>, CliError> {
    use std::io::Read;
    let cannot = |e: std::io::Error| CliError::Io(format!("cannot read {}: {e}", path.display()));
    let too_big = || {
        CliError::Usage(format!(
            "{}: larger than {limit} bytes, the most gartowen reads",
            path.display()
        ))
    };
    let mut file = std::fs::File::open(path).map_err(cannot)?;
    let meta = file.metadata().map_err(cannot)?;
    if meta.is_dir() {
        return Err(CliError::Usage(format!(
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

fn bad(path: &Path, msg: impl std::fmt::Display) -> CliError {
    CliError::Usage(format!("{}: {msg}", path.display()))
}

/// Reads a point set.
pub fn read_points(path: &Path, format: InputFormat) -> Result<PointSet, CliError> {
    read_points_typed(path, format, FloatWords::Exact).map(|(p, _)| p)
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
    fn word(self, v: f64) -> Result<u64, gartowen::core::CoreError> {
        match self {
            FloatWords::Exact => gartowen::core::word_from_f64(v, Width::W64),
            FloatWords::Floor => gartowen::core::word_from_f64_floor(v),
        }
    }
}

/// Reads a point set and whether its file held floats (CSV values or float64 `.npy`,
/// converted to 64-bit words as `floats` says) rather than words.
pub fn read_points_typed(
    path: &Path,
    format: InputFormat,
    floats: FloatWords,
) -> Result<(PointSet, bool), CliError> {
    let format = match format {
        InputFormat::Auto => match path.extension().and_then(|e| e.to_str()) {
            Some("npy") => InputFormat::Npy,
            Some("csv") => InputFormat::Csv,
            Some("hex") | Some("txt") => InputFormat::Hex,
            _ => {
                return Err(bad(
                    path,
                    "cannot tell the format from the extension; pass --format npy|csv|hex",
                ))
            }
        },
        f => f,
    };
    if format == InputFormat::Npy {
        return read_npy_file(path, floats);
    }
    let bytes = read_limited(path, MAX_INPUT_BYTES, TEXT_PROBE, text_probe)?;
    match format {
        InputFormat::Npy => read_npy(path, &bytes, floats),
        InputFormat::Csv => read_csv(path, &bytes, floats).map(|p| (p, true)),
        InputFormat::Hex => read_hex(path, &bytes).map(|p| (p, false)),
        InputFormat::Auto => unreachable!(),
    }
}

/// The word width and item size of a .npy dtype gartowen reads (little-endian float64,
/// uint32, uint64); the error names the dtype, its byte order where that is the trouble, and
/// the dtypes accepted.
fn npy_dtype(descr: &str) -> Result<(Width, usize), String> {
    let descr = descr.trim_matches('\'');
    let accepted = "float64 values in [0,1) ('<f8') or uint32/uint64 words ('<u4', '<u8')";
    if let Some(rest) = descr.strip_prefix('>') {
        if matches!(rest, "f8" | "u4" | "u8") {
            return Err(format!(
                "dtype '{descr}' is big-endian; gartowen reads little-endian {accepted}: \
                 convert with a.astype(a.dtype.newbyteorder('<'))"
            ));
        }
    }
    match descr.trim_start_matches(['<', '|', '=']) {
        "f8" | "u8" => Ok((Width::W64, 8)),
        "u4" => Ok((Width::W32, 4)),
        _ => Err(format!(
            "unsupported dtype '{descr}': gartowen reads {accepted}"
        )),
    }
}

/// The first bytes of every .npy file.
const NPY_MAGIC: &[u8] = b"\x93NUMPY";

/// Deepest bracket nesting accepted in a .npy header (a plain header has 2: the dict and the
/// shape tuple).
const NPY_MAX_NESTING: usize = 4;

/// The shape a .npy header declares and where the header ends (the data starts), read
/// without trusting the header: the header length must lie inside the file and the shape's
/// element count must not overflow (npyz would multiply it unchecked).
fn npy_declared_shape(bytes: &[u8]) -> Result<(Vec<u64>, usize), String> {
    if bytes.len() < 10 || &bytes[..6] != b"\x93NUMPY" {
        return Err("not a valid .npy file: no NUMPY magic".into());
    }
    let (len, start) = match bytes[6] {
        1 => (u16::from_le_bytes([bytes[8], bytes[9]]) as usize, 10usize),
        2 | 3 if bytes.len() >= 12 => (
            u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]) as usize,
            12,
        ),
        v => return Err(format!("not a valid .npy file: format version {v}")),
    };
    let end = start
        .checked_add(len)
        .filter(|&e| e <= bytes.len())
        .ok_or_else(|| {
            format!(
                "not a valid .npy file: the header claims {len} bytes, the file has {}",
                bytes.len()
            )
        })?;
    let text = String::from_utf8_lossy(&bytes[start..end]);
    // npyz's header parser takes exponential time in the nesting depth (23 nested braces ran
    // for minutes; found by fuzzing): a point file's header is a flat dict with a shape tuple.
    let (mut depth, mut deepest) = (0usize, 0usize);
    for c in text.chars() {
        match c {
            '(' | '[' | '{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            ')' | ']' | '}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    if deepest > NPY_MAX_NESTING {
        return Err(format!(
            "not a valid .npy file: the header nests brackets {deepest} deep (a point file's \
             header is a flat dict; at most {NPY_MAX_NESTING})"
        ));
    }
    let shape_text = text
        .split_once("'shape'")
        .and_then(|(_, rest)| rest.split_once('('))
        .and_then(|(_, rest)| rest.split_once(')'))
        .map(|(inside, _)| inside)
        .ok_or("not a valid .npy file: no shape in the header")?;
    let shape = shape_text
        .split(',')
        .map(str::trim)
        .filter(|t| !t.is_empty())
        .map(|t| {
            t.trim_end_matches('L')
                .parse::<u64>()
                .map_err(|_| format!("shape entry '{t}' is not a 64-bit size"))
        })
        .collect::<Result<Vec<u64>, String>>()?;
    if shape
        .iter()
        .try_fold(1u64, |a, &d| a.checked_mul(d))
        .is_none()
    {
        return Err(format!("shape {shape:?} overflows 64 bits"));
    }
    Ok((shape, end))
}

fn read_npy(path: &Path, bytes: &[u8], floats: FloatWords) -> Result<(PointSet, bool), CliError> {
    let (_, end) = npy_declared_shape(bytes).map_err(|e| bad(path, e))?;
    decode_npy(
        path,
        &bytes[..end],
        bytes.len() - end,
        &bytes[end..],
        floats,
    )
}

/// Reads a regular .npy file header first, then its data straight into the point set's
/// columns (the file's bytes are never held whole); other files go through [`read_npy`].
fn read_npy_file(path: &Path, floats: FloatWords) -> Result<(PointSet, bool), CliError> {
    use std::io::Read;
    let cannot = |e: std::io::Error| CliError::Io(format!("cannot read {}: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(cannot)?;
    let meta = file.metadata().map_err(cannot)?;
    if !meta.is_file() || meta.len() > MAX_INPUT_BYTES {
        drop(file);
        // A stream is refused at its first bytes unless they are the .npy magic.
        let bytes = read_limited(path, MAX_INPUT_BYTES, NPY_MAGIC.len(), |first| {
            if first == NPY_MAGIC {
                Ok(())
            } else {
                Err(format!(
                    "not a .npy file: it starts with {first:02x?}, not the magic \\x93NUMPY"
                ))
            }
        })?;
        return read_npy(path, &bytes, floats);
    }
    let total = meta.len() as usize;
    let mut reader = std::io::BufReader::with_capacity(1 << 20, file);
    // The preamble (magic, version, header length), then the header it announces.
    let mut header = vec![0u8; 12.min(total)];
    reader.read_exact(&mut header).map_err(cannot)?;
    let header_len = match header.get(6) {
        Some(1) => 10 + u16::from_le_bytes([header[8], header[9]]) as usize,
        Some(2 | 3) if header.len() == 12 => {
            12 + u32::from_le_bytes([header[8], header[9], header[10], header[11]]) as usize
        }
        // Let the byte-level parser name what is wrong.
        _ => return read_npy(path, &header, floats),
    };
    if header_len > total {
        return read_npy(path, &header, floats);
    }
    let already = header.len();
    header.resize(header_len.max(already), 0);
    reader.read_exact(&mut header[already..]).map_err(cannot)?;
    let (_, end) = npy_declared_shape(&header).map_err(|e| bad(path, e))?;
    // Bytes of a v1 header read past its end belong to the data.
    let (head, early) = header.split_at(end);
    decode_npy(path, head, total - end, early.chain(reader), floats)
}

/// Decodes a .npy file from its header bytes and a reader of its `data_len` data bytes.
fn decode_npy(
    path: &Path,
    bytes: &[u8],
    data_bytes: usize,
    mut data: impl std::io::Read,
    float_words: FloatWords,
) -> Result<(PointSet, bool), CliError> {
    let (declared, _) = npy_declared_shape(bytes).map_err(|e| bad(path, e))?;
    let npy =
        npyz::NpyFile::new(bytes).map_err(|e| bad(path, format!("not a valid .npy file: {e}")))?;
    let shape = npy.shape().to_vec();
    if shape != declared {
        return Err(bad(
            path,
            format!("unreadable shape in the header: {shape:?}"),
        ));
    }
    // The dtype first (a wrong one is named as such), then the element count must match the
    // data that follows, byte for byte.
    let descr = npy.dtype().descr();
    let (width, item) = npy_dtype(&descr).map_err(|e| bad(path, e))?;
    let elements = npy.len();
    let item = item as u64;
    if elements.checked_mul(item) != Some(data_bytes as u64) {
        return Err(bad(
            path,
            format!(
                "the header's shape {shape:?} ({elements} elements of {item} bytes) does not match the {data_bytes} data bytes"
            ),
        ));
    }
    let (n, dims) = match shape.as_slice() {
        [n] => (*n as usize, 1usize),
        [n, d] => (*n as usize, *d as usize),
        _ => {
            return Err(bad(
                path,
                format!("expected a 1-D or 2-D array, got shape {shape:?}"),
            ))
        }
    };
    if n == 0 || dims == 0 {
        return Err(bad(path, format!("empty array of shape {shape:?}")));
    }
    let fortran = npy.order() == npyz::Order::Fortran;
    // Decoded straight into columns: no intermediate copies of the values.
    // Element k of the data is (point, dimension) (k / dims, k % dims) in C order and
    // (k % n, k / n) in Fortran order.
    let point_dim: fn(usize, usize, usize) -> (usize, usize) = if fortran {
        |k, n, _| (k % n, k / n)
    } else {
        |k, _, dims| (k / dims, k % dims)
    };
    let dtype = descr.trim_matches('\'').trim_start_matches(['<', '|', '=']);
    let item = item as usize;
    let floats = dtype == "f8";
    let mut coords = vec![vec![0u64; n]; dims];
    let mut block = vec![0u8; (1 << 20) / item * item];
    let mut k = 0usize;
    let total = n * dims;
    while k < total {
        let len = block.len().min((total - k) * item);
        data.read_exact(&mut block[..len])
            .map_err(|e| CliError::Io(format!("cannot read {}: {e}", path.display())))?;
        for chunk in block[..len].chunks_exact(item) {
            let (i, j) = point_dim(k, n, dims);
            coords[j][i] = match (item, floats) {
                (4, _) => u32::from_le_bytes(chunk.try_into().expect("4 bytes")) as u64,
                (_, false) => u64::from_le_bytes(chunk.try_into().expect("8 bytes")),
                (_, true) => {
                    let v = f64::from_le_bytes(chunk.try_into().expect("8 bytes"));
                    float_words.word(v).map_err(|e| {
                        bad(
                            path,
                            gartowen::netcheck::NetError::BadValue {
                                point: i,
                                dim: j,
                                reason: e.to_string(),
                            },
                        )
                    })?
                }
            };
            k += 1;
        }
    }
    PointSet::from_columns(width, coords)
        .map(|p| (p, floats))
        .map_err(|e| bad(path, e))
}

/// Lines that carry data: trimmed, skipping blank lines and '#' comments, with 1-based numbers.
/// Lines end in LF, CRLF or a lone CR (old Mac files; read as one line they once merged two points into one).
fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.split('\n')
        .flat_map(|l| l.strip_suffix('\r').unwrap_or(l).split('\r'))
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
}

fn utf8<'a>(path: &Path, bytes: &'a [u8]) -> Result<&'a str, CliError> {
    std::str::from_utf8(bytes).map_err(|_| bad(path, "not a text file (invalid UTF-8)"))
}

/// Records the first row's width in `dims` and rejects a later row of another width.
fn same_width(
    path: &Path,
    dims: &mut Option<usize>,
    line_no: usize,
    len: usize,
    what: &str,
) -> Result<(), CliError> {
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

fn read_csv(path: &Path, bytes: &[u8], floats: FloatWords) -> Result<PointSet, CliError> {
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

fn read_hex(path: &Path, bytes: &[u8]) -> Result<PointSet, CliError> {
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

/// Fuzzing of the readers: arbitrary and mutated inputs must give a point set or a named
/// error, never a panic, an abort or an allocation the input does not justify.
#[cfg(test)]
mod fuzz {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn signed_hex_words_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("signed.hex");
        for (text, ok) in [
            ("00000001 00000002\n", true),
            ("+0000001 00000002\n", false),
            ("00000001 -0000002\n", false),
        ] {
            std::fs::write(&path, text).unwrap();
            match read_points(&path, InputFormat::Hex) {
                Ok(p) => assert!(ok, "{text} was read: {:?}", p.point(0)),
                Err(e) => {
                    assert!(!ok, "{text}: {e}");
                    assert!(e.to_string().contains("is not hexadecimal"), "{e}");
                }
            }
        }
    }

    fn npy_header(descr: &str, fortran: bool, shape: &str) -> Vec<u8> {
        let dict = format!(
            "{{'descr': '{descr}', 'fortran_order': {}, 'shape': {shape}, }}",
            if fortran { "True" } else { "False" }
        );
        let mut header = dict.into_bytes();
        while (10 + header.len() + 1) % 64 != 0 {
            header.push(b' ');
        }
        header.push(b'\n');
        let mut out = b"\x93NUMPY\x01\x00".to_vec();
        out.extend_from_slice(&(header.len() as u16).to_le_bytes());
        out.extend_from_slice(&header);
        out
    }

    fn valid_npy(rows: usize, dims: usize, fortran: bool) -> Vec<u8> {
        let mut out = npy_header("<f8", fortran, &format!("({rows}, {dims})"));
        for k in 0..rows * dims {
            out.extend_from_slice(&((k as f64 + 0.5) / (rows * dims) as f64).to_le_bytes());
        }
        out
    }

    fn all_readers(bytes: &[u8]) {
        let p = Path::new("fuzz");
        for floats in [FloatWords::Exact, FloatWords::Floor] {
            let sets = [
                read_npy(p, bytes, floats).map(|(s, _)| s),
                read_csv(p, bytes, floats),
                read_hex(p, bytes),
            ];
            for set in sets.into_iter().flatten() {
                assert!(!set.is_empty() && set.dims() >= 1);
            }
        }
    }

    #[test]
    fn deeply_nested_headers_are_refused_at_once() {
        // 23 nested braces took npyz's parser minutes; refused before it is called.
        let mut bytes = npy_header("<f8", false, "(3, 2)");
        let at = bytes.iter().position(|&b| b == b'{').unwrap();
        bytes.splice(at..at, std::iter::repeat_n(b'{', 23));
        let len = (bytes.len() - 10) as u16;
        bytes[8..10].copy_from_slice(&len.to_le_bytes());
        let e = npy_declared_shape(&bytes).unwrap_err();
        assert!(e.contains("nests brackets 25 deep"), "{e}");
        let mut ok = npy_header("<f8", false, "(3, 2)");
        ok.extend_from_slice(&[0u8; 48]);
        assert_eq!(npy_declared_shape(&ok).unwrap().0, vec![3, 2]);
    }

    #[test]
    fn headers_that_claim_more_data_than_the_file_holds_are_refused() {
        // A shape of 2^40 rows over 16 data bytes must be an error, not an attempt to
        // allocate terabytes (npyz checks the data length against the shape; this pins it).
        for shape in [
            "(1099511627776, 1)",
            "(2, 9223372036854775807)",
            "(4611686018427387904,)",
        ] {
            let mut bytes = npy_header("<f8", false, shape);
            bytes.extend_from_slice(&[0u8; 16]);
            let e = read_npy(Path::new("big.npy"), &bytes, FloatWords::Exact).expect_err("refused");
            assert!(e.to_string().contains("big.npy"), "{e}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        #[test]
        fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..256)) {
            all_readers(&bytes);
        }

        #[test]
        fn mutated_npy_files_never_panic(
            rows in 1usize..6, dims in 1usize..4, fortran in any::<bool>(),
            edits in proptest::collection::vec((any::<u16>(), any::<u8>()), 1..6),
            cut in any::<u16>(),
        ) {
            let mut bytes = valid_npy(rows, dims, fortran);
            for (at, v) in edits {
                let i = at as usize % bytes.len();
                bytes[i] = v;
            }
            let keep = bytes.len() - (cut as usize % 8).min(bytes.len());
            bytes.truncate(keep);
            all_readers(&bytes);
        }

        #[test]
        fn text_from_the_format_alphabets_never_panics(
            text in "[0-9a-fA-Fx.,eE+\\- #\\n]{0,200}"
        ) {
            all_readers(text.as_bytes());
        }

        #[test]
        fn valid_files_read_back(rows in 1usize..20, dims in 1usize..5, fortran in any::<bool>()) {
            let (set, floats) =
                read_npy(Path::new("ok.npy"), &valid_npy(rows, dims, fortran), FloatWords::Exact)
                    .unwrap();
            prop_assert!(floats);
            prop_assert_eq!((set.len(), set.dims()), (rows, dims));
        }
    }
}
