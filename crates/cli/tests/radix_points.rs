//! `generate` and `scramble` in a base that is not a power of two: the base-3 Faure points
//! scrambled by `generate` equal the floats `scramble` reads back and scrambles itself, the
//! scrambled set is still a (0,m,3)-net in base 3 by `check`, digit words round-trip, and bad
//! requests exit 2 without touching the output.

use crate::support::run;
use std::path::Path;

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn scrambling_base_3_floats_equals_generating_them_scrambled_and_keeps_the_net() {
    let dir = tempfile::tempdir().unwrap();
    let (plain, made, read) = (
        dir.path().join("plain.csv"),
        dir.path().join("made.csv"),
        dir.path().join("read.csv"),
    );
    let faure = [
        "generate",
        "--seq",
        "faure:base=3",
        "--dims",
        "3",
        "--n",
        "243",
        "--bits",
        "64",
    ];
    let (code, _, err) = run(&[&faure[..], &["-o", path(&plain)]].concat());
    assert_eq!(code, 0, "{err}");
    for variant in ["owen-oracle", "owen-oracle:per-depth", "owen-oracle:cyclic"] {
        let scramble = ["--scramble", variant, "--seed", "5"];
        let (code, _, err) = run(&[&faure[..], &scramble, &["-o", path(&made)]].concat());
        assert_eq!(code, 0, "{err}");
        let (code, _, err) = run(&[
            &[
                "scramble",
                path(&plain),
                "--scramble-base",
                "3",
                "--bits",
                "64",
                "-o",
                path(&read),
            ][..],
            &scramble,
        ]
        .concat());
        assert_eq!(code, 0, "{err}");
        let (made_text, read_text) = (
            std::fs::read_to_string(&made).unwrap(),
            std::fs::read_to_string(&read).unwrap(),
        );
        assert_eq!(made_text, read_text, "{variant}");
        assert_ne!(made_text, std::fs::read_to_string(&plain).unwrap());
        // Every nested scramble keeps the (0,5,3)-net, counted on the floats by `check`.
        let (code, out, err) = run(&["check", path(&made), "--base", "3"]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains("t = 0 (m = 5, s = 3, base 3)"), "{out}");
        std::fs::remove_file(&read).unwrap();
    }
}

#[test]
fn digit_words_in_and_out_are_integers_below_b_to_the_m() {
    let dir = tempfile::tempdir().unwrap();
    let (words, scrambled) = (dir.path().join("w.npy"), dir.path().join("s.npy"));
    let gen = [
        "generate",
        "--seq",
        "faure:base=5",
        "--dims",
        "2",
        "--n",
        "25",
        "--words",
        "-o",
    ];
    let (code, _, err) = run(&[&gen[..], &[path(&words)]].concat());
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = run(&[
        "scramble",
        path(&words),
        "--scramble",
        "owen-oracle:base=5",
        "--seed",
        "2",
        "--words",
        "-o",
        path(&scrambled),
    ]);
    assert_eq!(code, 0, "{err}");
    // The same as generating the scrambled words directly.
    let direct = dir.path().join("d.npy");
    let (code, _, err) = run(&[
        &gen[..],
        &[path(&direct), "--scramble", "owen-oracle", "--seed", "2"],
    ]
    .concat());
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        std::fs::read(&direct).unwrap(),
        std::fs::read(&scrambled).unwrap()
    );
    // Hex words: 5^13 is the first word out of range in 32 bits.
    let hex = dir.path().join("bad.hex");
    std::fs::write(
        &hex,
        format!("{:08x}\n{:08x}\n", 5u64.pow(13) - 1, 5u64.pow(13)),
    )
    .unwrap();
    let (code, _, err) = run(&[
        "scramble",
        path(&hex),
        "--scramble",
        "owen-oracle",
        "--scramble-base",
        "5",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("point 1 coordinate 0") && err.contains("below 5^13"),
        "{err}"
    );
}

#[test]
fn base_b_requests_that_cannot_work_exit_2_and_leave_the_output_alone() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("kept.csv");
    std::fs::write(&out, "untouched\n").unwrap();
    let plain = dir.path().join("plain.csv");
    std::fs::write(&plain, "0.5,0.25\n0.75,0.125\n").unwrap();
    let o = path(&out);
    let cases: [(&[&str], &str); 8] = [
        (
            &[
                "generate",
                "--seq",
                "sobol",
                "--dims",
                "2",
                "--n",
                "4",
                "--scramble",
                "owen-oracle",
                "--scramble-base",
                "3",
                "-o",
                o,
            ],
            "generate faure:base=3",
        ),
        (
            &[
                "generate",
                "--seq",
                "faure:base=3",
                "--dims",
                "2",
                "--n",
                "4",
                "--scramble-base",
                "5",
                "-o",
                o,
            ],
            "--scramble-base 5 differs from the base 3",
        ),
        (
            &[
                "generate",
                "--seq",
                "faure:base=9",
                "--dims",
                "2",
                "--n",
                "4",
                "-o",
                o,
            ],
            "not a prime",
        ),
        (
            &[
                "generate",
                "--seq",
                "faure:base=3",
                "--dims",
                "4",
                "--n",
                "4",
                "-o",
                o,
            ],
            "4",
        ),
        (
            &[
                "generate",
                "--seq",
                "faure:base=3",
                "--dims",
                "2",
                "--n",
                "4",
                "--order",
                "gray",
                "-o",
                o,
            ],
            "--order gray",
        ),
        (
            &[
                "scramble",
                path(&plain),
                "--scramble",
                "art-owen-2",
                "--scramble-base",
                "3",
                "-o",
                o,
            ],
            "only owen-oracle",
        ),
        (
            &[
                "scramble",
                path(&plain),
                "--scramble",
                "owen-oracle",
                "--digits",
                "3",
                "-o",
                o,
            ],
            "--digits and --bits apply",
        ),
        (
            &[
                "scramble",
                path(&plain),
                "--scramble",
                "owen-oracle",
                "--scramble-base",
                "3",
                "--digits",
                "41",
                "-o",
                o,
            ],
            "--digits 41",
        ),
    ];
    for (args, fragment) in cases {
        let (code, _, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(fragment), "{args:?}: {err}");
        assert_eq!(std::fs::read_to_string(&out).unwrap(), "untouched\n");
    }
}

/// Points past the first b^d of a sequence carry more digits than ⌈log_b N⌉: ten Faure points
/// from index 600 in base 5 have four. The default depth grows until every value is on its
/// grid, so `scramble none` gives the points back and Owen's scramble equals `generate`'s, at
/// both widths (before, the values were floored to 5^-27 units and misread, silently);
/// `--digits` too small for them is refused, naming the point.
#[test]
fn points_with_more_digits_than_the_count_needs_are_read_exactly_or_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (plain, made, read) = (
        dir.path().join("plain.csv"),
        dir.path().join("made.csv"),
        dir.path().join("read.csv"),
    );
    for bits in ["32", "64"] {
        let faure = [
            "generate",
            "--seq",
            "faure:base=5",
            "--dims",
            "2",
            "--n",
            "10",
            "--start",
            "600",
            "--bits",
            bits,
        ];
        let (code, _, err) = run(&[&faure[..], &["-o", path(&plain)]].concat());
        assert_eq!(code, 0, "{err}");
        for (scramble, expected) in [("none", &plain), ("owen-oracle", &made)] {
            let with = ["--scramble", scramble, "--seed", "3"];
            let (code, _, err) = run(&[&faure[..], &with, &["-o", path(&made)]].concat());
            assert_eq!(code, 0, "{err}");
            let mut args = vec!["scramble", path(&plain), "--scramble-base", "5", "-o"];
            args.push(path(&read));
            args.extend(with);
            if bits == "64" {
                args.extend(["--bits", "64"]);
            }
            let (code, _, err) = run(&args);
            assert_eq!(code, 0, "{bits} {scramble}: {err}");
            assert_eq!(
                std::fs::read_to_string(&read).unwrap(),
                std::fs::read_to_string(expected).unwrap(),
                "{bits} {scramble}"
            );
            std::fs::remove_file(&read).unwrap();
        }
    }
    let (code, _, err) = run(&[
        "scramble",
        path(&plain),
        "--scramble-base",
        "5",
        "--scramble",
        "none",
        "--digits",
        "3",
        "-o",
        path(&read),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("point 0 coordinate 0") && err.contains("--digits"),
        "{err}"
    );
    assert!(!read.exists());
    // Values that are on no base-5 grid a float resolves (binary fractions) are refused too.
    std::fs::write(&plain, "0.1,0.5\n0.3,0.7\n").unwrap();
    let (code, _, err) = run(&[
        "scramble",
        path(&plain),
        "--scramble-base",
        "5",
        "--scramble",
        "none",
        "-o",
        path(&read),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("no grid of up to"), "{err}");
}

/// A request that names its base and a `--scramble-base` that names another is refused with
/// exit 2 naming both, as `--help` says (before, `:base=5` won over `--scramble-base 3`).
#[test]
fn a_base_named_twice_differently_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let (plain, out) = (dir.path().join("p.csv"), dir.path().join("o.csv"));
    let gen = [
        "generate",
        "--seq",
        "faure:base=3",
        "--dims",
        "2",
        "--n",
        "9",
        "-o",
    ];
    assert_eq!(run(&[&gen[..], &[path(&plain)]].concat()).0, 0);
    for (request, flag) in [("owen-oracle:base=5", "3"), ("owen-oracle:base=3", "5")] {
        let (code, _, err) = run(&[
            "scramble",
            path(&plain),
            "--scramble",
            request,
            "--scramble-base",
            flag,
            "-o",
            path(&out),
        ]);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains(&format!("--scramble-base {flag} conflicts with {request}")),
            "{err}"
        );
        assert!(!out.exists());
    }
    let (code, _, err) = run(&[
        "scramble",
        path(&plain),
        "--scramble",
        "owen-oracle:base=3",
        "--scramble-base",
        "3",
        "-o",
        path(&out),
    ]);
    assert_eq!(code, 0, "{err}");
}
