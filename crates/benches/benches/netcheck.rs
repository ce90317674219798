//! Checker speed: counting-path sequence check, a 16-D base-16 net check, and the rank path.
#![allow(missing_docs)] // criterion_group! defines an undocumented public function

use criterion::{criterion_group, criterion_main, Criterion};
use gartowen_core::Width;
use gartowen_netcheck::counting::{check_net, check_net_per_shape, check_sequence};
use gartowen_netcheck::{rank, CheckBase, PointSet, ProjectionSpec};
use gartowen_seq::{sobol, sz, DigitalSequence};

fn points(seq: &DigitalSequence, n: u64) -> PointSet {
    let dims: Vec<usize> = (0..seq.dims()).collect();
    PointSet::from_sequence(seq, &dims, n, |x, _| x).unwrap()
}

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("netcheck");
    g.sample_size(10);

    let sobol2 = points(&sobol::sequence(2, Width::W32).unwrap(), 1 << 20);
    g.bench_function("counting_sequence_check_2d_n2^20_all_m", |b| {
        b.iter(|| {
            assert!(
                check_sequence(&sobol2, CheckBase::new(2).unwrap(), 0, 20)
                    .unwrap()
                    .holds
            )
        })
    });

    let sz16 = points(&sz::sz16(16, Width::W32).unwrap(), 1 << 16);
    g.bench_function("counting_sz16_16d_base16_n16^4_t0", |b| {
        b.iter(|| {
            assert!(
                check_net(&sz16, CheckBase::new(16).unwrap(), 4, 0)
                    .unwrap()
                    .holds
            )
        })
    });
    // The reference in the same run: every shape's keys from scratch, one thread.
    g.bench_function("per_shape_reference_sz16_16d_base16_n16^4_t0", |b| {
        b.iter(|| {
            assert!(
                check_net_per_shape(&sz16, CheckBase::new(16).unwrap(), 4, 0)
                    .unwrap()
                    .holds
            )
        })
    });

    let sob64 = sobol::sequence(64, Width::W32).unwrap();
    let pairs = ProjectionSpec::Pairs.expand(64).unwrap();
    g.bench_function("rank_all_pairs_sobol64_m20", |b| {
        b.iter(|| {
            pairs
                .iter()
                .map(|p| rank::t_value(&sob64, p, 1, 20).unwrap())
                .sum::<u32>()
        })
    });
    g.finish();
}

criterion_group!(netcheck, benches);
criterion_main!(netcheck);
