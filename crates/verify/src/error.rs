//! The battery's typed errors: what could not be judged, with the value and the rule it broke
//! named. Messages are for people; programs match on the variants (which may grow, hence
//! `#[non_exhaustive]`).

use std::fmt;

/// Why the battery could not run on an implementation.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum BatteryError {
    /// The implementation's builder refused a seed (its message is kept as given).
    Instance {
        /// The seed the builder was asked for.
        seed: u64,
        /// The builder's own words.
        message: String,
    },
}

impl fmt::Display for BatteryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BatteryError::Instance { seed, message } => {
                write!(f, "no instance for seed {seed}: {message}")
            }
        }
    }
}

impl std::error::Error for BatteryError {}

/// Why shard reports do not merge into one run.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum MergeError {
    /// One implementation is in two shards.
    Duplicate {
        /// Its position in the run.
        index: usize,
        /// Its name.
        name: String,
    },
    /// A position is in no shard.
    Missing {
        /// The missing position.
        index: usize,
        /// The next implementation present, and its position.
        next: (String, usize),
    },
    /// The last positions are in no shard.
    Short {
        /// Implementations present.
        present: usize,
        /// Implementations in the run.
        total: usize,
    },
    /// One implementation ran other checks than the rest.
    Checks {
        /// Its position.
        index: usize,
        /// Its name.
        name: String,
        /// Its checks, in order.
        checks: Vec<String>,
        /// The others' checks.
        expected: Vec<String>,
    },
}

impl fmt::Display for MergeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MergeError::Duplicate { index, name } => {
                write!(f, "implementation {index} ({name}) appears in two shards")
            }
            MergeError::Missing { index, next } => write!(
                f,
                "implementation {index} is missing (next present: {} at {})",
                next.0, next.1
            ),
            MergeError::Short { present, total } => write!(
                f,
                "{present} of {total} implementations present: {present} to {} are missing",
                total.saturating_sub(1)
            ),
            MergeError::Checks {
                index,
                name,
                checks,
                expected,
            } => write!(
                f,
                "implementation {index} ({name}) has checks {checks:?}, the others {expected:?}"
            ),
        }
    }
}

impl std::error::Error for MergeError {}
