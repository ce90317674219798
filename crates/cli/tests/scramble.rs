//! `gartowen scramble`: the user's own points, scrambled column by column, equal the points
//! `generate` scrambles itself; bad input exits 2 and writes nothing.

use crate::support::gartowen;

#[test]
fn scrambling_a_file_equals_generating_scrambled() {
    let dir = tempfile::tempdir().unwrap();
    let plain = dir.path().join("plain.hex");
    let out = gartowen(&[
        "generate",
        "--seq",
        "sz16",
        "--dims",
        "4",
        "--n",
        "256",
        "-o",
        plain.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    // `generate` scrambles sz16 in its own base 16; `scramble` is told so, except for the
    // fixed binary digital shift (a base it does not take is refused).
    for (scrambler, base) in [
        ("art-owen-16p", Some("16")),
        ("owen-oracle", Some("16")),
        ("digital-shift", None),
    ] {
        let mut args = vec![
            "scramble",
            plain.to_str().unwrap(),
            "--scramble",
            scrambler,
            "--seed",
            "11",
        ];
        args.extend(base.map(|b| ["--scramble-base", b]).into_iter().flatten());
        let mine = gartowen(&args);
        let theirs = gartowen(&[
            "generate",
            "--seq",
            "sz16",
            "--dims",
            "4",
            "--n",
            "256",
            "--scramble",
            scrambler,
            "--seed",
            "11",
        ]);
        assert!(
            mine.status.success(),
            "{}",
            String::from_utf8_lossy(&mine.stderr)
        );
        assert_eq!(mine.stdout, theirs.stdout, "{scrambler}");
        assert_ne!(
            mine.stdout,
            std::fs::read(&plain).unwrap(),
            "{scrambler} changed nothing"
        );
    }
    // npy words in, npy words out: same words as the hex path.
    let words = dir.path().join("w.npy");
    let scrambled = dir.path().join("s.npy");
    assert!(gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "2",
        "--n",
        "32",
        "--words",
        "--format",
        "npy",
        "-o",
        words.to_str().unwrap(),
    ])
    .status
    .success());
    let o = gartowen(&[
        "scramble",
        words.to_str().unwrap(),
        "--scramble",
        "lk-hash",
        "--seed",
        "4",
        "--words",
        "-o",
        scrambled.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let hex = gartowen(&[
        "scramble",
        scrambled.to_str().unwrap(),
        "--scramble",
        "none",
        "--format",
        "hex",
    ]);
    let direct = gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "2",
        "--n",
        "32",
        "--scramble",
        "lk-hash",
        "--seed",
        "4",
    ]);
    assert_eq!(hex.stdout, direct.stdout);
}

#[test]
fn bad_scramble_requests_exit_2_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let plain = dir.path().join("plain.hex");
    assert!(gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "2",
        "--n",
        "8",
        "-o",
        plain.to_str().unwrap(),
    ])
    .status
    .success());
    let target = dir.path().join("out.hex");
    for args in [
        vec!["--scramble", "no-such"],
        vec!["--scramble", "owen-oracle", "--scramble-base", "3"],
        vec!["--scramble", "lk-hash", "--words", "--format", "hex"],
    ] {
        let mut all = vec!["scramble", plain.to_str().unwrap()];
        all.extend(args.iter().copied());
        all.extend(["-o", target.to_str().unwrap()]);
        let o = gartowen(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!o.stderr.is_empty());
        assert!(!target.exists());
    }
    let o = gartowen(&["scramble", "/nonexistent.hex", "--scramble", "none"]);
    assert_eq!(o.status.code(), Some(2));
}
