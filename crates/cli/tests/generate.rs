//! End-to-end tests of `gartowen generate`, `matrices` and `list`.

use crate::support::gartowen;
use std::path::Path;
use std::process::{Command, Output};

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

#[test]
fn hex_output_is_the_sequence_in_natural_order() {
    let o = gartowen(&[
        "generate", "--seq", "sobol", "--dims", "2", "--n", "4", "--start", "1",
    ]);
    assert!(o.status.success());
    // Indices 1..=4: van der Corput in dimension 0, the binary Pascal matrix in dimension 1.
    assert_eq!(
        stdout(&o),
        "80000000 80000000\n40000000 c0000000\nc0000000 40000000\n20000000 a0000000\n"
    );
}

#[test]
fn gray_order_reproduces_scipy_rows() {
    // Rows 0..4 of scipy.stats.qmc.Sobol(2, scramble=False).random(4) are 0, .5, .75/.25, .25/.75.
    let o = gartowen(&[
        "generate", "--seq", "sobol", "--dims", "2", "--n", "4", "--order", "gray", "--format",
        "csv",
    ]);
    assert_eq!(stdout(&o), "0.0,0.0\n0.5,0.5\n0.75,0.25\n0.25,0.75\n");
}

#[test]
fn npy_words_and_values_agree() {
    let dir = tempfile::tempdir().unwrap();
    let words = dir.path().join("w.npy");
    let values = dir.path().join("v.npy");
    for (path, extra) in [(&words, vec!["--words"]), (&values, vec![])] {
        let mut args = vec![
            "generate",
            "--seq",
            "sz16",
            "--dims",
            "16",
            "--log2-n",
            "8",
            "--format",
            "npy",
            "-o",
            path.to_str().unwrap(),
        ];
        args.extend(extra);
        assert!(gartowen(&args).status.success());
    }
    let bytes = std::fs::read(&words).unwrap();
    let w = npyz::NpyFile::new(bytes.as_slice()).unwrap();
    assert_eq!(w.shape(), &[256, 16]);
    let w: Vec<u32> = w.into_vec().unwrap();
    let v: Vec<f64> = npyz::NpyFile::new(std::fs::read(&values).unwrap().as_slice())
        .unwrap()
        .into_vec()
        .unwrap();
    for (x, y) in w.iter().zip(&v) {
        assert_eq!(*x as f64 / 4294967296.0, *y);
    }
}

#[test]
fn bad_arguments_exit_2_and_leave_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.npy");
    let cases: &[&[&str]] = &[
        &["--seq", "sobol", "--dims", "0", "--n", "4"],
        &["--seq", "sobol", "--dims", "21202", "--n", "4"],
        &["--seq", "sz4", "--dims", "5", "--n", "4"],
        &["--seq", "halton", "--dims", "2", "--n", "4"],
        &["--seq", "sobol", "--dims", "2", "--n", "0"],
        &["--seq", "sobol", "--dims", "2", "--log2-n", "33"],
        &[
            "--seq",
            "sobol",
            "--dims",
            "2",
            "--n",
            "2",
            "--start",
            "4294967295",
        ],
        &["--seq", "sobol", "--dims", "2", "--n", "4", "--bits", "16"],
        &[
            "--seq",
            "sobol",
            "--dims",
            "2",
            "--n",
            "4",
            "--scramble",
            "nope",
        ],
        &["--seq", "sobol", "--dims", "2"],
    ];
    for case in cases {
        let mut args = vec!["generate"];
        args.extend_from_slice(case);
        args.extend_from_slice(&["-o", out.to_str().unwrap()]);
        let o = gartowen(&args);
        assert_eq!(o.status.code(), Some(2), "{case:?}");
        assert!(
            !String::from_utf8_lossy(&o.stderr).contains("panicked"),
            "{case:?}"
        );
        assert!(!o.stderr.is_empty(), "{case:?}");
        assert!(!out.exists(), "{case:?} left a file");
        assert_eq!(
            std::fs::read_dir(dir.path()).unwrap().count(),
            0,
            "{case:?} left a temp file"
        );
    }
}

#[test]
fn a_failed_run_keeps_the_previous_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("keep.csv");
    std::fs::write(&out, "precious\n").unwrap();
    let o = gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "0",
        "--n",
        "4",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "precious\n");
}

#[test]
fn matrices_hex_and_json_carry_the_same_columns() {
    let hex = stdout(&gartowen(&["matrices", "--seq", "sz4", "--dims", "4"]));
    let lines: Vec<&str> = hex.lines().collect();
    assert_eq!(lines.len(), 4);
    // The published 4-D SZ: dimension 2 is P4(β), dimension 3 is P·P4(β).
    assert!(lines[2].starts_with("80000000 40000000 e0000000 90000000"));
    assert!(lines[3].starts_with("80000000 c0000000 e0000000 70000000"));
    let json: serde_json::Value = serde_json::from_str(&stdout(&gartowen(&[
        "matrices", "--seq", "sz4", "--dims", "4", "--format", "json",
    ])))
    .unwrap();
    for (j, line) in lines.iter().enumerate() {
        let cols: Vec<String> = json["dims"][j]["columns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c.as_str().unwrap().to_string())
            .collect();
        assert_eq!(cols.join(" "), *line);
    }
    assert_eq!(json["base"], 4);
}

#[test]
fn list_sequences_states_each_sequences_provenance() {
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&gartowen(&["list", "--sequences", "--json"]))).unwrap();
    let provenance = |name: &str| {
        json.as_array()
            .unwrap()
            .iter()
            .find(|r| r["name"] == name)
            .unwrap_or_else(|| panic!("{name} listed"))["provenance"]
            .as_str()
            .unwrap()
            .to_string()
    };
    assert_eq!(provenance("sobol"), "published");
    assert_eq!(provenance("sz4"), "third-party-derived");
    assert_eq!(provenance("sz16"), "gartowen's own");
    assert_eq!(provenance("sz16-faure"), "gartowen's own");
    // Every listed fixed name parses back as a sequence.
    for r in json.as_array().unwrap() {
        let name = r["name"].as_str().unwrap();
        if !name.contains('=') {
            let m = gartowen(&["matrices", "--seq", name, "--dims", "2"]);
            assert_eq!(m.status.code(), Some(0), "{name}");
        }
    }
}

#[test]
fn list_names_every_registry_entry() {
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&gartowen(&["list", "--json"]))).unwrap();
    let names: Vec<&str> = json
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["name"].as_str().unwrap())
        .collect();
    let registry = gartowen::registry();
    let expected: Vec<&str> = registry.specs().iter().map(|s| s.name).collect();
    assert_eq!(names, expected);
}

#[test]
fn help_explains_the_conventions() {
    let o = gartowen(&["generate", "--help"]);
    let text = stdout(&o);
    assert!(text.contains("--log2-n") && text.contains("scipy"));
    assert!(Path::new(env!("CARGO_BIN_EXE_gartowen")).exists());
}

/// `-o` respects what is there: a symlink or a read-only file is refused (exit 2, untouched),
/// a 0600 file keeps its mode, a FIFO and /dev/null are written in place, never replaced.
#[test]
fn output_targets_are_respected() {
    use std::os::unix::fs::{FileTypeExt, PermissionsExt};
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n);
    let gen = |out: &std::path::Path| {
        gartowen(&[
            "generate",
            "--seq",
            "sobol",
            "--dims",
            "2",
            "--n",
            "16",
            "-o",
            out.to_str().unwrap(),
        ])
    };
    // A symlink: refused, and neither the link nor its target changes.
    std::fs::write(path("real.hex"), "keep\n").unwrap();
    std::os::unix::fs::symlink(path("real.hex"), path("link.hex")).unwrap();
    let o = gen(&path("link.hex"));
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("symbolic link"));
    assert!(std::fs::symlink_metadata(path("link.hex"))
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(std::fs::read_to_string(path("real.hex")).unwrap(), "keep\n");
    // Read-only: refused and untouched.
    std::fs::write(path("ro.hex"), "keep\n").unwrap();
    std::fs::set_permissions(path("ro.hex"), std::fs::Permissions::from_mode(0o444)).unwrap();
    let o = gen(&path("ro.hex"));
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("read-only"));
    assert_eq!(std::fs::read_to_string(path("ro.hex")).unwrap(), "keep\n");
    // A private file stays private.
    std::fs::write(path("private.hex"), "old\n").unwrap();
    std::fs::set_permissions(path("private.hex"), std::fs::Permissions::from_mode(0o600)).unwrap();
    assert!(gen(&path("private.hex")).status.success());
    let m = std::fs::metadata(path("private.hex")).unwrap();
    assert_eq!(m.permissions().mode() & 0o777, 0o600);
    assert_eq!(
        std::fs::read_to_string(path("private.hex"))
            .unwrap()
            .lines()
            .count(),
        16
    );
    // /dev/null is written into and stays a character device.
    assert!(gen(std::path::Path::new("/dev/null")).status.success());
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // A FIFO: the reader gets the points, the FIFO stays a FIFO.
    let fifo = path("pipe.hex");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    assert!(gen(&fifo).status.success());
    assert_eq!(reader.join().unwrap().lines().count(), 16);
    assert!(std::fs::symlink_metadata(&fifo)
        .unwrap()
        .file_type()
        .is_fifo());
    // A directory is refused.
    assert_eq!(gen(dir.path()).status.code(), Some(2));
}

/// SIGTERM, SIGINT or SIGHUP during a long `generate -o` removes the temporary file (it once
/// left 600–730 MB behind) and leaves no target; the process ends by the signal.
#[test]
fn a_signal_removes_the_temporary_output() {
    use std::os::unix::process::ExitStatusExt;
    for signal in ["TERM", "INT", "HUP"] {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("big.npy");
        let mut child = Command::new(env!("CARGO_BIN_EXE_gartowen"))
            .args([
                "generate", "--seq", "sobol", "--dims", "64", "--log2-n", "22",
            ])
            .args(["--scramble", "owen-per-bit-hash", "--format", "npy", "-o"])
            .arg(&target)
            .spawn()
            .unwrap();
        // Wait until the temporary file exists and has data.
        let started = std::time::Instant::now();
        let tmp = loop {
            let found = std::fs::read_dir(dir.path())
                .unwrap()
                .filter_map(|e| e.ok())
                .find(|e| e.file_name().to_string_lossy().contains(".tmp-"));
            if let Some(e) = found {
                if e.metadata().map(|m| m.len() > 0).unwrap_or(false) {
                    break e.path();
                }
            }
            assert!(
                started.elapsed().as_secs() < 60,
                "no temporary file appeared"
            );
            std::thread::sleep(std::time::Duration::from_millis(20));
        };
        let kill = Command::new("kill")
            .args([format!("-{signal}"), child.id().to_string()])
            .status()
            .unwrap();
        assert!(kill.success());
        let status = child.wait().unwrap();
        assert!(!status.success(), "{signal}: {status:?}");
        assert!(
            status.signal().is_some() || status.code().is_some_and(|c| c > 128),
            "{signal}: {status:?}"
        );
        assert!(!tmp.exists(), "{signal}: {} left behind", tmp.display());
        assert!(!target.exists(), "{signal}: a partial target");
    }
}

#[test]
fn the_output_format_follows_the_extension_unless_given() {
    // -o x.npy without --format writes .npy (the same bytes as --format npy), x.csv writes
    // CSV, an unknown extension writes hex, and --format overrides the extension.
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let base = ["generate", "--seq", "sobol", "--dims", "2", "--n", "8"];
    let run = |extra: &[&str]| {
        let mut args: Vec<&str> = base.to_vec();
        args.extend_from_slice(extra);
        assert!(gartowen(&args).status.success(), "{args:?}");
    };
    let (inferred, explicit) = (path("a.npy"), path("b.out"));
    run(&["-o", &inferred]);
    run(&["--format", "npy", "-o", &explicit]);
    let bytes = std::fs::read(&inferred).unwrap();
    assert_eq!(&bytes[..6], b"\x93NUMPY");
    assert_eq!(bytes, std::fs::read(&explicit).unwrap());
    let csv = path("c.csv");
    run(&["-o", &csv]);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().count(), 8);
    assert!(text.lines().all(|l| l.split(',').count() == 2));
    let (hex, forced) = (path("d.dat"), path("e.npy"));
    run(&["-o", &hex]);
    run(&["--format", "hex", "-o", &forced]);
    let hex_text = std::fs::read_to_string(&hex).unwrap();
    assert_eq!(hex_text, std::fs::read_to_string(&forced).unwrap());
    assert!(hex_text
        .lines()
        .all(|l| l.split_whitespace().all(|w| w.len() == 8)));
}

/// The .npy writer overlaps computing and writing from two threads on: the bytes are the same
/// for 1, 2 and 3 threads over several blocks (2^16 rows, blocks of 2^14), values and words;
/// and a full disk under the pipelined writer exits 2 with a message, not a panic or a hang.
#[test]
fn npy_bytes_do_not_depend_on_threads_and_a_full_disk_stops_the_pipeline() {
    let run = |threads: &str, words: bool| {
        let mut args = vec![
            "generate",
            "--seq",
            "sobol",
            "--dims",
            "3",
            "--log2-n",
            "16",
            "--scramble",
            "art-owen-2",
            "--format",
            "npy",
        ];
        if words {
            args.push("--words");
        }
        let o = Command::new(env!("CARGO_BIN_EXE_gartowen"))
            .args(&args)
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .expect("binary runs");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    for words in [false, true] {
        let one = run("1", words);
        let item = if words { 4 } else { 8 };
        assert_eq!(one.len(), 128 + (3 << 16) * item, "header and data");
        assert_eq!(one, run("2", words), "2 threads, words {words}");
        assert_eq!(one, run("3", words), "3 threads, words {words}");
    }
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("/dev/full exists on Linux");
    let o = Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args([
            "generate", "--seq", "sobol", "--dims", "4", "--log2-n", "18",
        ])
        .args(["--scramble", "lk-hash", "--format", "npy"])
        .env("RAYON_NUM_THREADS", "2")
        .stdout(std::process::Stdio::from(full))
        .output()
        .expect("binary runs");
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!String::from_utf8_lossy(&o.stderr).is_empty());
}

/// At thousands of dimensions a block holds only a few dozen rows (the buffer stays a few MB;
/// 16,384 rows of 21,201 dimensions once took 2.8 GB and aborted): rows that cross several
/// blocks must be the rows of a run with three dimensions in one block, plain and scrambled,
/// in both orders.
#[test]
fn rows_across_many_blocks_at_thousands_of_dimensions_equal_the_rows_of_one_block() {
    let first3 = |text: &str| -> Vec<String> {
        text.lines()
            .map(|l| l.split(' ').take(3).collect::<Vec<_>>().join(" "))
            .collect()
    };
    for extra in [
        vec![],
        vec!["--scramble", "owen-oracle", "--seed", "3"],
        vec!["--order", "gray"],
    ] {
        let run = |dims: &str| {
            let mut args = vec!["generate", "--seq", "sobol", "--dims", dims, "--n", "300"];
            args.extend(&extra);
            let o = gartowen(&args);
            assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            stdout(&o)
        };
        let wide = run("5000");
        assert_eq!(wide.lines().count(), 300);
        assert_eq!(first3(&wide), first3(&run("3")), "{extra:?}");
    }
}

/// A scrambler whose base is a parameter, on a sequence of base 16 with no base asked for,
/// scrambles in base 16 and says so on stderr, naming how to ask for binary Owen; `:base=2`
/// gives binary Owen, the same points as `--scramble-base 2` (issue 58, item 5).
#[test]
fn a_base_taken_from_the_sequence_is_named_and_base_2_can_be_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    let out = |n: &str| dir.path().join(n).to_str().unwrap().to_string();
    let gen = |scramble: &[&str], file: &str| {
        let mut args = vec!["generate", "--seq", "sz16", "--dims", "2", "--log2-n", "8"];
        args.extend_from_slice(scramble);
        let path = out(file);
        args.extend(["-o", &path]);
        let o = crate::support::gartowen(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        (
            String::from_utf8_lossy(&o.stderr).to_string(),
            std::fs::read(path).unwrap(),
        )
    };
    let (note, base16) = gen(&["--scramble", "owen-oracle"], "a.hex");
    assert!(
        note.contains("scrambles in base 16") && note.contains("owen-oracle:base=2"),
        "{note}"
    );
    let (quiet, explicit16) = gen(&["--scramble", "owen-oracle:base=16"], "b.hex");
    assert_eq!(quiet, "");
    assert_eq!(base16, explicit16);
    let (quiet, binary) = gen(&["--scramble", "owen-oracle:base=2"], "c.hex");
    assert_eq!(quiet, "");
    let (_, flag) = gen(
        &["--scramble", "owen-oracle", "--scramble-base", "2"],
        "d.hex",
    );
    assert_eq!(binary, flag);
    assert_ne!(binary, base16);
    // A scrambler of a fixed base has nothing to say.
    assert_eq!(gen(&["--scramble", "art-owen-16p"], "e.hex").0, "");
}
