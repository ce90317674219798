//! `proofs/reusable.sh`, the rule by which `proofs/check.sh` reuses the theories that
//! `proofs/extract.sh` compiled: only a .vo newer than every source, and only when every theory
//! it requires is reused too. A wrong rule would let the proof check pass on stale libraries.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, SystemTime};

/// Writes `name` into `dir` with the given modification time.
fn file_at(dir: &Path, name: &str, text: &str, at: SystemTime) {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    std::fs::File::options()
        .write(true)
        .open(&path)
        .unwrap()
        .set_modified(at)
        .unwrap();
}

/// The theories reusable.sh names in `dir`, in the order given.
fn reusable(dir: &Path, theories: &[&str]) -> Vec<String> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("proofs/reusable.sh");
    let out = Command::new("bash")
        .arg(script)
        .arg(dir)
        .args(theories)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .split_whitespace()
        .map(String::from)
        .collect()
}

#[test]
fn only_fresh_libraries_whose_requirements_are_reused_are_reused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let old = SystemTime::now() - Duration::from_secs(3600);
    let new = old + Duration::from_secs(60);
    let theories = ["A", "B", "C", "D", "E"];
    // B requires A; D requires B (whose .vo is missing); E requires A and C.
    file_at(d, "A.v", "Lemma a : True. Proof. exact I. Qed.\n", old);
    file_at(d, "B.v", "From Gartowen Require Import A.\n", old);
    file_at(d, "C.v", "From Coq Require Import List.\n", old);
    file_at(d, "D.v", "From Gartowen Require Import B.\n", old);
    file_at(d, "E.v", "From Gartowen Require Import A C.\n", old);
    for t in ["A", "C", "D", "E"] {
        file_at(d, &format!("{t}.vo"), "compiled", new);
    }
    assert_eq!(reusable(d, &theories), ["A", "C", "E"]);
    // B compiled: D follows.
    file_at(d, "B.vo", "compiled", new);
    assert_eq!(reusable(d, &theories), theories);
    // A library older than its own source is stale, and so is every one that requires it.
    file_at(d, "C.vo", "compiled", old - Duration::from_secs(60));
    assert_eq!(reusable(d, &theories), ["A", "B", "D"]);
    // A source edited after the libraries were built makes all of them stale.
    file_at(d, "C.vo", "compiled", new);
    file_at(
        d,
        "B.v",
        "From Gartowen Require Import A.\n(* edited *)\n",
        new + Duration::from_secs(60),
    );
    assert!(reusable(d, &theories).is_empty());
}
