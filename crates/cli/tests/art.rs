//! End-to-end: every registered name generates, `:table=` works, bad tables are usage errors.

use crate::support::gartowen;

#[test]
fn every_registered_name_generates_and_is_reproducible() {
    let list: serde_json::Value =
        serde_json::from_slice(&gartowen(&["list", "--json"]).stdout).unwrap();
    let names: Vec<String> = list
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["name"].as_str().unwrap().to_string())
        .collect();
    for required in [
        "art-owen-2",
        "q-art-4",
        "art-owen-8p",
        "art-owen-16p",
        "art-owen-m5",
        "art-owen-t3",
        "lk-hash",
    ] {
        assert!(
            names.iter().any(|n| n == required),
            "{required} missing from list"
        );
    }
    for name in &names {
        let args = [
            "generate",
            "--seq",
            "sobol",
            "--dims",
            "3",
            "--log2-n",
            "6",
            "--scramble",
            name,
            "--seed",
            "9",
        ];
        let a = gartowen(&args);
        assert!(
            a.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&a.stderr)
        );
        assert_eq!(a.stdout, gartowen(&args).stdout, "{name} is deterministic");
        assert_eq!(String::from_utf8_lossy(&a.stdout).lines().count(), 64);
    }
}

#[test]
fn table_option_and_its_errors() {
    let small = gartowen(&[
        "generate",
        "--seq",
        "sz16",
        "--dims",
        "2",
        "--n",
        "8",
        "--scramble",
        "art-owen-16p:table=44",
    ]);
    let large = gartowen(&[
        "generate",
        "--seq",
        "sz16",
        "--dims",
        "2",
        "--n",
        "8",
        "--scramble",
        "art-owen-16p:table=256",
    ]);
    assert!(small.status.success() && large.status.success());
    assert_ne!(small.stdout, large.stdout);
    for bad in [
        "art-owen-16p:table=45",
        "art-owen-16p:table=x",
        // Past the bound: refused at once (2^32 once hung for minutes).
        "art-owen-16p:table=4294967296",
        "art-owen-16p:table=65537",
        "art-owen-16p:size=44",
        "art-owen-m9",
        "art-owen-t0",
    ] {
        let o = gartowen(&[
            "generate",
            "--seq",
            "sz16",
            "--dims",
            "2",
            "--n",
            "8",
            "--scramble",
            bad,
        ]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(
            !String::from_utf8_lossy(&o.stderr).contains("panicked"),
            "{bad}"
        );
    }
    let o = gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "2",
        "--n",
        "8",
        "--bits",
        "64",
        "--scramble",
        "lk-hash",
    ]);
    assert_eq!(o.status.code(), Some(2), "lk-hash has no 64-bit form");
}

#[test]
fn list_reports_each_art_records_size_beside_the_papers_ratios() {
    let out = gartowen(&["list", "--json"]);
    let list: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let row = |name: &str| {
        list.as_array()
            .unwrap()
            .iter()
            .find(|e| e["name"] == name)
            .unwrap()
            .clone()
    };
    let bytes = |name: &str| row(name)["record_bytes"].as_u64().unwrap();
    // Hand-worked 256-symbol layouts (crates/art/src/record.rs): 32-bit code, + 3-bit index,
    // one 32-bit word, 64-bit permutation + 32-bit code.
    assert_eq!(bytes("art-owen-2"), 1024);
    assert_eq!(bytes("q-art-4"), 1120);
    assert_eq!(bytes("art-owen-8p"), 1024);
    assert_eq!(bytes("art-owen-16p"), 3072);
    let m8 = row("art-owen-m8");
    assert!(m8["record_bytes_64"].as_u64().unwrap() <= 16 * 256);
    assert_eq!(
        m8["table_bytes"].as_u64().unwrap(),
        m8["child_table_bytes"].as_u64().unwrap() + m8["acceleration_bytes"].as_u64().unwrap()
    );
    let r16 = row("art-owen-16p");
    assert_eq!(r16["paper_ratio_to_q_art_4"], 3.0);
    assert!((r16["record_ratio_to_q_art_4"].as_f64().unwrap() - 3072.0 / 1120.0).abs() < 1e-12);
    assert!(row("lk-hash").get("record_bytes").is_none());
    // The text table prints the ratios beside the paper's.
    let text = String::from_utf8(gartowen(&["list"]).stdout).unwrap();
    assert!(
        text.contains("art-owen-8p / q-art-4 record = 0.91 (the paper: about 1"),
        "{text}"
    );
    assert!(
        text.contains("art-owen-16p / q-art-4 record = 2.74 (the paper: about 3"),
        "{text}"
    );
}
