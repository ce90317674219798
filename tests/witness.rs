//! `check --witness` re-checked by the checker extracted from `proofs/Witness.v`
//! (`revalidate_sound`): the witnesses the Rust checker writes are accepted, and every
//! tampered one (a smaller t-value, a wrong count, a moved box, a changed word, a false
//! "holds") is rejected, in bases 2, 3 and 16.

use crate::extracted_differential::driver;
use gartowen::core::Width;
use gartowen::netcheck::witness::{net_witness, NetWitness, WitnessClaim};
use gartowen::netcheck::{CheckBase, PointSet};
use gartowen::seq::radix::faure_prime;
use gartowen::seq::SequenceKind;
use std::path::Path;
use std::process::Command;

/// The re-checker's exit code and output on `text`.
fn revalidate(bin: &Path, text: &str, name: &str) -> (i32, String) {
    let dir = std::env::temp_dir().join(format!("gartowen-witness-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(name);
    std::fs::write(&file, text).unwrap();
    let out = Command::new(bin).arg(&file).output().unwrap();
    let _ = std::fs::remove_file(&file);
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    (out.status.code().unwrap_or(-1), text)
}

fn text(w: &NetWitness) -> String {
    let mut out = Vec::new();
    w.write(&mut out).unwrap();
    String::from_utf8(out).unwrap()
}

fn sequence(kind: SequenceKind, dims: usize, n: u64) -> PointSet {
    let seq = kind.build(dims, Width::W32).unwrap();
    let rows: Vec<Vec<u64>> = (0..n)
        .map(|i| (0..dims).map(|j| seq.point(i, j)).collect())
        .collect();
    PointSet::from_rows(Width::W32, &rows).unwrap()
}

/// The Faure net of p^m points in a prime base p, as 32-bit words ⌈v·2^32/p^m⌉.
fn faure(p: u64, m: u32, dims: usize) -> PointSet {
    let count = p.pow(m);
    let fr = faure_prime(p, count, dims).unwrap();
    let rows: Vec<Vec<u64>> = fr
        .chunks(dims)
        .map(|pt| {
            pt.iter()
                .map(|f| ((f.numer as u128) << 32).div_ceil(f.denom as u128) as u64)
                .collect()
        })
        .collect();
    PointSet::from_rows(Width::W32, &rows).unwrap()
}

/// The witness text with its `claim` line (and box line) replaced.
fn with_claim(text: &str, claim: &str) -> String {
    let mut out = Vec::new();
    let mut lines = text.lines();
    for line in lines.by_ref() {
        if line.starts_with("claim ") {
            out.push(claim.to_string());
            break;
        }
        out.push(line.to_string());
    }
    out.extend(
        lines
            .skip_while(|l| l.starts_with("box "))
            .map(str::to_string),
    );
    out.join("\n") + "\n"
}

/// Line `k` after `words` with its first word's lowest digit of the box prefix flipped.
fn with_word(text: &str, point: usize, word: u32) -> String {
    let mut out: Vec<String> = text.lines().map(str::to_string).collect();
    let at = out.iter().position(|l| l == "words").unwrap() + 1 + point;
    let mut fields: Vec<String> = out[at].split(' ').map(str::to_string).collect();
    fields[0] = format!("{word:x}");
    out[at] = fields.join(" ");
    out.join("\n") + "\n"
}

fn box_line(f: &gartowen::netcheck::BoxFailure, count: u64) -> String {
    let join = |v: Vec<String>| v.join(" ");
    format!(
        "box {} {} count {count}",
        join(f.shape.iter().map(|d| d.to_string()).collect()),
        join(f.box_index.iter().map(|a| a.to_string()).collect())
    )
}

#[test]
fn witnesses_are_re_checked_by_the_extracted_checker_and_tampered_ones_rejected() {
    // The 16-D net of 256 points has 136 shapes of 256 boxes for the model to count; the
    // large tier's twin below takes the net of 4096 points (816 shapes of 4096 boxes, 12 s).
    re_check_witnesses(sequence(SequenceKind::Sz16, 16, 1 << 8));
}

#[test]
#[ignore = "large tier (scripts/test-large.sh): the 16-D net of 4096 points, 12 s"]
fn witnesses_of_a_16_dimensional_net_of_4096_points_are_re_checked() {
    re_check_witnesses(sequence(SequenceKind::Sz16, 16, 1 << 12));
}

/// Witnesses of `sz16` (a net in base 16), a Sobol set (t > 0) and a Faure net in base 3,
/// re-checked by the extracted checker, and tampered ones rejected.
fn re_check_witnesses(sz16: PointSet) {
    let Some(driver) = driver() else { return };
    let bin = driver.with_file_name("revalidate");
    let cases: Vec<(&str, PointSet, u64)> = vec![
        ("sz16", sz16, 16),
        ("sobol5", sequence(SequenceKind::Sobol, 5, 1 << 8), 2),
        ("faure3", faure(3, 4, 3), 3),
    ];
    let mut positive_t = 0;
    for (name, points, b) in cases {
        let base = CheckBase::new(b).unwrap();
        // The t-value and its witness.
        let w = net_witness(&points, base, None, None).unwrap();
        let WitnessClaim::TValue { t, below } = w.claim.clone() else {
            panic!("{name}: a t-value claim")
        };
        let good = text(&w);
        let (rc, out) = revalidate(&bin, &good, name);
        assert_eq!(rc, 0, "{name}: the t-value witness must re-check: {out}");
        assert!(out.contains(&format!("t-value {t}")), "{out}");
        // A smaller t-value is rejected whatever box comes with it.
        if let Some(f) = &below {
            positive_t += 1;
            let smaller = with_claim(
                &good,
                &format!("claim tvalue {}\n{}", t - 1, box_line(f, f.count)),
            );
            assert_eq!(
                revalidate(&bin, &smaller, name).0,
                1,
                "{name}: t-value {}",
                t - 1
            );
            let wrong_count = with_claim(
                &good,
                &format!("claim tvalue {t}\n{}", box_line(f, f.count + 1)),
            );
            assert_eq!(
                revalidate(&bin, &wrong_count, name).0,
                1,
                "{name}: count + 1"
            );
            // The failing box at t − 1 is itself a "fails" witness.
            let fails = with_claim(
                &good,
                &format!("claim fails {}\n{}", t - 1, box_line(f, f.count)),
            );
            assert_eq!(
                revalidate(&bin, &fails, name).0,
                0,
                "{name}: fails at t − 1"
            );
            let holds = with_claim(&good, &format!("claim holds {}", t - 1));
            assert_eq!(
                revalidate(&bin, &holds, name).0,
                1,
                "{name}: holds at t − 1"
            );
        } else {
            let holds = with_claim(&good, "claim holds 0");
            assert_eq!(revalidate(&bin, &holds, name).0, 0, "{name}: holds at 0");
        }
        // Moving one point into another point's box breaks the net at t: the old witness no
        // longer re-checks, and the Rust checker's "fails" witness for the moved set does.
        let first = points.point(0)[0] as u32;
        let moved_word = first ^ 0x8000_0000;
        let moved = with_word(&good, 0, moved_word);
        assert_eq!(revalidate(&bin, &moved, name).0, 1, "{name}: a moved point");
        let mut broken = points.clone();
        broken.set(0, 0, moved_word as u64);
        let wf = net_witness(&broken, base, None, Some(t)).unwrap();
        let WitnessClaim::Fails { failure, .. } = &wf.claim else {
            panic!("{name}: the moved set fails at t = {t}")
        };
        let fails_text = text(&wf);
        assert_eq!(
            revalidate(&bin, &fails_text, name).0,
            0,
            "{name}: fails witness"
        );
        // A box holding exactly b^t is no failure; a box index past b^d is no box.
        let mut fine = failure.clone();
        fine.count = base.pow(t).unwrap();
        let (rc, _) = revalidate(
            &bin,
            &with_claim(
                &fails_text,
                &format!("claim fails {t}\n{}", box_line(failure, fine.count)),
            ),
            name,
        );
        assert_eq!(rc, 1, "{name}: a box of b^t points");
        let mut outside = failure.clone();
        let j = outside.shape.iter().position(|&d| d > 0).unwrap();
        outside.box_index[j] += base.pow(outside.shape[j]).unwrap();
        let (rc, _) = revalidate(
            &bin,
            &with_claim(
                &fails_text,
                &format!("claim fails {t}\n{}", box_line(&outside, failure.count)),
            ),
            name,
        );
        assert_eq!(rc, 1, "{name}: a box index past b^d");
    }
    assert!(
        positive_t >= 1,
        "a case with t > 0 exercises the box at t − 1"
    );
    // Malformed input is refused with exit 2, not judged.
    let (rc, out) = revalidate(
        &bin,
        "gartowen-witness 1\nbase 2 width 40 dims 1 m 1 points 2\n",
        "bad",
    );
    assert_eq!(rc, 2, "{out}");
}
