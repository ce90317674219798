//! The audit against a real quick run: the untouched certificate passes, and each edit is
//! refused naming its field.

use super::shards::shard_members;
use super::*;
use crate::battery::{seeds_used, verify_shard, Shard};
use serde_json::json;

fn registry() -> Registry {
    let mut r = Registry::with_core();
    for spec in gartowen_owen::registry::specs() {
        r.add(spec);
    }
    r
}

/// A certificate of a quick run over `none` (claims nothing) and the base-4 Owen oracle
/// (claims Owen), written as `gartowen verify --json` writes it.
fn certificate(registry: &Registry) -> Certificate {
    certificate_of(registry, &["none", "owen-oracle:base=4"])
}

/// A certificate of a quick run over `names`, as `gartowen verify --json` writes it.
fn certificate_of(registry: &Registry, names: &[&str]) -> Certificate {
    let names: Vec<String> = names.iter().map(|n| n.to_string()).collect();
    let reports = verify_shard(
        registry,
        &names,
        Level::Quick,
        Shard::ALL,
        None,
        &gartowen_core::Silent,
    )
    .unwrap();
    let failed = reports.iter().any(ImplReport::failed);
    Certificate::new(
        "verify",
        if failed {
            CertVerdict::Fail
        } else {
            CertVerdict::Pass
        },
        json!({
            "level": Level::Quick,
            "node_law_seeds": Level::Quick.plan().law_seeds,
            "family_alpha": FAMILY_ALPHA,
            "claim_override": null,
            "shard": {"index": 1, "count": 1},
            "implementations_total": names.len(),
        }),
        seeds_used(0),
        vec![],
        json!({ "implementations": reports }),
    )
}

/// Applies `edit` to the certificate's JSON and reads it back.
fn edited(c: &Certificate, edit: impl Fn(&mut Value)) -> Certificate {
    let mut v = serde_json::to_value(c).unwrap();
    edit(&mut v);
    serde_json::from_value(v).unwrap()
}

/// The index of check `name` of implementation `k`.
fn check_at(c: &Certificate, k: usize, name: &str) -> usize {
    c.result["implementations"][k]["checks"]
        .as_array()
        .unwrap()
        .iter()
        .position(|x| x["check"] == name)
        .unwrap()
}

#[test]
fn an_untouched_run_passes_and_every_edit_is_refused_naming_its_field() {
    let registry = registry();
    let c = certificate(&registry);
    let run = audit_verify(&c, &registry).unwrap();
    assert_eq!(run.level, Level::Quick);
    assert_eq!(run.reports.len(), 2);
    assert_eq!(run.shard, (1, 1));
    // Only the oracle's claim gets law verdicts.
    assert_eq!(run.judged, Some(1));
    let node = check_at(&c, 1, "node-law");
    let pair = check_at(&c, 1, "pair-law");
    let nested = check_at(&c, 0, "nested");
    let at = |k: usize, i: usize| format!("/result/implementations/{k}/checks/{i}");
    type Edit = Box<dyn Fn(&mut Value)>;
    let set = |pointer: String, value: Value| -> Edit {
        Box::new(move |v: &mut Value| *v.pointer_mut(&pointer).unwrap() = value.clone())
    };
    let cases: Vec<(Edit, String)> = vec![
        (
            set(format!("{}/tests/0/p_value", at(1, pair)), json!(2.5)),
            format!("result.implementations[1].checks[{pair}].tests[0].p_value"),
        ),
        (
            set(format!("{}/p_value", at(1, pair)), json!(-1.0)),
            format!("result.implementations[1].checks[{pair}].p_value"),
        ),
        (
            set(format!("{}/alpha", at(1, node)), json!(0.5)),
            "result.implementations[1].checks".into(),
        ),
        (
            set(format!("{}/tests/0/p_value", at(1, node)), json!(0.0)),
            format!("result.implementations[1].checks[{node}].tests[0].deviates"),
        ),
        (
            set(format!("{}/tests/0/deviates", at(1, node)), json!(true)),
            format!("result.implementations[1].checks[{node}].tests[0].deviates"),
        ),
        (
            // A χ² sub-test's power is recomputed (an exact test's is its own words).
            set(format!("{}/tests/1/power", at(1, node)), json!("anything")),
            format!("result.implementations[1].checks[{node}].tests[1].power"),
        ),
        (
            set(format!("{}/verdict", at(1, node)), json!("fail")),
            format!("result.implementations[1].checks[{node}].verdict"),
        ),
        (
            set(format!("{}/detail", at(1, node)), json!("fine")),
            format!("result.implementations[1].checks[{node}].detail"),
        ),
        (
            set(format!("{}/value", at(1, node)), json!(1e9)),
            format!("result.implementations[1].checks[{node}].value"),
        ),
        (
            set(format!("{}/verdict", at(0, nested)), json!("skipped")),
            format!("result.implementations[0].checks[{nested}].verdict"),
        ),
        (
            set(
                format!("{}/detail", at(0, nested)),
                json!("external program failed: x"),
            ),
            format!("result.implementations[0].checks[{nested}].detail"),
        ),
        (
            set("/result/implementations/1/claim".into(), json!("nested")),
            "result.implementations[1].claim".into(),
        ),
        (
            set(
                "/result/implementations/1/claims_nested_uniform".into(),
                json!(false),
            ),
            "result.implementations[1].claims_nested_uniform".into(),
        ),
        (
            set("/result/implementations/1/base".into(), json!(16)),
            "result.implementations[1].base".into(),
        ),
        (
            set("/result/implementations/0/name".into(), json!("none\u{7}")),
            "result.implementations[0].name".into(),
        ),
        (
            set("/result/implementations/0/name".into(), json!("no-such")),
            "result.implementations[0].name".into(),
        ),
        (
            set("/result/implementations/1/index".into(), json!(7)),
            "result.implementations[1].index".into(),
        ),
        (
            set("/result/implementations/1/profile/0/1".into(), json!("xx")),
            "result.implementations[1].profile".into(),
        ),
        (
            Box::new(|v: &mut Value| {
                v["result"]["implementations"][1]["checks"]
                    .as_array_mut()
                    .unwrap()
                    .remove(0);
            }),
            "result.implementations[1].checks".into(),
        ),
        (set("/verdict".into(), json!("fail")), "verdict".into()),
        (set("/seeds/1".into(), json!(99)), "seeds".into()),
        (
            set("/parameters/level".into(), json!("full")),
            "parameters.node_law_seeds".into(),
        ),
        (
            // The seed count relabelled with the level: the sub-tests still say n = 2000.
            Box::new(|v: &mut Value| {
                v["parameters"]["level"] = json!("full");
                v["parameters"]["node_law_seeds"] = json!(10_000);
            }),
            "parameters.level".into(),
        ),
        (
            set("/parameters/level".into(), json!("often")),
            "parameters.level".into(),
        ),
        (
            set("/parameters/family_alpha".into(), json!(0.05)),
            "parameters.family_alpha".into(),
        ),
        (
            set("/parameters/claim_override".into(), json!("bogus")),
            "parameters.claim_override".into(),
        ),
        (
            set("/parameters/implementations_total".into(), json!(0)),
            "parameters.implementations_total".into(),
        ),
        (
            set("/parameters/implementations_total".into(), json!(3)),
            "result.implementations".into(),
        ),
        (
            set("/parameters/shard".into(), json!({"index": 3, "count": 2})),
            "parameters.shard".into(),
        ),
        (
            set("/tool_version".into(), json!("0.0.1")),
            "tool_version".into(),
        ),
        (set("/tool".into(), json!("other")), "tool".into()),
        (set("/command".into(), json!("check")), "command".into()),
    ];
    for (edit, field) in cases {
        let e = audit_verify(&edited(&c, edit), &registry)
            .err()
            .unwrap_or_else(|| panic!("the edit of {field} was accepted"));
        assert_eq!(e.field, field, "{e}");
    }
}

#[test]
fn the_whole_run_must_hold_every_implementation_and_the_judged_count() {
    let registry = registry();
    let c = certificate(&registry);
    let run = audit_verify(&c, &registry).unwrap();
    assert!(audit_merged(&run.reports, 2, Some(1)).is_ok());
    assert!(audit_merged(&run.reports, 2, None).is_ok());
    // One implementation short, or a divisor the claims do not give.
    assert_eq!(
        audit_merged(&run.reports[..1], 2, Some(1))
            .unwrap_err()
            .field,
        "result.implementations"
    );
    assert!(audit_merged(&run.reports, 2, Some(2)).is_err());
    // A shard is checked as far as one shard shows: its own count is not the run's, but
    // it must hold exactly its members (shard 2/2 of four: implementations 1 and 3).
    let shard = edited(&c, |v| {
        v["parameters"]["shard"] = json!({"index": 2, "count": 2});
        v["parameters"]["implementations_total"] = json!(4);
        v["result"]["implementations"][0]["index"] = json!(1);
        v["result"]["implementations"][1]["index"] = json!(3);
    });
    let run = audit_verify(&shard, &registry).unwrap();
    assert_eq!(run.shard, (2, 2));
    assert_eq!(run.implementations_total, 4);
    for (index, count, total) in [(1, 2, 4), (2, 3, 4), (1, 3, 4), (2, 2, 6)] {
        let wrong = edited(&shard, |v| {
            v["parameters"]["shard"] = json!({"index": index, "count": count});
            v["parameters"]["implementations_total"] = json!(total);
        });
        let e = audit_verify(&wrong, &registry).unwrap_err();
        assert_eq!(
            e.field, "result.implementations",
            "{index}/{count} of {total}: {e}"
        );
        assert!(e.problem.contains("holds"), "{e}");
    }
    // A fixed matrix with more shards than implementations: shard 3/3 of two is empty and
    // passes (before, it was refused with no reason); the whole run may not be empty.
    let empty = |index: u64, count: u64, verdict: &str| {
        edited(&c, |v| {
            v["parameters"]["shard"] = json!({"index": index, "count": count});
            v["result"]["implementations"] = json!([]);
            v["verdict"] = json!(verdict);
        })
    };
    let run = audit_verify(&empty(3, 3, "pass"), &registry).unwrap();
    assert_eq!((run.shard, run.reports.len()), ((3, 3), 0));
    assert!(audit_verify(&empty(28, 28, "pass"), &registry).is_ok());
    assert_eq!(
        audit_verify(&empty(3, 3, "fail"), &registry)
            .unwrap_err()
            .field,
        "verdict"
    );
    for (index, count) in [(1, 1), (2, 3), (1, 3)] {
        let e = audit_verify(&empty(index, count, "pass"), &registry).unwrap_err();
        assert_eq!(e.field, "result.implementations", "{index}/{count}: {e}");
    }
    let e = audit_verify(&empty(4, 3, "pass"), &registry).unwrap_err();
    assert_eq!(e.field, "parameters.shard");
    assert!(e.problem.contains("1 ≤ I ≤ N"), "{e}");
    assert_eq!(
        AuditError {
            field: "f".into(),
            problem: "p".into()
        }
        .to_string(),
        "f: p"
    );
}

#[test]
fn in_base_3_nets_must_run_and_flip_rank_must_not() {
    let registry = registry();
    let c = certificate_of(&registry, &["owen-oracle:base=3"]);
    let run = audit_verify(&c, &registry).unwrap();
    assert_eq!(run.reports[0].base, 3);
    let nets = check_at(&c, 0, "nets");
    let rank = check_at(&c, 0, "flip-rank");
    let at = |i: usize| format!("/result/implementations/0/checks/{i}");
    let as_json = serde_json::to_value(&c).unwrap();
    assert_eq!(
        as_json.pointer(&format!("{}/verdict", at(nets))),
        Some(&json!("pass"))
    );
    let forged_skip = edited(&c, |v| {
        *v.pointer_mut(&format!("{}/verdict", at(nets))).unwrap() = json!("skipped")
    });
    let e = audit_verify(&forged_skip, &registry).unwrap_err();
    assert_eq!(
        e.field,
        format!("result.implementations[0].checks[{nets}].verdict")
    );
    let forged_rank = edited(&c, |v| {
        let t = v.pointer_mut(&format!("{}/tests/0", at(rank))).unwrap();
        // A sub-test that claims to have run, with plausible numbers.
        t["not_run"] = Value::Null;
        t["p_value"] = json!(0.5);
        t["statistic"] = json!(0.0);
    });
    let e = audit_verify(&forged_rank, &registry).unwrap_err();
    assert_eq!(
        e.field,
        format!("result.implementations[0].checks[{rank}].tests")
    );
    assert!(e.to_string().contains("does not apply"), "{e}");
}

#[test]
fn an_external_programs_battery_is_never_sharded() {
    let registry = registry();
    let c = certificate_of(&registry, &["none"]);
    let run = audit_verify(&c, &registry).unwrap();
    // External: its one report is shard 1/1 alone.
    assert!(shard_members(&run.reports, (1, 1), 1, true).is_ok());
    let e = shard_members(&[], (2, 2), 1, true).unwrap_err();
    assert_eq!(e.field, "parameters.shard");
    assert!(e.problem.contains("external"), "{e}");
    assert!(shard_members(&[], (2, 2), 1, false).is_ok());
}

#[test]
fn the_level_is_held_to_the_sub_tests_seed_counts_and_depths() {
    let registry = registry();
    let c = certificate(&registry);
    let node = check_at(&c, 1, "node-law");
    let relabelled = edited(&c, |v| {
        v["parameters"]["level"] = json!("full");
        v["parameters"]["node_law_seeds"] = json!(10_000);
    });
    let e = audit_verify(&relabelled, &registry).unwrap_err();
    assert_eq!(e.field, "parameters.level");
    assert!(
        e.problem.contains("at most n = 2000, as level quick draws"),
        "{e}"
    );
    // A node-law sub-test deeper than the level tests (quick: depth 12).
    let deeper = edited(&c, |v| {
        let t = &mut v["result"]["implementations"][1]["checks"][node]["tests"][0];
        t["depth"] = json!(13);
    });
    let e = audit_verify(&deeper, &registry).unwrap_err();
    assert_eq!(e.field, "parameters.level");
    assert!(e.problem.contains("tested depth 13"), "{e}");
}
