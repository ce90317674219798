use gartowen_core::Width;
use gartowen_netcheck::counting::{check_net, t_value};
use gartowen_netcheck::{CheckBase, PointSet};
use std::time::Instant;
fn main() {
    let seq = gartowen_seq::sobol::sequence(32, Width::W32).unwrap();
    let n = 1u64 << 20;
    for pair in [[0usize, 1], [30, 31], [4, 7]] {
        let cols = pair.iter().map(|&j| (0..n).map(|i| seq.point(i, j)).collect()).collect();
        let p = PointSet::from_columns(Width::W32, cols).unwrap();
        let b = CheckBase::new(2).unwrap();
        let t0 = Instant::now();
        let t = t_value(&p, b, 20).unwrap();
        let el = t0.elapsed();
        let mut per = vec![];
        for tt in 0..=t {
            let s = Instant::now();
            let r = check_net(&p, b, 20, tt).unwrap();
            per.push((tt, r.holds, r.shapes_checked, s.elapsed().as_secs_f64() * 1e3));
        }
        println!("{pair:?} t={t} t_value {:.1} ms; per-level {per:?}", el.as_secs_f64() * 1e3);
    }
}
