//! Box keys and the per-shape box check shared by every counting path.
//!
//! A shape (d_1..d_s) puts point i in the box whose key is the mixed-radix number of its digits
//! a_j = floor(x_ij · b^(d_j)), dimension 1 most significant: key = Σ_j a_j · b^(Σ_{i>j} d_i).
//! Digits come from the per-dimension prefixes floor(x · b^depth) by a cut (a shift for
//! b = 2^q). [`check_shape`] takes the keys from a filler, so the same check serves keys built
//! from scratch ([`keys_of`]) and keys extended from a parent shape's (`shape_tree`).

use crate::{BoxFailure, CheckBase};

/// Borrowed per-dimension views of owned prefix arrays.
pub(crate) fn views(prefix: &[Vec<u32>]) -> Vec<&[u32]> {
    prefix.iter().map(|p| p.as_slice()).collect()
}

/// Per active dimension: its prefix slice, how to cut its digit, and where it goes in the key.
pub(crate) struct KeyPart<'a> {
    pub(crate) prefix: &'a [u32],
    /// b^(K − d_j), or the shift q(K − d_j) for b = 2^q.
    pub(crate) cut: u32,
    /// Π_{i>j} b^(d_i), or the shift q·Σ_{i>j} d_i.
    pub(crate) place: u32,
}

/// The box-key function of a shape over prefixes floor(x·b^depth) (depth ≥ every d_j).
pub(crate) fn key_parts<'a>(
    prefix: &[&'a [u32]],
    base: CheckBase,
    depth: u32,
    shape: &[u32],
) -> Vec<KeyPart<'a>> {
    let mut parts = Vec::new();
    let mut place_exp = 0u32;
    for j in (0..shape.len()).rev() {
        let d = shape[j];
        if d == 0 {
            continue;
        }
        let (cut, place) = match base.log2() {
            Some(q) => (q * (depth - d), q * place_exp),
            None => (
                base.pow(depth - d).unwrap() as u32,
                base.pow(place_exp).unwrap() as u32,
            ),
        };
        parts.push(KeyPart {
            prefix: prefix[j],
            cut,
            place,
        });
        place_exp += d;
    }
    parts
}

/// Points per chunk of box keys: small enough for L1, large enough to vectorize.
pub(crate) const CHUNK: usize = 2048;

/// Box keys of points `start..start + keys.len()`, computed part by part (vectorizable).
/// `pow2` says whether the parts hold shifts (b = 2^q) rather than divisors and multipliers.
#[inline]
pub(crate) fn keys_of(parts: &[KeyPart], pow2: bool, start: usize, keys: &mut [u32]) {
    keys.fill(0);
    let end = start + keys.len();
    for p in parts {
        let src = &p.prefix[start..end];
        if pow2 {
            let (cut, place) = (p.cut, p.place);
            for (k, &x) in keys.iter_mut().zip(src) {
                *k |= (x >> cut) << place;
            }
        } else {
            for (k, &x) in keys.iter_mut().zip(src) {
                *k += (x / p.cut) * p.place;
            }
        }
    }
}

/// The key of one point (slow path, for reporting).
fn key_at(fill: &impl Fn(usize, &mut [u32]), i: usize) -> u32 {
    let mut key = [0u32];
    fill(i, &mut key);
    key[0]
}

/// Decodes a key into the per-dimension box index.
pub(crate) fn decode_key(key: u32, base: CheckBase, shape: &[u32]) -> Vec<u64> {
    let mut rest = key as u64;
    let mut index = vec![0u64; shape.len()];
    for j in (0..shape.len()).rev() {
        let side = base.pow(shape[j]).unwrap();
        index[j] = rest % side;
        rest /= side;
    }
    index
}

/// Checks one shape over points `start..start + n`; returns the first overflowing box.
/// `fill(i, keys)` writes the box keys of points `i..i + keys.len()` (keys below b^k); the
/// shape has Σd = k.
#[allow(clippy::too_many_arguments)]
pub(crate) fn check_shape(
    fill: impl Fn(usize, &mut [u32]),
    start: usize,
    n: usize,
    base: CheckBase,
    k: u32,
    t_count: u64,
    shape: &[u32],
    scratch: &mut Vec<u32>,
) -> Option<BoxFailure> {
    let (offset, end) = (start, start + n);
    let cells = base.pow(k).unwrap() as usize;
    let mut keys = [0u32; CHUNK];
    let mut bad_key = None;
    if t_count == 1 {
        // Each box holds exactly one point: a bitset collision is the first failure. Collisions
        // are OR-ed per chunk (no branch per point); a hit chunk is rescanned to find the key.
        scratch.clear();
        scratch.resize(cells.div_ceil(32), 0);
        let mut fresh = [false; CHUNK];
        'chunks: for start in (offset..end).step_by(CHUNK) {
            let keys = &mut keys[..CHUNK.min(end - start)];
            fill(start, keys);
            let mut hit = 0u32;
            for (&key, fresh) in keys.iter().zip(fresh.iter_mut()) {
                let word = &mut scratch[(key >> 5) as usize];
                let bit = 1u32 << (key & 31);
                let was = *word & bit;
                hit |= was;
                *fresh = was == 0;
                *word |= bit;
            }
            if hit != 0 {
                // Undo only the bits this chunk set (earlier chunks' bits are the evidence),
                // then replay it point by point to find the first collision.
                for (&key, &fresh) in keys.iter().zip(fresh.iter()) {
                    if fresh {
                        scratch[(key >> 5) as usize] &= !(1u32 << (key & 31));
                    }
                }
                for &key in keys.iter() {
                    let word = &mut scratch[(key >> 5) as usize];
                    let bit = 1u32 << (key & 31);
                    if *word & bit != 0 {
                        bad_key = Some(key);
                        break 'chunks;
                    }
                    *word |= bit;
                }
            }
        }
    } else if t_count < u8::MAX as u64 {
        // Byte counters keep the histogram 4× smaller than u32 (cache-resident longer).
        let counts = scratch_bytes(scratch, cells);
        'chunks8: for start in (offset..end).step_by(CHUNK) {
            let keys = &mut keys[..CHUNK.min(end - start)];
            fill(start, keys);
            for &key in keys.iter() {
                let c = &mut counts[key as usize];
                *c += 1;
                if *c as u64 > t_count {
                    bad_key = Some(key);
                    break 'chunks8;
                }
            }
        }
    } else {
        scratch.clear();
        scratch.resize(cells, 0);
        'chunks32: for start in (offset..end).step_by(CHUNK) {
            let keys = &mut keys[..CHUNK.min(end - start)];
            fill(start, keys);
            for &key in keys.iter() {
                let c = &mut scratch[key as usize];
                *c += 1;
                if *c as u64 > t_count {
                    bad_key = Some(key);
                    break 'chunks32;
                }
            }
        }
    }
    let key = bad_key?;
    let count = (offset..end).filter(|&i| key_at(&fill, i) == key).count() as u64;
    Some(BoxFailure {
        shape: shape.to_vec(),
        box_index: decode_key(key, base, shape),
        count,
        expected: t_count,
    })
}

/// `cells` zeroed byte counters carved out of the u32 scratch buffer.
fn scratch_bytes(scratch: &mut Vec<u32>, cells: usize) -> &mut [u8] {
    scratch.clear();
    scratch.resize(cells.div_ceil(4), 0);
    let bytes: &mut [u8] = bytemuck_u32_as_u8(scratch);
    &mut bytes[..cells]
}

/// Views a u32 slice as bytes (u8 has no alignment or validity requirements).
fn bytemuck_u32_as_u8(words: &mut [u32]) -> &mut [u8] {
    let len = words.len() * 4;
    // SAFETY: u32 memory is valid u8 memory of 4× the length; the borrow is exclusive.
    unsafe { std::slice::from_raw_parts_mut(words.as_mut_ptr() as *mut u8, len) }
}

/// The filler of [`check_shape`] for keys built from a shape's parts.
pub(crate) fn parts_filler<'a>(
    parts: &'a [KeyPart<'a>],
    base: CheckBase,
) -> impl Fn(usize, &mut [u32]) + 'a {
    let pow2 = base.log2().is_some();
    move |start, keys| keys_of(parts, pow2, start, keys)
}
