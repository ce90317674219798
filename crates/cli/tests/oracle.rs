//! End-to-end: scrambled generation with the oracle, and `inspect` verdicts.

use crate::support::gartowen;
use std::process::Output;

fn words(o: &Output) -> Vec<Vec<u64>> {
    String::from_utf8_lossy(&o.stdout)
        .lines()
        .map(|l| {
            l.split(' ')
                .map(|w| u64::from_str_radix(w, 16).unwrap())
                .collect()
        })
        .collect()
}

#[test]
fn scrambled_generation_uses_the_sequence_base_by_default_and_is_reproducible() {
    let run = |extra: &[&str]| {
        let mut args = vec![
            "generate",
            "--seq",
            "sz4",
            "--dims",
            "2",
            "--log2-n",
            "4",
            "--scramble",
            "owen-oracle",
            "--seed",
            "3",
        ];
        args.extend_from_slice(extra);
        words(&gartowen(&args))
    };
    let default = run(&[]);
    assert_eq!(
        default,
        run(&["--scramble-base", "4"]),
        "sz4 defaults to base 4"
    );
    assert_ne!(default, run(&["--scramble-base", "2"]));
    let explicit = words(&gartowen(&[
        "generate",
        "--seq",
        "sz4",
        "--dims",
        "2",
        "--log2-n",
        "4",
        "--scramble",
        "owen-oracle:base=2",
        "--seed",
        "3",
    ]));
    assert_eq!(
        run(&["--scramble-base", "2"]),
        explicit,
        ":base=2 equals --scramble-base 2"
    );
    let plain = words(&gartowen(&[
        "generate", "--seq", "sz4", "--dims", "2", "--log2-n", "4",
    ]));
    assert_ne!(default, plain);
    // A nested scramble permutes the set's first digits: the top base-4 digits of the 16 points
    // of a (0,2,2)-net still take every value 4 times in each coordinate.
    for j in 0..2 {
        let mut counts = [0; 4];
        for p in &default {
            counts[(p[j] >> 30) as usize] += 1;
        }
        assert_eq!(counts, [4; 4]);
    }
    let o = gartowen(&[
        "generate",
        "--seq",
        "sz4",
        "--dims",
        "2",
        "--n",
        "4",
        "--scramble",
        "owen-oracle:bogus",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let o = gartowen(&[
        "generate",
        "--seq",
        "sz4",
        "--dims",
        "2",
        "--n",
        "4",
        "--scramble",
        "owen-oracle",
        "--scramble-base",
        "6",
    ]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn inspect_accepts_nested_scramblers_and_rejects_others_with_the_node() {
    let ok = gartowen(&[
        "inspect",
        "--scramble",
        "owen-oracle",
        "--base",
        "4",
        "--width",
        "12",
        "--json",
    ]);
    assert_eq!(ok.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&ok.stdout).unwrap();
    assert_eq!(v["report"]["nested_scramble"], true);
    let bad = gartowen(&[
        "inspect",
        "--scramble",
        "owen-oracle:base=16",
        "--base",
        "2",
        "--width",
        "16",
        "--json",
    ]);
    assert_eq!(bad.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&bad.stdout).unwrap();
    assert_eq!(v["report"]["first_violation"]["kind"], "NotNested");
    let probes = gartowen(&[
        "inspect",
        "--scramble",
        "owen-oracle:affine",
        "--base",
        "8",
        "--width",
        "32",
        "--probes",
        "300",
    ]);
    assert_eq!(probes.status.code(), Some(0));
    // Base 5 is probed as base-5 digit words (tests/inspect_radix.rs); 512 is no base at all.
    assert_eq!(
        gartowen(&["inspect", "--scramble", "owen-oracle", "--base", "512"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        gartowen(&[
            "inspect",
            "--scramble",
            "owen-oracle",
            "--base",
            "4",
            "--width",
            "65"
        ])
        .status
        .code(),
        Some(2)
    );
}
