//! Float coordinates in a base that is not a power of two: snapping to the base's grid.
//!
//! A binary64 value cannot hold 1/3, so a point of a base-3 net at 1/3 is stored just below it
//! and a floor reads it in the wrong box (SciPy's Halton points in base 3, a perfect
//! (0,8,1)-net, once read as t = 8). A check at depth m (its deepest box digit) only asks in
//! which interval [j/b^m, (j+1)/b^m) each coordinate lies, so only the grid of depth m
//! matters. The rule, for base b, depth m and values carrying `radius` r of absolute error
//! (`gartowen check` uses r = 2^-46 for binary64 values in [0, 1): 64 units in the last place
//! at [1/2, 1), room for tools that sum digit terms in floats):
//!
//! 1. The depth must be one **the precision allows**: b^m < 2^-3 / r, so grid points j / b^m
//!    lie more than 8 radii apart (at r = 2^-46: base 3 m ≤ 27, base 10 m ≤ 12).
//! 2. A coordinate within r of a grid point j / b^m is **snapped** to it: it lies in
//!    [j/b^m, (j+1)/b^m), as the exact value it stands for does.
//! 3. A coordinate more than 4r from every grid point is read as it is: no boundary of depth
//!    ≤ m lies within 4r of it, so its intervals do not depend on the error.
//! 4. A coordinate between r and 4r from a grid point is **ambiguous**: too far to be that
//!    grid point up to the float's error, too near to be read safely (input quantized more
//!    coarsely than the float, e.g. truncated to 50 bits). It is refused, naming the point.
//!    So is a coordinate that snaps to 1. For values that do not come from the grid (random
//!    points) the ambiguous band is a fraction 6·r·b^m of [0, 1) (4.5·10^-8 at 3^12, r = 2^-46).
//!
//! A snapped value becomes the 64-bit word ⌈j · 2^64 / b^m⌉: at most one step above j / b^m
//! and below the next grid point, so its interval at every depth ≤ m is the grid point's. The
//! computation is exact (integers below 2^113).

use crate::{NetError, PointSet};
use gartowen_core::Width;

/// What snapping did (serialized as the certificate's `parameters.snap`).
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct SnapSummary {
    /// The base.
    pub base: u64,
    /// The depth m of the grid: intervals of depth ≤ m are read exactly.
    #[serde(rename = "depth")]
    pub digits: u32,
    /// Coordinates moved onto a grid point (those already exactly on one are not counted).
    pub snapped: usize,
    /// log2 of the error radius, negated (52 for binary64 values).
    pub radius_log2: u32,
}

/// A coordinate snapping refuses.
#[derive(Debug, Clone, PartialEq)]
pub struct AmbiguousPoint {
    /// Point index.
    pub point: usize,
    /// Dimension.
    pub dim: usize,
    /// The value as a float.
    pub value: f64,
    /// The nearest grid point as j / b^m.
    pub grid: (u128, u128),
    /// Why: ambiguous distance, or snapping to 1.
    pub reason: String,
}

impl std::fmt::Display for AmbiguousPoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "point {} coordinate {} = {:e}: {} (nearest grid point {}/{})",
            self.point, self.dim, self.value, self.reason, self.grid.0, self.grid.1
        )
    }
}

impl std::error::Error for AmbiguousPoint {}

/// b^m for the grid of depth `depth`, if the radius 2^-`radius_log2` allows it
/// (b^m < 2^(radius_log2 − 3)); the error names the deepest depth that would be allowed.
pub fn grid(b: u64, depth: u32, radius_log2: u32) -> Result<u128, NetError> {
    if b < 2 {
        return Err(NetError::BaseTooSmall(b));
    }
    let limit = 1u128 << radius_log2.saturating_sub(3).min(120);
    let (mut deepest, mut bm) = (0u32, 1u128);
    while bm * (b as u128) < limit {
        bm *= b as u128;
        deepest += 1;
    }
    if depth > deepest {
        return Err(NetError::BadValue {
            point: 0,
            dim: 0,
            reason: format!(
                "floats with an error of 2^-{radius_log2} resolve at most {deepest} base-{b} \
                 digits; this check needs {depth}"
            ),
        });
    }
    Ok((b as u128).pow(depth))
}

/// Snaps every coordinate of `points` (64-bit words holding values in [0, 1) exactly) to the
/// base-`b` grid of depth `depth` by the rule in the module doc. Returns the snapped set and
/// a summary, or the first ambiguous coordinate (in dimension order, then point order).
pub fn snap_to_grid(
    points: &PointSet,
    b: u64,
    depth: u32,
    radius_log2: u32,
) -> Result<Result<(PointSet, SnapSummary), AmbiguousPoint>, NetError> {
    if points.width() != Width::W64 {
        return Err(NetError::BadValue {
            point: 0,
            dim: 0,
            reason: "snapping reads 64-bit words of float values".into(),
        });
    }
    let bm = grid(b, depth, radius_log2)?;
    let digits = depth;
    // |x − k/b^m| ≤ r  ⇔  |word·b^m − k·2^64| ≤ b^m · 2^(64 − radius_log2).
    let unit = bm << (64 - radius_log2.min(64));
    let two64 = 1u128 << 64;
    let mut snapped = 0usize;
    let mut columns = Vec::with_capacity(points.dims());
    for dim in 0..points.dims() {
        let mut out = Vec::with_capacity(points.len());
        for (point, &word) in points.column(dim).iter().enumerate() {
            let scaled = word as u128 * bm; // x · b^M · 2^64
            let k = (scaled + (two64 >> 1)) >> 64; // nearest grid index
            let at = k << 64;
            let distance = scaled.abs_diff(at);
            let refuse = |reason: String| AmbiguousPoint {
                point,
                dim,
                value: word as f64 / two64 as f64,
                grid: (k, bm),
                reason,
            };
            if distance <= unit {
                if k == bm {
                    return Ok(Err(refuse("within the float's error of 1".into())));
                }
                // ⌈k · 2^64 / b^M⌉
                let w = (k << 64).div_ceil(bm);
                snapped += usize::from(distance != 0);
                out.push(w as u64);
            } else if distance <= 4 * unit {
                return Ok(Err(refuse(format!(
                    "{:.2} radii of 2^-{radius_log2} from a base-{b} grid point at depth {digits}: \
                     neither on it within the float's error nor clear of it (input rounded \
                     more coarsely than a float?)",
                    distance as f64 / unit as f64
                ))));
            } else {
                out.push(word);
            }
        }
        columns.push(out);
    }
    let set = PointSet::from_columns(Width::W64, columns)?;
    Ok(Ok((
        set,
        SnapSummary {
            base: b,
            digits,
            snapped,
            radius_log2,
        },
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::word_from_f64;

    fn set(values: &[f64]) -> PointSet {
        PointSet::from_f64(1, values).unwrap()
    }

    #[test]
    fn the_precision_bounds_the_depth() {
        assert!(grid(3, 30, 52).is_ok()); // 3^30 < 2^49 < 3^31
        let e = grid(3, 31, 52).unwrap_err().to_string();
        assert!(
            e.contains("at most 30 base-3 digits; this check needs 31"),
            "{e}"
        );
        assert!(grid(10, 14, 52).is_ok() && grid(10, 15, 52).is_err());
        assert!(grid(5, 21, 52).is_ok() && grid(5, 22, 52).is_err());
        for b in 2..40u64 {
            let deepest = (0..)
                .take_while(|&m| grid(b, m, 52).is_ok())
                .last()
                .unwrap();
            let bm = (b as u128).pow(deepest);
            assert!(bm < 1 << 49 && bm * b as u128 >= 1 << 49, "b {b}");
            assert_eq!(grid(b, deepest, 52).unwrap(), bm);
        }
        assert!(grid(1, 1, 52).is_err());
    }

    #[test]
    fn thirds_snap_into_their_boxes_and_clear_values_stay() {
        let third = 1.0 / 3.0; // stored below 1/3
        let p = set(&[0.0, third, 2.0 / 3.0, 0.5, 0.1]);
        let p30 = set(&[0.0, third, 2.0 / 3.0, 0.5]);
        let (s, summary) = snap_to_grid(&p30, 3, 30, 52).unwrap().unwrap();
        assert_eq!(summary.digits, 30);
        assert_eq!(summary.snapped, 2); // 1/3 and 2/3; 0 is exact, 0.5 is clear
        let three = 3u128;
        let in_box = |w: u64, d: u32| (w as u128 * three.pow(d)) >> 64;
        // Before: 1/3 reads as box 0 at depth 1; after, box 1.
        assert_eq!(in_box(p.column(0)[1], 1), 0);
        assert_eq!(in_box(s.column(0)[1], 1), 1);
        assert_eq!(in_box(s.column(0)[2], 1), 2);
        for d in 1..=30 {
            assert_eq!(in_box(s.column(0)[1], d), three.pow(d) / 3, "depth {d}");
        }
        // 0.1 is 2.16 radii from a grid point of depth 30 (ambiguous there), clear at 12.
        assert!(snap_to_grid(&set(&[0.1]), 3, 30, 52).unwrap().is_err());
        let (s, summary) = snap_to_grid(&p, 3, 12, 52).unwrap().unwrap();
        assert_eq!(summary.snapped, 2);
        // Values clear of the grid are unchanged.
        assert_eq!(s.column(0)[3], p.column(0)[3]);
        assert_eq!(s.column(0)[4], p.column(0)[4]);
    }

    #[test]
    fn coarse_rounding_is_ambiguous_and_a_snap_to_one_is_refused() {
        // 1/3 truncated to 50 bits: 2^-50·(fraction) below 1/3, about 1–4 radii of 2^-52.
        let truncated = (((1u128 << 64) / 3) >> 14 << 14) as u64;
        let x = truncated as f64 / 2f64.powi(64);
        let w = word_from_f64(x, Width::W64).unwrap();
        let p = PointSet::from_columns(Width::W64, vec![vec![0, w]]).unwrap();
        let e = snap_to_grid(&p, 3, 12, 52).unwrap().unwrap_err();
        assert_eq!((e.point, e.dim), (1, 0));
        assert_eq!(e.value, x);
        assert_eq!(e.grid, (3u128.pow(12) / 3, 3u128.pow(12)));
        assert!(e.to_string().contains("point 1 coordinate 0"), "{e}");
        assert!(e.reason.contains("radii"), "{e}");
        let near_one = set(&[1.0 - 2f64.powi(-53)]);
        let e = snap_to_grid(&near_one, 3, 12, 52).unwrap().unwrap_err();
        assert!(e.reason.contains("of 1"), "{e}");
        // Words, not floats: refused before reading.
        let words = PointSet::from_columns(Width::W32, vec![vec![1]]).unwrap();
        assert!(snap_to_grid(&words, 3, 12, 52).is_err());
    }
}
