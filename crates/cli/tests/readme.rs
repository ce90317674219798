//! The README's command-line examples, run as written in a scratch folder (the external program
//! `./my_scrambler` is `examples/external/owen_per_bit.c`), and each one's comment held to what
//! the command prints.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The indented `gartowen …` lines of the README's "One example per interface" section, each
/// split into its arguments and its trailing comment.
fn readme_commands() -> Vec<(Vec<String>, String)> {
    let readme =
        std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../README.md"))
            .unwrap();
    let section = readme
        .split("## One example per interface")
        .nth(1)
        .expect("the README has a section 'One example per interface'");
    let section = section.split("\n## ").next().unwrap();
    section
        .lines()
        .filter_map(|l| l.strip_prefix("    gartowen "))
        .map(|l| {
            let (command, comment) = l.split_once('#').unwrap_or((l, ""));
            let args = command.split_whitespace().map(str::to_string).collect();
            (args, comment.trim().to_string())
        })
        .collect()
}

fn compile_owen_per_bit(dir: &Path) {
    let src =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/external/owen_per_bit.c");
    let status = Command::new("cc")
        .args(["-O2", "-o"])
        .arg(dir.join("my_scrambler"))
        .arg(src)
        .status()
        .expect("a C compiler `cc`");
    assert!(status.success());
}

/// What a comment promises, as the text the command must print: "t = 0: still a (0,3,16)-net in
/// base 16" → "t = 0 (m = 3, s = 16, base 16)"; "digest checked" → "digest matches".
fn promised_output(command: &str, comment: &str) -> Option<String> {
    if command == "check" {
        let net = comment.split('(').nth(1)?.split(')').next()?;
        let [t, m, s]: [&str; 3] = net.split(',').collect::<Vec<_>>().try_into().ok()?;
        let base = comment.rsplit("base ").next()?.trim();
        return Some(format!("t = {t} (m = {m}, s = {s}, base {base})"));
    }
    if comment.contains("digest checked") {
        return Some("digest matches".into());
    }
    None
}

#[test]
fn the_readme_command_line_examples_run_and_print_what_their_comments_say() {
    let commands = readme_commands();
    assert!(
        commands.len() >= 4,
        "README examples not found: {commands:?}"
    );
    let dir = tempfile::tempdir().unwrap();
    compile_owen_per_bit(dir.path());
    for (args, comment) in &commands {
        let o = Command::new(env!("CARGO_BIN_EXE_gartowen"))
            .args(args)
            .current_dir(dir.path())
            .output()
            .unwrap();
        let out = String::from_utf8_lossy(&o.stdout);
        let line = format!("gartowen {}", args.join(" "));
        assert_eq!(
            o.status.code(),
            Some(0),
            "{line}: {out}{}",
            String::from_utf8_lossy(&o.stderr)
        );
        if !comment.is_empty() {
            let promised = promised_output(&args[0], comment)
                .unwrap_or_else(|| panic!("{line}: no rule reads the comment '{comment}'"));
            assert!(
                out.contains(&promised),
                "{line}: prints no '{promised}':\n{out}"
            );
        }
    }
}

#[test]
fn a_comment_that_misstates_the_net_is_caught() {
    assert_eq!(
        promised_output("check", "t = 0: still a (0,3,16)-net in base 16").as_deref(),
        Some("t = 0 (m = 3, s = 16, base 16)")
    );
    assert_eq!(
        promised_output("check", "t = 1: a (1,4,2)-net in base 2").as_deref(),
        Some("t = 1 (m = 4, s = 2, base 2)")
    );
    assert_eq!(promised_output("verify", "a comment no rule reads"), None);
}
