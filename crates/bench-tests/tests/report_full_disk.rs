//! A report that hits a full disk leaves its folder as it was (it once left new PNGs without
//! report.md). The file-size limit that stands in for a full disk applies to the whole process,
//! and `cargo test` runs this binary's other tests on its other threads: the test runs its body
//! in a child process, this binary filtered to this one test.

use crate::common;

use std::collections::BTreeMap;
use std::os::unix::fs::MetadataExt;
use std::path::Path;

/// Every file in `dir` with its inode and bytes.
fn snapshot(dir: &Path) -> BTreeMap<String, (u64, Vec<u8>)> {
    std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| {
            let m = e.metadata().unwrap();
            (
                e.file_name().to_string_lossy().into_owned(),
                (m.ino(), std::fs::read(e.path()).unwrap()),
            )
        })
        .collect()
}

/// Set in the child process that runs the body under the limit.
const CHILD: &str = "GARTOWEN_FULL_DISK_CHILD";

#[test]
fn a_write_error_keeps_the_previous_report_whole_and_leaves_no_staging_folder() {
    if std::env::var_os(CHILD).is_some() {
        return under_a_file_size_limit();
    }
    // The test's name in this binary: its module path without the crate's name.
    let module = module_path!().split_once("::").unwrap().1;
    let name = format!(
        "{module}::a_write_error_keeps_the_previous_report_whole_and_leaves_no_staging_folder"
    );
    let out = std::process::Command::new(std::env::current_exe().unwrap())
        .args([name.as_str(), "--exact", "--test-threads", "1"])
        .env(CHILD, "1")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // A filter that matched no test would pass too.
    assert!(stdout.contains("1 passed"), "{stdout}");
}

/// Two reports into one folder, the second past a file-size limit, then without it.
fn under_a_file_size_limit() {
    let registry = gartowen::registry();
    let dir = tempfile_dir();
    let first = common::report(-1.5, 1e-5, 2.0);
    gartowen_bench::report::write_report(&first, &registry, &dir, None).unwrap();
    let before = snapshot(&dir);
    assert!(before.contains_key("report.md") && before.contains_key("report.json"));
    let largest_png = before
        .iter()
        .filter(|(n, _)| n.ends_with(".png"))
        .map(|(_, (_, b))| b.len())
        .max()
        .expect("figures");
    // The second report's figures fit under the limit, its report.json does not: the write
    // fails after the figures are done, the case that once left PNGs without report.md.
    let mut second = common::report(-1.4, 2e-5, 2.5);
    second.tool_version = "x".repeat(largest_png + 1);
    let limit = (largest_png + 1) as u64;
    // SAFETY: plain libc calls on this process; SIGXFSZ ignored makes an over-limit write
    // fail with EFBIG instead of ending the process.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
        let rl = libc::rlimit {
            rlim_cur: limit,
            rlim_max: libc::RLIM_INFINITY,
        };
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &rl), 0);
    }
    let result = gartowen_bench::report::write_report(&second, &registry, &dir, None);
    // SAFETY: as above.
    unsafe {
        let rl = libc::rlimit {
            rlim_cur: libc::RLIM_INFINITY,
            rlim_max: libc::RLIM_INFINITY,
        };
        libc::setrlimit(libc::RLIMIT_FSIZE, &rl);
    }
    let e = result.expect_err("report.json exceeds the limit");
    assert!(e.to_string().contains("report.json"), "{e}");
    let now = snapshot(&dir);
    let changed: Vec<&String> = now
        .keys()
        .chain(before.keys())
        .filter(|n| now.get(*n) != before.get(*n))
        .collect();
    assert!(
        changed.is_empty(),
        "the earlier report was touched: {changed:?}"
    );
    // Without the limit the same report lands whole, replacing every file.
    gartowen_bench::report::write_report(&second, &registry, &dir, None).unwrap();
    let after = snapshot(&dir);
    assert_eq!(
        after.keys().collect::<Vec<_>>(),
        before.keys().collect::<Vec<_>>()
    );
    assert!(after.iter().all(|(n, (ino, _))| *ino != before[n].0));
    let _ = std::fs::remove_dir_all(&dir);
}

fn tempfile_dir() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("gartowen-full-disk-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}
