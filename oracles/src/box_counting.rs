//! Brute-force elementary-box counting: for every shape and every box, count the points inside
//! by testing interval membership, a·2^W ≤ X·b^d < (a+1)·2^W, in exact integers.
//! Deliberately naive (cost b^(m−t) boxes × N points per shape): for tiny sets only.

/// A box that does not hold b^t points.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BruteFailure {
    /// The shape (d_1..d_s).
    pub shape: Vec<u32>,
    /// The box (a_1..a_s).
    pub box_index: Vec<u64>,
    /// Points inside.
    pub count: u64,
}

/// Whether the W-bit word x lies in [a·b^-d, (a+1)·b^-d).
pub fn in_interval(x: u64, width_bits: u32, b: u64, d: u32, a: u64) -> bool {
    let scaled = x as u128 * (b as u128).pow(d);
    let lo = (a as u128) << width_bits;
    let hi = ((a + 1) as u128) << width_bits;
    lo <= scaled && scaled < hi
}

/// Number of points (rows) inside the box of `shape` with index `box_index`.
pub fn count_in_box(
    rows: &[Vec<u64>],
    width_bits: u32,
    b: u64,
    shape: &[u32],
    box_index: &[u64],
) -> u64 {
    rows.iter()
        .filter(|p| {
            (0..shape.len()).all(|j| in_interval(p[j], width_bits, b, shape[j], box_index[j]))
        })
        .count() as u64
}

/// Compositions of k into s parts, lexicographic, built by recursion on the first part.
pub fn compositions(k: u32, s: usize) -> Vec<Vec<u32>> {
    if s == 1 {
        return vec![vec![k]];
    }
    let mut out = Vec::new();
    for first in 0..=k {
        for mut rest in compositions(k - first, s - 1) {
            rest.insert(0, first);
            out.push(rest);
        }
    }
    out
}

/// Every box index of a shape, lexicographic.
fn boxes(b: u64, shape: &[u32]) -> Vec<Vec<u64>> {
    let mut out = vec![vec![]];
    for &d in shape {
        let side = b.pow(d);
        out = out
            .into_iter()
            .flat_map(|prefix| {
                (0..side).map(move |a| {
                    let mut p = prefix.clone();
                    p.push(a);
                    p
                })
            })
            .collect();
    }
    out
}

/// The first shape (lexicographic) with a box holding other than b^t points, with its first
/// such box (lexicographic); `None` when the rows form a (t,m,s)-net.
pub fn first_failure(
    rows: &[Vec<u64>],
    width_bits: u32,
    b: u64,
    m: u32,
    t: u32,
) -> Option<BruteFailure> {
    let s = rows[0].len();
    let expected = b.pow(t);
    for shape in compositions(m - t, s) {
        for box_index in boxes(b, &shape) {
            let count = count_in_box(rows, width_bits, b, &shape, &box_index);
            if count != expected {
                return Some(BruteFailure {
                    shape,
                    box_index,
                    count,
                });
            }
        }
    }
    None
}

/// The least t for which the b^m rows form a (t,m,s)-net.
pub fn t_value(rows: &[Vec<u64>], width_bits: u32, b: u64, m: u32) -> u32 {
    (0..=m)
        .find(|&t| first_failure(rows, width_bits, b, m, t).is_none())
        .expect("t = m always holds")
}
