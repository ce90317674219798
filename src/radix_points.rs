//! Points in a base b that is not a power of two (3, 5, 6, 7, …), for `generate` and
//! `scramble` with `--scramble-base B`: coordinates become base-b digit words (integers below
//! b^m, value k·b^-m, m the most digits whose b^m fits the word), are scrambled digit by digit
//! and written back as values or as those words.
//!
//! Reading floats: a binary64 value cannot hold 1/3, so a base-3 point k/3^n is stored a hair
//! away from it; its digits would read k − 1 followed by 2s, a different box at depth n. Floats
//! are therefore snapped to the base-b grid of depth n (`--digits n`, by default the fewest
//! digits that index every point, ⌈log_b N⌉) by the rule of `gartowen_netcheck::snap`: within
//! 2^-46 of a grid point they are that grid point, farther than 4·2^-46 from every grid point
//! they are read as they are (truncated to m digits), in between they are refused.

pub use crate::generate::radix_of_request;
use crate::generate::RequestError;
use crate::net_check::F64_RADIUS_LOG2;
use gartowen_core::{Radix, RadixLayout, RadixScrambler, Width};
use gartowen_netcheck::snap::snap_to_grid;
use gartowen_netcheck::PointSet;
use gartowen_owen::radix_tree::RadixOwen;
use gartowen_owen::registry::build_radix;
use gartowen_seq::radix::faure_prime;

/// The most coordinates (points × dimensions) the base-b Faure generator makes in one call:
/// it holds them as exact fractions (16 bytes each), so this bounds it to 1 GiB.
pub const MOST_FAURE_COORDINATES: u64 = 1 << 26;

/// A point set as base-b digit words, one column per dimension.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RadixPoints {
    /// How the words hold digits (base, width, m).
    pub layout: RadixLayout,
    /// Column j holds dimension j's words, each below b^m.
    pub columns: Vec<Vec<u64>>,
}

impl RadixPoints {
    /// Number of points.
    pub fn len(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Scrambles column j as dimension j.
    pub fn scramble(&mut self, s: &dyn RadixScrambler) {
        let width = self.layout.width();
        for (j, column) in self.columns.iter_mut().enumerate() {
            s.scramble_batch(column, width, j as u32);
        }
    }
}

/// The scrambler `request` in base `radix` with `seed` (`None` for `none`): the base-b Owen
/// oracle and its variants, `owen-oracle[:cyclic|:per-depth]`.
pub fn radix_scrambler(
    request: &str,
    radix: Radix,
    seed: u64,
) -> Result<Option<RadixOwen>, RequestError> {
    if request == "none" {
        return Ok(None);
    }
    Ok(Some(build_radix(request, radix, seed)?))
}

/// The fewest base-b digits that index `n` points: the least d with b^d ≥ n (at least 1).
pub fn digits_for(radix: Radix, n: u64) -> u32 {
    let (mut d, mut p) = (1u32, radix.get() as u128);
    while p < n as u128 {
        p *= radix.get() as u128;
        d += 1;
    }
    d
}

/// Float values (64-bit words holding them exactly) as base-b digit words of `layout`,
/// each snapped to the grid of `digits` digits. Without `digits`, the shallowest grid from
/// [`digits_for`] the number of points down that every value lies on (a point past the first
/// b^d of a sequence carries more digits than ⌈log_b N⌉). A value on no grid the float
/// resolves, or (with `digits`) off the grid asked for, is refused, named: read as it is, its
/// low digits would be rounding noise, and the scrambled points would not be the generator's.
pub fn from_floats(
    points: &PointSet,
    layout: RadixLayout,
    digits: Option<u32>,
) -> Result<RadixPoints, RequestError> {
    let b = layout.radix().get() as u64;
    let most = layout.num_digits();
    let depth = match digits {
        Some(0) => {
            return Err(RequestError::Invalid(
                "--digits 0: the values carry at least one base-b digit".into(),
            ))
        }
        Some(d) => {
            if d > most {
                return Err(RequestError::Invalid(format!(
                    "--digits {d}: {}-bit words hold {most} base-{b} digits",
                    layout.width().bits()
                )));
            }
            d
        }
        None => digits_for(layout.radix(), points.len() as u64).min(most),
    };
    check_depth(b, depth)?;
    let mut depth = depth;
    let snapped = loop {
        let snapped = snap(points, b, depth)?;
        let off = first_off_grid(&snapped, b, depth);
        match off {
            None => break snapped,
            // The default depth grows until every value is on its grid.
            Some(_) if digits.is_none() && depth < most && check_depth(b, depth + 1).is_ok() => {
                depth += 1
            }
            Some((point, dim)) => {
                let value = points.column(dim)[point] as f64 / 2f64.powi(64);
                let why = if digits.is_some() {
                    format!("pass a larger --digits than {depth}")
                } else {
                    format!(
                        "no grid of up to {depth} digits holds it: not a base-{b} point a \
                         {}-bit digit word can carry",
                        layout.width().bits()
                    )
                };
                return Err(RequestError::Invalid(format!(
                    "point {point} coordinate {dim} = {value:e} is not a multiple of \
                     {b}^-{depth} within 2^-{F64_RADIUS_LOG2} ({why})"
                )));
            }
        }
    };
    let capacity = layout.capacity() as u128;
    let columns = (0..snapped.dims())
        .map(|j| {
            snapped
                .column(j)
                .iter()
                // floor(x · b^m / 2^64): a snapped word is within 2^-64 above its grid point,
                // which moves no digit of m ≤ 40 (b^m ≤ 2^64).
                .map(|&x| ((x as u128 * capacity) >> 64) as u64)
                .collect()
        })
        .collect();
    Ok(RadixPoints { layout, columns })
}

/// Refuses a depth deeper than a float resolves, in `--digits` words.
fn check_depth(b: u64, depth: u32) -> Result<(), RequestError> {
    gartowen_netcheck::snap::grid(b, depth, F64_RADIUS_LOG2)
        .map(|_| ())
        .map_err(|e| {
            let why = match e {
                gartowen_netcheck::NetError::BadValue { reason, .. } => reason,
                other => other.to_string(),
            };
            RequestError::Invalid(format!(
                "--digits {depth}: {}",
                why.replace("this check needs", "asked for")
            ))
        })
}

/// The points snapped to the grid of `depth`, or the ambiguous coordinate refused.
fn snap(points: &PointSet, b: u64, depth: u32) -> Result<PointSet, RequestError> {
    match snap_to_grid(points, b, depth, F64_RADIUS_LOG2)
        .map_err(|e| RequestError::Invalid(e.to_string()))?
    {
        Ok((set, _)) => Ok(set),
        Err(ambiguous) => Err(RequestError::Invalid(format!(
            "{ambiguous}: too near the base-{b} grid of depth {depth} to read its digits \
             safely (pass --digits to choose the depth the values carry)"
        ))),
    }
}

/// The first coordinate of a snapped set that is not a grid point ⌈j·2^64/b^depth⌉ (snapping
/// leaves a value clear of the grid as it is).
fn first_off_grid(snapped: &PointSet, b: u64, depth: u32) -> Option<(usize, usize)> {
    let bm = (b as u128).pow(depth);
    (0..snapped.dims()).find_map(|dim| {
        snapped
            .column(dim)
            .iter()
            .enumerate()
            .find_map(|(point, &w)| {
                let j = (w as u128 * bm) >> 64;
                ((j << 64).div_ceil(bm) != w as u128).then_some((point, dim))
            })
    })
}

/// Words that are already base-b digit integers (below b^m of `layout`); an error names the
/// first that is not.
pub fn from_digit_words(
    points: &PointSet,
    layout: RadixLayout,
) -> Result<RadixPoints, RequestError> {
    let columns: Vec<Vec<u64>> = (0..points.dims())
        .map(|j| points.column(j).to_vec())
        .collect();
    for (j, column) in columns.iter().enumerate() {
        if let Some((i, &y)) = column
            .iter()
            .enumerate()
            .find(|(_, &y)| y >= layout.capacity())
        {
            return Err(RequestError::Invalid(format!(
                "point {i} coordinate {j}: word {y} is not a base-{} digit word (below {}^{})",
                layout.radix().get(),
                layout.radix().get(),
                layout.num_digits()
            )));
        }
    }
    Ok(RadixPoints { layout, columns })
}

/// The base of a sequence name that asks for a base-b generator: `faure:base=P` with P not a
/// power of two (the Faure sequence in the prime base P).
pub fn radix_sequence(name: &str) -> Option<u64> {
    let b: u64 = name.strip_prefix("faure:base=")?.parse().ok()?;
    (!b.is_power_of_two()).then_some(b)
}

/// Points `start..start + count` of the Faure sequence in the prime base `p`, `dims`
/// dimensions, as digit words of `width`-bit words (exact: point i's coordinate k/p^n is the
/// word k·p^(m−n)).
pub fn faure_points(
    p: u64,
    start: u64,
    count: u64,
    dims: usize,
    width: Width,
) -> Result<RadixPoints, RequestError> {
    let radix = Radix::new(p)?;
    let layout = RadixLayout::new(width, radix)?;
    let end = start
        .checked_add(count)
        .filter(|&e| e.saturating_mul(dims as u64) <= MOST_FAURE_COORDINATES)
        .ok_or_else(|| {
            RequestError::Invalid(format!(
                "{count} points from index {start} in {dims} dimensions: the base-{p} Faure \
                 generator makes at most {MOST_FAURE_COORDINATES} coordinates"
            ))
        })?;
    let flat = faure_prime(p, end, dims)?;
    let mut columns = vec![Vec::with_capacity(count as usize); dims];
    for (k, f) in flat.iter().enumerate().skip(start as usize * dims) {
        let digits = f.denom.ilog(p);
        if digits > layout.num_digits() {
            return Err(RequestError::Invalid(format!(
                "index {} needs {digits} base-{p} digits; {}-bit words hold {}",
                k / dims,
                width.bits(),
                layout.num_digits()
            )));
        }
        columns[k % dims].push(f.numer * p.pow(layout.num_digits() - digits));
    }
    Ok(RadixPoints { layout, columns })
}

#[cfg(test)]
mod tests;
