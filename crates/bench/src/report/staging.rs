//! Writing the report all or nothing: staged files moved into place when complete.

use super::*;
use crate::staged::write_staged;

/// Writes report.json, report.md and the figures into `dir`; returns the regressions against
/// `baseline` (empty without one). All or nothing: every file is written into
/// [`staging_dir`] first and moved into `dir` only when all are complete, so a write error
/// (a full disk) leaves `dir` as it was, an earlier report in it intact, and no staging
/// folder behind.
pub fn write_report(
    report: &Report,
    registry: &Registry,
    dir: &Path,
    baseline: Option<&Report>,
) -> Result<Vec<Regression>, ReportError> {
    let regressions = baseline.map(|b| compare(b, report));
    write_staged(dir, |staging| {
        stage_report(report, registry, staging, regressions.as_deref()).map_err(|e| match e {
            ReportError::Io(m) => m,
            other => other.to_string(),
        })
    })
    .map_err(ReportError::Io)?;
    Ok(regressions.unwrap_or_default())
}

/// Writes the figures, report.json and report.md into `staging`; returns the file names.
fn stage_report(
    report: &Report,
    registry: &Registry,
    staging: &Path,
    regressions: Option<&[Regression]>,
) -> Result<Vec<String>, ReportError> {
    let figures = write_figures(report, registry, staging)?;
    let write = |name: &str, text: &str| -> Result<(), ReportError> {
        std::fs::write(staging.join(name), text)
            .map_err(|e| ReportError::Io(format!("cannot write {name}: {e}")))
    };
    write(
        "report.json",
        &serde_json::to_string_pretty(report).expect("serializable"),
    )?;
    write("report.md", &markdown(report, &figures, regressions))?;
    let mut names = figures;
    names.push("report.json".into());
    names.push("report.md".into());
    Ok(names)
}
