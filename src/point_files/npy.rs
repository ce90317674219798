//! The .npy reader: the header checked before it is trusted, the data decoded straight into
//! the point set's columns.

use super::{bad, read_limited_from, FloatWords, PointFileError, MAX_INPUT_BYTES};
use gartowen_core::Width;
use gartowen_netcheck::PointSet;
use std::path::Path;

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
pub(crate) fn npy_declared_shape(bytes: &[u8]) -> Result<(Vec<u64>, usize), String> {
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

/// Reads a .npy file held in `bytes` (`path` names it in errors); with whether it held floats.
pub fn read_npy(
    path: &Path,
    bytes: &[u8],
    floats: FloatWords,
) -> Result<(PointSet, bool), PointFileError> {
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
pub(crate) fn read_npy_file(
    path: &Path,
    floats: FloatWords,
) -> Result<(PointSet, bool), PointFileError> {
    use std::io::Read;
    let cannot =
        |e: std::io::Error| PointFileError::Io(format!("cannot read {}: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(cannot)?;
    let meta = file.metadata().map_err(cannot)?;
    if !meta.is_file() || meta.len() > MAX_INPUT_BYTES {
        // A stream is refused at its first bytes unless they are the .npy magic; it is read
        // from the handle already open (a FIFO cannot be opened twice).
        let bytes = read_limited_from(file, path, MAX_INPUT_BYTES, NPY_MAGIC.len(), |first| {
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
) -> Result<(PointSet, bool), PointFileError> {
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
            .map_err(|e| PointFileError::Io(format!("cannot read {}: {e}", path.display())))?;
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
                            gartowen_netcheck::NetError::BadValue {
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
