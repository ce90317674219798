//! The README's table of what `verify` asks a program for is the code's own measurement:
//! every row equals `request_log::level_row` of the Owen oracle seen as a base-2 program of
//! 32-bit words, so a change to the battery's requests fails here until the README says it.

use gartowen::battery::request_log::{level_row, log_requests};
use gartowen::core::Width;
use gartowen::verify::{registry_candidate, Level};

#[test]
fn the_readme_lists_exactly_what_each_level_requests() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let registry = gartowen::registry();
    for level in [Level::Quick, Level::Full, Level::Exhaustive] {
        let make = || registry_candidate(&registry, "owen-oracle", 0).unwrap();
        let phases = log_requests(make, level, Width::W32, 0);
        // The laws ask every seed of the level, and only the probe's seed elsewhere.
        let laws = phases.iter().find(|p| p.phase == "laws").unwrap();
        assert_eq!(laws.seeds.len() as u64, level.plan().law_seeds);
        assert_eq!(laws.most_alive, 2, "the probe and one seed's instance");
        let row = level_row(level, &phases);
        assert!(
            readme.lines().any(|l| l == row),
            "README.md lacks the row\n{row}\n(regenerate: gartowen verify --list-requests --level {})",
            level.name()
        );
    }
}
