//! End-to-end tests of `gartowen check`: verdicts, exit codes, JSON and bad input.

use crate::support::gartowen;
use std::path::Path;
use std::process::Command;

pub(crate) fn generate(dir: &Path, name: &str, args: &[&str]) -> String {
    let path = dir.join(name).to_str().unwrap().to_string();
    let mut all = vec!["generate"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", &path]);
    assert!(gartowen(&all).status.success());
    path
}

/// The hex file at `good` with point 8's coordinate 3 copied onto point 7, as `bad.hex` in
/// `dir`: two points then share a box of every shape with d_3 ≥ 1.
pub(crate) fn point_7_copying_point_8(dir: &Path, good: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(good).unwrap();
    let mut rows: Vec<Vec<String>> = text
        .lines()
        .map(|l| l.split(' ').map(String::from).collect())
        .collect();
    rows[7][3] = rows[8][3].clone();
    let bad = dir.join("bad.hex");
    std::fs::write(
        &bad,
        rows.iter().map(|r| r.join(" ") + "\n").collect::<String>(),
    )
    .unwrap();
    bad
}

#[test]
fn sz16_is_a_0_3_16_net_and_a_mutation_fails_with_exit_1() {
    let dir = tempfile::tempdir().unwrap();
    let good = generate(
        dir.path(),
        "sz16.hex",
        &["--seq", "sz16", "--dims", "16", "--log2-n", "12"],
    );
    let o = gartowen(&["check", &good, "--base", "16", "--t", "0", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "pass");
    assert_eq!(v["schema"], "gartowen-certificate");
    assert_eq!(v["schema_version"], 1);
    assert_eq!(v["result"]["m"], 3);
    assert_eq!(v["result"]["shapes_checked"], 816);
    assert_eq!(v["inputs"][0]["details"]["points"], 4096);

    // Copy point 8's coordinate 3 onto point 7: two points share a box of shape d_3 ≥ 1.
    let bad = point_7_copying_point_8(dir.path(), &good);
    let o = gartowen(&[
        "check",
        bad.to_str().unwrap(),
        "--base",
        "16",
        "--t",
        "0",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let f = &v["result"]["first_failure"];
    assert_eq!(f["count"], 2);
    assert!(
        f["shape"][3].as_u64().unwrap() >= 1,
        "the mutated dimension is refined: {f}"
    );
    assert_ne!(v["inputs"][0]["checksum_fnv1a64"], serde_json::Value::Null);
}

#[test]
fn t_values_of_sobol_pairs_and_the_sequence_check() {
    let dir = tempfile::tempdir().unwrap();
    let f = generate(
        dir.path(),
        "s.npy",
        &[
            "--seq", "sobol", "--dims", "3", "--log2-n", "10", "--format", "npy",
        ],
    );
    let o = gartowen(&[
        "check",
        &f,
        "--base",
        "2",
        "--projections",
        "pairs",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "reporting only exits 0");
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let ts: Vec<u64> = v["result"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["t"].as_u64().unwrap())
        .collect();
    assert_eq!(ts.len(), 3);
    assert_eq!(ts[0], 0, "dims 0,1 form a (0,10,2)-net");
    let o = gartowen(&[
        "check",
        &f,
        "--base",
        "2",
        "--sequence",
        "--t",
        "0",
        "--projections",
        "0,1",
    ]);
    assert_eq!(o.status.code(), Some(0));
    let o = gartowen(&[
        "check",
        &f,
        "--base",
        "2",
        "--sequence",
        "--t",
        "0",
        "--projections",
        "0,2",
    ]);
    assert_eq!(
        o.status.code(),
        Some(1),
        "dims 0,2 are not a (0,2)-sequence"
    );
    assert!(String::from_utf8_lossy(&o.stdout).contains("first failure"));
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    let cases = [
        (write("nan.csv", "nan,0.5\n0.5,0.5\n"), "2", "NaN"),
        (
            write("one.csv", "0.5,1.0\n0.5,0.5\n"),
            "2",
            "outside [0, 1)",
        ),
        (
            write("neg.csv", "-0.5,0.5\n0.5,0.5\n"),
            "2",
            "outside [0, 1)",
        ),
        (write("ragged.csv", "0.5,0.25\n0.5\n"), "2", "line 2"),
        (write("empty.csv", ""), "2", "no data"),
        (write("words.csv", "a,b\n"), "2", "not a number"),
        (
            write("three.csv", "0.5\n0.25\n0.75\n"),
            "2",
            "not a power of the base",
        ),
        (write("ok.csv", "0.5\n0.25\n"), "1", "below 2"),
        (write("badhex.hex", "1234567\n"), "2", "8- or 16-digit"),
        (
            write("mixed.hex", "12345678\n1234567812345678\n"),
            "2",
            "digits",
        ),
        (write("garbage.npy", "not numpy"), "2", "npy"),
    ];
    for (path, base, needle) in cases {
        let o = gartowen(&["check", &path, "--base", base]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{path}: {err}");
        assert!(err.contains(needle), "{path}: '{err}' lacks '{needle}'");
        assert!(!err.contains("panicked"), "{path}");
    }
    let o = gartowen(&["check", "/nonexistent/file.csv", "--base", "2"]);
    assert_eq!(o.status.code(), Some(2));
    // Bounded resources: a file past 2 GiB is refused by its size before any read (a sparse
    // file here), a directory by its kind, an absurd --threads at once.
    let huge = dir.path().join("huge.csv");
    std::fs::File::create(&huge)
        .unwrap()
        .set_len(3 << 30)
        .unwrap();
    for (args, needle) in [
        (
            vec!["check", huge.to_str().unwrap(), "--base", "2"],
            "larger than",
        ),
        (
            vec![
                "check",
                dir.path().to_str().unwrap(),
                "--base",
                "2",
                "--format",
                "csv",
            ],
            "directory",
        ),
        (
            vec!["check", "/dev/null", "--base", "2", "--threads", "100000"],
            "at most 1024",
        ),
    ] {
        let o = gartowen(&args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// A .npy file whose header is v1 with the given shape text, over `values` float64 words.
fn npy_with_shape(dir: &Path, name: &str, shape: &str, values: &[f64]) -> String {
    let mut header = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}");
    // Pad so that magic (6) + version (2) + length (2) + header + newline is a multiple of 64.
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
    bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
    bytes.extend_from_slice(header.as_bytes());
    for v in values {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path.to_str().unwrap().to_string()
}

/// A header that lies about the shape is refused (exit 2, the shape named), never believed:
/// (2^63 + 4, 2) once wrapped to 8 elements and read 4 × 2 points; (2^61 + 1, 8) became one
/// point in 8 dimensions and was certified "pass".
#[test]
fn a_lying_npy_header_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let eight = [0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875];
    let honest = npy_with_shape(dir.path(), "ok.npy", "(4, 2)", &eight);
    assert!(gartowen(&["check", &honest, "--base", "2"])
        .status
        .success());
    for (name, shape) in [
        ("wrap.npy", "(9223372036854775812, 2)"),
        ("one.npy", "(2305843009213693953, 8)"),
        ("short.npy", "(5, 2)"),
        ("long.npy", "(3, 2)"),
    ] {
        let path = npy_with_shape(dir.path(), name, shape, &eight);
        for cmd in [
            vec!["check", path.as_str(), "--base", "2", "--json"],
            vec!["discrepancy", path.as_str()],
        ] {
            let out = gartowen(&cmd);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{name} {cmd:?}: {err}");
            assert!(err.contains(name) && err.contains("shape"), "{err}");
            assert!(out.stdout.is_empty(), "nothing certified for {name}");
        }
    }
    // A v2 header claiming 2^32 - 1 bytes is refused before anything is allocated.
    let mut v2 = b"\x93NUMPY\x02\x00".to_vec();
    v2.extend_from_slice(&u32::MAX.to_le_bytes());
    v2.extend_from_slice(b"{'descr': '<f8'");
    let path = dir.path().join("huge.npy");
    std::fs::write(&path, v2).unwrap();
    let out = gartowen(&["check", path.to_str().unwrap(), "--base", "2"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("header claims 4294967295 bytes"), "{err}");
}

/// Wide inputs are bounded: 4 points in 2000 dimensions (2 million shapes of 2000 parts, once
/// 5.7 GB and an abort) are refused at once with the estimate; one point in 200,000 dimensions
/// (once a stack overflow) is checked.
#[test]
fn wide_point_sets_are_refused_by_their_memory_estimate_or_checked() {
    let dir = tempfile::tempdir().unwrap();
    let wide = dir.path().join("wide.csv");
    let rows: Vec<String> = (0..4)
        .map(|i| {
            (0..2000)
                .map(|j| format!("{}", ((i * 7 + j * 3) % 4) as f64 / 4.0))
                .collect::<Vec<_>>()
                .join(",")
        })
        .collect();
    std::fs::write(&wide, rows.join("\n") + "\n").unwrap();
    let o = gartowen(&["check", wide.to_str().unwrap(), "--base", "2"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("shapes of 2000 dimensions need"), "{err}");
    // All pairs of 2000 dimensions are 1,999,000 projections: refused before expanding.
    let o = gartowen(&[
        "check",
        wide.to_str().unwrap(),
        "--base",
        "2",
        "--projections",
        "pairs",
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("1999000 projections"), "{err}");
    let deep = dir.path().join("deep.csv");
    std::fs::write(&deep, vec!["0.5"; 200_000].join(",") + "\n").unwrap();
    let o = gartowen(&["check", deep.to_str().unwrap(), "--base", "2", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(doc["result"]["t"], 0);
    assert_eq!(doc["result"]["s"], 200_000);
}

/// Halton floats in base 3, as another tool writes them (shortest round-trip decimals): snapped,
/// a (0,7,1)-net; read by floor (`--no-snap`), not; truncated to 44 bits, refused naming a
/// point. Values below 2^-11 (not multiples of 2^-64) are read, not refused.
#[test]
fn base_3_floats_are_snapped_refused_when_ambiguous_and_floored_on_request() {
    let dir = tempfile::tempdir().unwrap();
    let n = 3usize.pow(7);
    let h = gartowen::seq::radix::halton(n as u64, 2).unwrap();
    let column: Vec<f64> = h.iter().skip(1).step_by(2).map(|f| f.to_f64()).collect();
    let write = |name: &str, values: &[f64]| {
        let text: String = values.iter().map(|v| format!("{v:?}\n")).collect();
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_string()
    };
    let exact = write("h3.csv", &column);
    let o = gartowen(&["check", &exact, "--base", "3", "--t", "0"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        out.contains("floats snapped to the base-3 grid of depth 7"),
        "{out}"
    );
    let o = gartowen(&["check", &exact, "--base", "3", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["result"]["t"], 0);
    assert_eq!(v["parameters"]["snap"]["depth"], 7);
    assert!(v["parameters"]["snap"]["snapped"].as_u64().unwrap() > 0);
    let o = gartowen(&["check", &exact, "--base", "3", "--no-snap", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["result"]["t"].as_u64().unwrap() > 0, "{v}");
    // Quantized to 44 bits: ambiguous, exit 2, the point named, nothing on stdout.
    let coarse: Vec<f64> = column
        .iter()
        .map(|v| (v * 2f64.powi(44)).floor() / 2f64.powi(44))
        .collect();
    let path = write("coarse.csv", &coarse);
    let o = gartowen(&["check", &path, "--base", "3"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("coordinate 0") && err.contains("point "),
        "{err}"
    );
    assert!(o.stdout.is_empty());
    // Depth beyond what a float resolves.
    let o = gartowen(&["check", &exact, "--base", "3", "--m", "28"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("at most 27 base-3 digits"));
    // A tiny value is read (it used to be refused as "not a multiple of 2^-64").
    let path = write("tiny.csv", &[0.0, 1e-300, 0.5, 0.75]);
    let o = gartowen(&["check", &path, "--base", "2", "--m", "2", "--json"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// A point file given as a FIFO is opened once and read whole: it was once opened twice, so the
/// writer's data went to the first open and the second waited for a writer that never came.
#[test]
fn a_fifo_input_is_read_once_in_every_format() {
    let dir = tempfile::tempdir().unwrap();
    for (ext, extra) in [("npy", vec![]), ("hex", vec!["--format", "hex"])] {
        let mut args = vec!["--seq", "sobol", "--dims", "2", "--n", "64"];
        args.extend(&extra);
        let file = generate(dir.path(), &format!("s.{ext}"), &args);
        let fifo = dir.path().join(format!("fifo.{ext}"));
        assert!(Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success());
        let (src, dst) = (file.clone(), fifo.clone());
        let writer = std::thread::spawn(move || {
            let bytes = std::fs::read(src).unwrap();
            // Fails with a broken pipe if the reader closes early; the check below says why.
            let _ = std::fs::write(dst, bytes);
        });
        let mut child = Command::new(env!("CARGO_BIN_EXE_gartowen"))
            .args(["check", fifo.to_str().unwrap(), "--base", "2"])
            .stdout(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let started = std::time::Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break s;
            }
            if started.elapsed().as_secs() > 30 {
                let _ = child.kill();
                panic!("{ext}: check of a FIFO still running after 30 s");
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        };
        writer.join().unwrap();
        let mut out = String::new();
        std::io::Read::read_to_string(&mut child.stdout.take().unwrap(), &mut out).unwrap();
        assert!(status.success(), "{ext}: {out}");
        assert!(out.contains("t = 0 (m = 6, s = 2"), "{ext}: {out}");
    }
}

/// An endless stream of valid lines is refused at the stream budget (256 MiB), in about its own
/// size of memory, instead of growing toward the 2 GiB file limit.
#[test]
fn an_endless_stream_is_refused_at_the_stream_budget() {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(["check", "/dev/stdin", "--base", "2", "--format", "hex"])
        .stdin(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || {
        let line = "80000000 40000000\n".repeat(4096);
        // Ends when the reader stops reading (a broken pipe).
        while stdin.write_all(line.as_bytes()).is_ok() {}
    });
    let o = child.wait_with_output().unwrap();
    writer.join().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("268435456 bytes") && err.contains("stream"),
        "{err}"
    );
}

/// Where a limit on threads is lower than `--threads` (here `ulimit -u 64` for an unprivileged
/// user), the refusal says so and what to do, with exit 2 (before: "os error 11" alone). Runs
/// where it can drop to user nobody (as root, with setpriv).
#[test]
fn threads_the_system_refuses_are_explained() {
    let root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !root || Command::new("setpriv").arg("--help").output().is_err() {
        eprintln!("skipped: needs root and setpriv to run under another user's ulimit");
        return;
    }
    // A folder user nobody can read, with the binary and a point set in it.
    let dir = tempfile::tempdir().unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    let points = generate(
        dir.path(),
        "p.npy",
        &["--seq", "sobol", "--dims", "2", "--log2-n", "6"],
    );
    let binary = dir.path().join("gartowen");
    std::fs::copy(env!("CARGO_BIN_EXE_gartowen"), &binary).unwrap();
    for f in [&binary, &std::path::PathBuf::from(&points)] {
        std::fs::set_permissions(f, std::fs::Permissions::from_mode(0o755)).unwrap();
    }
    let o = Command::new("setpriv")
        .args([
            "--reuid",
            "65534",
            "--regid",
            "65534",
            "--clear-groups",
            "bash",
            "-c",
        ])
        .arg(format!(
            "ulimit -u 64; exec {} check {points} --base 2 --threads 1024",
            binary.display()
        ))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--threads 1024: the system refused") && err.contains("ulimit -u"),
        "{err}"
    );
}
