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
    // Sub-tests that did not run count towards no level.
    let ran = || {
        families
            .iter()
            .flat_map(|(_, t)| t.iter())
            .filter(|t| t.ran())
    };
    let claimed_tests = ran().filter(|t| t.requires.claimed_by(claim)).count();
    let all_tests = ran().count();
    let alpha = bonferroni(FAMILY_ALPHA, judged.max(1) * claimed_tests.max(1));
    // Measured-only sub-tests are flagged at the level they would have had if claimed.
    let measure_alpha = bonferroni(FAMILY_ALPHA, judged.max(1) * all_tests.max(1));
    families
        .into_iter()
        .map(|(family, tests)| judge_family(family, tests, claim, (alpha, measure_alpha), seconds))
        .collect()
}

/// Why the sub-tests that did not run did not, each reason once, in order.
fn not_run_reasons(tests: &[SubTest]) -> Vec<&str> {
    let mut reasons: Vec<&str> = Vec::new();
    for why in tests.iter().filter_map(|t| t.not_run.as_deref()) {
        if !reasons.contains(&why) {
            reasons.push(why);
        }
    }
    reasons
}

/// One family's check from its sub-tests, at the run's per-test levels (claimed, measured).
fn judge_family(
    family: &'static str,
    mut tests: Vec<SubTest>,
    claim: Claim,
    (alpha, measure_alpha): (f64, f64),
    seconds: f64,
) -> CheckResult {
    let mut judged_fail = false;
    let mut any_claimed = false;
    for t in tests.iter_mut().filter(|t| t.ran()) {
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
    for t in tests.iter_mut().filter(|t| !t.ran()) {
        t.deviates = false;
    }
    // The worst sub-test among those the verdict rests on (the judged ones when the claim
    // covers any): a pass is never explained by a sub-test it did not judge.
    let judged_of = |t: &SubTest| t.ran() && (!any_claimed || t.requires.claimed_by(claim));
    let worst = tests
        .iter()
        .filter(|t| judged_of(t))
        .min_by(|a, b| a.p_value.total_cmp(&b.p_value))
        .cloned();
    let count = |judged: bool| {
        let of: Vec<&SubTest> = tests
            .iter()
            .filter(|t| t.ran() && judged_of(t) == judged)
            .collect();
        (of.iter().filter(|t| t.deviates).count(), of.len())
    };
    let (deviations, judged_tests) = count(true);
    let (measured_deviations, measured_tests) = count(false);
    let reasons = not_run_reasons(&tests);
    let not_run = tests.len() - tests.iter().filter(|t| t.ran()).count();
    let verdict = if tests.is_empty() {
        Verdict::Skipped
    } else if worst.is_none() {
        Verdict::NotRun
    } else if !any_claimed {
        Verdict::Measured
    } else if judged_fail {
        Verdict::Fail
    } else {
        Verdict::Pass
    };
    let mut detail = match &worst {
        None if not_run > 0 => format!("not run: {}", reasons.join("; ")),
        None => "not applicable".to_string(),
        Some(w) => {
            let mut d = format!(
                "{}: {} of {} {}sub-tests deviate at α' = {:.1e}; worst: {} (p {}; {})",
                match verdict {
                    Verdict::Pass => "no deviation detected at this power",
                    Verdict::Fail => "deviation",
                    _ => "not claimed, measured",
                },
                deviations,
                judged_tests,
                if any_claimed && measured_tests > 0 {
                    "judged "
                } else {
                    ""
                },
                if any_claimed { alpha } else { measure_alpha },
                w.name,
                p_words(w.p_value),
                w.power
            );
            if measured_tests > 0 {
                d.push_str(&format!(
                    "; not claimed, measured: {measured_deviations} of {measured_tests} \
                     deviate at α' = {measure_alpha:.1e}"
                ));
            }
            d
        }
    };
    if worst.is_some() && not_run > 0 {
        detail.push_str(&format!(
            "; not run: {not_run} of {} sub-tests ({})",
            tests.len(),
            reasons.join("; ")
        ));
    }
    CheckResult {
        check: family.into(),
        verdict,
        detail,
        value: worst.as_ref().map(|w| w.statistic),
        seconds,
        words: None,
        p_value: worst.as_ref().map(|w| w.p_value),
        alpha: Some(if any_claimed { alpha } else { measure_alpha }),
        tests,
    }
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
                    } else if at.iter().any(|t| !t.ran()) {
                        '?'
                    } else {
                        '.'
                    }
                })
                .collect();
            (c.check.clone(), row)
        })
        .collect()
}

/// A p-value for people: "= 3.20e-5", and "< 1e-300" below 1e-300, where a double keeps no
/// meaningful digits (the tail probabilities underflow to 0 or to subnormals there).
pub fn p_words(p: f64) -> String {
    if p < 1e-300 {
        "< 1e-300".to_string()
    } else {
        format!("= {p:.2e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subtest::Requirement;
    use gartowen_core::NodeGroup;

    #[test]
    fn p_values_below_1e_300_are_said_as_a_bound() {
        assert_eq!(p_words(3.2e-5), "= 3.20e-5");
        assert_eq!(p_words(1e-300), "= 1.00e-300");
        assert_eq!(p_words(1.3e-318), "< 1e-300");
        assert_eq!(p_words(0.0), "< 1e-300");
    }

    fn sub(name: &str, requires: Requirement, p_value: f64) -> SubTest {
        SubTest {
            name: name.into(),
            depth: Some(0),
            requires,
            statistic: 1.0,
            p_value,
            n: 100,
            dof: None,
            power: "exact".into(),
            deviates: false,
            not_run: None,
        }
    }

    #[test]
    fn a_pass_is_explained_by_the_sub_tests_it_judged_not_by_measured_ones() {
        let tests = vec![
            sub("marginal", Requirement::Marginal, 0.5),
            sub("joint", Requirement::Independent, 0.0),
        ];
        let claim = Claim::marginal(NodeGroup::Symmetric);
        let c = &judge_families(vec![("family", tests.clone())], claim, 1, 0.0)[0];
        assert_eq!(c.verdict, Verdict::Pass);
        assert_eq!(c.p_value, Some(0.5), "the worst judged sub-test");
        assert!(
            c.detail.starts_with(
                "no deviation detected at this power: 0 of 1 judged sub-tests deviate"
            ),
            "{}",
            c.detail
        );
        assert!(c.detail.contains("worst: marginal"), "{}", c.detail);
        assert!(
            c.detail.contains("not claimed, measured: 1 of 1 deviate"),
            "{}",
            c.detail
        );
        // Claimed in full, the same sub-tests fail, and the worst is the joint one.
        let c = &judge_families(vec![("family", tests.clone())], Claim::OWEN, 1, 0.0)[0];
        assert_eq!(c.verdict, Verdict::Fail);
        assert_eq!(c.p_value, Some(0.0));
        assert!(
            c.detail.starts_with("deviation: 1 of 2 sub-tests deviate"),
            "{}",
            c.detail
        );
        assert!(!c.detail.contains("measured"), "{}", c.detail);
        // Claimed not at all: measured, every sub-test counted.
        let c = &judge_families(vec![("family", tests)], Claim::NESTED, 1, 0.0)[0];
        assert_eq!(c.verdict, Verdict::Measured);
        assert!(
            c.detail
                .starts_with("not claimed, measured: 1 of 2 sub-tests deviate"),
            "{}",
            c.detail
        );
    }

    #[test]
    fn sub_tests_that_did_not_run_count_towards_no_level_and_show_as_unmeasured() {
        let why = "needs dimension 7, beyond the 4 served";
        let gone = |name: &str| {
            let mut t = SubTest::not_run(name.into(), Some(1), Requirement::Marginal, why);
            // Even a stray p-value of 0 on a sub-test that did not run is no deviation.
            t.p_value = 0.0;
            t
        };
        let families = vec![
            ("ran", vec![sub("a", Requirement::Marginal, 0.5), gone("b")]),
            ("none", vec![gone("c"), gone("d")]),
            ("all", vec![sub("e", Requirement::Independent, 0.5)]),
            ("empty", vec![]),
        ];
        let claim = Claim::marginal(NodeGroup::Symmetric);
        let checks = judge_families(families, claim, 1, 0.0);
        // A family that ran in full, or had nothing to run, says nothing of "not run".
        assert!(
            !checks[2].detail.contains("not run"),
            "{}",
            checks[2].detail
        );
        assert_eq!(checks[3].verdict, Verdict::Skipped);
        assert_eq!(checks[3].detail, "not applicable");
        // One claimed sub-test ran: α' = 1e-3 / 1.
        assert_eq!(checks[0].alpha, Some(FAMILY_ALPHA));
        assert_eq!(checks[0].verdict, Verdict::Pass);
        assert!(
            checks[0]
                .detail
                .ends_with(&format!("; not run: 1 of 2 sub-tests ({why})")),
            "{}",
            checks[0].detail
        );
        assert!(!checks[0].tests[1].deviates);
        assert_eq!(checks[1].verdict, Verdict::NotRun);
        assert_eq!(checks[1].detail, format!("not run: {why}"));
        assert_eq!((checks[1].p_value, checks[1].value), (None, None));
        let rows = profile(&checks);
        assert_eq!(rows[0], ("ran".to_string(), ".?".to_string()));
        assert_eq!(rows[1], ("none".to_string(), "-?".to_string()));
    }

    #[test]
    fn the_level_is_split_over_implementations_times_sub_tests_and_p_at_the_level_passes() {
        // 3 implementations × 2 claimed sub-tests: α' = 1e-3 / 6 (not / 5).
        let alpha = FAMILY_ALPHA / 6.0;
        let tests = vec![
            sub("at the level", Requirement::Marginal, alpha),
            sub("just below", Requirement::Marginal, alpha * 0.999),
            sub("unclaimed", Requirement::Independent, 0.5),
        ];
        let claim = Claim::marginal(NodeGroup::Symmetric);
        let c = &judge_families(vec![("family", tests)], claim, 3, 0.0)[0];
        assert_eq!(c.alpha, Some(alpha));
        // p = α' is no deviation (p < α' is), p just below it is.
        assert!(!c.tests[0].deviates && c.tests[1].deviates);
        // Measured-only sub-tests are flagged at 1e-3 / (3 × 3), the level they would have had.
        assert!(
            c.detail
                .contains(&format!("at α' = {:.1e}", FAMILY_ALPHA / 9.0)),
            "{}",
            c.detail
        );
    }
}
