//! Nested scrambling preserves net properties in the scrambling base (DESIGN §4, theorem T2 at
//! bounded sizes): every scrambler in the registry that is nested in a sequence's base keeps
//! its t-values there, judged by the counting path against the rank path of the unscrambled
//! matrices.

use gartowen::core::{BuildContext, PowerOfTwoBase, Scrambler, Width};
use gartowen::netcheck::counting::t_value;
use gartowen::netcheck::{rank, CheckBase, PointSet};
use gartowen::seq::{DigitalSequence, SequenceKind};

fn scrambled(seq: &DigitalSequence, s: &dyn Scrambler, dims: &[usize], n: u64) -> PointSet {
    PointSet::from_sequence(seq, dims, n, |x, j| s.scramble(x, seq.width(), j as u32)).unwrap()
}

#[test]
fn every_registered_scrambler_keeps_t_values_in_the_scrambling_base() {
    let registry = gartowen::registry();
    let cases: [(SequenceKind, Vec<usize>, u32); 4] = [
        (SequenceKind::Sobol, vec![0, 1, 2], 10),
        (SequenceKind::Sobol, vec![3, 7], 12),
        (SequenceKind::Sz4, vec![0, 1, 2, 3], 5),
        (SequenceKind::Sz16, vec![0, 5, 10, 15], 3),
    ];
    for spec in registry.specs() {
        for (kind, dims, m) in &cases {
            for seed in [1u64, 2] {
                let ctx = BuildContext {
                    seed,
                    default_base: kind.base(),
                };
                let s = (spec.build)(
                    &gartowen::core::ScramblerRequest::parse(spec.name).unwrap(),
                    &ctx,
                )
                .unwrap();
                // Only claims in the sequence's own base are tested here.
                if s.base() != kind.base() && spec.name != "none" {
                    continue;
                }
                let seq = kind
                    .build(16, Width::W32)
                    .or_else(|_| kind.build(4, Width::W32))
                    .unwrap();
                let q = kind.base().q();
                let expected = rank::t_value(&seq, dims, q, *m).unwrap();
                let p = scrambled(&seq, s.as_ref(), dims, 1u64 << (q * m));
                let got =
                    t_value(&p, CheckBase::new(kind.base().base() as u64).unwrap(), *m).unwrap();
                assert_eq!(
                    got,
                    expected,
                    "{} on {:?} dims {dims:?} m {m} seed {seed}",
                    s.name(),
                    kind
                );
            }
        }
    }
}

#[test]
fn oracle_variants_in_every_base_keep_sz16_base_16_nets() {
    use gartowen::owen::{FullTreeOwen, OwenVariant};
    let seq = SequenceKind::Sz16.build(16, Width::W32).unwrap();
    let dims: Vec<usize> = (0..16).collect();
    for variant in OwenVariant::ALL {
        let s = FullTreeOwen::new(PowerOfTwoBase::B16, variant, 77);
        let p = scrambled(&seq, &s, &dims, 1 << 12);
        assert_eq!(
            t_value(&p, CheckBase::new(16).unwrap(), 3).unwrap(),
            0,
            "{variant:?}"
        );
    }
    // A base-16 scramble is not binary-nested: the binary (0,2) pair structure of dims (0,1)
    // is lost for some m (the point of the generalized paper).
    let s = FullTreeOwen::new(PowerOfTwoBase::B16, OwenVariant::Uniform, 77);
    let lost = (1..=8u32).any(|m| {
        let p = scrambled(&seq, &s, &[0, 1], 1 << m);
        t_value(&p, CheckBase::new(2).unwrap(), m).unwrap() > 0
    });
    assert!(
        lost,
        "base-16 Owen scrambling should break some binary (0,m,2)-net of sz16 dims 0,1"
    );
    let binary = FullTreeOwen::new(PowerOfTwoBase::B2, OwenVariant::Uniform, 77);
    for m in 1..=8u32 {
        let p = scrambled(&seq, &binary, &[0, 1], 1 << m);
        assert_eq!(
            t_value(&p, CheckBase::new(2).unwrap(), m).unwrap(),
            0,
            "binary Owen keeps it, m={m}"
        );
    }
}

/// The battery's nets check in every base: each registry entry, built with every default base,
/// keeps the t-values of the nets in its own base and in every base 2^(kq) it is nested in
/// (Faure over GF(2^r) in bases 8, 32, 64, 128 and 256).
#[test]
fn every_registered_scrambler_keeps_nets_in_every_base_it_is_nested_in() {
    use gartowen::verify::nets::{check_base, nested_bases};
    use gartowen::verify::Level;
    let registry = gartowen::registry();
    let mut seen = std::collections::BTreeSet::new();
    let mut bases_checked = std::collections::BTreeSet::new();
    for spec in registry.specs() {
        for q in 1..=8 {
            let ctx = BuildContext {
                seed: 3,
                default_base: PowerOfTwoBase::from_q(q).unwrap(),
            };
            let s = (spec.build)(
                &gartowen::core::ScramblerRequest::parse(spec.name).unwrap(),
                &ctx,
            )
            .unwrap();
            if !seen.insert((spec.name, s.base().q())) {
                continue;
            }
            for base in nested_bases(s.base()) {
                bases_checked.insert(base.base());
                if let Err(e) = check_base(s.as_ref(), Width::W32, base, Level::Quick, None) {
                    panic!("{} (base {}): {e}", s.name(), s.base().base());
                }
            }
        }
    }
    assert_eq!(
        bases_checked.into_iter().collect::<Vec<_>>(),
        vec![2, 4, 8, 16, 32, 64, 128, 256]
    );
}

/// Theorem T5's other side: a nested scramble in a base that is not a root of the net's base
/// may break the net. Base 16 on the base-8 Faure net, base 8 on sz16 and base 4 on the base-8
/// net each break it on some seed.
#[test]
fn a_scrambler_whose_base_the_net_is_not_nested_in_breaks_it_on_an_instance() {
    use gartowen::owen::{FullTreeOwen, OwenVariant};
    use gartowen::verify::nets::check_base;
    use gartowen::verify::Level;
    for (scramble_q, net_q) in [(4u32, 3u32), (3, 4), (2, 3)] {
        let broken = (0..8u64).find_map(|seed| {
            let s = FullTreeOwen::new(
                PowerOfTwoBase::from_q(scramble_q).unwrap(),
                OwenVariant::Uniform,
                seed,
            );
            check_base(
                &s,
                Width::W32,
                PowerOfTwoBase::from_q(net_q).unwrap(),
                Level::Quick,
                None,
            )
            .err()
        });
        let detail = broken.unwrap_or_else(|| {
            panic!(
                "base {} kept every base-{} net",
                1 << scramble_q,
                1 << net_q
            )
        });
        assert_eq!(detail.t, 0, "{detail}");
        assert!(detail.scrambled_t > 0, "{detail}");
        assert!(detail.m >= 1 && detail.dims.len() >= 3, "{detail}");
    }
}
