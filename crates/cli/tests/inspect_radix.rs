//! `gartowen inspect --base B` in a base that is not a power of two: the base-3 oracle is
//! nested, its per-depth variant fails Owen's joint laws, an external program that reverses
//! the digits (a bijection, not nested) is caught with its witness, and requests that cannot
//! work exit 2.

use crate::support::run;

/// A version-2 program that writes the base-b digits of each word in reverse order.
const REVERSED_DIGITS: &str = r#"
#include "radix_digits.h"
#include "protocol.h"
static uint64_t scramble(uint64_t x, unsigned width, uint32_t base, uint32_t dim, uint64_t seed) {
    (void)dim; (void)seed;
    uint64_t y = 0;
    for (unsigned k = 0; k < digits_in(base, width); k++) { y = y * base + x % base; x /= base; }
    return y;
}
int main(int argc, char **argv) { (void)argc; return serve(argv[0]); }
"#;

#[test]
fn the_base_3_oracle_is_nested_and_its_per_depth_variant_fails_owens_joint_laws() {
    let (code, out, err) = run(&["inspect", "--scramble", "owen-oracle", "--base", "3"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains(
            "owen-oracle:base=3: nested scramble in base 3 (32-bit words of 20 base-3 digits"
        ),
        "{out}"
    );
    let args = [
        "inspect",
        "--scramble",
        "owen-oracle:per-depth",
        "--base",
        "3",
        "--laws",
    ];
    let (code, out, err) = run(&args);
    assert_eq!(
        code, 0,
        "judged on its own claim, marginal:symmetric: {out}{err}"
    );
    let (code, out, _) = run(&[&args[..], &["--claim", "owen"]].concat());
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("pair-law    fail"), "{out}");
    assert!(out.contains("flip-rank   notrun"), "{out}");
    let (code, out, err) = run(&[
        "inspect",
        "--scramble",
        "owen-oracle:cyclic",
        "--base",
        "5",
        "--width",
        "64",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(doc["report"]["digits"], 27);
    assert_eq!(doc["report"]["nested_scramble"], true);
    assert_eq!(doc["report"]["nodes_checked"], 2000);
}

#[test]
fn an_external_program_reversing_base_5_digits_is_not_nested_and_says_where() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("reversed.c");
    std::fs::write(&src, REVERSED_DIGITS).unwrap();
    let bin = dir.path().join("reversed");
    let include = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/external");
    let status = std::process::Command::new("cc")
        .args(["-O2", "-I"])
        .arg(&include)
        .arg("-o")
        .arg(&bin)
        .arg(&src)
        .status()
        .expect("cc");
    assert!(status.success());
    let junit = dir.path().join("inspect.xml");
    let (code, out, err) = run(&[
        "inspect",
        "--external",
        bin.to_str().unwrap(),
        "--base",
        "5",
        "--junit",
        junit.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("NOT a nested scramble in base 5"), "{out}");
    assert!(
        out.contains("first violation: NotNested at depth 0"),
        "{out}"
    );
    assert!(out.contains("(base-5 digit words)"), "{out}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(
        xml.contains("nested in base 5") && xml.contains("not a nested scramble"),
        "{xml}"
    );
}

#[test]
fn base_b_inspections_that_cannot_work_exit_2() {
    let cases: [(&[&str], &str); 4] = [
        (
            &["inspect", "--scramble", "art-owen-2", "--base", "3"],
            "only owen-oracle",
        ),
        (
            &[
                "inspect",
                "--scramble",
                "owen-oracle",
                "--base",
                "3",
                "--depth",
                "2",
            ],
            "--depth applies",
        ),
        (
            &[
                "inspect",
                "--scramble",
                "owen-oracle",
                "--base",
                "3",
                "--probes",
                "0",
            ],
            "--probes",
        ),
        (
            &[
                "inspect",
                "--scramble",
                "owen-oracle",
                "--base",
                "3",
                "--laws",
                "--claim",
                "marginal:affine",
            ],
            "affine",
        ),
    ];
    for (args, fragment) in cases {
        let (code, _, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(fragment), "{args:?}: {err}");
    }
}
