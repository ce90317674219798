//! What the battery runs, read from its declared lists: the structure checks, the law
//! families and the level plans (`gartowen verify --list-checks`).

use crate::law_runner::FAMILIES;
use crate::level::{level_table, LevelPlan, LEVEL_PLANS};
use crate::structure::{Stage, STRUCTURE_CHECKS};
use crate::subtest::Requirement;
use serde::Serialize;

/// One check of the listing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ListedCheck {
    /// The check's name in reports.
    pub name: &'static str,
    /// `structure` or `law`.
    pub kind: &'static str,
    /// What a claim must promise for the check to be judged (empty: always judged).
    pub requires: Vec<Requirement>,
    /// What it tests, in one line.
    pub what: &'static str,
}

/// The battery as declared, in report order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Listing {
    /// Every check, in the order reports list them.
    pub checks: Vec<ListedCheck>,
    /// The level plans, smallest level first.
    pub levels: Vec<LevelPlan>,
}

/// The battery's checks in report order (structure before the laws, then the laws, then
/// structure after them) and the level plans.
pub fn listing() -> Listing {
    let structure = |stage: Stage| {
        STRUCTURE_CHECKS
            .iter()
            .filter(move |c| c.stage == stage)
            .map(|c| ListedCheck {
                name: c.name,
                kind: "structure",
                requires: Vec::new(),
                what: c.what,
            })
    };
    let laws = FAMILIES.iter().map(|f| ListedCheck {
        name: f.name(),
        kind: "law",
        requires: f.requires().to_vec(),
        what: f.what(),
    });
    Listing {
        checks: structure(Stage::BeforeLaws)
            .chain(laws)
            .chain(structure(Stage::AfterLaws))
            .collect(),
        levels: LEVEL_PLANS.to_vec(),
    }
}

/// The listing as text: one line per check, then the level table.
pub fn listing_text() -> String {
    let list = listing();
    let width = list.checks.iter().map(|c| c.name.len()).max().unwrap_or(0);
    let mut out = String::from("checks, in report order:\n");
    for c in &list.checks {
        let requires = if c.requires.is_empty() {
            "exact".to_string()
        } else {
            c.requires
                .iter()
                .map(|r| match r {
                    Requirement::Marginal => "marginal",
                    Requirement::Independent => "independent",
                })
                .collect::<Vec<_>>()
                .join("+")
        };
        out.push_str(&format!(
            "  {:<width$}  {:<9}  {:<20}  {}\n",
            c.name, c.kind, requires, c.what
        ));
    }
    out.push_str("\nsizes per level:\n");
    out.push_str(&level_table());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_listing_follows_the_report_order_of_a_run() {
        let names: Vec<&str> = listing().checks.iter().map(|c| c.name).collect();
        assert_eq!(
            names,
            [
                "inverse",
                "injective",
                "function",
                "nested",
                "nets",
                "node-law",
                "pair-law",
                "flip-rank",
                "collisions",
                "pair-lemma",
                "dimensions",
                "expect"
            ]
        );
        let text = listing_text();
        assert!(text.contains("pair-lemma") && text.contains("marginal+independent"));
        assert!(text.contains(&level_table()));
    }
}
