//! Comparing a report with a baseline report.json.

use super::*;

/// One regression against a baseline.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Regression {
    /// What regressed (method and integrand, or scrambler).
    pub what: String,
    /// The baseline value.
    pub before: f64,
    /// This run's value.
    pub after: f64,
    /// The threshold that was crossed, in words.
    pub rule: String,
}

/// How many (method, integrand) curves and scramblers' speeds `now` shares with `baseline`:
/// the rows [`compare`] can judge. Zero means a baseline that compares nothing.
pub fn comparable_rows(baseline: &Report, now: &Report) -> usize {
    let curves = now
        .methods
        .iter()
        .filter_map(|m| {
            baseline
                .methods
                .iter()
                .find(|o| o.label == m.label)
                .map(|o| (m, o))
        })
        .map(|(m, o)| {
            m.curves
                .iter()
                .filter(|c| o.curves.iter().any(|oc| oc.integrand == c.integrand))
                .count()
        })
        .sum::<usize>();
    let speeds = now
        .speed
        .iter()
        .filter(|s| baseline.speed.iter().any(|o| o.scrambler == s.scrambler))
        .count();
    curves + speeds
}

/// Compares `now` with `baseline`: slopes, RMSE at the largest common N, and speed ratios.
pub fn compare(baseline: &Report, now: &Report) -> Vec<Regression> {
    let t = &now.thresholds;
    let mut out = Vec::new();
    for m in &now.methods {
        let Some(old) = baseline.methods.iter().find(|o| o.label == m.label) else {
            continue;
        };
        for c in &m.curves {
            let Some(oc) = old.curves.iter().find(|o| o.integrand == c.integrand) else {
                continue;
            };
            if let (Some(a), Some(b)) = (oc.slope, c.slope) {
                if b > a + t.slope {
                    out.push(Regression {
                        what: format!("{} on {}: slope", m.label, c.integrand),
                        before: a,
                        after: b,
                        rule: format!("slope rose by more than {}", t.slope),
                    });
                }
            }
            let common =
                c.n.iter()
                    .zip(&c.rmse)
                    .filter_map(|(n, r)| {
                        oc.n.iter()
                            .position(|m| m == n)
                            .map(|k| (*n, *r, oc.rmse[k]))
                    })
                    .max_by_key(|x| x.0);
            if let Some((n, r, or)) = common {
                if r > or * t.rmse_factor {
                    out.push(Regression {
                        what: format!("{} on {}: RMSE at N = {n}", m.label, c.integrand),
                        before: or,
                        after: r,
                        rule: format!("RMSE grew by more than ×{:.3}", t.rmse_factor),
                    });
                }
            }
        }
    }
    if let (Some(old), Some(new)) = (&baseline.scene, &now.scene) {
        out.extend(
            crate::scene::report::compare_scenes(old, new)
                .into_iter()
                .map(|r| Regression {
                    what: r.what,
                    before: r.before,
                    after: r.after,
                    rule: format!(
                        "RMSE grew by more than ×{} and {} standard errors",
                        crate::scene::report::REGRESSION_FACTOR,
                        crate::scene::report::REGRESSION_Z
                    ),
                }),
        );
    }
    for s in &now.speed {
        if let Some(o) = baseline.speed.iter().find(|o| o.scrambler == s.scrambler) {
            let allowed = crate::speed::allowed_growth(o, s, t.speed_factor, t.speed_z);
            if s.ratio_to_lk_hash > o.ratio_to_lk_hash * allowed {
                out.push(Regression {
                    what: format!("{}: time per coordinate relative to lk-hash", s.scrambler),
                    before: o.ratio_to_lk_hash,
                    after: s.ratio_to_lk_hash,
                    rule: format!(
                        "median ratio grew by more than ×{allowed:.3} (×{} widened by {} \
                         standard errors of the two medians)",
                        t.speed_factor, t.speed_z
                    ),
                });
            }
        }
    }
    out
}

/// Reads a baseline report.json.
pub fn read_baseline(path: &Path) -> Result<Report, ReportError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| ReportError::Baseline(format!("cannot read {}: {e}", path.display())))?;
    let v: serde_json::Value = serde_json::from_str(&text)
        .map_err(|e| ReportError::Baseline(format!("{}: not JSON: {e}", path.display())))?;
    if v["schema"] != REPORT_SCHEMA || v["schema_version"] != REPORT_VERSION {
        return Err(ReportError::Baseline(format!(
            "{}: not a {REPORT_SCHEMA} version {REPORT_VERSION} file",
            path.display()
        )));
    }
    let report: Report = serde_json::from_value(v)
        .map_err(|e| ReportError::Baseline(format!("{}: {e}", path.display())))?;
    // A baseline that compares nothing would pass every run: refuse it.
    if report.methods.iter().all(|m| m.curves.is_empty()) && report.speed.is_empty() {
        return Err(ReportError::Baseline(format!(
            "{}: no error curves and no speed rows: nothing to compare",
            path.display()
        )));
    }
    Ok(report)
}
