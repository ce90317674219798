//! Which method computes a value: the `--method` of `gartowen discrepancy` and the `method=`
//! of the Python package, one definition for both.

use crate::{compensated, exact, fast2d, naive, Discrepancy, Kind, Points};

/// The relative error bound `auto` must prove before it returns a compensated value.
pub const AUTO_REL_ERROR: f64 = 1e-12;

/// Largest exact rational the exact method builds, in bits. Reducing it costs about the square
/// of its size (1 point in 20,000 dimensions, 1.3 Mbit, took 41 s on 2 cores), so larger ones
/// are refused instead of running for hours.
pub const EXACT_MAX_BITS: u64 = 1 << 20;

/// Most 64-bit limb products the exact pair sum may take (2^38: about two minutes on 2 cores).
pub const EXACT_MAX_LIMB_PRODUCTS: u64 = 1 << 38;

/// The exact method's cost on `points`: the bits of its rational (d factors of at most 2W + 2
/// bits each, and N²) and the limb products of its pair sum (N(N+1)/2 pairs, each a product of
/// d factors whose accumulator grows by W + 1 bits a factor). Saturates instead of overflowing.
///
/// ```
/// use gartowen_core::Width;
/// use gartowen_discrepancy::{choice::exact_cost, Points};
/// let words = vec![0u64; 20_000];
/// let (bits, products) = exact_cost(Points { words: &words, dims: 20_000, width: Width::W32 });
/// assert_eq!(bits, 20_000 * 66 + 128);
/// assert_eq!(products, 20_000u64 * 20_000 * 33 / 128);
/// ```
pub fn exact_cost(points: Points) -> (u64, u64) {
    let (n, d, w) = (
        points.len() as u64,
        points.dims as u64,
        points.width.bits() as u64,
    );
    let bits = d.saturating_mul(2 * w + 2).saturating_add(128);
    let pairs = n.saturating_mul(n.saturating_add(1)) / 2;
    let per_pair = (d.saturating_mul(d).saturating_mul(w + 1) / 128).max(1);
    (bits, pairs.saturating_mul(per_pair))
}

/// Refuses an exact computation past [`EXACT_MAX_BITS`] or [`EXACT_MAX_LIMB_PRODUCTS`], naming
/// its cost.
fn exact_within_budget(points: Points) -> Result<(), String> {
    let (bits, products) = exact_cost(points);
    if bits > EXACT_MAX_BITS || products > EXACT_MAX_LIMB_PRODUCTS {
        return Err(format!(
            "method exact: {} points in {} dimensions need a {bits}-bit rational and {products}              limb products (limits {EXACT_MAX_BITS} and {EXACT_MAX_LIMB_PRODUCTS}); refused              rather than run for hours: use --method compensated (its error bound, if any, is              reported) or fewer points or dimensions",
            points.len(),
            points.dims
        ));
    }
    Ok(())
}

/// A requested method; [`MethodChoice::Auto`] picks the fastest one whose relative error
/// bound is at most [`AUTO_REL_ERROR`]: fast for 2-D L2-star, else compensated when its bound
/// holds, else exact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodChoice {
    /// The fastest method proven within [`AUTO_REL_ERROR`].
    Auto,
    /// Plain f64 (what most tools do; shown for comparison).
    Naive,
    /// Double-double compensated sums with the error bound proved in `proofs/DdSum.v`; where its
    /// hypotheses fail at run time, the exact method (within its budget).
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
        name.parse().ok()
    }

    /// Every method, in the order of [`MethodChoice::NAMES`].
    pub const ALL: [MethodChoice; 5] = [
        MethodChoice::Auto,
        MethodChoice::Naive,
        MethodChoice::Compensated,
        MethodChoice::Exact,
        MethodChoice::Fast,
    ];

    /// The names of [`MethodChoice::ALL`].
    pub const NAMES: [&'static str; 5] = ["auto", "naive", "compensated", "exact", "fast"];

    /// The lower-case name, as [`MethodChoice::parse`] reads it.
    pub fn name(self) -> &'static str {
        MethodChoice::NAMES[self as usize]
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
        MethodChoice::Compensated => {
            // The proved bound's hypotheses (exact coordinates, no overflow or underflow) are
            // checked at run time; where they fail the value is computed exactly instead,
            // within the exact method's budget (else the unbounded compensated value).
            let c = compensated::compensated(points, kind);
            if c.rel_error_bound.is_none() && exact_within_budget(points).is_ok() {
                exact::exact(points, kind)
            } else {
                c
            }
        }
        MethodChoice::Exact => {
            exact_within_budget(points)?;
            exact::exact(points, kind)
        }
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
                    exact_within_budget(points).map_err(|e| {
                        format!(
                            "method auto cannot prove {AUTO_REL_ERROR:e} by compensation, and {e}"
                        )
                    })?;
                    exact::exact(points, kind)
                }
            }
        }
    })
}

impl std::str::FromStr for MethodChoice {
    type Err = gartowen_core::UnknownName;

    /// The method called `s`; the error names the choices.
    fn from_str(s: &str) -> Result<MethodChoice, Self::Err> {
        gartowen_core::names::parse_name("method", s, &MethodChoice::NAMES, &MethodChoice::ALL)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_the_error_lists_every_method() {
        for m in MethodChoice::ALL {
            assert_eq!(m.name().parse::<MethodChoice>(), Ok(m));
        }
        assert_eq!(MethodChoice::Compensated.name(), "compensated");
        assert_eq!(
            "quick".parse::<MethodChoice>().unwrap_err().to_string(),
            "unknown method 'quick'; use auto, naive, compensated, exact or fast"
        );
    }
}
