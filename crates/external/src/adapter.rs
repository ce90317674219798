//! One seed's view of an [`ExternalProcess`] as a [`Scrambler`] (base 2^q) or a
//! [`RadixScrambler`] (other bases).

use crate::error::ExternalError;
use crate::process::ExternalProcess;
use crate::protocol::MAX_BATCH;
use gartowen_core::{Claim, PowerOfTwoBase, Radix, RadixScrambler, Scrambler, Width};

use std::sync::Arc;

/// One seed's view of an [`ExternalProcess`] as a [`Scrambler`]. Calls after a failure return 0;
/// the verify battery reads [`ExternalProcess::failure`] after each check.
pub struct ExternalScrambler {
    process: Arc<ExternalProcess>,
    seed: u64,
    claim: Claim,
}

impl ExternalScrambler {
    /// The scrambler with `seed` on `process`; `claim` is what the user says it is.
    pub fn new(process: Arc<ExternalProcess>, seed: u64, claim: Claim) -> Self {
        ExternalScrambler {
            process,
            seed,
            claim,
        }
    }

    /// Scrambles a batch in one request.
    pub fn request(&self, words: &[u64], dim: u32) -> Result<Vec<u64>, ExternalError> {
        self.process.scramble_batch(self.seed, dim, words)
    }
}

impl Scrambler for ExternalScrambler {
    fn name(&self) -> String {
        format!("external:{}", self.process.command())
    }
    /// The process's base 2^q (a process in another base is reached through
    /// [`ExternalRadixScrambler`], and this answers base 2 for it).
    fn base(&self) -> PowerOfTwoBase {
        self.process
            .base()
            .power_of_two()
            .unwrap_or(PowerOfTwoBase::B2)
    }
    fn claim(&self) -> Claim {
        self.claim
    }
    fn supports_width(&self, width: Width) -> bool {
        width == self.process.width()
    }
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        self.request(&[x], dim).map(|v| v[0]).unwrap_or_default()
    }
    /// One request per [`MAX_BATCH`] words; after a failure the words become 0 (the battery
    /// reads [`ExternalProcess::failure`]).
    fn scramble_batch(&self, words: &mut [u64], _width: Width, dim: u32) {
        for chunk in words.chunks_mut(MAX_BATCH) {
            match self.request(chunk, dim) {
                Ok(out) => chunk.copy_from_slice(&out),
                Err(_) => chunk.fill(0),
            }
        }
    }
    /// Whole frames of up to [`MAX_BATCH`] words in place, without widening to 64 bits (the
    /// every-word sweep's path); after a failure the words become 0.
    fn scramble_batch_u32(&self, words: &mut [u32], dim: u32) {
        for chunk in words.chunks_mut(MAX_BATCH) {
            if self
                .process
                .scramble_batch_u32(self.seed, dim, chunk)
                .is_err()
            {
                chunk.fill(0);
            }
        }
    }
}

/// One seed's view of an [`ExternalProcess`] in a base that is not a power of two (version 2
/// frames of base-b digit integers). Calls after a failure return 0, as
/// [`ExternalScrambler`]'s do.
pub struct ExternalRadixScrambler {
    words: ExternalScrambler,
    radix: Radix,
}

impl ExternalRadixScrambler {
    /// The scrambler with `seed` on `process`; `None` when the process's base is a power of
    /// two (use [`ExternalScrambler`]).
    pub fn new(process: Arc<ExternalProcess>, seed: u64, claim: Claim) -> Option<Self> {
        let radix = process.base().radix()?;
        Some(ExternalRadixScrambler {
            words: ExternalScrambler::new(process, seed, claim),
            radix,
        })
    }
}

impl RadixScrambler for ExternalRadixScrambler {
    fn name(&self) -> String {
        Scrambler::name(&self.words)
    }
    fn radix(&self) -> Radix {
        self.radix
    }
    fn claim(&self) -> Claim {
        self.words.claim
    }
    /// The frames' width alone: words of another width would be cut or misread.
    fn supports_width(&self, width: Width) -> bool {
        Scrambler::supports_width(&self.words, width)
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        Scrambler::scramble(&self.words, x, width, dim)
    }
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        Scrambler::scramble_batch(&self.words, words, width, dim)
    }
}
