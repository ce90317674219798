//! Squared discrepancies as their definitions read: the integral of the squared local
//! discrepancy (the fraction of the points in a box minus the box's volume) over every box of
//! the kind's family, summed over the coordinate projections the kind includes. No closed form
//! (Warnock's or Hickernell's) is used, so this is the second, independent path behind
//! `discrepancy --method exact`: a wrong constant or factor in a closed form shows here.
//!
//! The box families, per coordinate:
//! - anchored (L2-star, generalized L2): [0, x) for x in [0, 1];
//! - centred: the box between x and the corner of [0, 1] nearest to it;
//! - wrap-around: [x, y) on the circle, for (x, y) in [0, 1]².
//!
//! L2-star integrates the full-dimensional boxes only; the other three kinds add up the
//! integrals of every projection (Hickernell's definitions; the empty projection adds 0).
//!
//! Every coordinate is a dyadic word X/2^W, so on each cell of the grid of step 2^-W (and, for
//! wrap-around boxes, on each of the two triangles of a diagonal cell) whether a point's
//! coordinate lies in the box is constant and the box's side is a polynomial of degree one.
//! Over a product of such pieces the count A is constant and the integral of
//! (A/N − Π_j len_j)² is (A/N)²·Π_j m0_j − 2(A/N)·Π_j m1_j + Π_j m2_j, where m_k is the integral
//! of len^k over the piece (Fubini on a product domain); the moments are the elementary
//! integrals of polynomials written out below. The cost is exponential in the dimension and the
//! word width: this is for tiny sets only.

use crate::exact_discrepancy::ReferenceKind;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

/// The most products of pieces one call may integrate (all projections together).
pub const MAX_PIECE_PRODUCTS: u128 = 1 << 22;

/// Why the integral was not computed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum IntegrationError {
    /// No points, or points with no coordinates.
    Empty,
    /// Point `point` has `dims` coordinates where the first point has `expected`.
    Ragged {
        /// Index of the offending point.
        point: usize,
        /// Its number of coordinates.
        dims: usize,
        /// The first point's number of coordinates.
        expected: usize,
    },
    /// A word does not fit the stated width, or the width is outside 1..=16.
    BadWord {
        /// The word (0 when the width itself is bad).
        word: u64,
        /// The stated width in bits.
        width_bits: u32,
    },
    /// The integral would take more than [`MAX_PIECE_PRODUCTS`] products of pieces.
    TooLarge {
        /// Products of pieces it would take.
        products: u128,
    },
}

impl std::fmt::Display for IntegrationError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            IntegrationError::Empty => write!(f, "no points, or points without coordinates"),
            IntegrationError::Ragged {
                point,
                dims,
                expected,
            } => write!(
                f,
                "point {point} has {dims} coordinates, the first has {expected}"
            ),
            IntegrationError::BadWord { word, width_bits } => write!(
                f,
                "word {word:#x} at width {width_bits} (widths 1..=16, words below 2^width)"
            ),
            IntegrationError::TooLarge { products } => write!(
                f,
                "{products} products of pieces exceed the limit {MAX_PIECE_PRODUCTS}"
            ),
        }
    }
}

impl std::error::Error for IntegrationError {}

/// One piece of a coordinate's box parameters: on it every point's membership is constant.
struct Piece {
    /// ∫ len^k over the piece, k = 0, 1, 2 (len: the box's side in this coordinate).
    moments: [BigRational; 3],
    /// `inside[i]`: point i's coordinate lies in the box for every parameter in the piece.
    inside: Vec<bool>,
}

fn rat(n: i64) -> BigRational {
    BigRational::from_integer(BigInt::from(n))
}

/// ∫ over [lo, hi] of (c0 + c1·x)^k dx for k = 0, 1, 2.
fn linear_moments(
    lo: &BigRational,
    hi: &BigRational,
    c0: &BigRational,
    c1: &BigRational,
) -> [BigRational; 3] {
    let (d1, d2, d3) = (hi - lo, hi * hi - lo * lo, hi * hi * hi - lo * lo * lo);
    [
        d1.clone(),
        c0 * &d1 + c1 * &d2 / rat(2),
        c0 * c0 * &d1 + c0 * c1 * &d2 + c1 * c1 * &d3 / rat(3),
    ]
}

/// ∫ over cell [lo, hi] of x^k dx for k = 0, 1, 2.
fn power_moments(lo: &BigRational, hi: &BigRational) -> [BigRational; 3] {
    linear_moments(lo, hi, &BigRational::zero(), &BigRational::one())
}

/// The pieces of one coordinate: `cells` grid cells of width h; `grid[i]` is point i's
/// coordinate in units of h.
fn pieces(kind: ReferenceKind, grid: &[u64], cells: u64) -> Vec<Piece> {
    let h = BigRational::new(BigInt::one(), BigInt::from(cells));
    let edge = |a: u64| &h * rat(a as i64);
    let (zero, one) = (BigRational::zero(), BigRational::one());
    let mut out = Vec::new();
    match kind {
        ReferenceKind::L2Star | ReferenceKind::GeneralizedL2 => {
            // x in (a·h, (a+1)·h): the box [0, x) holds c·h iff c ≤ a; its side is x.
            for a in 0..cells {
                out.push(Piece {
                    moments: power_moments(&edge(a), &edge(a + 1)),
                    inside: grid.iter().map(|&c| c <= a).collect(),
                });
            }
        }
        ReferenceKind::Centered => {
            for a in 0..cells {
                let (lo, hi) = (edge(a), edge(a + 1));
                if 2 * a < cells {
                    // Nearest corner 0: the box [0, x], side x.
                    out.push(Piece {
                        moments: linear_moments(&lo, &hi, &zero, &one),
                        inside: grid.iter().map(|&c| c <= a).collect(),
                    });
                } else {
                    // Nearest corner 1: the box [x, 1], side 1 − x.
                    out.push(Piece {
                        moments: linear_moments(&lo, &hi, &one, &-one.clone()),
                        inside: grid.iter().map(|&c| c > a).collect(),
                    });
                }
            }
        }
        ReferenceKind::WrapAround => {
            for a in 0..cells {
                let mx = power_moments(&edge(a), &edge(a + 1));
                for b in 0..cells {
                    let my = power_moments(&edge(b), &edge(b + 1));
                    if a == b {
                        // Two triangles; over either, ∫∫ t^k = h^(k+2)/((k+1)(k+2)), t = |y − x|.
                        let t = |k: i32| h.pow(k + 2) / rat(((k + 1) * (k + 2)) as i64);
                        // x < y: the box [x, y) lies inside the open cell, so holds no point.
                        out.push(Piece {
                            moments: [t(0), t(1), t(2)],
                            inside: vec![false; grid.len()],
                        });
                        // x > y: the box wraps round and holds every point; side 1 − t.
                        out.push(Piece {
                            moments: [t(0), t(0) - t(1), t(0) - rat(2) * t(1) + t(2)],
                            inside: vec![true; grid.len()],
                        });
                        continue;
                    }
                    // Side c0 + y − x: c0 = 0 for [x, y), 1 when the box wraps (x > y).
                    let c0 = if a < b { zero.clone() } else { one.clone() };
                    let area = &mx[0] * &my[0];
                    let m1 = &c0 * &area + &mx[0] * &my[1] - &mx[1] * &my[0];
                    let m2 = &c0 * &c0 * &area + &mx[0] * &my[2] + &mx[2] * &my[0]
                        - rat(2) * &mx[1] * &my[1]
                        + rat(2) * &c0 * (&mx[0] * &my[1] - &mx[1] * &my[0]);
                    let inside = grid
                        .iter()
                        .map(|&c| {
                            if a < b {
                                a < c && c <= b
                            } else {
                                c > a || c <= b
                            }
                        })
                        .collect();
                    out.push(Piece {
                        moments: [area, m1, m2],
                        inside,
                    });
                }
            }
        }
    }
    out
}

/// ∫ (A/N − Π_{j∈dims} len_j)² over the products of the pieces of the coordinates `dims`.
fn projection_integral(per_dim: &[Vec<Piece>], dims: &[usize], n: usize) -> BigRational {
    let nn = rat(n as i64);
    let mut chosen = vec![0usize; dims.len()];
    let mut total = BigRational::zero();
    loop {
        let count = (0..n)
            .filter(|&i| {
                dims.iter()
                    .zip(&chosen)
                    .all(|(&j, &p)| per_dim[j][p].inside[i])
            })
            .count();
        let product = |k: usize| -> BigRational {
            dims.iter()
                .zip(&chosen)
                .map(|(&j, &p)| per_dim[j][p].moments[k].clone())
                .fold(BigRational::one(), |acc, m| acc * m)
        };
        let fraction = rat(count as i64) / &nn;
        total += &fraction * &fraction * product(0) - rat(2) * &fraction * product(1) + product(2);
        // The next product of pieces (an odometer over the chosen pieces).
        let mut pos = 0;
        loop {
            if pos == dims.len() {
                return total;
            }
            chosen[pos] += 1;
            if chosen[pos] < per_dim[dims[pos]].len() {
                break;
            }
            chosen[pos] = 0;
            pos += 1;
        }
    }
}

/// D² of the points (each coordinate a `width_bits`-bit word, value X/2^W) as the integral of
/// its definition, exactly. Errors on empty or ragged input, words wider than the width,
/// widths outside 1..=16, and integrals of more than [`MAX_PIECE_PRODUCTS`] pieces.
///
/// ```
/// use gartowen_oracles::discrepancy_integral::integrate_discrepancy;
/// use gartowen_oracles::exact_discrepancy::ReferenceKind;
/// use num_rational::BigRational;
/// // One point at 0 in one dimension: ∫₀¹ (1 − x)² dx = 1/3.
/// let d = integrate_discrepancy(&[vec![0]], 4, ReferenceKind::L2Star).unwrap();
/// assert_eq!(d, BigRational::new(1.into(), 3.into()));
/// ```
pub fn integrate_discrepancy(
    points: &[Vec<u64>],
    width_bits: u32,
    kind: ReferenceKind,
) -> Result<BigRational, IntegrationError> {
    let d = points.first().map_or(0, |p| p.len());
    if d == 0 {
        return Err(IntegrationError::Empty);
    }
    if !(1..=16).contains(&width_bits) {
        return Err(IntegrationError::BadWord {
            word: 0,
            width_bits,
        });
    }
    for (i, p) in points.iter().enumerate() {
        if p.len() != d {
            return Err(IntegrationError::Ragged {
                point: i,
                dims: p.len(),
                expected: d,
            });
        }
        if let Some(&word) = p.iter().find(|&&x| x >> width_bits != 0) {
            return Err(IntegrationError::BadWord { word, width_bits });
        }
    }
    let cells = 1u64 << width_bits;
    let per_dim: Vec<Vec<Piece>> = (0..d)
        .map(|j| {
            let grid: Vec<u64> = points.iter().map(|p| p[j]).collect();
            pieces(kind, &grid, cells)
        })
        .collect();
    // The projections: the full set for L2-star, every subset otherwise.
    let projections: Vec<Vec<usize>> = match kind {
        ReferenceKind::L2Star => vec![(0..d).collect()],
        _ => (0u64..1 << d)
            .map(|set| (0..d).filter(|&j| set >> j & 1 == 1).collect())
            .collect(),
    };
    let products: u128 = projections
        .iter()
        .map(|u| {
            u.iter()
                .map(|&j| per_dim[j].len() as u128)
                .product::<u128>()
        })
        .sum();
    if products > MAX_PIECE_PRODUCTS {
        return Err(IntegrationError::TooLarge { products });
    }
    Ok(projections
        .iter()
        .map(|u| projection_integral(&per_dim, u, points.len()))
        .fold(BigRational::zero(), |acc, v| acc + v))
}
