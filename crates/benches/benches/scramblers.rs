//! Every scrambler and sequence side by side, with the `sobol_burley` crate (Burley's
//! hash-based Owen-scrambled Sobol, 4 dimensions per set) as the peer. Throughput is in
//! coordinates, so criterion reports coordinates per second; ns per coordinate is its inverse.
//! Table bytes are printed once before the runs.
#![allow(missing_docs)] // criterion_group! defines an undocumented public function

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use gartowen::core::{BuildContext, PowerOfTwoBase, SplitMix64, Width};
use gartowen::seq::SequenceKind;

const WORDS: usize = 4096;
/// Seed of every scrambler built here, so the extra kernel rows walk the registry rows' tables.
const SEED: u64 = 1;

fn scramblers(c: &mut Criterion) {
    let registry = gartowen::registry();
    let mut rng = SplitMix64::new(3);
    let words: Vec<u64> = (0..WORDS).map(|_| rng.next_u32() as u64).collect();
    let mut requests: Vec<(String, PowerOfTwoBase)> = registry
        .specs()
        .iter()
        .filter(|s| s.name != "owen-oracle")
        .map(|s| (s.name.to_string(), s.default_base))
        .collect();
    for b in [2u64, 16, 256] {
        requests.push((
            format!("owen-oracle:base={b}"),
            PowerOfTwoBase::from_base(b).expect("base"),
        ));
    }
    let mut group = c.benchmark_group("scramble_u32");
    group.throughput(Throughput::Elements(WORDS as u64));
    let mut built = Vec::new();
    for (request, base) in &requests {
        let s = registry
            .build_with(
                request,
                &BuildContext {
                    seed: SEED,
                    default_base: *base,
                },
            )
            .expect("registry entry");
        eprintln!("table bytes: {request} = {}", s.table_bytes());
        built.push((request.clone(), s));
    }
    for (request, s) in &built {
        group.bench_with_input(BenchmarkId::from_parameter(request), &words, |b, w| {
            b.iter(|| {
                let mut acc = 0u64;
                for (i, &x) in w.iter().enumerate() {
                    acc ^= s.scramble(x, Width::W32, (i & 7) as u32);
                }
                black_box(acc)
            })
        });
    }
    // The peer: sobol_burley computes Sobol point + Owen scramble + shuffle in one call, so it is
    // compared with gartowen's sequence point plus a scramble (below).
    group.bench_function("sobol_burley::sample (point + scramble)", |b| {
        b.iter(|| {
            let mut acc = 0f32;
            for i in 0..WORDS as u32 {
                acc += sobol_burley::sample(i & 0xFFFF, i & 3, 7);
            }
            black_box(acc)
        })
    });
    let seq = SequenceKind::Sobol.build(4, Width::W32).expect("sobol");
    let lk = registry.build("lk-hash", 7).expect("lk");
    group.bench_function("sobol point + lk-hash (point + scramble)", |b| {
        b.iter(|| {
            let mut acc = 0u64;
            for i in 0..WORDS as u64 {
                acc ^= lk.scramble(seq.point(i, (i & 3) as usize), Width::W32, (i & 3) as u32);
            }
            black_box(acc)
        })
    });
    group.finish();

    // The batch path on u32 words (one dimension per call, as generate and verify use it),
    // against the scalar path above in the same run; `copy` is the floor (the buffer copy alone).
    let words32: Vec<u32> = words.iter().map(|&w| w as u32).collect();
    let mut group = c.benchmark_group("scramble_batch_u32");
    group.throughput(Throughput::Elements(WORDS as u64));
    let mut buffer = words32.clone();
    group.bench_function("copy", |b| {
        b.iter(|| {
            buffer.copy_from_slice(&words32);
            black_box(buffer[WORDS - 1])
        })
    });
    for (request, s) in &built {
        group.bench_function(BenchmarkId::from_parameter(request), |b| {
            b.iter(|| {
                buffer.copy_from_slice(&words32);
                s.scramble_batch_u32(&mut buffer, 3);
                black_box(buffer[WORDS - 1])
            })
        });
    }
    // The ART kernels the CPU runs besides the one it picks (the portable one and the 64-bit
    // gather kernel on an AVX-512 machine), in the same run, so machines without AVX-512 can
    // be read off this one and each kernel's gain is a ratio.
    let others: Vec<_> = gartowen::art::BatchKernel::available()
        .into_iter()
        .filter(|&k| k != gartowen::art::BatchKernel::detect())
        .collect();
    for kernel in others {
        for name in ["art-owen-2", "art-owen-16p"] {
            let variant = gartowen::art::registry::variant_of(name).expect("an ART variant");
            let symbols = gartowen::art::registry::DEFAULT_SYMBOLS;
            let art = gartowen::art::ArtOwen::new(variant, symbols, SEED)
                .expect("the default alphabet")
                .with_kernel(kernel)
                .expect("an available kernel");
            let id = format!("{name} ({kernel:?} kernel)");
            group.bench_function(BenchmarkId::from_parameter(id), |b| {
                b.iter(|| {
                    buffer.copy_from_slice(&words32);
                    gartowen::core::Scrambler::scramble_batch_u32(&art, &mut buffer, 3);
                    black_box(buffer[WORDS - 1])
                })
            });
        }
    }
    group.finish();

    // 64-bit words (the batch path for W > 32: ART's split tables, 64-bit carries), random.
    let words64: Vec<u64> = (0..WORDS).map(|_| rng.next_u64()).collect();
    let mut group = c.benchmark_group("scramble_batch_u64");
    group.throughput(Throughput::Elements(WORDS as u64));
    let mut buffer64 = words64.clone();
    for (request, s) in built
        .iter()
        .filter(|(r, _)| ["lk-hash", "art-owen-2", "art-owen-16p"].contains(&r.as_str()))
    {
        group.bench_function(BenchmarkId::from_parameter(request), |b| {
            b.iter(|| {
                buffer64.copy_from_slice(&words64);
                s.scramble_batch(&mut buffer64, Width::W64, 3);
                black_box(buffer64[WORDS - 1])
            })
        });
    }
    group.finish();

    // Consecutive words (what the every-word sweep and index scrambling feed the batch path):
    // ART's groups share their leading steps and read the last one from one cache line. Every
    // kernel the CPU runs, so the portable kernel's figure for the sweep is here too.
    let start = 0x5A5A_0000u32;
    let consecutive: Vec<u32> = (0..WORDS as u32).map(|i| start + i).collect();
    let mut group = c.benchmark_group("scramble_batch_u32_consecutive");
    group.throughput(Throughput::Elements(WORDS as u64));
    for (request, s) in built.iter().filter(|(r, _)| r == "lk-hash") {
        group.bench_function(BenchmarkId::from_parameter(request), |b| {
            b.iter(|| {
                buffer.copy_from_slice(&consecutive);
                s.scramble_batch_u32(&mut buffer, 3);
                black_box(buffer[WORDS - 1])
            })
        });
    }
    let mut runs = Vec::new();
    for name in ["art-owen-2", "art-owen-16p", "art-owen-8p"] {
        let variant = gartowen::art::registry::variant_of(name).expect("an ART variant");
        let art =
            gartowen::art::ArtOwen::new(variant, gartowen::art::registry::DEFAULT_SYMBOLS, SEED)
                .expect("the default alphabet");
        for kernel in gartowen::art::BatchKernel::available() {
            let art = art.with_kernel(kernel).expect("an available kernel");
            runs.push((format!("{name} ({kernel:?} kernel)"), art));
        }
    }
    for (id, art) in &runs {
        group.bench_function(BenchmarkId::from_parameter(id), |b| {
            b.iter(|| {
                buffer.copy_from_slice(&consecutive);
                gartowen::core::Scrambler::scramble_batch_u32(art, &mut buffer, 3);
                black_box(buffer[WORDS - 1])
            })
        });
    }
    group.finish();

    let mut group = c.benchmark_group("sequence_point_u32");
    group.throughput(Throughput::Elements(WORDS as u64));
    for kind in SequenceKind::ALL {
        let seq = kind.build(4, Width::W32).expect("sequence");
        group.bench_function(kind.name(), |b| {
            b.iter(|| {
                let mut acc = 0u64;
                for i in 0..WORDS as u64 {
                    acc ^= seq.point(i.wrapping_mul(0x9E37) & 0xFFFFF, (i & 3) as usize);
                }
                black_box(acc)
            })
        });
    }
    group.finish();
}

/// What the batch kernels' table reads cost on their own: the four lookups a 32-bit word takes
/// in 8-bit steps, made independent (each index read from memory, none waiting on an entry),
/// so the figure is the throughput floor a four-lookup kernel cannot go below on this core.
/// Tables: one that fits the first-level cache, and the sizes the kernels walk for 256
/// symbols (the narrow table, 256 KiB; the 64-bit table the portable kernel reads, 512 KiB).
/// The rows with three lookups are what 11-bit steps would read (2048 entries per symbol:
/// 2 MiB narrow, 4 MiB of 64-bit entries), the row with two what 16-bit steps would (64 MiB
/// narrow). Throughput is in words, comparable with `scramble_batch_u32`.
fn lookup_floor(c: &mut Criterion) {
    let mut rng = SplitMix64::new(5);
    let raw: Vec<u32> = (0..4 * WORDS).map(|_| rng.next_u32()).collect();
    // Indices into `entries` entries, `lookups` per word.
    let indices = |lookups: usize, entries: usize| -> Vec<u32> {
        raw[..lookups * WORDS]
            .iter()
            .map(|&r| r % entries as u32)
            .collect()
    };
    let label = |lookups: usize, what: &str, kib: usize| match lookups {
        4 => format!("{what}, {kib} KiB table"),
        3 => format!("three {what}, {kib} KiB table (11-bit steps)"),
        _ => format!("two {what}, {kib} KiB table (16-bit steps)"),
    };
    let mut group = c.benchmark_group("scramble_lookup_floor");
    group.throughput(Throughput::Elements(WORDS as u64));
    for (lookups, kib) in [(4usize, 16usize), (4, 256), (4, 512), (3, 4096)] {
        let entries = kib * 1024 / 8;
        let table: Vec<u64> = (0..entries).map(|_| rng.next_u64()).collect();
        let idx = indices(lookups, entries);
        group.bench_function(label(lookups, "scalar loads", kib), |b| {
            b.iter(|| {
                let idx = black_box(&idx);
                black_box(match lookups {
                    4 => scalar_xor::<4>(&table, idx),
                    _ => scalar_xor::<3>(&table, idx),
                })
            })
        });
    }
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx512f") {
        for (lookups, kib) in [(4usize, 16usize), (4, 256), (3, 2048), (2, 65536)] {
            let entries = kib * 1024 / 4;
            let table: Vec<u32> = (0..entries).map(|_| rng.next_u32()).collect();
            let idx = indices(lookups, entries);
            group.bench_function(label(lookups, "16-lane gathers", kib), |b| {
                // SAFETY: AVX-512F was detected, and every index is below the table's length.
                b.iter(|| black_box(unsafe { gather_xor(black_box(&table), black_box(&idx)) }))
            });
        }
    }
    group.finish();
}

/// The XOR of `table[i]` over `idx`, read N at a time (one word's lookups) into N
/// accumulators.
fn scalar_xor<const N: usize>(table: &[u64], idx: &[u32]) -> u64 {
    let mut acc = [0u64; N];
    for chunk in idx.chunks_exact(N) {
        for (a, &i) in acc.iter_mut().zip(chunk) {
            *a ^= table[i as usize];
        }
    }
    acc.iter().fold(0, |x, &a| x ^ a)
}

/// The XOR of `table[i]` over `idx`, sixteen lanes per gather, four gathers in flight.
///
/// # Safety
/// The CPU must support AVX-512F, and every index must be below `table.len()`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
unsafe fn gather_xor(table: &[u32], idx: &[u32]) -> u32 {
    use std::arch::x86_64::*;
    let mut acc = [_mm512_setzero_si512(); 4];
    for (k, chunk) in idx.chunks_exact(16).enumerate() {
        // SAFETY: one unaligned load of the 16 indices of `chunk`; the gather reads inside
        // `table` by the caller's contract.
        let e = unsafe {
            let i = _mm512_loadu_si512(chunk.as_ptr().cast());
            _mm512_i32gather_epi32::<4>(i, table.as_ptr().cast())
        };
        acc[k % 4] = _mm512_xor_si512(acc[k % 4], e);
    }
    let all = _mm512_xor_si512(
        _mm512_xor_si512(acc[0], acc[1]),
        _mm512_xor_si512(acc[2], acc[3]),
    );
    _mm512_reduce_or_epi32(all) as u32
}

criterion_group!(benches, scramblers, lookup_floor);
criterion_main!(benches);
