//! End-to-end checks of the declared battery: `verify --list-checks`, `verify --profile`, and the `function`
//! structure check on a program that is not one.

use crate::support::gartowen;

#[test]
fn list_checks_prints_the_battery_and_refuses_a_run_alongside() {
    let o = gartowen(&["verify", "--list-checks"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    let at = |name: &str| {
        text.find(&format!("  {name} "))
            .unwrap_or_else(|| panic!("{name} listed"))
    };
    assert!(at("inverse") < at("nets") && at("nets") < at("node-law"));
    assert!(at("node-law") < at("dimensions") && at("dimensions") < at("expect"));
    assert!(text.contains("| seeds of the per-seed laws | 2,000 | 10,000 | 50,000 |"));
    let o = gartowen(&["verify", "--list-checks", "--impl", "lk-hash"]);
    assert_eq!(
        o.status.code(),
        Some(2),
        "a listing does not run implementations"
    );
    assert!(o.stdout.is_empty());
}

/// A protocol program (Python) whose answer for a word is the word XOR its position in the
/// request: nested word by word when asked one word at a time, but not a function.
const POSITIONAL: &str = r#"
import struct, sys
inp, out = sys.stdin.buffer, sys.stdout.buffer
while True:
    head = inp.read(32)
    if len(head) < 32:
        break
    _, _, width, _, _, n, _, _ = struct.unpack("<4sHHIIIIQ", head)
    size = width // 8
    data = inp.read(n * size)
    fmt = "<%d%s" % (n, "I" if size == 4 else "Q")
    words = struct.unpack(fmt, data)
    mask = (1 << width) - 1
    out.write(b"GOWR" + struct.pack("<I", n) + struct.pack(fmt, *[(w ^ k) & mask for k, w in enumerate(words)]))
    out.flush()
"#;

#[test]
fn a_program_whose_answer_depends_on_the_request_is_not_a_function() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("positional.py");
    std::fs::write(&script, POSITIONAL).unwrap();
    let command = format!("python3 {}", script.display());
    // Each command fails (exit 1) with a message holding every fragment.
    let fails_with = |args: &[&str], fragments: &[&str]| {
        let o = gartowen(args);
        let text = String::from_utf8_lossy(&o.stdout);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{text}{stderr}");
        assert!(fragments.iter().all(|f| text.contains(f)), "{text}");
    };
    fails_with(
        &[
            "verify",
            "--external",
            &command,
            "--base",
            "2",
            "--claim",
            "nested",
        ],
        &["not a function", "at another position"],
    );
    fails_with(
        &[
            "inspect",
            "--external",
            &command,
            "--base",
            "2",
            "--width",
            "32",
        ],
        &["FAIL function: not a function"],
    );
}

#[test]
fn the_time_profile_lists_the_slowest_checks_and_the_words_the_json_records() {
    let dir = tempfile::tempdir().unwrap();
    let json = dir.path().join("p.json");
    let o = gartowen(&[
        "verify",
        "--impl",
        "lk-hash",
        "--impl",
        "art-owen-8p",
        "--profile",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout).to_string();
    assert!(text.contains("time profile: 2 implementations"), "{text}");
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&json).unwrap()).unwrap();
    let imps = v["result"]["implementations"].as_array().unwrap();
    // The slowest-entries block: ten lines, seconds never increasing, each an entry of the JSON.
    let block: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.contains("slowest 10 (implementation, check)"))
        .skip(1)
        .take_while(|l| l.starts_with("    "))
        .collect();
    assert_eq!(block.len(), 10, "{text}");
    let seconds: Vec<f64> = block
        .iter()
        .map(|l| {
            let at = l.find(" s ").expect("a seconds column");
            l[..at].split_whitespace().last().unwrap().parse().unwrap()
        })
        .collect();
    assert!(seconds.windows(2).all(|w| w[0] >= w[1]), "{seconds:?}");
    // Per check, the words printed are the sum of the JSON's words over the implementations.
    for family in ["node-law", "pair-law", "collisions"] {
        let words: u64 = imps
            .iter()
            .flat_map(|r| r["checks"].as_array().unwrap())
            .filter(|c| c["check"] == family)
            .map(|c| c["words"].as_u64().expect("law checks count their words"))
            .sum();
        assert!(words > 0);
        let line = text
            .lines()
            .skip_while(|l| !l.contains("per check:"))
            .find(|l| l.trim_start().starts_with(family))
            .unwrap_or_else(|| panic!("no {family} line in {text}"));
        assert!(
            line.trim_end().ends_with(&format!(" {words}")),
            "{line} vs {words}"
        );
    }
    // Structure checks do not count words.
    assert!(imps[0]["checks"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["check"] == "nested")
        .all(|c| c.get("words").is_none()));
}
