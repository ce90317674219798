//! End-to-end `gartowen verify --level exhaustive --dims`: the every-word sweep, its shards and
//! their merge, external programs, and the refusals.

use crate::support::gartowen;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A sweep shard of lk-hash written to `dir/name`.
fn shard(dir: &Path, name: &str, dims: &str, shard: &str) -> String {
    let path = dir.join(name).display().to_string();
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        dims,
        "--impl",
        "lk-hash",
        "--shard",
        shard,
        "--json",
        &path,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    path
}

/// Compiles examples/external/NAME.c into `dir`.
fn example(dir: &Path, name: &str) -> PathBuf {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/external")
        .join(format!("{name}.c"));
    let out = dir.join(name);
    let status = Command::new("cc")
        .args(["-O2", "-Wall", "-Werror", "-o"])
        .arg(&out)
        .arg(src)
        .status()
        .expect("a C compiler `cc`");
    assert!(status.success());
    out
}

#[test]
fn two_shards_of_a_dimension_merge_into_a_certificate_of_every_32_bit_word() {
    let dir = tempfile::tempdir().unwrap();
    let a = shard(dir.path(), "a.json", "2", "1/2");
    let b = shard(dir.path(), "b.json", "2", "2/2");
    let all = dir.path().join("all.json");
    let xml = dir.path().join("all.xml");
    let o = gartowen(&[
        "verify",
        "--merge",
        &b,
        &a,
        "--json",
        all.to_str().unwrap(),
        "--junit",
        xml.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("=> bijective and nested on all 2^32 words, dimension 2, base 2"));
    // The merge writes the JUnit it is asked for (CI dashboards read it): a case per piece.
    let junit = std::fs::read_to_string(&xml).expect("the merge writes --junit");
    assert!(junit.contains("testsuite name=\"lk-hash\""), "{junit}");
    assert!(
        junit.contains("dim 2 chunks 0..2048") && junit.contains("dim 2 chunks 2048..4096"),
        "{junit}"
    );
    assert!(!junit.contains("<failure"), "{junit}");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&all).unwrap()).unwrap();
    assert_eq!(v["verdict"], "pass");
    let imp = &v["result"]["implementations"][0];
    assert_eq!(imp["implementation"], "lk-hash");
    assert_eq!(imp["dims"][0]["words"], 4_294_967_296u64);
    assert_eq!(imp["dims"][0]["dim"], 2);
    // The law of each depth k, tallied over all 2^k nodes of the depth.
    let laws = imp["dims"][0]["node_laws"].as_array().unwrap();
    assert_eq!(laws.len(), 22);
    for (k, law) in laws.iter().enumerate() {
        assert_eq!(law["depth"], k as u64, "{law}");
        assert_eq!(law["nodes"], 1u64 << k, "{law}");
    }
    // A shard alone certifies nothing beyond its pieces.
    let one: serde_json::Value = serde_json::from_slice(&std::fs::read(&a).unwrap()).unwrap();
    assert!(one["result"]["implementations"]
        .as_array()
        .unwrap()
        .is_empty());
    assert_eq!(
        one["result"]["pieces"][0]["piece"]["chunks"],
        serde_json::json!([0, 2048])
    );
}

#[test]
fn a_missing_doubled_or_foreign_shard_is_refused_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    // One chunk (2^20 words) per shard: 4096 shards of one dimension.
    let s1 = shard(dir.path(), "1.json", "2", "1/4096");
    let s2 = shard(dir.path(), "2.json", "2", "2/4096");
    let other = shard(dir.path(), "o.json", "3", "2/4096");
    for (files, says) in [
        (vec![&s1, &s2], "shard 3/4096 is missing (2 of 4096 given)"),
        (vec![&s1, &s1], "shard 1/4096 is given twice"),
        (vec![&s1, &other], "is a shard of another sweep"),
    ] {
        let mut args = vec!["verify", "--merge"];
        args.extend(files.iter().map(|s| s.as_str()));
        let o = gartowen(&args);
        assert_eq!(o.status.code(), Some(2), "{says}: {}", stderr(&o));
        assert!(stderr(&o).contains(says), "{says}: {}", stderr(&o));
    }
    // A shard's pieces and counts are printed.
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        "2",
        "--impl",
        "lk-hash",
        "--shard",
        "4096/4096",
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        stdout(&o).contains("lk-hash dim 2 chunks 4095..4096 of 4096: no failure in 1048576 words")
    );
}

#[test]
fn bad_ranges_levels_and_64_bit_words_are_refused_before_anything_runs() {
    for (args, says) in [
        (vec!["--dims", "3..1"], "is not A..B"),
        (vec!["--dims", "x"], "is not A..B"),
        (vec!["--dims", "0..-2"], "is not A..B"),
        (
            vec!["--dims", "0", "--level", "quick"],
            "--level exhaustive",
        ),
        (vec!["--dims", "0"], "--level exhaustive"),
        (vec!["--dims", "0", "--shard", "0/4"], "is not I/N"),
        (vec!["--dims", "0", "--impl", "no-such"], "no-such"),
    ] {
        let mut all = vec!["verify"];
        if !args.contains(&"--level") && args != ["--dims", "0"] {
            all.extend(["--level", "exhaustive"]);
        }
        all.extend(args);
        let o = gartowen(&all);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(says), "{all:?}: {}", stderr(&o));
    }
    // Refused before the program is started: the missing program is never looked for.
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        "0",
        "--external",
        "/no/such/program",
        "--width",
        "64",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("cannot be enumerated"),
        "{}",
        stderr(&o)
    );
    assert!(!stderr(&o).contains("cannot start"));
    // --help states the refusal.
    let help = stdout(&gartowen(&["verify", "--help"]));
    assert!(help.contains("64-bit words are refused") && help.contains("--dims"));
}

#[test]
fn external_programs_are_swept_over_pipes_and_a_broken_one_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let lk = example(dir.path(), "lk_hash");
    let broken = example(dir.path(), "broken_hash");
    let run_with = |program: &Path, shard: &str, extra: &[&str]| {
        let mut args = vec![
            "verify",
            "--level",
            "exhaustive",
            "--dims",
            "1",
            "--external",
            program.to_str().unwrap(),
            "--base",
            "2",
            "--shard",
            shard,
        ];
        args.extend_from_slice(extra);
        gartowen(&args)
    };
    let run = |program: &Path, shard: &str| run_with(program, shard, &[]);
    let o = run(&lk, "7/4096");
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains("chunks 6..7 of 4096: no failure in 1048576 words"));
    let o = run(&broken, "7/4096");
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("FAIL not nested: inputs 0x600000 and 0x600001 share 31 digit(s)"),
        "{}",
        stdout(&o)
    );
    // Its JUnit names the failing piece and the first failing words.
    let xml = dir.path().join("broken.xml");
    let o = run_with(&broken, "7/4096", &["--junit", xml.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    let junit = std::fs::read_to_string(&xml).unwrap();
    assert!(
        junit.contains("<failure")
            && junit.contains("dim 1 chunks 6..7: not nested: inputs 0x600000"),
        "{junit}"
    );
    // A program that dies is an external failure (exit 3), not a verdict; the certificate
    // is still written and names it.
    let json = dir.path().join("dead.json");
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        "1",
        "--external",
        "/bin/false",
        "--base",
        "2",
        "--shard",
        "1/4096",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).unwrap()).unwrap();
    assert_eq!(v["verdict"], "fail");
    assert!(v["result"]["external_failure"]
        .as_str()
        .unwrap()
        .contains("request 1"));
    assert!(v["result"]["pieces"].as_array().unwrap().is_empty());
}

/// `--estimate` sizes a sweep from a timed probe: every implementation gets a rate, the run's
/// words (dimensions × 2^32) and a time per shard count; nothing is written, and it needs the
/// exhaustive level and --dims. An external program is probed through its pipes.
#[test]
fn estimate_sizes_the_sweep_from_a_probe_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        "0..7",
        "--impl",
        "lk-hash",
        "--impl",
        "art-owen-16p",
        "--estimate",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    for name in ["lk-hash:", "art-owen-16p:table=256:"] {
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(name))
            .unwrap_or_else(|| panic!("{name}: {text}"));
        assert!(
            line.contains("words/s")
                && line.contains("8 dimension(s) × 4294967296 words = 3.436e10 words")
                && line.contains("per shard (1: ")
                && line.contains(", 64: "),
            "{line}"
        );
    }
    assert!(text.contains("in all ≈"), "{text}");
    let ext = example(dir.path(), "lk_hash");
    let o = gartowen(&[
        "verify",
        "--level",
        "exhaustive",
        "--dims",
        "3",
        "--external",
        ext.to_str().unwrap(),
        "--estimate",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("1 dimension(s) × 4294967296 words"),
        "{}",
        stdout(&o)
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "only the program"
    );
    // Refusals: not the exhaustive level, without --dims, with an output file.
    let json = dir.path().join("e.json");
    for args in [
        &["verify", "--dims", "0", "--impl", "lk-hash", "--estimate"][..],
        &["verify", "--impl", "lk-hash", "--estimate"][..],
        &[
            "verify",
            "--level",
            "exhaustive",
            "--dims",
            "0",
            "--estimate",
            "--json",
            json.to_str().unwrap(),
        ][..],
    ] {
        let o = gartowen(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!stderr(&o).is_empty());
    }
    assert!(!json.exists());
}
