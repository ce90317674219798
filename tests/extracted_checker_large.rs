//! The counting net checker against its Coq model (`proofs/Checker.v`, extracted) past the
//! small corpus of `extracted_checker.rs`: sets of N ≥ 4096 points, where the t search's quick
//! probe (the first N/64 points) runs, with box counts b^t ≥ 255 (the 32-bit histogram) and
//! b^t < 255 (the byte histogram), one bit per box (t = 0) in bases 2^q (the packed and narrow
//! walks) and base 3 (no fast path), nets with one point moved (a box of b^t + 1 points at
//! every level below the t-value), pseudo-random sets. Every verdict, t-value, first failing
//! shape, box and count must agree. `scripts/planted-bugs.sh` seeds two bugs into the Rust
//! checker (the probe's keys cut at the wrong depth; the overflow bound one too high) and
//! shows this test failing on each.
//!
//! The test command leaves out the whole three-dimensional nets and their last-digit moves,
//! which the model checks to their last level (4 to 6 s each); the large tier adds them.

use crate::extracted_checker::{
    answers, broken, disagreements, faure, model_answers, random, reports, sobol, DigitSet, NetPath,
};
use crate::extracted_differential::driver;
use gartowen::core::SplitMix64;

/// The large corpus; every set has at least 4096 points. Without `deep`, the nets the model
/// checks to their last level are left out: the whole nets in three dimensions and their
/// last-digit moves (base 2 and base 3), which hold or fail only there.
fn corpus(deep: bool) -> Vec<DigitSet> {
    let mut rng = SplitMix64::new(0x1a59e);
    let nets = vec![
        (sobol(1, 12, 2, 12), true),
        (sobol(1, 12, 3, 12), deep),
        (sobol(2, 6, 3, 6), true),
        (sobol(4, 3, 3, 3), true),
        (faure(3, 8, 3), deep),
    ];
    let mut sets = Vec::new();
    for (net, whole) in nets {
        // The top digit of point i, coordinate 0, moved: the box that gains it holds b^t + 1
        // at every level it breaks.
        for i in [0, 1234] {
            sets.push(broken(&net, i, 0, 0));
        }
        if whole {
            sets.push(broken(&net, 77, 1, (net.n - 1) as usize));
            sets.push(net);
        }
    }
    sets.push(random(2, 2, 12, 4096, &mut rng));
    sets.push(random(16, 2, 3, 4096, &mut rng));
    sets
}

#[test]
fn the_net_checker_agrees_with_its_coq_model_on_sets_of_4096_points() {
    agrees_with_the_model(&corpus(false));
}

#[test]
#[ignore = "large tier (scripts/test-large.sh): the whole 3-D nets of 4096 and 6561 points, 25 s"]
fn the_net_checker_agrees_with_its_coq_model_on_sets_of_4096_points_and_the_whole_3d_nets() {
    agrees_with_the_model(&corpus(true));
}

/// Every path of the Rust checker gives the model's answers on `sets`, and the sets reach the
/// cases the corpus is for.
fn agrees_with_the_model(sets: &[DigitSet]) {
    let Some(driver) = driver() else { return };
    assert!(sets.iter().all(|s| s.points.len() >= 4096));
    let model = model_answers(&driver, sets);
    for path in [NetPath::TreeWalk, NetPath::PerShape, NetPath::Owned] {
        let rust: Vec<String> = sets
            .iter()
            .flat_map(|s| answers(&reports(s, path)))
            .collect();
        let (n, shown) = disagreements(&model, &rust, 10);
        assert_eq!(
            n,
            0,
            "{path:?} disagrees with Checker.v:\n{}",
            shown.join("\n")
        );
    }
    // The corpus reaches what it is for: t-values above 0 found past a failing probe level,
    // failures with b^t ≥ 255 (the 32-bit histogram) and boxes of exactly b^t + 1 points.
    let tvals: Vec<u32> = model
        .iter()
        .filter_map(|l| l.strip_prefix("answer tval "))
        .map(|l| l.rsplit(' ').next().unwrap().parse().unwrap())
        .collect();
    assert!(tvals.iter().filter(|&&t| t >= 2).count() >= 5, "{tvals:?}");
    let fails_at = |min_count: u64| {
        model.iter().any(|l| {
            l.starts_with("answer net ")
                && l.contains(" fails ")
                && l.rsplit(' ').next().unwrap().parse::<u64>().unwrap() >= min_count
        })
    };
    assert!(fails_at(257), "no failing box of 257 points or more");
}

/// The planted bugs of `scripts/planted-bugs.sh` still apply to the checker's source, so the
/// large tier keeps showing what this corpus catches.
#[test]
fn the_planted_bugs_apply_to_the_checker_source() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("tests/planted");
    let mut patches: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "patch"))
        .collect();
    patches.sort();
    assert!(patches.len() >= 2, "{patches:?}");
    for p in patches {
        let text = std::fs::read_to_string(&p).unwrap();
        // Each patch changes one line of one file, and that line is in the source today.
        let removed: Vec<&str> = text
            .lines()
            .filter(|l| l.starts_with('-') && !l.starts_with("---"))
            .map(|l| &l[1..])
            .collect();
        let file = text
            .lines()
            .find_map(|l| l.strip_prefix("--- a/"))
            .unwrap_or_else(|| panic!("{}: no file", p.display()));
        assert_eq!(removed.len(), 1, "{}", p.display());
        let source = std::fs::read_to_string(root.join(file)).unwrap();
        assert!(
            source.lines().any(|l| l == removed[0]),
            "{}: the line it changes is no longer in {file}:\n{}",
            p.display(),
            removed[0]
        );
    }
}
