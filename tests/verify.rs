//! `verify` passes the registry and fails each deliberately broken implementation on the check
//! it should: translation-only claimed as uniform (node-law), a non-nested hash (nested), and an
//! off-by-one keying whose node at depth k sees its own digit (nested). Claims decide what is
//! judged: the ART family claims marginal laws only, so its joint laws are measured.

use gartowen::core::registry::BuildContext;
use gartowen::core::Unscramble;
use gartowen::core::{
    mix64, Claim, CoreError, DigitLayout, PowerOfTwoBase, Registry, Scrambler, ScramblerRequest,
    ScramblerSpec, Width,
};
use gartowen::owen::{FullTreeOwen, OwenVariant};
use gartowen::verify::{verify, Level, Verdict};

/// Translation-only ART-Owen in base 16, but claiming nested uniformity.
struct FalseClaim(Box<dyn Scrambler>);
impl Scrambler for FalseClaim {
    fn name(&self) -> String {
        "broken-translation-claims-uniform".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        self.0.base()
    }
    fn claim(&self) -> Claim {
        Claim::OWEN
    }
    fn scramble(&self, x: u64, w: Width, d: u32) -> u64 {
        self.0.scramble(x, w, d)
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for FalseClaim {
    fn unscramble(&self, y: u64, w: Width, d: u32) -> u64 {
        self.0
            .inverse()
            .expect("the wrapped entry inverts")
            .unscramble(y, w, d)
    }
}

/// A bijective but non-nested hash: an odd multiplier and xor-shifts mix low bits upward.
struct NonNested(u64);
impl Scrambler for NonNested {
    fn name(&self) -> String {
        "broken-non-nested-hash".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    fn claim(&self) -> Claim {
        Claim::OWEN
    }
    fn scramble(&self, x: u64, w: Width, _d: u32) -> u64 {
        (x ^ (self.0 & w.mask())).wrapping_mul(0x9E37_79B9_7F4A_7C15 | 1) & w.mask()
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for NonNested {
    fn unscramble(&self, y: u64, w: Width, _d: u32) -> u64 {
        // Multiplicative inverse of the odd multiplier mod 2^64, then undo the xor.
        let mut inv: u64 = 1;
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(0x9E37_79B9_7F4A_7C15u64.wrapping_mul(inv)));
        }
        (y.wrapping_mul(inv) & w.mask()) ^ (self.0 & w.mask())
    }
}

/// The oracle's node maps keyed by k+1 digits (the node's own digit included): off by one.
struct OffByOne(FullTreeOwen);
impl Scrambler for OffByOne {
    fn name(&self) -> String {
        "broken-off-by-one-keying".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B4
    }
    fn claim(&self) -> Claim {
        Claim::OWEN
    }
    fn scramble(&self, x: u64, w: Width, d: u32) -> u64 {
        let l = DigitLayout::new(w, PowerOfTwoBase::B4);
        (0..l.num_digits()).fold(0, |y, k| {
            l.set(
                y,
                k,
                self.0
                    .node_permutation(w, d, k, l.prefix(x, k + 1))
                    .apply(l.get(x, k)),
            )
        })
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for OffByOne {
    fn unscramble(&self, y: u64, _w: Width, _d: u32) -> u64 {
        y // not invertible in general; the inverse check reports it too
    }
}

fn false_claim(_: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    Ok(Box::new(FalseClaim(
        gartowen::registry().build("art-owen-t4", ctx.seed)?,
    )))
}
fn non_nested(_: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    Ok(Box::new(NonNested(mix64(ctx.seed))))
}
fn off_by_one(_: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    Ok(Box::new(OffByOne(FullTreeOwen::new(
        PowerOfTwoBase::B4,
        OwenVariant::Uniform,
        ctx.seed,
    ))))
}

fn verdict(reports: &[gartowen::verify::ImplReport], name: &str, check: &str) -> Verdict {
    let r = reports.iter().find(|r| r.name == name).unwrap();
    r.checks.iter().find(|c| c.check == check).unwrap().verdict
}

#[test]
fn the_registry_passes_quick_verification() {
    let reports = verify(&gartowen::registry(), &[], Level::Quick).unwrap();
    assert_eq!(reports.len(), gartowen::registry().specs().len());
    for r in &reports {
        assert!(!r.failed(), "{}: {:?}", r.name, r.checks);
        assert_eq!(
            verdict(&reports, &r.name, "nested"),
            Verdict::Pass,
            "{}",
            r.name
        );
    }
    // Judged on what is claimed, measured otherwise.
    for (name, check, v) in [
        ("none", "node-law", Verdict::Measured),
        ("art-owen-t4:table=256", "node-law", Verdict::Pass),
        ("art-owen-16p:table=256", "node-law", Verdict::Pass),
        ("art-owen-16p:table=256", "pair-law", Verdict::Measured),
        ("art-owen-16p:table=256", "dimensions", Verdict::Pass),
        ("owen-oracle:uniform:base=2", "pair-law", Verdict::Pass),
        ("owen-oracle:uniform:base=2", "flip-rank", Verdict::Pass),
        ("owen-per-bit-hash", "collisions", Verdict::Pass),
        ("lk-hash", "flip-rank", Verdict::Measured),
    ] {
        assert_eq!(verdict(&reports, name, check), v, "{name} {check}");
    }
    // ART's finite table shows in the measured collision profile (nodes outnumber symbols).
    let art = reports
        .iter()
        .find(|r| r.name == "art-owen-16p:table=256")
        .unwrap();
    let collisions = &art
        .profile
        .iter()
        .find(|(f, _)| f == "collisions")
        .unwrap()
        .1;
    assert!(collisions.contains('x'), "{collisions}");
}

#[test]
fn broken_implementations_fail_the_check_they_should() {
    let mut registry = Registry::with_core();
    let spec = |name, base, build| ScramblerSpec {
        name,
        default_base: base,
        claim: Claim::OWEN,
        summary: "broken",
        build,
    };
    registry.add(spec(
        "broken-translation-claims-uniform",
        PowerOfTwoBase::B16,
        false_claim,
    ));
    registry.add(spec(
        "broken-non-nested-hash",
        PowerOfTwoBase::B2,
        non_nested,
    ));
    registry.add(spec(
        "broken-off-by-one-keying",
        PowerOfTwoBase::B4,
        off_by_one,
    ));
    let reports = verify(&registry, &[], Level::Quick).unwrap();
    assert_eq!(
        verdict(&reports, "broken-translation-claims-uniform", "node-law"),
        Verdict::Fail
    );
    assert_eq!(
        verdict(&reports, "broken-translation-claims-uniform", "nested"),
        Verdict::Pass
    );
    assert_eq!(
        verdict(&reports, "broken-non-nested-hash", "nested"),
        Verdict::Fail
    );
    assert_eq!(
        verdict(&reports, "broken-non-nested-hash", "inverse"),
        Verdict::Pass
    );
    assert_eq!(
        verdict(&reports, "broken-off-by-one-keying", "nested"),
        Verdict::Fail
    );
    let r = reports
        .iter()
        .find(|r| r.name == "broken-off-by-one-keying")
        .unwrap();
    assert!(
        r.checks.iter().any(|c| c.detail.contains("NotBijective")),
        "{:?}",
        r.checks
    );
    assert_eq!(verdict(&reports, "none", "nested"), Verdict::Pass);
}

#[test]
fn q_art_with_composed_linear_parts_passes_what_q_art_claims() {
    // Nested, invertible, nets in base 4, each node uniform over S_4 = AGL(2,2): the battery
    // judges the composed variant on Q-ART's own claim and finds no failure.
    let registry = gartowen::registry();
    let reports = gartowen::verify::verify(
        &registry,
        &["q-art-4:compose=linear".to_string()],
        gartowen::verify::Level::Quick,
    )
    .unwrap();
    let r = &reports[0];
    assert_eq!(r.claim, "marginal:symmetric");
    assert!(!r.failed(), "{:?}", r.checks);
    for check in ["inverse", "nested", "nets", "node-law", "pair-lemma"] {
        let c = r.checks.iter().find(|c| c.check == check).unwrap();
        assert_eq!(
            c.verdict,
            gartowen::verify::Verdict::Pass,
            "{check}: {}",
            c.detail
        );
    }
}
