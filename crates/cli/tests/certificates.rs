//! Certificates are checked, not trusted: `verify --merge` and `certificate check` recompute
//! every verdict from the recorded statistics, check every field against the registry and the
//! level, and refuse an edit that kept the fields consistent by the content digest. Each
//! tampered certificate of issue 38 is refused with exit 2 naming the field.

use crate::support::gartowen;
use serde_json::Value;
use std::path::Path;

const IMPLEMENTATIONS: [&str; 3] = ["lk-hash", "digital-shift", "owen-oracle:base=4"];

/// Writes shards 1/2 and 2/2 of a quick run into `dir`.
fn shards(dir: &Path) -> (String, String) {
    let path = |n: &str| dir.join(n).to_str().unwrap().to_string();
    for (shard, file) in [("1/2", "a1.json"), ("2/2", "a2.json")] {
        let mut args = vec!["verify", "--shard", shard];
        for i in IMPLEMENTATIONS {
            args.extend(["--impl", i]);
        }
        let out = path(file);
        args.extend(["--json", &out]);
        let o = gartowen(&args);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    (path("a1.json"), path("a2.json"))
}

fn implementation<'a>(doc: &'a mut Value, name: &str) -> &'a mut Value {
    doc["result"]["implementations"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|i| i["name"].as_str().unwrap().starts_with(name))
        .unwrap()
}

fn check<'a>(imp: &'a mut Value, name: &str) -> &'a mut Value {
    imp["checks"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find(|c| c["check"] == name)
        .unwrap()
}

type Edit = fn(&mut Value);

/// (what, the edit, a fragment of the field the refusal must name).
fn tamperings() -> Vec<(&'static str, Edit, &'static str)> {
    vec![
        (
            "a claimed node-law with every p-value 0, sub-tests deviating, verdict pass",
            |d| {
                let c = check(implementation(d, "owen-oracle"), "node-law");
                for t in c["tests"].as_array_mut().unwrap() {
                    t["p_value"] = 0.0.into();
                    t["deviates"] = true.into();
                }
            },
            "checks[",
        ),
        (
            "a structure check's verdict changed to measured",
            |d| check(implementation(d, "lk-hash"), "inverse")["verdict"] = "measured".into(),
            "checks[0].verdict",
        ),
        (
            "a structure check's verdict changed to skipped",
            |d| check(implementation(d, "lk-hash"), "nets")["verdict"] = "skipped".into(),
            ".verdict",
        ),
        (
            "a p-value of 2.5",
            |d| {
                check(implementation(d, "owen-oracle"), "pair-law")["tests"][0]["p_value"] =
                    2.5.into()
            },
            ".tests[0].p_value",
        ),
        (
            "a p-value of -1",
            |d| check(implementation(d, "owen-oracle"), "pair-law")["p_value"] = (-1.0).into(),
            ".p_value",
        ),
        (
            "the claim weakened from owen to nested",
            |d| {
                let i = implementation(d, "owen-oracle");
                i["claim"] = "nested".into();
                i["claims_nested_uniform"] = false.into();
            },
            ".claim",
        ),
        (
            "the base changed",
            |d| implementation(d, "lk-hash")["base"] = 4.into(),
            ".base",
        ),
        (
            "an injected external failure",
            |d| {
                let c = check(implementation(d, "lk-hash"), "nested");
                c["verdict"] = "fail".into();
                c["detail"] = "external program failed: no reply".into();
                d["verdict"] = "fail".into();
            },
            ".detail",
        ),
        (
            "the level changed",
            |d| d["parameters"]["level"] = "full".into(),
            "parameters.",
        ),
        ("the seeds changed", |d| d["seeds"][1] = 99.into(), "seeds"),
        (
            "an implementation renamed",
            |d| implementation(d, "lk-hash")["name"] = "lk-hash-2".into(),
            ".name",
        ),
        (
            "a name with control characters",
            |d| implementation(d, "lk-hash")["name"] = "lk-hash\u{1b}[2J".into(),
            ".name",
        ),
        (
            "the overall verdict changed",
            |d| d["verdict"] = "fail".into(),
            "verdict",
        ),
        (
            "a consistent edit (a structure check's words)",
            |d| check(implementation(d, "lk-hash"), "nested")["detail"] = "trust me".into(),
            "digest",
        ),
        (
            "the digest removed",
            |d| {
                d.as_object_mut().unwrap().remove("digest");
            },
            "digest",
        ),
    ]
}

#[test]
fn tampered_shards_are_refused_by_merge_and_by_certificate_check_naming_the_field() {
    let dir = tempfile::tempdir().unwrap();
    let (a1, a2) = shards(dir.path());
    // The untouched shards merge, and every certificate involved checks out.
    let merged = dir.path().join("merged.json");
    let o = gartowen(&[
        "verify",
        "--merge",
        &a1,
        &a2,
        "--json",
        merged.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let o = gartowen(&["certificate", "check", &a1, &a2, merged.to_str().unwrap()]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(
        String::from_utf8_lossy(&o.stdout)
            .matches(": consistent")
            .count(),
        3
    );
    let original: Value = serde_json::from_str(&std::fs::read_to_string(&a1).unwrap()).unwrap();
    let tampered = dir.path().join("tampered.json");
    let tampered = tampered.to_str().unwrap();
    for (what, edit, field) in tamperings() {
        let mut doc = original.clone();
        edit(&mut doc);
        assert_ne!(doc, original, "{what}: the edit changed nothing");
        std::fs::write(tampered, serde_json::to_string_pretty(&doc).unwrap()).unwrap();
        for args in [
            vec!["verify", "--merge", tampered, &a2],
            vec!["certificate", "check", tampered],
        ] {
            let o = gartowen(&args);
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{what} ({}): {err}", args[0]);
            assert!(
                err.contains("tampered.json") && err.contains(field),
                "{what} ({}): the refusal names the file and {field}: {err}",
                args[0]
            );
        }
    }
}

#[test]
fn certificates_of_check_and_discrepancy_carry_a_digest_that_catches_edits() {
    let dir = tempfile::tempdir().unwrap();
    let points = dir.path().join("p.npy");
    let points = points.to_str().unwrap();
    let o = gartowen(&[
        "generate", "--seq", "sobol", "--dims", "2", "--log2-n", "6", "-o", points,
    ]);
    assert!(o.status.success());
    for command in [
        vec!["check", points, "--base", "2", "--json"],
        vec!["discrepancy", points, "--json"],
    ] {
        let o = gartowen(&command);
        assert!(o.status.success());
        let file = dir.path().join(format!("{}.json", command[0]));
        std::fs::write(&file, &o.stdout).unwrap();
        let file = file.to_str().unwrap();
        assert_eq!(
            gartowen(&["certificate", "check", file]).status.code(),
            Some(0)
        );
        let text = String::from_utf8(o.stdout).unwrap();
        let edited = text.replacen("\"points\": 64", "\"points\": 65", 1);
        assert_ne!(edited, text);
        std::fs::write(file, edited).unwrap();
        let o = gartowen(&["certificate", "check", file]);
        assert_eq!(o.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&o.stderr).contains("digest"));
    }
}

/// A shard of the every-word sweep is checked field by field too: its level, seed,
/// implementations, pieces and verdict; anything else edited is caught by the digest.
#[test]
fn a_tampered_sweep_shard_is_refused_naming_the_field() {
    let dir = tempfile::tempdir().unwrap();
    let shard = dir.path().join("w1.json");
    let shard = shard.to_str().unwrap();
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        "0",
        "--impl",
        "lk-hash",
        "--shard",
        "1/4096",
        "--json",
        shard,
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let o = gartowen(&["certificate", "check", shard]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let original: Value = serde_json::from_str(&std::fs::read_to_string(shard).unwrap()).unwrap();
    let edits: [(Edit, &str); 6] = [
        (|d| d["seeds"][0] = 5.into(), "seeds"),
        (
            |d| d["parameters"]["level"] = "quick".into(),
            "parameters.level",
        ),
        (
            |d| d["parameters"]["sweep"]["implementations"][0] = "lk-hash-2".into(),
            "parameters.sweep.implementations[0]",
        ),
        (|d| d["verdict"] = "fail".into(), "verdict"),
        (
            |d| d["result"]["pieces"][0]["implementation"] = "art-owen-2".into(),
            "result.pieces[0]",
        ),
        (
            |d| d["result"]["pieces"][0]["seconds"] = 99.0.into(),
            "digest",
        ),
    ];
    let tampered = dir.path().join("tampered.json");
    for (edit, field) in edits {
        let mut doc = original.clone();
        edit(&mut doc);
        std::fs::write(&tampered, doc.to_string()).unwrap();
        let o = gartowen(&["certificate", "check", tampered.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{field}: {err}");
        assert!(
            err.contains(&format!("tampered.json: {field}")),
            "{field}: {err}"
        );
    }
}

/// A fixed job matrix with more shards than implementations: the empty shards say so, their
/// certificates pass `certificate check`, and the merge of all of them is the whole run
/// (before, shard 3/3 of two was refused by both, naming `parameters.shard` with no reason).
#[test]
fn shards_beyond_the_implementations_are_empty_and_merge() {
    let dir = tempfile::tempdir().unwrap();
    for n in [3usize, 28] {
        let mut files = Vec::new();
        for i in 1..=n {
            let file = dir.path().join(format!("s{i}of{n}.json"));
            let shard = format!("{i}/{n}");
            let o = gartowen(&[
                "verify",
                "--impl",
                "lk-hash",
                "--impl",
                "digital-shift",
                "--shard",
                &shard,
                "--json",
                file.to_str().unwrap(),
            ]);
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(0), "{shard}: {err}");
            assert_eq!(err.contains("holds none of the 2"), i > 2, "{shard}: {err}");
            let audit = gartowen(&["certificate", "check", file.to_str().unwrap()]);
            assert_eq!(
                audit.status.code(),
                Some(0),
                "{shard}: {}",
                String::from_utf8_lossy(&audit.stderr)
            );
            files.push(file.to_str().unwrap().to_string());
        }
        let merged = dir.path().join(format!("merged{n}.json"));
        let mut args = vec!["verify", "--merge"];
        args.extend(files.iter().map(String::as_str));
        args.extend(["--json", merged.to_str().unwrap()]);
        let o = gartowen(&args);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let doc: Value = serde_json::from_str(&std::fs::read_to_string(&merged).unwrap()).unwrap();
        let names: Vec<&str> = doc["result"]["implementations"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["name"].as_str().unwrap())
            .collect();
        assert_eq!(names, ["lk-hash", "digital-shift"]);
        // Without its empty shard the set is incomplete, and that is named.
        let mut short = vec!["verify", "--merge"];
        short.extend(files[..n - 1].iter().map(String::as_str));
        let o = gartowen(&short);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(&format!("shard {n}/{n} is missing")), "{err}");
    }
}

/// Writes `doc` to `path` with a digest recomputed as a forger would (the digest is unkeyed).
fn forge(path: &Path, mut doc: Value) {
    doc.as_object_mut().unwrap().remove("digest");
    let digest = gartowen::certificate::content_digest(&doc);
    doc["digest"] = digest.into();
    std::fs::write(path, serde_json::to_string_pretty(&doc).unwrap()).unwrap();
}

/// Forgeries an unkeyed digest cannot stop, each refused by content (issue 59): the level
/// relabelled with its seed count (the sub-tests keep n = 2000), a failing verify report
/// relabelled a passing `check`, a full run relabelled quick, `pass` on a discrepancy.
#[test]
fn relabelled_certificates_with_recomputed_digests_are_refused_by_content() {
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n);
    let run = |level: &str, file: &str| {
        let out = path(file);
        let o = gartowen(&[
            "verify",
            "--impl",
            "lk-hash",
            "--impl",
            "none",
            "--claim",
            "owen",
            "--level",
            level,
            "--json",
            out.to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(1),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        serde_json::from_str::<Value>(&std::fs::read_to_string(out).unwrap()).unwrap()
    };
    let quick = run("quick", "quick.json");
    let full = run("full", "full.json");
    let points = path("p.npy");
    let points = points.to_str().unwrap();
    let o = gartowen(&[
        "generate", "--seq", "sobol", "--dims", "2", "--log2-n", "6", "-o", points,
    ]);
    assert!(o.status.success());
    let o = gartowen(&["discrepancy", points, "--json"]);
    let discrepancy: Value = serde_json::from_slice(&o.stdout).unwrap();
    type Forgery = (&'static str, Value, &'static str);
    let edit = |doc: &Value, f: &dyn Fn(&mut Value)| {
        let mut d = doc.clone();
        f(&mut d);
        d
    };
    let forgeries: Vec<Forgery> = vec![
        (
            "quick relabelled full with node_law_seeds changed",
            edit(&quick, &|d| {
                d["parameters"]["level"] = "full".into();
                d["parameters"]["node_law_seeds"] = 10_000.into();
            }),
            "parameters.level",
        ),
        (
            "a failing verify report relabelled a passing check",
            edit(&quick, &|d| {
                d["command"] = "check".into();
                d["verdict"] = "pass".into();
            }),
            "command",
        ),
        (
            "full relabelled quick",
            edit(&full, &|d| {
                d["parameters"]["level"] = "quick".into();
                d["parameters"]["node_law_seeds"] = 2000.into();
            }),
            "parameters.level",
        ),
        (
            "pass on a discrepancy certificate",
            edit(&discrepancy, &|d| d["verdict"] = "pass".into()),
            "verdict",
        ),
    ];
    // The untouched ones pass, re-digested or not.
    for (name, doc) in [
        ("quick", &quick),
        ("full", &full),
        ("discrepancy", &discrepancy),
    ] {
        let file = path(&format!("{name}-again.json"));
        forge(&file, doc.clone());
        let o = gartowen(&["certificate", "check", file.to_str().unwrap()]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    for (what, doc, field) in forgeries {
        let file = path("forged.json");
        forge(&file, doc);
        let o = gartowen(&["certificate", "check", file.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{what}: {err}");
        assert!(
            err.contains(&format!("{field}:")),
            "{what}: names {field}: {err}"
        );
    }
}
