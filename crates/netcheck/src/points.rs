//! Point sets as W-bit words, stored per dimension (column-major) so a shape streams only the
//! dimensions it refines.

use crate::NetError;
use gartowen_core::{word_from_f64, CoreError, Width};

/// N points in s dimensions, W-bit words. Coordinate j of point i is `coords[j][i]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PointSet {
    width: Width,
    coords: Vec<Vec<u64>>,
}

impl PointSet {
    /// From row-major words (`rows[i][j]` = point i, dimension j). Errors on an empty or
    /// ragged set, zero dimensions, or a word wider than `width`.
    pub fn from_rows(width: Width, rows: &[Vec<u64>]) -> Result<Self, NetError> {
        let first = rows.first().ok_or(NetError::Empty)?;
        let dims = first.len();
        if dims == 0 {
            return Err(NetError::BadShape("points have zero dimensions".into()));
        }
        let mut coords = vec![Vec::with_capacity(rows.len()); dims];
        for (i, row) in rows.iter().enumerate() {
            if row.len() != dims {
                return Err(NetError::BadShape(format!(
                    "point {i} has {} coordinates, point 0 has {dims}",
                    row.len()
                )));
            }
            for (j, &x) in row.iter().enumerate() {
                width.check(x).map_err(|e| NetError::BadValue {
                    point: i,
                    dim: j,
                    reason: e.to_string(),
                })?;
                coords[j].push(x);
            }
        }
        Ok(PointSet { width, coords })
    }

    /// From flat row-major words with `dims` per point.
    pub fn from_flat(width: Width, dims: usize, flat: &[u64]) -> Result<Self, NetError> {
        if dims == 0 {
            return Err(NetError::BadShape("points have zero dimensions".into()));
        }
        if flat.is_empty() {
            return Err(NetError::Empty);
        }
        if !flat.len().is_multiple_of(dims) {
            return Err(NetError::BadShape(format!(
                "{} values do not split into points of {dims} coordinates",
                flat.len()
            )));
        }
        let n = flat.len() / dims;
        let mut coords = vec![Vec::with_capacity(n); dims];
        for (k, &x) in flat.iter().enumerate() {
            width.check(x).map_err(|e| NetError::BadValue {
                point: k / dims,
                dim: k % dims,
                reason: e.to_string(),
            })?;
            coords[k % dims].push(x);
        }
        Ok(PointSet { width, coords })
    }

    /// From flat row-major f64 values, converted exactly to 64-bit words. Errors name the first
    /// NaN, value outside [0,1), or value that is not a multiple of 2^-64.
    pub fn from_f64(dims: usize, values: &[f64]) -> Result<Self, NetError> {
        Self::from_f64_by(dims, values, |v| word_from_f64(v, Width::W64))
    }

    /// From flat row-major f64 values, each read as the 64-bit word at or below it
    /// ([`gartowen_core::word_from_f64_floor`]: values below 2^-11 lose bits below 2^-64, which
    /// no box of depth ≤ 64 bits tells apart). Errors name the first NaN or value outside [0,1).
    pub fn from_f64_floor(dims: usize, values: &[f64]) -> Result<Self, NetError> {
        Self::from_f64_by(dims, values, gartowen_core::word_from_f64_floor)
    }

    /// From flat row-major f64 values, each made a 64-bit word by `word`.
    fn from_f64_by(
        dims: usize,
        values: &[f64],
        word: impl Fn(f64) -> Result<u64, CoreError>,
    ) -> Result<Self, NetError> {
        if dims == 0 {
            return Err(NetError::BadShape("points have zero dimensions".into()));
        }
        let mut words = Vec::with_capacity(values.len());
        for (k, &v) in values.iter().enumerate() {
            words.push(word(v).map_err(|e| NetError::BadValue {
                point: k / dims,
                dim: k % dims,
                reason: e.to_string(),
            })?);
        }
        PointSet::from_flat(Width::W64, dims, &words)
    }

    /// The word width and the per-dimension columns, giving up the set (so a caller can free
    /// each column as soon as it has read it).
    pub fn into_columns(self) -> (Width, Vec<Vec<u64>>) {
        (self.width, self.coords)
    }

    /// From per-dimension columns (all of equal length).
    pub fn from_columns(width: Width, coords: Vec<Vec<u64>>) -> Result<Self, NetError> {
        let n = coords
            .first()
            .ok_or(NetError::BadShape("zero dimensions".into()))?
            .len();
        if n == 0 {
            return Err(NetError::Empty);
        }
        if coords.iter().any(|c| c.len() != n) {
            return Err(NetError::BadShape("dimensions of differing lengths".into()));
        }
        Ok(PointSet { width, coords })
    }

    /// Points 0..n of the listed dimensions of a digital sequence, each word passed through
    /// `map(word, dim)` (e.g. a scrambler; use `|x, _| x` for the plain sequence).
    pub fn from_sequence(
        seq: &gartowen_seq::DigitalSequence,
        dims: &[usize],
        n: u64,
        map: impl Fn(u64, usize) -> u64,
    ) -> Result<Self, NetError> {
        let coords = dims
            .iter()
            .map(|&j| (0..n).map(|i| map(seq.point(i, j), j)).collect())
            .collect();
        PointSet::from_columns(seq.width(), coords)
    }

    /// The word width W.
    pub fn width(&self) -> Width {
        self.width
    }

    /// Number of points N.
    pub fn len(&self) -> usize {
        self.coords[0].len()
    }

    /// Whether there are no points (never true for a constructed set).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Number of dimensions s.
    pub fn dims(&self) -> usize {
        self.coords.len()
    }

    /// All coordinates of dimension j.
    pub fn column(&self, j: usize) -> &[u64] {
        &self.coords[j]
    }

    /// Point i as a vector.
    pub fn point(&self, i: usize) -> Vec<u64> {
        self.coords.iter().map(|c| c[i]).collect()
    }

    /// Replaces coordinate j of point i (used to build deliberately broken sets in tests).
    pub fn set(&mut self, i: usize, j: usize, x: u64) {
        self.coords[j][i] = x;
    }

    /// The projection onto the listed dimensions, in that order.
    pub fn project(&self, dims: &[usize]) -> Result<PointSet, NetError> {
        let mut coords = Vec::with_capacity(dims.len());
        for &d in dims {
            coords.push(
                self.coords
                    .get(d)
                    .ok_or(NetError::NoSuchDimension {
                        dim: d,
                        dims: self.dims(),
                    })?
                    .clone(),
            );
        }
        PointSet::from_columns(self.width, coords)
    }

    /// The first `n` points as a new set (n ≥ 1).
    pub fn prefix(&self, n: usize) -> PointSet {
        PointSet {
            width: self.width,
            coords: self.coords.iter().map(|c| c[..n].to_vec()).collect(),
        }
    }

    /// 64-bit FNV-1a over the little-endian words, row-major: a checksum of the input for reports.
    pub fn checksum(&self) -> u64 {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for i in 0..self.len() {
            for c in &self.coords {
                for byte in c[i].to_le_bytes() {
                    h ^= byte as u64;
                    h = h.wrapping_mul(0x0000_0100_0000_01b3);
                }
            }
        }
        h
    }
}
