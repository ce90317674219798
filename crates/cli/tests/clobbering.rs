//! Inputs are never outputs: an output naming an input file (directly, through a link or a
//! hard link) or another output is refused with exit 2 before anything is written, and the
//! input is left byte for byte.

use crate::support::gartowen;
use std::path::Path;
use std::process::Output;

fn refused(o: &Output, fragment: &str) {
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(fragment), "{stderr}");
    assert!(!stderr.contains("panicked"));
}

fn points(dir: &Path) -> (std::path::PathBuf, Vec<u8>) {
    let p = dir.join("points.npy");
    let o = gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "2",
        "--log2-n",
        "6",
        "-o",
        p.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let bytes = std::fs::read(&p).unwrap();
    (p, bytes)
}

#[test]
fn check_and_scramble_never_write_over_their_input() {
    let dir = tempfile::tempdir().unwrap();
    let (p, bytes) = points(dir.path());
    let s = p.to_str().unwrap();
    refused(
        &gartowen(&["check", s, "--base", "2", "--junit", s]),
        "is the input FILE",
    );
    let hard = dir.path().join("hard.npy");
    std::fs::hard_link(&p, &hard).unwrap();
    refused(
        &gartowen(&[
            "scramble",
            s,
            "--scramble",
            "lk-hash",
            "-o",
            hard.to_str().unwrap(),
        ]),
        "writing it would destroy the input",
    );
    #[cfg(unix)]
    {
        let link = dir.path().join("link.npy");
        std::os::unix::fs::symlink(&p, &link).unwrap();
        refused(
            &gartowen(&["check", link.to_str().unwrap(), "--base", "2", "--junit", s]),
            "--junit",
        );
    }
    assert_eq!(std::fs::read(&p).unwrap(), bytes, "the input is intact");
    // A distinct output path is accepted.
    let out = dir.path().join("c.xml");
    let o = gartowen(&[
        "check",
        s,
        "--base",
        "2",
        "--t",
        "0",
        "--junit",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
}

#[test]
fn two_outputs_on_one_path_and_a_baseline_in_the_output_folder_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let both = dir.path().join("v.out");
    let b = both.to_str().unwrap();
    refused(
        &gartowen(&["verify", "--impl", "lk-hash", "--json", b, "--junit", b]),
        "are one file",
    );
    assert!(!both.exists(), "nothing was written");
    let out = dir.path().join("rep");
    std::fs::create_dir(&out).unwrap();
    let baseline = out.join("report.json");
    std::fs::write(&baseline, b"{}").unwrap();
    refused(
        &gartowen(&[
            "report",
            "--out",
            out.to_str().unwrap(),
            "--baseline",
            baseline.to_str().unwrap(),
            "--quick",
        ]),
        "rewrites",
    );
    assert_eq!(std::fs::read(&baseline).unwrap(), b"{}");
    let merged = dir.path().join("m.json");
    std::fs::write(&merged, b"{}").unwrap();
    let m = merged.to_str().unwrap();
    refused(
        &gartowen(&["verify", "--merge", m, "--json", m]),
        "is the input --merge",
    );
}
