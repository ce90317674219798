//! JUnit XML for CI dashboards (`--junit FILE` on `verify`, `check` and `inspect`): one
//! `<testsuite>` per implementation or file, one `<testcase>` per check, a `<failure>` with the
//! message and the measured value for each failing check, and the certificate's path in
//! `<system-out>`. Written with the `quick-junit` crate.

use crate::verdict::{CheckResult, ImplReport, Verdict};
use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};
use std::time::Duration;

/// One test case: its name, outcome and wall time.
#[derive(Debug, Clone, PartialEq)]
pub struct JunitCase {
    /// The check's name.
    pub name: String,
    /// None: passed (or measured); Some((message, details)): failed.
    pub failure: Option<(String, String)>,
    /// Not run (not applicable).
    pub skipped: bool,
    /// What was measured, for `<system-out>`.
    pub output: String,
    /// Wall time in seconds.
    pub seconds: f64,
}

/// One suite: an implementation or a file, its cases, and the certificate path if written.
#[derive(Debug, Clone, PartialEq)]
pub struct JunitSuite {
    /// The implementation or file.
    pub name: String,
    /// The cases.
    pub cases: Vec<JunitCase>,
    /// The certificate written for this run, if any.
    pub certificate: Option<String>,
}

/// A case per check (measured checks pass, with their value in `<system-out>`; skipped and
/// not-run ones are skipped; a failure carries the measured value, p-value and level).
pub fn check_cases(checks: &[CheckResult]) -> Vec<JunitCase> {
    checks
        .iter()
        .map(|c| JunitCase {
            name: c.check.clone(),
            failure: (c.verdict == Verdict::Fail).then(|| {
                (
                    format!("{} failed: {}", c.check, c.detail),
                    format!(
                        "measured value: {}; p-value: {}; level: {}",
                        c.value.map_or("none".into(), |v| format!("{v}")),
                        c.p_value.map_or("none".into(), |v| format!("{v:e}")),
                        c.alpha.map_or("none".into(), |v| format!("{v:e}")),
                    ),
                )
            }),
            skipped: matches!(c.verdict, Verdict::Skipped | Verdict::NotRun),
            output: format!("{:?}: {}", c.verdict, c.detail),
            seconds: c.seconds,
        })
        .collect()
}

/// The suites of a verify run: one per implementation, a case per check.
pub fn verify_suites(reports: &[ImplReport], certificate: Option<&str>) -> Vec<JunitSuite> {
    reports
        .iter()
        .map(|r| JunitSuite {
            name: format!("{} (claim {})", r.name, r.claim),
            certificate: certificate.map(str::to_string),
            cases: check_cases(&r.checks),
        })
        .collect()
}

/// The JUnit XML document of `suites` under the run name `run`.
pub fn to_xml(run: &str, suites: &[JunitSuite]) -> String {
    let mut report = Report::new(run);
    for s in suites {
        let mut suite = TestSuite::new(s.name.as_str());
        if let Some(c) = &s.certificate {
            suite.set_system_out(format!("certificate: {c}"));
        }
        for c in &s.cases {
            let status = match &c.failure {
                Some((message, details)) => {
                    let mut st = TestCaseStatus::non_success(NonSuccessKind::Failure);
                    st.set_message(message.as_str());
                    st.set_description(details.as_str());
                    st
                }
                None if c.skipped => TestCaseStatus::skipped(),
                None => TestCaseStatus::success(),
            };
            let mut case = TestCase::new(c.name.as_str(), status);
            case.set_classname(s.name.as_str());
            case.set_time(Duration::from_secs_f64(c.seconds.max(0.0)));
            case.set_system_out(c.output.as_str());
            suite.add_test_case(case);
        }
        report.add_test_suite(suite);
    }
    report.to_string().expect("JUnit XML serializes")
}
