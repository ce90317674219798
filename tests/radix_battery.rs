//! The battery in bases that are not powers of two: the base-b Owen oracle passes, and the
//! imitations users run (random shifts per node, one permutation per depth as in scrambled
//! Halton) fail the named laws; the laws' false-alarm rate on the oracle agrees with the level.

use gartowen::battery::radix_words::RadixWords;
use gartowen::core::{Claim, Radix, RadixLayout, RadixScrambler, Width};
use gartowen::verify::{
    check_candidate, judge_families, law_runner::run_laws, registry_candidate, verify_shard,
    Candidate, ImplReport, Level, Shard, Verdict,
};

fn verdicts(r: &ImplReport) -> Vec<(&str, Verdict)> {
    r.checks
        .iter()
        .map(|c| (c.check.as_str(), c.verdict))
        .collect()
}

/// Every check passes except `fails`; flip-rank does not apply.
fn assert_only_failures(r: &ImplReport, fails: &[&str]) {
    for (check, verdict) in verdicts(r) {
        let want = match check {
            "flip-rank" => Verdict::NotRun,
            c if fails.contains(&c) => Verdict::Fail,
            _ => Verdict::Pass,
        };
        assert_eq!(verdict, want, "{} {check}: {:?}", r.name, r.checks);
    }
}

#[test]
fn owen_in_bases_3_5_and_7_passes_and_imitations_claiming_owen_fail_the_named_laws() {
    let registry = gartowen::registry();
    let names: Vec<String> = [
        "owen-oracle:base=3",
        "owen-oracle:base=5",
        "owen-oracle:base=7",
        "owen-oracle:cyclic:base=3",
        "owen-oracle:per-depth:base=3",
        "owen-oracle:per-depth:base=6",
    ]
    .map(String::from)
    .to_vec();
    let reports = verify_shard(
        &registry,
        &names,
        Level::Quick,
        Shard::ALL,
        Some(Claim::OWEN),
        &|_| {},
    )
    .unwrap();
    let expected: [&[&str]; 6] = [
        &[],
        &[],
        &[],
        // A random shift per node: uniform over Z_3, not S_3, from the root on.
        &["node-law", "pair-lemma"],
        // One permutation per depth: each node uniform, nodes of a depth identical.
        &["pair-law", "collisions", "pair-lemma"],
        &["pair-law", "collisions", "pair-lemma"],
    ];
    for (r, fails) in reports.iter().zip(expected) {
        assert_eq!(
            r.base,
            r.name.rsplit('=').next().unwrap().parse::<u32>().unwrap()
        );
        assert_only_failures(r, fails);
    }
    let cyclic = reports[3]
        .checks
        .iter()
        .find(|c| c.check == "node-law")
        .unwrap();
    assert!(
        cyclic.detail.contains("depth 0") && cyclic.detail.contains("S_3"),
        "{}",
        cyclic.detail
    );
    // Nets in the scrambler's own base: Faure in a prime base, Hammersley otherwise.
    let nets = |r: &ImplReport| {
        r.checks
            .iter()
            .find(|c| c.check == "nets")
            .unwrap()
            .detail
            .clone()
    };
    assert!(
        nets(&reports[0]).contains("faure:base=3 dims [0, 1, 2] m ≤ 7"),
        "{}",
        nets(&reports[0])
    );
    assert!(
        nets(&reports[5]).contains("hammersley:base=6 dims [0, 1] m ≤ 4"),
        "{}",
        nets(&reports[5])
    );
    let not_applicable = &reports[0]
        .checks
        .iter()
        .find(|c| c.check == "flip-rank")
        .unwrap();
    assert!(
        not_applicable.detail.contains("not applicable in base 3"),
        "{}",
        not_applicable.detail
    );
}

#[test]
fn imitations_pass_on_their_own_claims() {
    let registry = gartowen::registry();
    for (name, claim) in [
        ("owen-oracle:cyclic:base=5", "independent:cyclic"),
        ("owen-oracle:per-depth:base=3", "marginal:symmetric"),
    ] {
        let c = registry_candidate(&registry, name, 0).unwrap();
        assert_eq!(c.claim.to_string(), claim);
        let r = check_candidate(&c, Level::Quick, 1);
        assert!(
            r.checks.iter().all(|c| c.verdict != Verdict::Fail),
            "{name}: {:?}",
            verdicts(&r)
        );
        // The per-depth scramble claims no independence: its joint laws are measured, and
        // the measurement shows the deviation.
        if name.contains("per-depth") {
            let pair = r.checks.iter().find(|c| c.check == "pair-law").unwrap();
            assert_eq!(pair.verdict, Verdict::Measured);
            let pair_profile = r.profile.iter().find(|(f, _)| f == "pair-law").unwrap();
            assert!(pair_profile.1.contains('x'), "{:?}", r.profile);
        }
    }
}

/// Reverses the order of the base-b digits: a bijection, not nested.
struct ReversedDigits(Radix);

impl RadixScrambler for ReversedDigits {
    fn name(&self) -> String {
        "reversed-digits".into()
    }
    fn radix(&self) -> Radix {
        self.0
    }
    fn claim(&self) -> Claim {
        Claim::NESTED
    }
    fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 {
        let l = RadixLayout::new(width, self.0).unwrap();
        let m = l.num_digits();
        (0..m).fold(0, |y, k| l.set(y, m - 1 - k, l.get(x, k)))
    }
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> Option<u64> {
        Some(self.scramble(y, width, dim))
    }
}

#[test]
fn a_bijection_that_is_not_nested_in_base_5_fails_nested_and_keeps_its_inverse() {
    let five = Radix::new(5).unwrap();
    let mut c = Candidate::from_builder(
        "reversed-digits",
        Claim::NESTED,
        Box::new(move |_| Ok(Box::new(RadixWords(Box::new(ReversedDigits(five)))))),
    )
    .unwrap();
    c.radix = Some(five);
    let r = check_candidate(&c, Level::Quick, 0);
    let get = |name: &str| r.checks.iter().find(|c| c.check == name).unwrap();
    assert_eq!(
        get("inverse").verdict,
        Verdict::Pass,
        "{}",
        get("inverse").detail
    );
    assert_eq!(get("nested").verdict, Verdict::Fail);
    assert!(
        get("nested").detail.starts_with("NotNested"),
        "{}",
        get("nested").detail
    );
    assert_eq!(r.base, 5);
}

#[test]
fn false_alarms_of_the_base_3_laws_on_the_oracle_agree_with_the_level() {
    // Independent runs of every law family (seed bases far apart) on the base-3 oracle: no
    // family may fail (family-wise α = 1e-3 per run: P(any failure in 8 runs) < 0.8%), and the
    // χ² p-values must be uniform: shares below 0.01 and 0.1 within 5 binomial standard
    // deviations. A wrong cell law in base 3 (e.g. one assuming XOR digits) shifts them by far
    // more.
    let registry = gartowen::registry();
    let c = registry_candidate(&registry, "owen-oracle:base=3", 0).unwrap();
    let mut p_values = Vec::new();
    for run in 0..8u64 {
        let families = run_laws(&c, Level::Quick, (run + 1) << 40).unwrap();
        for check in judge_families(families, Claim::OWEN, 1, 0.0) {
            assert_ne!(check.verdict, Verdict::Fail, "run {run}: {}", check.detail);
            p_values.extend(
                check
                    .tests
                    .iter()
                    .filter(|t| t.dof.is_some())
                    .map(|t| t.p_value),
            );
        }
    }
    let n = p_values.len() as f64;
    assert!(n > 400.0, "{n}");
    for level in [0.01, 0.1] {
        let share = p_values.iter().filter(|&&p| p < level).count() as f64 / n;
        let sd = (level * (1.0 - level) / n).sqrt();
        assert!(
            (share - level).abs() < 5.0 * sd,
            "P(p < {level}) = {share} over {n}"
        );
    }
}
