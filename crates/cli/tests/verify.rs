//! End-to-end `gartowen verify`: exit codes, table and JSON report.

use std::process::{Command, Output};

fn gartowen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .output()
        .expect("runs")
}

#[test]
fn verify_named_implementations_writes_json_and_exits_0() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("v.json");
    let o = gartowen(&[
        "verify",
        "--impl",
        "art-owen-16p:table=44",
        "--impl",
        "lk-hash",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("art-owen-16p:table=44")
            && text.contains("2 implementations, 0 with failures")
    );
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).unwrap()).unwrap();
    assert_eq!(v["command"], "verify");
    let imps = v["implementations"].as_array().unwrap();
    assert_eq!(imps.len(), 2);
    assert_eq!(imps[0]["checks"].as_array().unwrap().len(), 4);
    assert_eq!(
        imps[1]["checks"][3]["verdict"], "measured",
        "lk-hash makes no uniformity claim"
    );
}

#[test]
fn verify_bad_usage_exits_2() {
    assert_eq!(
        gartowen(&["verify", "--impl", "no-such-scrambler"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        gartowen(&["verify", "--level", "huge"]).status.code(),
        Some(2)
    );
}

#[test]
fn merged_shards_equal_one_unsharded_run() {
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n).to_str().unwrap().to_string();
    assert!(gartowen(&["verify", "--json", &path("all.json")])
        .status
        .success());
    for i in 1..=3 {
        let shard = format!("{i}/3");
        assert!(gartowen(&[
            "verify",
            "--shard",
            &shard,
            "--json",
            &path(&format!("s{i}.json"))
        ])
        .status
        .success());
    }
    let o = gartowen(&[
        "verify",
        "--merge",
        &path("s3.json"),
        &path("s1.json"),
        &path("s2.json"),
        "--json",
        &path("merged.json"),
    ]);
    assert_eq!(o.status.code(), Some(0));
    // Equal up to the timings.
    let strip = |file: &str| {
        let mut v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(path(file)).unwrap()).unwrap();
        for imp in v["implementations"].as_array_mut().unwrap() {
            for c in imp["checks"].as_array_mut().unwrap() {
                c["seconds"] = serde_json::Value::Null;
            }
        }
        v
    };
    assert_eq!(strip("merged.json"), strip("all.json"));
    // A missing or duplicated shard is a usage error.
    let missing = gartowen(&["verify", "--merge", &path("s1.json"), &path("s2.json")]);
    assert_eq!(missing.status.code(), Some(2));
    let twice = gartowen(&[
        "verify",
        "--merge",
        &path("s1.json"),
        &path("s1.json"),
        &path("s2.json"),
        &path("s3.json"),
    ]);
    assert_eq!(twice.status.code(), Some(2));
    assert_eq!(
        gartowen(&["verify", "--shard", "4/3"]).status.code(),
        Some(2)
    );
    assert_eq!(
        gartowen(&["verify", "--shard", "0/3"]).status.code(),
        Some(2)
    );
}
