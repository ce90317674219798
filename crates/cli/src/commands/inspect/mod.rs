//! `gartowen inspect`: is a registered scrambler (or an external program) a nested scramble in
//! base B, and what are its node laws by depth?

use crate::CliError;
use clap::Args;
use gartowen::core::{BuildContext, Claim, PowerOfTwoBase, Scrambler, Width};
use gartowen::external::{ExternalProcess, ExternalScrambler};
use gartowen::oracles::inspector::{inspect_exhaustive, inspect_probes, InspectReport, Violation};
use gartowen::verify::{
    judge_families, law_runner::run_laws, Candidate, CheckResult, Level, SeedBuilder,
};
use std::process::ExitCode;
use std::sync::Arc;

mod radix;

/// Decide from black-box evaluations whether a scrambler is a nested scramble in base B.
///
/// Nested: output digit k depends only on input digits 0..k, and every node's map on digit k is
/// a bijection. Widths ≤ 16 are checked exhaustively; 32 and 64 bits by seeded node probes
/// (each probe evaluates all B digits of one node with two random tails). The report gives the
/// first violation (node, two inputs, two outputs) and the law of reconstructed node
/// permutations against uniform S_B. Exit 0 when nested, 1 when not, 2 on bad usage.
///
/// Examples:
///   gartowen inspect --scramble owen-oracle --base 4 --width 16
///   gartowen inspect --scramble owen-oracle:base=16 --base 2 --width 16      (exit 1)
///   gartowen inspect --scramble owen-oracle:xor --base 16 --width 64 --probes 5000 --json
///   gartowen inspect --external ./my_scrambler --base 2 --width 32 --laws   (node and joint laws)
///   gartowen inspect --scramble owen-oracle:per-depth --base 3 --laws --claim owen   (exit 1)
///
/// With --laws, the marginal and joint law tests of `verify --level quick` run over seeds
/// 0, 1, 2, … and print their per-depth profile (`.` no deviation detected, `x` deviation,
/// `-` not tested) with the worst sub-test of each family; --claim sets what is judged.
#[derive(Args, Debug)]
#[command(verbatim_doc_comment)]
pub struct InspectArgs {
    /// Scrambler from the registry, NAME[:OPTION...].
    #[arg(
        long,
        required_unless_present = "external",
        conflicts_with = "external"
    )]
    pub scramble: Option<String>,
    /// An external program speaking the gartowen protocol (see `verify --external`).
    #[arg(long)]
    pub external: Option<String>,
    /// Seconds to wait for each reply of the external program.
    #[arg(long, default_value_t = 10.0, requires = "external")]
    pub timeout: f64,
    /// Also run the node and joint law tests and print their per-depth profile.
    #[arg(long)]
    pub laws: bool,
    /// Claim to judge the laws on (default: the scrambler's own; owen for external programs).
    #[arg(long, requires = "laws")]
    pub claim: Option<String>,
    /// Base B in which to test nestedness (also the default base of the scrambler): 2^q, or
    /// any other base 3..65535, whose words are base-B digit integers (probes only; the
    /// built-in scrambler there is owen-oracle[:cyclic|:per-depth]).
    #[arg(long)]
    pub base: u64,
    /// Word width in bits (≤ 16 exhaustive; 32 or 64 by probes). Default: 16, or 32 with
    /// --external (the protocol carries 32- or 64-bit words).
    #[arg(long)]
    pub width: Option<u32>,
    /// Depth K (digits) to which node permutations are reconstructed (default: all).
    #[arg(long)]
    pub depth: Option<u32>,
    /// Number of node probes for widths above 16.
    #[arg(long, default_value_t = 2000)]
    pub probes: u64,
    /// Seed of the scrambler.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Seed of the probe generator.
    #[arg(long, default_value_t = 1)]
    pub probe_seed: u64,
    /// Dimension to inspect.
    #[arg(long, default_value_t = 0)]
    pub dim: u32,
    /// Print the report as JSON.
    #[arg(long)]
    pub json: bool,
    /// Also write JUnit XML: a testcase for nestedness and one per law check.
    #[arg(long)]
    pub junit: Option<std::path::PathBuf>,
}

fn text(r: &InspectReport, name: &str) -> String {
    let mut out = format!(
        "{name}: {} in base {} ({}-bit words, {:?}, {} evaluations, {} nodes)\n",
        if r.nested_scramble {
            "nested scramble"
        } else {
            "NOT a nested scramble"
        },
        r.base,
        r.width,
        r.mode,
        r.evaluations,
        r.nodes_checked
    );
    if let Some(v) = &r.first_violation {
        out += &format!(
            "  first violation: {:?} at depth {}, prefix {:#x}: inputs {:#x}, {:#x} -> outputs {:#x}, {:#x}\n",
            v.kind, v.depth, v.prefix, v.inputs[0], v.inputs[1], v.outputs[0], v.outputs[1]
        );
    } else {
        out += &format!(
            "  node permutations ({} cells = {}): chi-square {:.1} on {} dof, total variation {:.4}\n",
            r.node_law.counts.len(),
            r.node_law.cells_are,
            r.node_law.chi_square,
            r.node_law.dof,
            r.node_law.total_variation
        );
    }
    out
}

/// The scrambler for `seed`: a registry entry or one seed's view of the external program.
fn builder<'a>(
    a: &'a InspectArgs,
    base: PowerOfTwoBase,
    width: Width,
) -> Result<(Box<SeedBuilder<'a>>, Option<Arc<ExternalProcess>>), CliError> {
    if let Some(command) = &a.external {
        let p = Arc::new(super::spawn_external(command, base, width, a.timeout)?);
        let claim = super::parse_claim(&a.claim)?.unwrap_or(Claim::OWEN);
        let shared = p.clone();
        Ok((
            Box::new(move |seed| {
                Ok(
                    Box::new(ExternalScrambler::new(shared.clone(), seed, claim))
                        as Box<dyn Scrambler>,
                )
            }),
            Some(p),
        ))
    } else {
        let request = a.scramble.clone().expect("clap requires one");
        let registry = gartowen::registry();
        registry.build_with(
            &request,
            &BuildContext {
                seed: 0,
                default_base: base,
            },
        )?;
        Ok((
            Box::new(move |seed| {
                registry
                    .build_with(
                        &request,
                        &BuildContext {
                            seed,
                            default_base: base,
                        },
                    )
                    .map_err(|e| e.to_string())
            }),
            None,
        ))
    }
}

/// Runs `inspect`.
pub fn run(a: InspectArgs) -> Result<ExitCode, CliError> {
    if let (Some(junit), Some(program)) = (
        &a.junit,
        a.external.as_deref().and_then(crate::paths::program_path),
    ) {
        use crate::paths::{named, refuse_clobbering};
        refuse_clobbering(&[named("--external", &program)], &[named("--junit", junit)])?;
    }
    let base = match gartowen::external::ProtocolBase::from_base(a.base)
        .map_err(|e| CliError::Usage(format!("--base {}: {e}", a.base)))?
    {
        gartowen::external::ProtocolBase::Radix(radix) => return radix::run(&a, radix),
        gartowen::external::ProtocolBase::PowerOfTwo(base) => base,
    };
    let bits = a
        .width
        .unwrap_or(if a.external.is_some() { 32 } else { 16 });
    let width = Width::new(bits)?;
    let (with_seed, process) = builder(&a, base, width)?;
    let s = with_seed(a.seed).map_err(CliError::Usage)?;
    if !s.supports_width(width) {
        return Err(CliError::Usage(format!(
            "{} does not support {}-bit words",
            s.name(),
            bits
        )));
    }
    if process.is_some() {
        // Every verdict below assumes a function of (word, dimension, seed): an external
        // program is asked first (a position-dependent answer would look nested word by word).
        let check = gartowen::verify::STRUCTURE_CHECKS
            .iter()
            .find(|c| c.name == "function")
            .expect("the function check is declared");
        // A closure borrowing the builder for this block only (the laws below take it).
        #[allow(clippy::redundant_closure)]
        let mut c = Candidate::from_builder(s.name(), s.claim(), Box::new(|seed| with_seed(seed)))
            .map_err(CliError::Usage)?;
        c.probe = with_seed(a.seed).map_err(CliError::Usage)?;
        let outcome = (check.run)(&c, Level::Quick.plan());
        if let Some(e) = process.as_ref().and_then(|p| p.failure()) {
            return Err(external_stop(&a, &s.name(), e));
        }
        if outcome.verdict == gartowen::verify::Verdict::Fail {
            if a.json {
                crate::outln!(
                    "{}",
                    serde_json::to_string_pretty(&serde_json::json!({
                        "tool": "gartowen", "version": env!("CARGO_PKG_VERSION"),
                        "command": "inspect", "scrambler": s.name(),
                        "function": { "verdict": "fail", "detail": outcome.detail },
                    }))
                    .expect("json")
                );
            } else {
                crate::outln!("{}: FAIL function: {}", s.name(), outcome.detail);
            }
            junit_stopped(&a, &s.name(), "function", &outcome.detail)?;
            return Ok(ExitCode::from(1));
        }
    }
    let depth = a.depth.unwrap_or(u32::MAX);
    let f = |x: u64| s.scramble(x, width, a.dim);
    let report = if bits <= 16 {
        inspect_exhaustive(&f, width, base, depth)
    } else {
        if a.probes == 0 {
            return Err(CliError::Usage("--probes must be at least 1".into()));
        }
        inspect_probes(&f, width, base, depth, a.probes, a.probe_seed)
    };
    let external_failure = || process.as_ref().and_then(|p| p.failure());
    if let Some(e) = external_failure() {
        return Err(external_stop(&a, &s.name(), e));
    }
    let laws = if a.laws {
        // External programs report the claim given (default owen); registry entries their own.
        let claim = super::parse_claim(&a.claim)?.unwrap_or_else(|| s.claim());
        let probe = with_seed(a.seed).map_err(CliError::Usage)?;
        let mut c = Candidate::from_builder(s.name(), claim, with_seed).map_err(CliError::Usage)?;
        c.probe = probe;
        let families = run_laws(&c, Level::Quick, 0).map_err(|e| CliError::Usage(e.to_string()))?;
        if let Some(e) = external_failure() {
            return Err(external_stop(&a, &s.name(), e));
        }
        Some((claim, judge_families(families, claim, 1, 0.0)))
    } else {
        None
    };
    if a.json {
        let mut doc = serde_json::json!({
            "tool": "gartowen", "version": env!("CARGO_PKG_VERSION"), "command": "inspect",
            "scrambler": s.name(), "seed": a.seed, "dim": a.dim, "report": report,
        });
        add_laws_json(&mut doc, laws.as_ref());
        crate::outln!("{}", serde_json::to_string_pretty(&doc).expect("json"));
    } else {
        crate::out!("{}", text(&report, &s.name()));
        if let Some((claim, checks)) = &laws {
            let bits = if s.supports_width(Width::W32) { 32 } else { 64 };
            print_laws(*claim, checks, bits)?;
        }
    }
    if let Some(path) = &a.junit {
        let nested = Nested {
            base: base.base(),
            violation: report
                .first_violation
                .as_ref()
                .map(|v| (v, format!("{:#x}", v.prefix), hex_words(v))),
            evaluations: report.evaluations,
            nodes: report.nodes_checked,
        };
        write_junit(path, &s.name(), &nested, laws.as_ref().map(|(_, c)| c))?;
    }
    Ok(exit_code(report.nested_scramble, laws.as_ref()))
}

/// The witness words of a violation in hex (binary words).
fn hex_words(v: &Violation) -> String {
    format!(
        "inputs {:#x}, {:#x} -> outputs {:#x}, {:#x}",
        v.inputs[0], v.inputs[1], v.outputs[0], v.outputs[1]
    )
}

/// The `--laws` part of the JSON report: the claim judged, the checks and the profile.
pub(super) fn add_laws_json(doc: &mut serde_json::Value, laws: Option<&(Claim, Vec<CheckResult>)>) {
    if let Some((claim, checks)) = laws {
        doc["claim"] = serde_json::json!(claim.to_string());
        doc["laws"] = serde_json::json!(checks);
        doc["profile"] = serde_json::json!(gartowen::verify::profile(checks));
    }
}

/// Exit 0 when nested and no law failed, else 1.
pub(super) fn exit_code(nested: bool, laws: Option<&(Claim, Vec<CheckResult>)>) -> ExitCode {
    let laws_failed = laws.is_some_and(|(_, checks)| {
        checks
            .iter()
            .any(|c| c.verdict == gartowen::verify::Verdict::Fail)
    });
    if nested && !laws_failed {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// The per-depth law profile of `--laws`, one family a line with its worst sub-test.
pub(super) fn print_laws(claim: Claim, checks: &[CheckResult], bits: u32) -> Result<(), CliError> {
    crate::outln!(
        "  laws over seeds 0, 1, 2, … ({bits}-bit words, dimension 0; dimensions 0..64 for \
         `dimensions`) judged as {claim} (family-wise α = 1e-3):"
    );
    let profile = gartowen::verify::profile(checks);
    for c in checks {
        let row = profile
            .iter()
            .find(|(f, _)| *f == c.check)
            .map_or("", |(_, r)| r.as_str());
        crate::outln!(
            "    {:<11} {:<9} depth 0→ {row}",
            c.check,
            format!("{:?}", c.verdict).to_lowercase()
        );
        crate::outln!("        {}", c.detail);
    }
    Ok(())
}

/// The nestedness verdict as JUnit sees it: the base, the first violation (with its prefix
/// and witness words already formatted for the base), the work done.
pub(super) struct Nested<'a> {
    pub base: u32,
    pub violation: Option<(&'a Violation, String, String)>,
    pub evaluations: u64,
    pub nodes: u64,
}

/// Ends a run that stopped before its verdicts (the program failed, or is not a function):
/// with `--junit`, one failing testcase named `case` says why, so that a CI reading the file
/// sees the failure instead of a missing file. Returns the error to exit with, if any.
pub(super) fn junit_stopped(
    a: &InspectArgs,
    name: &str,
    case: &str,
    why: &str,
) -> Result<(), CliError> {
    let Some(path) = &a.junit else {
        return Ok(());
    };
    use gartowen::battery::junit::{JunitCase, JunitSuite};
    let suite = JunitSuite {
        name: name.to_string(),
        cases: vec![JunitCase {
            name: case.to_string(),
            failure: Some((
                why.lines().next().unwrap_or(why).to_string(),
                why.to_string(),
            )),
            skipped: false,
            output: String::new(),
            seconds: 0.0,
        }],
        certificate: None,
    };
    crate::output::write_junit(path, "gartowen inspect", &[suite])
}

/// The error an external program's failure `e` ends the run with, its JUnit written first.
pub(super) fn external_stop(a: &InspectArgs, name: &str, e: impl std::fmt::Display) -> CliError {
    let why = format!("external program failed: {e}");
    match junit_stopped(a, name, "external program", &why) {
        Ok(()) => CliError::External(e.to_string()),
        Err(w) => w,
    }
}

/// Writes `--junit`: a testcase for nestedness and one per law check.
pub(super) fn write_junit(
    path: &std::path::Path,
    name: &str,
    nested: &Nested,
    laws: Option<&Vec<CheckResult>>,
) -> Result<(), CliError> {
    use gartowen::battery::junit::{JunitCase, JunitSuite};
    let mut cases = vec![JunitCase {
        name: format!("nested in base {}", nested.base),
        failure: nested.violation.as_ref().map(|(v, prefix, words)| {
            (
                format!("not a nested scramble: {:?} at depth {}", v.kind, v.depth),
                format!("prefix {prefix}: {words}"),
            )
        }),
        skipped: false,
        output: format!("{} evaluations, {} nodes", nested.evaluations, nested.nodes),
        seconds: 0.0,
    }];
    if let Some(checks) = laws {
        cases.extend(gartowen::battery::junit::check_cases(checks));
    }
    let suite = JunitSuite {
        name: name.to_string(),
        cases,
        certificate: None,
    };
    crate::output::write_junit(path, "gartowen inspect", &[suite])
}
