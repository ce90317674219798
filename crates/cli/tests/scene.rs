//! End-to-end `gartowen scene`: files, user layouts and scramblers, bad input refused before
//! any work with nothing written, and the baseline gate's exit codes.

use crate::support::gartowen;
use std::process::{Command, Output};

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The scene.json written into `out`.
fn scene_json(out: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("scene.json")).unwrap()).unwrap()
}

/// `scene --quick --scene roulette --out OUT`, which must succeed.
fn quick_roulette(out: &str) {
    let o = gartowen(&["scene", "--quick", "--scene", "roulette", "--out", out]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn a_quick_roulette_run_writes_its_report_and_the_baseline_gate_works() {
    let dir = tempfile::tempdir().unwrap();
    let path = |p: &str| dir.path().join(p).to_str().unwrap().to_string();
    quick_roulette(&path("a"));
    for f in ["scene.md", "scene.json", "scene-roulette.png"] {
        assert!(dir.path().join("a").join(f).exists(), "{f}");
    }
    assert!(!dir.path().join("a/scene-image-renders.png").exists());
    let md = std::fs::read_to_string(path("a/scene.md")).unwrap();
    assert!(md.contains("Base 16 against binary"), "{md}");
    assert!(md.contains("sz16+art-owen-16p"));
    let json = scene_json(&dir.path().join("a"));
    assert_eq!(json["schema"], "gartowen.scene-report");
    assert_eq!(json["results"].as_array().unwrap().len(), 6);

    // The same run against itself: deterministic, so no regression.
    let o = gartowen(&[
        "scene",
        "--quick",
        "--scene",
        "roulette",
        "--out",
        &path("b"),
        "--baseline",
        &path("a/scene.json"),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // A baseline twice as good with no noise: exit 1, named regressions.
    let mut better = json.clone();
    for r in better["results"].as_array_mut().unwrap() {
        for l in r["layouts"].as_array_mut().unwrap() {
            for x in l["rmse"].as_array_mut().unwrap() {
                *x = serde_json::json!(x.as_f64().unwrap() / 2.0);
            }
            for x in l["rmse_se"].as_array_mut().unwrap() {
                *x = serde_json::json!(0.0);
            }
        }
    }
    std::fs::write(path("better.json"), better.to_string()).unwrap();
    let o = gartowen(&[
        "scene",
        "--quick",
        "--scene",
        "roulette",
        "--out",
        &path("c"),
        "--baseline",
        &path("better.json"),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("REGRESSION roulette"));
}

#[test]
fn a_user_layout_and_scrambler_are_measured_alone() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("u");
    let o = gartowen(&[
        "scene",
        "--quick",
        "--scene",
        "direct",
        "--layout",
        "light=0,1;bsdf=6,7",
        "--sequence",
        "sobol",
        "--scramble",
        "owen-per-bit-hash",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let json = scene_json(&out);
    let results = json["results"].as_array().unwrap();
    assert_eq!(results.len(), 1);
    assert_eq!(results[0]["method"], "sobol+owen-per-bit-hash");
    let layouts = results[0]["layouts"].as_array().unwrap();
    assert_eq!(layouts.len(), 1);
    assert_eq!(layouts[0]["layout"], "light=0,1;bsdf=6,7");
}

#[test]
fn bad_arguments_exit_2_before_any_work_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("never");
    let out = out.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["--scene", "roulette", "--layout", "roulette=0;bounce=0,1"],
            "dimension 0",
        ),
        (&["--scene", "roulette", "--layout", "roulette=0"], "bounce"),
        (
            &["--scene", "roulette", "--layout", "lens=0;bounce=1,2"],
            "slots: roulette, bounce",
        ),
        (
            &["--layout", "roulette=0;bounce=1,2"],
            "exactly one --scene",
        ),
        (
            &["--scene", "teapot"],
            "scenes: roulette, direct, defocus, image",
        ),
        (
            &["--sequence", "sz4", "--scramble", "owen-oracle"],
            "16 dimensions",
        ),
        (&["--scramble", "no-such-scrambler"], "no-such-scrambler"),
        (&["--sequence", "halton"], "--sequence"),
        (&["--external", "/no/such/program"], "/no/such/program"),
        (&["--baseline", "/no/such/scene.json"], "cannot read"),
    ];
    for (args, needle) in cases {
        let mut all = vec!["scene", "--quick", "--out", out];
        all.extend_from_slice(args);
        let o = gartowen(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
        assert!(
            !std::path::Path::new(out).exists(),
            "{args:?} created --out"
        );
    }
}

#[test]
fn an_external_twin_measures_exactly_like_the_built_in() {
    let dir = tempfile::tempdir().unwrap();
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/external/owen_per_bit.c");
    let exe = dir.path().join("owen_per_bit");
    let status = Command::new("cc")
        .args(["-O2", "-o"])
        .arg(&exe)
        .arg(src)
        .status()
        .expect("cc");
    assert!(status.success());
    let out = dir.path().join("x");
    let o = gartowen(&[
        "scene",
        "--quick",
        "--scene",
        "defocus",
        "--sequence",
        "sobol",
        "--scramble",
        "owen-per-bit-hash",
        "--external",
        exe.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let json = scene_json(&out);
    let results = json["results"].as_array().unwrap();
    assert_eq!(results.len(), 2);
    assert_eq!(results[0]["method"], "sobol+owen-per-bit-hash");
    assert!(results[1]["method"]
        .as_str()
        .unwrap()
        .starts_with("sobol+external:"));
    // Same seeds, same words: every layout's RMSE is bit-identical.
    assert_eq!(results[0]["layouts"], results[1]["layouts"]);
}

#[test]
fn a_baseline_that_compares_nothing_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = |p: &str| dir.path().join(p).to_str().unwrap().to_string();
    quick_roulette(&path("a"));
    // Another scene, or only other methods: nothing in common.
    for args in [
        &["--scene", "defocus"][..],
        &[
            "--scene",
            "roulette",
            "--scramble",
            "owen-per-bit-hash",
            "--sequence",
            "sobol",
        ][..],
    ] {
        let (out, base) = (path("b"), path("a/scene.json"));
        let mut all = vec!["scene", "--quick", "--out", &out, "--baseline", &base];
        all.extend_from_slice(args);
        let o = gartowen(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("nothing"), "{}", stderr(&o));
        assert!(!dir.path().join("b").exists());
    }
}
