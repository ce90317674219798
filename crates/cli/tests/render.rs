//! `gartowen render` runs the Python package's rendering benchmark: the arguments pass through
//! unchanged and its exit code comes back; a missing interpreter or package is named with the
//! install line, exit 2, no traceback.

use std::process::Command;

fn render(python: &str, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .arg("render")
        .args(args)
        .env("GARTOWEN_PYTHON", python)
        .output()
        .unwrap()
}

#[test]
fn arguments_pass_through_and_the_exit_code_comes_back() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("args");
    let fake = dir.path().join("python");
    // A stand-in interpreter: records what follows the launcher code, exits 7.
    std::fs::write(
        &fake,
        format!(
            "#!/bin/sh\nshift 2\necho \"$@\" > {}\nexit 7\n",
            log.display()
        ),
    )
    .unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
    let o = render(
        fake.to_str().unwrap(),
        &["--quick", "--out", "x y", "--help"],
    );
    assert_eq!(o.status.code(), Some(7));
    assert_eq!(
        std::fs::read_to_string(&log).unwrap(),
        "--quick --out x y --help\n"
    );
}

#[test]
fn a_missing_interpreter_or_package_is_named_with_the_install_line() {
    let o = render("/nonexistent/python3", &["--quick"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("/nonexistent/python3") && err.contains("pip install"),
        "{err}"
    );
    // A real interpreter that cannot see the package (-S: no site-packages).
    let Ok(python) = which("python3") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let bare = dir.path().join("bare-python");
    std::fs::write(&bare, format!("#!/bin/sh\nexec {python} -S \"$@\"\n")).unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&bare, std::fs::Permissions::from_mode(0o755)).unwrap();
    let o = render(bare.to_str().unwrap(), &["--quick"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("pip install ./python[mitsuba]") && !err.contains("Traceback"),
        "{err}"
    );
}

fn which(tool: &str) -> Result<String, ()> {
    let o = Command::new("sh")
        .args(["-c", &format!("command -v {tool}")])
        .output()
        .map_err(|_| ())?;
    let path = String::from_utf8_lossy(&o.stdout).trim().to_string();
    if path.is_empty() {
        Err(())
    } else {
        Ok(path)
    }
}
