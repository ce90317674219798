//! The level a verify certificate names, held to the sizes its sub-tests record: relabelling a
//! quick run `full` (and its `node_law_seeds` with it) leaves n = 2000 per node, which only
//! quick draws; a full run relabelled quick keeps n = 10,000 and its depths past 12.

use super::{refuse, AuditError, EXTERNAL_FAILURE};
use crate::level::Level;
use crate::verdict::ImplReport;

/// The law families whose sub-tests observe every law seed (n = the level's law seeds at
/// most; the largest n of a family that ran is exactly that).
const PER_SEED_FAMILIES: [&str; 3] = ["node-law", "pair-law", "pair-lemma"];

/// Checks every report's per-seed sub-tests against `level`'s law seeds and its deepest
/// depth; names `parameters.level` when they disagree.
pub(super) fn sizes_match_level(reports: &[ImplReport], level: Level) -> Result<(), AuditError> {
    let plan = level.plan();
    let seeds = plan.law_seeds;
    for (k, r) in reports.iter().enumerate() {
        for (i, c) in r.checks.iter().enumerate() {
            if !PER_SEED_FAMILIES.contains(&c.check.as_str())
                || c.detail.starts_with(EXTERNAL_FAILURE)
            {
                continue;
            }
            let ran: Vec<_> = c.tests.iter().filter(|t| t.ran()).collect();
            let Some(most) = ran.iter().map(|t| t.n).max() else {
                continue;
            };
            let at = format!("result.implementations[{k}].checks[{i}]");
            if most != seeds {
                return Err(refuse(
                    "parameters.level",
                    format!(
                        "{}, which draws {seeds} seeds per law, but {at} ('{}') observed at \
                         most n = {most}{}",
                        level.name(),
                        c.check,
                        level_of_seeds(most)
                            .map(|l| format!(", as level {} draws", l.name()))
                            .unwrap_or_default()
                    ),
                ));
            }
            let deepest = ran.iter().filter_map(|t| t.depth).max().unwrap_or(0);
            if c.check == "node-law" && deepest > plan.max_depth {
                return Err(refuse(
                    "parameters.level",
                    format!(
                        "{}, which tests depths to {}, but {at} tested depth {deepest}",
                        level.name(),
                        plan.max_depth
                    ),
                ));
            }
        }
    }
    Ok(())
}

fn level_of_seeds(n: u64) -> Option<Level> {
    Level::ALL.into_iter().find(|l| l.plan().law_seeds == n)
}
