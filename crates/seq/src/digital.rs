//! A digital sequence given by its binary generator matrices.

use crate::{GrayCodeIter, LookupTables, SeqError};
use gartowen_core::{PowerOfTwoBase, Width};

/// Generator matrices C_0..C_{s−1} of a digital sequence, each as `index_bits` column words.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DigitalSequence {
    name: String,
    width: Width,
    base: PowerOfTwoBase,
    index_bits: u32,
    /// Column c of dimension j at `j * 64 + c`; unused columns are zero.
    columns: Vec<[u64; 64]>,
}

impl DigitalSequence {
    /// A sequence from explicit columns: `columns[j][c]` is column c of C_j, a W-bit word with
    /// row 0 in its top bit. `base` is the base in which the sequence is meant to be a
    /// (t,s)-sequence (it only labels the sequence). At most 64 columns per dimension.
    pub fn from_columns(
        name: &str,
        width: Width,
        base: PowerOfTwoBase,
        columns: &[Vec<u64>],
    ) -> Result<Self, SeqError> {
        if columns.is_empty() {
            return Err(SeqError::NoDimensions);
        }
        let index_bits = columns[0].len();
        let mut packed = Vec::with_capacity(columns.len());
        for (j, cols) in columns.iter().enumerate() {
            if cols.len() != index_bits || index_bits > 64 {
                return Err(SeqError::InvalidField(format!(
                    "dimension {j} has {} columns; all dimensions need the same count ≤ 64",
                    cols.len()
                )));
            }
            let mut arr = [0u64; 64];
            for (c, &w) in cols.iter().enumerate() {
                width
                    .check(w)
                    .map_err(|e| SeqError::InvalidField(e.to_string()))?;
                arr[c] = w;
            }
            packed.push(arr);
        }
        Ok(DigitalSequence {
            name: name.to_string(),
            width,
            base,
            index_bits: index_bits as u32,
            columns: packed,
        })
    }

    /// The sequence's name (e.g. `sobol`).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Word width W of the points.
    pub fn width(&self) -> Width {
        self.width
    }

    /// The base the sequence is built for (2 for Sobol, 4 for sz4, 16 for sz16).
    pub fn base(&self) -> PowerOfTwoBase {
        self.base
    }

    /// Number of dimensions s.
    pub fn dims(&self) -> usize {
        self.columns.len()
    }

    /// Number of index bits (columns per matrix); indices run over 0..2^index_bits.
    pub fn index_bits(&self) -> u32 {
        self.index_bits
    }

    /// The number of points, 2^index_bits, saturating at u64::MAX for 64 index bits.
    pub fn max_points(&self) -> u64 {
        if self.index_bits >= 64 {
            u64::MAX
        } else {
            1u64 << self.index_bits
        }
    }

    /// Columns of C_dim, column 0 first.
    pub fn columns(&self, dim: usize) -> &[u64] {
        &self.columns[dim][..self.index_bits as usize]
    }

    /// Column c of C_dim (zero for c ≥ index_bits).
    #[inline(always)]
    pub fn column(&self, dim: usize, c: usize) -> u64 {
        self.columns[dim][c & 63]
    }

    /// Coordinate `dim` of point `index`: the XOR of the columns at the set bits of `index`.
    /// Index bits at or above `index_bits` meet zero columns; use [`Self::try_point`] to reject them.
    #[inline]
    pub fn point(&self, index: u64, dim: usize) -> u64 {
        let cols = &self.columns[dim];
        let mut i = index;
        let mut x = 0u64;
        while i != 0 {
            x ^= cols[(i.trailing_zeros() & 63) as usize];
            i &= i - 1;
        }
        x
    }

    /// Points `first..first + out.len()` of dimension `dim` (natural order) into `out`, each
    /// from the previous one: going from index i to i + 1 flips bits 0..=t, t the number of
    /// trailing ones of i, so the point changes by the XOR of columns 0..=t, read from a
    /// table of prefix XORs (one look-up per point, against one XOR per set bit of the index
    /// for [`Self::point`]). Equal to `point(first + k, dim)` (tested).
    pub fn fill_points(&self, dim: usize, first: u64, out: &mut [u64]) {
        let cols = &self.columns[dim];
        let mut prefix_xor = [0u64; 64];
        let mut acc = 0u64;
        for (p, &c) in prefix_xor.iter_mut().zip(cols.iter()) {
            acc ^= c;
            *p = acc;
        }
        let mut x = self.point(first, dim);
        let len = out.len();
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = x;
            if k + 1 < len {
                let index = first + k as u64;
                x ^= prefix_xor[((!index).trailing_zeros() & 63) as usize];
            }
        }
    }

    /// Points of Gray-code indices gray(first + k), k < out.len(), of dimension `dim`:
    /// consecutive Gray codes differ in the bit at the trailing zeros of the next position,
    /// so each point is the previous one XOR one column. Equal to `point(gray_code(first + k),
    /// dim)` (tested).
    pub fn fill_points_gray(&self, dim: usize, first: u64, out: &mut [u64]) {
        let cols = &self.columns[dim];
        let mut x = self.point(first ^ (first >> 1), dim);
        let len = out.len();
        for (k, slot) in out.iter_mut().enumerate() {
            *slot = x;
            if k + 1 < len {
                let next = first + k as u64 + 1;
                x ^= cols[(next.trailing_zeros() & 63) as usize];
            }
        }
    }

    /// Like [`Self::point`], but errors when `index` is past the last point.
    pub fn try_point(&self, index: u64, dim: usize) -> Result<u64, SeqError> {
        if self.index_bits < 64 && index >> self.index_bits != 0 {
            return Err(SeqError::IndexOutOfRange {
                index,
                index_bits: self.index_bits,
            });
        }
        Ok(self.point(index, dim))
    }

    /// 32-bit-index form of [`Self::point`].
    #[inline]
    pub fn point_u32(&self, index: u32, dim: usize) -> u64 {
        self.point(index as u64, dim)
    }

    /// Checks that points `start..start+count` exist; returns the end index.
    pub fn check_range(&self, start: u64, count: u64) -> Result<u64, SeqError> {
        let end = start.checked_add(count).ok_or(SeqError::IndexOutOfRange {
            index: u64::MAX,
            index_bits: self.index_bits,
        })?;
        if count > 0 && self.index_bits < 64 && (end - 1) >> self.index_bits != 0 {
            return Err(SeqError::IndexOutOfRange {
                index: end - 1,
                index_bits: self.index_bits,
            });
        }
        Ok(end)
    }

    /// Gray-code iteration over positions `start..end` (see [`GrayCodeIter`]).
    pub fn gray_iter(&self, start: u64, end: u64) -> Result<GrayCodeIter<'_>, SeqError> {
        self.check_range(start, end.saturating_sub(start))?;
        Ok(GrayCodeIter::new(self, start, end))
    }

    /// Byte lookup tables for fast random access on 32-bit indices.
    pub fn lookup_tables(&self) -> LookupTables {
        LookupTables::new(self)
    }

    /// The same sequence restricted to its first `dims` dimensions.
    pub fn truncated(&self, dims: usize) -> Result<DigitalSequence, SeqError> {
        if dims == 0 {
            return Err(SeqError::NoDimensions);
        }
        if dims > self.dims() {
            return Err(SeqError::TooManyDimensions {
                sequence: self.name.clone(),
                requested: dims,
                max: self.dims(),
            });
        }
        let mut out = self.clone();
        out.columns.truncate(dims);
        Ok(out)
    }
}
