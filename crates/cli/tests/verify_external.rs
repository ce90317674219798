//! End-to-end `gartowen verify --external`: the C examples judged with certificates, the
//! laws through `inspect`, a program that fails at start, signals reaching its helpers.

use crate::support::gartowen;
use std::process::Command;

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
