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

/// Most bytes the enumerated shapes may take (a shape holds one u32 per dimension, so wide
/// sets blow up long before [`SHAPE_LIMIT`]: 2 million shapes of 2000 dimensions took 5.7 GB).
pub const SHAPE_BYTES_LIMIT: u128 = 1 << 30;

/// Every composition of `k` into `s` parts, lexicographic ((0,…,0,k) first, (k,0,…,0) last).
/// Refused, before anything is allocated, past [`SHAPE_LIMIT`] shapes or
/// [`SHAPE_BYTES_LIMIT`] bytes.
pub fn shapes(k: u32, s: usize) -> Result<Vec<Vec<u32>>, NetError> {
    let count = shape_count(k, s);
    if count > SHAPE_LIMIT {
        return Err(NetError::TooManyShapes {
            shapes: count,
            limit: SHAPE_LIMIT,
        });
    }
    let bytes = count.saturating_mul(4 * s as u128 + std::mem::size_of::<Vec<u32>>() as u128);
    if bytes > SHAPE_BYTES_LIMIT {
        return Err(NetError::ShapesTooLarge {
            shapes: count,
            dims: s,
            bytes,
            limit: SHAPE_BYTES_LIMIT,
        });
    }
    let mut out = Vec::with_capacity(count as usize);
    if s == 0 {
        return Ok(out);
    }
    // Iterative, not recursive: the depth would be s (one point in 200,000 dimensions
    // overflowed the stack). The successor of a composition in lexicographic order moves one
    // unit from its last nonzero part p into part p − 1 and the rest of part p to the end.
    let mut cur = vec![0u32; s];
    cur[s - 1] = k;
    loop {
        out.push(cur.clone());
        let Some(p) = cur.iter().rposition(|&d| d > 0).filter(|&p| p > 0) else {
            break;
        };
        let rest = cur[p];
        cur[p] = 0;
        cur[p - 1] += 1;
        cur[s - 1] = rest - 1;
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

    /// Every vector of [0, k]^s with sum k, in lexicographic order: the definition.
    fn brute_force(k: u32, s: usize) -> Vec<Vec<u32>> {
        let mut all = Vec::new();
        let total = (k as usize + 1).pow(s as u32);
        for mut code in 0..total {
            let mut v = vec![0u32; s];
            for d in v.iter_mut().rev() {
                *d = (code % (k as usize + 1)) as u32;
                code /= k as usize + 1;
            }
            if v.iter().sum::<u32>() == k {
                all.push(v);
            }
        }
        all
    }

    #[test]
    fn enumeration_equals_the_definition() {
        for s in 1..=5 {
            for k in 0..=5 {
                assert_eq!(shapes(k, s).unwrap(), brute_force(k, s), "k = {k}, s = {s}");
            }
        }
        assert!(shapes(3, 0).unwrap().is_empty());
    }

    #[test]
    fn wide_sets_are_refused_by_memory_and_deep_ones_do_not_recurse() {
        // 2,001,000 shapes of 2000 dimensions: 16 GB, refused before allocating.
        match shapes(2, 2000) {
            Err(NetError::ShapesTooLarge { shapes, dims, .. }) => {
                assert_eq!((shapes, dims), (2_001_000, 2000));
            }
            other => panic!("{other:?}"),
        }
        // One shape of 200,000 dimensions: no recursion, no stack overflow.
        let one = shapes(0, 200_000).unwrap();
        assert_eq!(one.len(), 1);
        let two = shapes(1, 3000).unwrap();
        assert_eq!(two.len(), 3000);
        assert_eq!(two[0][2999], 1);
        assert_eq!(two[2999][0], 1);
        assert!(matches!(
            shapes(1, 100_000),
            Err(NetError::ShapesTooLarge { .. })
        ));
    }
}
