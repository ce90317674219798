//! `gartowen inspect --base B` for a base b that is not a power of two: the base-b probe
//! inspector (digits of base-b digit words) and, with `--laws`, the battery's law families.

use super::{add_laws_json, exit_code, print_laws, write_junit, InspectArgs, Nested};
use crate::CliError;
use gartowen::core::{Claim, Radix, RadixLayout, Width};
use gartowen::external::ProtocolBase;
use gartowen::oracles::radix_inspector::inspect_radix_probes;
use gartowen::verify::{
    external_candidate, judge_families, law_runner::run_laws, radix_candidate, Level,
    STRUCTURE_CHECKS,
};
use std::process::ExitCode;
use std::sync::Arc;

/// Runs `inspect` in base `radix`: probes always (no exhaustive mode in base b), 32-bit words
/// unless --width says otherwise.
pub fn run(a: &InspectArgs, radix: Radix) -> Result<ExitCode, CliError> {
    if a.depth.is_some() {
        return Err(CliError::Usage(format!(
            "--depth applies to bases 2^q (node permutations reconstructed to a depth); base {} \
             probes every depth",
            radix.get()
        )));
    }
    if a.probes == 0 {
        return Err(CliError::Usage("--probes must be at least 1".into()));
    }
    let width = Width::new(a.width.unwrap_or(32))?;
    let layout = RadixLayout::new(width, radix)?;
    let given_claim = super::super::parse_claim(&a.claim)?;
    let (mut candidate, process) = match (&a.external, &a.scramble) {
        (Some(command), _) => {
            let p = Arc::new(super::super::spawn_external(
                command,
                ProtocolBase::Radix(radix),
                width,
                a.timeout,
            )?);
            let claim = given_claim.unwrap_or(Claim::OWEN).in_base(radix.get())?;
            (external_candidate(p.clone(), a.seed, claim, None), Some(p))
        }
        (None, Some(request)) => (radix_candidate(request, radix, 0)?, None),
        (None, None) => unreachable!("clap requires --scramble or --external"),
    };
    candidate.probe = (candidate.with_seed)(a.seed).map_err(CliError::Usage)?;
    let external_failure = || process.as_ref().and_then(|p| p.failure());
    if process.is_some() {
        // The verdicts below assume a function of (word, dimension, seed).
        let check = STRUCTURE_CHECKS
            .iter()
            .find(|c| c.name == "function")
            .expect("the function check is declared");
        let outcome = (check.run)(&candidate, Level::Quick.plan());
        if let Some(e) = external_failure() {
            return Err(super::external_stop(a, &candidate.name, e));
        }
        if outcome.verdict == gartowen::verify::Verdict::Fail {
            crate::outln!("{}: FAIL function: {}", candidate.name, outcome.detail);
            super::junit_stopped(a, &candidate.name, "function", &outcome.detail)?;
            return Ok(ExitCode::from(1));
        }
    }
    let probe = candidate.probe.as_ref();
    let batch = |words: &mut [u64]| probe.scramble_batch(words, width, a.dim);
    let report = inspect_radix_probes(&batch, layout, a.probes, a.probe_seed);
    if let Some(e) = external_failure() {
        return Err(super::external_stop(a, &candidate.name, e));
    }
    let laws = if a.laws {
        let claim = match given_claim {
            Some(c) => c.in_base(radix.get())?,
            None => candidate.claim,
        };
        candidate.claim = claim;
        let families =
            run_laws(&candidate, Level::Quick, 0).map_err(|e| CliError::Usage(e.to_string()))?;
        if let Some(e) = external_failure() {
            return Err(super::external_stop(a, &candidate.name, e));
        }
        Some((claim, judge_families(families, claim, 1, 0.0)))
    } else {
        None
    };
    let nested = report.first_violation.is_none();
    let words = |v: &gartowen::oracles::inspector::Violation| {
        format!(
            "inputs {}, {} -> outputs {}, {} (base-{} digit words)",
            v.inputs[0],
            v.inputs[1],
            v.outputs[0],
            v.outputs[1],
            radix.get()
        )
    };
    if a.json {
        let mut doc = serde_json::json!({
            "tool": "gartowen", "version": env!("CARGO_PKG_VERSION"), "command": "inspect",
            "scrambler": candidate.name, "seed": a.seed, "dim": a.dim,
            "report": {
                "width": width.bits(), "base": radix.get(), "digits": layout.num_digits(),
                "mode": "Probes", "evaluations": report.evaluations,
                "nodes_checked": report.nodes_checked, "nested_scramble": nested,
                "first_violation": report.first_violation,
            },
        });
        add_laws_json(&mut doc, laws.as_ref());
        crate::outln!("{}", serde_json::to_string_pretty(&doc).expect("json"));
    } else {
        crate::outln!(
            "{}: {} in base {} ({}-bit words of {} base-{} digits, probes, {} evaluations, {} \
             nodes)",
            candidate.name,
            if nested {
                "nested scramble"
            } else {
                "NOT a nested scramble"
            },
            radix.get(),
            width.bits(),
            layout.num_digits(),
            radix.get(),
            report.evaluations,
            report.nodes_checked
        );
        if let Some(v) = &report.first_violation {
            crate::outln!(
                "  first violation: {:?} at depth {}, prefix {}: {}",
                v.kind,
                v.depth,
                v.prefix,
                words(v)
            );
        }
        if let Some((claim, checks)) = &laws {
            print_laws(*claim, checks, width.bits())?;
        }
    }
    if let Some(path) = &a.junit {
        let nested = Nested {
            base: radix.get(),
            violation: report
                .first_violation
                .as_ref()
                .map(|v| (v, v.prefix.to_string(), words(v))),
            evaluations: report.evaluations,
            nodes: report.nodes_checked,
        };
        write_junit(
            path,
            &candidate.name,
            &nested,
            laws.as_ref().map(|(_, c)| c),
        )?;
    }
    Ok(exit_code(nested, laws.as_ref()))
}
