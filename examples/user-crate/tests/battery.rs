//! The samplers gated by the gartowen battery from `cargo test`.

use gartowen::testing::{Base, Battery, Claim, Level, TestScrambler, Width};
use gartowen_example_user::{DigitalShift, PerBitOwen};

struct Owen(PerBitOwen);
impl TestScrambler for Owen {
    fn scramble(&self, word: u64, dim: u32) -> u64 {
        self.0.scramble(word as u32, dim) as u64
    }
}

struct Shift(DigitalShift);
impl TestScrambler for Shift {
    fn scramble(&self, word: u64, dim: u32) -> u64 {
        self.0.scramble(word as u32, dim) as u64
    }
}

#[test]
fn per_bit_owen_is_an_owen_scramble() {
    Battery::new(Base::B2, Width::W32)
        .claims(Claim::OWEN)
        .level(Level::Quick)
        .assert(|seed| Owen(PerBitOwen::new(seed)));
}

/// This is the test a renderer would write and see fail: the panic names the failing check.
#[test]
#[should_panic(expected = "FAIL pair-law: deviation")]
fn a_digital_shift_claiming_owen_fails_the_pair_law() {
    Battery::new(Base::B2, Width::W32)
        .claims(Claim::OWEN)
        .assert(|seed| Shift(DigitalShift::new(seed)));
}

#[test]
fn a_digital_shift_claiming_only_marginal_translations_passes() {
    let report = Battery::new(Base::B2, Width::W32)
        .claims(Claim::marginal(gartowen::testing::NodeGroup::Translation))
        .name("digital shift")
        .run(|seed| Shift(DigitalShift::new(seed)));
    assert!(
        !report.failed(),
        "{}",
        gartowen::testing::failure_text(&report)
    );
    // ...while its joint laws are measured, and show it departs from depth 1 on.
    let pair = report
        .profile
        .iter()
        .find(|(f, _)| f == "pair-law")
        .unwrap();
    assert!(pair.1.starts_with("-x"), "{}", pair.1);
}
