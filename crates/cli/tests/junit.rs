//! `--junit FILE` on verify, check and inspect: JUnit XML that a standard parser reads, with
//! the schema's required elements and one failing testcase per failing check.

use crate::support::gartowen;

/// (suite name, testcase name, failed) for every testcase, after checking the elements and
/// attributes the JUnit schema requires and that the counts agree with the cases.
fn cases(xml: &str) -> Vec<(String, String, bool)> {
    let doc = roxmltree::Document::parse(xml).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "testsuites");
    let mut out = Vec::new();
    for suite in root.children().filter(|n| n.has_tag_name("testsuite")) {
        let name = suite.attribute("name").expect("testsuite@name").to_string();
        let tests: usize = suite.attribute("tests").expect("tests").parse().unwrap();
        let failures: usize = suite
            .attribute("failures")
            .expect("failures")
            .parse()
            .unwrap();
        let mut seen = (0, 0);
        for case in suite.children().filter(|n| n.has_tag_name("testcase")) {
            assert!(case.attribute("classname").is_some() && case.attribute("time").is_some());
            let failure = case.children().find(|n| n.has_tag_name("failure"));
            if let Some(f) = failure {
                assert!(!f.attribute("message").unwrap_or("").is_empty());
                seen.1 += 1;
            }
            seen.0 += 1;
            out.push((
                name.clone(),
                case.attribute("name").expect("testcase@name").to_string(),
                failure.is_some(),
            ));
        }
        assert_eq!(seen, (tests, failures), "counts of {name}");
    }
    out
}

#[test]
fn verify_junit_has_a_failing_case_per_failing_check() {
    let dir = tempfile::tempdir().unwrap();
    let junit = dir.path().join("v.xml");
    let cert = dir.path().join("v.json");
    let o = gartowen(&[
        "verify",
        "--impl",
        "digital-shift",
        "--impl",
        "owen-per-bit-hash",
        "--claim",
        "owen",
        "--junit",
        junit.to_str().unwrap(),
        "--json",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let xml = std::fs::read_to_string(&junit).unwrap();
    let all = cases(&xml);
    let failing: Vec<&str> = all.iter().filter(|c| c.2).map(|c| c.1.as_str()).collect();
    assert_eq!(
        failing,
        ["pair-law", "flip-rank", "collisions", "pair-lemma"]
    );
    assert!(all
        .iter()
        .filter(|c| c.0.starts_with("owen-per-bit-hash"))
        .all(|c| !c.2));
    // Two implementations × (function, nested, nets, six law families, expect).
    assert_eq!(all.len(), 20);
    assert!(xml.contains(&format!("certificate: {}", cert.display())));
}

#[test]
fn check_and_inspect_write_junit() {
    let dir = tempfile::tempdir().unwrap();
    let pts = dir.path().join("p.hex");
    assert!(gartowen(&[
        "generate",
        "--seq",
        "sobol",
        "--dims",
        "3",
        "--log2-n",
        "10",
        "-o",
        pts.to_str().unwrap(),
    ])
    .status
    .success());
    let junit = dir.path().join("c.xml");
    let o = gartowen(&[
        "check",
        pts.to_str().unwrap(),
        "--base",
        "2",
        "--t",
        "0",
        "--projections",
        "pairs",
        "--junit",
        junit.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let c = cases(&std::fs::read_to_string(&junit).unwrap());
    // Sobol pairs (0,1) is a (0,10,2)-net; (0,2) and (1,2) are not.
    assert_eq!(
        c.iter().map(|c| (c.1.as_str(), c.2)).collect::<Vec<_>>(),
        [
            ("dims [0,1]", false),
            ("dims [0,2]", true),
            ("dims [1,2]", true)
        ]
    );
    // A failure names the projection, the property and its first failing box.
    let xml = std::fs::read_to_string(&junit).unwrap();
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let message = doc
        .descendants()
        .find(|n| n.has_tag_name("failure"))
        .and_then(|f| f.attribute("message"))
        .unwrap()
        .to_string();
    assert!(
        message.starts_with("dims [0,2]: not a (0,10,2)-net in base 2: shape [")
            && message.contains("the box")
            && message.contains("every box must hold 1"),
        "{message}"
    );
    let junit = dir.path().join("i.xml");
    let o = gartowen(&[
        "inspect",
        "--scramble",
        "owen-oracle:base=16",
        "--base",
        "2",
        "--width",
        "16",
        "--junit",
        junit.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let c = cases(&std::fs::read_to_string(&junit).unwrap());
    assert_eq!(c.len(), 1);
    assert!(c[0].1.starts_with("nested in base 2") && c[0].2);
}

/// A program that fails (here `false`, which exits at once) or is no function still gets its
/// JUnit file, with one failing testcase saying why (before: exit 3 and no file at all).
#[test]
fn inspect_writes_junit_when_the_external_program_fails() {
    let dir = tempfile::tempdir().unwrap();
    for base in ["2", "3"] {
        let xml = dir.path().join(format!("inspect-{base}.xml"));
        let o = gartowen(&[
            "inspect",
            "--external",
            "false",
            "--base",
            base,
            "--junit",
            xml.to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(3),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let text = std::fs::read_to_string(&xml).expect("the JUnit file is written");
        let all = cases(&text);
        assert_eq!(all.len(), 1, "{text}");
        assert_eq!(
            (all[0].1.as_str(), all[0].2),
            ("external program", true),
            "{text}"
        );
        assert!(text.contains("exited with status 1"), "{text}");
    }
}
