//! The sixteen-word scan, on every kernel this CPU runs, against the definition: the first
//! out-of-range output, non-nested consecutive pair or repeated output of a chunk in word
//! order, the seams between chunks, the chunks' image prefixes and the node laws counted node
//! by node.

use super::chunk_scan::{block_low_bits, node_cell, node_cells};
use super::group_scan::{self, GroupKernel};
use super::scan::sweep_with;
use super::tests::Mapped;
use super::*;
use gartowen_core::SplitMix64;

/// (q, width) pairs where groups apply: blocks of 16 and 32 words, blocks equal to chunks and
/// deeper ones (node digits between), node laws every word, every 4 words, every group and
/// every other group.
const GEOMETRIES: [(u32, u32); 8] = [
    (2, 16),
    (2, 20),
    (3, 17),
    (3, 20),
    (4, 16),
    (4, 20),
    (4, 24),
    (7, 19),
];

/// The geometries small enough to break in many ways (up to 2^20 words).
fn small_geometries() -> impl Iterator<Item = (u32, u32)> {
    GEOMETRIES.into_iter().filter(|&(_, width)| width <= 20)
}

fn plan(q: u32, width: u32) -> SweepPlan {
    SweepPlan::new(
        Width::new(width).unwrap(),
        PowerOfTwoBase::from_q(q).unwrap(),
    )
    .unwrap()
}

fn kernels() -> Vec<GroupKernel> {
    let mut k = vec![GroupKernel::Portable];
    if GroupKernel::detect() == GroupKernel::Avx512 {
        k.push(GroupKernel::Avx512);
    }
    k
}

/// A nested bijection with a different affine map e ↦ a·e + t (a odd) at every node, drawn
/// from a hash of the node's prefix.
fn affine_nodes(q: u32, width: u32, seed: u64) -> impl Fn(u64) -> u64 + Send + Sync + Copy {
    move |x| {
        let mut y = 0;
        let mut k = 0;
        while q * k < width {
            let top = width - q * k;
            let bits = q.min(top);
            let below = top - bits;
            let prefix = x >> top;
            let digit = (x >> below) & ((1 << bits) - 1);
            let h = SplitMix64::new(seed ^ (prefix << 6 | u64::from(k))).next_u64();
            let image = ((h | 1).wrapping_mul(digit) + (h >> 32)) & ((1 << bits) - 1);
            y |= image << below;
            k += 1;
        }
        y
    }
}

/// What a sweep of every chunk must report, by definition.
struct Expected {
    failure: Option<SweepFailure>,
    images: Vec<u64>,
    cells: Vec<Vec<(u32, u64)>>,
}

fn expected(f: &dyn Fn(u64) -> u64, plan: &SweepPlan) -> Expected {
    let (w, q, d) = (plan.width().bits(), plan.base().q(), plan.chunk_digits());
    let shift = w - plan.chunk_prefix_bits();
    let mut images = Vec::new();
    let mut last = 0;
    for c in 0..plan.chunks() {
        let start = plan.chunk_start(c);
        let words: Vec<u64> = (start..start + plan.chunk_words()).collect();
        let ys: Vec<u64> = words.iter().map(|&x| f(x)).collect();
        // The first repeat: sort (output, input) and take the second input of each run.
        let mut pairs: Vec<(u64, u64)> = ys.iter().copied().zip(words.iter().copied()).collect();
        pairs.sort_unstable();
        let repeat = pairs
            .windows(2)
            .filter(|p| p[0].0 == p[1].0)
            .map(|p| (p[1].1, p[0].1, p[0].0))
            .min();
        for (i, (&x, &y)) in words.iter().zip(&ys).enumerate() {
            let failure = if y > plan.width().mask() {
                Some(SweepFailure::OutOfRange {
                    input: x,
                    output: y,
                })
            } else if i == 0 {
                (c > 0).then(|| plan.seam_failure(x, last, y)).flatten()
            } else {
                plan.step_failure(x, ys[i - 1], y)
            };
            let failure = failure.or_else(|| {
                repeat
                    .filter(|r| r.0 == x)
                    .map(|(x, earlier, y)| SweepFailure::Collision {
                        inputs: [earlier, x],
                        output: y,
                    })
            });
            if failure.is_some() {
                return Expected {
                    failure,
                    images,
                    cells: Vec::new(),
                };
            }
        }
        images.push(ys[0] >> shift);
        last = *ys.last().unwrap();
    }
    // Node laws of depths d..L: each node's children's first words, digit k of their outputs.
    let cells = (d..plan.law_depths())
        .map(|k| {
            let below = w - q * (k + 1);
            let mut counts = vec![0u64; node_cells(1 << q)];
            for node in 0..1u64 << (q * k) {
                let images: Vec<u8> = (0..1u64 << q)
                    .map(|e| ((f((node << q | e) << below) >> below) & ((1 << q) - 1)) as u8)
                    .collect();
                if let Some(cell) = node_cell(&images) {
                    counts[cell as usize] += 1;
                }
            }
            let sparse = counts.into_iter().enumerate().filter(|&(_, n)| n > 0);
            sparse.map(|(cell, n)| (cell as u32, n)).collect()
        })
        .collect();
    Expected {
        failure: None,
        images,
        cells,
    }
}

/// Sweeps `f` with every kernel and checks each piece against the definition.
fn check(f: &(dyn Fn(u64) -> u64 + Sync), plan: &SweepPlan, label: &str) {
    let want = expected(f, plan);
    let s = Mapped {
        f: move |x, _| f(x),
        base: plan.base(),
        widths: vec![plan.width().bits()],
    };
    for kernel in kernels() {
        let piece = sweep_with(&s, plan, 0, 0..plan.chunks(), &|_| {}, kernel).unwrap();
        let label = format!("{label} {kernel:?}");
        assert_eq!(piece.failure, want.failure, "{label}");
        if want.failure.is_none() {
            assert_eq!(piece.images, want.images, "{label}");
            assert_eq!(piece.node_cells, want.cells, "{label}");
            assert_eq!(piece.words, plan.words(), "{label}");
            assert_eq!(piece.rescanned_chunks, 0, "{label}");
        } else {
            // Exactly the failing chunk was rejected by the groups and named word by word.
            assert_eq!(piece.rescanned_chunks, 1, "{label}");
        }
    }
}

#[test]
fn the_geometries_cover_both_block_sizes_and_every_law_spacing() {
    let mut blocks = Vec::new();
    let mut law_masks = Vec::new();
    for (q, width) in GEOMETRIES {
        let p = plan(q, width);
        assert!(group_scan::applies(&p), "q {q} width {width}");
        blocks.push(block_low_bits(&p));
        law_masks.push(width - q * p.law_depths());
    }
    for bits in [4, 5] {
        assert!(blocks.contains(&bits));
    }
    for low in [0, 2, 4, 5] {
        assert!(law_masks.contains(&low), "{law_masks:?}");
    }
    // Groups need blocks of 16 or 32 words: not base 2, not blocks of 2 or 256 words.
    assert!(!group_scan::applies(&plan(1, 20)));
    assert!(!group_scan::applies(&plan(5, 16)));
    assert!(!group_scan::applies(&plan(8, 24)));
}

#[test]
fn true_bijections_pass_with_the_definitions_images_and_node_laws() {
    for (q, width) in GEOMETRIES {
        let p = plan(q, width);
        check(
            &affine_nodes(q, width, 5),
            &p,
            &format!("q {q} width {width}"),
        );
        let shift = 0x5a5a_5a5a & p.width().mask();
        check(&|x| x ^ shift, &p, &format!("q {q} width {width} shift"));
    }
}

#[test]
fn every_kind_of_break_at_every_lane_is_named_as_the_definition_names_it() {
    let mut rng = SplitMix64::new(77);
    for (q, width) in small_geometries() {
        let p = plan(q, width);
        let mask = p.width().mask();
        // The unbroken outputs, tabulated once.
        let table: Vec<u64> = (0..1u64 << width).map(affine_nodes(q, width, 9)).collect();
        let good = |x: u64| table[x as usize];
        // Words at a chunk's start, a block's, a group's first and last lane, anywhere.
        let block = (1u64 << block_low_bits(&p)) - 1;
        let mut at = |align: u64, set: u64| (rng.next_u64() & mask & !align) | set;
        let words = [
            0,
            mask,
            at(p.chunk_words() - 1, 0),
            at(block, 0),
            at(15, 0),
            at(0, 15),
            at(0, 0),
        ];
        let (bit, far) = (rng.next_u64() % u64::from(width), 1u64 << 40);
        for x0 in words {
            let label = format!("q {q} width {width} word {x0:#x}");
            // One output bit flipped: a repeat, a non-nested pair or both.
            check(
                &|x| good(x) ^ (u64::from(x == x0) << bit),
                &p,
                &format!("{label} bit {bit}"),
            );
            // Outputs past the width, just past it or past 32 bits (read as u32::MAX).
            for over in [1u64 << width, far] {
                check(
                    &|x| good(x) | if x == x0 { over } else { 0 },
                    &p,
                    &format!("{label} over {over:#x}"),
                );
            }
            // Two words of one leaf node exchanged: still nested and bijective, so it passes.
            let partner = x0 ^ 1;
            check(
                &|x| match x {
                    x if x == x0 => good(partner),
                    x if x == partner => good(x0),
                    x => good(x),
                },
                &p,
                &format!("{label} leaf swap"),
            );
        }
    }
}

#[test]
fn a_merge_at_every_depth_below_the_chunks_is_named_as_the_definition_names_it() {
    let mut rng = SplitMix64::new(78);
    for (q, width) in small_geometries() {
        let p = plan(q, width);
        let good = affine_nodes(q, width, 11);
        for k in p.chunk_digits()..width.div_ceil(q) {
            // Below one node of depth k, output digit k's value e1 sent to e2 (both taken
            // by siblings): nested, not injective.
            let top = width - q * k;
            let bits = q.min(top);
            let below = top - bits;
            let digit = (1u64 << bits) - 1;
            let prefix = rng.next_u64() & ((1u64 << (width - top)) - 1);
            let e1 = rng.next_u64() & digit;
            let e2 = (e1 + 1 + rng.next_u64() % digit.max(1)) & digit;
            let f = move |x: u64| {
                let y = good(x);
                if x >> top == prefix && (y >> below) & digit == e1 {
                    y & !(digit << below) | e2 << below
                } else {
                    y
                }
            };
            check(&f, &p, &format!("q {q} width {width} depth {k}"));
        }
    }
}

#[test]
fn a_break_at_a_frame_seam_inside_a_chunk_is_named() {
    // Base 128 at 32 bits: chunks of 2^25 words span 32 frames. The words of chunk 0 from
    // 2^20 on have digit 0 of their outputs changed, consistently, so the only pair that shows
    // it is the one across the seam of frames 0 and 1: (2^20 − 1, 2^20).
    let p = plan(7, 32);
    assert!(group_scan::applies(&p) && p.chunk_words() > 1 << 20);
    let seam = 1u64 << 20;
    let f = move |x: u64| {
        let y = x ^ 0x5a5a_5a5a;
        if (seam..p.chunk_words()).contains(&x) {
            y ^ 1 << 25
        } else {
            y
        }
    };
    let s = Mapped {
        f: move |x, _| f(x),
        base: p.base(),
        widths: vec![32],
    };
    for kernel in kernels() {
        let piece = sweep_with(&s, &p, 0, 0..p.chunks(), &|_| {}, kernel).unwrap();
        assert_eq!(
            piece.failure,
            p.step_failure(seam, f(seam - 1), f(seam)),
            "{kernel:?}"
        );
        assert!(piece.failure.is_some());
    }
}
