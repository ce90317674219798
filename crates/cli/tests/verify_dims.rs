//! `verify --external --max-dims N`: a program that serves N dimensions gets a verdict on every
//! check those dimensions allow and "not run" on the rest, never a program failure; without
//! the flag its failure shows as `?` in the profile, never as deviations.

use crate::support::gartowen;
use serde_json::Value;

/// `examples/external/NAME.c` built with `-DSERVED_DIMS=dims` into `dir`.
fn build_serving(dir: &std::path::Path, name: &str, dims: u32) -> String {
    crate::support::build_c_example(dir, name, &[&format!("-DSERVED_DIMS={dims}")])
}

/// Runs `verify --external PROGRAM --base 2 EXTRA… --json` and returns (exit code, stdout,
/// the implementation's report).
fn verify(program: &str, extra: &[&str], dir: &std::path::Path) -> (Option<i32>, String, Value) {
    let cert = dir.join("cert.json");
    let _ = std::fs::remove_file(&cert);
    let mut args = vec!["verify", "--external", program, "--base", "2"];
    args.extend_from_slice(extra);
    args.extend_from_slice(&["--json", cert.to_str().unwrap()]);
    let o = gartowen(&args);
    let v: Value = serde_json::from_slice(&std::fs::read(&cert).unwrap()).unwrap();
    let out = String::from_utf8_lossy(&o.stdout).to_string();
    // Whatever ran or did not, the certificate passes its own audit.
    let check = gartowen(&["certificate", "check", cert.to_str().unwrap()]);
    assert_eq!(
        check.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&check.stderr)
    );
    (
        o.status.code(),
        out,
        v["result"]["implementations"][0].clone(),
    )
}

fn check<'a>(report: &'a Value, name: &str) -> &'a Value {
    report["checks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["check"] == name)
        .unwrap_or_else(|| panic!("no check {name}"))
}

fn profile_row<'a>(report: &'a Value, family: &str) -> &'a str {
    report["profile"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p[0] == family)
        .map(|p| p[1].as_str().unwrap())
        .unwrap_or_else(|| panic!("no profile row {family}"))
}

#[test]
fn a_program_of_four_dimensions_gets_verdicts_within_them_and_not_run_beyond() {
    let dir = tempfile::tempdir().unwrap();
    let program = build_serving(dir.path(), "owen_per_bit", 4);

    // Asked for dimension 4 and beyond, it exits 4: a program failure (exit 3), shown as
    // unmeasured (`?`), never as deviations.
    let (code, out, r) = verify(&program, &[], dir.path());
    assert_eq!(code, Some(3), "{out}");
    let failed = check(&r, "dimensions");
    assert_eq!(failed["verdict"], "fail");
    assert!(failed["detail"]
        .as_str()
        .unwrap()
        .starts_with("external program failed"));
    let tests = failed["tests"].as_array().unwrap();
    assert!(!tests.is_empty());
    assert!(tests
        .iter()
        .all(|t| t["not_run"] == "external program failed"
            && t["p_value"].is_null()
            && t["deviates"] == false));
    for (_, row) in r["profile"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p[0].clone(), p[1].clone()))
    {
        let row = row.as_str().unwrap();
        assert!(!row.contains('x'), "{row}");
    }
    assert!(profile_row(&r, "dimensions").contains('?'));

    // Told it serves 4, it passes every check 4 dimensions allow.
    let (code, out, r) = verify(&program, &["--max-dims", "4"], dir.path());
    assert_eq!(code, Some(0), "{out}");
    for name in [
        "injective",
        "function",
        "nested",
        "nets",
        "node-law",
        "pair-law",
        "flip-rank",
    ] {
        assert_eq!(check(&r, name)["verdict"], "pass", "{name}");
    }
    let nets = check(&r, "nets")["detail"].as_str().unwrap().to_string();
    assert!(nets.contains("faure:base=256 dims [0, 1, 2]"), "{nets}");
    assert!(!nets.contains("dims [0, 1, 255]"), "{nets}");
    let dims = check(&r, "dimensions");
    assert_eq!(dims["verdict"], "pass");
    let detail = dims["detail"].as_str().unwrap();
    assert!(
        detail.contains("not run: 3 of 7 sub-tests (needs dimension 7, beyond the 4 served"),
        "{detail}"
    );
    let tests = dims["tests"].as_array().unwrap();
    let ran: Vec<&str> = tests
        .iter()
        .filter(|t| t["not_run"].is_null())
        .map(|t| t["name"].as_str().unwrap())
        .collect();
    assert!(
        ran.iter()
            .any(|n| n.starts_with("dimensions 0..4 pairwise distinct")),
        "{ran:?}"
    );
    assert_eq!(
        ran.len(),
        4,
        "distinct + root pairs (0,1), (0,2), (1,2): {ran:?}"
    );
    assert!(profile_row(&r, "dimensions").starts_with("?-"));
    assert!(out.contains("not run"), "{out}");
    assert_eq!(r["checks"].as_array().unwrap().len(), 10);
}

#[test]
fn one_dimension_runs_the_laws_of_one_dimension_and_says_what_needs_two() {
    let dir = tempfile::tempdir().unwrap();
    let program = build_serving(dir.path(), "owen_per_bit", 1);
    let (code, out, r) = verify(
        &program,
        &[
            "--max-dims",
            "1",
            "--equivalent-to",
            "owen",
            "--equivalence-seeds",
            "100",
        ],
        dir.path(),
    );
    assert_eq!(code, Some(0), "{out}");
    for (name, needs) in [("flip-rank", 1), ("equivalent-to-owen", 1)] {
        let c = check(&r, name);
        assert_eq!(c["verdict"], "not-run", "{c}");
        assert!(
            c["detail"].as_str().unwrap().starts_with(&format!(
                "not run: needs dimension {needs}, beyond the 1 served"
            )),
            "{c}"
        );
    }
    let row = profile_row(&r, "flip-rank");
    assert!(row.starts_with('?') && !row.contains(['.', 'x']), "{row}");
    assert_eq!(check(&r, "node-law")["verdict"], "pass");
    assert_eq!(check(&r, "nets")["verdict"], "pass");
    let row = out
        .lines()
        .find(|l| l.contains("not run"))
        .unwrap_or_default();
    assert!(row.contains("not run"), "{out}");
}

#[test]
fn max_dims_zero_or_without_a_program_is_bad_usage() {
    for args in [
        &["verify", "--external", "true", "--max-dims", "0"][..],
        &["verify", "--max-dims", "4"][..],
    ] {
        let o = gartowen(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
    }
}
