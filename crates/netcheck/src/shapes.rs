//! Shapes: compositions (d_1..d_s) of K = m − t into s non-negative parts, in lexicographic order.

use crate::NetError;

/// Number of compositions of `k` into `s` parts, C(k+s−1, s−1), saturating.
pub fn shape_count(k: u32, s: usize) -> u128 {
    if s == 0 {
        return 0;
    }
    let n = k as u128 + s as u128 - 1;
    let r = (s as u128 - 1).min(k as u128);
    // C(n, i+1) = C(n, i)·(n − i)/(i + 1) is exact at every step (until saturation).
    (0..r).fold(1u128, |c, i| c.saturating_mul(n - i) / (i + 1))
}

/// Most shapes the counting path will enumerate at once.
pub const SHAPE_LIMIT: u128 = 50_000_000;

/// Every composition of `k` into `s` parts, lexicographic ((0,…,0,k) first, (k,0,…,0) last).
pub fn shapes(k: u32, s: usize) -> Result<Vec<Vec<u32>>, NetError> {
    let count = shape_count(k, s);
    if count > SHAPE_LIMIT {
        return Err(NetError::TooManyShapes {
            shapes: count,
            limit: SHAPE_LIMIT,
        });
    }
    let mut out = Vec::with_capacity(count as usize);
    let mut cur = vec![0u32; s];
    fn rec(j: usize, left: u32, cur: &mut Vec<u32>, out: &mut Vec<Vec<u32>>) {
        if j + 1 == cur.len() {
            cur[j] = left;
            out.push(cur.clone());
            return;
        }
        for d in 0..=left {
            cur[j] = d;
            rec(j + 1, left - d, cur, out);
        }
    }
    if s > 0 {
        rec(0, k, &mut cur, &mut out);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_order() {
        let s = shapes(2, 3).unwrap();
        assert_eq!(s.len() as u128, shape_count(2, 3));
        assert_eq!(s.first().unwrap(), &vec![0, 0, 2]);
        assert_eq!(s.last().unwrap(), &vec![2, 0, 0]);
        let mut sorted = s.clone();
        sorted.sort();
        assert_eq!(s, sorted);
        assert_eq!(shape_count(5, 16), 15504);
        assert_eq!(shape_count(0, 7), 1);
    }
}
