//! `verify` in bases that are not powers of two: the base-b C examples over version 2 of the
//! protocol (base-b digit integers) and the built-in base-b oracle. A true Owen scramble passes
//! in bases 3 and 5; a random shift per node fails `owen` at the root and passes its own claim;
//! the per-digit permutation of scrambled Halton fails the joint laws. Every certificate passes
//! its own audit.

use crate::support::{build_c_example, gartowen};
use serde_json::Value;

/// Runs `verify ARGS… --json` and returns (exit code, stderr, the first implementation's
/// report), after checking the certificate passes `certificate check`.
fn verify(args: &[&str], dir: &std::path::Path) -> (Option<i32>, String, Value) {
    let cert = dir.join("cert.json");
    let _ = std::fs::remove_file(&cert);
    let mut all = vec!["verify"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--json", cert.to_str().unwrap()]);
    let o = gartowen(&all);
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    let v: Value = serde_json::from_slice(&std::fs::read(&cert).unwrap())
        .unwrap_or_else(|e| panic!("{e}: {err}"));
    let audit = gartowen(&["certificate", "check", cert.to_str().unwrap()]);
    assert_eq!(
        audit.status.code(),
        Some(0),
        "{}{}",
        String::from_utf8_lossy(&audit.stdout),
        String::from_utf8_lossy(&audit.stderr)
    );
    (
        o.status.code(),
        err,
        v["result"]["implementations"][0].clone(),
    )
}

/// The verdict of every check, by name.
fn verdicts(report: &Value) -> Vec<(String, String)> {
    report["checks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["check"].as_str().unwrap().into(),
                c["verdict"].as_str().unwrap().into(),
            )
        })
        .collect()
}

/// Every check passes but `fails`; flip-rank is not run.
fn assert_verdicts(report: &Value, fails: &[&str]) {
    for (check, verdict) in verdicts(report) {
        let want = match check.as_str() {
            "flip-rank" => "not-run",
            c if fails.contains(&c) => "fail",
            _ => "pass",
        };
        assert_eq!(verdict, want, "{check}: {report}");
    }
}

#[test]
fn base_3_and_5_owen_pass_and_the_imitations_fail_the_documented_laws() {
    let dir = tempfile::tempdir().unwrap();
    let owen = build_c_example(dir.path(), "owen_radix", &[]);
    let cyclic = build_c_example(dir.path(), "cyclic_shift_radix", &[]);
    let halton = build_c_example(dir.path(), "halton_permutation", &[]);
    for base in ["3", "5"] {
        let (code, err, r) = verify(&["--external", &owen, "--base", base], dir.path());
        assert_eq!(code, Some(0), "{err}");
        assert_eq!(r["base"], base.parse::<u32>().unwrap());
        assert_verdicts(&r, &[]);
    }
    let (code, _, r) = verify(&["--external", &cyclic, "--base", "3"], dir.path());
    assert_eq!(code, Some(1));
    assert_verdicts(&r, &["node-law", "pair-lemma"]);
    let node_law = r["checks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["check"] == "node-law");
    let detail = node_law.unwrap()["detail"].as_str().unwrap();
    assert!(
        detail.contains("depth 0") && detail.contains("S_3"),
        "{detail}"
    );
    let own = [
        "--external",
        &cyclic,
        "--base",
        "3",
        "--claim",
        "independent:cyclic",
    ];
    let (code, _, r) = verify(&own, dir.path());
    assert_eq!(code, Some(0));
    assert_verdicts(&r, &[]);
    let (code, _, r) = verify(&["--external", &halton, "--base", "3"], dir.path());
    assert_eq!(code, Some(1));
    assert_verdicts(&r, &["pair-law", "collisions", "pair-lemma"]);
}

#[test]
fn a_version_1_program_asked_for_base_3_fails_naming_the_version_and_bad_bases_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let binary = build_c_example(dir.path(), "owen_nested", &[]);
    let o = gartowen(&["verify", "--external", &binary, "--base", "3"]);
    assert_eq!(o.status.code(), Some(3));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("unsupported request (version 2"), "{err}");
    for (args, says) in [
        (vec!["--base", "1"], "--base 1"),
        (vec!["--base", "512"], "--base 512"),
        (
            vec!["--base", "3", "--claim", "marginal:affine"],
            "in base 3",
        ),
        (
            vec!["--base", "3", "--expect", "art-owen-2"],
            "--expect art-owen-2",
        ),
    ] {
        let mut all = vec!["verify", "--external", &binary];
        all.extend_from_slice(&args);
        let o = gartowen(&all);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

#[test]
fn the_built_in_base_3_oracle_passes_and_its_per_depth_mutant_fails_the_pair_law() {
    let dir = tempfile::tempdir().unwrap();
    let (code, _, r) = verify(&["--impl", "owen-oracle:base=3"], dir.path());
    assert_eq!(code, Some(0));
    assert_verdicts(&r, &[]);
    let per_depth = ["--impl", "owen-oracle:per-depth:base=3", "--claim", "owen"];
    let (code, _, r) = verify(&per_depth, dir.path());
    assert_eq!(code, Some(1));
    assert_verdicts(&r, &["pair-law", "collisions", "pair-lemma"]);
}

#[test]
fn version_2_words_stay_below_b_to_the_m_at_full_level_and_in_64_bit_frames() {
    // Before: a second batch of injectivity words (64-bit words cut to 32-bit frames) carried
    // words ≥ 3^20, and x and x − 3^20 collided; with `--width 64` 20-digit words were judged
    // against 3^20 while 40-digit frames were sent. A true bijection must pass both ways.
    let dir = tempfile::tempdir().unwrap();
    let owen = build_c_example(dir.path(), "owen_radix", &[]);
    for args in [
        vec!["--base", "3", "--level", "full"],
        vec!["--base", "3", "--width", "64"],
        vec!["--base", "5", "--width", "64"],
    ] {
        let mut all = vec!["--external", owen.as_str()];
        all.extend_from_slice(&args);
        let (code, err, r) = verify(&all, dir.path());
        assert_eq!(code, Some(0), "{args:?}: {err}\n{r}");
        assert_verdicts(&r, &[]);
    }
}

#[test]
fn a_reply_word_at_b_to_the_m_is_named_as_garbage() {
    // The largest word answered with 3^20, one past the last: every reply is range-checked,
    // so the `function` check's request of the largest word fails the program (before, the
    // run passed).
    let dir = tempfile::tempdir().unwrap();
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs");
    let out = dir.path().join("radix_overflow");
    let include = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/external");
    let status = std::process::Command::new("cc")
        .args(["-O2", "-I"])
        .arg(&include)
        .arg("-o")
        .arg(&out)
        .arg(src.join("radix_overflow.c"))
        .status()
        .expect("cc");
    assert!(status.success());
    let o = gartowen(&["verify", "--external", out.to_str().unwrap(), "--base", "3"]);
    let text = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert_ne!(o.status.code(), Some(0), "{text}");
    assert!(
        text.contains("reply word") && text.contains("not below 3486784401 = 3^20"),
        "{text}"
    );
    // The program's failure fails the checks that asked it, not flip-rank, which does not
    // apply in base 3 (before, it was shown as FAIL with the program's failure).
    assert!(!text.contains("FAIL flip-rank"), "{text}");
    assert!(
        text.contains("flip-rank: not run: not applicable in base 3"),
        "{text}"
    );
}

/// `--list-requests` counts what a version 2 run sends: a program counting the request
/// headers and words it reads agrees with the whole-level row (before, base 3 listed 1.13 M
/// words and 1.99 M were sent: a second batch of 64-bit injectivity words went uncounted).
#[test]
fn the_request_table_counts_what_a_base_b_run_sends() {
    let dir = tempfile::tempdir().unwrap();
    let program = dir.path().join("counting_radix");
    let manifest = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let status = std::process::Command::new("cc")
        .args(["-O2", "-I"])
        .arg(manifest.join("../../examples/external"))
        .arg("-o")
        .arg(&program)
        .arg(manifest.join("tests/programs/counting_radix.c"))
        .status()
        .expect("cc");
    assert!(status.success());
    for (base, width) in [("3", "32"), ("5", "64")] {
        let counts = dir.path().join(format!("counts-{base}-{width}"));
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_gartowen"))
            .args([
                "verify",
                "--external",
                program.to_str().unwrap(),
                "--base",
                base,
            ])
            .args(["--width", width])
            .env("COUNT_FILE", &counts)
            .output()
            .unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let sent = std::fs::read_to_string(&counts).unwrap();
        let listed = gartowen(&[
            "verify",
            "--list-requests",
            "--base",
            base,
            "--width",
            width,
        ]);
        let table = String::from_utf8_lossy(&listed.stdout).to_string();
        let row = table
            .lines()
            .find(|l| l.starts_with("| quick |"))
            .unwrap_or_else(|| panic!("{table}"));
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        assert_eq!(
            format!("{} {}", cells[2], cells[3]),
            sent.trim(),
            "base {base}, width {width}: listed (requests words) vs sent"
        );
    }
}

#[test]
fn verify_help_names_the_bases_beyond_powers_of_two() {
    let o = gartowen(&["verify", "--help"]);
    let help = String::from_utf8_lossy(&o.stdout);
    assert!(
        help.contains("3..=65535") && help.contains("version 2"),
        "{help}"
    );
    assert!(!help.contains("(a power of two, 2..=256)"), "{help}");
}
