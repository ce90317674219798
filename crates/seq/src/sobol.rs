//! Sobol generator matrices from Joe & Kuo's "new-joe-kuo-6.21201" direction numbers.
//!
//! The table (`data/new-joe-kuo-6.21201.txt`, in Joe & Kuo's own text format) was recovered
//! from the copy SciPy ships (`scipy/stats/_sobol_direction_numbers.npz`) by
//! `tools/extract_joe_kuo.py`. Dimension 0 is the van der Corput sequence (all m_i = 1);
//! line d of the table (d = 2..21201) gives dimension d − 1.

use crate::{DigitalSequence, SeqError};
use gartowen_core::{PowerOfTwoBase, Width};

/// The raw table text, embedded at compile time.
const JOE_KUO_TABLE: &str = include_str!("../data/new-joe-kuo-6.21201.txt");

/// Number of Sobol dimensions the table defines (van der Corput included).
pub const MAX_DIMS: usize = 21201;

/// One table row: degree s, coefficient bits a (a_1 most significant of s−1 bits), and m_1..m_s.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DirectionNumbers {
    /// Degree s of the primitive polynomial.
    pub degree: u32,
    /// Interior coefficients a_1..a_{s−1} as an (s−1)-bit integer, a_1 most significant.
    pub coefficients: u64,
    /// Initial m_1..m_s (m_i odd, m_i < 2^i).
    pub initial: Vec<u64>,
}

/// The direction numbers of dimension `dim` (0-based; dimension 0 is van der Corput, degree 0).
pub fn direction_numbers(dim: usize) -> Result<DirectionNumbers, SeqError> {
    if dim >= MAX_DIMS {
        return Err(SeqError::TooManyDimensions {
            sequence: "sobol".into(),
            requested: dim + 1,
            max: MAX_DIMS,
        });
    }
    if dim == 0 {
        return Ok(DirectionNumbers {
            degree: 0,
            coefficients: 0,
            initial: vec![],
        });
    }
    let line = JOE_KUO_TABLE
        .lines()
        .nth(dim)
        .expect("table has MAX_DIMS - 1 data lines after its header");
    Ok(parse_row(line))
}

/// Parses one table line `d s a m_1 … m_s`.
fn parse_row(line: &str) -> DirectionNumbers {
    let fields: Vec<u64> = line
        .split_whitespace()
        .map(|f| f.parse().expect("table holds integers"))
        .collect();
    let degree = fields[1] as u32;
    DirectionNumbers {
        degree,
        coefficients: fields[2],
        initial: fields[3..3 + degree as usize].to_vec(),
    }
}

/// The W columns of Sobol dimension `dim` for `width`-bit words: v_i = m_i · 2^(W−i),
/// with m_i from the table for i ≤ s and from the Joe–Kuo recurrence beyond
/// (m_i = 2a_1 m_{i−1} ⊕ 4a_2 m_{i−2} ⊕ … ⊕ 2^s m_{i−s} ⊕ m_{i−s}).
pub fn columns(dim: usize, width: Width) -> Result<Vec<u64>, SeqError> {
    Ok(columns_from(&direction_numbers(dim)?, width))
}

/// The first `dims` dimensions of the Sobol sequence with `width`-bit words (W columns each).
///
/// ```
/// use gartowen_core::Width;
/// let s = gartowen_seq::sobol::sequence(2, Width::W32).unwrap();
/// assert_eq!(s.point(1, 0), 0x8000_0000);
/// assert_eq!(s.point(3, 1), 0x4000_0000);
/// ```
pub fn sequence(dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
    if dims == 0 {
        return Err(SeqError::NoDimensions);
    }
    if dims > MAX_DIMS {
        return Err(SeqError::TooManyDimensions {
            sequence: "sobol".into(),
            requested: dims,
            max: MAX_DIMS,
        });
    }
    // Parse the table once, in order, instead of scanning it per dimension.
    let mut cols = vec![columns(0, width)?];
    cols.extend(
        JOE_KUO_TABLE
            .lines()
            .skip(1)
            .take(dims - 1)
            .map(|line| columns_from(&parse_row(line), width)),
    );
    DigitalSequence::from_columns("sobol", width, PowerOfTwoBase::B2, &cols)
}

fn columns_from(dn: &DirectionNumbers, width: Width) -> Vec<u64> {
    let w = width.bits() as usize;
    let s = dn.degree as usize;
    let mut m: Vec<u64> = Vec::with_capacity(w);
    for i in 0..w {
        let mi = if s == 0 {
            1 // van der Corput
        } else if i < s {
            dn.initial[i]
        } else {
            let mut v = m[i - s] ^ (m[i - s] << s);
            for k in 1..s {
                if (dn.coefficients >> (s - 1 - k)) & 1 == 1 {
                    v ^= m[i - k] << k;
                }
            }
            v
        };
        m.push(mi);
    }
    m.iter()
        .enumerate()
        .map(|(c, &mi)| (mi << (w - c - 1)) & width.mask())
        .collect()
}
