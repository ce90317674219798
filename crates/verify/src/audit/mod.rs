//! A verify certificate checked, not trusted: every field against the schema and the
//! registry, and every law verdict recomputed from the sub-test statistics the certificate
//! records (the same [`judge_families`] the battery ran). What the statistics cannot show (a
//! structure check's exact verdict) is held to the verdicts that check can give; the content
//! digest ([`crate::certificate::check_digest`]) catches edits that stay consistent.

use crate::certificate::{CertVerdict, Certificate};
use crate::judge::{judge_families, profile};
use crate::law_runner::FAMILIES;
use crate::level::Level;
use crate::stats::FAMILY_ALPHA;
use crate::structure::{Stage, STRUCTURE_CHECKS};
use crate::verdict::{CheckResult, ImplReport, Verdict};
use gartowen_core::registry::Registry;
use gartowen_core::{Claim, Width};
use serde_json::Value;
use std::fmt;

mod content;
mod shards;
mod sizes;

pub use content::{audit_check, audit_discrepancy, content_of, Content};

/// An inconsistency, naming the field (a JSON path) and what is wrong with it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AuditError {
    /// The field, e.g. `result.implementations[2].checks[5].verdict`.
    pub field: String,
    /// What is wrong, in words.
    pub problem: String,
}

impl fmt::Display for AuditError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field, self.problem)
    }
}

impl std::error::Error for AuditError {}

fn refuse(field: impl Into<String>, problem: impl Into<String>) -> AuditError {
    AuditError {
        field: field.into(),
        problem: problem.into(),
    }
}

/// Name of the check `--equivalent-to owen` adds.
const EQUIVALENCE_CHECK: &str = "equivalent-to-owen";
/// How a check that met a broken external program begins its detail.
const EXTERNAL_FAILURE: &str = "external program failed: ";

/// What a verify certificate says about its run, read and checked field by field.
#[derive(Debug, Clone, PartialEq)]
pub struct AuditedRun {
    /// The level.
    pub level: Level,
    /// The claim every implementation was judged on instead of its own, if any.
    pub claim_override: Option<Claim>,
    /// Implementations in the whole run (all shards).
    pub implementations_total: usize,
    /// This certificate's shard: (index, count), 1-based.
    pub shard: (u64, u64),
    /// The reports, as recorded.
    pub reports: Vec<ImplReport>,
    /// The number of judged implementations the recorded per-test levels imply (the
    /// Bonferroni divisor), where a law check was judged.
    pub judged: Option<usize>,
}

/// Checks a `verify` certificate of registry implementations (or of one external program)
/// field by field and recomputes its verdicts. A shard's certificate is checked as far as one
/// shard shows; [`audit_merged`] checks what only the whole run shows.
pub fn audit_verify(cert: &Certificate, registry: &Registry) -> Result<AuditedRun, AuditError> {
    envelope(cert)?;
    let p = &cert.parameters;
    let level: Level = serde_json::from_value(p["level"].clone())
        .map_err(|_| refuse("parameters.level", format!("{} is not a level", p["level"])))?;
    if p["node_law_seeds"].as_u64() != Some(level.plan().law_seeds as u64) {
        return Err(refuse(
            "parameters.node_law_seeds",
            format!(
                "{}, but level {} uses {}",
                p["node_law_seeds"],
                level.name(),
                level.plan().law_seeds
            ),
        ));
    }
    if p["family_alpha"].as_f64() != Some(FAMILY_ALPHA) {
        return Err(refuse(
            "parameters.family_alpha",
            format!("{}, but the battery's is {FAMILY_ALPHA}", p["family_alpha"]),
        ));
    }
    let claim_override = match &p["claim_override"] {
        Value::Null => None,
        Value::String(s) => {
            Some(Claim::parse(s).map_err(|e| refuse("parameters.claim_override", e.to_string()))?)
        }
        other => return Err(refuse("parameters.claim_override", format!("{other}"))),
    };
    let total = p["implementations_total"]
        .as_u64()
        .filter(|&n| n >= 1)
        .ok_or_else(|| refuse("parameters.implementations_total", "missing or 0"))?
        as usize;
    let shard = match (p["shard"]["index"].as_u64(), p["shard"]["count"].as_u64()) {
        (Some(i), Some(n)) if 1 <= i && i <= n => (i, n),
        (Some(_), Some(_)) => {
            return Err(refuse(
                "parameters.shard",
                format!("{}: a shard I/N has 1 ≤ I ≤ N", p["shard"]),
            ))
        }
        (None, None) if p.get("shard").is_none() => (1, 1),
        _ => {
            return Err(refuse(
                "parameters.shard",
                format!("{}: needs whole numbers index and count", p["shard"]),
            ))
        }
    };
    let external = p.get("external").filter(|e| !e.is_null());
    let main_seed = match external {
        Some(e) => e["seed"]
            .as_u64()
            .ok_or_else(|| refuse("parameters.external.seed", "missing"))?,
        None => 0,
    };
    if cert.seeds != crate::battery::seeds_used(main_seed) {
        return Err(refuse(
            "seeds",
            format!(
                "{:?}, but the battery draws from {:?}",
                cert.seeds,
                crate::battery::seeds_used(main_seed)
            ),
        ));
    }
    let reports: Vec<ImplReport> = serde_json::from_value(cert.result["implementations"].clone())
        .map_err(|e| refuse("result.implementations", e.to_string()))?;
    // The level's sizes first: every later check reads the sub-tests it sized.
    sizes::sizes_match_level(&reports, level)?;
    let equivalence = p.get("equivalence").is_some_and(|e| !e.is_null());
    let mut judged = None;
    for (k, r) in reports.iter().enumerate() {
        let at = format!("result.implementations[{k}]");
        let expected = match external {
            Some(e) => external_expectation(e, r, &at)?,
            None => registry_expectation(registry, r, claim_override, &at)?,
        };
        if r.index >= total {
            return Err(refuse(
                format!("{at}.index"),
                format!("{}, but the run has {total} implementations", r.index),
            ));
        }
        let implied = audit_report(r, &expected, equivalence, external.is_some(), &at)?;
        if let Some(j) = implied {
            match judged {
                Some(prev) if prev != j => {
                    return Err(refuse(
                        format!("{at}.checks"),
                        format!(
                            "per-test levels imply {j} judged implementations, earlier ones {prev}"
                        ),
                    ))
                }
                _ => judged = Some(j),
            }
        }
    }
    shards::shard_members(&reports, shard, total, external.is_some())?;
    if let Some(j) = judged {
        if j > total {
            return Err(refuse(
                "result.implementations",
                format!("per-test levels imply {j} judged implementations of {total}"),
            ));
        }
    }
    let failed = reports.iter().any(ImplReport::failed);
    let verdict = if failed {
        CertVerdict::Fail
    } else {
        CertVerdict::Pass
    };
    if cert.verdict != verdict {
        return Err(refuse(
            "verdict",
            format!("says {:?}, the checks give {verdict:?}", cert.verdict).to_lowercase(),
        ));
    }
    let run = AuditedRun {
        level,
        claim_override,
        implementations_total: total,
        shard,
        reports,
        judged,
    };
    if shard.1 == 1 {
        audit_merged(&run.reports, total, judged)?;
    }
    Ok(run)
}

/// What only the whole run shows: every implementation present once, and the Bonferroni
/// divisor the per-test levels imply equal to the number of implementations whose claims
/// get law verdicts.
pub fn audit_merged(
    reports: &[ImplReport],
    total: usize,
    judged: Option<usize>,
) -> Result<(), AuditError> {
    if reports.len() != total {
        return Err(refuse(
            "result.implementations",
            format!("{} of {total} implementations", reports.len()),
        ));
    }
    let claimed = reports
        .iter()
        .filter(|r| Claim::parse(&r.claim).is_ok_and(|c| c.marginal.is_some()))
        .count();
    if let Some(j) = judged {
        if j != claimed.max(1) {
            return Err(refuse(
                "result.implementations",
                format!(
                    "per-test levels imply {j} judged implementations, the claims give {claimed}"
                ),
            ));
        }
    }
    Ok(())
}

fn envelope(cert: &Certificate) -> Result<(), AuditError> {
    if cert.tool != "gartowen" {
        return Err(refuse("tool", format!("'{}', not gartowen", cert.tool)));
    }
    let ours = env!("CARGO_PKG_VERSION");
    if cert.tool_version != ours {
        return Err(refuse(
            "tool_version",
            format!(
                "made by gartowen {}; this build ({ours}) recomputes only its own certificates",
                cert.tool_version
            ),
        ));
    }
    if cert.command != "verify" {
        return Err(refuse(
            "command",
            format!("'{}', not a verify report", cert.command),
        ));
    }
    Ok(())
}

/// What a report must say of itself: its base and claim, and the checks it must have.
struct Expectation {
    base: u32,
    claim: Claim,
    /// The structure checks before the laws and after them.
    before: Vec<&'static str>,
    after: Vec<&'static str>,
    /// Whether `nested` may be skipped (the implementation has neither 32- nor 64-bit words).
    nested_may_skip: bool,
    /// The dimensions served (`--max-dims`), when not every one is.
    max_dims: Option<u32>,
}

fn plain_name(name: &str, at: &str) -> Result<(), AuditError> {
    if name.is_empty() || name.chars().any(char::is_control) {
        return Err(refuse(
            format!("{at}.name"),
            format!("{name:?} is empty or has control characters"),
        ));
    }
    Ok(())
}

fn registry_expectation(
    registry: &Registry,
    r: &ImplReport,
    claim_override: Option<Claim>,
    at: &str,
) -> Result<Expectation, AuditError> {
    plain_name(&r.name, at)?;
    let c = crate::candidate::registry_candidate(registry, &r.name, r.index)
        .map_err(|e| refuse(format!("{at}.name"), format!("'{}': {e}", r.name)))?;
    if c.name != r.name {
        return Err(refuse(
            format!("{at}.name"),
            format!("'{}' is listed as '{}'", r.name, c.name),
        ));
    }
    let widths = [Width::W32, Width::W64].map(|w| c.probe.supports_width(w));
    let stage = |stage: Stage| {
        STRUCTURE_CHECKS
            .iter()
            .filter(|s| s.stage == stage && (s.applies)(&c))
            .map(|s| s.name)
            .collect()
    };
    Ok(Expectation {
        base: c.base(),
        claim: claim_override.unwrap_or(c.claim),
        before: stage(Stage::BeforeLaws),
        after: stage(Stage::AfterLaws),
        nested_may_skip: !widths.contains(&true),
        max_dims: None,
    })
}

fn external_expectation(e: &Value, r: &ImplReport, at: &str) -> Result<Expectation, AuditError> {
    plain_name(&r.name, at)?;
    let base = e["base"]
        .as_u64()
        .and_then(|b| u32::try_from(b).ok())
        .ok_or_else(|| refuse("parameters.external.base", "missing"))?;
    let claim = e["claim"]
        .as_str()
        .and_then(|c| Claim::parse(c).ok())
        .ok_or_else(|| refuse("parameters.external.claim", format!("{}", e["claim"])))?;
    let mut after = Vec::new();
    if !e["expect"].is_null() {
        after.push("expect");
    }
    Ok(Expectation {
        base,
        claim,
        before: vec!["injective", "function", "nested", "nets"],
        after,
        nested_may_skip: false,
        max_dims: e["max_dims"].as_u64().and_then(|n| u32::try_from(n).ok()),
    })
}

/// Checks one report against what it must say and recomputes its law verdicts; returns the
/// number of judged implementations its per-test levels imply, if a law check was judged.
fn audit_report(
    r: &ImplReport,
    want: &Expectation,
    equivalence: bool,
    external: bool,
    at: &str,
) -> Result<Option<usize>, AuditError> {
    if r.base != want.base {
        return Err(refuse(
            format!("{at}.base"),
            format!(
                "{}, but '{}' scrambles in base {}",
                r.base, r.name, want.base
            ),
        ));
    }
    if Claim::parse(&r.claim).ok() != Some(want.claim) {
        return Err(refuse(
            format!("{at}.claim"),
            format!(
                "'{}', but '{}' is judged on '{}'",
                r.claim, r.name, want.claim
            ),
        ));
    }
    if r.claims_nested_uniform != want.claim.is_owen() {
        return Err(refuse(
            format!("{at}.claims_nested_uniform"),
            format!(
                "{}, but the claim is '{}'",
                r.claims_nested_uniform, want.claim
            ),
        ));
    }
    // A base that is not a power of two: digits are base-b integers, and only claims whose
    // group exists there are judged.
    let radix = !want.base.is_power_of_two();
    if let Err(e) = want.claim.in_base(want.base) {
        return Err(refuse(format!("{at}.claim"), e.to_string()));
    }
    let names: Vec<&str> = r.checks.iter().map(|c| c.check.as_str()).collect();
    let laws_failed = names.contains(&"laws");
    let mut expected: Vec<&str> = want.before.clone();
    if laws_failed {
        expected.push("laws");
    } else {
        expected.extend(FAMILIES.iter().map(|f| f.name()));
    }
    expected.extend(&want.after);
    if equivalence {
        expected.push(EQUIVALENCE_CHECK);
    }
    if names != expected {
        return Err(refuse(
            format!("{at}.checks"),
            format!(
                "'{}' has checks {names:?}, but is checked by {expected:?}",
                r.name
            ),
        ));
    }
    let mut families = Vec::new();
    let mut law_positions = Vec::new();
    let mut program_failed = false;
    for (k, c) in r.checks.iter().enumerate() {
        let field = format!("{at}.checks[{k}]");
        if c.detail.starts_with(EXTERNAL_FAILURE) {
            if !external {
                return Err(refuse(
                    format!("{field}.detail"),
                    "an external program's failure in a registry implementation's report",
                ));
            }
            if c.verdict != Verdict::Fail {
                return Err(refuse(
                    format!("{field}.verdict"),
                    "the program failed, yet the check does not",
                ));
            }
            program_failed = true;
        }
        if !c.detail.starts_with(EXTERNAL_FAILURE) {
            // A broken program's checks measured nothing: their numbers may be NaN.
            numbers_in_range(c, &field)?;
            // Otherwise only a dimension beyond those served keeps a sub-test from running
            // (and the GF(2) rank test, which applies in bases 2^q only).
            let inapplicable = radix && c.check == "flip-rank";
            if inapplicable && c.tests.iter().any(|t| t.ran()) {
                return Err(refuse(
                    format!("{field}.tests"),
                    format!(
                        "flip-rank ran in base {}, where it does not apply",
                        want.base
                    ),
                ));
            }
            if want.max_dims.is_none() && !inapplicable && c.tests.iter().any(|t| !t.ran()) {
                return Err(refuse(
                    format!("{field}.tests"),
                    "a sub-test did not run, yet every dimension is served",
                ));
            }
        }
        if let Some(family) = FAMILIES.iter().find(|f| f.name() == c.check) {
            families.push((family.name(), c.tests.clone()));
            law_positions.push(k);
            continue;
        }
        if c.detail.starts_with(EXTERNAL_FAILURE) {
            continue;
        }
        let allowed: &[Verdict] = match c.check.as_str() {
            "nested" if want.nested_may_skip => &[Verdict::Skipped],
            // The equivalence estimators are defined in bases 2^q.
            "equivalent-to-owen" if radix => &[Verdict::NotRun],
            // Its estimators read dimensions 0 and 1.
            "equivalent-to-owen" if want.max_dims.is_some_and(|n| n < 2) => &[Verdict::NotRun],
            "laws" => &[Verdict::Fail],
            _ => &[Verdict::Pass, Verdict::Fail],
        };
        if !allowed.contains(&c.verdict) {
            return Err(refuse(
                format!("{field}.verdict"),
                format!(
                    "'{}' gives {:?} here, never {:?}",
                    c.check, allowed, c.verdict
                )
                .to_lowercase(),
            ));
        }
    }
    // A broken program's law checks carry its failure, not their sub-tests' verdict.
    if families.is_empty() || program_failed {
        return Ok(None);
    }
    let implied = implied_judged(r, &law_positions, want.claim, &families, at)?;
    let recomputed = judge_families(families, want.claim, implied.unwrap_or(1), 0.0);
    for (&k, again) in law_positions.iter().zip(&recomputed) {
        same_law_check(&r.checks[k], again, &format!("{at}.checks[{k}]"))?;
    }
    let again = profile(&r.checks);
    if r.profile != again {
        return Err(refuse(
            format!("{at}.profile"),
            format!("{:?}, the sub-tests give {again:?}", r.profile),
        ));
    }
    Ok(implied)
}

/// The number of judged implementations (the Bonferroni divisor) that the first recorded
/// per-test level implies: α' = FAMILY_ALPHA / (judged × sub-tests), counting the claimed
/// sub-tests when the family has one, else all of them (measured families).
fn implied_judged(
    r: &ImplReport,
    law_positions: &[usize],
    claim: Claim,
    families: &[(&'static str, Vec<crate::subtest::SubTest>)],
    at: &str,
) -> Result<Option<usize>, AuditError> {
    // Sub-tests that did not run count towards no level.
    let all: Vec<_> = families
        .iter()
        .flat_map(|(_, t)| t.iter())
        .filter(|t| t.ran())
        .collect();
    let claimed = all.iter().filter(|t| t.requires.claimed_by(claim)).count();
    let Some(c) = law_positions
        .iter()
        .map(|&k| &r.checks[k])
        .find(|c| c.tests.iter().any(|t| t.ran()) && c.alpha.is_some())
    else {
        return Ok(None);
    };
    let a = c.alpha.expect("found with a level");
    let divisor = if c
        .tests
        .iter()
        .any(|t| t.ran() && t.requires.claimed_by(claim))
    {
        claimed
    } else {
        all.len()
    };
    let j = (FAMILY_ALPHA / (a * divisor.max(1) as f64)).round();
    if !(1.0..=1e9).contains(&j) {
        return Err(refuse(
            format!("{at}.checks"),
            format!("per-test level {a} implies no whole number of judged implementations"),
        ));
    }
    Ok(Some(j as usize))
}

/// p-values in [0, 1], statistics and values finite, levels in (0, 1).
fn numbers_in_range(c: &CheckResult, field: &str) -> Result<(), AuditError> {
    let unit = |x: f64| (0.0..=1.0).contains(&x);
    if let Some(p) = c.p_value.filter(|p| !unit(*p)) {
        return Err(refuse(
            format!("{field}.p_value"),
            format!("{p} is not in [0, 1]"),
        ));
    }
    if let Some(a) = c.alpha.filter(|a| !(*a > 0.0 && *a < 1.0)) {
        return Err(refuse(
            format!("{field}.alpha"),
            format!("{a} is not in (0, 1)"),
        ));
    }
    if let Some(v) = c.value.filter(|v| !v.is_finite()) {
        return Err(refuse(
            format!("{field}.value"),
            format!("{v} is not finite"),
        ));
    }
    for (k, t) in c.tests.iter().enumerate() {
        if !t.ran() {
            // A sub-test that did not run measured nothing and may not claim otherwise.
            if !(t.p_value.is_nan() && t.statistic.is_nan() && !t.deviates) {
                return Err(refuse(
                    format!("{field}.tests[{k}]"),
                    "not run, yet it carries a statistic, a p-value or a deviation",
                ));
            }
            plain_name(&t.name, &format!("{field}.tests[{k}]"))?;
            continue;
        }
        if !unit(t.p_value) {
            return Err(refuse(
                format!("{field}.tests[{k}].p_value"),
                format!("{} is not in [0, 1]", t.p_value),
            ));
        }
        if !t.statistic.is_finite() {
            return Err(refuse(
                format!("{field}.tests[{k}].statistic"),
                format!("{} is not finite", t.statistic),
            ));
        }
        plain_name(&t.name, &format!("{field}.tests[{k}]"))?;
    }
    Ok(())
}

/// A recorded law check against its recomputation, field by field (all but the time).
fn same_law_check(got: &CheckResult, again: &CheckResult, field: &str) -> Result<(), AuditError> {
    for (k, (t, u)) in got.tests.iter().zip(&again.tests).enumerate() {
        if t.deviates != u.deviates {
            return Err(refuse(
                format!("{field}.tests[{k}].deviates"),
                format!(
                    "says {}, p = {:e} at the recomputed level gives {}",
                    t.deviates, t.p_value, u.deviates
                ),
            ));
        }
        if t.power != u.power {
            return Err(refuse(
                format!("{field}.tests[{k}].power"),
                format!("'{}', recomputed '{}'", t.power, u.power),
            ));
        }
    }
    let differs = |what: &str, a: String, b: String| {
        if a == b {
            Ok(())
        } else {
            Err(refuse(
                format!("{field}.{what}"),
                format!("says {a}, the sub-tests give {b}"),
            ))
        }
    };
    let verdict = |v: Verdict| format!("{v:?}").to_lowercase();
    differs("verdict", verdict(got.verdict), verdict(again.verdict))?;
    let number = |x: Option<f64>| x.map_or_else(|| "none".to_string(), |x| format!("{x:e}"));
    differs("alpha", number(got.alpha), number(again.alpha))?;
    differs("p_value", number(got.p_value), number(again.p_value))?;
    differs("value", number(got.value), number(again.value))?;
    differs("detail", got.detail.clone(), again.detail.clone())
}

#[cfg(test)]
mod tests;
