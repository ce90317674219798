//! Every registered scrambler side by side in time per 32-bit coordinate, with the identity
//! and the LK hash as in-run references (ratios are what the closing note reports).
#![allow(missing_docs)] // criterion_group! defines an undocumented public function

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use gartowen_art::peers::{LkFlavor, LkHash, PerBitOwen};
use gartowen_art::{ArtMutant, ArtOwen, ArtVariant};
use gartowen_core::ScramblerExt;
use gartowen_core::{Identity, PowerOfTwoBase, Scrambler, SplitMix64};
use gartowen_owen::{FullTreeOwen, OwenVariant};

const N: usize = 4096;

fn scramblers(c: &mut Criterion) {
    let mut rng = SplitMix64::new(1);
    let xs: Vec<u32> = (0..N).map(|_| rng.next_u32()).collect();
    let mut list: Vec<(String, Box<dyn Scrambler>)> = vec![
        ("identity".into(), Box::new(Identity)),
        (
            "lk-hash".into(),
            Box::new(LkHash::new(LkFlavor::Classic, 1)),
        ),
        (
            "lk-hash-improved".into(),
            Box::new(LkHash::new(LkFlavor::Improved, 1)),
        ),
        ("owen-per-bit-hash".into(), Box::new(PerBitOwen::new(1))),
        (
            "owen-oracle-b2".into(),
            Box::new(FullTreeOwen::new(
                PowerOfTwoBase::B2,
                OwenVariant::Uniform,
                1,
            )),
        ),
        (
            "owen-oracle-b16".into(),
            Box::new(FullTreeOwen::new(
                PowerOfTwoBase::B16,
                OwenVariant::Uniform,
                1,
            )),
        ),
    ];
    let mut variants = vec![
        ArtVariant::ArtOwen2,
        ArtVariant::QArt4,
        ArtVariant::ArtOwen8P,
        ArtVariant::ArtOwen16P,
    ];
    variants.extend((1..=8).map(ArtVariant::Matrix));
    variants.extend((1..=8).map(ArtVariant::Translation));
    for v in variants {
        let s = ArtOwen::new(v, 256, 1).unwrap();
        list.push((
            format!("{}:table=256 ({} B)", v.name(), s.table_bytes()),
            Box::new(s),
        ));
    }
    // The design before per-dimension shifts, as the in-run reference for their cost.
    for v in [ArtVariant::ArtOwen2, ArtVariant::ArtOwen16P] {
        let s = ArtOwen::with_mutant(v, 256, 1, ArtMutant::RootOnlyDimensions).unwrap();
        list.push((
            format!("{}:table=256 without dimension shifts", v.name()),
            Box::new(s),
        ));
    }
    let mut g = c.benchmark_group("scramble_u32");
    g.throughput(Throughput::Elements(N as u64));
    for (name, s) in &list {
        g.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| {
                xs.iter()
                    .enumerate()
                    .fold(0u32, |a, (i, &x)| a ^ s.scramble_u32(x, (i & 3) as u32))
            })
        });
    }
    g.finish();
}

criterion_group!(benches, scramblers);
criterion_main!(benches);
