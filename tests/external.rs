//! External implementations through the stdin/stdout protocol: the C examples under
//! `examples/external/` (a correct twin of `owen-per-bit-hash`, a broken non-nested hash, and
//! the imitations a digital shift and the LK hashes) and misbehaving children (crash, hang,
//! short and garbage replies). Needs a C compiler `cc`, which the Rust toolchain already
//! requires for linking.

use gartowen::core::{Claim, PowerOfTwoBase, Width};
use gartowen::external::{ExternalError, ExternalProcess};
use gartowen::verify::{check_candidate, external_candidate, Level, Verdict};
use std::path::PathBuf;
use std::process::Command;
use std::sync::{Arc, OnceLock};
use std::time::Duration;

/// Compiles the examples once per test binary: (owen_per_bit, broken_hash, digital_shift,
/// lk_hash, owen_nested).
fn examples() -> &'static (PathBuf, PathBuf, PathBuf, PathBuf, PathBuf) {
    static BUILT: OnceLock<(PathBuf, PathBuf, PathBuf, PathBuf, PathBuf)> = OnceLock::new();
    BUILT.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("gartowen-external-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples/external");
        let build = |name: &str| {
            let out = dir.join(name);
            let status = Command::new("cc")
                .args(["-O2", "-Wall", "-Werror", "-o"])
                .arg(&out)
                .arg(src.join(format!("{name}.c")))
                .status()
                .expect("a C compiler `cc` (the Rust toolchain needs one to link)");
            assert!(status.success(), "compiling {name}.c failed");
            out
        };
        (
            build("owen_per_bit"),
            build("broken_hash"),
            build("digital_shift"),
            build("lk_hash"),
            build("owen_nested"),
        )
    })
}

fn check<'a>(r: &'a gartowen::verify::ImplReport, name: &str) -> &'a gartowen::verify::CheckResult {
    r.checks.iter().find(|c| c.check == name).unwrap()
}

#[test]
fn a_true_owen_scramble_passes_every_check_in_bases_2_4_and_16_as_an_external_program() {
    for base in [PowerOfTwoBase::B2, PowerOfTwoBase::B4, PowerOfTwoBase::B16] {
        let p = ExternalProcess::spawn(
            examples().4.to_str().unwrap(),
            base,
            Width::W32,
            Duration::from_secs(10),
        )
        .unwrap();
        let c = external_candidate(Arc::new(p), 3, Claim::OWEN, None);
        let r = check_candidate(&c, Level::Quick, 1);
        for check in &r.checks {
            assert_eq!(
                check.verdict,
                Verdict::Pass,
                "base {} {check:?}",
                base.base()
            );
        }
    }
}

#[test]
fn imitations_claiming_owen_fail_the_joint_laws_as_external_programs() {
    let ex = examples();
    for (command, fails) in [
        (
            ex.2.display().to_string(),
            &["pair-law", "flip-rank", "pair-lemma"][..],
        ),
        (ex.3.display().to_string(), &["flip-rank"][..]),
        (format!("{} improved", ex.3.display()), &["flip-rank"][..]),
    ] {
        let p = spawn(&command, Width::W32, 10_000);
        let c = external_candidate(Arc::new(p), 0, Claim::OWEN, None);
        let r = check_candidate(&c, Level::Quick, 1);
        // Structure and single-node laws hold: the imitations are nested and fair node by node.
        for ok in ["injective", "nested", "nets", "node-law"] {
            assert_eq!(check(&r, ok).verdict, Verdict::Pass, "{command} {ok}");
        }
        for f in fails {
            let c = check(&r, f);
            assert_eq!(c.verdict, Verdict::Fail, "{command} {f}: {}", c.detail);
            assert!(
                c.detail.contains("depth") || c.detail.contains("r = "),
                "{}",
                c.detail
            );
        }
    }
}

fn spawn(command: &str, width: Width, timeout_ms: u64) -> ExternalProcess {
    ExternalProcess::spawn(
        command,
        PowerOfTwoBase::B2,
        width,
        Duration::from_millis(timeout_ms),
    )
    .unwrap()
}

#[test]
fn correct_example_passes_bit_exact_against_its_builtin_twin() {
    let registry = gartowen::registry();
    for width in [Width::W32, Width::W64] {
        let p = spawn(examples().0.to_str().unwrap(), width, 10_000);
        let c = external_candidate(
            Arc::new(p),
            7,
            Claim::OWEN,
            Some((&registry, "owen-per-bit-hash")),
        );
        let r = check_candidate(&c, Level::Quick, 1);
        let names: Vec<&str> = r.checks.iter().map(|c| c.check.as_str()).collect();
        assert_eq!(
            names,
            [
                "injective",
                "function",
                "nested",
                "nets",
                "node-law",
                "pair-law",
                "flip-rank",
                "collisions",
                "pair-lemma",
                "dimensions",
                "expect"
            ]
        );
        for check in &r.checks {
            assert_eq!(check.verdict, Verdict::Pass, "{width:?} {check:?}");
        }
        assert!(check(&r, "expect").detail.contains("bit-exact"));
    }
}

#[test]
fn expect_catches_a_twin_that_differs() {
    // The correct program is not lk-hash: the expect check must name the first differing word.
    let registry = gartowen::registry();
    let p = spawn(examples().0.to_str().unwrap(), Width::W32, 10_000);
    let c = external_candidate(Arc::new(p), 0, Claim::OWEN, Some((&registry, "lk-hash")));
    let r = check_candidate(&c, Level::Quick, 1);
    let expect = check(&r, "expect");
    assert_eq!(expect.verdict, Verdict::Fail);
    assert!(
        expect.detail.contains("seed 0, dim 0, word 0x0"),
        "{}",
        expect.detail
    );
}

#[test]
fn broken_example_is_rejected_naming_the_failing_node() {
    let p = spawn(examples().1.to_str().unwrap(), Width::W32, 10_000);
    let c = external_candidate(Arc::new(p), 0, Claim::OWEN, None);
    let r = check_candidate(&c, Level::Quick, 1);
    assert!(r.failed());
    // A bijection of words and a function, so injectivity holds; nestedness does not.
    assert_eq!(r.checks[0].verdict, Verdict::Pass);
    assert_eq!(
        (r.checks[1].check.as_str(), r.checks[1].verdict),
        ("function", Verdict::Pass)
    );
    let nested = &r.checks[2];
    assert_eq!(nested.verdict, Verdict::Fail);
    assert!(
        nested.detail.starts_with("NotNested at depth") && nested.detail.contains("prefix"),
        "{}",
        nested.detail
    );
    assert_eq!(r.checks[3].verdict, Verdict::Fail, "{}", r.checks[3].detail);
}

fn first_failure(command: &str, timeout_ms: u64) -> (ExternalError, u32) {
    let p = spawn(command, Width::W32, timeout_ms);
    let pid = p.pid();
    let e = p.scramble_batch(0, 0, &[1, 2, 3]).unwrap_err();
    assert_eq!(p.failure(), Some(e.clone()), "the session is poisoned");
    assert_eq!(
        p.scramble_batch(0, 0, &[1]).unwrap_err(),
        e,
        "no second exchange"
    );
    (e, pid)
}

#[test]
fn a_program_that_cannot_start_is_named() {
    let e = ExternalProcess::spawn(
        "/nonexistent/scrambler --fast",
        PowerOfTwoBase::B2,
        Width::W32,
        Duration::from_secs(1),
    )
    .err()
    .unwrap();
    assert!(
        matches!(&e, ExternalError::Spawn { program, .. } if program == "/nonexistent/scrambler")
    );
    assert!(e
        .to_string()
        .contains("cannot start '/nonexistent/scrambler'"));
}

#[test]
fn an_exiting_program_reports_its_status_and_stderr() {
    let (e, _) = first_failure("sh -c 'echo unsupported base >&2; exit 3'", 5000);
    let text = e.to_string();
    assert!(text.contains("exited with status 3"), "{text}");
    assert!(text.contains("unsupported base"), "{text}");
}

#[test]
fn a_crash_is_reported_with_its_signal() {
    let (e, _) = first_failure("sh -c 'head -c 32 >/dev/null; kill -SEGV $$'", 5000);
    assert!(e.to_string().contains("killed by signal 11"), "{e}");
}

#[test]
fn a_short_reply_is_reported_with_the_byte_counts() {
    // Magic, count 3, then 6 of the 12 word bytes, then exit.
    let (e, _) = first_failure(
        r"sh -c 'head -c 44 >/dev/null; printf GOWR; printf \\003\\000\\000\\000\\001\\002\\003\\004\\005\\006'",
        5000,
    );
    match &e {
        ExternalError::Exited {
            received, expected, ..
        } => assert_eq!((*received, *expected), (14, 20), "{e}"),
        other => panic!("expected an exit mid-reply, got {other}"),
    }
}

#[test]
fn garbage_replies_are_named() {
    let (e, _) = first_failure("sh -c 'head -c 44 >/dev/null; echo hello; sleep 5'", 5000);
    assert!(
        matches!(&e, ExternalError::Garbage { detail, .. } if detail.contains("\"hell\"")),
        "{e}"
    );
    // Right magic, wrong count.
    let (e, _) = first_failure(
        r"sh -c 'head -c 44 >/dev/null; printf GOWR\\002\\000\\000\\000; head -c 12 /dev/zero; sleep 5'",
        5000,
    );
    assert!(
        e.to_string().contains("reply count 2, the request had 3"),
        "{e}"
    );
}

fn running(marker: &str) -> bool {
    std::fs::read_dir("/proc").unwrap().flatten().any(|d| {
        std::fs::read(d.path().join("cmdline"))
            .map(|c| {
                String::from_utf8_lossy(&c)
                    .replace('\0', " ")
                    .contains(marker)
            })
            .unwrap_or(false)
    })
}

#[test]
fn a_hanging_program_times_out_and_nothing_is_left_running() {
    // The shell forks `sleep` as a grandchild: killing only the shell would leave it behind.
    let marker = "31.4159";
    let (e, pid) = first_failure(&format!("sh -c 'sleep {marker}; true'"), 300);
    assert!(
        matches!(
            e,
            ExternalError::Timeout {
                batch: 1,
                received: 0,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("was killed"));
    std::thread::sleep(Duration::from_millis(100));
    assert!(!running(marker), "the grandchild sleep survived");
    assert!(!std::path::Path::new(&format!("/proc/{pid}")).exists());
}

#[test]
fn a_dead_program_whose_helper_holds_its_pipes_is_named_as_dead_and_the_helper_killed() {
    // The helper leaves the process group with setsid and keeps stdin and stdout: the pipe
    // never reaches end of file, so the host once waited the whole timeout and reported a
    // hang. The program reads the request, then exits with 3.
    let marker = "27.1828";
    let (e, _) = first_failure(
        &format!(
            "sh -c 'setsid sh -c \"exec sleep {marker}\" <&0 & head -c 44 >/dev/null; exit 3'"
        ),
        60_000,
    );
    let text = e.to_string();
    assert!(
        matches!(e, ExternalError::Exited { batch: 1, .. }),
        "{text}"
    );
    assert!(text.contains("exited with status 3"), "{text}");
    assert!(text.contains("still held open by pid"), "{text}");
    let waited = std::time::Instant::now();
    while running(marker) && waited.elapsed() < Duration::from_secs(5) {
        std::thread::sleep(Duration::from_millis(20));
    }
    assert!(!running(marker), "the setsid helper survived");
}

#[test]
fn a_failing_program_fails_every_check_with_the_reason() {
    let p = spawn("sh -c 'exec sleep 30'", Width::W32, 200);
    let c = external_candidate(Arc::new(p), 0, Claim::OWEN, None);
    let r = check_candidate(&c, Level::Quick, 1);
    // Nothing was measured: every sub-test is not run, and the profile shows `?` where it
    // would have tested, never a deviation or a pass.
    assert!(!r.profile.is_empty());
    for (family, row) in &r.profile {
        assert!(
            row.contains('?') && !row.contains(['x', '.']),
            "{family} {row}"
        );
    }
    for check in &r.checks {
        assert!(
            check.p_value.is_none()
                && check
                    .tests
                    .iter()
                    .all(|t| t.not_run.as_deref() == Some("external program failed")
                        && t.p_value.is_nan()
                        && !t.deviates),
            "{}",
            check.check
        );
        assert_eq!(check.verdict, Verdict::Fail);
        assert!(
            check
                .detail
                .starts_with("external program failed: no complete reply to request 1"),
            "{}",
            check.detail
        );
    }
}

#[test]
fn a_well_behaved_program_exits_when_the_session_ends() {
    let p = spawn(examples().0.to_str().unwrap(), Width::W32, 10_000);
    let pid = p.pid();
    assert_eq!(p.scramble_batch(0, 0, &[0]).unwrap().len(), 1);
    drop(p);
    assert!(!std::path::Path::new(&format!("/proc/{pid}")).exists());
}

mod protocol_fuzz {
    use gartowen::core::{PowerOfTwoBase, Width};
    use gartowen::external::{
        decode_reply, decode_request, encode_request, ProtocolBase, RequestHeader,
    };
    use proptest::prelude::*;

    fn header(width64: bool, q: u32, dim: u32, seed: u64) -> RequestHeader {
        RequestHeader {
            width: if width64 { Width::W64 } else { Width::W32 },
            base: PowerOfTwoBase::from_q(q).unwrap().into(),
            dim,
            seed,
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        /// Decoders return a value or an error for any bytes; they never panic.
        #[test]
        fn decoders_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..128),
                                count in 0usize..20, width64 in any::<bool>()) {
            let _ = decode_request(&bytes);
            let w = if width64 { Width::W64 } else { Width::W32 };
            for b in [2u64, 3, 65_535] {
                let base = ProtocolBase::from_base(b).unwrap();
                if let Ok(words) = decode_reply(&bytes, count, w, base, 1) {
                    prop_assert_eq!(words.len(), count);
                    prop_assert_eq!(&bytes[..4], b"GOWR");
                    prop_assert!(words.iter().all(|&x| x <= base.largest_word(w)));
                }
            }
        }

        /// Encoding then decoding a request is the identity (words truncated to the width).
        #[test]
        fn requests_round_trip(width64 in any::<bool>(), q in 1u32..=8, dim in any::<u32>(),
                               seed in any::<u64>(),
                               words in proptest::collection::vec(any::<u64>(), 1..40)) {
            let h = header(width64, q, dim, seed);
            let words: Vec<u64> = words.iter().map(|w| w & h.width.mask()).collect();
            let (back, decoded) = decode_request(&encode_request(&h, &words).unwrap()).unwrap();
            prop_assert_eq!(back, h);
            prop_assert_eq!(decoded, words);
        }

        /// Version 2 frames (bases that are not powers of two) round-trip too, and carry
        /// version 2; the same bytes with version 1 are refused, as is version 2 naming a
        /// power of two.
        #[test]
        fn base_b_requests_round_trip_and_versions_match_their_bases(
            b in 3u32..=65_535, width64 in any::<bool>(), dim in any::<u32>(),
            seed in any::<u64>(), words in proptest::collection::vec(any::<u32>(), 1..40)) {
            prop_assume!(!b.is_power_of_two());
            let h = RequestHeader {
                width: if width64 { Width::W64 } else { Width::W32 },
                base: ProtocolBase::from_base(u64::from(b)).unwrap(),
                dim,
                seed,
            };
            let bound = h.base.largest_word(h.width) + 1;
            let words: Vec<u64> = words.into_iter().map(|w| u64::from(w) % bound).collect();
            let mut frame = encode_request(&h, &words).unwrap();
            prop_assert_eq!(&frame[4..6], &[2u8, 0][..]);
            let (back, decoded) = decode_request(&frame).unwrap();
            prop_assert_eq!(back, h);
            prop_assert_eq!(decoded, words.clone());
            frame[4] = 1;
            prop_assert!(decode_request(&frame).is_err());
            let q = b.ilog2().clamp(1, 8);
            let mut binary = encode_request(&header(width64, q, dim, seed), &words).unwrap();
            binary[4] = 2;
            prop_assert!(decode_request(&binary).is_err());
        }

        /// A version 2 word at or above b^m is refused on every side: the host's encoder, the
        /// child's decoder and the host's reply check (one such reply word once passed for
        /// another word's image).
        #[test]
        fn base_b_words_at_or_above_b_to_the_m_are_refused(
            b in 3u32..=65_535, width64 in any::<bool>(), at in 0usize..8, excess in 0u64..1000,
            words in proptest::collection::vec(any::<u32>(), 8)) {
            prop_assume!(!b.is_power_of_two());
            let h = RequestHeader {
                width: if width64 { Width::W64 } else { Width::W32 },
                base: ProtocolBase::from_base(u64::from(b)).unwrap(),
                dim: 0,
                seed: 1,
            };
            let largest = h.base.largest_word(h.width);
            let too_big = (largest + 1).saturating_add(excess) & h.width.mask();
            prop_assume!(too_big > largest);
            let mut words: Vec<u64> = words.into_iter().map(|w| u64::from(w) % (largest + 1)).collect();
            let good = encode_request(&h, &words).unwrap();
            words[at] = too_big;
            prop_assert!(encode_request(&h, &words).is_err());
            // The same frame with the bad word written in place.
            let wb = h.width.bits() as usize / 8;
            let mut frame = good.clone();
            let start = 32 + at * wb;
            frame[start..start + wb].copy_from_slice(&too_big.to_le_bytes()[..wb]);
            prop_assert!(decode_request(&frame).is_err());
            let mut reply = b"GOWR".to_vec();
            reply.extend_from_slice(&8u32.to_le_bytes());
            reply.extend_from_slice(&frame[32..]);
            let e = decode_reply(&reply, 8, h.width, h.base, 1).unwrap_err().to_string();
            prop_assert!(e.contains(&format!("reply word {at} is {too_big}")), "{}", e);
            reply[8 + at * wb..8 + (at + 1) * wb].copy_from_slice(&largest.to_le_bytes()[..wb]);
            prop_assert!(decode_reply(&reply, 8, h.width, h.base, 1).is_ok());
        }

        /// A corrupted header byte either is rejected or decodes to a frame that differs
        /// exactly in the corrupted field: the base (to another power of two), the dimension
        /// or the seed. (Fuzzing found the reserved field unchecked; it is now rejected.)
        #[test]
        fn corrupted_headers_are_caught(at in 0usize..32, flip in 1u8..=255,
                                        words in proptest::collection::vec(any::<u32>(), 1..8)) {
            let h = header(false, 1, 3, 99);
            let words: Vec<u64> = words.into_iter().map(u64::from).collect();
            let mut frame = encode_request(&h, &words).unwrap();
            frame[at] ^= flip;
            match decode_request(&frame) {
                Err(_) => {}
                Ok((h2, w2)) => {
                    prop_assert!((8..16).contains(&at) || (24..32).contains(&at), "byte {} accepted", at);
                    prop_assert_eq!(w2, words);
                    prop_assert_eq!(h2.width, h.width);
                    prop_assert_eq!(h2.base == h.base, !(8..12).contains(&at));
                    prop_assert_eq!(h2.dim == h.dim, !(12..16).contains(&at));
                    prop_assert_eq!(h2.seed == h.seed, !(24..32).contains(&at));
                }
            }
        }
    }
}

/// A timeout past what `Instant` can add (once a panic in the reply wait, with the child
/// left running) waits like a very long one: the answer comes back.
#[test]
fn an_enormous_timeout_does_not_panic() {
    let p = ExternalProcess::spawn(
        examples().0.to_str().unwrap(),
        PowerOfTwoBase::B2,
        Width::W32,
        Duration::from_secs(u64::MAX),
    )
    .unwrap();
    let out = p.scramble_batch(1, 0, &[0, 1, 2]).unwrap();
    assert_eq!(out.len(), 3);
    let s = gartowen::registry().build("owen-per-bit-hash", 1).unwrap();
    assert_eq!(out[2], s.scramble(2, Width::W32, 0));
}

#[test]
fn a_pool_of_instances_sweeps_exactly_as_one_instance_and_the_32_bit_frames_match_64_bit_ones() {
    use gartowen::core::Scrambler;
    use gartowen::external::ExternalScrambler;
    use gartowen::external_pool::ExternalPool;
    use gartowen::word_sweep::{sweep, SweepPlan};
    let spawn = || {
        Arc::new(
            ExternalProcess::spawn(
                examples().3.to_str().unwrap(),
                PowerOfTwoBase::B2,
                Width::W32,
                Duration::from_secs(10),
            )
            .unwrap(),
        )
    };
    let pool = ExternalPool::new(vec![spawn(), spawn()], 4, Claim::NESTED);
    let single = ExternalScrambler::new(spawn(), 4, Claim::NESTED);
    assert_eq!(pool.len(), 2);
    let plan = SweepPlan::new(Width::W32, PowerOfTwoBase::B2).unwrap();
    let a = sweep(&pool, &plan, 3, 100..104, &|_| {}).unwrap();
    let b = sweep(&single, &plan, 3, 100..104, &|_| {}).unwrap();
    assert_eq!(a, b);
    assert!(a.failure.is_none() && a.words == 4 << 20);
    assert!(pool.failure().is_none());
    // The in-place 32-bit path answers as the 64-bit one, word for word.
    let mut narrow: Vec<u32> = (0..5000u32).map(|k| k.wrapping_mul(0x9e37_79b9)).collect();
    let mut wide: Vec<u64> = narrow.iter().map(|&x| x as u64).collect();
    single.scramble_batch_u32(&mut narrow, 7);
    single.scramble_batch(&mut wide, Width::W32, 7);
    assert!(narrow.iter().zip(&wide).all(|(&n, &w)| n as u64 == w));
    // The broken hash is caught by a pool too.
    let broken = ExternalPool::new(
        vec![Arc::new(
            ExternalProcess::spawn(
                examples().1.to_str().unwrap(),
                PowerOfTwoBase::B2,
                Width::W32,
                Duration::from_secs(10),
            )
            .unwrap(),
        )],
        0,
        Claim::NESTED,
    );
    let piece = sweep(&broken, &plan, 0, 0..1, &|_| {}).unwrap();
    assert!(piece.failure.is_some());
}

#[test]
fn a_32_bit_frame_is_refused_by_a_64_bit_session_and_after_a_failure_words_become_zero() {
    let p = ExternalProcess::spawn(
        examples().0.to_str().unwrap(),
        PowerOfTwoBase::B2,
        Width::W64,
        Duration::from_secs(10),
    )
    .unwrap();
    let mut words = [1u32, 2, 3];
    assert!(matches!(
        p.scramble_batch_u32(0, 0, &mut words),
        Err(ExternalError::BadRequest(_))
    ));
    assert!(matches!(
        p.scramble_batch_u32(0, 0, &mut []),
        Err(ExternalError::BadRequest(_))
    ));
    // A refused request does not poison the session.
    assert!(p.failure().is_none());
    let dead = Arc::new(
        ExternalProcess::spawn(
            "/bin/false",
            PowerOfTwoBase::B2,
            Width::W32,
            Duration::from_secs(10),
        )
        .unwrap(),
    );
    let s = gartowen::external::ExternalScrambler::new(dead.clone(), 0, Claim::NESTED);
    let mut words = [5u32, 6, 7];
    gartowen::core::Scrambler::scramble_batch_u32(&s, &mut words, 0);
    assert_eq!(words, [0, 0, 0]);
    assert!(dead.failure().is_some());
}

#[test]
fn equivalence_to_owen_passes_a_true_owen_program_and_fails_a_digital_shift() {
    // The check a user runs with `verify --external … --equivalent-to owen`: the C Owen
    // scramble (keyed differently from the oracle) is equivalent within ±10% in base 16; the
    // digital shift's coordinate mean is not (fixed seeds 0..4000, α = 0.05).
    use gartowen::battery::owen_equivalence::check_equivalent_to_owen;
    let ex = examples();
    for (command, base, pass) in [
        (ex.4.display().to_string(), PowerOfTwoBase::B16, true),
        (ex.2.display().to_string(), PowerOfTwoBase::B2, false),
    ] {
        let p =
            ExternalProcess::spawn(&command, base, Width::W64, Duration::from_secs(10)).unwrap();
        let c = external_candidate(Arc::new(p), 0, Claim::OWEN, None);
        let r = check_equivalent_to_owen(c.with_seed.as_ref(), base, Width::W64, 4000, 0.1);
        let want = if pass { Verdict::Pass } else { Verdict::Fail };
        assert_eq!(r.verdict, want, "{command}: {}", r.detail);
        assert!(r.detail.contains("4000 seeds"), "{}", r.detail);
        if !pass {
            assert!(r.detail.contains("mean dim 0: ratio"), "{}", r.detail);
            assert!(r.detail.contains("different"), "{}", r.detail);
        }
    }
}
