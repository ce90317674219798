//! One-shot timing of the fast exact 2-D L2-star on 2^20 Owen-scrambled Sobol points.
use gartowen_core::{PowerOfTwoBase, Scrambler, Width};
use gartowen_discrepancy::{fast2d, Points};
use gartowen_owen::{FullTreeOwen, OwenVariant};
use std::time::Instant;

fn main() {
    let n = 1usize << 20;
    let seq = gartowen_seq::sobol::sequence(2, Width::W32).unwrap();
    let s = FullTreeOwen::new(PowerOfTwoBase::B2, OwenVariant::Uniform, 777);
    let words: Vec<u64> = (0..n as u64)
        .flat_map(|i| [0, 1].map(|j| s.scramble(seq.point(i, j), Width::W32, j as u32)))
        .collect();
    let t = Instant::now();
    let r = fast2d::fast(Points {
        words: &words,
        dims: 2,
        width: Width::W32,
    })
    .unwrap();
    println!(
        "fast 2-D L2-star, N = 2^20: D² = {:e} in {:.3} s",
        r.value,
        t.elapsed().as_secs_f64()
    );
}
