//! External programs cannot hold verify: one deadline governs each request, writes included,
//! so a program that never reads, stops reading or stops itself ends with the program-failure
//! status (3) within 2 × --timeout + 5 s at every level, and nothing of its process group is
//! left running.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// Compiles `programs/stalling.c` into `dir`.
fn stalling(dir: &Path) -> PathBuf {
    let out = dir.join("stalling");
    let status = Command::new("cc")
        .args(["-O2", "-o"])
        .arg(&out)
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/stalling.c"))
        .status()
        .expect("cc");
    assert!(status.success(), "compiling stalling.c failed");
    out
}

/// The pids of live (not zombie) processes whose process group is `group`.
fn members(group: u32) -> Vec<u32> {
    std::fs::read_dir("/proc")
        .unwrap()
        .flatten()
        .filter_map(|d| {
            let pid: u32 = d.file_name().to_str()?.parse().ok()?;
            let stat = std::fs::read_to_string(d.path().join("stat")).ok()?;
            // The fields after the command name: state, ppid, pgrp, ...
            let rest: Vec<&str> = stat.rsplit_once(") ")?.1.split(' ').collect();
            let live = rest.first()? != &"Z";
            (live && rest.get(2)?.parse::<u32>().ok()? == group).then_some(pid)
        })
        .collect()
}

/// The per-request deadline given to verify. A quarter second keeps the twelve stalled runs
/// short; a slow reply under load only makes the kill come sooner, with the same verdict.
const TIMEOUT_SECONDS: f64 = 0.25;

/// Runs gartowen with `args`; a run past `limit` is killed and fails the test (a hang must
/// fail, not hold the test binary).
fn run_bounded(args: &[String], limit: Duration, case: &str) -> std::process::Output {
    use std::io::Read;
    let mut child = Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Drain the pipes on threads, so that a chatty child cannot block on a full pipe.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let out = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = out.read_to_end(&mut v);
        v
    });
    let err = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = err.read_to_end(&mut v);
        v
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{case}: verify still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    std::process::Output {
        status,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
    }
}

#[test]
fn a_never_reading_a_stop_reading_and_a_self_stopping_program_end_in_time_at_every_level() {
    let dir = tempfile::tempdir().unwrap();
    let program = stalling(dir.path());
    for level in ["quick", "full", "exhaustive"] {
        for (mode, answers) in [("never", 0), ("stop", 111), ("sigstop", 111), ("stop", 3)] {
            let case = format!("{mode} after {answers} replies at --level {level}");
            let pidfile = dir.path().join(format!("{mode}-{answers}-{level}.pid"));
            let command = format!(
                "{} {mode} {answers} {}",
                program.display(),
                pidfile.display()
            );
            let mut args = vec![
                "verify".to_string(),
                "--external".into(),
                command,
                "--level".into(),
                level.into(),
                "--timeout".into(),
                TIMEOUT_SECONDS.to_string(),
            ];
            if level == "exhaustive" {
                args.extend(["--dims".into(), "0".into()]);
            }
            let start = Instant::now();
            let out = run_bounded(&args, Duration::from_secs(60), &case);
            let took = start.elapsed();
            let stdout = String::from_utf8_lossy(&out.stdout);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(3), "{case}: {stdout}{stderr}");
            assert!(
                took <= Duration::from_secs_f64(2.0 * TIMEOUT_SECONDS + 5.0),
                "{case}: took {took:?}"
            );
            let text = format!("{stdout}{stderr}");
            assert!(
                text.contains(&format!("within {TIMEOUT_SECONDS} s")) && text.contains("killed"),
                "{case}: the failure names the timeout: {text}"
            );
            let groups: Vec<u32> = std::fs::read_to_string(&pidfile)
                .unwrap()
                .lines()
                .map(|l| l.parse().unwrap())
                .collect();
            assert!(!groups.is_empty(), "{case}: the program never started");
            // The kill is done before verify exits; allow the kernel a moment to reap.
            let left = || {
                groups
                    .iter()
                    .flat_map(|&g| members(g))
                    .collect::<Vec<u32>>()
            };
            let waited = Instant::now();
            while !left().is_empty() && waited.elapsed() < Duration::from_secs(2) {
                std::thread::sleep(Duration::from_millis(20));
            }
            assert_eq!(left(), Vec::<u32>::new(), "{case}: left running");
        }
    }
}

/// Whether `pid` is a live (not zombie) process.
fn alive(pid: u32) -> bool {
    std::fs::read_to_string(format!("/proc/{pid}/stat"))
        .ok()
        .and_then(|s| s.rsplit_once(") ").map(|(_, rest)| !rest.starts_with('Z')))
        .unwrap_or(false)
}

/// A program whose grandchild double-forks into a new session and closes every descriptor
/// (out of reach of the group kill and the pipe scan) leaves nothing running once verify
/// exits: verify adopts orphaned descendants and ends them (before, the grandchild outlived
/// verify).
#[test]
fn a_double_forked_setsid_grandchild_does_not_outlive_verify() {
    let dir = tempfile::tempdir().unwrap();
    let program = dir.path().join("escaping");
    let status = Command::new("cc")
        .args(["-O2", "-o"])
        .arg(&program)
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/escaping.c"))
        .status()
        .expect("cc");
    assert!(status.success(), "compiling escaping.c failed");
    let pidfile = dir.path().join("escaped.pid");
    let args = vec![
        "verify".to_string(),
        "--external".into(),
        format!("{} {}", program.display(), pidfile.display()),
        "--claim".into(),
        "nested".into(),
    ];
    let out = run_bounded(&args, Duration::from_secs(60), "escaping");
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    // The identity is nested but not a bijection of the tree it claims nothing about: it
    // runs to the end either way; only what is left running matters here.
    assert!(matches!(out.status.code(), Some(0 | 1)), "{text}");
    let pids: Vec<u32> = std::fs::read_to_string(&pidfile)
        .unwrap()
        .lines()
        .map(|l| l.parse().unwrap())
        .collect();
    assert!(!pids.is_empty(), "the grandchild never started: {text}");
    let waited = Instant::now();
    while pids.iter().any(|&p| alive(p)) && waited.elapsed() < Duration::from_secs(2) {
        std::thread::sleep(Duration::from_millis(20));
    }
    let left: Vec<u32> = pids.into_iter().filter(|&p| alive(p)).collect();
    for &p in &left {
        // Do not leave it behind even when the assertion fails.
        let _ = Command::new("kill").args(["-9", &p.to_string()]).status();
    }
    assert_eq!(left, Vec::<u32>::new(), "left running after verify exited");
}
