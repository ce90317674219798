//! q×q matrices over GF(2), q ≤ 8, packed in one u64.
//!
//! Row i occupies bits `[8i, 8i+8)`; bit j of a row is the entry in column j. A vector of q
//! bits is an integer whose bit j is component j, and `apply` computes y = A·x.

use crate::{CoreError, SplitMix64};

/// A q×q matrix over GF(2), q in 1..=8.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Gf2Matrix {
    q: u8,
    rows: u64,
}

impl Gf2Matrix {
    /// The q×q identity.
    pub fn identity(q: u32) -> Result<Self, CoreError> {
        let mut rows = [0u8; 8];
        for (i, r) in rows.iter_mut().enumerate().take(q as usize) {
            *r = 1 << i;
        }
        Gf2Matrix::from_rows(q, &rows[..q.min(8) as usize])
    }

    /// A matrix from its rows (bit j of `rows[i]` is entry (i, j)). Errors if q is not in
    /// 1..=8, the row count differs from q, or a row has bits at or above column q.
    pub fn from_rows(q: u32, rows: &[u8]) -> Result<Self, CoreError> {
        if !(1..=8).contains(&q) || rows.len() != q as usize {
            return Err(CoreError::InvalidMatrix {
                reason: format!("{} rows for a {q}×{q} matrix (q must be 1..=8)", rows.len()),
            });
        }
        let mut packed = 0u64;
        for (i, &r) in rows.iter().enumerate() {
            if q < 8 && r >> q != 0 {
                return Err(CoreError::InvalidMatrix {
                    reason: format!("row {i} = {r:#b} has entries beyond column {}", q - 1),
                });
            }
            packed |= (r as u64) << (8 * i);
        }
        Ok(Gf2Matrix {
            q: q as u8,
            rows: packed,
        })
    }

    /// A matrix from its packed form (as returned by [`Gf2Matrix::packed`]).
    pub fn from_packed(q: u32, packed: u64) -> Result<Self, CoreError> {
        if !(1..=8).contains(&q) || (q < 8 && packed >> (8 * q) != 0) {
            return Err(CoreError::InvalidMatrix {
                reason: format!("packed word {packed:#x} is not a {q}×{q} matrix"),
            });
        }
        let rows: Vec<u8> = (0..q).map(|i| (packed >> (8 * i)) as u8).collect();
        Gf2Matrix::from_rows(q, &rows)
    }

    /// The size q.
    #[inline(always)]
    pub fn size(&self) -> u32 {
        self.q as u32
    }

    /// The packed form: row i in bits [8i, 8i+8).
    #[inline(always)]
    pub fn packed(&self) -> u64 {
        self.rows
    }

    /// Row i as a bit vector.
    #[inline(always)]
    pub fn row(&self, i: u32) -> u8 {
        (self.rows >> (8 * i)) as u8
    }

    /// Entry (i, j).
    #[inline(always)]
    pub fn get(&self, i: u32, j: u32) -> bool {
        (self.row(i) >> j) & 1 == 1
    }

    /// y = A·x over GF(2), for a q-bit vector x.
    #[inline(always)]
    pub fn apply(&self, x: u32) -> u32 {
        let mut y = 0u32;
        for i in 0..self.q as u32 {
            y |= ((self.row(i) as u32 & x).count_ones() & 1) << i;
        }
        y
    }

    /// A·x for every q-bit x, indexed by x: built by linearity (A·x = A·(x without its highest
    /// set bit) ⊕ column of that bit), one XOR per entry instead of q parities.
    pub fn images(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(1 << self.q);
        self.images_into(&mut out);
        out
    }

    /// [`Gf2Matrix::images`] appended to `out` (no allocation when `out` has room: a table of
    /// many matrices is filled in place).
    pub fn images_into(&self, out: &mut Vec<u8>) {
        let start = out.len();
        out.resize(start + (1 << self.q), 0);
        let images = &mut out[start..];
        // Doubling: the images of the x with top set bit j are those below 2^j XOR column j, a
        // block XOR the compiler vectorizes.
        for j in 0..self.q as usize {
            let column = self.apply(1 << j) as u8;
            let (below, above) = images.split_at_mut(1 << j);
            for (a, b) in above[..1 << j].iter_mut().zip(below.iter()) {
                *a = b ^ column;
            }
        }
    }

    /// The product A·B (apply B first). Panics on different sizes.
    pub fn mul(&self, other: &Gf2Matrix) -> Gf2Matrix {
        assert_eq!(self.q, other.q, "multiplying matrices of different sizes");
        let q = self.q as u32;
        // Column j of A·B is A·(column j of B).
        let mut rows = [0u8; 8];
        for j in 0..q {
            let col_b: u32 = (0..q).map(|i| (other.get(i, j) as u32) << i).sum();
            let col = self.apply(col_b);
            for (i, r) in rows.iter_mut().enumerate().take(q as usize) {
                *r |= (((col >> i) & 1) as u8) << j;
            }
        }
        Gf2Matrix::from_rows(q, &rows[..q as usize]).expect("product stays q×q")
    }

    /// The rank over GF(2), by elimination on the rows (no allocation): each row is reduced by
    /// the basis rows kept so far, indexed by their leading bit, and joins the basis when
    /// something is left.
    pub fn rank(&self) -> u32 {
        let mut basis = [0u8; 8];
        let mut rank = 0;
        for i in 0..self.q as u32 {
            let mut row = self.row(i);
            while row != 0 {
                let lead = 7 - row.leading_zeros() as usize;
                if basis[lead] == 0 {
                    basis[lead] = row;
                    rank += 1;
                    break;
                }
                row ^= basis[lead];
            }
        }
        rank
    }

    /// Whether the matrix is invertible (rank q).
    pub fn is_invertible(&self) -> bool {
        self.rank() == self.q as u32
    }

    /// The inverse, or `None` when singular (Gauss–Jordan on [A | I]).
    pub fn inverse(&self) -> Option<Gf2Matrix> {
        let q = self.q as usize;
        let mut a: Vec<u16> = (0..q)
            .map(|i| self.row(i as u32) as u16 | (1u16 << (8 + i)))
            .collect();
        for col in 0..q {
            let p = (col..q).find(|&r| (a[r] >> col) & 1 == 1)?;
            a.swap(col, p);
            let pivot = a[col];
            for (r, row) in a.iter_mut().enumerate() {
                if r != col && (*row >> col) & 1 == 1 {
                    *row ^= pivot;
                }
            }
        }
        let rows: Vec<u8> = a.iter().map(|&r| (r >> 8) as u8).collect();
        Some(Gf2Matrix::from_rows(q as u32, &rows).expect("inverse stays q×q"))
    }

    /// A uniformly random invertible q×q matrix: uniform random bits (one 64-bit draw per
    /// try, row i from byte i), rejected until invertible. No allocation.
    pub fn random_invertible(q: u32, rng: &mut SplitMix64) -> Result<Gf2Matrix, CoreError> {
        if !(1..=8).contains(&q) {
            return Err(CoreError::InvalidMatrix {
                reason: format!("size {q} is not in 1..=8"),
            });
        }
        let col_mask = (((1u32 << q) - 1) as u8) as u64 * 0x0101_0101_0101_0101;
        let used = if q == 8 {
            u64::MAX
        } else {
            (1u64 << (8 * q)) - 1
        };
        loop {
            let m = Gf2Matrix {
                q: q as u8,
                rows: rng.next_u64() & col_mask & used,
            };
            if m.is_invertible() {
                return Ok(m);
            }
        }
    }

    /// Every invertible q×q matrix, in increasing packed order (|GL(q,2)| of them); q ≤ 3.
    pub fn all_invertible(q: u32) -> Vec<Gf2Matrix> {
        assert!((1..=3).contains(&q), "enumeration is meant for q ≤ 3");
        let mut out = Vec::new();
        for bits in 0u32..(1 << (q * q)) {
            let rows: Vec<u8> = (0..q)
                .map(|i| ((bits >> (q * i)) & ((1 << q) - 1)) as u8)
                .collect();
            let m = Gf2Matrix::from_rows(q, &rows).expect("valid rows");
            if m.is_invertible() {
                out.push(m);
            }
        }
        out.sort_by_key(|m| m.packed());
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gl_sizes() {
        // |GL(q,2)| = Π_{i<q} (2^q − 2^i): 1, 6, 168.
        assert_eq!(Gf2Matrix::all_invertible(1).len(), 1);
        assert_eq!(Gf2Matrix::all_invertible(2).len(), 6);
        assert_eq!(Gf2Matrix::all_invertible(3).len(), 168);
    }

    #[test]
    fn apply_matches_entries() {
        let m = Gf2Matrix::from_rows(2, &[0b11, 0b10]).unwrap();
        // y0 = x0 + x1, y1 = x1.
        assert_eq!(m.apply(0b01), 0b01);
        assert_eq!(m.apply(0b10), 0b11);
        assert!(Gf2Matrix::from_rows(2, &[0b100, 0]).is_err());
    }

    #[test]
    fn the_rank_is_the_log_of_the_image_size() {
        // Two paths: elimination against 2^rank distinct images A·x.
        let mut rng = SplitMix64::new(9);
        for q in 1..=8u32 {
            for k in 0..200 {
                let rows: Vec<u8> = (0..q)
                    .map(|_| {
                        let r = (rng.next_u64() as u8) & ((1u16 << q) - 1) as u8;
                        // Sparse rows too, so that low ranks occur.
                        if k % 2 == 0 {
                            r & (rng.next_u64() as u8)
                        } else {
                            r
                        }
                    })
                    .collect();
                let m = Gf2Matrix::from_rows(q, &rows).unwrap();
                let mut images: Vec<u32> = (0..1u32 << q).map(|x| m.apply(x)).collect();
                images.sort_unstable();
                images.dedup();
                assert_eq!(1usize << m.rank(), images.len(), "{m:?}");
            }
        }
    }

    #[test]
    fn images_by_linearity_equal_the_row_parities() {
        let mut rng = SplitMix64::new(3);
        for q in 1..=8 {
            for _ in 0..20 {
                let m = Gf2Matrix::random_invertible(q, &mut rng).unwrap();
                let images = m.images();
                assert_eq!(images.len(), 1 << q);
                for (x, &y) in images.iter().enumerate() {
                    assert_eq!(y as u32, m.apply(x as u32), "q {q} x {x} of {m:?}");
                }
                // Appended after what the buffer holds, which stays.
                let mut table = vec![0xA5, 0x5A];
                m.images_into(&mut table);
                assert_eq!(table[..2], [0xA5, 0x5A]);
                assert_eq!(table[2..], images[..]);
            }
        }
    }
}
