//! A full disk on standard output is an error with a message and exit code 2, never a panic
//! (exit 101), in every command that prints results.

use std::process::{Command, Stdio};

fn run_to_dev_full(args: &[&str]) -> (Option<i32>, String) {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("/dev/full exists on Linux");
    let o = Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .stdout(Stdio::from(full))
        .output()
        .expect("run gartowen");
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn printing_to_a_full_disk_exits_2_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let pts = dir.path().join("p.hex");
    let made = Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args([
            "generate", "--seq", "sobol", "--dims", "2", "--n", "64", "-o",
        ])
        .arg(&pts)
        .status()
        .unwrap();
    assert!(made.success());
    let p = pts.to_str().unwrap();
    for args in [
        vec!["check", p, "--base", "2"],
        vec!["check", p, "--base", "2", "--json"],
        vec!["discrepancy", p],
        vec!["discrepancy", p, "--json"],
        vec![
            "inspect",
            "--scramble",
            "none",
            "--base",
            "2",
            "--width",
            "8",
        ],
        vec![
            "inspect",
            "--scramble",
            "none",
            "--base",
            "2",
            "--width",
            "8",
            "--json",
        ],
        vec!["verify", "--impl", "none"],
        vec!["generate", "--seq", "sobol", "--dims", "2", "--n", "4"],
    ] {
        let (code, err) = run_to_dev_full(&args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(err.contains("No space left on device"), "{args:?}: {err}");
    }
}
