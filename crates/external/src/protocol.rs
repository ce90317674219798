//! The protocol's frames as bytes: request encoding and decoding, reply checks (no I/O).

use crate::error::ExternalError;
use gartowen_core::{CoreError, PowerOfTwoBase, Radix, RadixLayout, Width};

/// Request magic, `GOWQ`.
pub const REQUEST_MAGIC: [u8; 4] = *b"GOWQ";
/// Reply magic, `GOWR`.
pub const REPLY_MAGIC: [u8; 4] = *b"GOWR";
/// Protocol version of frames in a base 2^q (words are W-bit binary fractions).
pub const PROTOCOL_VERSION: u16 = 1;
/// Protocol version of frames in any other base b (words are base-b digit integers below b^m,
/// m the most digits with b^m ≤ 2^W; the framing is version 1's).
pub const RADIX_PROTOCOL_VERSION: u16 = 2;
/// Most words in one request.
pub const MAX_BATCH: usize = 1 << 20;
/// Request header length in bytes.
pub const HEADER_BYTES: usize = 32;

/// The base a request names, which fixes its version: 1 for b = 2^q, 2 for other bases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProtocolBase {
    /// Base 2^q: words carry digits in their bits (version 1).
    PowerOfTwo(PowerOfTwoBase),
    /// Another base: words are base-b digit integers (version 2).
    Radix(Radix),
}

impl ProtocolBase {
    /// Base `b`: 2^q up to 256, or any base 3..=65535 that is not a power of two.
    ///
    /// ```
    /// use gartowen_external::protocol::ProtocolBase;
    /// assert_eq!(ProtocolBase::from_base(16).unwrap().version(), 1);
    /// assert_eq!(ProtocolBase::from_base(3).unwrap().version(), 2);
    /// assert!(ProtocolBase::from_base(1).is_err());
    /// ```
    pub fn from_base(b: u64) -> Result<ProtocolBase, CoreError> {
        match PowerOfTwoBase::from_base(b) {
            Ok(p) => Ok(ProtocolBase::PowerOfTwo(p)),
            Err(_) => Radix::new(b).map(ProtocolBase::Radix),
        }
    }

    /// The base b.
    pub fn get(self) -> u32 {
        match self {
            ProtocolBase::PowerOfTwo(p) => p.base(),
            ProtocolBase::Radix(r) => r.get(),
        }
    }

    /// The protocol version of its frames.
    pub fn version(self) -> u16 {
        match self {
            ProtocolBase::PowerOfTwo(_) => PROTOCOL_VERSION,
            ProtocolBase::Radix(_) => RADIX_PROTOCOL_VERSION,
        }
    }

    /// The base 2^q, if it is one.
    pub fn power_of_two(self) -> Option<PowerOfTwoBase> {
        match self {
            ProtocolBase::PowerOfTwo(p) => Some(p),
            ProtocolBase::Radix(_) => None,
        }
    }

    /// The base, if it is not a power of two.
    pub fn radix(self) -> Option<Radix> {
        match self {
            ProtocolBase::PowerOfTwo(_) => None,
            ProtocolBase::Radix(r) => Some(r),
        }
    }

    /// The largest word a frame of `width` bits may carry either way: 2^W − 1 in version 1,
    /// b^m − 1 in version 2 (m the most base-b digits whose b^m fits W bits).
    ///
    /// ```
    /// use gartowen_core::Width;
    /// use gartowen_external::protocol::ProtocolBase;
    /// let three = ProtocolBase::from_base(3).unwrap();
    /// assert_eq!(three.largest_word(Width::W32), 3u64.pow(20) - 1);
    /// assert_eq!(ProtocolBase::from_base(4).unwrap().largest_word(Width::W32), u32::MAX as u64);
    /// ```
    pub fn largest_word(self, width: Width) -> u64 {
        match self {
            ProtocolBase::PowerOfTwo(_) => width.mask(),
            // Every base up to 65535 has a digit in 32 bits, so the layout exists.
            ProtocolBase::Radix(r) => RadixLayout::new(width, r).map_or(0, |l| l.capacity() - 1),
        }
    }
}

impl From<PowerOfTwoBase> for ProtocolBase {
    fn from(b: PowerOfTwoBase) -> Self {
        ProtocolBase::PowerOfTwo(b)
    }
}

/// The fixed fields of a request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RequestHeader {
    /// Word width (32 or 64).
    pub width: Width,
    /// The base (and with it the version).
    pub base: ProtocolBase,
    /// Dimension.
    pub dim: u32,
    /// Seed.
    pub seed: u64,
}

/// Encodes a request frame for `words`.
pub fn encode_request(h: &RequestHeader, words: &[u64]) -> Result<Vec<u8>, ExternalError> {
    if words.is_empty() || words.len() > MAX_BATCH {
        return Err(ExternalError::BadRequest(format!(
            "{} words (1..={MAX_BATCH} allowed)",
            words.len()
        )));
    }
    let largest = h.base.largest_word(h.width);
    if let Some((k, w)) = words.iter().enumerate().find(|(_, &w)| w > largest) {
        return Err(ExternalError::BadRequest(format!(
            "word {k} is {w:#x}, above the largest {}-bit word of base {} ({largest:#x})",
            h.width.bits(),
            h.base.get()
        )));
    }
    let wb = h.width.bits() as usize / 8;
    let mut out = Vec::with_capacity(HEADER_BYTES + words.len() * wb);
    push_header(&mut out, h, words.len());
    for &w in words {
        out.extend_from_slice(&w.to_le_bytes()[..wb]);
    }
    Ok(out)
}

/// Appends the 32 header bytes of a request for `count` words (checked by the caller).
pub(super) fn push_header(out: &mut Vec<u8>, h: &RequestHeader, count: usize) {
    out.extend_from_slice(&REQUEST_MAGIC);
    out.extend_from_slice(&h.base.version().to_le_bytes());
    out.extend_from_slice(&(h.width.bits() as u16).to_le_bytes());
    out.extend_from_slice(&h.base.get().to_le_bytes());
    out.extend_from_slice(&h.dim.to_le_bytes());
    out.extend_from_slice(&(count as u32).to_le_bytes());
    out.extend_from_slice(&0u32.to_le_bytes());
    out.extend_from_slice(&h.seed.to_le_bytes());
}

/// Decodes a request frame (the child's side; the host uses it in tests and fuzzing):
/// the header and the words, or a reason the bytes are not one complete frame.
pub fn decode_request(bytes: &[u8]) -> Result<(RequestHeader, Vec<u64>), String> {
    if bytes.len() < HEADER_BYTES {
        return Err(format!(
            "{} bytes, a header needs {HEADER_BYTES}",
            bytes.len()
        ));
    }
    if bytes[..4] != REQUEST_MAGIC {
        return Err(format!("magic {:02x?} is not GOWQ", &bytes[..4]));
    }
    let u16_at = |o: usize| u16::from_le_bytes([bytes[o], bytes[o + 1]]);
    let u32_at = |o: usize| u32::from_le_bytes(bytes[o..o + 4].try_into().expect("4 bytes"));
    let version = u16_at(4);
    if version != PROTOCOL_VERSION && version != RADIX_PROTOCOL_VERSION {
        return Err(format!("protocol version {version}"));
    }
    let width = match u16_at(6) {
        32 => Width::W32,
        64 => Width::W64,
        w => return Err(format!("width {w} is not 32 or 64")),
    };
    let b = u32_at(8) as u64;
    let base = if version == PROTOCOL_VERSION {
        ProtocolBase::PowerOfTwo(PowerOfTwoBase::from_base(b).map_err(|e| e.to_string())?)
    } else {
        ProtocolBase::Radix(Radix::new(b).map_err(|e| format!("version 2: {e}"))?)
    };
    let count = u32_at(16) as usize;
    if count == 0 || count > MAX_BATCH {
        return Err(format!("count {count} outside 1..={MAX_BATCH}"));
    }
    let wb = width.bits() as usize / 8;
    if bytes.len() != HEADER_BYTES + count * wb {
        return Err(format!(
            "{} bytes, the frame needs {}",
            bytes.len(),
            HEADER_BYTES + count * wb
        ));
    }
    if u32_at(20) != 0 {
        return Err(format!("reserved field {:#x} is not 0", u32_at(20)));
    }
    let seed = u64::from_le_bytes(bytes[24..32].try_into().expect("8 bytes"));
    let words = words_from_le(&bytes[HEADER_BYTES..], wb);
    let largest = base.largest_word(width);
    if let Some((k, w)) = words.iter().enumerate().find(|(_, &w)| w > largest) {
        return Err(format!(
            "word {k} is {w:#x}, above the largest word of base {} ({largest:#x})",
            base.get()
        ));
    }
    Ok((
        RequestHeader {
            width,
            base,
            dim: u32_at(12),
            seed,
        },
        words,
    ))
}

/// Decodes a complete reply of `count` words of `width` bits in `base` for request `batch`.
pub fn decode_reply(
    bytes: &[u8],
    count: usize,
    width: Width,
    base: ProtocolBase,
    batch: u64,
) -> Result<Vec<u64>, ExternalError> {
    check_reply(bytes, count, width, base, batch)?;
    Ok(words_from_le(&bytes[8..], width.bits() as usize / 8))
}

/// Checks a complete reply's length, magic and count, and that every word is one of the
/// base's words (below b^m in version 2: a larger one would pass for another word's image).
pub(super) fn check_reply(
    bytes: &[u8],
    count: usize,
    width: Width,
    base: ProtocolBase,
    batch: u64,
) -> Result<(), ExternalError> {
    let wb = width.bits() as usize / 8;
    let need = 8 + count * wb;
    if bytes.len() != need {
        return Err(ExternalError::Garbage {
            batch,
            detail: format!("{} bytes, the reply needs {need}", bytes.len()),
        });
    }
    if bytes[..4] != REPLY_MAGIC {
        return Err(ExternalError::Garbage {
            batch,
            detail: format!(
                "starts with {:?} ({:02x?}), not the reply magic GOWR",
                String::from_utf8_lossy(&bytes[..4]),
                &bytes[..4]
            ),
        });
    }
    let n = u32::from_le_bytes(bytes[4..8].try_into().expect("4 bytes")) as usize;
    if n != count {
        return Err(ExternalError::Garbage {
            batch,
            detail: format!("reply count {n}, the request had {count}"),
        });
    }
    let largest = base.largest_word(width);
    if largest != width.mask() {
        let wb = width.bits() as usize / 8;
        let out_of_range = le_words(&bytes[8..], wb)
            .enumerate()
            .find(|&(_, w)| w > largest);
        if let Some((k, w)) = out_of_range {
            return Err(ExternalError::Garbage {
                batch,
                detail: format!(
                    "reply word {k} is {w}, not below {} = {}^{} (version 2 words are base-{} \
                     digit integers)",
                    largest as u128 + 1,
                    base.get(),
                    base.radix().map_or(0, |r| r.digits_in(width)),
                    base.get()
                ),
            });
        }
    }
    Ok(())
}

/// Little-endian words of `wb` bytes each (a trailing partial word is ignored).
fn words_from_le(bytes: &[u8], wb: usize) -> Vec<u64> {
    le_words(bytes, wb).collect()
}

/// The little-endian words of `wb` bytes each, read in place (no allocation).
fn le_words(bytes: &[u8], wb: usize) -> impl Iterator<Item = u64> + '_ {
    bytes.chunks_exact(wb).map(move |c| {
        let mut b = [0u8; 8];
        b[..wb].copy_from_slice(c);
        u64::from_le_bytes(b)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header(b: u64, width: Width) -> RequestHeader {
        RequestHeader {
            width,
            base: ProtocolBase::from_base(b).unwrap(),
            dim: 1,
            seed: 2,
        }
    }

    fn reply(words: &[u64], width: Width) -> Vec<u8> {
        let wb = width.bits() as usize / 8;
        let mut out = REPLY_MAGIC.to_vec();
        out.extend_from_slice(&(words.len() as u32).to_le_bytes());
        for w in words {
            out.extend_from_slice(&w.to_le_bytes()[..wb]);
        }
        out
    }

    #[test]
    fn the_largest_word_is_b_to_the_m_less_one_or_the_width_mask() {
        for (b, w, want) in [
            (3, Width::W32, 3u64.pow(20) - 1),
            (3, Width::W64, 3u64.pow(40) - 1),
            (5, Width::W32, 5u64.pow(13) - 1),
            (65_535, Width::W32, 65_535u64.pow(2) - 1),
            (2, Width::W32, u32::MAX as u64),
            (256, Width::W64, u64::MAX),
        ] {
            assert_eq!(
                ProtocolBase::from_base(b).unwrap().largest_word(w),
                want,
                "{b} {w:?}"
            );
        }
    }

    #[test]
    fn words_past_the_largest_are_refused_on_every_side_and_the_largest_passes() {
        for (b, width) in [(3, Width::W32), (5, Width::W64), (6, Width::W32)] {
            let h = header(b, width);
            let largest = h.base.largest_word(width);
            let frame = encode_request(&h, &[0, largest]).unwrap();
            assert_eq!(decode_request(&frame).unwrap().1, vec![0, largest]);
            let e = encode_request(&h, &[0, largest + 1])
                .unwrap_err()
                .to_string();
            assert!(
                e.contains("word 1") && e.contains("above the largest"),
                "{e}"
            );
            let mut bad = frame.clone();
            let wb = width.bits() as usize / 8;
            bad[HEADER_BYTES + wb..].copy_from_slice(&(largest + 1).to_le_bytes()[..wb]);
            assert!(decode_request(&bad).unwrap_err().contains("word 1"));
            let ok = decode_reply(&reply(&[largest, 7], width), 2, width, h.base, 1).unwrap();
            assert_eq!(ok, vec![largest, 7]);
            let e = decode_reply(&reply(&[7, largest + 1], width), 2, width, h.base, 1)
                .unwrap_err()
                .to_string();
            assert!(
                e.contains(&format!("reply word 1 is {}", largest + 1)),
                "{e}"
            );
            assert!(e.contains(&format!("{b}^")), "{e}");
        }
        // A base 2^q's words fill the width: nothing is out of range.
        let h = header(4, Width::W32);
        let all = [0, u32::MAX as u64];
        assert!(decode_reply(&reply(&all, Width::W32), 2, Width::W32, h.base, 1).is_ok());
    }
}
