//! `gartowen verify`: the conformance battery over the registry or named implementations.

pub use super::verify_args::{program_record, LevelArg, NetBases, VerifyArgs};
use crate::CliError;
use gartowen::battery::verdict::Outcome;
use gartowen::certificate::{CertVerdict, Certificate, InputRecord};
use gartowen::core::{Claim, PowerOfTwoBase, Width};
use gartowen::external::ProtocolBase;
use gartowen::verify::{
    check_candidate, external_candidate, merge, verify_shard, CheckResult, ImplReport, Level,
    Shard, Verdict,
};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;

/// The seeds of the equivalence check at `level`.
fn equivalence_seeds(a: &VerifyArgs, level: Level) -> u64 {
    a.equivalence_seeds
        .unwrap_or_else(|| gartowen::battery::owen_equivalence::equivalence_seeds(level))
}

/// Refuses a `--json` or `--junit` path that is an input (a `--merge` file, the external
/// program) or the other output.
fn refuse_clobbering_any(a: &VerifyArgs) -> Result<(), CliError> {
    use crate::paths::{named, program_path, refuse_clobbering};
    let program = a.external.as_deref().and_then(program_path);
    let mut inputs: Vec<_> = a.merge.iter().map(|p| named("--merge", p)).collect();
    if let Some(p) = &program {
        inputs.push(named("--external", p));
    }
    let outputs: Vec<_> = [("--json", &a.json), ("--junit", &a.junit)]
        .into_iter()
        .filter_map(|(flag, p)| p.as_deref().map(|p| named(flag, p)))
        .collect();
    refuse_clobbering(&inputs, &outputs)
}

/// `--list-checks`: the declared battery as text on standard output, or as JSON in `json`.
/// The program's `--base` and `--width`, or an error naming the bad one.
fn protocol_base_and_width(a: &VerifyArgs) -> Result<(ProtocolBase, Width), CliError> {
    let base = ProtocolBase::from_base(a.base)
        .map_err(|e| CliError::Usage(format!("--base {}: {e}", a.base)))?;
    let width = match a.width {
        32 => Width::W32,
        64 => Width::W64,
        w => {
            return Err(CliError::Usage(format!(
                "--width {w}: the protocol carries 32- or 64-bit words"
            )))
        }
    };
    Ok((base, width))
}

/// `--list-requests`: the requests of every phase at `level`, for the Owen oracle of --base
/// at --width seen as an external program.
fn list_requests(a: &VerifyArgs, level: Level) -> Result<ExitCode, CliError> {
    use gartowen::battery::request_log::{level_row, log_requests, markdown, LEVEL_HEADER};
    let (base, width) = protocol_base_and_width(a)?;
    let registry = gartowen::registry();
    let name = format!("owen-oracle:base={}", a.base);
    let make = || {
        let mut c = gartowen::verify::registry_candidate(&registry, &name, 0)
            .expect("the oracle serves every protocol base");
        c.max_dims = a.max_dims;
        c.own_base_nets = a.net_bases == NetBases::Own;
        c
    };
    let phases = log_requests(make, level, width, a.seed);
    crate::output::write_atomically(
        a.json.as_deref().or(Some(std::path::Path::new("-"))),
        |out| match &a.json {
            Some(_) => serde_json::to_writer_pretty(&mut *out, &phases)
                .map_err(|e| CliError::Io(e.to_string()))
                .and_then(|()| {
                    out.write_all(b"\n")
                        .map_err(|e| CliError::Io(e.to_string()))
                }),
            None => {
                let text = format!(
                    "requests of `verify --level {}` to a base-{} program of {}-bit \
                     words{} (one thread; with T threads, T seeds are in flight at once):\n{}",
                    level.name(),
                    base.get(),
                    width.bits(),
                    a.max_dims
                        .map_or_else(String::new, |n| format!(" serving {n} dimensions")),
                    markdown(&phases)
                ) + &format!(
                    "\nthe whole level (the README's row):\n{LEVEL_HEADER}{}\n",
                    level_row(level, &phases)
                );
                out.write_all(text.as_bytes())
                    .map_err(|e| CliError::Io(e.to_string()))
            }
        },
    )?;
    Ok(ExitCode::SUCCESS)
}

fn list_checks(json: Option<&std::path::Path>) -> Result<ExitCode, CliError> {
    use gartowen::battery::listing::{listing, listing_text};
    crate::output::write_atomically(json.or(Some(std::path::Path::new("-"))), |out| {
        match json {
            Some(_) => {
                serde_json::to_writer_pretty(&mut *out, &listing())
                    .map_err(|e| CliError::Io(e.to_string()))?;
                out.write_all(b"\n")
            }
            None => out.write_all(listing_text().as_bytes()),
        }
        .map_err(|e| CliError::Io(e.to_string()))
    })?;
    Ok(ExitCode::SUCCESS)
}

fn level_name(level: Level) -> &'static str {
    match level {
        Level::Quick => "quick",
        Level::Full => "full",
        Level::Exhaustive => "exhaustive",
    }
}

/// What every shard of one run must share (and the merged certificate records).
const SHARED_PARAMETERS: [&str; 6] = [
    "level",
    "node_law_seeds",
    "family_alpha",
    "claim_override",
    "implementations_total",
    "equivalence",
];

/// Reads shard certificates and merges them: the shards 1..N of one run, each exactly once,
/// from the same tool version with the same parameters, each checked field by field with
/// every law verdict recomputed from its statistics (`gartowen::audit`) and its digest
/// matching; anything else is refused with the file and the field named.
fn merged(paths: &[PathBuf]) -> Result<(Level, Vec<ImplReport>, Option<String>), CliError> {
    use super::shards::{check_digest, read_certificate, refuse, ShardSet};
    let registry = gartowen::registry();
    let mut set = ShardSet::default();
    let mut first: Option<(Certificate, Option<usize>)> = None;
    let mut parts = Vec::new();
    for p in paths {
        let (cert, text) = read_certificate(p)?;
        if cert.command != "verify" {
            return Err(refuse(
                p,
                format!("a '{}' certificate, not a verify report", cert.command),
            ));
        }
        if cert.inputs.iter().any(|i| i.kind != "registry") {
            return Err(refuse(
                p,
                "verifies an external program; only registry shards merge",
            ));
        }
        let earlier = set.admit(p, &cert)?;
        let run = gartowen::audit::audit_verify(&cert, &registry).map_err(|e| refuse(p, e))?;
        if let (Some(fp), Some((f, judged))) = (earlier, &first) {
            for key in SHARED_PARAMETERS {
                if f.parameters[key] != cert.parameters[key] {
                    return Err(refuse(
                        p,
                        format!(
                            "{key} = {}, but {} = {} in {}",
                            cert.parameters[key],
                            key,
                            f.parameters[key],
                            fp.display()
                        ),
                    ));
                }
            }
            if let (Some(a), Some(b)) = (run.judged, judged) {
                if a != *b {
                    return Err(refuse(
                        p,
                        format!(
                            "result.implementations: per-test levels imply {a} judged implementations, {b} in {}",
                            fp.display()
                        ),
                    ));
                }
            }
        }
        check_digest(p, &text)?;
        let judged = run.judged;
        parts.push(run.reports);
        match &mut first {
            None => first = Some((cert, judged)),
            Some((_, j)) if j.is_none() => *j = judged,
            Some(_) => {}
        }
    }
    set.complete()?;
    let (f, judged) = first.expect("at least one file");
    let fp = &paths[0];
    let level: Level = serde_json::from_value(f.parameters["level"].clone())
        .map_err(|e| refuse(fp, format!("bad level: {e}")))?;
    let total = f.parameters["implementations_total"]
        .as_u64()
        .ok_or_else(|| refuse(fp, "no implementations_total"))? as usize;
    let all = merge(parts, total).map_err(|e| CliError::Usage(e.to_string()))?;
    gartowen::audit::audit_merged(&all, total, judged)
        .map_err(|e| CliError::Usage(format!("the merged shards: {e}")))?;
    let claim = f.parameters["claim_override"].as_str().map(str::to_string);
    Ok((level, all, claim))
}

/// The certificate's records of registry implementations, in report order.
fn registry_inputs(reports: &[ImplReport]) -> Vec<InputRecord> {
    reports
        .iter()
        .map(|r| InputRecord {
            kind: "registry".into(),
            name: r.name.clone(),
            checksum_fnv1a64: None,
            details: serde_json::json!({ "base": r.base }),
        })
        .collect()
}

/// Runs the battery on an external program: the report, and the program's failure if it
/// failed during the run.
fn run_external(
    a: &VerifyArgs,
    command: &str,
    level: Level,
) -> Result<(ImplReport, Option<String>), CliError> {
    let (base, width) = protocol_base_and_width(a)?;
    let registry = gartowen::registry();
    match (&a.expect, base) {
        (Some(name), ProtocolBase::Radix(radix)) => {
            gartowen::owen::registry::build_radix(name, radix, 0)
                .map_err(|e| CliError::Usage(format!("--expect {name}: {e}")))?;
        }
        (Some(name), ProtocolBase::PowerOfTwo(base)) => expect_in_base(&registry, name, base)?,
        (None, _) => {}
    }
    let process = super::spawn_external(command, base, width, a.timeout)?;
    let claim = if a.no_uniform_claim {
        Claim::NESTED
    } else {
        super::parse_claim(&a.claim)?.unwrap_or(Claim::OWEN)
    };
    let claim = claim
        .in_base(base.get())
        .map_err(|e| CliError::Usage(format!("--claim: {e}")))?;
    let process = Arc::new(process);
    let mut candidate = external_candidate(
        process.clone(),
        a.seed,
        claim,
        a.expect.as_deref().map(|n| (&registry, n)),
    );
    candidate.max_dims = a.max_dims;
    candidate.own_base_nets = a.net_bases == NetBases::Own;
    if let Some(k) = a.bits {
        candidate =
            gartowen::battery::top_bits::top_bits(candidate, width, k).map_err(CliError::Usage)?;
    }
    let mut report = check_candidate(&candidate, level, 1);
    if a.equivalent_to.is_some() {
        // The estimators read dimensions 0 and 1, in a base 2^q.
        let why = match base {
            ProtocolBase::Radix(r) => Some(equivalence_not_applicable(r.get())),
            ProtocolBase::PowerOfTwo(_) => {
                gartowen::battery::family::needs_dimension(a.max_dims, 1)
            }
        };
        if let Some(why) = why {
            let not_run = Outcome::not_run(why);
            let check = CheckResult::from_outcome("equivalent-to-owen", not_run, 0.0);
            report.checks.push(check);
            return Ok((report, process.failure().map(|e| e.to_string())));
        }
        let mut check = gartowen::battery::owen_equivalence::check_equivalent_to_owen(
            candidate.with_seed.as_ref(),
            base.power_of_two().expect("a base 2^q"),
            width,
            equivalence_seeds(a, level),
            a.margin,
        );
        if let Some(e) = process.failure() {
            check.verdict = Verdict::Fail;
            check.detail = format!("external program failed: {e}");
            check.value = None;
        }
        report.checks.push(check);
    }
    Ok((report, process.failure().map(|e| e.to_string())))
}

/// Why `equivalent-to-owen` does not run in base `b` (not a power of two).
fn equivalence_not_applicable(b: u32) -> String {
    format!("not applicable in base {b}: the equivalence estimators are defined in bases 2^q")
}

/// Checks that `--expect NAME` is a registry entry scrambling in the program's base 2^q.
fn expect_in_base(
    registry: &gartowen::core::Registry,
    name: &str,
    base: PowerOfTwoBase,
) -> Result<(), CliError> {
    let twin = registry
        .build_with(
            name,
            &gartowen::core::BuildContext {
                seed: 0,
                default_base: base,
            },
        )
        .map_err(|e| CliError::Usage(format!("--expect {name}: {e}")))?;
    if twin.base() != base {
        return Err(CliError::Usage(format!(
            "--expect {name} scrambles in base {}, the program in base {}",
            twin.base().base(),
            base.base()
        )));
    }
    Ok(())
}

/// Whether `path` is a certificate of the every-word sweep (its merge is the sweep's).
/// (Read within the certificate size bound: `/dev/zero` is refused, not read without end.)
fn is_sweep_certificate(path: &std::path::Path) -> Result<bool, CliError> {
    let (cert, _) = super::shards::read_certificate(path)?;
    Ok(!cert.parameters["sweep"].is_null())
}

/// Runs `verify`.
pub fn run(a: VerifyArgs) -> Result<ExitCode, CliError> {
    refuse_clobbering_any(&a)?;
    if a.list_checks {
        return list_checks(a.json.as_deref());
    }
    if let Some(first) = a.merge.first() {
        if is_sweep_certificate(first)? {
            return super::sweep::merge(&a.merge, a.json.as_ref(), a.junit.as_ref());
        }
    }
    if let Some(dims) = &a.dims {
        if a.estimate {
            return super::estimate::run(&a, dims);
        }
        return super::sweep::run(&a, dims);
    }
    if a.external.is_some() && a.shard.is_some() {
        return Err(CliError::Usage(
            "--shard with --external splits the every-word sweep (add --level exhaustive --dims A..B)"
                .into(),
        ));
    }
    let level = match a.level {
        LevelArg::Quick => Level::Quick,
        LevelArg::Full => Level::Full,
        LevelArg::Exhaustive => Level::Exhaustive,
    };
    if a.list_requests {
        return list_requests(&a, level);
    }
    let mut external_failure = None;
    let mut claim_override = a.claim.clone();
    let mut shard_record = Shard::ALL;
    let mut total = 1;
    let (level, reports, inputs) = if !a.merge.is_empty() {
        let (level, reports, claim) = merged(&a.merge)?;
        claim_override = claim;
        total = reports.len();
        let inputs = registry_inputs(&reports);
        (level, reports, inputs)
    } else if let Some(command) = &a.external {
        let (report, failure) = run_external(&a, command, level)?;
        external_failure = failure;
        (level, vec![report], vec![program_record(command)])
    } else {
        let shard = match &a.shard {
            None => Shard::ALL,
            Some(t) => Shard::parse(t).ok_or_else(|| {
                CliError::Usage(format!("--shard '{t}' is not I/N with 1 ≤ I ≤ N"))
            })?,
        };
        let registry = gartowen::registry();
        total = if a.implementations.is_empty() {
            registry.specs().len()
        } else {
            a.implementations.len()
        };
        shard_record = shard;
        if shard.index > total {
            // A fixed CI matrix may have more shards than implementations: say so, and
            // record the empty shard so that the merge still sees every one.
            eprintln!(
                "note: shard {}/{} holds none of the {total} implementations (shard I/N holds \
                 the I-th, (I+N)-th, … of the list); its certificate records an empty shard, \
                 which the merge accepts",
                shard.index, shard.count
            );
        }
        let bar = crate::progress::Bar::new("verify {msg} [{bar:30}] {pos}/{len}");
        let claim = super::parse_claim(&a.claim)?;
        let reports = verify_shard(&registry, &a.implementations, level, shard, claim, &bar)?;
        let mut reports = reports;
        if a.equivalent_to.is_some() {
            for r in &mut reports {
                let Ok(base) = PowerOfTwoBase::from_base(u64::from(r.base)) else {
                    let not_run = Outcome::not_run(equivalence_not_applicable(r.base));
                    let check = CheckResult::from_outcome("equivalent-to-owen", not_run, 0.0);
                    r.checks.push(check);
                    continue;
                };
                let builder = gartowen::verify::registry_seeds(&registry, &r.name, base);
                r.checks.push(
                    gartowen::battery::owen_equivalence::check_equivalent_to_owen(
                        builder.as_ref(),
                        base,
                        Width::W32,
                        equivalence_seeds(&a, level),
                        a.margin,
                    ),
                );
            }
        }
        let inputs = registry_inputs(&reports);
        (level, reports, inputs)
    };
    print_table(&reports)?;
    if a.profile {
        crate::outln!("{}", gartowen::battery::time_profile::render(&reports, 10));
    }
    let failed = reports.iter().filter(|r| r.failed()).count();
    if let Some(path) = &a.junit {
        let certificate = a.json.as_ref().map(|p| p.display().to_string());
        let suites = gartowen::battery::junit::verify_suites(&reports, certificate.as_deref());
        crate::output::write_junit(path, "gartowen verify", &suites)?;
    }
    crate::outln!(
        "{} implementations, {failed} with failures ({} level)",
        reports.len(),
        level_name(level)
    );
    if let Some(path) = &a.json {
        let mut parameters = serde_json::json!({
            "level": level,
            "node_law_seeds": level.plan().law_seeds,
            "family_alpha": gartowen::verify::stats::FAMILY_ALPHA,
            "claim_override": claim_override,
            // What a merge needs to refuse an incomplete or mixed set of shards.
            "shard": { "index": shard_record.index, "count": shard_record.count },
            "implementations_total": total,
        });
        if a.equivalent_to.is_some() {
            parameters["equivalence"] = serde_json::json!({
                "to": "owen", "margin": a.margin, "alpha": gartowen::battery::equivalence::DEFAULT_ALPHA,
                "seeds": equivalence_seeds(&a, level),
            });
        }
        if let Some(command) = &a.external {
            parameters["external"] = serde_json::json!({
                "command": command, "base": a.base, "width": a.width, "seed": a.seed,
                "expect": a.expect, "timeout_seconds": a.timeout, "max_dims": a.max_dims,
                "bits": a.bits, "net_bases": format!("{:?}", a.net_bases).to_lowercase(),
                "claim": reports[0].claim,
            });
        }
        let cert = Certificate::new(
            "verify",
            if failed == 0 {
                CertVerdict::Pass
            } else {
                CertVerdict::Fail
            },
            parameters,
            gartowen::verify::seeds_used(if a.external.is_some() { a.seed } else { 0 }),
            inputs,
            serde_json::json!({ "implementations": reports }),
        );
        crate::output::write_atomically(Some(path), |out| {
            out.write_all(cert.to_json().as_bytes())
                .map_err(|e| CliError::Io(e.to_string()))
        })?;
    }
    if let Some(e) = external_failure {
        // The report and certificate are written (every check names the failure); the exit
        // code tells a broken program from a failed check.
        return Err(CliError::External(e));
    }
    Ok(ExitCode::from(if failed == 0 {
        crate::error::EXIT_PASS
    } else {
        crate::error::EXIT_FAIL
    }))
}

/// The widest the implementation column grows (characters).
const NAME_COLUMN: usize = 40;

/// The verdict table: one row per implementation, one column per check, then the failures
/// and the per-depth profile of the law checks.
fn print_table(reports: &[ImplReport]) -> Result<(), CliError> {
    let Some(first) = reports.first() else {
        return Ok(());
    };
    let names: Vec<&str> = first.checks.iter().map(|c| c.check.as_str()).collect();
    // Columns as wide as their longest entry, the name column at most NAME_COLUMN: a longer
    // name (an external command line) gets a line of its own above its row.
    let width = |text: &str| text.chars().count();
    let name_column = reports
        .iter()
        .map(|r| width(&r.name))
        .filter(|&w| w <= NAME_COLUMN)
        .fold(26, usize::max);
    let claim_column = reports.iter().map(|r| width(&r.claim)).fold(22, usize::max);
    let mut header = format!(
        "{:<name_column$} {:<claim_column$}",
        "implementation", "claim"
    );
    for n in &names {
        header.push_str(&format!(" {n:<11}"));
    }
    crate::outln!("{}", header.trim_end());
    for r in reports {
        let name = if width(&r.name) > name_column {
            crate::outln!("{}", r.name);
            ""
        } else {
            r.name.as_str()
        };
        let mut row = format!("{name:<name_column$} {:<claim_column$}", r.claim);
        for c in &r.checks {
            row.push_str(&format!(" {:<11}", c.verdict.label()));
        }
        crate::outln!("{}", row.trim_end());
        for c in r.checks.iter().filter(|c| c.verdict == Verdict::Fail) {
            crate::outln!("    FAIL {}: {}", c.check, c.detail);
        }
        // What could not run (dimensions beyond --max-dims), also inside a passing check.
        for c in r.checks.iter().filter(|c| c.verdict != Verdict::Fail) {
            if let Some(at) = c.detail.find("not run: ") {
                crate::outln!("    {}: {}", c.check, &c.detail[at..]);
            }
        }
        // An equivalence verdict is worth reading when it passes too: it states the intervals.
        for c in r
            .checks
            .iter()
            .filter(|c| c.check == "equivalent-to-owen" && c.verdict != Verdict::Fail)
        {
            crate::outln!("    {}: {}", c.check, c.detail);
        }
        if !r.profile.is_empty() {
            let cells: Vec<String> = r
                .profile
                .iter()
                .map(|(family, row)| format!("{family} {row}"))
                .collect();
            crate::outln!("    profile (depth 0→): {}", cells.join("  "));
        }
    }
    crate::outln!(
        "law checks: family-wise α = {} (Bonferroni); pass = no deviation detected at the stated power; \
         profile: . none detected, x deviation, ? not measured, - not tested; \
         nodes are named by their digit path from the root (0.1 = child 1 of child 0, in hex digits)",
        gartowen::verify::stats::FAMILY_ALPHA
    );
    Ok(())
}
