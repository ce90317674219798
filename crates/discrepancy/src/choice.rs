//! Which method computes a value: the `--method` of `gartowen discrepancy` and the `method=`
//! of the Python package, one definition for both.

use crate::{compensated, exact, fast2d, naive, Discrepancy, Kind, Points};

/// The relative error bound `auto` must prove before it returns a compensated value.
pub const AUTO_REL_ERROR: f64 = 1e-12;

/// A requested method; [`MethodChoice::Auto`] picks the fastest one whose relative error
/// bound is at most [`AUTO_REL_ERROR`]: fast for 2-D L2-star, else compensated when its bound
/// holds, else exact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodChoice {
    /// The fastest method proven within [`AUTO_REL_ERROR`].
    Auto,
    /// Plain f64 (what most tools do; shown for comparison).
    Naive,
    /// Double-double compensated sums.
    Compensated,
    /// Exact rational.
    Exact,
    /// O(N log N) exact 2-D L2-star.
    Fast,
}

impl MethodChoice {
    /// The method called `name` (`auto`, `naive`, `compensated`, `exact`, `fast`).
    ///
    /// ```
    /// use gartowen_discrepancy::choice::MethodChoice;
    /// assert_eq!(MethodChoice::parse("exact"), Some(MethodChoice::Exact));
    /// assert_eq!(MethodChoice::parse("quick"), None);
    /// ```
    pub fn parse(name: &str) -> Option<MethodChoice> {
        Some(match name {
            "auto" => MethodChoice::Auto,
            "naive" => MethodChoice::Naive,
            "compensated" => MethodChoice::Compensated,
            "exact" => MethodChoice::Exact,
            "fast" => MethodChoice::Fast,
            _ => return None,
        })
    }

    /// The lower-case name, as [`MethodChoice::parse`] reads it.
    pub fn name(self) -> &'static str {
        match self {
            MethodChoice::Auto => "auto",
            MethodChoice::Naive => "naive",
            MethodChoice::Compensated => "compensated",
            MethodChoice::Exact => "exact",
            MethodChoice::Fast => "fast",
        }
    }
}

/// The squared discrepancy D² of `points` by `method`; an error names a method that does not
/// apply (`fast` is 2-D L2-star only).
///
/// ```
/// use gartowen_core::Width;
/// use gartowen_discrepancy::{choice::{compute, MethodChoice}, Kind, Method, Points};
/// let words = [0u64, 0, 1 << 31, 1 << 31]; // (0, 0) and (1/2, 1/2), 32-bit words
/// let p = Points { words: &words, dims: 2, width: Width::W32 };
/// let auto = compute(p, Kind::L2Star, MethodChoice::Auto).unwrap();
/// assert_eq!(auto.method, Method::Fast);
/// assert_eq!(auto.value, compute(p, Kind::L2Star, MethodChoice::Exact).unwrap().value);
/// assert!(compute(p, Kind::Centered, MethodChoice::Fast).is_err());
/// ```
pub fn compute(points: Points, kind: Kind, method: MethodChoice) -> Result<Discrepancy, String> {
    let fast_applies = kind == Kind::L2Star && points.dims == 2;
    Ok(match method {
        MethodChoice::Naive => naive::naive(points, kind),
        MethodChoice::Compensated => compensated::compensated(points, kind),
        MethodChoice::Exact => exact::exact(points, kind),
        MethodChoice::Fast => {
            if !fast_applies {
                return Err("method fast is 2-D L2-star only".into());
            }
            fast2d::fast(points).expect("2-D")
        }
        MethodChoice::Auto => {
            if fast_applies {
                fast2d::fast(points).expect("2-D")
            } else {
                let c = compensated::compensated(points, kind);
                if c.rel_error_bound.is_some_and(|b| b <= AUTO_REL_ERROR) {
                    c
                } else {
                    exact::exact(points, kind)
                }
            }
        }
    })
}
