//! `gartowen verify --list-requests`: the per-phase table honours --base, --width and
//! --max-dims, its JSON carries the same phases, and settings no program could have exit 2.

use crate::support::run;

#[test]
fn the_request_table_follows_the_settings_it_is_given() {
    let (code, out, err) = run(&["verify", "--list-requests"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("base-2 program of 32-bit words"), "{out}");
    assert!(
        out.contains("| nets |") && out.contains("127, 255"),
        "{out}"
    );
    assert!(out.contains("| quick |"), "{out}");
    // Four dimensions served: no phase asks beyond dimension 3.
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("requests.json");
    let (code, _, err) = run(&[
        "verify",
        "--list-requests",
        "--base",
        "3",
        "--width",
        "64",
        "--max-dims",
        "4",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let phases: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let phases = phases.as_array().unwrap();
    assert!(phases.iter().any(|p| p["phase"] == "laws"));
    for p in phases {
        assert!(
            p["dims"]
                .as_array()
                .unwrap()
                .iter()
                .all(|d| d.as_u64().unwrap() < 4),
            "{p}"
        );
        assert!(
            p["widths"].as_array().unwrap().iter().all(|w| w == 64),
            "{p}"
        );
    }
    // Nets in the program's own base only: Sobol's three dimensions, no Faure net of base 256.
    let (code, _, err) = run(&[
        "verify",
        "--list-requests",
        "--net-bases",
        "own",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let phases: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let nets = phases
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["phase"] == "nets")
        .unwrap();
    assert_eq!(nets["dims"], serde_json::json!([0, 1, 2]), "{nets}");
    for (args, fragment) in [
        (
            &["verify", "--list-requests", "--base", "512"][..],
            "--base 512",
        ),
        (
            &["verify", "--list-requests", "--width", "16"][..],
            "--width 16",
        ),
        (&["verify", "--base", "3"][..], "--base"),
        (&["verify", "--net-bases", "own"][..], "--net-bases"),
    ] {
        let (code, _, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(fragment), "{args:?}: {err}");
    }
}
