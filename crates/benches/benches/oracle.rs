//! FullTreeOwen in time per 32-bit coordinate for b = 2, 4, 16, 256, single queries and the
//! batch path (lane-interleaved), with the identity as the in-run reference.
#![allow(missing_docs)] // criterion_group! defines an undocumented public function

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use gartowen_core::{Identity, PowerOfTwoBase, Scrambler, SplitMix64, Width};
use gartowen_owen::{FullTreeOwen, OwenVariant};

const N: usize = 1024;

fn oracle(c: &mut Criterion) {
    let mut rng = SplitMix64::new(1);
    let xs: Vec<u64> = (0..N).map(|_| rng.next_u32() as u64).collect();
    let mut g = c.benchmark_group("oracle_u32");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("identity_reference", |b| {
        b.iter(|| {
            xs.iter().fold(0u64, |a, &x| {
                a ^ Identity.scramble(black_box(x), Width::W32, 0)
            })
        })
    });
    for q in [1u32, 2, 4, 8] {
        let s = FullTreeOwen::new(PowerOfTwoBase::from_q(q).unwrap(), OwenVariant::Uniform, 7);
        g.bench_function(BenchmarkId::new("single", 1u32 << q), |b| {
            b.iter(|| {
                xs.iter()
                    .fold(0u64, |a, &x| a ^ s.scramble(x, Width::W32, 0))
            })
        });
        g.bench_function(BenchmarkId::new("batch", 1u32 << q), |b| {
            b.iter(|| {
                let mut v = xs.clone();
                s.scramble_batch(&mut v, Width::W32, 0);
                v[0]
            })
        });
    }
    g.finish();
}

criterion_group!(benches, oracle);
criterion_main!(benches);
