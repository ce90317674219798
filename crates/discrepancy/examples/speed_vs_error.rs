//! Speed against error: every method on Owen-scrambled Sobol sets, time and relative error
//! against the exact value (or against `fast`, which is exact, for 2-D L2-star). Writes the
//! sets as .npy-compatible raw files for scripts/bench-discrepancy-vs-scipy.sh when given a
//! directory. Usage: cargo run --release -p gartowen-discrepancy --example speed_vs_error [DIR]
use gartowen_core::{word_to_f64, PowerOfTwoBase, Scrambler, Width};
use gartowen_discrepancy::{compensated, exact, fast2d, naive, rational, Kind, Points};
use gartowen_owen::{FullTreeOwen, OwenVariant};
use std::time::Instant;

fn set(n: usize, d: usize) -> Vec<u64> {
    let seq = gartowen_seq::sobol::sequence(d, Width::W32).unwrap();
    let s = FullTreeOwen::new(PowerOfTwoBase::B2, OwenVariant::Uniform, 777);
    (0..n as u64)
        .flat_map(|i| (0..d).map(move |j| (i, j)))
        .map(|(i, j)| s.scramble(seq.point(i, j), Width::W32, j as u32))
        .collect()
}

fn time<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t = Instant::now();
    let r = f();
    (r, t.elapsed().as_secs_f64())
}

fn main() {
    let dir = std::env::args().nth(1);
    println!("| kind | N | d | method | seconds | rel. error vs exact |");
    println!("|---|---|---|---|---|---|");
    for (n, d) in [
        (1usize << 12, 2usize),
        (1 << 16, 2),
        (1 << 20, 2),
        (1 << 12, 16),
        (1 << 14, 16),
    ] {
        let words = set(n, d);
        if let Some(dir) = &dir {
            // Row-major float64 values, little-endian, for numpy.fromfile.
            let bytes: Vec<u8> = words
                .iter()
                .flat_map(|&w| word_to_f64(w, Width::W32).to_le_bytes())
                .collect();
            std::fs::write(format!("{dir}/sobol_owen_n{n}_d{d}.f64"), bytes).unwrap();
        }
        let p = Points {
            words: &words,
            dims: d,
            width: Width::W32,
        };
        let kinds: &[Kind] = if d == 2 {
            &[Kind::L2Star, Kind::Centered]
        } else {
            &[Kind::L2Star]
        };
        for &kind in kinds {
            let truth = if kind == Kind::L2Star && d == 2 {
                let (r, s) = time(|| fast2d::fast(p).unwrap());
                println!(
                    "| {} | {n} | {d} | fast (exact) | {s:.4} | 0 |",
                    kind.name()
                );
                Some(r.exact.unwrap())
            } else if n * n * d <= 1 << 30 {
                let (r, s) = time(|| exact::exact(p, kind));
                println!("| {} | {n} | {d} | exact | {s:.4} | 0 |", kind.name());
                Some(r.exact.unwrap())
            } else {
                None
            };
            let err = |v: f64| match &truth {
                Some(t) => format!(
                    "{:.1e}",
                    ((v - rational::to_f64(t)) / rational::to_f64(t)).abs()
                ),
                None => "exact not run (bound below)".into(),
            };
            if n > 1 << 16 {
                continue; // O(N²) methods: only up to 2^16 points
            }
            let (c, s) = time(|| compensated::compensated(p, kind));
            println!(
                "| {} | {n} | {d} | compensated | {s:.4} | {} (bound {:.1e}) |",
                kind.name(),
                err(c.value),
                c.rel_error_bound.unwrap()
            );
            if n <= 1 << 16 {
                let (v, s) = time(|| naive::naive(p, kind));
                println!(
                    "| {} | {n} | {d} | naive | {s:.4} | {} |",
                    kind.name(),
                    err(v.value)
                );
            }
            if let Some(t) = &truth {
                println!(
                    "<!-- {} {n} {d} exact {:.17e} -->",
                    kind.name(),
                    rational::to_f64(t)
                );
            }
        }
    }
}
