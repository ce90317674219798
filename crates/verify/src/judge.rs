//! Judging the law families: the Bonferroni split of the family-wise level over the judged
//! sub-tests, a verdict per family (only where the claim covers it), and the per-depth
//! profile.

use crate::stats::{bonferroni, min_detectable_w, FAMILY_ALPHA};
use crate::subtest::SubTest;
use crate::verdict::{CheckResult, Verdict};
use gartowen_core::Claim;

/// Turns each law family's sub-tests into a check: the per-test level is
/// [`FAMILY_ALPHA`] / (judged implementations × judged sub-tests), and a family gets a verdict
/// only if the claim covers every sub-test that deviates (others are measured).
pub fn judge_families(
    families: Vec<(&'static str, Vec<SubTest>)>,
    claim: Claim,
    judged: usize,
    seconds: f64,
) -> Vec<CheckResult> {
    let claimed_tests: usize = families
        .iter()
        .flat_map(|(_, t)| t.iter())
        .filter(|t| t.requires.claimed_by(claim))
        .count();
    let all_tests: usize = families.iter().map(|(_, t)| t.len()).sum();
    let alpha = bonferroni(FAMILY_ALPHA, judged.max(1) * claimed_tests.max(1));
    // Measured-only sub-tests are flagged at the level they would have had if claimed.
    let measure_alpha = bonferroni(FAMILY_ALPHA, judged.max(1) * all_tests.max(1));
    families
        .into_iter()
        .map(|(family, mut tests)| {
            let mut judged_fail = false;
            let mut any_claimed = false;
            for t in &mut tests {
                let claimed = t.requires.claimed_by(claim);
                any_claimed |= claimed;
                let a = if claimed { alpha } else { measure_alpha };
                t.deviates = t.p_value < a;
                judged_fail |= claimed && t.deviates;
                if let Some(dof) = t.dof {
                    t.power = format!(
                        "χ² {dof} dof, n = {}: detects Cohen's w ≥ {:.3} at power 0.9",
                        t.n,
                        min_detectable_w(dof, t.n, a)
                    );
                }
            }
            let worst = tests
                .iter()
                .min_by(|a, b| a.p_value.total_cmp(&b.p_value))
                .cloned();
            let deviations = tests.iter().filter(|t| t.deviates).count();
            let verdict = if !any_claimed {
                Verdict::Measured
            } else if judged_fail {
                Verdict::Fail
            } else {
                Verdict::Pass
            };
            let detail = match &worst {
                None => "not applicable".to_string(),
                Some(w) => format!(
                    "{}: {} of {} sub-tests deviate at α' = {:.1e}; worst: {} (p = {:.2e}; {})",
                    if verdict == Verdict::Pass {
                        "no deviation detected at this power"
                    } else if verdict == Verdict::Fail {
                        "deviation"
                    } else {
                        "not claimed, measured"
                    },
                    deviations,
                    tests.len(),
                    if any_claimed { alpha } else { measure_alpha },
                    w.name,
                    w.p_value,
                    w.power
                ),
            };
            CheckResult {
                check: family.into(),
                verdict: if tests.is_empty() {
                    Verdict::Skipped
                } else {
                    verdict
                },
                detail,
                value: worst.as_ref().map(|w| w.statistic),
                seconds,
                p_value: worst.as_ref().map(|w| w.p_value),
                alpha: Some(if any_claimed { alpha } else { measure_alpha }),
                tests,
            }
        })
        .collect()
}

/// The per-depth profile of the law checks: one string per family, a character per depth.
pub fn profile(checks: &[CheckResult]) -> Vec<(String, String)> {
    let depth_max = checks
        .iter()
        .flat_map(|c| c.tests.iter())
        .filter_map(|t| t.depth)
        .max();
    let Some(depth_max) = depth_max else {
        return Vec::new();
    };
    checks
        .iter()
        .filter(|c| !c.tests.is_empty())
        .map(|c| {
            let row: String = (0..=depth_max)
                .map(|d| {
                    let at: Vec<&SubTest> = c.tests.iter().filter(|t| t.depth == Some(d)).collect();
                    if at.is_empty() {
                        '-'
                    } else if at.iter().any(|t| t.deviates) {
                        'x'
                    } else {
                        '.'
                    }
                })
                .collect();
            (c.check.clone(), row)
        })
        .collect()
}
