//! The prerequisite check of the test command and the main job: with `coqc` hidden from PATH
//! and installing disabled, it stops at once (well within 10 s) naming the install line.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn find(tool: &str) -> Option<PathBuf> {
    if tool == "python3" {
        // Through the interpreter itself: a version manager's shim is a script that needs the
        // rest of PATH.
        let out = Command::new("python3")
            .args(["-c", "import sys; print(sys.executable)"])
            .output()
            .ok()?;
        let exe = String::from_utf8(out.stdout).ok()?;
        return Some(PathBuf::from(exe.trim())).filter(|p| p.is_file());
    }
    std::env::var_os("PATH").and_then(|p| {
        std::env::split_paths(&p)
            .map(|d| d.join(tool))
            .find(|f| f.is_file())
    })
}

#[test]
fn a_missing_coqc_stops_the_check_in_seconds_with_the_install_line() {
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("bin");
    std::fs::create_dir(&bin).unwrap();
    // Everything the script and a working machine offer, except coqc.
    for tool in [
        "bash", "dirname", "ls", "mktemp", "rm", "id", "cargo", "cc", "python3", "ocamlopt",
    ] {
        if let Some(p) = find(tool) {
            std::os::unix::fs::symlink(p, bin.join(tool)).unwrap();
        }
    }
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/prerequisites.sh");
    let start = Instant::now();
    let mut child = Command::new(find("bash").expect("bash"))
        .arg(&script)
        .env("PATH", &bin)
        .env("GARTOWEN_NO_INSTALL", "1")
        .env_remove("GARTOWEN_SKIP_PROOFS")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            panic!("the prerequisite check ran for more than 10 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("apt-get install -y"), "{err}");
    assert!(err.contains("coq") && err.contains("libcoq-flocq"), "{err}");
    assert!(err.contains("GARTOWEN_SKIP_PROOFS=1"), "{err}");

    // Skipping the proofs, nothing else is missing on this machine's tools.
    let out = Command::new(find("bash").unwrap())
        .arg(&script)
        .env("PATH", &bin)
        .env("GARTOWEN_NO_INSTALL", "1")
        .env("GARTOWEN_SKIP_PROOFS", "1")
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The main job's check installs nothing it does not need (issue 59: as root it once ran
/// `apt-get install parallel`, pulling sysstat and its timers): with cc present and GNU
/// parallel absent, a recording `apt-get` is never called; with cc absent it is called for gcc
/// alone, and the script says so before it does.
#[test]
fn only_what_is_missing_and_required_is_installed_and_announced() {
    let is_root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !is_root {
        eprintln!("skipped: installing is tried as root only");
        return;
    }
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts/prerequisites.sh");
    for with_cc in [true, false] {
        let dir = tempfile::tempdir().unwrap();
        let bin = dir.path().join("bin");
        std::fs::create_dir(&bin).unwrap();
        let mut tools = vec!["bash", "dirname", "ls", "mktemp", "rm", "id", "cargo"];
        if with_cc {
            tools.push("cc");
        }
        for tool in tools {
            if let Some(p) = find(tool) {
                std::os::unix::fs::symlink(p, bin.join(tool)).unwrap();
            }
        }
        let log = dir.path().join("apt.log");
        let fake = bin.join("apt-get");
        std::fs::write(
            &fake,
            format!(
                "#!{}\necho \"$*\" >> {}\n",
                find("bash").unwrap().display(),
                log.display()
            ),
        )
        .unwrap();
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
        let out = Command::new(find("bash").unwrap())
            .arg(&script)
            .env("PATH", &bin)
            .env("GARTOWEN_SKIP_PROOFS", "1")
            .env("GARTOWEN_SKIP_PYTHON", "1")
            .env_remove("GARTOWEN_NO_INSTALL")
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).to_string()
            + &String::from_utf8_lossy(&out.stderr);
        let calls = std::fs::read_to_string(&log).unwrap_or_default();
        if with_cc {
            assert_eq!(out.status.code(), Some(0), "{text}");
            assert_eq!(calls, "", "apt-get called with cc present: {text}");
        } else {
            assert!(calls.contains("install -y gcc"), "{calls}");
            assert!(!calls.contains("parallel"), "{calls}");
            assert!(
                text.contains("gcc missing and required; installing"),
                "{text}"
            );
        }
    }
}
