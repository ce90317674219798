//! The counting net checker of `crates/netcheck` against its Coq model (`proofs/Checker.v`,
//! proved there to decide `is_net` and `is_sequence` and to return the least t), extracted to
//! OCaml and run by the differential driver on the same point sets. Every verdict, t-value,
//! first failing shape and box, box count and counter of the reports must agree, on:
//! - every ordered 4-point set of 2-digit points in [0,1)² in base 2, every 3-point set of
//!   1-digit points in [0,1)² in base 3, every 4-point set of 1-digit points in [0,1)² in
//!   base 4 (exhaustive: the net checks, the t-value and the sequence checks of each);
//! - Sobol nets in bases 2, 4 and 16, Faure nets in bases 3 and 5, Hammersley nets in base 3
//!   and 5, each also with one digit broken, and pseudo-random sets, in 1 to 5 dimensions;
//! - the boundaries: one point (m = 0), t = m, one dimension, the largest digits.
//!
//! And checkers with a seeded defect (the last shape skipped; the t search off by one at either
//! end) must disagree with the model on this corpus.

use crate::extracted_differential::{driver, run_driver};
use gartowen::core::{SplitMix64, Width};
use gartowen::netcheck::counting::{
    check_net, check_net_owned, check_net_per_shape, check_sequence, t_value, BoxFailure,
    NetReport, SequenceReport,
};
use gartowen::netcheck::{CheckBase, PointSet};
use gartowen::seq::radix::faure_prime;
use gartowen::seq::SequenceKind;
use rayon::prelude::*;
use std::fmt::Write as _;

/// A point set as base-b digits: `points[i][j]` is coordinate j of point i, n digits, most
/// significant first.
pub(crate) struct DigitSet {
    pub(crate) b: u64,
    pub(crate) n: u32,
    pub(crate) points: Vec<Vec<Vec<u64>>>,
}

/// The queries asked of one set: its m when N = b^m, and the largest M with b^M ≤ N.
struct Queries {
    m: Option<u32>,
    max_m: u32,
}

impl DigitSet {
    pub(crate) fn dims(&self) -> usize {
        self.points[0].len()
    }

    fn value(&self, digits: &[u64]) -> u64 {
        digits.iter().fold(0, |v, &d| v * self.b + d)
    }

    /// The 32-bit words the Rust checker reads: x = ⌈v·2^32 / b^n⌉ lies in the digit string's
    /// cell [v/b^n, (v+1)/b^n), so its first n base-b digits are the string (asserted).
    fn words(&self) -> PointSet {
        let bn = (self.b as u128).pow(self.n);
        assert!(bn <= 1 << 32, "b^n must fit the 32-bit words");
        let base = CheckBase::new(self.b).unwrap();
        let rows: Vec<Vec<u64>> = self
            .points
            .iter()
            .map(|p| {
                p.iter()
                    .map(|digits| {
                        let v = self.value(digits);
                        let x = ((v as u128) << 32).div_ceil(bn) as u64;
                        assert_eq!(base.top_digits(x, 32, self.n), v, "the word's digits");
                        x
                    })
                    .collect()
            })
            .collect();
        PointSet::from_rows(Width::W32, &rows).unwrap()
    }

    fn queries(&self) -> Queries {
        let n = self.points.len() as u64;
        let mut max_m = 0;
        while self.b.pow(max_m + 1) <= n {
            max_m += 1;
        }
        Queries {
            m: (self.b.pow(max_m) == n).then_some(max_m),
            max_m,
        }
    }

    /// The driver's section: the digits, then every query.
    fn write(&self, out: &mut String) {
        let s = self.dims();
        writeln!(
            out,
            "checker {} {s} {} {}",
            self.b,
            self.n,
            self.points.len()
        )
        .unwrap();
        for p in &self.points {
            out.push_str("pt");
            for digits in p {
                for d in digits {
                    write!(out, " {d}").unwrap();
                }
            }
            out.push('\n');
        }
        let q = self.queries();
        if let Some(m) = q.m {
            for t in 0..=m {
                writeln!(out, "net {m} {t}").unwrap();
            }
            writeln!(out, "tval {m}").unwrap();
        }
        for t in 0..=q.max_m {
            writeln!(out, "seq {t} {}", q.max_m).unwrap();
        }
        out.push_str("endchecker\n");
    }
}

/// The Rust reports of one set, in the order of the driver's answers.
pub(crate) struct RustReports {
    nets: Vec<(u32, u32, NetReport)>,
    t_value: Option<(u32, u32)>,
    sequences: Vec<(u32, u32, SequenceReport)>,
}

/// Which Rust net path answers the net queries (each must agree with the model).
#[derive(Clone, Copy, Debug)]
pub(crate) enum NetPath {
    TreeWalk,
    PerShape,
    Owned,
}

pub(crate) fn reports(set: &DigitSet, path: NetPath) -> RustReports {
    let points = set.words();
    let base = CheckBase::new(set.b).unwrap();
    let q = set.queries();
    let mut nets = Vec::new();
    let mut tv = None;
    if let Some(m) = q.m {
        for t in 0..=m {
            let report = match path {
                NetPath::TreeWalk => check_net(&points, base, m, t),
                NetPath::PerShape => check_net_per_shape(&points, base, m, t),
                NetPath::Owned => {
                    check_net_owned(points.clone(), base, m, t, &gartowen::core::Silent)
                }
            };
            nets.push((m, t, report.unwrap()));
        }
        tv = Some((m, t_value(&points, base, m).unwrap()));
    }
    let sequences = (0..=q.max_m)
        .map(|t| {
            (
                t,
                q.max_m,
                check_sequence(&points, base, t, q.max_m).unwrap(),
            )
        })
        .collect();
    RustReports {
        nets,
        t_value: tv,
        sequences,
    }
}

fn join(v: &[impl std::fmt::Display]) -> String {
    v.iter()
        .map(|x| x.to_string())
        .collect::<Vec<_>>()
        .join(",")
}

fn failure_text(f: &BoxFailure) -> String {
    format!(
        "shape {} box {} count {}",
        join(&f.shape),
        join(&f.box_index),
        f.count
    )
}

/// The Rust reports written as the driver writes the model's answers.
pub(crate) fn answers(r: &RustReports) -> Vec<String> {
    let mut out = Vec::new();
    for (m, t, n) in &r.nets {
        out.push(match &n.first_failure {
            None if n.holds => format!("answer net {m} {t} holds {}", n.shapes_checked),
            Some(f) if !n.holds => format!(
                "answer net {m} {t} fails {} {}",
                n.shapes_checked,
                failure_text(f)
            ),
            _ => format!("answer net {m} {t} inconsistent report {n:?}"),
        });
    }
    if let Some((m, t)) = r.t_value {
        out.push(format!("answer tval {m} {t}"));
    }
    for (t, max_m, s) in &r.sequences {
        out.push(match &s.first_failure {
            None if s.holds => format!(
                "answer seq {t} {max_m} holds {} {}",
                s.blocks_checked, s.shapes_checked
            ),
            Some(f) if !s.holds => format!(
                "answer seq {t} {max_m} fails {} {} at {} block {} {}",
                s.blocks_checked,
                s.shapes_checked,
                f.m,
                f.block,
                failure_text(&f.failure)
            ),
            _ => format!("answer seq {t} {max_m} inconsistent report {s:?}"),
        });
    }
    out
}

/// A checker with a seeded defect, applied to the real reports.
#[derive(Clone, Copy, Debug)]
enum Mutant {
    /// The shape enumeration stops before its last shape (m − t, 0, …, 0); the t search sees
    /// the mutated verdicts.
    LastShapeSkipped,
    /// The t search starts at t = 1.
    TSearchFromOne,
    /// The t search reports the last failing t instead of the first passing one.
    TSearchLastFailing,
}

fn mutate(r: &RustReports, mutant: Mutant, dims: usize) -> RustReports {
    let mut nets: Vec<(u32, u32, NetReport)> = r.nets.clone();
    let mut t_value = r.t_value;
    match mutant {
        Mutant::LastShapeSkipped => {
            for (m, t, n) in nets.iter_mut() {
                let mut last = vec![0u32; dims];
                last[0] = *m - *t;
                if n.first_failure.as_ref().is_some_and(|f| f.shape == last) {
                    n.holds = true;
                    n.first_failure = None;
                    n.shapes_checked -= 1;
                }
            }
            if let Some((m, _)) = t_value {
                let least = nets.iter().find(|(_, _, n)| n.holds).map(|(_, t, _)| *t);
                t_value = Some((m, least.unwrap_or(m)));
            }
        }
        Mutant::TSearchFromOne => {
            t_value = t_value.map(|(m, t)| (m, if m >= 1 { t.max(1) } else { t }));
        }
        Mutant::TSearchLastFailing => {
            t_value = t_value.map(|(m, t)| (m, t.saturating_sub(1)));
        }
    }
    RustReports {
        nets,
        t_value,
        sequences: r.sequences.clone(),
    }
}

/// Base-b digits of v, most significant first, exactly n of them.
pub(crate) fn digits_of(mut v: u64, b: u64, n: u32) -> Vec<u64> {
    let mut d = vec![0; n as usize];
    for k in (0..n as usize).rev() {
        d[k] = v % b;
        v /= b;
    }
    d
}

/// Every ordered `npts`-tuple of points with `s` coordinates of `n` digits in base b.
fn exhaustive(b: u64, s: usize, n: u32, npts: u32) -> Vec<DigitSet> {
    let cell = b.pow(n).pow(s as u32);
    (0..cell.pow(npts))
        .map(|mut code| {
            let points = (0..npts)
                .map(|_| {
                    let mut p = code % cell;
                    code /= cell;
                    (0..s)
                        .map(|_| {
                            let x = p % b.pow(n);
                            p /= b.pow(n);
                            digits_of(x, b, n)
                        })
                        .collect()
                })
                .collect();
            DigitSet { b, n, points }
        })
        .collect()
}

/// The first b^m points of Sobol in `dims` dimensions, read as n base-2^q digits.
pub(crate) fn sobol(q: u32, m: u32, dims: usize, n: u32) -> DigitSet {
    let seq = SequenceKind::Sobol.build(dims, Width::W32).unwrap();
    let b = 1u64 << q;
    let points = (0..b.pow(m))
        .map(|i| {
            (0..dims)
                .map(|j| digits_of(seq.point(i, j) >> (32 - q * n), b, n))
                .collect()
        })
        .collect();
    DigitSet { b, n, points }
}

/// The first p^m points of Faure in a prime base p (n = max(m, 1) digits).
pub(crate) fn faure(p: u64, m: u32, dims: usize) -> DigitSet {
    let count = p.pow(m);
    let fr = faure_prime(p, count, dims).unwrap();
    let n = m.max(1);
    assert_eq!(fr[0].denom, p.pow(n));
    let points = fr
        .chunks(dims)
        .map(|pt| pt.iter().map(|f| digits_of(f.numer, p, n)).collect())
        .collect();
    DigitSet { b: p, n, points }
}

/// The Hammersley (0,m,2)-net in base b: (i/b^m, radical inverse of i), n = m digits.
fn hammersley(b: u64, m: u32) -> DigitSet {
    let points = (0..b.pow(m))
        .map(|i| {
            let d = digits_of(i, b, m);
            let mut r = d.clone();
            r.reverse();
            vec![d, r]
        })
        .collect();
    DigitSet { b, n: m, points }
}

/// The set with one digit changed: point i, coordinate j, digit k becomes (d + 1) mod b.
pub(crate) fn broken(set: &DigitSet, i: usize, j: usize, k: usize) -> DigitSet {
    let mut points = set.points.clone();
    points[i][j][k] = (points[i][j][k] + 1) % set.b;
    DigitSet {
        b: set.b,
        n: set.n,
        points,
    }
}

pub(crate) fn random(b: u64, s: usize, n: u32, npts: usize, rng: &mut SplitMix64) -> DigitSet {
    let points = (0..npts)
        .map(|_| {
            (0..s)
                .map(|_| (0..n).map(|_| rng.next_u64() % b).collect())
                .collect()
        })
        .collect();
    DigitSet { b, n, points }
}

/// The corpus: exhaustive tiny sets, nets, broken nets, random sets and boundary cases.
fn corpus() -> Vec<DigitSet> {
    let mut sets = exhaustive(2, 2, 2, 4);
    sets.extend(exhaustive(3, 2, 1, 3));
    sets.extend(exhaustive(4, 2, 1, 4));
    let mut nets = vec![
        sobol(1, 6, 3, 6),
        sobol(1, 5, 5, 7),
        sobol(2, 3, 3, 3),
        sobol(2, 2, 4, 4),
        sobol(4, 2, 2, 2),
        faure(3, 3, 3),
        faure(3, 4, 2),
        faure(5, 2, 5),
        faure(5, 3, 3),
        hammersley(3, 3),
        hammersley(5, 2),
        hammersley(16, 2),
    ];
    let mut rng = SplitMix64::new(0xc0ffee);
    let mut broken_nets = Vec::new();
    for net in &nets {
        for _ in 0..4 {
            let i = (rng.next_u64() % net.points.len() as u64) as usize;
            let j = (rng.next_u64() % net.dims() as u64) as usize;
            let k = (rng.next_u64() % net.n as u64) as usize;
            broken_nets.push(broken(net, i, j, k));
        }
    }
    nets.extend(broken_nets);
    sets.extend(nets);
    for (b, s, n, npts) in [
        (2, 3, 6, 64),
        (2, 2, 5, 24),
        (3, 2, 3, 27),
        (3, 3, 2, 18),
        (4, 2, 3, 64),
        (5, 2, 2, 25),
        (16, 2, 2, 256),
        (16, 1, 3, 48),
    ] {
        for _ in 0..3 {
            sets.push(random(b, s, n, npts, &mut rng));
        }
    }
    // Boundaries: one point; one dimension; every point in the top corner.
    for b in [2, 3, 16] {
        sets.push(DigitSet {
            b,
            n: 1,
            points: vec![vec![vec![b - 1], vec![0]]],
        });
        sets.push(DigitSet {
            b,
            n: 2,
            points: (0..b * b).map(|i| vec![digits_of(i, b, 2)]).collect(),
        });
        sets.push(DigitSet {
            b,
            n: 2,
            points: vec![vec![vec![b - 1, b - 1]; 2]; (b * b) as usize],
        });
    }
    sets
}

/// The model's answer lines, in order.
pub(crate) fn model_answers(driver: &std::path::Path, sets: &[DigitSet]) -> Vec<String> {
    let mut input = String::new();
    for set in sets {
        set.write(&mut input);
    }
    input.push_str("done\n");
    let (ok, stdout, stderr) = run_driver(driver, &input);
    assert!(ok, "the driver failed:\n{stderr}");
    assert!(
        stdout.contains(&format!("checker: {} point sets", sets.len())),
        "{stdout}"
    );
    stdout
        .lines()
        .filter(|l| l.starts_with("answer "))
        .map(str::to_owned)
        .collect()
}

/// Answer lines where the Rust reports and the model differ (at most `show` are kept).
pub(crate) fn disagreements(
    model: &[String],
    rust: &[String],
    show: usize,
) -> (usize, Vec<String>) {
    assert_eq!(model.len(), rust.len(), "one answer per query");
    let diff: Vec<(&String, &String)> = model.iter().zip(rust).filter(|(a, b)| a != b).collect();
    let shown = diff
        .iter()
        .take(show)
        .map(|(a, b)| format!("model: {a}\n rust: {b}"))
        .collect();
    (diff.len(), shown)
}

#[test]
fn the_rust_net_checker_agrees_with_its_coq_model_and_seeded_defects_do_not() {
    let Some(driver) = driver() else { return };
    let sets = corpus();
    assert!(sets.len() > 130_000);
    let model = model_answers(&driver, &sets);
    // Sets in parallel, each checked on one thread (the checker's own parallelism would only
    // add wake-ups on sets this small); the reports do not depend on the thread count.
    let real: Vec<RustReports> = sets
        .par_iter()
        .map(|s| reports(s, NetPath::TreeWalk))
        .collect();
    let rust: Vec<String> = real.iter().flat_map(answers).collect();
    let (n, shown) = disagreements(&model, &rust, 10);
    assert_eq!(
        n,
        0,
        "the Rust checker disagrees with Checker.v:\n{}",
        shown.join("\n")
    );
    // The verdicts vary: the corpus holds nets, sets that fail, and every t-value.
    let holds = model.iter().filter(|l| l.contains(" holds ")).count();
    let fails = model.iter().filter(|l| l.contains(" fails ")).count();
    assert!(
        holds > 10_000 && fails > 10_000,
        "{holds} hold, {fails} fail"
    );
    for t in 0..=3 {
        let line_end = format!(" {t}");
        assert!(
            model
                .iter()
                .any(|l| l.starts_with("answer tval") && l.ends_with(&line_end)),
            "no set with t-value {t}"
        );
    }
    // The other net paths answer the same (sampled: every 16th exhaustive set, every other set).
    for path in [NetPath::PerShape, NetPath::Owned] {
        let mut model_lines = Vec::new();
        let mut rust_lines = Vec::new();
        let mut at = 0;
        for (i, set) in sets.iter().enumerate() {
            let count = answers(&real[i]).len();
            if i % 16 == 0 || i >= 131_000 {
                rust_lines.extend(answers(&reports(set, path)));
                model_lines.extend_from_slice(&model[at..at + count]);
            }
            at += count;
        }
        let (n, shown) = disagreements(&model_lines, &rust_lines, 10);
        assert_eq!(
            n,
            0,
            "{path:?} disagrees with Checker.v:\n{}",
            shown.join("\n")
        );
    }
    for mutant in [
        Mutant::LastShapeSkipped,
        Mutant::TSearchFromOne,
        Mutant::TSearchLastFailing,
    ] {
        let rust: Vec<String> = real
            .iter()
            .zip(&sets)
            .flat_map(|(r, s)| answers(&mutate(r, mutant, s.dims())))
            .collect();
        let (n, _) = disagreements(&model, &rust, 0);
        assert!(n > 100, "{mutant:?} went unseen ({n} disagreements)");
    }
}
