//! Which method computes a value: the `--method` of `gartowen discrepancy` and the `method=`
//! of the Python package, one definition for both.

use crate::{compensated, exact, fast2d, naive, Discrepancy, Kind, Method, Points};

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

/// How long `auto` lets the exact method take (estimated by [`estimated_seconds`]) when the
/// compensated bound is above [`AUTO_REL_ERROR`]; past it `auto` returns the compensated value
/// with its proven (looser) bound instead of running for minutes.
pub const AUTO_EXACT_SECONDS: f64 = 10.0;

/// Pair-factor operations (point pairs × dimensions) per second of each pair-sum method on
/// the 2-core reference machine, rounded down from 16,384 × 6 points (l2star and cd; see
/// record/2026-12-03-hardening.md): naive 2.3e8, compensated 1.6e9, exact 2.8e7.
const PAIR_FACTORS_PER_SECOND: [(Method, f64); 3] = [
    (Method::Naive, 2e8),
    (Method::Compensated, 1e9),
    (Method::Exact, 2.5e7),
];

/// The estimated wall time of `method` on `points`, in seconds on the 2-core reference
/// machine: N(N+1)/2 pairs × d factors at the method's measured rate (the O(N log N) fast
/// method: N log2 N at 1e8 per second). An estimate to refuse or announce long jobs by, not a
/// promise.
///
/// ```
/// use gartowen_core::Width;
/// use gartowen_discrepancy::{choice::estimated_seconds, Method, Points};
/// let words = vec![0u64; 65_536 * 6];
/// let p = Points { words: &words, dims: 6, width: Width::W64 };
/// // The exact method on 2^16 points in 6 dimensions: minutes, not seconds.
/// assert!(estimated_seconds(p, Method::Exact) > 300.0);
/// assert!(estimated_seconds(p, Method::Compensated) < 30.0);
/// ```
pub fn estimated_seconds(points: Points, method: Method) -> f64 {
    estimated_seconds_for(points.len(), points.dims, method)
}

/// [`estimated_seconds`] for `n` points in `dims` dimensions, before any word is read.
pub fn estimated_seconds_for(n: usize, dims: usize, method: Method) -> f64 {
    let n = n as f64;
    if method == Method::Fast {
        return n * n.max(2.0).log2() / 1e8;
    }
    let rate = PAIR_FACTORS_PER_SECOND
        .iter()
        .find(|(m, _)| *m == method)
        .map_or(1e8, |(_, r)| *r);
    n * (n + 1.0) / 2.0 * dims.max(1) as f64 / rate
}

/// The estimated wall time of `choice` on `points` (see [`estimated_seconds`]): for `auto`,
/// the compensated pass plus, where it may follow, the exact one within
/// [`AUTO_EXACT_SECONDS`].
pub fn estimated_choice_seconds(points: Points, kind: Kind, choice: MethodChoice) -> f64 {
    estimated_choice_seconds_for(points.len(), points.dims, kind, choice)
}

/// [`estimated_choice_seconds`] for `n` points in `dims` dimensions, before any word is read.
pub fn estimated_choice_seconds_for(
    n: usize,
    dims: usize,
    kind: Kind,
    choice: MethodChoice,
) -> f64 {
    let fast_applies = kind == Kind::L2Star && dims == 2;
    let estimated_seconds = |method| estimated_seconds_for(n, dims, method);
    match choice {
        MethodChoice::Naive => estimated_seconds(Method::Naive),
        MethodChoice::Compensated => estimated_seconds(Method::Compensated),
        MethodChoice::Exact => estimated_seconds(Method::Exact),
        MethodChoice::Fast => estimated_seconds(Method::Fast),
        MethodChoice::Auto if fast_applies => estimated_seconds(Method::Fast),
        MethodChoice::Auto => {
            let exact = estimated_seconds(Method::Exact);
            estimated_seconds(Method::Compensated)
                + if exact <= AUTO_EXACT_SECONDS {
                    exact
                } else {
                    0.0
                }
        }
    }
}

/// Whether `auto`, having computed the compensated value with relative error bound `bound`,
/// keeps it rather than computing exactly (estimated at `exact_seconds`): when the bound is
/// within [`AUTO_REL_ERROR`], or when there is a bound and exact would take longer than
/// [`AUTO_EXACT_SECONDS`]. Without a proven bound it never keeps it.
pub fn auto_keeps_compensated(bound: Option<f64>, exact_seconds: f64) -> bool {
    match bound {
        None => false,
        Some(b) => b <= AUTO_REL_ERROR || exact_seconds > AUTO_EXACT_SECONDS,
    }
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
/// holds, else exact when it takes at most [`AUTO_EXACT_SECONDS`], else compensated with its
/// proven (looser) bound.
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
                let exact_seconds = estimated_seconds(points, Method::Exact);
                if auto_keeps_compensated(c.rel_error_bound, exact_seconds) {
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
    fn auto_keeps_a_proven_bound_when_exact_would_take_long_and_never_an_unproven_one() {
        let quick = AUTO_EXACT_SECONDS / 2.0;
        let long = AUTO_EXACT_SECONDS * 2.0;
        assert!(auto_keeps_compensated(Some(AUTO_REL_ERROR), long));
        assert!(auto_keeps_compensated(Some(AUTO_REL_ERROR), quick));
        assert!(!auto_keeps_compensated(Some(AUTO_REL_ERROR * 10.0), quick));
        assert!(auto_keeps_compensated(Some(AUTO_REL_ERROR * 10.0), long));
        assert!(!auto_keeps_compensated(None, long));
        assert!(!auto_keeps_compensated(None, quick));
        // At the limit itself exact still runs.
        assert!(!auto_keeps_compensated(
            Some(AUTO_REL_ERROR * 10.0),
            AUTO_EXACT_SECONDS
        ));
    }

    #[test]
    fn estimates_grow_with_pairs_and_dimensions_and_rank_the_methods() {
        let words = vec![0u64; 4096 * 6];
        let at = |n: usize, d: usize| Points {
            words: &words[..n * d],
            dims: d,
            width: gartowen_core::Width::W64,
        };
        let e = |n, d, m| estimated_seconds(at(n, d), m);
        // N(N+1)/2 pairs: doubling N about quadruples the time; d multiplies it.
        let ratio = e(4096, 3, Method::Exact) / e(2048, 3, Method::Exact);
        assert!((ratio - 4.0).abs() < 0.01, "{ratio}");
        let ratio = e(1024, 6, Method::Exact) / e(1024, 3, Method::Exact);
        assert!((ratio - 2.0).abs() < 1e-9, "{ratio}");
        assert!(e(4096, 6, Method::Exact) > e(4096, 6, Method::Naive));
        assert!(e(4096, 6, Method::Naive) > e(4096, 6, Method::Compensated));
        assert!(e(4096, 2, Method::Compensated) > e(4096, 2, Method::Fast));
        // The fast method: N log2 N, so 4096 points cost 2 × 12/11 of 2048.
        let ratio = e(4096, 2, Method::Fast) / e(2048, 2, Method::Fast);
        assert!((ratio - 24.0 / 11.0).abs() < 1e-9, "{ratio}");
        // 16,384 points in 6 dimensions took 16 s (l2star) and 29 s (cd) exactly here.
        let words = vec![0u64; 16_384 * 6];
        let p = Points {
            words: &words,
            dims: 6,
            width: gartowen_core::Width::W64,
        };
        let exact = estimated_seconds(p, Method::Exact);
        assert!((16.0..=60.0).contains(&exact), "{exact}");
        assert_eq!(
            estimated_choice_seconds(p, Kind::Centered, MethodChoice::Auto),
            estimated_seconds(p, Method::Compensated),
            "auto does not plan an exact pass past its limit"
        );
    }

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
