//! `gartowen verify`: the conformance battery over the registry or named implementations.

use crate::CliError;
use clap::{Args, ValueEnum};
use gartowen::certificate::{fnv1a64, CertVerdict, Certificate, InputRecord};
use gartowen::core::{Claim, PowerOfTwoBase, Width};
use gartowen::verify::{
    check_candidate, external_candidate, merge, verify_shard, ImplReport, Level, Shard, Verdict,
};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;

/// Battery size.
#[derive(Clone, Copy, Debug, ValueEnum, PartialEq, Eq)]
pub enum LevelArg {
    /// Under a minute for the whole registry on 2 cores.
    Quick,
    /// Larger samples and deeper nets.
    Full,
    /// Long (minutes); split it with --shard and combine with --merge.
    Exhaustive,
}

/// Run the conformance battery. Structure is checked exactly: inverse (injectivity for external
/// programs), nestedness (inspector), net preservation in the scrambling base. Randomness is
/// checked by laws over independent seeds:
///   node-law    each node permutation uniform over the claimed group, depths 0..12 (marginal)
///   pair-law    pairs of nodes (siblings, parent-child, cousins, distant) independent (joint)
///   flip-rank   no exact GF(2) relation among node flips of depths ≤ D, dims 0-1 (joint)
///   collisions  no two subtrees alike within one seed (joint; finite tables show here)
///   pair-lemma  Owen's pair lemma for inputs first differing at digit r (marginal + joint)
///   dimensions  dimensions 0..64 distinct (marginal) and root pairs independent (joint)
///
/// Each implementation is judged only on what it claims (`gartowen list` shows the claims;
/// --claim overrides them): `nested`, `marginal:GROUP` (node permutations uniform over
/// symmetric|affine|translation|cyclic), `independent:GROUP`, or `owen` (= independent:symmetric).
/// Unclaimed checks are `measured`. The family-wise false-alarm rate of a run is 1e-3
/// (Bonferroni over implementations and sub-tests); a pass reads "no deviation detected at this
/// power", and each sub-test's power (smallest Cohen's w at power 0.9, or what an exact test
/// detects) is in the JSON. The profile line shows, per family and depth 0, 1, 2, …, where an
/// implementation departs from Owen: `.` nothing detected, `x` deviation, `-` not tested.
///
/// Prints a table (implementation × check). Exit codes: 0 every check passed, 1 a check
/// failed, 2 bad usage or input, 3 the external program failed (crash, exit, hang, garbage).
///
/// Examples:
///   gartowen verify --level quick
///   gartowen verify --impl art-owen-16p --impl lk-hash --json verify.json
///   gartowen verify --impl digital-shift --impl lk-hash --claim owen     (imitations fail)
///   gartowen verify --level exhaustive --shard 2/4 --json shard2.json     (one CI job of four)
///   gartowen verify --merge shard1.json shard2.json shard3.json shard4.json --json all.json
///
/// Every word (--level exhaustive --dims A..B): all 2^32 inputs of each dimension, in order,
/// through the batch path, proving bijective and nested at every depth (3-40 s per dimension
/// for built-ins on 2 cores, about 1 min for the C example over pipes; under 50 MB of memory).
/// Scramblers without 32-bit support are swept at 24 bits; 64-bit words are refused (2^64 words
/// cannot be enumerated; the sampled checks apply). --shard I/N cuts the (implementation,
/// dimension, chunk) units into N contiguous runs, so N dividing the dimensions shards by
/// dimension and other N split inside dimensions; --merge joins the shards and refuses a
/// missing, doubled or foreign one:
///   gartowen verify --level exhaustive --dims 0..3 --impl art-owen-2 --impl lk-hash
///   gartowen verify --level exhaustive --dims 0..1023 --impl art-owen-2 --shard 7/32 --json s7.json
///   gartowen verify --level exhaustive --dims 0..3 --external ./lk_hash --base 2 --claim nested
///
/// External implementations (the protocol is in docs/external.md):
///   gartowen verify --external './my_scrambler --fast' --base 16 --width 32
///   gartowen verify --external ./owen_per_bit --base 2 --width 64 --expect owen-per-bit-hash
///
/// Equivalence to Owen (the estimator variance against the exact Owen variance of the base,
/// TOST with a stated margin; the seeds used are printed and in the JSON):
///   gartowen verify --impl art-owen-16p --equivalent-to owen --margin 0.1
///   gartowen verify --external ./owen_nested --base 16 --equivalent-to owen --equivalence-seeds 4000
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct VerifyArgs {
    /// Battery size.
    #[arg(long, value_enum, default_value_t = LevelArg::Quick)]
    pub level: LevelArg,
    /// Implementations to verify (registry names, with options); default: all.
    #[arg(long = "impl")]
    pub implementations: Vec<String>,
    /// Also write the report as JSON to this file.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Run only shard I of N (1 ≤ I ≤ N): implementation k goes to shard (k mod N) + 1.
    #[arg(long)]
    pub shard: Option<String>,
    /// Combine shard JSON files (from --json) into one report instead of running checks.
    #[arg(long, num_args = 1.., conflicts_with_all = ["shard", "implementations"])]
    pub merge: Vec<PathBuf>,
    /// Verify an external program speaking the gartowen protocol instead of the registry
    /// (the command line is split on spaces; quotes group; no shell is involved).
    #[arg(long, conflicts_with_all = ["implementations", "merge"])]
    pub external: Option<String>,
    /// Every-word sweep of dimensions A..B (both included; or one dimension A) with
    /// --level exhaustive: every 2^32 input word of each dimension (2^24 for scramblers without
    /// 32-bit support) is scrambled and checked for bijectivity and nestedness at every depth,
    /// in one streaming pass. 64-bit words cannot be enumerated (2^64 words) and are refused;
    /// the sampled levels (without --dims) check them.
    #[arg(long, conflicts_with_all = ["merge", "expect", "junit"])]
    pub dims: Option<String>,
    /// Scrambling base of the external program (a power of two, 2..=256).
    #[arg(long, default_value_t = 2, requires = "external")]
    pub base: u64,
    /// Word width the external program receives: 32 or 64.
    #[arg(long, default_value_t = 32, requires = "external")]
    pub width: u32,
    /// Seed of the external program's main instance (the node law uses seeds 0, 1, 2, …).
    #[arg(long, default_value_t = 0, requires = "external")]
    pub seed: u64,
    /// Require bit-exact agreement with this built-in implementation (registry name).
    #[arg(long, requires = "external")]
    pub expect: Option<String>,
    /// Seconds to wait for each reply before the program is killed.
    #[arg(long, default_value_t = 10.0, requires = "external")]
    pub timeout: f64,
    /// The external program does not claim any law (same as --claim nested).
    #[arg(long, requires = "external", conflicts_with = "claim")]
    pub no_uniform_claim: bool,
    /// Also write JUnit XML (one testsuite per implementation, one testcase per check).
    #[arg(long)]
    pub junit: Option<PathBuf>,
    /// Judge on this claim instead of each implementation's own: nested | owen |
    /// `marginal[:GROUP]` | `independent:GROUP` (GROUP: symmetric, affine, translation, cyclic).
    /// External programs default to owen.
    #[arg(long)]
    pub claim: Option<String>,
    /// Also test equivalence to the full-tree Owen scramble of the implementation's base: the
    /// variance of a box-volume estimator (64 fixed points, boxes of 1, 2 and 3 digits) over
    /// seeds 0..S, divided by its exact Owen value, must have its 90% interval inside
    /// [1 − margin, 1 + margin] at every level (TOST, α = 0.05). Check `equivalent-to-owen`:
    /// pass = equivalent; fail = different, or inconclusive with the seeds that would decide.
    #[arg(long, value_parser = ["owen"], conflicts_with_all = ["merge", "dims"])]
    pub equivalent_to: Option<String>,
    /// Equivalence margin on the variance ratio (0 < margin < 1).
    #[arg(long, default_value_t = gartowen::battery::equivalence::DEFAULT_MARGIN,
          value_parser = super::parse_margin, requires = "equivalent_to")]
    pub margin: f64,
    /// Seeds of the equivalence check (default: 1000 quick, 10000 full, 50000 exhaustive;
    /// at most 1000000).
    #[arg(long, value_parser = clap::value_parser!(u64).range(2..=1_000_000),
          requires = "equivalent_to")]
    pub equivalence_seeds: Option<u64>,
}

/// The seeds of the equivalence check at `level`.
fn equivalence_seeds(a: &VerifyArgs, level: Level) -> u64 {
    a.equivalence_seeds
        .unwrap_or_else(|| gartowen::battery::owen_equivalence::equivalence_seeds(level))
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
/// from the same tool version with the same parameters; anything else is refused with the
/// file named.
fn merged(paths: &[PathBuf]) -> Result<(Level, Vec<ImplReport>, Option<String>), CliError> {
    use super::shards::{read_certificate, refuse, ShardSet};
    let mut set = ShardSet::default();
    let mut first: Option<Certificate> = None;
    let mut parts = Vec::new();
    for p in paths {
        let cert = read_certificate(p)?;
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
        if let Some(fp) = set.admit(p, &cert)? {
            let f = first.as_ref().expect("admitted before");
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
        }
        let reports: Vec<ImplReport> =
            serde_json::from_value(cert.result["implementations"].clone())
                .map_err(|e| refuse(p, format!("bad report: {e}")))?;
        parts.push(reports);
        if first.is_none() {
            first = Some(cert);
        }
    }
    set.complete()?;
    let f = first.expect("at least one file");
    let fp = &paths[0];
    let level: Level = serde_json::from_value(f.parameters["level"].clone())
        .map_err(|e| refuse(fp, format!("bad level: {e}")))?;
    let total = f.parameters["implementations_total"]
        .as_u64()
        .ok_or_else(|| refuse(fp, "no implementations_total"))? as usize;
    let all = merge(parts, total).map_err(CliError::Usage)?;
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
    let base = PowerOfTwoBase::from_base(a.base)
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
    let registry = gartowen::registry();
    if let Some(name) = &a.expect {
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
    }
    let process = super::spawn_external(command, base, width, a.timeout)?;
    let claim = if a.no_uniform_claim {
        Claim::NESTED
    } else {
        super::parse_claim(&a.claim)?.unwrap_or(Claim::OWEN)
    };
    let process = Arc::new(process);
    let candidate = external_candidate(
        process.clone(),
        a.seed,
        claim,
        a.expect.as_deref().map(|n| (&registry, n)),
    );
    let mut report = check_candidate(&candidate, level, 1);
    if a.equivalent_to.is_some() {
        let mut check = gartowen::battery::owen_equivalence::check_equivalent_to_owen(
            candidate.with_seed.as_ref(),
            base,
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

/// The certificate's record of an external program: its command line and, where the program
/// file can be read, the checksum of its bytes.
pub(crate) fn program_record(command: &str) -> InputRecord {
    let program = gartowen::external::split_command(command)
        .ok()
        .and_then(|w| w.into_iter().next());
    let checksum = program
        .as_ref()
        .and_then(|p| std::fs::read(p).ok())
        .map(|bytes| format!("{:016x}", fnv1a64(&bytes)));
    InputRecord {
        kind: "program".into(),
        name: command.into(),
        checksum_fnv1a64: checksum,
        details: serde_json::json!({ "program": program }),
    }
}

/// Whether `path` is a certificate of the every-word sweep (its merge is the sweep's).
fn is_sweep_certificate(path: &PathBuf) -> bool {
    std::fs::read_to_string(path)
        .ok()
        .and_then(|t| Certificate::parse(&t).ok())
        .is_some_and(|c| !c.parameters["sweep"].is_null())
}

/// Runs `verify`.
pub fn run(a: VerifyArgs) -> Result<ExitCode, CliError> {
    if a.merge.first().is_some_and(is_sweep_certificate) {
        return super::sweep::merge(&a.merge, a.json.as_ref());
    }
    if let Some(dims) = &a.dims {
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
        let bar = indicatif::ProgressBar::new(total.div_ceil(shard.count) as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("verify {msg} [{bar:30}] {pos}/{len}")
                .expect("template"),
        );
        let claim = super::parse_claim(&a.claim)?;
        let reports = verify_shard(
            &registry,
            &a.implementations,
            level,
            shard,
            claim,
            &|name| {
                bar.set_message(name.to_string());
                bar.inc(1);
            },
        )?;
        bar.finish_and_clear();
        let mut reports = reports;
        if a.equivalent_to.is_some() {
            for r in &mut reports {
                let base = PowerOfTwoBase::from_base(u64::from(r.base))
                    .map_err(|e| CliError::Usage(e.to_string()))?;
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
            "node_law_seeds": gartowen::verify::node_law_seeds(level),
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
                "expect": a.expect, "timeout_seconds": a.timeout,
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

/// The verdict table: one row per implementation, one column per check, then the failures
/// and the per-depth profile of the law checks.
fn print_table(reports: &[ImplReport]) -> Result<(), CliError> {
    let Some(first) = reports.first() else {
        return Ok(());
    };
    let names: Vec<&str> = first.checks.iter().map(|c| c.check.as_str()).collect();
    let mut header = format!("{:<26} {:<22}", "implementation", "claim");
    for n in &names {
        header.push_str(&format!(" {n:<11}"));
    }
    crate::outln!("{}", header.trim_end());
    for r in reports {
        let mut row = format!("{:<26} {:<22}", r.name, r.claim);
        for c in &r.checks {
            let v = match c.verdict {
                Verdict::Pass => "pass",
                Verdict::Fail => "FAIL",
                Verdict::Measured => "measured",
                Verdict::Skipped => "skipped",
            };
            row.push_str(&format!(" {v:<11}"));
        }
        crate::outln!("{}", row.trim_end());
        for c in r.checks.iter().filter(|c| c.verdict == Verdict::Fail) {
            crate::outln!("    FAIL {}: {}", c.check, c.detail);
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
         profile: . none detected, x deviation, - not tested",
        gartowen::verify::stats::FAMILY_ALPHA
    );
    Ok(())
}
