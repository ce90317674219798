//! Helpers every test module of this binary shares.

use std::process::{Command, Output};

/// Runs the `gartowen` binary built for these tests with `args`, capturing its output.
pub fn gartowen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gartowen"))
        .args(args)
        .output()
        .expect("the gartowen binary runs")
}

/// [`gartowen`] as (exit code, stdout, stderr), the streams as text.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = gartowen(args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `examples/external/NAME.c` compiled with `cc -O2 FLAGS…` into `dir`; the binary's path. Its
/// name carries the flags, so one folder holds several builds of one example.
pub fn build_c_example(dir: &std::path::Path, name: &str, flags: &[&str]) -> String {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/external")
        .join(format!("{name}.c"));
    let suffix: String = flags
        .iter()
        .flat_map(|f| f.chars().filter(char::is_ascii_alphanumeric))
        .collect();
    let out = dir.join(if suffix.is_empty() {
        name.to_string()
    } else {
        format!("{name}_{suffix}")
    });
    let status = std::process::Command::new("cc")
        .arg("-O2")
        .args(flags)
        .arg("-o")
        .arg(&out)
        .arg(src)
        .status()
        .expect("cc");
    assert!(status.success());
    out.to_str().unwrap().to_string()
}
