//! End-to-end tests of `gartowen check --witness`: the file holds the words read and what the
//! verdict rests on, and what it cannot cover is refused without touching an earlier file.

use crate::check::{generate, point_7_copying_point_8};
use crate::support::gartowen;

#[test]
fn witness_files_hold_the_words_and_the_failing_box_and_refuse_what_they_cannot_cover() {
    let dir = tempfile::tempdir().unwrap();
    let good = generate(
        dir.path(),
        "sz16.hex",
        &["--seq", "sz16", "--dims", "16", "--log2-n", "12"],
    );
    let wpath = dir.path().join("sz16.witness");
    let w = wpath.to_str().unwrap();
    let o = gartowen(&["check", &good, "--base", "16", "--witness", w]);
    assert_eq!(o.status.code(), Some(0));
    let witness = std::fs::read_to_string(&wpath).unwrap();
    let lines: Vec<&str> = witness.lines().collect();
    assert_eq!(lines[0], "gartowen-witness 1");
    assert_eq!(lines[1], "base 16 width 32 dims 16 m 3 points 4096");
    assert_eq!(lines[2], "claim tvalue 0");
    assert_eq!(lines[3], "words");
    // The words are the input's, point by point.
    let input = std::fs::read_to_string(&good).unwrap();
    let parse = |l: &str| -> Vec<u64> {
        l.split(' ')
            .map(|x| u64::from_str_radix(x.trim_start_matches("0x"), 16).unwrap())
            .collect()
    };
    for (k, row) in input.lines().enumerate().step_by(97) {
        assert_eq!(parse(lines[4 + k]), parse(row), "point {k}");
    }
    assert_eq!(*lines.last().unwrap(), "end");

    // A broken set: the witness names the box the report names, with its count.
    let bad = point_7_copying_point_8(dir.path(), &good);
    let bad = bad.to_str().unwrap();
    let o = gartowen(&[
        "check",
        bad,
        "--base",
        "16",
        "--t",
        "0",
        "--json",
        "--witness",
        w,
    ]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let f = &v["result"]["first_failure"];
    let witness = std::fs::read_to_string(&wpath).unwrap();
    let lines: Vec<&str> = witness.lines().collect();
    assert_eq!(lines[2], "claim fails 0");
    let join = |x: &serde_json::Value| -> String {
        x.as_array()
            .unwrap()
            .iter()
            .map(|d| d.to_string())
            .collect::<Vec<_>>()
            .join(" ")
    };
    assert_eq!(
        lines[3],
        format!(
            "box {} {} count {}",
            join(&f["shape"]),
            join(&f["box_index"]),
            f["count"]
        )
    );

    // Refused with exit 2, the existing witness untouched: a sequence check, a projection
    // check, the input as the witness.
    for args in [
        vec!["check", bad, "--base", "16", "--sequence", "--witness", w],
        vec![
            "check",
            bad,
            "--base",
            "16",
            "--projections",
            "pairs",
            "--witness",
            w,
        ],
        vec!["check", bad, "--base", "16", "--witness", bad],
    ] {
        let o = gartowen(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&o.stderr).contains("--witness"),
            "{args:?}"
        );
        assert_eq!(
            std::fs::read_to_string(&wpath).unwrap(),
            witness,
            "{args:?}"
        );
    }
    assert_eq!(std::fs::read_to_string(bad).unwrap().lines().count(), 4096);
}
