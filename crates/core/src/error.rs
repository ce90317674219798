//! The typed error of the core crate; every variant names the offending value.

use std::fmt;

/// Errors from constructing core values or converting inputs.
#[derive(Debug, Clone, PartialEq)]
pub enum CoreError {
    /// A word width outside 1..=64 bits.
    InvalidWidth(u32),
    /// A digit exponent q outside 1..=8 (base 2^q).
    InvalidDigitBits(u32),
    /// A base that is not 2^q with q in 1..=8.
    NotPowerOfTwoBase(u64),
    /// A base that is not in 3..=65535 or is a power of two (see [`crate::Radix`]).
    InvalidRadix(u64),
    /// A base whose one digit does not fit the word width.
    RadixTooLarge {
        /// The base b.
        base: u32,
        /// The word width W in bits.
        width: u32,
    },
    /// A base-b word not below b^m.
    RadixWordTooLarge {
        /// The word given.
        word: u64,
        /// The base b.
        base: u32,
        /// The digits m a word holds.
        digits: u32,
    },
    /// A claim whose group exists only in bases 2^q, made in another base.
    ClaimNeedsPowerOfTwo {
        /// The claim.
        claim: String,
        /// The base b.
        base: u32,
    },
    /// A float input that is NaN.
    NotANumber,
    /// A float input outside [0, 1).
    OutOfUnitInterval(f64),
    /// A float in [0,1) that is not a multiple of 2^-width, so no word holds it exactly.
    NotRepresentable {
        /// The float given.
        value: f64,
        /// The word width W in bits.
        width: u32,
    },
    /// A word with bits set above the width.
    WordTooWide {
        /// The word given.
        word: u64,
        /// The word width W in bits.
        width: u32,
    },
    /// A slice that is not a permutation of 0..n.
    NotAPermutation {
        /// What is wrong with it.
        reason: String,
    },
    /// A permutation size that is not supported (must be 1..=256).
    InvalidPermutationSize(usize),
    /// A GF(2) matrix of size outside 1..=8 or an entry outside it.
    InvalidMatrix {
        /// What is wrong with it.
        reason: String,
    },
    /// A scrambler name that no registry entry has.
    UnknownScrambler {
        /// The name given.
        name: String,
        /// The registry's names.
        known: Vec<String>,
    },
    /// A claim that does not parse ([`crate::Claim::parse`]).
    InvalidClaim {
        /// The text given.
        text: String,
        /// The claim it would be in lower case, if any (claims are lower case).
        lower_case: Option<String>,
    },
    /// A scrambler option that the named scrambler does not accept, or a bad value.
    InvalidOption {
        /// The scrambler's name.
        scrambler: String,
        /// The option given.
        option: String,
        /// Why it is refused.
        reason: String,
    },
}

impl fmt::Display for CoreError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CoreError::InvalidWidth(w) => write!(f, "word width {w} is not in 1..=64 bits"),
            CoreError::InvalidDigitBits(q) => {
                write!(f, "digit size q = {q} is not in 1..=8 (base 2^q from 2 to 256)")
            }
            CoreError::NotPowerOfTwoBase(b) => {
                write!(f, "base {b} is not a power of two 2^q with q in 1..=8")
            }
            CoreError::InvalidRadix(b) => match b {
                0 | 1 => write!(f, "base {b}: a base is at least 2"),
                b if b.is_power_of_two() && *b > 256 => write!(
                    f,
                    "base {b} is a power of two above 256: bases 2^q go up to 256 (q ≤ 8)"
                ),
                b if b.is_power_of_two() => write!(
                    f,
                    "base {b} is a power of two: its digits are bits (base 2^q), not base-b integers"
                ),
                b if *b > 65535 => write!(f, "base {b} is above 65535, the largest base served"),
                b => write!(f, "base {b} is not served as base-b digit integers"),
            },
            CoreError::RadixTooLarge { base, width } => {
                write!(f, "not one base-{base} digit fits a {width}-bit word")
            }
            CoreError::RadixWordTooLarge { word, base, digits } => write!(
                f,
                "word {word} is not below {base}^{digits}, the {digits} base-{base} digits a word holds"
            ),
            CoreError::ClaimNeedsPowerOfTwo { claim, base } => write!(
                f,
                "claim '{claim}' names a group of base-2^q digits; in base {base} claim nested, \
                 owen, marginal[:symmetric|:cyclic] or independent:symmetric|cyclic"
            ),
            CoreError::NotANumber => write!(f, "value is NaN"),
            CoreError::OutOfUnitInterval(v) => write!(f, "value {v} is outside [0, 1)"),
            CoreError::NotRepresentable { value, width } => write!(
                f,
                "value {value:e} is not a multiple of 2^-{width}, so no {width}-bit word holds it exactly"
            ),
            CoreError::WordTooWide { word, width } => {
                write!(f, "word {word:#x} has bits set above width {width}")
            }
            CoreError::NotAPermutation { reason } => write!(f, "not a permutation: {reason}"),
            CoreError::InvalidPermutationSize(n) => {
                write!(f, "permutation size {n} is not in 1..=256")
            }
            CoreError::InvalidMatrix { reason } => write!(f, "invalid GF(2) matrix: {reason}"),
            CoreError::UnknownScrambler { name, known } => write!(
                f,
                "unknown scrambler '{name}'; known scramblers: {}",
                known.join(", ")
            ),
            CoreError::InvalidOption {
                scrambler,
                option,
                reason,
            } => write!(f, "scrambler '{scrambler}': option '{option}': {reason}"),
            CoreError::InvalidClaim { text, lower_case } => match lower_case {
                Some(lower) => write!(f, "unknown claim '{text}'; claims are lower case: '{lower}'"),
                None => write!(
                    f,
                    "unknown claim '{text}'; use nested, owen, marginal[:GROUP], \
                     per-depth[:GROUP] (= marginal) or independent:GROUP (GROUP: symmetric, \
                     affine, translation, cyclic)"
                ),
            },
        }
    }
}

impl std::error::Error for CoreError {}
