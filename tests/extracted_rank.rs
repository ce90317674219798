//! The rank path of `crates/netcheck` (`rank.rs`: its XOR basis and its depth-first search over
//! shapes) against the Coq model of the basis (`proofs/RankBasis.v`, `independent`, proved to
//! accept a shape's stacked rows exactly when every box of the shape holds the same number of
//! points), extracted to OCaml. For Sobol and SZ sequences of the registry, random and broken
//! generator matrices and a word narrower than the shapes need, in bases 2, 4 and 16: the model
//! judges every shape of every t; the first failing shape of each t (lexicographic order) and
//! the t-value must be the Rust ones. The rows are read off the points at the unit indices
//! (point 2^c is column c), not off the generator columns the Rust code reads. Bases without
//! teeth are excluded by seeded defects: a basis that never reduces, and rows of the last
//! dimension left out, must each disagree with the model on many cases.

use crate::extracted_differential::{driver, run_driver};
use gartowen_core::{PowerOfTwoBase, SplitMix64, Width};
use gartowen_netcheck::rank::RowMatrices;
use gartowen_seq::{sobol, sz, DigitalSequence};
use std::fmt::Write as _;

/// One rank question: the dimensions `dims` of `seq` in base 2^q, nets of 2^(q·m) points.
struct Case {
    name: String,
    seq: DigitalSequence,
    dims: Vec<usize>,
    q: u32,
    m: u32,
}

/// Compositions of `total` into `parts` parts, d_0 ascending first (lexicographic order).
fn compositions(total: u32, parts: usize) -> Vec<Vec<u32>> {
    if parts == 1 {
        return vec![vec![total]];
    }
    (0..=total)
        .flat_map(|d| {
            compositions(total - d, parts - 1)
                .into_iter()
                .map(move |rest| {
                    let mut shape = vec![d];
                    shape.extend(rest);
                    shape
                })
        })
        .collect()
}

/// Row r of dimension `dim` as a mask over the q·m index bits: bit c is bit r (from the top)
/// of the point at index 2^c. Rows past the word are zero.
fn rows(seq: &DigitalSequence, dim: usize, q: u32, m: u32) -> Vec<u64> {
    let (cols, w) = (q * m, seq.width().bits());
    (0..cols)
        .map(|r| {
            if r >= w {
                return 0;
            }
            (0..cols).fold(0u64, |acc, c| {
                acc | (((seq.point(1 << c, dim) >> (w - 1 - r)) & 1) << c)
            })
        })
        .collect()
}

/// A shape's stacked rows: the first q·d_j rows of each dimension, in order.
fn stacked(case: &Case, shape: &[u32]) -> Vec<u64> {
    case.dims
        .iter()
        .zip(shape)
        .flat_map(|(&j, &d)| {
            rows(&case.seq, j, case.q, case.m)
                .into_iter()
                .take((case.q * d) as usize)
        })
        .collect()
}

/// Every shape of every t, in the order the answers come back.
fn shapes(case: &Case) -> Vec<(u32, Vec<u32>)> {
    (0..=case.m)
        .flat_map(|t| {
            compositions(case.m - t, case.dims.len())
                .into_iter()
                .map(move |s| (t, s))
        })
        .collect()
}

/// The first failing shape per t and the t-value, from per-shape verdicts.
fn summary(case: &Case, accepted: &[bool]) -> (Vec<Option<Vec<u32>>>, u32) {
    let mut first = vec![None; case.m as usize + 1];
    for ((t, shape), &ok) in shapes(case).iter().zip(accepted) {
        if !ok && first[*t as usize].is_none() {
            first[*t as usize] = Some(shape.clone());
        }
    }
    let t_value = (0..=case.m)
        .find(|&t| first[t as usize].is_none())
        .expect("t = m has only the empty shape");
    (first, t_value)
}

fn rust_summary(case: &Case) -> (Vec<Option<Vec<u32>>>, u32) {
    let rm = RowMatrices::new(&case.seq, &case.dims, case.q, case.m).unwrap();
    let first = (0..=case.m).map(|t| rm.first_failure(t).unwrap()).collect();
    (first, rm.t_value())
}

fn random_sequence(seed: u64, dims: usize, width: Width) -> DigitalSequence {
    let mut rng = SplitMix64::new(seed);
    let cols: Vec<Vec<u64>> = (0..dims)
        .map(|_| {
            (0..width.bits())
                .map(|_| rng.next_u64() & width.mask())
                .collect()
        })
        .collect();
    DigitalSequence::from_columns("random", width, PowerOfTwoBase::B2, &cols).unwrap()
}

/// Sobol's first four dimensions with one generator bit flipped.
fn broken_sobol(dim: usize, column: usize, row: u32) -> DigitalSequence {
    let seq = sobol::sequence(4, Width::W32).unwrap();
    let cols: Vec<Vec<u64>> = (0..4)
        .map(|j| {
            let mut c = seq.columns(j).to_vec();
            if j == dim {
                c[column] ^= 1 << (31 - row);
            }
            c
        })
        .collect();
    DigitalSequence::from_columns("broken", Width::W32, PowerOfTwoBase::B2, &cols).unwrap()
}

fn corpus() -> Vec<Case> {
    let mut cases = Vec::new();
    let mut add = |name: &str, seq: &DigitalSequence, dims: &[usize], q: u32, max_m: u32| {
        for m in 1..=max_m {
            cases.push(Case {
                name: format!("{name} dims {dims:?} q {q}"),
                seq: seq.clone(),
                dims: dims.to_vec(),
                q,
                m,
            });
        }
    };
    let sob = sobol::sequence(6, Width::W32).unwrap();
    for dims in [&[0, 1][..], &[0, 1, 2], &[1, 3], &[2, 4, 5], &[0, 1, 2, 3]] {
        add("sobol", &sob, dims, 1, 9);
    }
    add("sobol", &sob, &[0, 1], 2, 5);
    add("sobol", &sob, &[0, 1, 2], 2, 4);
    add("sobol", &sob, &[0, 1], 4, 2);
    let sz4 = sz::sz4(3, Width::W32).unwrap();
    add("sz4", &sz4, &[0, 1], 2, 5);
    add("sz4", &sz4, &[0, 1, 2], 2, 4);
    add("sz4", &sz4, &[0, 1, 2], 1, 8);
    let sz16 = sz::sz16(3, Width::W32).unwrap();
    add("sz16", &sz16, &[0, 1], 4, 2);
    add("sz16", &sz16, &[0, 1, 2], 4, 2);
    for seed in 0..6 {
        let r = random_sequence(0x7a4c + seed, 3, Width::new(16).unwrap());
        add(&format!("random {seed}"), &r, &[0, 1, 2], 1, 8);
        add(&format!("random {seed}"), &r, &[0, 2], 2, 4);
    }
    for (dim, column, row) in [(0, 0, 0), (1, 2, 1), (2, 5, 3), (3, 7, 6)] {
        add(
            "broken sobol",
            &broken_sobol(dim, column, row),
            &[0, 1, 2, 3],
            1,
            8,
        );
    }
    // 5-bit words with 8 index bits: shapes that need more than 5 rows of one dimension fail
    // (rows past W are 0).
    let mut rng = SplitMix64::new(0x5b17);
    let narrow_cols: Vec<Vec<u64>> = (0..2)
        .map(|_| (0..8).map(|_| rng.next_u64() & 0x1f).collect())
        .collect();
    let narrow = DigitalSequence::from_columns(
        "narrow",
        Width::new(5).unwrap(),
        PowerOfTwoBase::B2,
        &narrow_cols,
    )
    .unwrap();
    add("narrow W5", &narrow, &[0, 1], 1, 8);
    cases
}

/// The model's verdict on every shape of every case, in order.
fn model_verdicts(driver: &std::path::Path, cases: &[Case]) -> Vec<Vec<bool>> {
    let mut input = String::new();
    for case in cases {
        for (_, shape) in shapes(case) {
            let rows = stacked(case, &shape);
            write!(input, "rank {} {}", case.q * case.m, rows.len()).unwrap();
            for r in rows {
                write!(input, " {r}").unwrap();
            }
            input.push('\n');
        }
    }
    input.push_str("done\n");
    let (ok, stdout, stderr) = run_driver(driver, &input);
    assert!(ok, "the driver failed:\n{stderr}");
    let mut answers = stdout
        .lines()
        .filter_map(|l| l.strip_prefix("answer rank "))
        .map(|a| a == "1");
    cases
        .iter()
        .map(|case| {
            (0..shapes(case).len())
                .map(|_| answers.next().expect("an answer per shape"))
                .collect()
        })
        .collect()
}

/// A defective basis for the negative controls: `NoReduction` stores a row when its top slot
/// is empty and rejects it otherwise (no XOR with the pivot).
#[derive(Clone, Copy, Debug)]
enum Defect {
    NoReduction,
    LastDimensionSkipped,
}

fn defective_verdict(case: &Case, shape: &[u32], defect: Defect) -> bool {
    let mut rows = stacked(case, shape);
    match defect {
        Defect::NoReduction => {
            let mut slots = [false; 64];
            rows.iter().all(|&r| {
                if r == 0 {
                    return false;
                }
                let top = 63 - r.leading_zeros() as usize;
                !std::mem::replace(&mut slots[top], true)
            })
        }
        Defect::LastDimensionSkipped => {
            let last = (case.q * shape[shape.len() - 1]) as usize;
            rows.truncate(rows.len() - last);
            let mut pivots = [0u64; 64];
            rows.iter().all(|&r| {
                let mut v = r;
                while v != 0 {
                    let top = 63 - v.leading_zeros() as usize;
                    if pivots[top] == 0 {
                        pivots[top] = v;
                        return true;
                    }
                    v ^= pivots[top];
                }
                false
            })
        }
    }
}

#[test]
fn the_rust_rank_path_agrees_with_its_coq_model_and_defective_bases_do_not() {
    let Some(driver) = driver() else { return };
    let cases = corpus();
    let model = model_verdicts(&driver, &cases);
    let mut shapes_judged = 0;
    let mut failing_t = 0;
    for (case, verdicts) in cases.iter().zip(&model) {
        shapes_judged += verdicts.len();
        let want = summary(case, verdicts);
        failing_t += want.0.iter().filter(|f| f.is_some()).count();
        assert_eq!(
            rust_summary(case),
            want,
            "{} m {}: (first failing shape per t, t-value), Rust vs model",
            case.name,
            case.m
        );
    }
    // The corpus has teeth: 13,117 shapes, failures at 308 (case, t); each defect below
    // disagrees on more than 120 of the 189 cases.
    assert!(shapes_judged > 10_000, "{shapes_judged} shapes");
    assert!(
        failing_t > 200,
        "{failing_t} (case, t) with a failing shape"
    );
    for defect in [Defect::NoReduction, Defect::LastDimensionSkipped] {
        let disagreements = cases
            .iter()
            .zip(&model)
            .filter(|(case, verdicts)| {
                let broken: Vec<bool> = shapes(case)
                    .iter()
                    .map(|(_, s)| defective_verdict(case, s, defect))
                    .collect();
                summary(case, &broken) != summary(case, verdicts)
            })
            .count();
        assert!(
            disagreements > 100,
            "{defect:?}: {disagreements} cases disagree"
        );
    }
}
