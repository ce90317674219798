//! End-to-end `gartowen discrepancy`: JSON fields, methods agree, bad input exits 2.

use crate::support::gartowen;
use std::process::Output;

fn json(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|_| panic!("{}", String::from_utf8_lossy(&o.stderr)))
}

#[test]
fn methods_agree_and_json_carries_the_fields() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("s.npy");
    let f = f.to_str().unwrap();
    let g = [
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "3",
        "--log2-n",
        "9",
        "--scramble",
        "owen-oracle",
        "--format",
        "npy",
        "-o",
        f,
    ];
    assert!(gartowen(&g).status.success());
    for kind in ["l2star", "cd", "wd", "gl2"] {
        let exact = json(&gartowen(&[
            "discrepancy",
            f,
            "--kind",
            kind,
            "--method",
            "exact",
            "--json",
        ]));
        let comp = json(&gartowen(&[
            "discrepancy",
            f,
            "--kind",
            kind,
            "--method",
            "compensated",
            "--json",
        ]));
        let auto = json(&gartowen(&["discrepancy", f, "--kind", kind, "--json"]));
        let (e, c) = (
            exact["result"]["value"].as_f64().unwrap(),
            comp["result"]["value"].as_f64().unwrap(),
        );
        assert!(((c - e) / e).abs() <= 1e-12, "{kind}: {c} vs {e}");
        assert_eq!(exact["result"]["squared"], true);
        assert_eq!(exact["result"]["kind"], kind);
        assert_eq!(exact["result"]["method"], "exact");
        let r = exact["result"]["exact"].as_str().unwrap();
        let (num, den) = r.split_once('/').unwrap();
        let approx = num.parse::<f64>().unwrap() / den.parse::<f64>().unwrap();
        assert!(
            ((approx - e) / e).abs() < 1e-12,
            "the rational string is the value"
        );
        assert!(auto["result"]["rel_error_bound"].as_f64().unwrap() <= 1e-12);
        assert!(auto["result"]["seconds"].as_f64().unwrap() >= 0.0);
    }
    let root = json(&gartowen(&["discrepancy", f, "--root", "--json"]));
    let sq = json(&gartowen(&["discrepancy", f, "--json"]));
    assert_eq!(root["result"]["squared"], false);
    let (r, s) = (
        root["result"]["value"].as_f64().unwrap(),
        sq["result"]["value"].as_f64().unwrap(),
    );
    assert!((r * r - s).abs() <= 1e-15 * s);
    let pairs = json(&gartowen(&["discrepancy", f, "--pairs", "all", "--json"]));
    assert_eq!(pairs["result"]["pairs"].as_array().unwrap().len(), 3);
}

#[test]
fn bad_input_and_usage_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "0.5,nan\n").unwrap();
    let ok = dir.path().join("ok.csv");
    std::fs::write(&ok, "0.5,0.25,0.125\n0.75,0.5,0.0\n").unwrap();
    for args in [
        vec!["discrepancy", bad.to_str().unwrap()],
        vec!["discrepancy", ok.to_str().unwrap(), "--kind", "md"],
        vec!["discrepancy", ok.to_str().unwrap(), "--method", "fast"],
        vec!["discrepancy", "/nonexistent.npy"],
    ] {
        let o = gartowen(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!String::from_utf8_lossy(&o.stderr).contains("panicked"));
    }
    // The message the library's vocabulary gives, the same in Python.
    let o = gartowen(&["discrepancy", ok.to_str().unwrap(), "--kind", "md"]);
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("unknown kind 'md'; use l2star, cd, wd or gl2")
    );
}

/// High dimensions: c0 = (4/3)^d overflows f64 and 3^-d underflows. No panic (WD and GL2 once
/// panicked at "finite"), no false claim ("0 … rel. error ≤ 0"): the value is reported with
/// no relative bound, the exact rational in the JSON.
#[test]
fn values_outside_the_f64_range_are_reported_honestly() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("wide.csv");
    let row: Vec<String> = (0..2600)
        .map(|k| format!("{}", ((k * 7919) % 1024) as f64 / 1024.0))
        .collect();
    std::fs::write(&path, row.join(",") + "\n").unwrap();
    let file = path.to_str().unwrap();
    for kind in ["wd", "gl2", "l2star"] {
        let out = gartowen(&["discrepancy", file, "--kind", kind, "--json"]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{kind}: {err}");
        let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let r = &doc["result"];
        assert_eq!(r["rel_error_bound"], serde_json::Value::Null, "{kind}: {r}");
        assert!(r["exact"].is_string(), "{kind}");
        let text = gartowen(&["discrepancy", file, "--kind", kind]);
        let line = String::from_utf8_lossy(&text.stdout);
        assert!(line.contains("outside the f64 range"), "{kind}: {line}");
        assert!(!line.contains("rel. error ≤ 0"), "{line}");
    }
    // CD stays in range at this size: a normal value with its bound.
    let out = gartowen(&["discrepancy", file, "--kind", "cd", "--json"]);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(doc["result"]["rel_error_bound"].as_f64().unwrap() <= 1e-12);
}

/// Writes `n` scrambled Sobol points in `dims` dimensions (float64 .npy) into `dir`.
fn points(dir: &std::path::Path, n: u64, dims: u32) -> String {
    let f = dir.join(format!("p{n}x{dims}.npy"));
    let f = f.to_str().unwrap().to_string();
    let (n, dims) = (n.to_string(), dims.to_string());
    let o = gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        &dims,
        "--n",
        &n,
        "--scramble",
        "owen-oracle",
        "--seed",
        "1",
        "-o",
        &f,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    f
}

/// Long jobs are estimated before they start: past --max-seconds they are refused (exit 2,
/// naming the estimate and the flag), and the estimate scales with N² × d.
#[test]
fn a_job_past_max_seconds_is_refused_before_it_starts() {
    let dir = tempfile::tempdir().unwrap();
    let f = points(dir.path(), 65_536, 16);
    // About 23 minutes exactly: refused at the default limit, at once.
    let started = std::time::Instant::now();
    let o = gartowen(&["discrepancy", &f, "--method", "exact"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("estimated")
            && err.contains("--max-seconds 600")
            && err.contains("compensated"),
        "{err}"
    );
    assert!(started.elapsed().as_secs() < 30);
    // A tight limit refuses even the compensated pass; a bad limit is named.
    let o = gartowen(&[
        "discrepancy",
        &f,
        "--method",
        "compensated",
        "--max-seconds",
        "0.5",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--max-seconds 0.5"));
    for bad in ["--max-seconds=0", "--max-seconds=-3", "--max-seconds=NaN"] {
        let o = gartowen(&["discrepancy", &f, bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("--max-seconds"));
    }
}

/// `auto` on float64 points in 6 dimensions: the compensated bound is above 1e-12 there, and
/// the exact method would take about half a minute, so auto keeps the compensated value and
/// reports its proven bound (it once took the exact path: 953 s at 2^16 points).
#[test]
fn auto_keeps_the_compensated_value_with_its_bound_when_exact_would_take_long() {
    let dir = tempfile::tempdir().unwrap();
    let f = points(dir.path(), 16_384, 6);
    let o = gartowen(&["discrepancy", &f, "--json"]);
    let r = &json(&o)["result"];
    assert_eq!(r["method"], "compensated", "{r}");
    let bound = r["rel_error_bound"].as_f64().unwrap();
    assert!(bound > 1e-12 && bound < 1e-6, "{bound}");
    // A small set of the same kind still gets the exact value.
    let f = points(dir.path(), 1024, 6);
    let o = gartowen(&["discrepancy", &f, "--json"]);
    let r = &json(&o)["result"];
    assert!(
        r["method"] == "exact" || r["rel_error_bound"].as_f64().unwrap() <= 1e-12,
        "{r}"
    );
}
