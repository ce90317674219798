//! End-to-end `gartowen verify`: exit codes, table and JSON report.

use crate::support::gartowen;
use std::process::Command;

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
    let imps = v["result"]["implementations"].as_array().unwrap();
    assert_eq!(imps.len(), 2);
    let names: Vec<&str> = imps[0]["checks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["check"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "inverse",
            "function",
            "nested",
            "nets",
            "node-law",
            "pair-law",
            "flip-rank",
            "collisions",
            "pair-lemma",
            "dimensions"
        ]
    );
    for check in imps[1]["checks"].as_array().unwrap().iter().skip(4) {
        assert_eq!(check["verdict"], "measured", "lk-hash claims no law");
    }
    assert_eq!(imps[0]["claim"], "marginal:symmetric");
    assert_eq!(imps[0]["checks"][4]["verdict"], "pass");
    assert_eq!(imps[0]["checks"][5]["verdict"], "measured");
    // Every law sub-test carries its p-value and power.
    let sub = &imps[0]["checks"][4]["tests"][0];
    assert!(sub["p_value"].is_number() && sub["power"].as_str().unwrap().len() > 10);

    // The declared listing names what the run reported, in the same order (the checks that
    // do not apply to a registry entry, `injective` and `expect`, left out).
    let listed = dir.path().join("list.json");
    let o = gartowen(&[
        "verify",
        "--list-checks",
        "--json",
        listed.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        o.stdout.is_empty(),
        "the listing goes to the JSON file only"
    );
    let list: serde_json::Value = serde_json::from_slice(&std::fs::read(&listed).unwrap()).unwrap();
    let declared: Vec<&str> = list["checks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .filter(|n| !["injective", "expect"].contains(n))
        .collect();
    assert_eq!(declared, names);
    let quick = &list["levels"][0];
    assert_eq!(quick["level"], "quick");
    let node_law = &imps[0]["checks"][4];
    assert_eq!(
        node_law["tests"][0]["n"], quick["law_seeds"],
        "node-law draws the plan's seeds at quick"
    );
}

#[test]
fn imitations_claiming_owen_fail_with_the_check_and_depth_named() {
    let o = gartowen(&[
        "verify",
        "--impl",
        "digital-shift",
        "--impl",
        "lk-hash",
        "--impl",
        "lk-hash-improved",
        "--impl",
        "owen-per-bit-hash",
        "--claim",
        "owen",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("3 with failures"), "{text}");
    assert!(
        text.contains("FAIL pair-law: deviation") && text.contains("siblings at depth 1"),
        "{text}"
    );
    assert!(text.contains("FAIL flip-rank: deviation"), "{text}");
    assert!(text.contains("profile (depth 0→)"), "{text}");
    // A claim that does not parse is bad usage.
    let o = gartowen(&["verify", "--impl", "lk-hash", "--claim", "owenish"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--claim owenish"));
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
    assert_eq!(
        without_timings(&path("merged.json")),
        without_timings(&path("all.json"))
    );
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

/// A verify certificate with its `seconds` fields and its digest (over them) cleared.
fn without_timings(file: &str) -> serde_json::Value {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    v["digest"] = serde_json::Value::Null;
    for imp in v["result"]["implementations"].as_array_mut().unwrap() {
        for c in imp["checks"].as_array_mut().unwrap() {
            c["seconds"] = serde_json::Value::Null;
        }
    }
    v
}

#[test]
fn shard_local_script_merges_four_shards_into_the_unsharded_certificate() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("shards");
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/ci/shard-local.sh"
    );
    let impls = [
        "--impl",
        "none",
        "--impl",
        "art-owen-2",
        "--impl",
        "lk-hash",
        "--impl",
        "owen-per-bit-hash",
        "--impl",
        "digital-shift",
        "--impl",
        "q-art-4",
    ];
    let o = Command::new("bash")
        .arg(script)
        .args(["4", out.to_str().unwrap()])
        .args(impls)
        .env("GARTOWEN", env!("CARGO_BIN_EXE_gartowen"))
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    for i in 1..=4 {
        assert!(out.join(format!("shard{i}.json")).exists());
    }
    let all = dir.path().join("all.json");
    let mut args = vec!["verify", "--json", all.to_str().unwrap()];
    args.extend(impls);
    assert!(gartowen(&args).status.success());
    assert_eq!(
        without_timings(out.join("merged.json").to_str().unwrap()),
        without_timings(all.to_str().unwrap())
    );
}

fn build_example(dir: &std::path::Path, name: &str) -> String {
    crate::support::build_c_example(dir, name, &[])
}

#[test]
fn external_programs_are_verified_with_a_certificate() {
    let dir = tempfile::tempdir().unwrap();
    let built = build_example(dir.path(), "owen_per_bit");
    // In a folder with a long name, so that the command is longer than the name column.
    let folder = dir
        .path()
        .join("a-folder-whose-name-is-longer-than-the-name-column");
    std::fs::create_dir(&folder).unwrap();
    let good = folder.join("owen_per_bit").to_str().unwrap().to_string();
    std::fs::copy(&built, &good).unwrap();
    let broken = build_example(dir.path(), "broken_hash");
    let cert = dir.path().join("ext.json");
    let o = gartowen(&[
        "verify",
        "--external",
        &good,
        "--base",
        "2",
        "--width",
        "64",
        "--expect",
        "owen-per-bit-hash",
        "--json",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    // The command line (a temporary path) is longer than the name column: it gets a line of
    // its own, and the claim stays in the claim column.
    let text = String::from_utf8_lossy(&o.stdout);
    let header = text.lines().next().unwrap();
    let at = header.find("claim").unwrap();
    let name_line = text
        .lines()
        .position(|l| l == format!("external:{good}"))
        .unwrap();
    let row = text.lines().nth(name_line + 1).unwrap();
    assert_eq!(row.find("owen"), Some(at), "{text}");
    assert!(row[..at].trim().is_empty(), "{text}");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&cert).unwrap()).unwrap();
    assert_eq!(v["schema"], "gartowen-certificate");
    assert_eq!(v["verdict"], "pass");
    assert_eq!(v["parameters"]["external"]["expect"], "owen-per-bit-hash");
    assert_eq!(v["inputs"][0]["kind"], "program");
    assert_eq!(
        v["inputs"][0]["checksum_fnv1a64"].as_str().unwrap().len(),
        16,
        "the program's bytes are checksummed"
    );
    let checks = v["result"]["implementations"][0]["checks"]
        .as_array()
        .unwrap();
    let expect = checks.last().unwrap();
    assert_eq!(expect["check"], "expect");
    assert_eq!(expect["verdict"], "pass");
    assert!(checks.iter().all(|c| c["verdict"] == "pass"));
    assert_eq!(v["parameters"]["external"]["claim"], "owen");

    let o = gartowen(&["verify", "--external", &broken, "--base", "2"]);
    assert_eq!(o.status.code(), Some(1));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("FAIL nested: NotNested at depth"), "{text}");

    // Bad usage: exit 2, a message naming the value, no certificate written.
    let none = dir.path().join("none.json");
    for args in [
        vec!["--width", "16"],
        // Base 3 is served by protocol version 2; 512 is no base at all.
        vec!["--base", "512"],
        vec!["--expect", "no-such-scrambler"],
        vec!["--expect", "art-owen-16p"],
        vec!["--timeout", "NaN"],
        // Once a panic (an Instant overflow) and a child left running; now refused.
        vec!["--timeout", "1e19"],
        vec!["--timeout", "1e20"],
        vec!["--timeout", "86401"],
    ] {
        let mut all = vec!["verify", "--external", good.as_str()];
        all.extend(args.iter().copied());
        all.extend(["--json", none.to_str().unwrap()]);
        let o = gartowen(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!o.stderr.is_empty());
        assert!(!none.exists());
    }
    let o = gartowen(&["verify", "--external", "/nonexistent/prog"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot start '/nonexistent/prog'"));
}

#[test]
fn inspect_runs_the_laws_on_an_external_program() {
    let dir = tempfile::tempdir().unwrap();
    let shift = build_example(dir.path(), "digital_shift");
    let good = build_example(dir.path(), "owen_per_bit");
    let o = gartowen(&[
        "inspect",
        "--external",
        &shift,
        "--base",
        "2",
        "--width",
        "32",
        "--laws",
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(text.contains("nested scramble in base 2"), "{text}");
    assert!(text.contains("pair-law    fail      depth 0→ -x"), "{text}");
    // Without --width an external program gets 32-bit words (the protocol's narrowest).
    let o = gartowen(&[
        "inspect",
        "--external",
        &good,
        "--base",
        "2",
        "--laws",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["report"]["width"], 32);
    assert_eq!(v["claim"], "owen");
    assert!(v["laws"]
        .as_array()
        .unwrap()
        .iter()
        .all(|c| c["verdict"] == "pass"));
    // The digital shift claiming only marginal translations is judged on that: it passes.
    let o = gartowen(&[
        "inspect",
        "--external",
        &shift,
        "--base",
        "2",
        "--width",
        "32",
        "--laws",
        "--claim",
        "marginal:translation",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
}

#[test]
fn a_program_that_starts_and_fails_exits_3_with_its_certificate_written() {
    // Run through `sh` so that no freshly written executable is exec'd (ETXTBSY races with
    // other tests forking while the file is open).
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("dies.sh");
    std::fs::write(&script, "echo 'out of coffee' >&2\nexit 7\n").unwrap();
    let command = format!("sh {}", script.display());
    let cert = dir.path().join("c.json");
    let o = gartowen(&[
        "verify",
        "--external",
        &command,
        "--json",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(3));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("external program failed") && err.contains("out of coffee"),
        "{err}"
    );
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&cert).unwrap()).unwrap();
    assert_eq!(v["verdict"], "fail");
    let o = gartowen(&[
        "inspect",
        "--external",
        &command,
        "--base",
        "2",
        "--width",
        "32",
    ]);
    assert_eq!(o.status.code(), Some(3));
}

/// A merge refuses what is not one complete run: the last shard missing (it once merged 25 of
/// 26 with exit 0), a shard from another run or tool version, a shard with a check removed
/// (once a panic, exit 101). Every refusal is exit 2 with the file named.
#[test]
fn merge_refuses_incomplete_or_mixed_shards() {
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n).to_str().unwrap().to_string();
    let run = |shard: &str, out: &str, extra: &[&str]| {
        let mut args = vec![
            "verify",
            "--impl",
            "lk-hash",
            "--impl",
            "digital-shift",
            "--shard",
            shard,
            "--json",
        ];
        let p = path(out);
        args.push(&p);
        args.extend_from_slice(extra);
        let o = gartowen(&args);
        assert!(o.status.code() == Some(0) || o.status.code() == Some(1));
    };
    run("1/2", "a1.json", &[]);
    run("2/2", "a2.json", &[]);
    run("2/2", "owen2.json", &["--claim", "owen"]);
    let merge = |files: &[String]| {
        let mut args = vec!["verify".to_string(), "--merge".to_string()];
        args.extend(files.iter().cloned());
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        gartowen(&refs)
    };
    let ok = merge(&[path("a2.json"), path("a1.json")]);
    assert!(ok.status.code() == Some(0) || ok.status.code() == Some(1));
    // The tail shard alone is missing: no gap in the indexes shows it, the record does.
    let o = merge(&[path("a1.json")]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("shard 2/2 is missing"));
    // Another run's shard (another claim) does not mix in.
    let o = merge(&[path("a1.json"), path("owen2.json")]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("owen2.json") && err.contains("claim_override"),
        "{err}"
    );
    // Tampered shards: another tool version, no shard record, a check removed.
    let text = std::fs::read_to_string(path("a2.json")).unwrap();
    let mut doc: serde_json::Value = serde_json::from_str(&text).unwrap();
    let mut edited = doc.clone();
    edited["tool_version"] = "0.0.9".into();
    std::fs::write(path("old.json"), edited.to_string()).unwrap();
    let mut edited = doc.clone();
    edited["parameters"]
        .as_object_mut()
        .unwrap()
        .remove("shard");
    std::fs::write(path("bare.json"), edited.to_string()).unwrap();
    doc["result"]["implementations"][0]["checks"]
        .as_array_mut()
        .unwrap()
        .remove(1);
    std::fs::write(path("cut.json"), doc.to_string()).unwrap();
    for (file, fragment) in [
        ("old.json", "made by gartowen 0.0.9"),
        ("bare.json", "no shard record"),
        ("cut.json", "has checks"),
    ] {
        let o = merge(&[path("a1.json"), path(file)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{file}: {err}");
        assert!(err.contains(fragment), "{file}: {err}");
    }
}

/// SIGTERM to `verify --external` ends the program's whole process group: a helper the
/// program started (here a `sleep`) does not outlive verify (it once kept running).
#[test]
fn a_signal_to_verify_ends_the_external_programs_helpers() {
    signal_ends_helper(|pidfile| format!("sleep 300 &\necho $! > {pidfile}\nwait\n"));
}

/// A helper that left the program's process group with `setsid` (so the group kill misses it)
/// but holds the program's pipes is found by its pipes and killed too.
#[test]
fn a_signal_to_verify_ends_a_helper_that_left_the_process_group() {
    signal_ends_helper(|pidfile| {
        format!("setsid sh -c 'echo $$ > {pidfile}; exec sleep 300' <&0 &\nwait\n")
    });
}

/// Starts `verify --external` on a script (its body made from the helper's pid file path),
/// waits for the helper's pid, sends SIGTERM to verify and asserts the helper ends.
fn signal_ends_helper(body: impl Fn(&str) -> String) {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let pidfile = dir.path().join("helper.pid");
    let script = dir.path().join("hang.sh");
    std::fs::write(
        &script,
        format!("#!/bin/sh\n{}", body(&pidfile.display().to_string())),
    )
    .unwrap();
    std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(["verify", "--external"])
        .arg(&script)
        .args(["--timeout", "120"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let started = std::time::Instant::now();
    let helper = loop {
        if let Ok(text) = std::fs::read_to_string(&pidfile) {
            if let Ok(pid) = text.trim().parse::<u32>() {
                break pid;
            }
        }
        assert!(started.elapsed().as_secs() < 30, "the helper never started");
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    let alive = |pid: u32| {
        // Gone, or a zombie waiting for its reaper, counts as ended.
        std::fs::read_to_string(format!("/proc/{pid}/stat"))
            .map(|s| !s.split(") ").nth(1).unwrap_or("").starts_with('Z'))
            .unwrap_or(false)
    };
    assert!(alive(helper));
    assert!(Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap()
        .success());
    child.wait().unwrap();
    let waited = std::time::Instant::now();
    while alive(helper) && waited.elapsed().as_secs() < 10 {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(!alive(helper), "helper {helper} outlived verify");
}

#[test]
fn equivalent_to_owen_is_a_check_with_its_seeds_margin_and_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("eq.json");
    let o = gartowen(&[
        "verify",
        "--impl",
        "owen-oracle:base=4",
        "--impl",
        "art-owen-t4",
        "--equivalent-to",
        "owen",
        "--equivalence-seeds",
        "4000",
        "--json",
        json.to_str().unwrap(),
    ]);
    // The translation-only ART variant is nested and fair node by node, but its coordinate
    // mean's variance is not Owen's: exit 1 with the check named.
    assert_eq!(o.status.code(), Some(1));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("equivalent-to-owen"), "{text}");
    assert!(
        text.contains("FAIL equivalent-to-owen: estimator variance"),
        "{text}"
    );
    let cert: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(cert["parameters"]["equivalence"]["seeds"], 4000);
    assert_eq!(cert["parameters"]["equivalence"]["margin"], 0.1);
    let verdict = |k: usize| {
        cert["result"]["implementations"][k]["checks"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["check"] == "equivalent-to-owen")
            .unwrap()["verdict"]
            .clone()
    };
    assert_eq!(verdict(0), "pass");
    assert_eq!(verdict(1), "fail");
    // Usage errors: a margin outside (0, 1), a margin without the check, an unknown reference,
    // too many seeds.
    for args in [
        &[
            "verify",
            "--impl",
            "lk-hash",
            "--equivalent-to",
            "owen",
            "--margin",
            "1.5",
        ][..],
        &["verify", "--impl", "lk-hash", "--margin", "0.2"][..],
        &["verify", "--impl", "lk-hash", "--equivalent-to", "sobol"][..],
        &[
            "verify",
            "--impl",
            "lk-hash",
            "--equivalent-to",
            "owen",
            "--equivalence-seeds",
            "9999999",
        ][..],
    ] {
        let o = gartowen(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!o.stderr.is_empty());
    }
}
