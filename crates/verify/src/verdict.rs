//! What the battery reports: a check's verdict, its result and the results of one
//! implementation. Vocabulary only: the checks themselves live in [`crate::structure`] and the
//! law families.

use crate::subtest::SubTest;
use serde::Serialize;

/// A check's outcome.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// The property holds.
    Pass,
    /// The property is violated.
    Fail,
    /// A measured value without a verdict (no claim to judge).
    Measured,
    /// Not applicable (e.g. no sequence in this base).
    Skipped,
    /// Could not run: it needs more than the implementation serves (a dimension beyond
    /// `--max-dims`). The detail says what it needed.
    #[serde(rename = "not-run")]
    NotRun,
}

impl Verdict {
    /// The word reports print for it (`pass`, `FAIL`, `measured`, `skipped`, `not run`).
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "FAIL",
            Verdict::Measured => "measured",
            Verdict::Skipped => "skipped",
            Verdict::NotRun => "not run",
        }
    }
}

/// One check of one implementation.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct CheckResult {
    /// Check name.
    pub check: String,
    /// Outcome.
    pub verdict: Verdict,
    /// What was found, in words (the failing node or box, the measured distance).
    pub detail: String,
    /// The measured value where there is one (the worst sub-test's statistic for the laws).
    pub value: Option<f64>,
    /// Wall time in seconds. The law checks share one evaluation pass over the seeds: each
    /// gets the share of it its words took, plus its own analysis and passes.
    pub seconds: f64,
    /// Words scrambled for this check (law checks; `None` where not counted).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub words: Option<u64>,
    /// The smallest p-value of the sub-tests (laws only).
    #[serde(default)]
    pub p_value: Option<f64>,
    /// The per-sub-test level the p-values were compared with (laws only).
    #[serde(default)]
    pub alpha: Option<f64>,
    /// The sub-tests (laws only), each with its statistic, p-value and power.
    #[serde(default)]
    pub tests: Vec<SubTest>,
}

/// All checks of one implementation.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct ImplReport {
    /// Position in the list of implementations verified (restores order when shards merge).
    pub index: usize,
    /// Registry name.
    pub name: String,
    /// Scrambling base.
    pub base: u32,
    /// Whether it claims nested uniformity.
    pub claims_nested_uniform: bool,
    /// What it claims (`nested`, `marginal:GROUP`, `independent:GROUP`, `owen`).
    #[serde(default)]
    pub claim: String,
    /// The checks.
    pub checks: Vec<CheckResult>,
    /// Per law family, one character per depth 0, 1, …: `.` no deviation detected, `x` a
    /// deviation at the per-test level, `?` not measured (the program failed, or a sub-test
    /// needed more dimensions than served), `-` not tested (the "how close to Owen" profile).
    #[serde(default)]
    pub profile: Vec<(String, String)>,
}

impl CheckResult {
    /// The result of check `name` from a structure-style outcome that took `seconds` (no
    /// sub-tests, levels or words).
    pub fn from_outcome(name: &str, outcome: Outcome, seconds: f64) -> CheckResult {
        CheckResult {
            check: name.into(),
            verdict: outcome.verdict,
            detail: outcome.detail,
            value: outcome.value,
            seconds,
            words: None,
            p_value: None,
            alpha: None,
            tests: Vec::new(),
        }
    }
}

impl ImplReport {
    /// Whether any check failed.
    pub fn failed(&self) -> bool {
        self.checks.iter().any(|c| c.verdict == Verdict::Fail)
    }
}

/// What a structure check found: its verdict, the finding in words and the measured value
/// where there is one.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The verdict.
    pub verdict: Verdict,
    /// The finding, in words (the failing word, node or box; what was checked).
    pub detail: String,
    /// The measured value, where there is one.
    pub value: Option<f64>,
}

impl Outcome {
    /// A passing outcome described by `detail`.
    pub fn pass(detail: impl Into<String>) -> Outcome {
        Outcome {
            verdict: Verdict::Pass,
            detail: detail.into(),
            value: None,
        }
    }

    /// A failing outcome described by `detail`.
    pub fn fail(detail: impl Into<String>) -> Outcome {
        Outcome {
            verdict: Verdict::Fail,
            detail: detail.into(),
            value: None,
        }
    }

    /// A skipped check, with the reason.
    pub fn skipped(reason: impl Into<String>) -> Outcome {
        Outcome {
            verdict: Verdict::Skipped,
            detail: reason.into(),
            value: None,
        }
    }

    /// A check that could not run, with what it needed (`needs dimension 7`).
    pub fn not_run(needed: impl Into<String>) -> Outcome {
        Outcome {
            verdict: Verdict::NotRun,
            detail: format!("not run: {}", needed.into()),
            value: None,
        }
    }
}

/// Reports built by hand for the tests of other modules (merging, the time profile).
#[cfg(test)]
pub(crate) mod fixtures {
    use super::{CheckResult, ImplReport, Verdict};

    /// A passing check `name` that took `seconds` and scrambled `words`.
    pub fn check(name: &str, seconds: f64, words: Option<u64>) -> CheckResult {
        CheckResult {
            check: name.into(),
            verdict: Verdict::Pass,
            detail: String::new(),
            value: None,
            seconds,
            words,
            p_value: None,
            alpha: None,
            tests: Vec::new(),
        }
    }

    /// Implementation `name` at position `index` with `checks`, claiming `nested`.
    pub fn report(index: usize, name: &str, checks: Vec<CheckResult>) -> ImplReport {
        ImplReport {
            index,
            name: name.into(),
            base: 2,
            claims_nested_uniform: false,
            claim: "nested".into(),
            checks,
            profile: Vec::new(),
        }
    }
}
