//! Bases for elementary intervals: any integer b ≥ 2, with exact integer digits.

use crate::NetError;
use serde::Serialize;

/// An integer base b ≥ 2 for elementary boxes. For b = 2^q digits come from shifts; otherwise
/// floor(x·b^k) is computed exactly in 128-bit integers from the W-bit word.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct CheckBase {
    b: u64,
    /// q when b = 2^q.
    log2: Option<u32>,
}

impl CheckBase {
    /// Base b; errors if b < 2.
    pub fn new(b: u64) -> Result<Self, NetError> {
        if b < 2 {
            return Err(NetError::BaseTooSmall(b));
        }
        Ok(CheckBase {
            b,
            log2: b.is_power_of_two().then(|| b.trailing_zeros()),
        })
    }

    /// The base b.
    pub fn get(self) -> u64 {
        self.b
    }

    /// q when b = 2^q.
    pub fn log2(self) -> Option<u32> {
        self.log2
    }

    /// b^k, or `None` on u64 overflow.
    pub fn pow(self, k: u32) -> Option<u64> {
        self.b.checked_pow(k)
    }

    /// The m with b^m = n, if any.
    pub fn exact_log(self, n: usize) -> Option<u32> {
        let mut p = 1u64;
        let mut m = 0;
        while p < n as u64 {
            p = p.checked_mul(self.b)?;
            m += 1;
        }
        (p == n as u64).then_some(m)
    }

    /// floor(x · b^k) for the W-bit word x (value x·2^-W), exactly. Requires b^k < 2^64.
    #[inline(always)]
    pub fn top_digits(self, x: u64, width_bits: u32, k: u32) -> u64 {
        match self.log2 {
            Some(q) => {
                let bits = q * k;
                if bits == 0 {
                    0
                } else if bits <= width_bits {
                    x >> (width_bits - bits)
                } else {
                    // Callers keep b^k ≤ 2^32, so this shift is below 64.
                    x << (bits - width_bits)
                }
            }
            None => {
                let p = self.b.pow(k) as u128;
                ((x as u128 * p) >> width_bits) as u64
            }
        }
    }
}
