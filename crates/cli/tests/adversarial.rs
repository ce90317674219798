//! The standing adversarial corpus (`tests/adversarial/cases.json` at the repository root):
//! malformed files, absurd parameters, hostile external programs and tampered certificates,
//! each with the exit code and message fragment it must give. Every command runs under a 2 GB
//! address-space cap (`prlimit`) and a 60 s wall clock, so a blow-up fails the case instead of
//! the machine. Files are made by the runner from the case (text, random CSV, `.npy` headers,
//! or gartowen commands of the case's `setup`), so the corpus holds no data.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const MEMORY_CAP_BYTES: u64 = 2_000_000_000;
const WALL_CLOCK: Duration = Duration::from_secs(60);

fn corpus() -> Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/adversarial/cases.json");
    serde_json::from_str(&std::fs::read_to_string(&path).expect("the corpus file")).expect("JSON")
}

/// A SplitMix64 stream, so random files are the same on every run.
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Writes one file of a case into `dir`.
fn make_file(dir: &Path, name: &str, spec: &Value) {
    let path = dir.join(name);
    if let Some(text) = spec["text"].as_str() {
        std::fs::write(&path, text).unwrap();
    } else if let Some(csv) = spec.get("csv") {
        let (rows, cols) = (csv["rows"].as_u64().unwrap(), csv["cols"].as_u64().unwrap());
        let mut state = csv["seed"].as_u64().unwrap_or(1);
        let mut out = String::new();
        for _ in 0..rows {
            let row: Vec<String> = (0..cols)
                .map(|_| {
                    format!(
                        "{}",
                        (splitmix(&mut state) >> 11) as f64 / (1u64 << 53) as f64
                    )
                })
                .collect();
            out.push_str(&row.join(","));
            out.push('\n');
        }
        std::fs::write(&path, out).unwrap();
    } else if let Some(npy) = spec.get("npy") {
        // A v1 header with the given shape text over `values` little-endian f64 zeros (or a
        // v2 header whose length field is `header_len`, with no header after it).
        let mut bytes = b"\x93NUMPY".to_vec();
        if let Some(len) = npy["v2_header_len"].as_u64() {
            bytes.extend_from_slice(&[2, 0]);
            bytes.extend_from_slice(&(len as u32).to_le_bytes());
        } else {
            let mut header = match npy["raw_header"].as_str() {
                Some(raw) => raw.to_string(),
                None => {
                    let shape = npy["shape"].as_str().unwrap();
                    let descr = npy["descr"].as_str().unwrap_or("<f8");
                    format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}")
                }
            };
            while (10 + header.len() + 1) % 64 != 0 {
                header.push(' ');
            }
            header.push('\n');
            bytes.extend_from_slice(&[1, 0]);
            bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
            bytes.extend_from_slice(header.as_bytes());
            bytes.resize(
                bytes.len() + 8 * npy["values"].as_u64().unwrap() as usize,
                0,
            );
        }
        std::fs::write(&path, bytes).unwrap();
    } else {
        panic!("file {name}: unknown spec {spec}");
    }
    if let Some(mode) = spec["mode"].as_str() {
        use std::os::unix::fs::PermissionsExt;
        let mode = u32::from_str_radix(mode, 8).unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode)).unwrap();
    }
    if let Some(target) = spec["symlink_to"].as_str() {
        std::fs::remove_file(&path).unwrap();
        std::os::unix::fs::symlink(dir.join(target), &path).unwrap();
    }
}

/// Edits a JSON file of the case in place: sets the value at a `/`-separated pointer.
fn edit_json(dir: &Path, edit: &Value) {
    let path = dir.join(edit["file"].as_str().unwrap());
    let mut doc: Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    let pointer = edit["pointer"].as_str().unwrap();
    match edit.get("value") {
        Some(v) => {
            *doc.pointer_mut(pointer)
                .unwrap_or_else(|| panic!("{pointer}")) = v.clone()
        }
        None => {
            // Remove the last segment.
            let (parent, key) = pointer.rsplit_once('/').unwrap();
            let p = doc.pointer_mut(parent).unwrap();
            match p {
                Value::Object(m) => {
                    m.remove(key);
                }
                Value::Array(a) => {
                    a.remove(key.parse::<usize>().unwrap());
                }
                _ => panic!("{parent} holds no {key}"),
            }
        }
    }
    std::fs::write(&path, doc.to_string()).unwrap();
}

struct Outcome {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    seconds: f64,
}

/// Runs gartowen with `args` in `dir` under the memory cap and wall clock.
fn run_capped(dir: &Path, args: &[String], stdout_to: Option<&str>) -> Outcome {
    let mut cmd = Command::new("prlimit");
    cmd.arg(format!("--as={MEMORY_CAP_BYTES}"))
        .arg("--")
        .arg(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stderr(Stdio::piped());
    match stdout_to {
        Some(p) => cmd.stdout(std::fs::OpenOptions::new().write(true).open(p).unwrap()),
        None => cmd.stdout(Stdio::piped()),
    };
    let start = Instant::now();
    let mut child = cmd.spawn().expect("prlimit (util-linux) runs");
    // Read both pipes on threads so a chatty child never blocks.
    let mut out = child.stdout.take();
    let mut err = child.stderr.take().unwrap();
    let t_out = std::thread::spawn(move || {
        let mut s = String::new();
        if let Some(o) = out.as_mut() {
            let _ = std::io::Read::read_to_string(o, &mut s);
        }
        s
    });
    let t_err = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = std::io::Read::read_to_string(&mut err, &mut s);
        s
    });
    let code = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status.code();
        }
        if start.elapsed() > WALL_CLOCK {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    Outcome {
        code,
        stdout: t_out.join().unwrap(),
        stderr: t_err.join().unwrap(),
        seconds: start.elapsed().as_secs_f64(),
    }
}

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .map(|a| a.iter().map(|s| s.as_str().unwrap().to_string()).collect())
        .unwrap_or_default()
}

/// The folders that cases' setups left, by the case's files and setup commands: many cases
/// edit the same certificates, and the commands are deterministic, so each distinct setup runs
/// once and later cases start from a copy of its files.
type SetupCache = std::sync::Mutex<std::collections::HashMap<String, Vec<CachedFile>>>;

/// A file of a cached setup: its path in the case's folder, bytes and permission bits.
type CachedFile = (PathBuf, Vec<u8>, u32);

/// Every regular file under `dir` (relative path, bytes, mode); `None` when the folder holds
/// anything else (a link, a special file), which a copy would not reproduce.
fn regular_files(dir: &Path) -> Option<Vec<CachedFile>> {
    use std::os::unix::fs::PermissionsExt;
    let mut found = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).ok()?.flatten() {
            let t = e.file_type().ok()?;
            if t.is_dir() {
                todo.push(e.path());
            } else if t.is_file() {
                let rel = e.path().strip_prefix(dir).ok()?.to_path_buf();
                let mode = e.metadata().ok()?.permissions().mode();
                found.push((rel, std::fs::read(e.path()).ok()?, mode));
            } else {
                return None;
            }
        }
    }
    Some(found)
}

/// Runs one case; the reasons it failed, if any.
fn run_case(case: &Value) -> Vec<String> {
    run_case_with(case, &SetupCache::default())
}

/// [`run_case`], starting from the cached result of an identical setup where there is one.
fn run_case_with(case: &Value, cache: &SetupCache) -> Vec<String> {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let setup = case["setup"].as_array().filter(|s| !s.is_empty());
    let key = setup.map(|s| format!("{}|{}", case["files"], Value::Array(s.clone())));
    let cached = key
        .as_ref()
        .and_then(|k| cache.lock().unwrap().get(k).cloned());
    if let Some(files) = cached {
        use std::os::unix::fs::PermissionsExt;
        for (rel, bytes, mode) in files {
            let path = d.join(rel);
            if let Some(parent) = path.parent() {
                std::fs::create_dir_all(parent).unwrap();
            }
            std::fs::write(&path, bytes).unwrap();
            std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode)).unwrap();
        }
    } else {
        if let Some(files) = case["files"].as_object() {
            for (name, spec) in files {
                make_file(d, name, spec);
            }
        }
        for step in setup.into_iter().flatten() {
            let o = run_capped(d, &strings(step), None);
            if o.code != Some(0) {
                return vec![format!("setup {step} exited {:?}: {}", o.code, o.stderr)];
            }
        }
        if let (Some(key), Some(files)) = (key, regular_files(d)) {
            cache.lock().unwrap().insert(key, files);
        }
    }
    for edit in case["edit"].as_array().into_iter().flatten() {
        edit_json(d, edit);
    }
    let args = strings(&case["args"]);
    let o = run_capped(d, &args, case["stdout_to"].as_str());
    let mut wrong = Vec::new();
    let expect = case["exit"].as_i64().map(|c| c as i32);
    if o.code != expect {
        wrong.push(format!(
            "exit {:?}, expected {expect:?} ({:.1} s); stderr: {}",
            o.code,
            o.seconds,
            o.stderr.trim()
        ));
    }
    for want in strings(&case["stderr"]) {
        if !o.stderr.contains(&want) {
            wrong.push(format!("stderr lacks {want:?}: {}", o.stderr.trim()));
        }
    }
    for want in strings(&case["stdout"]) {
        if !o.stdout.contains(&want) {
            wrong.push(format!("stdout lacks {want:?}"));
        }
    }
    if o.stderr.contains("panicked") || o.code == Some(101) {
        wrong.push(format!("panicked: {}", o.stderr.trim()));
    }
    // Bad usage leaves nothing behind: every file the case names as absent is absent.
    for absent in strings(&case["absent"]) {
        if d.join(&absent).exists() {
            wrong.push(format!("{absent} was left behind"));
        }
    }
    for (name, text) in case["unchanged"].as_object().into_iter().flatten() {
        let now = std::fs::read_to_string(d.join(name)).unwrap_or_default();
        if now != text.as_str().unwrap() {
            wrong.push(format!("{name} was changed to {now:?}"));
        }
    }
    wrong
}

#[test]
fn every_adversarial_case_exits_as_stated_under_a_memory_cap() {
    let corpus = corpus();
    let cases = corpus["cases"].as_array().expect("cases");
    assert!(cases.len() >= 40, "the corpus has {} cases", cases.len());
    let mut names = std::collections::HashSet::new();
    for case in cases {
        let name = case["name"].as_str().expect("every case has a name");
        assert!(names.insert(name), "case {name} is listed twice");
    }
    let start = Instant::now();
    // Two runners take cases in turn: a third of the corpus waits on a deadline (a hung or
    // silent program), so the cases overlap well on two cores. The failures keep corpus order.
    let next = std::sync::atomic::AtomicUsize::new(0);
    let cache = SetupCache::default();
    let mut found: Vec<(usize, String)> = std::thread::scope(|s| {
        let runners: Vec<_> = (0..2)
            .map(|_| {
                s.spawn(|| {
                    let mut mine = Vec::new();
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some(case) = cases.get(i) else { break mine };
                        let name = case["name"].as_str().unwrap();
                        mine.extend(
                            run_case_with(case, &cache)
                                .into_iter()
                                .map(|why| (i, format!("{name}: {why}"))),
                        );
                    }
                })
            })
            .collect();
        runners
            .into_iter()
            .flat_map(|r| r.join().unwrap())
            .collect()
    });
    found.sort();
    let failures: Vec<String> = found.into_iter().map(|(_, why)| why).collect();
    println!(
        "adversarial corpus: {} cases, {} failures, {:.1} s",
        cases.len(),
        failures.len(),
        start.elapsed().as_secs_f64()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_runner_notices_a_wrong_exit_code_a_missing_message_and_a_leftover_file() {
    // A case that expects the wrong things must fail, or the corpus proves nothing.
    let case = serde_json::json!({
        "name": "self-check",
        "files": {"x.hex": {"text": "zz\n"}},
        "args": ["check", "x.hex", "--base", "2"],
        "exit": 0,
        "stderr": ["this text is not in the message"],
        "absent": ["x.hex"],
    });
    let wrong = run_case(&case);
    assert_eq!(wrong.len(), 3, "{wrong:?}");
}
