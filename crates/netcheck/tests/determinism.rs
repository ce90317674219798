//! Reports are identical for any thread count: the first failure is defined by shape order.

use gartowen_core::Width;
use gartowen_netcheck::counting::{check_net, check_sequence};
use gartowen_netcheck::{CheckBase, PointSet};

fn broken_sobol() -> PointSet {
    let seq = gartowen_seq::sobol::sequence(3, Width::W32).unwrap();
    let mut p = PointSet::from_sequence(&seq, &[0, 1, 2], 4096, |x, _| x).unwrap();
    // Several independent defects, so threads racing over shapes could see different ones.
    for (i, j) in [(100, 0), (2000, 1), (3000, 2), (4000, 1)] {
        let other = p.column(j)[i + 1];
        p.set(i, j, other);
    }
    p
}

#[test]
fn one_two_and_four_threads_give_identical_reports() {
    let p = broken_sobol();
    let base = CheckBase::new(2).unwrap();
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            (
                check_net(&p, base, 12, 0).unwrap(),
                check_net(&p, base, 12, 1).unwrap(),
                check_sequence(&p, base, 0, 12).unwrap(),
            )
        })
    };
    let one = run(1);
    assert!(!one.0.holds && !one.2.holds);
    for threads in [2, 4] {
        assert_eq!(run(threads), one, "{threads} threads");
    }
}
