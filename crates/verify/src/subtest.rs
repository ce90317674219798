//! What every law sub-test reports, and which part of a claim it judges.

use gartowen_core::Claim;
use serde::{Deserialize, Serialize};

/// The part of a claim a sub-test judges: it gets a verdict only when the implementation
/// claims it, and is measured otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Requirement {
    /// A law for each node permutation on its own (or for distinct dimensions).
    Marginal,
    /// Independence of distinct nodes, depths and dimensions.
    Independent,
}

impl Requirement {
    /// Whether `claim` promises what this requirement tests.
    pub fn claimed_by(self, claim: Claim) -> bool {
        match self {
            Requirement::Marginal => claim.marginal.is_some(),
            Requirement::Independent => claim.marginal.is_some() && claim.independent,
        }
    }
}

/// A number that JSON may hold as `null` (serde_json's NaN).
fn nan_if_null<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
}

/// One statistical (or exact) test inside a check family.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SubTest {
    /// What was tested, e.g. `siblings at depth 3 (0x5.3.1 | 0x5.3.7)`.
    pub name: String,
    /// The tree depth it concerns (for the per-depth profile), if any.
    pub depth: Option<u32>,
    /// What claim it judges.
    pub requires: Requirement,
    /// The statistic (χ², collision count, rank deficiency, violations). NaN when nothing
    /// was measured (a failed external program); JSON writes NaN as `null` and reads it back.
    #[serde(deserialize_with = "nan_if_null")]
    pub statistic: f64,
    /// The p-value under the claimed law (an upper bound for exact tests); NaN as above.
    #[serde(deserialize_with = "nan_if_null")]
    pub p_value: f64,
    /// Observations (seeds, nodes or pairs).
    pub n: u64,
    /// χ² degrees of freedom, when the test is a χ² test (its power is then stated as the
    /// smallest Cohen's w detected at power 0.9).
    pub dof: Option<usize>,
    /// What an exact test detects, in words (for χ² tests this is filled in by the battery).
    pub power: String,
    /// Whether p fell below the per-test level (filled in by the battery).
    #[serde(default)]
    pub deviates: bool,
    /// Why nothing was measured, when nothing was (`needs dimension 63`, `external program
    /// failed: …`): such a sub-test counts towards no level and no verdict.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub not_run: Option<String>,
}

impl SubTest {
    /// A χ² sub-test.
    pub fn chi(
        name: String,
        depth: Option<u32>,
        requires: Requirement,
        c: crate::stats::ChiSquare,
    ) -> SubTest {
        SubTest {
            name,
            depth,
            requires,
            statistic: c.statistic,
            p_value: c.p_value,
            n: c.n,
            dof: Some(c.dof),
            power: String::new(),
            deviates: false,
            not_run: None,
        }
    }

    /// A sub-test that could not run, with why (its statistic and p-value are NaN).
    pub fn not_run(
        name: String,
        depth: Option<u32>,
        requires: Requirement,
        why: impl Into<String>,
    ) -> SubTest {
        SubTest {
            name,
            depth,
            requires,
            statistic: f64::NAN,
            p_value: f64::NAN,
            n: 0,
            dof: None,
            power: String::new(),
            deviates: false,
            not_run: Some(why.into()),
        }
    }

    /// Whether it measured something.
    pub fn ran(&self) -> bool {
        self.not_run.is_none()
    }
}
