//! Where a battery run's time goes (`gartowen verify --profile`): seconds and words scrambled
//! per implementation and check, the slowest entries first, with totals per check and per
//! implementation. The law checks' seconds are their share of the shared evaluation pass (by
//! words) plus their own analysis and passes ([`crate::law_runner::FamilyRun`]).

use crate::verdict::ImplReport;

/// One (implementation, check) entry of the profile.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileEntry {
    /// Implementation name.
    pub implementation: String,
    /// Check name.
    pub check: String,
    /// Wall seconds.
    pub seconds: f64,
    /// Words scrambled, where counted.
    pub words: Option<u64>,
}

/// Every (implementation, check) entry of `reports`, slowest first (ties in report order).
pub fn entries(reports: &[ImplReport]) -> Vec<ProfileEntry> {
    let mut out: Vec<ProfileEntry> = reports
        .iter()
        .flat_map(|r| {
            r.checks.iter().map(|c| ProfileEntry {
                implementation: r.name.clone(),
                check: c.check.clone(),
                seconds: c.seconds,
                words: c.words,
            })
        })
        .collect();
    out.sort_by(|a, b| b.seconds.total_cmp(&a.seconds));
    out
}

/// Sums `entries` by `key` (seconds, words where counted), largest first; names in first-seen
/// order break ties.
fn totals(
    entries: &[ProfileEntry],
    key: impl Fn(&ProfileEntry) -> &str,
) -> Vec<(String, f64, u64)> {
    let mut out: Vec<(String, f64, u64)> = Vec::new();
    for e in entries {
        let name = key(e);
        let at = match out.iter().position(|(n, _, _)| n == name) {
            Some(at) => at,
            None => {
                out.push((name.to_string(), 0.0, 0));
                out.len() - 1
            }
        };
        out[at].1 += e.seconds;
        out[at].2 += e.words.unwrap_or(0);
    }
    out.sort_by(|a, b| b.1.total_cmp(&a.1));
    out
}

fn words_text(words: Option<u64>) -> String {
    words.map_or_else(|| "-".into(), |w| w.to_string())
}

/// The profile as text: the `top` slowest entries, then seconds and words per check, then per
/// implementation (the `top` largest), each line `name  seconds  words`.
pub fn render(reports: &[ImplReport], top: usize) -> String {
    let all = entries(reports);
    let total: f64 = all.iter().map(|e| e.seconds).sum();
    let mut out = format!(
        "time profile: {} implementations, {total:.2} s in checks (summed over threads)\n",
        reports.len()
    );
    out.push_str(&format!(
        "  slowest {} (implementation, check): seconds, words scrambled\n",
        top.min(all.len())
    ));
    for e in all.iter().take(top) {
        out.push_str(&format!(
            "    {:<32} {:<12} {:>8.3} s {:>12}\n",
            e.implementation,
            e.check,
            e.seconds,
            words_text(e.words)
        ));
    }
    out.push_str("  per check: seconds, words scrambled\n");
    for (name, seconds, words) in totals(&all, |e| &e.check) {
        out.push_str(&format!("    {name:<45} {seconds:>8.3} s {words:>12}\n"));
    }
    let per_impl = totals(&all, |e| &e.implementation);
    out.push_str(&format!(
        "  per implementation (slowest {}): seconds, words scrambled\n",
        top.min(per_impl.len())
    ));
    for (name, seconds, words) in per_impl.into_iter().take(top) {
        out.push_str(&format!("    {name:<45} {seconds:>8.3} s {words:>12}\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verdict::fixtures;

    fn report(name: &str, checks: &[(&str, f64, Option<u64>)]) -> ImplReport {
        let checks = checks
            .iter()
            .map(|&(check, seconds, words)| fixtures::check(check, seconds, words))
            .collect();
        fixtures::report(0, name, checks)
    }

    #[test]
    fn entries_come_slowest_first_and_totals_add_up() {
        let reports = [
            report(
                "fast",
                &[("nets", 0.5, None), ("node-law", 0.25, Some(100))],
            ),
            report(
                "slow",
                &[("nets", 0.125, None), ("node-law", 2.0, Some(700))],
            ),
        ];
        let e = entries(&reports);
        let order: Vec<(&str, &str)> = e
            .iter()
            .map(|e| (e.implementation.as_str(), e.check.as_str()))
            .collect();
        assert_eq!(
            order,
            [
                ("slow", "node-law"),
                ("fast", "nets"),
                ("fast", "node-law"),
                ("slow", "nets")
            ]
        );
        let by_check = totals(&e, |e| &e.check);
        assert_eq!(
            by_check,
            [
                ("node-law".to_string(), 2.25, 800),
                ("nets".to_string(), 0.625, 0)
            ]
        );
        let text = render(&reports, 1);
        assert!(text.starts_with("time profile: 2 implementations, 2.88 s in checks"));
        assert!(text.contains("slowest 1 (implementation, check)"), "{text}");
        assert!(
            text.contains("slow ") && text.contains("2.000 s          700"),
            "{text}"
        );
        // Only the slowest entry is listed; the per-check lines list every check.
        assert!(!text.contains("0.250 s"), "{text}");
        assert!(
            text.contains("nets") && text.contains("0.625 s            0"),
            "{text}"
        );
        assert!(text.contains("per implementation (slowest 1)"), "{text}");
        assert!(text.contains("2.125 s          700"), "{text}");
    }

    #[test]
    fn uncounted_words_print_as_a_dash() {
        assert_eq!(words_text(None), "-");
        assert_eq!(words_text(Some(12)), "12");
    }
}
