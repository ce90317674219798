//! The Slurm scripts of examples/slurm without a cluster: `check-summary.sbatch` run directly
//! on exit-code files, and `submit.sh` against a recording `sbatch` that expands `--output`
//! patterns as Slurm does.

use std::path::Path;
use std::process::Command;

fn slurm(script: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/slurm")
        .join(script)
}

/// An empty or garbled exit-code file is no verdict: the summary names it and exits 2
/// (before: `[ "" -gt 0 ]` failed quietly and the summary exited 0).
#[test]
fn check_summary_refuses_empty_and_garbled_exit_codes() {
    for (codes, want) in [
        (&["0", "0"][..], 0),
        (&["0", "1"][..], 1),
        (&["0", ""][..], 2),
        (&["0", "x7"][..], 2),
        (&["abc", "0"][..], 2),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let list = dir.path().join("list");
        std::fs::write(&list, "a.npy --base 2\nb.npy --base 2\n").unwrap();
        for (k, code) in codes.iter().enumerate() {
            std::fs::write(dir.path().join(format!("check{}.rc", k + 1)), code).unwrap();
        }
        let o = Command::new("bash")
            .arg(slurm("check-summary.sbatch"))
            .arg(&list)
            .arg(dir.path())
            .output()
            .unwrap();
        let text =
            String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(want), "{codes:?}: {text}");
        assert_eq!(
            want == 2,
            text.contains("unreadable exit code"),
            "{codes:?}: {text}"
        );
    }
}

/// Slurm's `--output` reads `%` as a pattern; an OUT with `%` in its name is passed as `%%`,
/// so the task logs land in OUT/logs (before: `%d` in a folder name became a number).
#[test]
fn submit_escapes_percent_signs_in_out() {
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("bin");
    std::fs::create_dir(&bin).unwrap();
    let record = dir.path().join("sbatch.log");
    let fake = bin.join("sbatch");
    std::fs::write(
        &fake,
        format!(
            "#!/usr/bin/env bash\nfor a in \"$@\"; do case \"$a\" in --output=*) echo \"${{a#--output=}}\" >> {};; esac; done\necho 4242\n",
            record.display()
        ),
    )
    .unwrap();
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
    let out = dir.path().join("run 100%done %a");
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap());
    let o = Command::new("bash")
        .arg(slurm("submit.sh"))
        .args(["verify", "2"])
        .arg(&out)
        .args(["--level", "quick"])
        .env("PATH", path)
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // Slurm's expansion: %% is a literal %, %a the task id (here 7); any other % pattern
    // would change the path.
    let expand = |p: &str| {
        p.replace("%%", "\u{0}")
            .replace("%a", "7")
            .replace('\u{0}', "%")
    };
    let logs: Vec<String> = std::fs::read_to_string(&record)
        .unwrap()
        .lines()
        .map(expand)
        .collect();
    let out = out.to_str().unwrap();
    assert_eq!(
        logs,
        [
            format!("{out}/logs/verify-7.out"),
            format!("{out}/logs/merge.out")
        ]
    );
}
