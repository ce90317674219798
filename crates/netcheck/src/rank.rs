//! The rank path: t-values of digital nets in base 2^q from generator matrices.
//!
//! A base-2^q box of shape (d_j) is a binary box of shape (q·d_j), so a shape with
//! Σd_j = m − t holds iff the stacked first q·d_j rows of every C_j, restricted to the first
//! q·m columns, are linearly independent over GF(2) (rank q(m − t)). `docs/design.md` §4 says
//! "full rank q·m", which is the t = 0 case; for t > 0 only q(m − t) rows are stacked.
//!
//! Shapes are explored depth-first over dimensions with an incremental XOR basis: the rows of a
//! prefix are reduced once and shared by every completion, and a dependent prefix fails every
//! completion at once. The cost depends on s, m and q, never on N.

use crate::NetError;
use gartowen_seq::DigitalSequence;

/// A GF(2) basis of vectors of ≤ 64 bits, one pivot per leading bit.
#[derive(Clone)]
struct XorBasis {
    pivots: [u64; 64],
}

impl XorBasis {
    fn new() -> Self {
        XorBasis { pivots: [0; 64] }
    }

    /// Adds `v`; false when it is dependent on the basis (reduces to zero).
    #[inline]
    fn insert(&mut self, mut v: u64) -> bool {
        while v != 0 {
            let top = 63 - v.leading_zeros() as usize;
            if self.pivots[top] == 0 {
                self.pivots[top] = v;
                return true;
            }
            v ^= self.pivots[top];
        }
        false
    }
}

/// Rows of selected generator matrices, restricted to the first q·m columns.
pub struct RowMatrices {
    q: u32,
    m: u32,
    /// `rows[j][r]`: row r of the j-th selected matrix as a bit mask over columns (bit c = column c).
    rows: Vec<Vec<u64>>,
}

impl RowMatrices {
    /// Rows of dimensions `dims` of `seq` in base 2^q for nets of b^m points.
    pub fn new(seq: &DigitalSequence, dims: &[usize], q: u32, m: u32) -> Result<Self, NetError> {
        if !(1..=8).contains(&q) {
            return Err(NetError::NotPowerOfTwo(1u64 << q.min(63)));
        }
        let cols = q * m;
        if cols > 64 || cols > seq.index_bits() {
            return Err(NetError::TooManyBits { bits: cols });
        }
        let w = seq.width().bits();
        let mut rows = Vec::with_capacity(dims.len());
        for &j in dims {
            if j >= seq.dims() {
                return Err(NetError::NoSuchDimension {
                    dim: j,
                    dims: seq.dims(),
                });
            }
            // Rows past W are zero: boxes finer than the word cannot separate points.
            let dim_rows = (0..cols)
                .map(|r| {
                    if r >= w {
                        return 0;
                    }
                    (0..cols).fold(0u64, |acc, c| {
                        acc | (((seq.column(j, c as usize) >> (w - 1 - r)) & 1) << c)
                    })
                })
                .collect();
            rows.push(dim_rows);
        }
        Ok(RowMatrices { q, m, rows })
    }

    /// The first shape (lexicographic) with Σd = m − t whose rows are dependent, if any.
    pub fn first_failure(&self, t: u32) -> Result<Option<Vec<u32>>, NetError> {
        if t > self.m {
            return Err(NetError::TooLargeT { t, m: self.m });
        }
        let s = self.rows.len();
        let mut shape = vec![0u32; s];
        let found = self.search(0, self.m - t, &XorBasis::new(), &mut shape);
        Ok(found.then_some(shape))
    }

    /// Depth-first search over d_j; true when a failure was found (written into `shape`).
    fn search(&self, j: usize, left: u32, basis: &XorBasis, shape: &mut [u32]) -> bool {
        let s = self.rows.len();
        let q = self.q as usize;
        let mut b = basis.clone();
        let last = j + 1 == s;
        let first_d = if last { left } else { 0 };
        // For the last dimension only d = left is a shape; add its rows up front.
        for d in 0..=left {
            if d > 0 {
                for r in q * (d as usize - 1)..q * d as usize {
                    if !b.insert(self.rows[j][r]) {
                        // Every shape with this prefix and d_j ≥ d fails; the first in
                        // lexicographic order puts the rest in the last dimension.
                        if last {
                            shape[j] = left;
                        } else {
                            shape[j] = d;
                            for x in shape.iter_mut().skip(j + 1) {
                                *x = 0;
                            }
                            shape[s - 1] = left - d;
                        }
                        return true;
                    }
                }
            }
            if d < first_d {
                continue;
            }
            shape[j] = d;
            if !last && self.search(j + 1, left - d, &b, shape) {
                return true;
            }
        }
        false
    }

    /// The least t such that every shape with Σd = m − t is independent.
    pub fn t_value(&self) -> u32 {
        (0..=self.m)
            .find(|&t| self.first_failure(t).expect("t ≤ m").is_none())
            .expect("t = m has the empty shape only")
    }
}

/// The t-value of the first b^m points of `seq` (dimensions `dims`) in base 2^q.
pub fn t_value(seq: &DigitalSequence, dims: &[usize], q: u32, m: u32) -> Result<u32, NetError> {
    Ok(RowMatrices::new(seq, dims, q, m)?.t_value())
}

/// The least t for which the digital sequence is a (t,s)-sequence for all block sizes b^m,
/// m ≤ max_m: the largest t-value of its leading nets (every block of b^m consecutive points
/// is a digital shift of the first one, which permutes boxes).
pub fn sequence_t_value(
    seq: &DigitalSequence,
    dims: &[usize],
    q: u32,
    max_m: u32,
) -> Result<u32, NetError> {
    let mut t = 0;
    for m in 1..=max_m {
        t = t.max(t_value(seq, dims, q, m)?);
    }
    Ok(t)
}

/// The first (m, shape) at which the sequence is not a (t,s)-sequence, for m ≤ max_m.
pub fn sequence_failure(
    seq: &DigitalSequence,
    dims: &[usize],
    q: u32,
    t: u32,
    max_m: u32,
) -> Result<Option<(u32, Vec<u32>)>, NetError> {
    for m in t..=max_m {
        if let Some(shape) = RowMatrices::new(seq, dims, q, m)?.first_failure(t)? {
            return Ok(Some((m, shape)));
        }
    }
    Ok(None)
}
