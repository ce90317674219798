//! The implementations the battery judges, however they are reached: registry entries,
//! external programs, or any in-process builder of instances per seed.

use crate::radix_words::RadixWords;
use crate::sampling::{ManySeeds, SeedBuilder};
use gartowen_core::{
    BuildContext, Claim, CoreError, PowerOfTwoBase, Radix, RadixScrambler, Registry, Scrambler,
};
use gartowen_owen::registry::build_radix;

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
    /// Many seeds per call, where the implementation offers it (the law passes then use it).
    pub many: Option<Box<ManySeeds<'a>>>,
    /// A failure of the transport, checked after every check (external programs).
    pub health: Box<dyn Fn() -> Option<String> + 'a>,
    /// A built-in twin the implementation must agree with bit for bit (`--expect`).
    pub twin: Option<(String, Box<SeedBuilder<'a>>)>,
    /// What the implementation is judged on (its own claim unless overridden).
    pub claim: Claim,
    /// It serves dimensions 0..N only (`--max-dims N`): checks use no others, and those
    /// that need one say "not run". `None`: every dimension.
    pub max_dims: Option<u32>,
    /// Its base when that is not a power of two: words are base-b digit integers, the probe
    /// and instances are [`RadixWords`]. `None`: base 2^q, the
    /// probe's [`Scrambler::base`].
    pub radix: Option<Radix>,
    /// Check nets only in its own base (`--net-bases own`: an implementation never meant for
    /// the larger bases 2^(kq) it is nested in); `false`: in every such base up to 256.
    pub own_base_nets: bool,
}

impl<'a> Candidate<'a> {
    /// The base b its digits are in.
    pub fn base(&self) -> u32 {
        self.radix
            .map_or_else(|| self.probe.base().base(), |r| r.get())
    }

    /// An in-process candidate judged on `claim`, with instances from `with_seed`
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
            many: None,
            health: Box::new(|| None),
            twin: None,
            claim,
            max_dims: None,
            radix: None,
            own_base_nets: false,
        })
    }
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

/// The candidate for registry entry `request` at position `index` (a request whose
/// `:base=B` is not a power of two is the built-in of that base: see
/// [`radix_candidate`]).
pub fn registry_candidate<'a>(
    registry: &'a Registry,
    request: &'a str,
    index: usize,
) -> Result<Candidate<'a>, CoreError> {
    if let Some(radix) = gartowen_owen::registry::requested_radix(request, 2)? {
        return radix_candidate(request, radix, index);
    }
    let probe = registry.build(request, 0)?;
    let base = probe.base();
    Ok(Candidate {
        index,
        name: probe.name(),
        claim: probe.claim(),
        probe,
        with_seed: registry_seeds(registry, request, base),
        many: None,
        health: Box::new(|| None),
        twin: None,
        max_dims: None,
        radix: None,
        own_base_nets: false,
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

/// The candidate for an external program: instances for every seed share the one process;
/// `twin` names a registry entry it must match bit for bit. A process in a base that is not a
/// power of two speaks version 2 frames and is judged on base-b digits.
pub fn external_candidate<'a>(
    process: std::sync::Arc<crate::external::ExternalProcess>,
    seed: u64,
    claim: Claim,
    twin: Option<(&'a Registry, &'a str)>,
) -> Candidate<'a> {
    use crate::external::{ExternalRadixScrambler, ExternalScrambler};
    let base = process.base();
    let radix = base.radix();
    let for_seed = process.clone();
    let watched = process.clone();
    // One seed's instance: the binary view, or the base-b view behind RadixWords.
    let instance = move |p: std::sync::Arc<crate::external::ExternalProcess>, s: u64| {
        match ExternalRadixScrambler::new(p.clone(), s, claim) {
            Some(r) => Box::new(RadixWords(Box::new(r))) as Box<dyn Scrambler>,
            None => Box::new(ExternalScrambler::new(p, s, claim)),
        }
    };
    Candidate {
        index: 0,
        name: format!("external:{}", process.command()),
        claim,
        probe: instance(process, seed),
        with_seed: Box::new(move |s| Ok(instance(for_seed.clone(), s))),
        many: None,
        health: Box::new(move || watched.failure().map(|e| e.to_string())),
        twin: twin.map(|(registry, request)| {
            let seeds = match radix {
                Some(r) => radix_seeds(request, r),
                None => registry_seeds(registry, request, base.power_of_two().expect("2^q")),
            };
            (request.to_string(), seeds)
        }),
        max_dims: None,
        radix,
        own_base_nets: false,
    }
}

/// The candidate for the built-in `request` in base `radix` (see
/// [`gartowen_owen::registry::build_radix`]) at position `index`.
pub fn radix_candidate<'a>(
    request: &str,
    radix: Radix,
    index: usize,
) -> Result<Candidate<'a>, CoreError> {
    let probe = build_radix(request, radix, 0)?;
    Ok(Candidate {
        index,
        name: probe.name(),
        claim: probe.claim(),
        probe: Box::new(RadixWords(Box::new(probe))),
        with_seed: radix_seeds(request, radix),
        many: None,
        health: Box::new(|| None),
        twin: None,
        max_dims: None,
        radix: Some(radix),
        own_base_nets: false,
    })
}

/// Instances of the built-in `request` in base `radix` for any seed (an external program's
/// `--expect` twin in that base).
pub fn radix_seeds<'a>(request: &str, radix: Radix) -> Box<SeedBuilder<'a>> {
    let request = request.to_string();
    Box::new(move |seed| {
        let s = build_radix(&request, radix, seed).map_err(|e| e.to_string())?;
        Ok(Box::new(RadixWords(Box::new(s))) as Box<dyn Scrambler>)
    })
}
