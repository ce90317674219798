//! `verify --level exhaustive --dims A..B`: the every-word sweep (bijective and nested at every
//! depth on all 2^32 words of each dimension), sharded by dimension and word range, merged by
//! `verify --merge` into one certificate.

use super::verify_args::{program_record, LevelArg, VerifyArgs};
use crate::CliError;
use gartowen::certificate::{CertVerdict, Certificate, InputRecord};
use gartowen::core::{Claim, PowerOfTwoBase, Scrambler, Width};
use gartowen::external_pool::ExternalPool;
use gartowen::verify::Shard;
use gartowen::word_sweep::{
    combine, shard_range, split_run, sweep, SweepPiece, SweepPlan, SweepVerdict,
};
use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

/// Dimensions A..B, both included.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct DimRange {
    /// First dimension.
    pub first: u32,
    /// Last dimension (included).
    pub last: u32,
}

impl DimRange {
    /// Parses `A..B` (both included) or `A`.
    pub fn parse(text: &str) -> Result<DimRange, CliError> {
        let bad = || {
            CliError::Usage(format!(
                "--dims '{text}' is not A..B (both included, A ≤ B) or A"
            ))
        };
        let num = |t: &str| t.trim().parse::<u32>().map_err(|_| bad());
        let (first, last) = match text.split_once("..") {
            Some((a, b)) => (num(a)?, num(b.strip_prefix('=').unwrap_or(b))?),
            None => (num(text)?, num(text)?),
        };
        if first > last {
            return Err(bad());
        }
        Ok(DimRange { first, last })
    }

    fn dims(&self) -> impl Iterator<Item = u32> {
        self.first..=self.last
    }

    pub(crate) fn count(&self) -> u64 {
        (self.last - self.first) as u64 + 1
    }

    fn label(&self) -> String {
        if self.first == self.last {
            format!("dimension {}", self.first)
        } else {
            format!("dimensions {}..{}", self.first, self.last)
        }
    }
}

/// One implementation to sweep.
pub(crate) struct Target {
    pub(crate) name: String,
    pub(crate) scrambler: Arc<dyn Scrambler>,
    pub(crate) plan: SweepPlan,
    pub(crate) pool: Option<Arc<ExternalPool>>,
}

/// What every shard of one sweep shares (the merge refuses anything else).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct SweepParameters {
    dims: DimRange,
    implementations: Vec<String>,
    seed: u64,
    external: Option<serde_json::Value>,
}

/// A piece with the implementation it belongs to and the time it took.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct PieceRecord {
    implementation: String,
    seconds: f64,
    piece: SweepPiece,
}

/// An implementation's verdicts over the dimensions.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct ImplementationVerdict {
    implementation: String,
    base: u32,
    width: u32,
    passed: bool,
    statement: String,
    seconds: f64,
    dims: Vec<SweepVerdict>,
}

pub(crate) fn targets(a: &VerifyArgs) -> Result<Vec<Target>, CliError> {
    if let Some(command) = &a.external {
        let base = PowerOfTwoBase::from_base(a.base)
            .map_err(|e| CliError::Usage(format!("--base {}: {e}", a.base)))?;
        if a.width != 32 {
            // Refused before anything is started.
            return Err(CliError::Usage(format!(
                "--width {}: {}; drop --dims for the sampled checks",
                a.width,
                gartowen::word_sweep::SweepError::TooWide(a.width)
            )));
        }
        let claim = if a.no_uniform_claim {
            Claim::NESTED
        } else {
            super::parse_claim(&a.claim)?.unwrap_or(Claim::OWEN)
        };
        let instances = rayon::current_num_threads().max(1);
        let mut processes = Vec::with_capacity(instances);
        for _ in 0..instances {
            processes.push(Arc::new(super::spawn_external(
                command,
                base,
                Width::W32,
                a.timeout,
            )?));
        }
        let pool = Arc::new(ExternalPool::new(processes, a.seed, claim));
        let plan = SweepPlan::new(Width::W32, base).expect("32 bits");
        return Ok(vec![Target {
            name: format!("external:{command}"),
            scrambler: pool.clone(),
            plan,
            pool: Some(pool),
        }]);
    }
    let registry = gartowen::registry();
    gartowen::verify::names_or_all(&registry, &a.implementations)
        .iter()
        .map(|n| {
            let s = registry.build(n, 0)?;
            let plan =
                SweepPlan::for_scrambler(s.as_ref()).map_err(|e| CliError::Usage(e.to_string()))?;
            Ok(Target {
                name: s.name(),
                scrambler: Arc::from(s),
                plan,
                pool: None,
            })
        })
        .collect()
}

/// Runs the sweep (or this shard's part of it).
pub fn run(a: &VerifyArgs, dims_text: &str) -> Result<ExitCode, CliError> {
    if a.level != LevelArg::Exhaustive {
        return Err(CliError::Usage(
            "--dims runs the every-word sweep, which is --level exhaustive".into(),
        ));
    }
    let dims = DimRange::parse(dims_text)?;
    let shard = match &a.shard {
        None => Shard::ALL,
        Some(t) => Shard::parse(t)
            .ok_or_else(|| CliError::Usage(format!("--shard '{t}' is not I/N with 1 ≤ I ≤ N")))?,
    };
    let targets = targets(a)?;
    // Units are (implementation, dimension, chunk) in that order; a shard takes a contiguous run.
    let segments: Vec<u64> = targets
        .iter()
        .flat_map(|t| dims.dims().map(move |_| t.plan.chunks()))
        .collect();
    let total: u64 = segments.iter().sum();
    let run = shard_range(total, shard.index as u64, shard.count as u64);
    let work = split_run(&segments, run);
    let words: u64 = work
        .iter()
        .map(|(seg, r)| (r.end - r.start) * targets[seg / dims.count() as usize].plan.chunk_words())
        .sum();
    let bar = indicatif::ProgressBar::new(words);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "sweep {msg} [{bar:30}] {percent}% {human_pos}/{human_len} words, {per_sec}, ETA {eta}",
        )
        .expect("template"),
    );
    let mut records = Vec::new();
    let mut external_failure = None;
    for (seg, chunks) in work {
        let t = &targets[seg / dims.count() as usize];
        let dim = dims.first + (seg as u64 % dims.count()) as u32;
        bar.set_message(format!("{} dim {dim}", t.name));
        let start = Instant::now();
        let piece = sweep(t.scrambler.as_ref(), &t.plan, dim, chunks, &|n| bar.inc(n))
            .map_err(|e| CliError::Usage(e.to_string()))?;
        if let Some(e) = t.pool.as_ref().and_then(|p| p.failure()) {
            // The piece met the failure (its words became 0): it is not a verdict.
            external_failure = Some(e.to_string());
            break;
        }
        records.push(PieceRecord {
            implementation: t.name.clone(),
            seconds: start.elapsed().as_secs_f64(),
            piece,
        });
    }
    bar.finish_and_clear();
    let parameters = SweepParameters {
        dims,
        implementations: targets.iter().map(|t| t.name.clone()).collect(),
        seed: if a.external.is_some() { a.seed } else { 0 },
        external: a.external.as_ref().map(|c| {
            serde_json::json!({"command": c, "base": a.base, "width": a.width,
                               "timeout_seconds": a.timeout})
        }),
    };
    let inputs: Vec<InputRecord> = match &a.external {
        Some(c) => vec![program_record(c)],
        None => targets
            .iter()
            .map(|t| InputRecord {
                kind: "registry".into(),
                name: t.name.clone(),
                checksum_fnv1a64: None,
                details: serde_json::json!({"base": t.plan.base().base(), "width": t.plan.width().bits()}),
            })
            .collect(),
    };
    let code = finish(
        a.json.as_ref(),
        a.junit.as_ref(),
        &parameters,
        shard,
        inputs,
        records,
        external_failure.as_deref(),
    )?;
    match external_failure {
        // The pieces before it and the certificate are written; the exit code says the
        // program broke, not that a check failed.
        Some(e) => Err(CliError::External(e)),
        None => Ok(code),
    }
}

/// Prints and certifies: the verdicts when the pieces cover everything (one shard of one, or a
/// merge), else the pieces there are (a shard's, or those before an external program failed).
fn finish(
    json: Option<&PathBuf>,
    junit: Option<&PathBuf>,
    parameters: &SweepParameters,
    shard: Shard,
    inputs: Vec<InputRecord>,
    records: Vec<PieceRecord>,
    external_failure: Option<&str>,
) -> Result<ExitCode, CliError> {
    let complete = shard.count == 1 && external_failure.is_none();
    let verdicts = if complete {
        verdicts(parameters, &records)?
    } else {
        Vec::new()
    };
    let failed = if complete {
        for v in &verdicts {
            print_verdict(v)?;
        }
        verdicts.iter().filter(|v| !v.passed).count()
    } else {
        for r in &records {
            let p = &r.piece;
            let what = match &p.failure {
                None => format!("no failure in {} words", p.words),
                Some(f) => format!("FAIL {}", f.describe(p.base)),
            };
            crate::outln!(
                "{} dim {} chunks {}..{} of {}: {what} ({:.1} s)",
                r.implementation,
                p.dim,
                p.chunks[0],
                p.chunks[1],
                SweepPlan::new(
                    Width::new(p.width)?,
                    PowerOfTwoBase::from_base(p.base as u64)?
                )
                .map(|plan| plan.chunks())
                .unwrap_or(0),
                r.seconds
            );
        }
        crate::outln!(
            "shard {}/{} of the every-word sweep: combine every shard's --json with verify --merge",
            shard.index,
            shard.count
        );
        records.iter().filter(|r| r.piece.failure.is_some()).count()
    };
    if let Some(path) = junit {
        crate::output::write_junit(
            path,
            "gartowen verify --level exhaustive",
            &junit_suites(&records, external_failure, json),
        )?;
    }
    if let Some(path) = json {
        let cert = Certificate::new(
            "verify",
            if failed == 0 && external_failure.is_none() {
                CertVerdict::Pass
            } else {
                CertVerdict::Fail
            },
            serde_json::json!({
                "level": "exhaustive",
                "sweep": parameters,
                "shard": {"index": shard.index, "count": shard.count},
            }),
            vec![parameters.seed],
            inputs,
            serde_json::json!({ "pieces": piece_records(&records, complete),
                                "implementations": verdicts,
                                "external_failure": external_failure }),
        );
        crate::output::write_atomically(Some(path), |out| {
            out.write_all(cert.to_json().as_bytes())
                .map_err(|e| CliError::Io(e.to_string()))
        })?;
    }
    Ok(ExitCode::from(if failed == 0 {
        crate::error::EXIT_PASS
    } else {
        crate::error::EXIT_FAIL
    }))
}

/// JUnit for the sweep: a suite per implementation, a case per piece (dimension and chunks),
/// failing with the first failing word's description; a failed external program is a failing
/// case of its own.
fn junit_suites(
    records: &[PieceRecord],
    external_failure: Option<&str>,
    json: Option<&PathBuf>,
) -> Vec<gartowen::battery::junit::JunitSuite> {
    use gartowen::battery::junit::{JunitCase, JunitSuite};
    let mut names: Vec<&str> = records.iter().map(|r| r.implementation.as_str()).collect();
    names.dedup();
    let mut suites: Vec<JunitSuite> = names
        .iter()
        .map(|name| JunitSuite {
            name: name.to_string(),
            certificate: json.map(|p| p.display().to_string()),
            cases: records
                .iter()
                .filter(|r| r.implementation == *name)
                .map(|r| {
                    let p = &r.piece;
                    let what = format!("dim {} chunks {}..{}", p.dim, p.chunks[0], p.chunks[1]);
                    JunitCase {
                        failure: p.failure.as_ref().map(|f| {
                            (
                                format!("{what}: {}", f.describe(p.base)),
                                serde_json::to_string(f).expect("failures serialize"),
                            )
                        }),
                        name: what,
                        skipped: false,
                        output: format!("{} words", p.words),
                        seconds: r.seconds,
                    }
                })
                .collect(),
        })
        .collect();
    if let Some(e) = external_failure {
        suites.push(JunitSuite {
            name: "external program".into(),
            certificate: None,
            cases: vec![JunitCase {
                name: "the program answered every request".into(),
                failure: Some((e.to_string(), e.to_string())),
                skipped: false,
                output: String::new(),
                seconds: 0.0,
            }],
        });
    }
    suites
}

/// The pieces as a certificate keeps them: whole for a shard (the merge needs their chunk
/// images and node laws), summarized once the verdicts are complete (the images of 1024
/// dimensions would make a ~90 MB certificate; the shards keep them).
fn piece_records(records: &[PieceRecord], complete: bool) -> serde_json::Value {
    if !complete {
        return serde_json::to_value(records).expect("pieces serialize");
    }
    records
        .iter()
        .map(|r| {
            serde_json::json!({
                "implementation": r.implementation,
                "seconds": r.seconds,
                "dim": r.piece.dim,
                "chunks": r.piece.chunks,
                "words": r.piece.words,
                "failure": r.piece.failure,
            })
        })
        .collect()
}

impl SweepParameters {
    /// Whether `r` is a piece of this sweep: one of its implementations, in its dimensions.
    fn holds(&self, r: &PieceRecord) -> bool {
        self.implementations.contains(&r.implementation)
            && (self.dims.first..=self.dims.last).contains(&r.piece.dim)
    }
}

/// Combines the pieces of every implementation and dimension; a missing one is refused.
fn verdicts(
    parameters: &SweepParameters,
    records: &[PieceRecord],
) -> Result<Vec<ImplementationVerdict>, CliError> {
    if let Some(r) = records.iter().find(|r| !parameters.holds(r)) {
        return Err(CliError::Usage(format!(
            "a piece of {} dimension {} is not part of this sweep ({}, {})",
            r.implementation,
            r.piece.dim,
            parameters.implementations.join(", "),
            parameters.dims.label()
        )));
    }
    let mut out = Vec::new();
    for name in &parameters.implementations {
        let mut dims = Vec::new();
        let mut seconds = 0.0;
        for dim in parameters.dims.dims() {
            let pieces: Vec<SweepPiece> = records
                .iter()
                .filter(|r| &r.implementation == name && r.piece.dim == dim)
                .inspect(|r| seconds += r.seconds)
                .map(|r| r.piece.clone())
                .collect();
            if pieces.is_empty() {
                return Err(CliError::Usage(format!(
                    "{name}: dimension {dim} has no pieces: a shard is missing"
                )));
            }
            dims.push(combine(&pieces).map_err(|e| CliError::Usage(format!("{name}: {e}")))?);
        }
        let (base, width) = (dims[0].base, dims[0].width);
        let passed = dims.iter().all(|d| d.passed);
        let statement = if passed {
            format!(
                "bijective and nested on all 2^{width} words, {}, base {base}",
                parameters.dims.label()
            )
        } else {
            format!(
                "NOT bijective and nested on all 2^{width} words: {} of {} dimension(s) failed",
                dims.iter().filter(|d| !d.passed).count(),
                dims.len()
            )
        };
        out.push(ImplementationVerdict {
            implementation: name.clone(),
            base,
            width,
            passed,
            statement,
            seconds,
            dims,
        });
    }
    Ok(out)
}

fn print_verdict(v: &ImplementationVerdict) -> Result<(), CliError> {
    crate::outln!(
        "{} (base {}, {}-bit words, {:.1} s)",
        v.implementation,
        v.base,
        v.width,
        v.seconds
    );
    for d in &v.dims {
        let mark = if d.passed { "pass" } else { "FAIL" };
        crate::outln!("  {mark} {}", d.statement);
        if !d.node_laws.is_empty() {
            let p: Vec<String> = d
                .node_laws
                .iter()
                .map(|l| format!("{:.2}", l.p_value))
                .collect();
            crate::outln!(
                "    node laws by depth 0..{} (measured, χ² p-value against uniform S_{}): {}",
                d.node_laws.len() - 1,
                d.base,
                p.join(" ")
            );
        }
    }
    crate::outln!("  => {}", v.statement);
    Ok(())
}

/// `verify --merge` of sweep shards: the shards 1..N of one sweep, each once, from the same tool
/// version and parameters; every implementation, dimension and chunk covered exactly once.
pub fn merge(
    paths: &[PathBuf],
    json: Option<&PathBuf>,
    junit: Option<&PathBuf>,
) -> Result<ExitCode, CliError> {
    use super::shards::{check_digest, read_certificate, refuse, ShardSet};
    let mut set = ShardSet::default();
    let mut first: Option<(Certificate, SweepParameters)> = None;
    let mut records = Vec::new();
    let mut texts = Vec::new();
    for p in paths {
        let (cert, text) = read_certificate(p)?;
        let params: SweepParameters = serde_json::from_value(cert.parameters["sweep"].clone())
            .map_err(|_| {
                refuse(
                    p,
                    "not a shard of the every-word sweep (verify --level exhaustive --dims)",
                )
            })?;
        if let Some(fp) = set.admit(p, &cert)? {
            if first.as_ref().expect("admitted before").1 != params {
                return Err(refuse(
                    p,
                    format!("is a shard of another sweep than {}", fp.display()),
                ));
            }
        }
        let pieces: Vec<PieceRecord> = serde_json::from_value(cert.result["pieces"].clone())
            .map_err(|e| refuse(p, format!("bad pieces: {e}")))?;
        texts.push((p, text));
        records.extend(pieces);
        if first.is_none() {
            first = Some((cert, params));
        }
    }
    set.complete()?;
    let (cert, params) = first.expect("at least one file");
    // The pieces' own checks first (they name what was edited), then the digests (edits that
    // kept the pieces consistent).
    verdicts(&params, &records)?;
    for (p, text) in &texts {
        check_digest(p, text)?;
    }
    finish(json, junit, &params, Shard::ALL, cert.inputs, records, None)
}

/// Checks a certificate of the every-word sweep field by field (`certificate check`): the tool
/// version, the sweep's parameters and seed, the shard record, every piece belonging to the
/// sweep, and the verdict following from the pieces (a shard) or from the implementations'
/// verdicts (a whole sweep). Returns what was checked, in words.
pub fn audit(cert: &Certificate) -> Result<String, CliError> {
    let field = |f: &str, m: String| CliError::Usage(format!("{f}: {m}"));
    let ours = env!("CARGO_PKG_VERSION");
    if cert.tool_version != ours {
        return Err(field(
            "tool_version",
            format!(
                "made by gartowen {}; this build ({ours}) checks only its own certificates",
                cert.tool_version
            ),
        ));
    }
    if cert.parameters["level"] != "exhaustive" {
        return Err(field(
            "parameters.level",
            format!("{}, but a sweep is exhaustive", cert.parameters["level"]),
        ));
    }
    let params: SweepParameters = serde_json::from_value(cert.parameters["sweep"].clone())
        .map_err(|e| field("parameters.sweep", e.to_string()))?;
    if cert.seeds != [params.seed] {
        return Err(field(
            "seeds",
            format!("{:?}, but the sweep's seed is {}", cert.seeds, params.seed),
        ));
    }
    let shard = &cert.parameters["shard"];
    let (index, count) = match (shard["index"].as_u64(), shard["count"].as_u64()) {
        (Some(i), Some(n)) if 1 <= i && i <= n => (i, n),
        _ => return Err(field("parameters.shard", shard.to_string())),
    };
    if params.external.is_none() {
        let registry = gartowen::registry();
        for (k, name) in params.implementations.iter().enumerate() {
            if name.chars().any(char::is_control) || registry.build(name, 0).is_err() {
                return Err(field(
                    &format!("parameters.sweep.implementations[{k}]"),
                    format!("{name:?} is no registry implementation"),
                ));
            }
        }
    }
    let external_failure = !cert.result["external_failure"].is_null();
    let failed = if count == 1 && !external_failure {
        let verdicts: Vec<ImplementationVerdict> =
            serde_json::from_value(cert.result["implementations"].clone())
                .map_err(|e| field("result.implementations", e.to_string()))?;
        let names: Vec<&String> = verdicts.iter().map(|v| &v.implementation).collect();
        if names != params.implementations.iter().collect::<Vec<_>>() {
            return Err(field(
                "result.implementations",
                format!("{names:?}, but the sweep has {:?}", params.implementations),
            ));
        }
        verdicts.iter().any(|v| !v.passed)
    } else {
        let pieces: Vec<PieceRecord> = serde_json::from_value(cert.result["pieces"].clone())
            .map_err(|e| field("result.pieces", e.to_string()))?;
        if let Some((k, r)) = pieces.iter().enumerate().find(|(_, r)| !params.holds(r)) {
            return Err(field(
                &format!("result.pieces[{k}]"),
                format!(
                    "a piece of {} dimension {} is not part of this sweep",
                    r.implementation, r.piece.dim
                ),
            ));
        }
        external_failure || pieces.iter().any(|r| r.piece.failure.is_some())
    };
    let verdict = if failed {
        CertVerdict::Fail
    } else {
        CertVerdict::Pass
    };
    if cert.verdict != verdict {
        return Err(field(
            "verdict",
            format!("says {:?}, the sweep gives {verdict:?}", cert.verdict).to_lowercase(),
        ));
    }
    Ok(format!(
        "every-word sweep of {} implementation(s), {}, shard {index}/{count}, fields checked",
        params.implementations.len(),
        params.dims.label()
    ))
}
