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
