//! How much the battery runs: the three levels and their plan, every size the battery uses at
//! each level in one table ([`LEVEL_PLANS`]). `docs/battery.md`'s level table is
//! [`level_table`]'s output (a test keeps them equal).

use serde::{Deserialize, Serialize};

/// How much to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// About 6 s for the whole registry on 2 cores (the CI gate).
    Quick,
    /// Larger samples and deeper nets.
    Full,
    /// Long: the largest samples and nets; meant to be sharded.
    Exhaustive,
}

impl Level {
    /// Every level, smallest first.
    pub const ALL: [Level; 3] = [Level::Quick, Level::Full, Level::Exhaustive];

    /// The level's name as the CLI spells it.
    pub fn name(self) -> &'static str {
        Level::NAMES[self as usize]
    }

    /// The sizes of this level.
    pub fn plan(self) -> &'static LevelPlan {
        &LEVEL_PLANS[self as usize]
    }

    /// The names of [`Level::ALL`], in that order.
    pub const NAMES: [&'static str; 3] = ["quick", "full", "exhaustive"];
}

impl std::str::FromStr for Level {
    type Err = gartowen_core::UnknownName;

    /// The level called `s` (`quick`, `full`, `exhaustive`); the error names the choices.
    fn from_str(s: &str) -> Result<Level, Self::Err> {
        gartowen_core::names::parse_name("level", s, &Level::NAMES, &Level::ALL)
    }
}

/// Every size the battery uses at one level (counts of seeds, words, columns; depths in
/// digits of the scrambler's base).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct LevelPlan {
    /// The level this plan is for.
    pub level: Level,
    /// Independent instances (seeds 0, 1, …) of the per-seed laws (`node-law`, `pair-law`,
    /// `pair-lemma`, the root pairs of `dimensions`).
    pub law_seeds: u64,
    /// Deepest tree depth the laws test (capped by the digits a word has).
    pub max_depth: u32,
    /// Most columns (node bits) of the `flip-rank` matrix.
    pub rank_columns: usize,
    /// Most nodes per depth whose subtrees `collisions` compares.
    pub collision_nodes: usize,
    /// Instances `collisions` draws (each compared within itself).
    pub collision_seeds: u64,
    /// Instances the distinct-dimensions test of `dimensions` draws.
    pub distinct_seeds: u64,
    /// Seeded words per supported width that `inverse` round-trips.
    pub inverse_words: u64,
    /// Seeded words per dimension that `injective` maps (external programs).
    pub injective_words: usize,
    /// Words per seed and dimension that `expect` compares with the twin.
    pub twin_words: usize,
    /// log2 of the most points of one net in `nets` (at least m = 2 digits per base).
    pub net_log2_points: u32,
    /// Instances of `--equivalent-to owen`.
    pub equivalence_seeds: u64,
}

/// The plans of [`Level::ALL`], in that order.
pub const LEVEL_PLANS: [LevelPlan; 3] = [
    LevelPlan {
        level: Level::Quick,
        law_seeds: 2000,
        max_depth: 12,
        rank_columns: 1024,
        collision_nodes: 320,
        collision_seeds: 2,
        distinct_seeds: 20,
        inverse_words: 10_000,
        injective_words: 4096,
        twin_words: 512,
        net_log2_points: 12,
        equivalence_seeds: 10_000,
    },
    LevelPlan {
        level: Level::Full,
        law_seeds: 10_000,
        max_depth: 16,
        rank_columns: 2048,
        collision_nodes: 1280,
        collision_seeds: 8,
        distinct_seeds: 100,
        inverse_words: 100_000,
        injective_words: 32_768,
        twin_words: 4096,
        net_log2_points: 16,
        equivalence_seeds: 40_000,
    },
    LevelPlan {
        level: Level::Exhaustive,
        law_seeds: 50_000,
        max_depth: 20,
        rank_columns: 4096,
        collision_nodes: 1280,
        collision_seeds: 8,
        distinct_seeds: 200,
        inverse_words: 100_000,
        injective_words: 32_768,
        twin_words: 4096,
        net_log2_points: 18,
        equivalence_seeds: 100_000,
    },
];

/// One row of the level table: what it sizes and its value per level.
fn rows() -> Vec<(&'static str, [String; 3])> {
    let per = |f: &dyn Fn(&LevelPlan) -> String| -> [String; 3] {
        [f(&LEVEL_PLANS[0]), f(&LEVEL_PLANS[1]), f(&LEVEL_PLANS[2])]
    };
    vec![
        (
            "seeds of the per-seed laws",
            per(&|p| group_digits(p.law_seeds)),
        ),
        ("deepest depth tested", per(&|p| p.max_depth.to_string())),
        (
            "`flip-rank` columns at most",
            per(&|p| group_digits(p.rank_columns as u64)),
        ),
        (
            "`collisions`: nodes per depth at most × seeds",
            per(&|p| {
                format!(
                    "{} × {}",
                    group_digits(p.collision_nodes as u64),
                    p.collision_seeds
                )
            }),
        ),
        (
            "`dimensions`: seeds of the distinct test",
            per(&|p| group_digits(p.distinct_seeds)),
        ),
        (
            "`inverse`: words per width",
            per(&|p| group_digits(p.inverse_words)),
        ),
        (
            "`injective`: words per dimension",
            per(&|p| group_digits(p.injective_words as u64)),
        ),
        (
            "`expect`: words per seed and dimension",
            per(&|p| group_digits(p.twin_words as u64)),
        ),
        (
            "`nets`: points per net at most",
            per(&|p| format!("2^{}", p.net_log2_points)),
        ),
        (
            "`--equivalent-to owen`: seeds",
            per(&|p| group_digits(p.equivalence_seeds)),
        ),
    ]
}

/// `n` with commas between groups of three digits (`10,000`), as the manual writes counts.
fn group_digits(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, ch) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push(',');
        }
        out.push(ch);
    }
    out
}

/// The level plan as a Markdown table (one row per size, one column per level).
pub fn level_table() -> String {
    let mut out = String::from("| size | quick | full | exhaustive |\n|---|---|---|---|\n");
    for (what, [q, f, e]) in rows() {
        out.push_str(&format!("| {what} | {q} | {f} | {e} |\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_level_finds_its_own_plan_and_name() {
        for level in Level::ALL {
            assert_eq!(level.plan().level, level);
            assert_eq!(level.name().parse::<Level>(), Ok(level));
        }
        assert_eq!(Level::Full.name(), "full");
        let e = "fast".parse::<Level>().unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown level 'fast'; use quick, full or exhaustive"
        );
    }

    #[test]
    fn larger_levels_never_shrink_a_size() {
        for pair in LEVEL_PLANS.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            assert!(a.law_seeds < b.law_seeds && a.max_depth < b.max_depth);
            assert!(a.rank_columns < b.rank_columns && a.net_log2_points < b.net_log2_points);
            assert!(
                a.collision_nodes <= b.collision_nodes && a.collision_seeds <= b.collision_seeds
            );
            assert!(
                a.distinct_seeds < b.distinct_seeds && a.equivalence_seeds < b.equivalence_seeds
            );
            assert!(a.inverse_words <= b.inverse_words && a.injective_words <= b.injective_words);
            assert!(a.twin_words <= b.twin_words);
        }
    }

    #[test]
    fn counts_are_grouped_by_thousands() {
        assert_eq!(group_digits(7), "7");
        assert_eq!(group_digits(999), "999");
        assert_eq!(group_digits(1000), "1,000");
        assert_eq!(group_digits(100_000), "100,000");
        assert_eq!(group_digits(1_234_567), "1,234,567");
    }

    #[test]
    fn the_manual_shows_the_level_table_as_planned() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/battery.md");
        let manual = std::fs::read_to_string(path).expect("docs/battery.md");
        let table = level_table();
        assert!(
            manual.contains(&table),
            "docs/battery.md must contain the level table exactly as planned:\n{table}"
        );
        // The table has a row per size and a column per level.
        assert_eq!(table.lines().count(), 2 + rows().len());
        assert!(table.lines().all(|l| l.matches('|').count() == 5));
    }
}
