//! Every repository path the documentation cites exists: a `code span` that starts with a
//! top-level folder of the repository (`crates/…`, `docs/…`, `tests/…`, …) and every relative
//! markdown link, in README.md, docs/, proofs/, python/ and examples/. Spans with wildcards or
//! placeholders (`*`, `{`, `<`, `$`, `|`) are patterns, not paths, and are skipped; a `:line`
//! or `#anchor` suffix is dropped.

use std::path::{Path, PathBuf};

/// The folders a cited path may start with.
const ROOTS: [&str; 12] = [
    "crates/",
    "src/",
    "tests/",
    "python/",
    "oracles/",
    "proofs/",
    "docs/",
    "record/",
    "scripts/",
    "examples/",
    ".ci/",
    "benches/",
];

/// The repository paths `text` cites as code spans, cleaned of suffixes.
fn cited_paths(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (k, span) in text.split('`').enumerate() {
        // Odd pieces are inside backticks.
        if k % 2 == 0 || span.contains(char::is_whitespace) {
            continue;
        }
        if !ROOTS.iter().any(|r| span.starts_with(r)) || span.contains(['*', '{', '<', '$', '|']) {
            continue;
        }
        let path = span.split([':', '#']).next().unwrap_or(span);
        out.push(path.trim_end_matches(['.', ',', ';', ')']).to_string());
    }
    out
}

/// The relative targets of markdown links `](target)` in `text`, anchors dropped.
fn linked_paths(text: &str) -> Vec<String> {
    text.split("](")
        .skip(1)
        .filter_map(|rest| rest.split([')', ' ']).next())
        .filter(|t| !t.starts_with("http") && !t.starts_with('#') && !t.starts_with("mailto:"))
        .map(|t| t.split('#').next().unwrap_or(t).to_string())
        .filter(|t| !t.is_empty())
        .collect()
}

fn markdown_files(root: &Path) -> Vec<PathBuf> {
    let mut files = vec![root.join("README.md")];
    let mut stack: Vec<PathBuf> = ["docs", "proofs", "python", "examples"]
        .iter()
        .map(|d| root.join(d))
        .collect();
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "md") {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn the_scanner_finds_spans_and_links_and_skips_patterns() {
    let text = "see `crates/a/b.rs:12`, `docs/x.md#part`, `figure_*.png`, `crates/{a,b}`, \
                `cargo test`, `tests/y.rs`. and [z](../z.md#top) [w](https://x) [v](#here)";
    assert_eq!(
        cited_paths(text),
        ["crates/a/b.rs", "docs/x.md", "tests/y.rs"]
    );
    assert_eq!(linked_paths(text), ["../z.md"]);
}

#[test]
fn every_path_the_documentation_cites_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = markdown_files(root);
    assert!(files.len() > 10, "the docs were found: {files:?}");
    let mut missing = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let doc = f.strip_prefix(root).unwrap().display().to_string();
        for p in cited_paths(&text) {
            if !root.join(&p).exists() {
                missing.push(format!("{doc}: `{p}`"));
            }
        }
        for p in linked_paths(&text) {
            if !f.parent().unwrap().join(&p).exists() {
                missing.push(format!("{doc}: link ({p})"));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "cited but missing:\n{}",
        missing.join("\n")
    );
}
