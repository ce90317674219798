//! The structure checks, as one declared list ([`STRUCTURE_CHECKS`]): exact properties every
//! scramble of the claimed kind has, whatever its randomness.
//!
//! * `inverse`: `unscramble(scramble(x)) = x` on seeded words of every supported width;
//! * `injective` (implementations without an inverse, e.g. external programs): images stay in
//!   range and distinct inputs of one dimension never collide;
//! * `function`: a scramble is a function of (word, dimension, seed): the same words give the
//!   same outputs in a second request, in reverse order, one word per request, and from a
//!   second instance of one seed. Every other check assumes it (an external program that
//!   answers fresh random words would otherwise pass the laws);
//! * `nested`: the inspector, exhaustive at 16 bits (probes at 32 bits where 16 is
//!   unsupported);
//! * `nets` ([`crate::nets`]): nets in the scrambler's base and every base it is nested in keep
//!   their t-values;
//! * `expect`: bit-exact agreement with a built-in twin (`--expect`), after the laws.
//!
//! Sizes come from the [`LevelPlan`].

use crate::candidate::Candidate;
use crate::family::usable_dims;
use crate::level::LevelPlan;
use crate::radix_words::radix_tree;
use crate::sampling::SeedBuilder;
use crate::sampling::Tree;
use crate::verdict::Outcome;
use gartowen_core::{DigitLayout, Radix, RadixLayout, Scrambler, SplitMix64, Width};
use gartowen_oracles::inspector::{inspect_exhaustive, inspect_probes_batched};
use gartowen_oracles::radix_inspector::inspect_radix_probes;

/// When a structure check runs relative to the law families.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// Before the laws.
    BeforeLaws,
    /// After the laws (checks that compare with something else).
    AfterLaws,
}

/// One structure check: its name, when it applies and runs, and what it does.
#[derive(Clone, Copy)]
pub struct StructureCheck {
    /// The check's name in reports.
    pub name: &'static str,
    /// What it verifies, in words (for listings).
    pub what: &'static str,
    /// Whether it runs before or after the law families.
    pub stage: Stage,
    /// Whether it applies to a candidate.
    pub applies: fn(&Candidate) -> bool,
    /// Runs it at a level's sizes.
    pub run: fn(&Candidate, &LevelPlan) -> Outcome,
}

/// Every structure check, in report order within its stage.
pub const STRUCTURE_CHECKS: [StructureCheck; 6] = [
    StructureCheck {
        name: "inverse",
        what: "unscramble(scramble(x)) = x on seeded words of every supported width",
        stage: Stage::BeforeLaws,
        applies: |c| c.probe.inverse().is_some(),
        run: check_inverse,
    },
    StructureCheck {
        name: "injective",
        what: "no inverse to test: images in range, no two inputs of a dimension collide",
        stage: Stage::BeforeLaws,
        applies: |c| c.probe.inverse().is_none(),
        run: check_injective,
    },
    StructureCheck {
        name: "function",
        what: "the same word, dimension and seed always give the same output (requests, instances, positions)",
        stage: Stage::BeforeLaws,
        applies: |_| true,
        run: check_function,
    },
    StructureCheck {
        name: "nested",
        what: "output digit k depends only on input digits 0..k; node maps bijective",
        stage: Stage::BeforeLaws,
        applies: |_| true,
        run: |c, _| match c.radix {
            None => check_nested(c.probe.as_ref()),
            Some(radix) => check_nested_radix(c.probe.as_ref(), radix),
        },
    },
    StructureCheck {
        name: "nets",
        what: "nets in the scrambler's base and every base it is nested in keep their t-values (Faure or Hammersley nets in a base b that is not 2^q)",
        stage: Stage::BeforeLaws,
        applies: |_| true,
        run: |c, plan| match c.radix {
            None => check_nets(c.probe.as_ref(), plan, c.max_dims, c.own_base_nets),
            Some(radix) => check_radix_nets(c.probe.as_ref(), radix, plan, c.max_dims),
        },
    },
    StructureCheck {
        name: "expect",
        what: "bit-exact agreement with the built-in twin named by --expect",
        stage: Stage::AfterLaws,
        applies: |c| c.twin.is_some(),
        run: |c, plan| match &c.twin {
            Some((name, twin)) => check_twin(c, name, twin.as_ref(), plan),
            None => Outcome::skipped("no twin to compare with"),
        },
    },
];

/// Seed of the words `inverse` and `injective` draw.
pub const INVERSE_SEED: u64 = 0x1234;
/// Seed of the inspector's node probes.
pub const PROBE_SEED: u64 = 1;
/// Seed of the words `expect` compares.
pub const TWIN_SEED: u64 = 0xE8EC7;
/// Dimensions `expect` compares (fewer when fewer are served).
const TWIN_DIMS: u32 = 8;

/// Nodes the inspector probes when 16-bit words are unsupported.
const NESTED_PROBES: u64 = 2000;

fn supported_widths(s: &dyn Scrambler) -> Vec<Width> {
    [Width::W32, Width::W64]
        .into_iter()
        .filter(|w| s.supports_width(*w))
        .collect()
}

/// The width the battery scrambles at: 32 bits where supported, else 64, else the widest it
/// supports (a view of the top K bits).
pub fn working_width(s: &dyn Scrambler) -> Width {
    if s.supports_width(Width::W32) {
        Width::W32
    } else if s.supports_width(Width::W64) {
        Width::W64
    } else {
        // A view of the top K bits (`verify --bits K`) supports K alone.
        (1..64)
            .rev()
            .filter_map(|bits| Width::new(bits).ok())
            .find(|&w| s.supports_width(w))
            .unwrap_or(Width::W64)
    }
}

/// The words of `width` bits the candidate scrambles, and their digits: base-b digit
/// integers for a candidate in a base that is not a power of two, else base-2^q bits.
pub fn candidate_tree(c: &Candidate, width: Width) -> Tree {
    match c.radix {
        Some(radix) => radix_tree(radix, width).expect("supported widths hold a digit"),
        None => Tree::new(DigitLayout::new(width, c.probe.base())),
    }
}

fn check_inverse(c: &Candidate, plan: &LevelPlan) -> Outcome {
    let (s, max_dims) = (c.probe.as_ref(), c.max_dims);
    let Some(inverse) = s.inverse() else {
        return Outcome::fail("the implementation offers no inverse (Scrambler::inverse is None)");
    };
    let n = plan.inverse_words;
    let mut rng = SplitMix64::new(INVERSE_SEED);
    for width in supported_widths(s) {
        let tree = candidate_tree(c, width);
        for _ in 0..n {
            let x = tree.random_word(&mut rng);
            let dim = rng.bounded(usable_dims(max_dims, 8));
            let y = s.scramble(x, width, dim);
            if !tree.holds(y) || inverse.unscramble(y, width, dim) != x {
                return Outcome::fail(format!(
                    "{}-bit word {x:#x} (dim {dim}) -> {y:#x} does not invert",
                    width.bits()
                ));
            }
        }
    }
    Outcome::pass(format!("{n} words per supported width invert"))
}

fn check_injective(c: &Candidate, plan: &LevelPlan) -> Outcome {
    let (s, max_dims) = (c.probe.as_ref(), c.max_dims);
    let n = plan.injective_words;
    let mut rng = SplitMix64::new(INVERSE_SEED);
    for width in supported_widths(s) {
        let tree = candidate_tree(c, width);
        for dim in 0..usable_dims(max_dims, 4) {
            let mut inputs: Vec<u64> = (0..n).map(|_| tree.random_word(&mut rng)).collect();
            inputs.sort_unstable();
            inputs.dedup();
            let mut outputs = inputs.clone();
            s.scramble_batch(&mut outputs, width, dim);
            let mut seen = std::collections::HashMap::with_capacity(inputs.len());
            for (&x, &y) in inputs.iter().zip(&outputs) {
                if !tree.holds(y) {
                    return Outcome::fail(format!(
                        "{}-bit word {x:#x} (dim {dim}) -> {y:#x} is out of range",
                        width.bits()
                    ));
                }
                if let Some(other) = seen.insert(y, x) {
                    return Outcome::fail(format!(
                        "not injective: {other:#x} and {x:#x} (dim {dim}) both -> {y:#x}"
                    ));
                }
            }
        }
    }
    Outcome::pass(format!(
        "{n} words per dimension map to distinct in-range words (no inverse to test)"
    ))
}

/// Words the `function` check sends per dimension (0, the largest word, and seeded words), in
/// dimensions 0..FUNCTION_DIMS; the first FUNCTION_SINGLES also one word per request.
const FUNCTION_WORDS: usize = 256;
const FUNCTION_DIMS: u32 = 4;
const FUNCTION_SINGLES: usize = 8;
/// Seed of the `function` check's words.
pub const FUNCTION_SEED: u64 = 0xF0_0C7;

fn check_function(c: &Candidate, _plan: &LevelPlan) -> Outcome {
    let probe = c.probe.as_ref();
    let width = working_width(probe);
    let tree = candidate_tree(c, width);
    let mut rng = SplitMix64::new(FUNCTION_SEED);
    let differs = |what: &str, dim: u32, x: u64, y: u64, z: u64| {
        Outcome::fail(format!(
            "not a function: word {x:#x} (dim {dim}) gave {y:#x}, then {z:#x} {what}"
        ))
    };
    // Two fresh instances of seed 1 (seed 0's is the probe).
    let (one, two) = match (c.with_seed.as_ref()(1), c.with_seed.as_ref()(1)) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => return Outcome::fail(format!("cannot build seed 1: {e}")),
    };
    let dims = usable_dims(c.max_dims, FUNCTION_DIMS);
    for dim in 0..dims {
        let xs: Vec<u64> = (0..FUNCTION_WORDS)
            .map(|k| match k {
                0 => 0,
                1 => tree.largest_word(),
                _ => tree.random_word(&mut rng),
            })
            .collect();
        let batch = |s: &dyn Scrambler, words: &[u64]| {
            let mut out = words.to_vec();
            s.scramble_batch(&mut out, width, dim);
            out
        };
        let first = batch(probe, &xs);
        let again = batch(probe, &xs);
        if let Some(k) = (0..xs.len()).find(|&k| first[k] != again[k]) {
            return differs("in a second request", dim, xs[k], first[k], again[k]);
        }
        let reversed: Vec<u64> = xs.iter().rev().copied().collect();
        let back = batch(probe, &reversed);
        if let Some(k) = (0..xs.len()).find(|&k| first[k] != back[xs.len() - 1 - k]) {
            let z = back[xs.len() - 1 - k];
            return differs("at another position of a request", dim, xs[k], first[k], z);
        }
        for k in 0..FUNCTION_SINGLES {
            let z = probe.scramble(xs[k], width, dim);
            if z != first[k] {
                return differs("alone in a request", dim, xs[k], first[k], z);
            }
        }
        let (a, b) = (batch(one.as_ref(), &xs), batch(two.as_ref(), &xs));
        if let Some(k) = (0..xs.len()).find(|&k| a[k] != b[k]) {
            return differs("from a second instance of seed 1", dim, xs[k], a[k], b[k]);
        }
    }
    Outcome::pass(format!(
        "{FUNCTION_WORDS} {}-bit words in dims 0..{dims}: equal outputs in a second request, \
         in reverse order, alone, and from a second instance",
        width.bits()
    ))
}

fn check_nested(s: &dyn Scrambler) -> Outcome {
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
            NESTED_PROBES,
            PROBE_SEED,
        )
    };
    match report.first_violation {
        None => Outcome::pass(format!(
            "nested in base {} ({} nodes)",
            base.base(),
            report.nodes_checked
        )),
        Some(v) => Outcome::fail(format!(
            "{:?} at depth {}, prefix {:#x}: inputs {:#x}, {:#x} -> outputs {:#x}, {:#x}",
            v.kind, v.depth, v.prefix, v.inputs[0], v.inputs[1], v.outputs[0], v.outputs[1]
        )),
    }
}

/// `nested` in a base that is not a power of two: the probe inspector at the working width.
fn check_nested_radix(s: &dyn Scrambler, radix: Radix) -> Outcome {
    let width = working_width(s);
    let Ok(layout) = RadixLayout::new(width, radix) else {
        return Outcome::skipped(format!("no base-{} digit fits a word", radix.get()));
    };
    let batch = |words: &mut [u64]| s.scramble_batch(words, width, 0);
    let report = inspect_radix_probes(&batch, layout, NESTED_PROBES, PROBE_SEED);
    match report.first_violation {
        None => Outcome::pass(format!(
            "nested in base {} ({} nodes)",
            radix.get(),
            report.nodes_checked
        )),
        Some(v) => Outcome::fail(format!(
            "{:?} at depth {}, prefix {}: inputs {}, {} -> outputs {}, {}",
            v.kind, v.depth, v.prefix, v.inputs[0], v.inputs[1], v.outputs[0], v.outputs[1]
        )),
    }
}

fn check_nets(
    s: &dyn Scrambler,
    plan: &LevelPlan,
    max_dims: Option<u32>,
    own_base_only: bool,
) -> Outcome {
    let width = working_width(s);
    if !s.supports_width(width) {
        return Outcome::skipped("neither 32- nor 64-bit words");
    }
    let (verdict, detail) = crate::nets::check_nets(s, width, plan.level, max_dims, own_base_only);
    Outcome {
        verdict,
        detail,
        value: None,
    }
}

fn check_radix_nets(
    s: &dyn Scrambler,
    radix: Radix,
    plan: &LevelPlan,
    max_dims: Option<u32>,
) -> Outcome {
    let width = working_width(s);
    let (verdict, detail) =
        crate::radix_nets::check_radix_nets(s, width, radix, plan.level, max_dims);
    Outcome {
        verdict,
        detail,
        value: None,
    }
}

/// Bit-exact agreement with the twin on seeds 0..4, dimensions 0..8 and the plan's words each
/// (0, the largest word, and seeded random words).
fn check_twin(c: &Candidate, twin_name: &str, twin: &SeedBuilder, plan: &LevelPlan) -> Outcome {
    let words = plan.twin_words;
    let width = working_width(c.probe.as_ref());
    let tree = candidate_tree(c, width);
    let mut rng = SplitMix64::new(TWIN_SEED);
    let mut compared = 0u64;
    for seed in 0..4u64 {
        let (mine, theirs) = match (c.with_seed.as_ref()(seed), twin(seed)) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(e), _) | (_, Err(e)) => {
                return Outcome::fail(format!("cannot build seed {seed}: {e}"))
            }
        };
        if !theirs.supports_width(width) {
            return Outcome::fail(format!(
                "{twin_name} does not support {}-bit words",
                width.bits()
            ));
        }
        for dim in 0..usable_dims(c.max_dims, TWIN_DIMS) {
            let xs: Vec<u64> = (0..words)
                .map(|k| match k {
                    0 => 0,
                    1 => tree.largest_word(),
                    _ => tree.random_word(&mut rng),
                })
                .collect();
            // One batch each: an external or Python implementation answers one request.
            let (mut a, mut b) = (xs.clone(), xs.clone());
            mine.scramble_batch(&mut a, width, dim);
            theirs.scramble_batch(&mut b, width, dim);
            if let Some(k) = (0..xs.len()).find(|&k| a[k] != b[k]) {
                return Outcome::fail(format!(
                    "seed {seed}, dim {dim}, word {:#x}: got {:#x}, {twin_name} gives {:#x}",
                    xs[k], a[k], b[k]
                ));
            }
            compared += xs.len() as u64;
        }
    }
    Outcome::pass(format!(
        "bit-exact with {twin_name} on {compared} {}-bit words (seeds 0..4, dims 0..{})",
        width.bits(),
        usable_dims(c.max_dims, TWIN_DIMS)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checks_have_distinct_names_and_only_expect_follows_the_laws() {
        let mut names: Vec<&str> = STRUCTURE_CHECKS.iter().map(|c| c.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), STRUCTURE_CHECKS.len());
        let after: Vec<&str> = STRUCTURE_CHECKS
            .iter()
            .filter(|c| c.stage == Stage::AfterLaws)
            .map(|c| c.name)
            .collect();
        assert_eq!(after, ["expect"]);
    }

    /// A scrambler whose output depends on how often it was asked (a counter) or on a word's
    /// position in its request: the `function` check must fail each.
    struct Forgetful {
        calls: std::sync::atomic::AtomicU64,
        by_position: bool,
    }

    impl Scrambler for Forgetful {
        fn name(&self) -> String {
            "forgetful".into()
        }
        fn base(&self) -> gartowen_core::PowerOfTwoBase {
            gartowen_core::PowerOfTwoBase::B2
        }
        fn claim(&self) -> gartowen_core::Claim {
            gartowen_core::Claim::OWEN
        }
        fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 {
            let n = self
                .calls
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            (x ^ if self.by_position { 0 } else { n }) & width.mask()
        }
        fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
            for (k, w) in words.iter_mut().enumerate() {
                *w = self.scramble(*w, width, dim) ^ if self.by_position { k as u64 } else { 0 };
            }
        }
        fn inverse(&self) -> Option<&dyn gartowen_core::Unscramble> {
            Some(self)
        }
    }

    impl gartowen_core::Unscramble for Forgetful {
        fn unscramble(&self, y: u64, _width: Width, _dim: u32) -> u64 {
            y
        }
    }

    fn candidate(by_position: bool) -> Candidate<'static> {
        Candidate::from_builder(
            "forgetful",
            gartowen_core::Claim::OWEN,
            Box::new(move |_| {
                Ok(Box::new(Forgetful {
                    calls: 0.into(),
                    by_position,
                }) as Box<dyn Scrambler>)
            }),
        )
        .unwrap()
    }

    #[test]
    fn a_scramble_that_is_not_a_function_fails_and_a_real_one_passes() {
        let plan = crate::level::Level::Quick.plan();
        let counter = check_function(&candidate(false), plan);
        assert_eq!(counter.verdict, crate::verdict::Verdict::Fail);
        assert!(
            counter.detail.contains("in a second request"),
            "{}",
            counter.detail
        );
        let positional = check_function(&candidate(true), plan);
        assert_eq!(positional.verdict, crate::verdict::Verdict::Fail);
        assert!(
            positional.detail.contains("another position"),
            "{}",
            positional.detail
        );
        let real = Candidate::from_builder(
            "identity",
            gartowen_core::Claim::NESTED,
            Box::new(|_| Ok(Box::new(gartowen_core::Identity) as Box<dyn Scrambler>)),
        )
        .unwrap();
        assert_eq!(
            check_function(&real, plan).verdict,
            crate::verdict::Verdict::Pass
        );
    }
}
