//! End-to-end tests of `gartowen check`: verdicts, exit codes, JSON and bad input.

use std::path::Path;
use std::process::{Command, Output};

fn gartowen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .output()
        .expect("runs")
}

fn generate(dir: &Path, name: &str, args: &[&str]) -> String {
    let path = dir.join(name).to_str().unwrap().to_string();
    let mut all = vec!["generate"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", &path]);
    assert!(gartowen(&all).status.success());
    path
}

#[test]
fn sz16_is_a_0_3_16_net_and_a_mutation_fails_with_exit_1() {
    let dir = tempfile::tempdir().unwrap();
    let good = generate(
        dir.path(),
        "sz16.hex",
        &["--seq", "sz16", "--dims", "16", "--log2-n", "12"],
    );
    let o = gartowen(&["check", &good, "--base", "16", "--t", "0", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "pass");
    assert_eq!(v["schema"], "gartowen-certificate");
    assert_eq!(v["schema_version"], 1);
    assert_eq!(v["result"]["m"], 3);
    assert_eq!(v["result"]["shapes_checked"], 816);
    assert_eq!(v["inputs"][0]["details"]["points"], 4096);

    // Copy point 8's coordinate 3 onto point 7: two points share a box of shape d_3 ≥ 1.
    let text = std::fs::read_to_string(&good).unwrap();
    let mut rows: Vec<Vec<String>> = text
        .lines()
        .map(|l| l.split(' ').map(String::from).collect())
        .collect();
    rows[7][3] = rows[8][3].clone();
    let bad = dir.path().join("bad.hex");
    std::fs::write(
        &bad,
        rows.iter().map(|r| r.join(" ") + "\n").collect::<String>(),
    )
    .unwrap();
    let o = gartowen(&[
        "check",
        bad.to_str().unwrap(),
        "--base",
        "16",
        "--t",
        "0",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let f = &v["result"]["first_failure"];
    assert_eq!(f["count"], 2);
    assert!(
        f["shape"][3].as_u64().unwrap() >= 1,
        "the mutated dimension is refined: {f}"
    );
    assert_ne!(v["inputs"][0]["checksum_fnv1a64"], serde_json::Value::Null);
}

#[test]
fn t_values_of_sobol_pairs_and_the_sequence_check() {
    let dir = tempfile::tempdir().unwrap();
    let f = generate(
        dir.path(),
        "s.npy",
        &[
            "--seq", "sobol", "--dims", "3", "--log2-n", "10", "--format", "npy",
        ],
    );
    let o = gartowen(&[
        "check",
        &f,
        "--base",
        "2",
        "--projections",
        "pairs",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "reporting only exits 0");
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let ts: Vec<u64> = v["result"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["t"].as_u64().unwrap())
        .collect();
    assert_eq!(ts.len(), 3);
    assert_eq!(ts[0], 0, "dims 0,1 form a (0,10,2)-net");
    let o = gartowen(&[
        "check",
        &f,
        "--base",
        "2",
        "--sequence",
        "--t",
        "0",
        "--projections",
        "0,1",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let o = gartowen(&[
        "check",
        &f,
        "--base",
        "2",
        "--sequence",
        "--t",
        "0",
        "--projections",
        "0,2",
    ]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "dims 0,2 are not a (0,2)-sequence"
    );
    assert!(String::from_utf8_lossy(&o.stdout).contains("first failure"));
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let cases = [
        (write("nan.csv", "nan,0.5\n0.5,0.5\n"), "2", "NaN"),
        (
            write("one.csv", "0.5,1.0\n0.5,0.5\n"),
            "2",
            "outside [0, 1)",
        ),
        (
            write("neg.csv", "-0.5,0.5\n0.5,0.5\n"),
            "2",
            "outside [0, 1)",
        ),
        (write("ragged.csv", "0.5,0.25\n0.5\n"), "2", "line 2"),
        (write("empty.csv", ""), "2", "no data"),
        (write("words.csv", "a,b\n"), "2", "not a number"),
        (
            write("three.csv", "0.5\n0.25\n0.75\n"),
            "2",
            "not a power of the base",
        ),
        (write("ok.csv", "0.5\n0.25\n"), "1", "below 2"),
        (write("badhex.hex", "1234567\n"), "2", "8- or 16-digit"),
        (
            write("mixed.hex", "12345678\n1234567812345678\n"),
            "2",
            "digits",
        ),
        (write("garbage.npy", "not numpy"), "2", "npy"),
    ];
    for (path, base, needle) in cases {
        let o = gartowen(&["check", &path, "--base", base]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{path}: {err}");
        assert!(err.contains(needle), "{path}: '{err}' lacks '{needle}'");
        assert!(!err.contains("panicked"), "{path}");
    }
    let o = gartowen(&["check", "/nonexistent/file.csv", "--base", "2"]);
    assert_eq!(o.status.code(), Some(2));
}
