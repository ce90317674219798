//! Gray-code iteration: consecutive Gray codes differ in one bit, so each step XORs one column.

use crate::DigitalSequence;

/// The binary reflected Gray code of n, n ⊕ (n ≫ 1).
///
/// ```
/// assert_eq!(gartowen_seq::gray_code(3), 2);
/// ```
#[inline(always)]
pub const fn gray_code(n: u64) -> u64 {
    n ^ (n >> 1)
}

/// Walks positions n = start, start+1, …, end−1 and yields the point with index
/// `gray_code(n)`: the order scipy.stats.qmc.Sobol uses. Each step costs one XOR per dimension.
pub struct GrayCodeIter<'a> {
    seq: &'a DigitalSequence,
    /// Position of the point held in `current`.
    position: u64,
    end: u64,
    current: Vec<u64>,
    /// Whether `current` was handed out and must advance before the next call.
    emitted: bool,
}

impl<'a> GrayCodeIter<'a> {
    /// Positions `start..end`; `end` must not exceed 2^index_bits (checked by the caller).
    pub fn new(seq: &'a DigitalSequence, start: u64, end: u64) -> Self {
        let g = gray_code(start);
        let current = (0..seq.dims()).map(|j| seq.point(g, j)).collect();
        GrayCodeIter {
            seq,
            position: start,
            end,
            current,
            emitted: false,
        }
    }

    /// The next point as a borrowed slice (one word per dimension), with its index.
    #[inline]
    pub fn next_point(&mut self) -> Option<(u64, &[u64])> {
        if self.emitted {
            self.position += 1;
            self.emitted = false;
            if self.position < self.end {
                let c = self.position.trailing_zeros() as usize;
                for (j, x) in self.current.iter_mut().enumerate() {
                    *x ^= self.seq.column(j, c);
                }
            }
        }
        if self.position >= self.end {
            return None;
        }
        self.emitted = true;
        Some((gray_code(self.position), &self.current))
    }
}
