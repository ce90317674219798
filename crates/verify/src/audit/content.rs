//! What a certificate is, read from its content and not from its `command` label: a verify
//! report relabelled `check` is still a verify report, and is held to a verify report's rules.
//! The `check` and `discrepancy` certificates' verdicts are recomputed from what they record.

use super::{refuse, AuditError};
use crate::certificate::{CertVerdict, Certificate};
use serde_json::Value;

/// The kinds of certificate gartowen writes, told apart by their fields.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Content {
    /// `verify` over implementations (registry or external): `result.implementations`.
    Verify,
    /// `verify --dims` (the every-word sweep): `parameters.sweep`.
    Sweep,
    /// `check`: net verdicts or t-values per projection.
    Check,
    /// `discrepancy`: a measured value, never a verdict.
    Discrepancy,
}

impl Content {
    /// The `command` label this content is written under.
    pub fn command(self) -> &'static str {
        match self {
            Content::Verify | Content::Sweep => "verify",
            Content::Check => "check",
            Content::Discrepancy => "discrepancy",
        }
    }
}

fn has(v: &Value, key: &str) -> bool {
    v.get(key).is_some_and(|x| !x.is_null())
}

/// A `check` result item: a net or sequence verdict (`holds`) or a t-value, per projection.
fn is_projection(v: &Value) -> bool {
    has(v, "projection") && (has(v, "holds") || has(v, "t"))
}

/// The kind of `cert`, from its fields alone; refused when it matches none or several.
pub fn content_of(cert: &Certificate) -> Result<Content, AuditError> {
    let (p, r) = (&cert.parameters, &cert.result);
    let verify = has(r, "implementations") || has(p, "node_law_seeds");
    let sweep = has(p, "sweep");
    let check = has(p, "base")
        && p.get("t").is_some()
        && p.get("m").is_some()
        && match r {
            Value::Array(items) => !items.is_empty() && items.iter().all(is_projection),
            other => is_projection(other),
        };
    let discrepancy = has(r, "kind") && has(r, "squared") && r.get("value").is_some();
    let kinds: Vec<Content> = [
        (verify && !sweep, Content::Verify),
        (sweep, Content::Sweep),
        (check, Content::Check),
        (discrepancy, Content::Discrepancy),
    ]
    .into_iter()
    .filter_map(|(matches, kind)| matches.then_some(kind))
    .collect();
    match kinds.as_slice() {
        [one] => {
            if cert.command != one.command() {
                return Err(refuse(
                    "command",
                    format!(
                        "'{}', but the content is a {} certificate's",
                        cert.command,
                        one.command()
                    ),
                ));
            }
            Ok(*one)
        }
        [] => Err(refuse(
            "result",
            format!(
                "labelled '{}', but its fields are those of no certificate gartowen writes",
                cert.command
            ),
        )),
        several => Err(refuse(
            "result",
            format!("its fields mix those of {several:?} certificates"),
        )),
    }
}

/// A `check` certificate: every projection's verdict agrees with its first failure, its base
/// and t with the parameters, and the overall verdict is `pass` iff every verdict holds
/// (t-values alone judge nothing and pass).
pub fn audit_check(cert: &Certificate) -> Result<String, AuditError> {
    let items: Vec<&Value> = match &cert.result {
        Value::Array(items) => items.iter().collect(),
        one => vec![one],
    };
    let asked_t = cert.parameters["t"].as_u64();
    let base = cert.parameters["base"].as_u64();
    let mut holds = true;
    let mut verdicts = 0;
    for (k, item) in items.iter().enumerate() {
        let at = if items.len() == 1 && !cert.result.is_array() {
            "result".to_string()
        } else {
            format!("result[{k}]")
        };
        let verdict = item.get("holds");
        match verdict {
            Some(Value::Bool(h)) => {
                verdicts += 1;
                holds &= *h;
                if *h != item["first_failure"].is_null() {
                    return Err(refuse(
                        format!("{at}.holds"),
                        format!("{h}, but first_failure is {}", item["first_failure"]),
                    ));
                }
                if asked_t.is_some() && item["t"].as_u64() != asked_t {
                    return Err(refuse(
                        format!("{at}.t"),
                        format!(
                            "{}, but parameters.t is {}",
                            item["t"], cert.parameters["t"]
                        ),
                    ));
                }
                if base.is_some() && item["base"].as_u64() != base {
                    return Err(refuse(
                        format!("{at}.base"),
                        format!(
                            "{}, but parameters.base is {}",
                            item["base"], cert.parameters["base"]
                        ),
                    ));
                }
            }
            Some(other) => {
                return Err(refuse(
                    format!("{at}.holds"),
                    format!("{other} is not true or false"),
                ))
            }
            None if asked_t.is_some() => {
                return Err(refuse(
                    format!("{at}.holds"),
                    format!(
                        "missing, but --t {} asks for a verdict",
                        cert.parameters["t"]
                    ),
                ))
            }
            None => {}
        }
    }
    let want = if holds {
        CertVerdict::Pass
    } else {
        CertVerdict::Fail
    };
    if cert.verdict != want {
        return Err(refuse(
            "verdict",
            format!(
                "says {:?}, the recorded results give {want:?}",
                cert.verdict
            )
            .to_lowercase(),
        ));
    }
    Ok(format!(
        "check, {} projection(s), {verdicts} verdict(s) recomputed",
        items.len()
    ))
}

/// A `discrepancy` certificate measures and judges nothing: its verdict is `measured`, and its
/// value is a number (or null where the f64 overflowed and the exact rational is recorded).
pub fn audit_discrepancy(cert: &Certificate) -> Result<String, AuditError> {
    if cert.verdict != CertVerdict::Measured {
        return Err(refuse(
            "verdict",
            format!(
                "says {:?}, but a discrepancy is measured, never judged",
                cert.verdict
            )
            .to_lowercase(),
        ));
    }
    match &cert.result["value"] {
        Value::Number(_) => {}
        Value::Null if has(&cert.result, "exact") => {}
        other => return Err(refuse("result.value", format!("{other} is not a number"))),
    }
    Ok("discrepancy, measured".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn net(holds: bool, t: u64) -> Value {
        json!({"base": 2, "dims": 2, "m": 6, "t": t, "holds": holds, "shapes_checked": 7,
               "projection": [0, 1],
               "first_failure": if holds { Value::Null } else { json!({"shape": [3, 3]}) }})
    }

    fn check_cert(verdict: CertVerdict, t: Value, result: Value) -> Certificate {
        Certificate::new(
            "check",
            verdict,
            json!({"base": 2, "m": null, "t": t}),
            vec![],
            vec![],
            result,
        )
    }

    fn discrepancy(verdict: CertVerdict, value: Value) -> Certificate {
        Certificate::new(
            "discrepancy",
            verdict,
            json!({"kind": "l2-star", "method": "auto"}),
            vec![],
            vec![],
            json!({"kind": "l2-star", "value": value, "squared": true, "exact": null}),
        )
    }

    #[test]
    fn check_verdicts_are_recomputed_from_the_projections() {
        let t_value = json!({"projection": [0, 1], "t": 1, "m": 6, "s": 2, "b": 2});
        let ok = [
            check_cert(CertVerdict::Pass, json!(0), net(true, 0)),
            check_cert(CertVerdict::Fail, json!(0), net(false, 0)),
            check_cert(
                CertVerdict::Fail,
                json!(0),
                json!([net(true, 0), net(false, 0)]),
            ),
            check_cert(CertVerdict::Pass, Value::Null, t_value.clone()),
        ];
        for c in &ok {
            assert_eq!(content_of(c), Ok(Content::Check));
            assert!(audit_check(c).is_ok(), "{:?}", audit_check(c));
        }
        let said = audit_check(&ok[2]).unwrap();
        assert_eq!(said, "check, 2 projection(s), 2 verdict(s) recomputed");
        assert!(audit_check(&ok[3]).unwrap().contains("0 verdict(s)"));
        let field = |c: &Certificate| audit_check(c).unwrap_err().field;
        let forged = [
            (
                check_cert(CertVerdict::Pass, json!(0), net(false, 0)),
                "verdict",
            ),
            (
                check_cert(
                    CertVerdict::Pass,
                    json!(0),
                    json!([net(true, 0), net(false, 0)]),
                ),
                "verdict",
            ),
            (
                check_cert(CertVerdict::Fail, Value::Null, t_value.clone()),
                "verdict",
            ),
            (
                check_cert(CertVerdict::Pass, json!(0), t_value),
                "result.holds",
            ),
            (
                check_cert(CertVerdict::Pass, json!(1), net(true, 0)),
                "result.t",
            ),
        ];
        for (c, f) in &forged {
            assert_eq!(field(c), *f);
        }
        let mut inconsistent = net(true, 0);
        inconsistent["first_failure"] = json!({"shape": [3, 3]});
        let c = check_cert(CertVerdict::Pass, json!(0), json!([inconsistent]));
        assert_eq!(field(&c), "result[0].holds");
    }

    #[test]
    fn a_check_needs_its_parameters_and_projections_that_say_something() {
        let ok = check_cert(CertVerdict::Pass, json!(0), net(true, 0));
        assert_eq!(content_of(&ok), Ok(Content::Check));
        // Each of base, t and m missing from the parameters: no kind at all.
        for key in ["base", "t", "m"] {
            let mut c = ok.clone();
            c.parameters.as_object_mut().unwrap().remove(key);
            assert_eq!(content_of(&c).unwrap_err().field, "result", "{key}");
        }
        // A result item without a projection, or with one but neither verdict nor t-value.
        for item in [
            json!({"holds": true, "t": 0}),
            json!({"projection": [0, 1], "m": 6}),
        ] {
            let mut c = ok.clone();
            c.result = item.clone();
            assert_eq!(content_of(&c).unwrap_err().field, "result", "{item}");
            c.result = json!([net(true, 0), item.clone()]);
            assert_eq!(content_of(&c).unwrap_err().field, "result", "[.., {item}]");
        }
        let mut empty = ok.clone();
        empty.result = json!([]);
        assert_eq!(content_of(&empty).unwrap_err().field, "result");
    }

    #[test]
    fn a_discrepancy_is_measured_and_labels_follow_the_content() {
        assert!(audit_discrepancy(&discrepancy(CertVerdict::Measured, json!(0.01))).is_ok());
        for v in [CertVerdict::Pass, CertVerdict::Fail] {
            let e = audit_discrepancy(&discrepancy(v, json!(0.01))).unwrap_err();
            assert_eq!(e.field, "verdict");
        }
        let e = audit_discrepancy(&discrepancy(CertVerdict::Measured, json!("small")));
        assert_eq!(e.unwrap_err().field, "result.value");
        // A null value (the f64 overflowed) stands only beside the exact rational.
        let mut overflowed = discrepancy(CertVerdict::Measured, Value::Null);
        let e = audit_discrepancy(&overflowed).unwrap_err();
        assert_eq!(e.field, "result.value");
        overflowed.result["exact"] = json!("1/3");
        assert!(audit_discrepancy(&overflowed).is_ok());
        // Relabelled: the content decides, and the label must agree with it.
        let mut d = discrepancy(CertVerdict::Measured, json!(0.01));
        assert_eq!(content_of(&d), Ok(Content::Discrepancy));
        d.command = "check".into();
        assert_eq!(content_of(&d).unwrap_err().field, "command");
        let mut c = check_cert(CertVerdict::Pass, json!(0), net(true, 0));
        c.command = "verify".into();
        assert_eq!(content_of(&c).unwrap_err().field, "command");
        let mut v = c.clone();
        v.command = "verify".into();
        v.result = json!({"implementations": []});
        v.parameters = json!({"node_law_seeds": 2000});
        assert_eq!(content_of(&v), Ok(Content::Verify));
        v.command = "check".into();
        assert_eq!(content_of(&v).unwrap_err().field, "command");
        v.parameters["sweep"] = json!({"dims": [0, 1]});
        v.command = "verify".into();
        assert_eq!(content_of(&v), Ok(Content::Sweep));
        // Fields of no kind, or of two.
        v.result = json!({"nothing": 1});
        v.parameters = json!({});
        assert_eq!(content_of(&v).unwrap_err().field, "result");
        // Each of a discrepancy result's kind, squared and value missing: no kind at all.
        for key in ["kind", "squared", "value"] {
            let mut d = discrepancy(CertVerdict::Measured, json!(0.01));
            d.result.as_object_mut().unwrap().remove(key);
            assert_eq!(content_of(&d).unwrap_err().field, "result", "{key}");
        }
        let mut both = discrepancy(CertVerdict::Measured, json!(0.01));
        both.result["implementations"] = json!([]);
        assert_eq!(content_of(&both).unwrap_err().field, "result");
    }
}
