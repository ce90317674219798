//! One-shot timing of the largest checker target: sz16, N = 16^5 points, 16 dims, base 16, t = 0
//! (15504 shapes over 2^20 points; too long for criterion's ten-sample minimum).
use gartowen_core::Width;
use gartowen_netcheck::counting::check_net;
use gartowen_netcheck::{CheckBase, PointSet};
use std::time::Instant;

fn main() {
    let seq = gartowen_seq::sz::sz16(16, Width::W32).unwrap();
    let n = 1u64 << 20;
    let dims: Vec<usize> = (0..16).collect();
    let p = PointSet::from_sequence(&seq, &dims, n, |x, _| x).unwrap();
    let start = Instant::now();
    let r = check_net(&p, CheckBase::new(16).unwrap(), 5, 0).unwrap();
    println!(
        "sz16 16^5 points, 16 dims, base 16, t = 0: holds = {}, {} shapes, {:.1} s on {} threads",
        r.holds,
        r.shapes_checked,
        start.elapsed().as_secs_f64(),
        rayon::current_num_threads()
    );
}
