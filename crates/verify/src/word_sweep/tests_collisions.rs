//! Collisions at every depth, in every base, against a brute-force search: the scan decides
//! injectivity by blocks (a one-word bitmap) and by the digits each node's children take, so
//! a merge at any depth, partial last digit included, must be found and named exactly as the
//! first repeated output in word order names it.

use super::tests::Mapped;
use super::*;
use gartowen_core::SplitMix64;

/// The first input, in word order, whose output an earlier input already gave: (earlier, it,
/// output).
fn first_repeat(f: &dyn Fn(u64) -> u64, width: u32) -> Option<(u64, u64, u64)> {
    let mut seen = vec![u32::MAX; 1 << width];
    for x in 0..1u64 << width {
        let y = f(x);
        let slot = &mut seen[y as usize];
        if *slot != u32::MAX {
            return Some((u64::from(*slot), x, y));
        }
        *slot = x as u32;
    }
    None
}

/// Digit k of a `width`-bit word in base 2^q: its position (low bit) and bit count (a partial
/// last digit has fewer than q bits).
fn digit_at(width: u32, q: u32, k: u32) -> (u32, u32) {
    let top = width - q * k;
    let bits = q.min(top);
    (top - bits, bits)
}

#[test]
fn a_merge_at_any_depth_is_found_where_a_brute_force_search_finds_it() {
    let mut rng = SplitMix64::new(41);
    for q in 1..=8u32 {
        for width in [14u32, 16, 17] {
            let plan = SweepPlan::new(
                Width::new(width).unwrap(),
                PowerOfTwoBase::from_q(q).unwrap(),
            )
            .unwrap();
            let depths = width.div_ceil(q);
            for k in 0..depths {
                let (at, bits) = digit_at(width, q, k);
                let mask = (1u64 << bits) - 1;
                // A nested bijection (a digital shift), then, below one node of depth k (the
                // inputs with one k-digit prefix), output digit k's value e1 sent to e2: still
                // nested, no longer injective.
                let shift = rng.next_u64() & ((1u64 << width) - 1);
                let prefix = rng.next_u64() & ((1u64 << (width - at - bits)) - 1);
                let e1 = rng.next_u64() & mask;
                let e2 = (e1 + 1 + rng.next_u64() % mask.max(1)) & mask;
                assert_ne!(e1, e2);
                let f = move |x: u64| {
                    let y = x ^ shift;
                    let below = x >> (at + bits) == prefix;
                    if below && (y >> at) & mask == e1 {
                        y & !(mask << at) | e2 << at
                    } else {
                        y
                    }
                };
                let s = Mapped {
                    f: move |x, _| f(x),
                    base: plan.base(),
                    widths: vec![width],
                };
                let piece = sweep(&s, &plan, 0, 0..plan.chunks(), &|_| {}).unwrap();
                let (earlier, x, y) = first_repeat(&f, width).expect("a merge repeats outputs");
                let label = format!("q {q} width {width} depth {k}");
                if k >= plan.chunk_digits() {
                    assert_eq!(
                        piece.failure,
                        Some(SweepFailure::Collision {
                            inputs: [earlier, x],
                            output: y
                        }),
                        "{label}"
                    );
                } else {
                    // Chunks merge: found when the pieces' image prefixes are joined.
                    assert!(piece.failure.is_none(), "{label}: {:?}", piece.failure);
                    let verdict = combine(&[piece]).unwrap();
                    assert!(
                        matches!(verdict.failure, Some(SweepFailure::SubtreesMerged { .. })),
                        "{label}: {:?}",
                        verdict.failure
                    );
                }
            }
        }
    }
}

#[test]
fn a_true_bijection_passes_in_every_base_and_width() {
    // The same digital shifts, unbroken: no block, digit set or bitmap word may complain.
    let mut rng = SplitMix64::new(43);
    for q in 1..=8u32 {
        for width in [13u32, 16, 17] {
            let plan = SweepPlan::new(
                Width::new(width).unwrap(),
                PowerOfTwoBase::from_q(q).unwrap(),
            )
            .unwrap();
            let shift = rng.next_u64() & ((1u64 << width) - 1);
            let s = Mapped {
                f: move |x, _| x ^ shift,
                base: plan.base(),
                widths: vec![width],
            };
            let piece = sweep(&s, &plan, 0, 0..plan.chunks(), &|_| {}).unwrap();
            assert_eq!(piece.failure, None, "q {q} width {width}");
            assert!(combine(&[piece]).unwrap().passed, "q {q} width {width}");
        }
    }
}
