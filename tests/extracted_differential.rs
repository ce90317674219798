//! The machine link between the Coq theories and the Rust code: the ART word loop
//! (`proofs/ArtWord.v`), the nested-scramble action and the box count (`proofs/Nested.v`),
//! extracted to OCaml (`proofs/Extract.v`, driver `proofs/extracted/driver.ml`, built by
//! `proofs/extract.sh`), recompute what the Rust code computes, bit for bit:
//! - every ART variant's production scramble (`Scrambler::scramble` and `scramble_batch`) on
//!   the same tables, roots, dimension shifts and words: every word at widths 8..=12 (partial
//!   tail digits for q = 3, 5, 6, 7, 8), sampled 32- and 64-bit words;
//! - the explicit-tree bridge: `node_permutation` along a word's path, composed by Coq's
//!   action, gives the Rust scramble;
//! - the netcheck counting path's histograms of box counts against Coq's `count` on every box.
//!
//! And the comparison must FAIL for mutated Rust loops (a code bit stuck at 0, a tail digit
//! left untranslated), which shows the test can see a defect in the loop.
//!
//! Needs `coqc` and `ocamlopt` (Debian's coq); without them the test fails with a message,
//! unless `GARTOWEN_SKIP_PROOFS=1` asks to skip (loudly), as `proofs/check.sh` does.

use gartowen::art::{ArtMutant, ArtOwen, ArtVariant, TailUntranslated};
use gartowen::core::{DigitLayout, PowerOfTwoBase, Scrambler, SplitMix64, Width};
use gartowen::netcheck::counting::histograms;
use gartowen::netcheck::{CheckBase, PointSet};
use gartowen::seq::SequenceKind;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;

/// The differential driver, built once per test run by `proofs/extract.sh` (the checker's
/// test shares it); `None` when `GARTOWEN_SKIP_PROOFS=1` and it cannot be built.
pub(crate) fn driver() -> Option<PathBuf> {
    static DRIVER: OnceLock<Option<PathBuf>> = OnceLock::new();
    DRIVER.get_or_init(build_driver).clone()
}

fn build_driver() -> Option<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = root.join("target").join("extracted");
    let status = Command::new(root.join("proofs").join("extract.sh"))
        .arg(&out)
        .status();
    match status {
        Ok(s) if s.success() => Some(out.join("driver")),
        _ if std::env::var("GARTOWEN_SKIP_PROOFS").as_deref() == Ok("1") => {
            eprintln!("######## WARNING: the extracted driver could not be built and GARTOWEN_SKIP_PROOFS=1: the differential test was NOT run ########");
            None
        }
        other => panic!(
            "proofs/extract.sh failed ({other:?}): it needs coqc and ocamlopt (Debian's coq); \
             set GARTOWEN_SKIP_PROOFS=1 to skip loudly"
        ),
    }
}

/// Runs the driver on `input`; returns (success, stdout, stderr).
pub(crate) fn run_driver(driver: &Path, input: &str) -> (bool, String, String) {
    let mut child = Command::new(driver)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the driver starts");
    // Written from a thread of its own: the driver answers as it reads, and an answer larger
    // than the pipe's buffer would block it while this side still writes.
    let mut stdin = child.stdin.take().unwrap();
    let input = input.to_owned();
    let writer = std::thread::spawn(move || stdin.write_all(input.as_bytes()));
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap().expect("the driver reads its input");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The table section of one scrambler (tables of `tables`, outputs of `outputs`: the same
/// scrambler, or a mutant of it for the negative controls).
fn art_section(
    out: &mut String,
    tables: &ArtOwen,
    outputs: &dyn Scrambler,
    words: &[(Width, u32, u64)],
) {
    let q = tables.variant().q();
    let b = 1u32 << q;
    let symbols = tables.grammar().symbols();
    // One section per width (the driver's section carries W).
    let mut widths: Vec<u32> = words.iter().map(|w| w.0.bits()).collect();
    widths.dedup();
    for bits in widths {
        let psi = tables.psi_images();
        writeln!(
            out,
            "art {q} {bits} {symbols} {}",
            u8::from(!psi.is_empty())
        )
        .unwrap();
        out.push_str("child");
        for s in 0..symbols {
            for d in 0..b {
                write!(out, " {}", tables.grammar().child(s, d)).unwrap();
            }
        }
        out.push('\n');
        if !psi.is_empty() {
            out.push_str("psi");
            for v in psi {
                write!(out, " {v}").unwrap();
            }
            out.push('\n');
        }
        out.push_str("codes");
        for c in tables.codes() {
            write!(out, " {c:x}").unwrap();
        }
        out.push('\n');
        let group: Vec<&(Width, u32, u64)> = words.iter().filter(|w| w.0.bits() == bits).collect();
        // The batch path on the same words: the driver checks both outputs.
        let mut batch: Vec<u64> = group.iter().map(|w| w.2).collect();
        for (i, &&(width, dim, x)) in group.iter().enumerate() {
            let y = outputs.scramble(x, width, dim);
            if i == 0 || group[i - 1].1 != dim {
                let end = group[i..].iter().take_while(|w| w.1 == dim).count();
                outputs.scramble_batch(&mut batch[i..i + end], width, dim);
            }
            let (a, d) = tables.dimension_shifts(dim, width);
            let root = tables.root(dim);
            writeln!(out, "word {root} {a:x} {d:x} {x:x} {y:x} {:x}", batch[i]).unwrap();
        }
        out.push_str("end\n");
    }
}

/// Words of one scrambler: every word at widths 8..=12 (dimensions 0 and 1), 300 sampled
/// 32-bit and 100 sampled 64-bit words (dimensions 0, 1, 5).
fn words_for(seed: u64) -> Vec<(Width, u32, u64)> {
    let mut v = Vec::new();
    for bits in 8..=12u32 {
        let w = Width::new(bits).unwrap();
        for dim in 0..2 {
            v.extend((0..1u64 << bits).map(|x| (w, dim, x)));
        }
    }
    let mut rng = SplitMix64::new(seed);
    for (w, n) in [(Width::W32, 300), (Width::W64, 100)] {
        for dim in [0, 1, 5] {
            v.extend((0..n).map(|_| (w, dim, rng.next_u64() & w.mask())));
        }
    }
    v
}

/// One `act` line: the node maps along x's path, reconstructed from outputs alone (at depth k
/// the image of digit d is digit k of the output for x's first k digits, then d, then a tail
/// drawn afresh), x's digits and its Rust output's. The extracted nested scramble built from
/// these maps reproduces the output only if every node's map depends on its prefix alone
/// (prefix keying): the maps are not read from the implementation, so nothing is compared
/// with itself.
fn act_section(
    out: &mut String,
    s: &dyn Scrambler,
    q: u32,
    width: Width,
    dim: u32,
    x: u64,
    rng: &mut SplitMix64,
) {
    let layout = DigitLayout::new(width, PowerOfTwoBase::from_q(q).unwrap());
    let k = layout.num_digits();
    let y = s.scramble(x, width, dim);
    write!(out, "act {k}").unwrap();
    for depth in 0..k {
        let size = 1u32 << layout.digit_bits(depth);
        let tail = rng.next_u64() & width.mask();
        write!(out, " {size}").unwrap();
        for d in 0..size {
            let mut w = tail;
            for j in 0..depth {
                w = layout.set(w, j, layout.get(x, j));
            }
            w = layout.set(w, depth, d);
            write!(out, " {}", layout.get(s.scramble(w, width, dim), depth)).unwrap();
        }
    }
    for depth in 0..k {
        write!(out, " {}", layout.get(x, depth)).unwrap();
    }
    for depth in 0..k {
        write!(out, " {}", layout.get(y, depth)).unwrap();
    }
    out.push('\n');
}

/// A bijection that is not prefix-keyed: `inner`, then the top bit flipped when the input's
/// lowest bit is set (the root's map depends on the tail).
struct TailKeyed(ArtOwen);

impl Scrambler for TailKeyed {
    fn name(&self) -> String {
        "tail-keyed".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        self.0.base()
    }
    fn claim(&self) -> gartowen::core::Claim {
        self.0.claim()
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.0.scramble(x, width, dim) ^ ((x & 1) << (width.bits() - 1))
    }
}

fn net_section(out: &mut String, points: &PointSet, q: u32, m: u32) {
    let base = CheckBase::new(1 << q).unwrap();
    let bits = points.width().bits();
    let n = bits / q;
    writeln!(
        out,
        "net {} {} {n} {}",
        1u32 << q,
        points.dims(),
        points.len()
    )
    .unwrap();
    for i in 0..points.len() {
        out.push_str("pt");
        for x in points.point(i) {
            for k in 0..n {
                write!(out, " {}", (x >> (bits - q * (k + 1))) & ((1 << q) - 1)).unwrap();
            }
        }
        out.push('\n');
    }
    for h in histograms(points, base, m, 0).unwrap() {
        out.push_str("shape");
        for l in &h.shape {
            write!(out, " {l}").unwrap();
        }
        write!(out, " {}", h.boxes_by_count.len()).unwrap();
        for (c, boxes) in &h.boxes_by_count {
            write!(out, " {c} {boxes}").unwrap();
        }
        out.push('\n');
    }
    out.push_str("endnet\n");
}

#[test]
fn extracted_coq_code_agrees_with_the_rust_code_and_sees_mutants() {
    let Some(driver) = driver() else { return };
    let mut input = String::new();
    let variants = ArtVariant::all();
    let mut n_words = 0;
    for (i, &v) in variants.iter().enumerate() {
        let s = ArtOwen::new(v, 256, 7 + i as u64).unwrap();
        let words = words_for(i as u64);
        n_words += words.len();
        art_section(&mut input, &s, &s, &words);
        for bits in [12, 32] {
            let w = Width::new(bits).unwrap();
            let mut rng = SplitMix64::new(100 + i as u64);
            for dim in [0, 3] {
                for _ in 0..20 {
                    let x = rng.next_u64() & w.mask();
                    act_section(&mut input, &s, v.q(), w, dim, x, &mut rng);
                }
            }
        }
    }
    // Box counts: scrambled Sobol nets (every box full) and pseudo-random words (varied counts).
    let seq = SequenceKind::Sobol
        .build(3, Width::new(12).unwrap())
        .unwrap();
    let art = ArtOwen::new(ArtVariant::ArtOwen2, 256, 3).unwrap();
    let sobol = PointSet::from_sequence(&seq, &[0, 1, 2], 256, |x, j| {
        art.scramble(x, seq.width(), j as u32)
    })
    .unwrap();
    let mut rng = SplitMix64::new(11);
    let rows: Vec<Vec<u64>> = (0..256)
        .map(|_| (0..3).map(|_| rng.next_u64() & 0xfff).collect())
        .collect();
    let random = PointSet::from_rows(Width::new(12).unwrap(), &rows).unwrap();
    for points in [&sobol, &random] {
        for (q, m) in [(1, 8), (2, 4), (4, 2)] {
            net_section(&mut input, points, q, m);
        }
    }
    input.push_str("done\n");
    let (ok, stdout, stderr) = run_driver(&driver, &input);
    eprintln!("{stdout}{stderr}");
    assert!(
        ok,
        "the extracted code disagrees with the Rust code:\n{stderr}"
    );
    let arts = stdout.lines().filter(|l| l.starts_with("art ")).count();
    assert!(arts >= variants.len() * 7, "{stdout}");
    assert!(
        stdout.contains(&format!("act: {} words", variants.len() * 80)),
        "{stdout}"
    );
    assert_eq!(stdout.lines().filter(|l| l.starts_with("net ")).count(), 6);
    assert!(n_words > 100_000);

    // Negative controls: the real tables, the mutated loop's outputs.
    // q = 3 with random codes in every field: partial tail digits at 8, 10, 11, 32, 64 bits.
    let v = ArtVariant::Translation(3);
    let real = ArtOwen::new(v, 256, 5).unwrap();
    let mutants: [(&str, Box<dyn Scrambler>); 2] = [
        (
            "StuckCodeBit",
            Box::new(ArtOwen::with_mutant(v, 256, 5, ArtMutant::StuckCodeBit).unwrap()),
        ),
        ("TailUntranslated", Box::new(TailUntranslated(real.clone()))),
    ];
    // Prefix keying: a map of the root that depends on the tail is seen by the act section.
    let mut input = String::new();
    let mut rng = SplitMix64::new(9);
    let tail_keyed = TailKeyed(real.clone());
    for _ in 0..20 {
        let x = rng.next_u64() & Width::W32.mask();
        act_section(&mut input, &tail_keyed, 3, Width::W32, 0, x, &mut rng);
    }
    input.push_str("done\n");
    let (ok, stdout, _) = run_driver(&driver, &input);
    assert!(!ok, "a tail-keyed root went unseen:\n{stdout}");
    for (mutant, bad) in &mutants {
        let mut input = String::new();
        art_section(&mut input, &real, bad.as_ref(), &words_for(1));
        input.push_str("done\n");
        let (ok, stdout, _) = run_driver(&driver, &input);
        assert!(!ok, "{mutant} went unseen:\n{stdout}");
        let mismatches: usize = stdout
            .lines()
            .find_map(|l| l.strip_prefix("mismatches "))
            .and_then(|n| n.parse().ok())
            .unwrap();
        assert!(mismatches > 1000, "{mutant}: only {mismatches} mismatches");
    }
}
