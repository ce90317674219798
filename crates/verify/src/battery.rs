//! The conformance battery behind `gartowen verify`: every check runs on any registered
//! scrambler as a black box, so external and deliberately broken implementations are judged
//! the same way.
//!
//! Checks per implementation:
//! * `inverse`: `unscramble(scramble(x)) = x` on 10^4 (quick) or 10^5 (full) seeded words;
//! * `nested`: the inspector, exhaustive at 16 bits (probes at 32 bits where 16 is unsupported);
//! * `nets` ([`crate::nets`]): a net in the scrambler's base and in every base 2^(kq) it is
//!   nested in (Sobol, sz4, sz16, Faure over GF(2^r)) keeps the t-value the rank path gives
//!   for the unscrambled matrices, for every m up to a level bound;
//! * the laws ([`crate::laws`]): `node-law` (marginal, by depth), `pair-law`, `flip-rank`,
//!   `collisions` (joint), `pair-lemma` and `dimensions`. Each sub-test states what it requires
//!   (a marginal law or independence), its p-value, and its power; a check gets a verdict only
//!   when the implementation claims what it tests, and is `measured` otherwise. The family-wise
//!   level of a run is [`FAMILY_ALPHA`] = 10^-3, split evenly (Bonferroni) over the
//!   implementations judged and their judged sub-tests.

use crate::law::SubTest;
use crate::sampling::SeedBuilder;
use crate::stats::{bonferroni, min_detectable_w, FAMILY_ALPHA};
use gartowen_core::{
    BuildContext, Claim, CoreError, PowerOfTwoBase, Registry, Scrambler, SplitMix64, Width,
};
use gartowen_oracles::inspector::{inspect_exhaustive, inspect_probes_batched};
use serde::Serialize;
use std::time::Instant;

/// How much to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// Under a minute for the whole registry on 2 cores.
    Quick,
    /// Larger samples and deeper nets.
    Full,
    /// Long: the largest samples and nets; meant to be sharded.
    Exhaustive,
}

/// A check's outcome.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// The property holds.
    Pass,
    /// The property is violated.
    Fail,
    /// A measured value without a verdict (no claim to judge).
    Measured,
    /// Not applicable (e.g. no sequence in this base).
    Skipped,
}

/// One check of one implementation.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct CheckResult {
    /// Check name.
    pub check: String,
    /// Outcome.
    pub verdict: Verdict,
    /// What was found, in words (the failing node or box, the measured distance).
    pub detail: String,
    /// The measured value where there is one (the worst sub-test's statistic for the laws).
    pub value: Option<f64>,
    /// Wall time (the law checks share one pass over the seeds: each gets an equal share).
    pub seconds: f64,
    /// The smallest p-value of the sub-tests (laws only).
    #[serde(default)]
    pub p_value: Option<f64>,
    /// The per-sub-test level the p-values were compared with (laws only).
    #[serde(default)]
    pub alpha: Option<f64>,
    /// The sub-tests (laws only), each with its statistic, p-value and power.
    #[serde(default)]
    pub tests: Vec<SubTest>,
}

/// All checks of one implementation.
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
pub struct ImplReport {
    /// Position in the list of implementations verified (restores order when shards merge).
    pub index: usize,
    /// Registry name.
    pub name: String,
    /// Scrambling base.
    pub base: u32,
    /// Whether it claims nested uniformity.
    pub claims_nested_uniform: bool,
    /// What it claims (`nested`, `marginal:GROUP`, `independent:GROUP`, `owen`).
    #[serde(default)]
    pub claim: String,
    /// The checks.
    pub checks: Vec<CheckResult>,
    /// Per law family, one character per depth 0, 1, …: `.` no deviation detected, `x` a
    /// deviation at the per-test level, `-` not tested (the "how close to Owen" profile).
    #[serde(default)]
    pub profile: Vec<(String, String)>,
}

impl ImplReport {
    /// Whether any check failed.
    pub fn failed(&self) -> bool {
        self.checks.iter().any(|c| c.verdict == Verdict::Fail)
    }
}

fn timed(check: &str, f: impl FnOnce() -> (Verdict, String, Option<f64>)) -> CheckResult {
    let t = Instant::now();
    let (verdict, detail, value) = f();
    CheckResult {
        check: check.into(),
        verdict,
        detail,
        value,
        seconds: t.elapsed().as_secs_f64(),
        p_value: None,
        alpha: None,
        tests: Vec::new(),
    }
}

fn check_inverse(s: &dyn Scrambler, level: Level) -> (Verdict, String, Option<f64>) {
    let n = if level == Level::Quick {
        10_000
    } else {
        100_000
    };
    let mut rng = SplitMix64::new(INVERSE_SEED);
    for width in supported_widths(s) {
        for _ in 0..n {
            let x = rng.next_u64() & width.mask();
            let dim = rng.bounded(8);
            let y = s.scramble(x, width, dim);
            if width.check(y).is_err() || s.unscramble(y, width, dim) != x {
                return (
                    Verdict::Fail,
                    format!(
                        "{}-bit word {x:#x} (dim {dim}) -> {y:#x} does not invert",
                        width.bits()
                    ),
                    None,
                );
            }
        }
    }
    (
        Verdict::Pass,
        format!("{n} words per supported width invert"),
        None,
    )
}

/// For implementations without an inverse (external programs): images stay in range and
/// distinct inputs of one dimension never collide.
fn check_injective(s: &dyn Scrambler, level: Level) -> (Verdict, String, Option<f64>) {
    let n = if level == Level::Quick { 4096 } else { 32_768 };
    let mut rng = SplitMix64::new(INVERSE_SEED);
    for width in supported_widths(s) {
        for dim in 0..4u32 {
            let mut inputs: Vec<u64> = (0..n).map(|_| rng.next_u64() & width.mask()).collect();
            inputs.sort_unstable();
            inputs.dedup();
            let mut outputs = inputs.clone();
            s.scramble_batch(&mut outputs, width, dim);
            let mut seen = std::collections::HashMap::with_capacity(inputs.len());
            for (&x, &y) in inputs.iter().zip(&outputs) {
                if width.check(y).is_err() {
                    return (
                        Verdict::Fail,
                        format!(
                            "{}-bit word {x:#x} (dim {dim}) -> {y:#x} is out of range",
                            width.bits()
                        ),
                        None,
                    );
                }
                if let Some(other) = seen.insert(y, x) {
                    return (
                        Verdict::Fail,
                        format!("not injective: {other:#x} and {x:#x} (dim {dim}) both -> {y:#x}"),
                        None,
                    );
                }
            }
        }
    }
    (
        Verdict::Pass,
        format!("{n} words per dimension map to distinct in-range words (no inverse to test)"),
        None,
    )
}

fn supported_widths(s: &dyn Scrambler) -> Vec<Width> {
    [Width::W32, Width::W64]
        .into_iter()
        .filter(|w| s.supports_width(*w))
        .collect()
}

/// The width the battery scrambles at: 32 bits where supported, else 64.
fn working_width(s: &dyn Scrambler) -> Width {
    if s.supports_width(Width::W32) {
        Width::W32
    } else {
        Width::W64
    }
}

fn check_nested(s: &dyn Scrambler) -> (Verdict, String, Option<f64>) {
    let base = s.base();
    let w16 = Width::new(16).expect("16");
    let report = if s.supports_width(w16) {
        inspect_exhaustive(&|x| s.scramble(x, w16, 0), w16, base, 16)
    } else {
        let w = working_width(s);
        inspect_probes_batched(
            &|words: &mut [u64]| s.scramble_batch(words, w, 0),
            w,
            base,
            w.bits(),
            2000,
            PROBE_SEED,
        )
    };
    match report.first_violation {
        None => (
            Verdict::Pass,
            format!(
                "nested in base {} ({} nodes)",
                base.base(),
                report.nodes_checked
            ),
            None,
        ),
        Some(v) => (
            Verdict::Fail,
            format!(
                "{:?} at depth {}, prefix {:#x}: inputs {:#x}, {:#x} -> outputs {:#x}, {:#x}",
                v.kind, v.depth, v.prefix, v.inputs[0], v.inputs[1], v.outputs[0], v.outputs[1]
            ),
            None,
        ),
    }
}

fn check_nets(s: &dyn Scrambler, level: Level) -> (Verdict, String, Option<f64>) {
    let width = working_width(s);
    if !s.supports_width(width) {
        return (
            Verdict::Skipped,
            "neither 32- nor 64-bit words".into(),
            None,
        );
    }
    let (verdict, detail) = crate::nets::check_nets(s, width, level);
    (verdict, detail, None)
}

/// Which part of the list to run: shard `index` (1-based) of `count`; implementation k goes to
/// shard (k mod count) + 1, so shards are deterministic and disjoint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// 1-based shard number.
    pub index: usize,
    /// Number of shards.
    pub count: usize,
}

impl Shard {
    /// The whole list.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// Parses `I/N` with 1 ≤ I ≤ N.
    pub fn parse(text: &str) -> Option<Shard> {
        let (i, n) = text.split_once('/')?;
        let (index, count) = (i.trim().parse().ok()?, n.trim().parse().ok()?);
        (count >= 1 && (1..=count).contains(&index)).then_some(Shard { index, count })
    }

    /// Whether implementation k belongs to this shard.
    pub fn contains(&self, k: usize) -> bool {
        k % self.count + 1 == self.index
    }
}

/// Merges shard reports into one list in implementation order: exactly `total`
/// implementations, each once, every one with the same checks in the same order. Errors name
/// the duplicate, the missing implementation or the odd check list.
pub fn merge(parts: Vec<Vec<ImplReport>>, total: usize) -> Result<Vec<ImplReport>, String> {
    let mut all: Vec<ImplReport> = parts.into_iter().flatten().collect();
    all.sort_by_key(|r| r.index);
    if let Some(w) = all.windows(2).find(|w| w[0].index == w[1].index) {
        return Err(format!(
            "implementation {} ({}) appears in two shards",
            w[0].index, w[0].name
        ));
    }
    if let Some((k, r)) = all.iter().enumerate().find(|(k, r)| r.index != *k) {
        return Err(format!(
            "implementation {k} is missing (next present: {} at {})",
            r.name, r.index
        ));
    }
    if all.len() != total {
        return Err(format!(
            "{} of {total} implementations present: {} to {} are missing",
            all.len(),
            all.len(),
            total.saturating_sub(1)
        ));
    }
    let names = |r: &ImplReport| r.checks.iter().map(|c| c.check.clone()).collect::<Vec<_>>();
    if let Some(first) = all.first() {
        let want = names(first);
        if let Some(r) = all.iter().find(|r| names(r) != want) {
            return Err(format!(
                "implementation {} ({}) has checks {:?}, the others {want:?}",
                r.index,
                r.name,
                names(r)
            ));
        }
    }
    Ok(all)
}

/// One implementation as the battery sees it, however it is reached (registry or external).
pub struct Candidate<'a> {
    /// Position in the list being verified.
    pub index: usize,
    /// Name for the report.
    pub name: String,
    /// The instance with the run's seed (0 for registry entries).
    pub probe: Box<dyn Scrambler + 'a>,
    /// Instances for other seeds (the node law draws thousands).
    pub with_seed: Box<SeedBuilder<'a>>,
    /// Whether `unscramble` is a real inverse (false for external programs: the battery then
    /// checks injectivity instead).
    pub invertible: bool,
    /// A failure of the transport, checked after every check (external programs).
    pub health: Box<dyn Fn() -> Option<String> + 'a>,
    /// A built-in twin the implementation must agree with bit for bit (`--expect`).
    pub twin: Option<(String, Box<SeedBuilder<'a>>)>,
    /// What the implementation is judged on (its own claim unless overridden).
    pub claim: Claim,
}

impl<'a> Candidate<'a> {
    /// An invertible in-process candidate judged on `claim`, with instances from `with_seed`
    /// (the probe is seed 0's instance).
    pub fn from_builder(
        name: impl Into<String>,
        claim: Claim,
        with_seed: Box<SeedBuilder<'a>>,
    ) -> Result<Candidate<'a>, String> {
        Ok(Candidate {
            index: 0,
            name: name.into(),
            probe: with_seed(0)?,
            with_seed,
            invertible: true,
            health: Box::new(|| None),
            twin: None,
            claim,
        })
    }
}

/// Bit-exact agreement with the twin on seeds 0..4, dimensions 0..8 and 512 words each
/// (0, the largest word, and seeded random words).
fn check_twin(
    c: &Candidate,
    twin_name: &str,
    twin: &SeedBuilder,
    level: Level,
) -> (Verdict, String, Option<f64>) {
    let words = if level == Level::Quick { 512 } else { 4096 };
    let width = working_width(c.probe.as_ref());
    let mut rng = SplitMix64::new(TWIN_SEED);
    let mut compared = 0u64;
    for seed in 0..4u64 {
        let (mine, theirs) = match (c.with_seed.as_ref()(seed), twin(seed)) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(e), _) | (_, Err(e)) => {
                return (
                    Verdict::Fail,
                    format!("cannot build seed {seed}: {e}"),
                    None,
                )
            }
        };
        if !theirs.supports_width(width) {
            return (
                Verdict::Fail,
                format!("{twin_name} does not support {}-bit words", width.bits()),
                None,
            );
        }
        for dim in 0..8u32 {
            let xs: Vec<u64> = (0..words)
                .map(|k| match k {
                    0 => 0,
                    1 => width.mask(),
                    _ => rng.next_u64() & width.mask(),
                })
                .collect();
            // One batch each: an external or Python implementation answers one request.
            let (mut a, mut b) = (xs.clone(), xs.clone());
            mine.scramble_batch(&mut a, width, dim);
            theirs.scramble_batch(&mut b, width, dim);
            if let Some(k) = (0..xs.len()).find(|&k| a[k] != b[k]) {
                return (
                    Verdict::Fail,
                    format!(
                        "seed {seed}, dim {dim}, word {:#x}: got {:#x}, {twin_name} gives {:#x}",
                        xs[k], a[k], b[k]
                    ),
                    None,
                );
            }
            compared += xs.len() as u64;
        }
    }
    (
        Verdict::Pass,
        format!(
            "bit-exact with {twin_name} on {compared} {}-bit words (seeds 0..4, dims 0..8)",
            width.bits()
        ),
        None,
    )
}

/// The number of independent instances (seeds 0, 1, …) the per-seed laws draw at `level`.
pub fn node_law_seeds(level: Level) -> u64 {
    match level {
        Level::Quick => 2000,
        Level::Full => 10_000,
        Level::Exhaustive => 50_000,
    }
}

/// Every fixed seed the battery uses: the main instance's seed, then the seeds of the inverse
/// sample, the inspector's probes and the twin comparison. Law instances use seeds
/// 0..[`node_law_seeds`] (and fewer for flip-rank, collisions and dimensions).
pub fn seeds_used(main_seed: u64) -> Vec<u64> {
    vec![main_seed, INVERSE_SEED, PROBE_SEED, TWIN_SEED]
}

const INVERSE_SEED: u64 = 0x1234;
const PROBE_SEED: u64 = 1;
const TWIN_SEED: u64 = 0xE8EC7;

/// Runs every check on one candidate; `judged` is the number of implementations in the whole
/// run whose claims get law verdicts (the Bonferroni divisor of [`FAMILY_ALPHA`]).
pub fn check_candidate(c: &Candidate, level: Level, judged: usize) -> ImplReport {
    let probe = c.probe.as_ref();
    let base = probe.base();
    // A transport failure turns the check that met it into a failure naming it.
    let guard = |mut r: CheckResult| {
        if let Some(e) = (c.health)() {
            r.verdict = Verdict::Fail;
            r.detail = format!("external program failed: {e}");
            r.value = None;
        }
        r
    };
    let guarded =
        |check: &str, f: &dyn Fn() -> (Verdict, String, Option<f64>)| guard(timed(check, f));
    let mut checks = vec![
        if c.invertible {
            guarded("inverse", &|| check_inverse(probe, level))
        } else {
            guarded("injective", &|| check_injective(probe, level))
        },
        guarded("nested", &|| check_nested(probe)),
        guarded("nets", &|| check_nets(probe, level)),
    ];
    let started = Instant::now();
    match crate::laws::run_laws(c, level, 0) {
        Ok(families) => {
            let seconds = started.elapsed().as_secs_f64() / families.len().max(1) as f64;
            checks.extend(
                judge_families(families, c.claim, judged, seconds)
                    .into_iter()
                    .map(guard),
            );
        }
        Err(e) => checks.push(guard(CheckResult {
            check: "laws".into(),
            verdict: Verdict::Fail,
            detail: format!("could not build per-seed instances: {e}"),
            value: None,
            seconds: started.elapsed().as_secs_f64(),
            p_value: None,
            alpha: None,
            tests: Vec::new(),
        })),
    }
    if let Some((twin_name, twin)) = &c.twin {
        checks.push(guarded("expect", &|| {
            check_twin(c, twin_name, twin.as_ref(), level)
        }));
    }
    let profile = profile(&checks);
    ImplReport {
        index: c.index,
        name: c.name.clone(),
        base: base.base(),
        claims_nested_uniform: c.claim.is_owen(),
        claim: c.claim.to_string(),
        checks,
        profile,
    }
}

/// Turns each law family's sub-tests into a check: the per-test level is
/// [`FAMILY_ALPHA`] / (judged implementations × judged sub-tests), and a family gets a verdict
/// only if the claim covers every sub-test that deviates (others are measured).
pub fn judge_families(
    families: Vec<(&'static str, Vec<SubTest>)>,
    claim: Claim,
    judged: usize,
    seconds: f64,
) -> Vec<CheckResult> {
    let claimed_tests: usize = families
        .iter()
        .flat_map(|(_, t)| t.iter())
        .filter(|t| t.requires.claimed_by(claim))
        .count();
    let all_tests: usize = families.iter().map(|(_, t)| t.len()).sum();
    let alpha = bonferroni(FAMILY_ALPHA, judged.max(1) * claimed_tests.max(1));
    // Measured-only sub-tests are flagged at the level they would have had if claimed.
    let measure_alpha = bonferroni(FAMILY_ALPHA, judged.max(1) * all_tests.max(1));
    families
        .into_iter()
        .map(|(family, mut tests)| {
            let mut judged_fail = false;
            let mut any_claimed = false;
            for t in &mut tests {
                let claimed = t.requires.claimed_by(claim);
                any_claimed |= claimed;
                let a = if claimed { alpha } else { measure_alpha };
                t.deviates = t.p_value < a;
                judged_fail |= claimed && t.deviates;
                if let Some(dof) = t.dof {
                    t.power = format!(
                        "χ² {dof} dof, n = {}: detects Cohen's w ≥ {:.3} at power 0.9",
                        t.n,
                        min_detectable_w(dof, t.n, a)
                    );
                }
            }
            let worst = tests
                .iter()
                .min_by(|a, b| a.p_value.total_cmp(&b.p_value))
                .cloned();
            let deviations = tests.iter().filter(|t| t.deviates).count();
            let verdict = if !any_claimed {
                Verdict::Measured
            } else if judged_fail {
                Verdict::Fail
            } else {
                Verdict::Pass
            };
            let detail = match &worst {
                None => "not applicable".to_string(),
                Some(w) => format!(
                    "{}: {} of {} sub-tests deviate at α' = {:.1e}; worst: {} (p = {:.2e}; {})",
                    if verdict == Verdict::Pass {
                        "no deviation detected at this power"
                    } else if verdict == Verdict::Fail {
                        "deviation"
                    } else {
                        "not claimed, measured"
                    },
                    deviations,
                    tests.len(),
                    if any_claimed { alpha } else { measure_alpha },
                    w.name,
                    w.p_value,
                    w.power
                ),
            };
            CheckResult {
                check: family.into(),
                verdict: if tests.is_empty() {
                    Verdict::Skipped
                } else {
                    verdict
                },
                detail,
                value: worst.as_ref().map(|w| w.statistic),
                seconds,
                p_value: worst.as_ref().map(|w| w.p_value),
                alpha: Some(if any_claimed { alpha } else { measure_alpha }),
                tests,
            }
        })
        .collect()
}

/// The per-depth profile of the law checks: one string per family, a character per depth.
pub fn profile(checks: &[CheckResult]) -> Vec<(String, String)> {
    let depth_max = checks
        .iter()
        .flat_map(|c| c.tests.iter())
        .filter_map(|t| t.depth)
        .max();
    let Some(depth_max) = depth_max else {
        return Vec::new();
    };
    checks
        .iter()
        .filter(|c| !c.tests.is_empty())
        .map(|c| {
            let row: String = (0..=depth_max)
                .map(|d| {
                    let at: Vec<&SubTest> = c.tests.iter().filter(|t| t.depth == Some(d)).collect();
                    if at.is_empty() {
                        '-'
                    } else if at.iter().any(|t| t.deviates) {
                        'x'
                    } else {
                        '.'
                    }
                })
                .collect();
            (c.check.clone(), row)
        })
        .collect()
}

/// Instances of registry entry `request` for any seed, in `base` unless the request names one.
pub fn registry_seeds<'a>(
    registry: &'a Registry,
    request: &'a str,
    base: PowerOfTwoBase,
) -> Box<SeedBuilder<'a>> {
    Box::new(move |seed| {
        registry
            .build_with(
                request,
                &BuildContext {
                    seed,
                    default_base: base,
                },
            )
            .map_err(|e| e.to_string())
    })
}

/// The candidate for registry entry `request` at position `index`.
pub fn registry_candidate<'a>(
    registry: &'a Registry,
    request: &'a str,
    index: usize,
) -> Result<Candidate<'a>, CoreError> {
    let probe = registry.build(request, 0)?;
    let base = probe.base();
    Ok(Candidate {
        index,
        name: probe.name(),
        claim: probe.claim(),
        probe,
        with_seed: registry_seeds(registry, request, base),
        invertible: true,
        health: Box::new(|| None),
        twin: None,
    })
}

/// The names given, or every registry entry's name when none is given.
pub fn names_or_all(registry: &Registry, names: &[String]) -> Vec<String> {
    if names.is_empty() {
        registry
            .specs()
            .iter()
            .map(|s| s.name.to_string())
            .collect()
    } else {
        names.to_vec()
    }
}

/// Runs the battery on the named implementations (all of the registry's when `names` is empty).
pub fn verify(
    registry: &Registry,
    names: &[String],
    level: Level,
) -> Result<Vec<ImplReport>, CoreError> {
    verify_shard(registry, names, level, Shard::ALL, None, &|_| {})
}

/// [`verify`] restricted to one shard, judging every implementation on `claim` when given
/// (else on its own claim), calling `progress` after each implementation.
pub fn verify_shard(
    registry: &Registry,
    names: &[String],
    level: Level,
    shard: Shard,
    claim: Option<Claim>,
    progress: &dyn Fn(&str),
) -> Result<Vec<ImplReport>, CoreError> {
    let names = names_or_all(registry, names);
    let judged = names
        .iter()
        .filter_map(|n| registry.build(n, 0).ok())
        .filter(|s| claim.unwrap_or_else(|| s.claim()).marginal.is_some())
        .count();
    let mut out = Vec::new();
    for (index, name) in names.iter().enumerate().filter(|(k, _)| shard.contains(*k)) {
        let mut candidate = registry_candidate(registry, name, index)?;
        if let Some(c) = claim {
            candidate.claim = c;
        }
        out.push(check_candidate(&candidate, level, judged));
        progress(name);
    }
    Ok(out)
}

/// The candidate for an external program: instances for every seed share the one process;
/// `twin` names a registry entry it must match bit for bit.
pub fn external_candidate<'a>(
    process: std::sync::Arc<crate::external::ExternalProcess>,
    seed: u64,
    claim: Claim,
    twin: Option<(&'a Registry, &'a str)>,
) -> Candidate<'a> {
    use crate::external::ExternalScrambler;
    let base = process.base();
    let for_seed = process.clone();
    let watched = process.clone();
    Candidate {
        index: 0,
        name: format!("external:{}", process.command()),
        claim,
        probe: Box::new(ExternalScrambler::new(process, seed, claim)),
        with_seed: Box::new(move |s| {
            Ok(Box::new(ExternalScrambler::new(for_seed.clone(), s, claim)))
        }),
        invertible: false,
        health: Box::new(move || watched.failure().map(|e| e.to_string())),
        twin: twin.map(|(registry, request)| {
            (request.to_string(), registry_seeds(registry, request, base))
        }),
    }
}
