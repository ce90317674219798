//! The verify battery from `cargo test`: gate your own scrambler in your own test suite.
//!
//! Your type implements [`TestScrambler`] (scramble one word of one dimension); a closure
//! builds it for a seed. The battery runs every check of `gartowen verify` on it (injectivity
//! instead of an inverse), judged on the claim you state: structure exactly, the marginal and
//! joint laws at the level's power, with the family-wise false-alarm rate 10^-3.
//!
//! ```
//! use gartowen::testing::{Base, Battery, Claim, Level, TestScrambler, Width};
//!
//! /// A per-bit hashed binary Owen scramble: bit k flips by a hash of (seed, dim, k, prefix).
//! struct MyOwen(u64);
//! impl TestScrambler for MyOwen {
//!     fn scramble(&self, x: u64, dim: u32) -> u64 {
//!         let mut y = x;
//!         for k in 0..32 {
//!             let prefix = if k == 0 { 0 } else { x >> (32 - k) };
//!             let h = gartowen::core::hash_words(&[self.0, dim as u64, k as u64, prefix]);
//!             y ^= (h & 1) << (31 - k);
//!         }
//!         y
//!     }
//! }
//!
//! Battery::new(Base::B2, Width::W32)
//!     .claims(Claim::OWEN)
//!     .level(Level::Quick)
//!     .assert(|seed| MyOwen(seed)); // panics with the report if a check fails
//! ```
//!
//! A digital shift claiming Owen fails, and the panic names the check and the depth:
//!
//! ```should_panic
//! use gartowen::testing::{Base, Battery, Claim, TestScrambler, Width};
//! struct Shift(u64);
//! impl TestScrambler for Shift {
//!     fn scramble(&self, x: u64, dim: u32) -> u64 {
//!         x ^ (gartowen::core::hash_words(&[self.0, dim as u64]) >> 32)
//!     }
//! }
//! Battery::new(Base::B2, Width::W32).claims(Claim::OWEN).assert(|seed| Shift(seed));
//! ```

pub use crate::verify::{CheckResult, ImplReport, Level, Verdict};
pub use gartowen_core::{Claim, NodeGroup, PowerOfTwoBase as Base, Width};

use crate::verify::{check_candidate, Candidate};
use gartowen_core::{PowerOfTwoBase, Scrambler};

/// What a scrambler under test implements: the scramble of one `width`-bit word (its value is
/// word · 2^-W; bits above the width are zero) in dimension `dim`. Seeds are the constructor's
/// business: the battery builds one instance per seed.
pub trait TestScrambler: Send + Sync {
    /// The scrambled word.
    fn scramble(&self, word: u64, dim: u32) -> u64;
}

/// Adapts a [`TestScrambler`] to the battery's scrambler interface.
struct Adapter<S> {
    inner: S,
    base: PowerOfTwoBase,
    width: Width,
    claim: Claim,
    name: String,
}

impl<S: TestScrambler> Scrambler for Adapter<S> {
    fn name(&self) -> String {
        self.name.clone()
    }
    fn base(&self) -> PowerOfTwoBase {
        self.base
    }
    fn claim(&self) -> Claim {
        self.claim
    }
    fn supports_width(&self, width: Width) -> bool {
        width == self.width
    }
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        self.inner.scramble(x, dim)
    }
}

/// The battery, configured: base, width, claim, level and the name in the report.
#[derive(Debug, Clone)]
pub struct Battery {
    base: PowerOfTwoBase,
    width: Width,
    claim: Claim,
    level: Level,
    name: String,
}

impl Battery {
    /// A battery for scramblers in `base` on `width`-bit words, claiming Owen at quick level.
    pub fn new(base: PowerOfTwoBase, width: Width) -> Battery {
        Battery {
            base,
            width,
            claim: Claim::OWEN,
            level: Level::Quick,
            name: "scrambler under test".into(),
        }
    }

    /// What the scrambler claims (default [`Claim::OWEN`]); only claimed laws get verdicts.
    pub fn claims(mut self, claim: Claim) -> Battery {
        self.claim = claim;
        self
    }

    /// How much to run (default [`Level::Quick`]).
    pub fn level(mut self, level: Level) -> Battery {
        self.level = level;
        self
    }

    /// The name used in the report.
    pub fn name(mut self, name: impl Into<String>) -> Battery {
        self.name = name.into();
        self
    }

    /// Runs every check on the scramblers `make(seed)` builds and returns the report.
    pub fn run<S, F>(&self, make: F) -> ImplReport
    where
        S: TestScrambler + 'static,
        F: Fn(u64) -> S + Send + Sync + 'static,
    {
        let (base, width, claim, name) = (self.base, self.width, self.claim, self.name.clone());
        let build = move |seed: u64| {
            Ok(Box::new(Adapter {
                inner: make(seed),
                base,
                width,
                claim,
                name: name.clone(),
            }) as Box<dyn Scrambler>)
        };
        let candidate = Candidate::from_builder(self.name.clone(), self.claim, Box::new(build))
            .expect("building a test scrambler cannot fail");
        check_candidate(&candidate, self.level, 1)
    }

    /// Runs the battery and panics with a report naming every failing check (and its worst
    /// sub-test: depth, nodes, p-value) when one fails.
    pub fn assert<S, F>(&self, make: F)
    where
        S: TestScrambler + 'static,
        F: Fn(u64) -> S + Send + Sync + 'static,
    {
        let report = self.run(make);
        if report.failed() {
            panic!("{}", failure_text(&report));
        }
    }
}

/// The panic message of [`Battery::assert`]: one line per failing check, then the profile.
pub fn failure_text(report: &ImplReport) -> String {
    let mut text = format!(
        "gartowen battery: {} (claim {}) failed:\n",
        report.name, report.claim
    );
    for c in report.checks.iter().filter(|c| c.verdict == Verdict::Fail) {
        text += &format!("  FAIL {}: {}\n", c.check, c.detail);
    }
    for (family, row) in &report.profile {
        text += &format!("  profile {family:<11} depth 0→ {row}\n");
    }
    text
}
