//! Random access and Gray-code iteration, in time per 32-bit coordinate
//! (criterion's throughput is set to the number of coordinates produced).
#![allow(missing_docs)] // criterion_group! defines an undocumented public function

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use gartowen_core::{SplitMix64, Width};
use gartowen_seq::SequenceKind;

const DIMS: usize = 16;
const POINTS: u64 = 1 << 12;

fn random_access(c: &mut Criterion) {
    let mut g = c.benchmark_group("random_access_u32");
    let mut rng = SplitMix64::new(1);
    let indices: Vec<u32> = (0..POINTS).map(|_| rng.next_u32() >> 12).collect(); // < 2^20
    for kind in SequenceKind::ALL {
        let dims = DIMS.min(kind.max_dims());
        let seq = kind.build(dims, Width::W32).unwrap();
        g.throughput(Throughput::Elements(POINTS * dims as u64));
        g.bench_function(BenchmarkId::new("set_bit_loop", kind.name()), |b| {
            b.iter(|| {
                let mut acc = 0u64;
                for &i in &indices {
                    for j in 0..dims {
                        acc ^= seq.point_u32(i, j);
                    }
                }
                black_box(acc)
            })
        });
        let tables = seq.lookup_tables();
        g.bench_function(BenchmarkId::new("byte_tables", kind.name()), |b| {
            b.iter(|| {
                let mut acc = 0u64;
                for &i in &indices {
                    for j in 0..dims {
                        acc ^= tables.point_u32(i, j);
                    }
                }
                black_box(acc)
            })
        });
    }
    g.finish();
}

fn gray_iteration(c: &mut Criterion) {
    let mut g = c.benchmark_group("gray_iteration_u32");
    for kind in SequenceKind::ALL {
        let dims = DIMS.min(kind.max_dims());
        let seq = kind.build(dims, Width::W32).unwrap();
        g.throughput(Throughput::Elements(POINTS * dims as u64));
        g.bench_function(kind.name(), |b| {
            b.iter(|| {
                let mut it = seq.gray_iter(1 << 20, (1 << 20) + POINTS).unwrap();
                let mut acc = 0u64;
                while let Some((_, p)) = it.next_point() {
                    acc ^= p[0] ^ p[dims - 1];
                }
                black_box(acc)
            })
        });
    }
    g.finish();
}

criterion_group!(benches, random_access, gray_iteration);
criterion_main!(benches);
