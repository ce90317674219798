use super::*;
use gartowen_core::{Claim, SplitMix64};
use gartowen_owen::{FullTreeOwen, OwenVariant};

/// A map given by a closure, at the widths listed (for broken and partial variants).
pub(super) struct Mapped<F> {
    pub(super) f: F,
    pub(super) base: PowerOfTwoBase,
    pub(super) widths: Vec<u32>,
}

impl<F: Fn(u64, u32) -> u64 + Send + Sync> Scrambler for Mapped<F> {
    fn name(&self) -> String {
        "mapped".into()
    }
    fn base(&self) -> PowerOfTwoBase {
        self.base
    }
    fn claim(&self) -> Claim {
        Claim::NESTED
    }
    fn supports_width(&self, width: Width) -> bool {
        self.widths.contains(&width.bits())
    }
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        (self.f)(x, dim)
    }
}

pub(super) fn w(bits: u32) -> Width {
    Width::new(bits).unwrap()
}

pub(super) fn b(q: u32) -> PowerOfTwoBase {
    PowerOfTwoBase::from_q(q).unwrap()
}

fn oracle(q: u32, seed: u64) -> FullTreeOwen {
    FullTreeOwen::new(b(q), OwenVariant::Uniform, seed)
}

/// The whole dimension in one piece, combined.
pub(super) fn whole(s: &dyn Scrambler, width: Width, dim: u32) -> SweepVerdict {
    let plan = SweepPlan::new(width, s.base()).unwrap();
    let piece = sweep(s, &plan, dim, 0..plan.chunks(), &|_| {}).unwrap();
    combine(&[piece]).unwrap()
}

/// `oracle` with the outputs of `a` and `b` exchanged: still a bijection.
fn swapped(q: u32, width: u32, a: u64, c: u64) -> Mapped<impl Fn(u64, u32) -> u64 + Send + Sync> {
    let o = oracle(q, 7);
    let ww = w(width);
    Mapped {
        f: move |x, dim| {
            let x = if x == a {
                c
            } else if x == c {
                a
            } else {
                x
            };
            o.scramble(x, ww, dim)
        },
        base: b(q),
        widths: vec![width],
    }
}

#[test]
fn plans_have_the_stated_geometry_and_refuse_words_past_32_bits() {
    // (q, chunk digits, chunks, words per chunk, law depths) at 32 bits.
    let expected = [
        (1, 12, 1 << 12, 1 << 20, 22),
        (2, 6, 1 << 12, 1 << 20, 11),
        (3, 4, 1 << 12, 1 << 20, 7),
        (4, 3, 1 << 12, 1 << 20, 5),
        (5, 2, 1 << 10, 1 << 22, 4),
        (6, 2, 1 << 12, 1 << 20, 3),
        (7, 1, 1 << 7, 1 << 25, 3),
        (8, 1, 1 << 8, 1 << 24, 2),
    ];
    for (q, d, chunks, per, laws) in expected {
        let p = SweepPlan::new(Width::W32, b(q)).unwrap();
        assert_eq!(
            (
                p.chunk_digits(),
                p.chunks(),
                p.chunk_words(),
                p.law_depths()
            ),
            (d, chunks, per, laws),
            "q = {q}"
        );
        assert_eq!(p.chunks() * p.chunk_words(), 1 << 32);
        assert_eq!(p.full_digits(), 32 / q);
    }
    let small = SweepPlan::new(w(8), b(3)).unwrap();
    assert_eq!((small.chunk_digits(), small.law_depths()), (2, 2));
    for bits in [33, 48, 64] {
        let e = SweepPlan::new(w(bits), b(1)).unwrap_err();
        assert_eq!(e, SweepError::TooWide(bits));
        assert!(e.to_string().contains("cannot be enumerated"), "{e}");
    }
}

#[test]
fn plans_take_32_bits_then_24_and_refuse_a_scrambler_with_neither() {
    let only = |widths: Vec<u32>| Mapped {
        f: |x, _| x,
        base: b(2),
        widths,
    };
    let p = SweepPlan::for_scrambler(&only(vec![24, 32, 64])).unwrap();
    assert_eq!(p.width().bits(), 32);
    let p = SweepPlan::for_scrambler(&only(vec![24, 64])).unwrap();
    assert_eq!((p.width().bits(), p.base().base()), (24, 4));
    let e = SweepPlan::for_scrambler(&only(vec![64])).unwrap_err();
    assert_eq!(e, SweepError::NoSweepableWidth("mapped".into()));
}

#[test]
fn shared_digits_and_free_bits_agree_with_digit_by_digit_comparison() {
    let width = w(12);
    for q in 1..=8 {
        let plan = SweepPlan::new(width, b(q)).unwrap();
        let layout = gartowen_core::DigitLayout::new(width, b(q));
        let brute = |a: u64, c: u64| {
            (0..layout.num_digits())
                .take_while(|&k| layout.get(a, k) == layout.get(c, k))
                .count() as u32
        };
        let mut rng = SplitMix64::new(q as u64);
        for _ in 0..2000 {
            let (a, c) = (rng.next_u64() & 0xfff, rng.next_u64() & 0xfff);
            assert_eq!(
                plan.shared_digits(a, c),
                brute(a, c),
                "q {q}: {a:#x} {c:#x}"
            );
        }
        for x in 1..4096u64 {
            let s = brute(x - 1, x);
            assert_eq!(plan.free_bits_after(x), 12 - q * s, "q {q} x {x:#x}");
            // Outputs that differ in the lowest forbidden bit fail; in the highest free one pass.
            let free = plan.free_bits_after(x);
            if free < 12 {
                assert!(plan.step_failure(x, 0, 1 << free).is_some());
            }
            assert!(plan.step_failure(x, 0, (1 << free) - 1).is_none());
        }
    }
}

#[test]
fn oracles_pass_in_every_base_and_certify_every_word() {
    for q in 1..=8 {
        for variant in OwenVariant::ALL {
            let s = FullTreeOwen::new(b(q), variant, 11);
            let v = whole(&s, w(16), 3);
            assert!(v.passed, "q {q} {variant:?}: {:?}", v.failure);
            assert_eq!(v.words, 1 << 16);
            assert_eq!(
                v.statement,
                format!(
                    "bijective and nested at every depth on all 65536 16-bit words, dimension 3, \
                     base {}",
                    1 << q
                )
            );
        }
    }
}

#[test]
fn the_base_2_test_passes_a_true_scramble_without_the_bitmap_and_calls_it_on_a_broken_one() {
    let plan = SweepPlan::new(w(16), b(1)).unwrap();
    let good = sweep(&oracle(1, 4), &plan, 0, 0..plan.chunks(), &|_| {}).unwrap();
    assert!(good.failure.is_none());
    assert_eq!(good.rescanned_chunks, 0);
    let bad = swapped(1, 16, 0x1234, 0x1224);
    let piece = sweep(&bad, &plan, 0, 0..plan.chunks(), &|_| {}).unwrap();
    assert!(piece.failure.is_some());
    assert!(piece.rescanned_chunks >= 1);
    // Base 32 at 16 bits takes neither the binary test nor groups (blocks of 2 words).
    let plan32 = SweepPlan::new(w(16), b(5)).unwrap();
    let p32 = sweep(
        &swapped(5, 16, 0x1234, 0x1224),
        &plan32,
        0,
        0..plan32.chunks(),
        &|_| {},
    );
    let p32 = p32.unwrap();
    assert!(p32.failure.is_some());
    assert_eq!(p32.rescanned_chunks, 0);
}

#[test]
fn a_swap_across_two_deep_subtrees_is_named() {
    // 0x1234 and 0x1234 ^ 0x10 share 11 bits: different subtrees of a depth-11 node.
    let (a, c) = (0x1234, 0x1234 ^ 0x10);
    let s = swapped(1, 16, a, c);
    let v = whole(&s, w(16), 0);
    assert!(!v.passed);
    match v.failure.unwrap() {
        SweepFailure::NotNested {
            inputs,
            input_digits,
            output_digits,
            ..
        } => {
            // The smaller word, 0x1224, is reached first; x − 1 = 0x1223 shares 13 bits with it.
            assert_eq!(inputs, [c - 1, c]);
            assert_eq!(input_digits, 13);
            assert_eq!(output_digits, 11);
        }
        f => panic!("{f:?}"),
    }
    assert!(v.statement.contains("0x1223 and 0x1224"), "{}", v.statement);
}

#[test]
fn a_collision_names_both_inputs_and_the_output() {
    // 0xa55 and 0xa57 differ in the last base-4 digit only, so f(0xa53) := f(0xa51) keeps
    // every nesting relation and collides.
    let (a, c) = (0x0a55, 0x0a57);
    let o = oracle(2, 3);
    let y = o.scramble(a, w(16), 0);
    let s = Mapped {
        f: move |x, dim| o.scramble(if x == c { a } else { x }, w(16), dim),
        base: b(2),
        widths: vec![16],
    };
    let f = whole(&s, w(16), 0).failure.unwrap();
    assert_eq!(
        f,
        SweepFailure::Collision {
            inputs: [a, c],
            output: y
        }
    );
    assert!(f
        .describe(4)
        .contains("nested but not injective: inputs 0xa55 and 0xa57 both give"));
    // 32 bits, base 32: a node map at depth 2 sends child 16 where child 8 goes, so the
    // collision's partner is 2^20 words back, in the chunk's second frame of four (the rescan
    // walks past the first).
    let collapse = |x: u64, _| {
        if (x >> 17) & 31 == 16 {
            x & !(31 << 17) | 8 << 17
        } else {
            x
        }
    };
    let s = Mapped {
        f: collapse,
        base: b(5),
        widths: vec![32],
    };
    let plan = SweepPlan::new(Width::W32, b(5)).unwrap();
    let start = plan.chunk_start(3);
    let piece = sweep(&s, &plan, 0, 3..4, &|_| {}).unwrap();
    assert_eq!(
        piece.failure,
        Some(SweepFailure::Collision {
            inputs: [start + (1 << 20), start + (1 << 21)],
            output: start + (1 << 20)
        })
    );
    // In a later frame of a 32-bit chunk: the partner is found by the rescan.
    let (a, c) = (0x0010_0003u64, 0x001f_fff3u64);
    let s = Mapped {
        f: move |x, _| if x == c { a } else { x },
        base: b(1),
        widths: vec![32],
    };
    let plan = SweepPlan::new(Width::W32, b(1)).unwrap();
    let piece = sweep(&s, &plan, 0, 1..2, &|_| {}).unwrap();
    assert!(matches!(
        piece.failure,
        Some(SweepFailure::NotNested { .. })
    ));
}

#[test]
fn subtrees_merged_by_a_shallow_node_are_named() {
    // The top bit forced to 0: nested, injective inside every chunk, but chunks c and c + 2^11
    // share an image.
    let s = Mapped {
        f: |x, _| x & 0x7fff,
        base: b(1),
        widths: vec![16],
    };
    let f = whole(&s, w(16), 0).failure.unwrap();
    assert_eq!(
        f,
        SweepFailure::SubtreesMerged {
            subtrees: [0, 2048],
            first_words: [0, 0x8000],
            image: 0,
            depth: 12,
        }
    );
    assert!(f.describe(2).contains("both map onto subtree 0x0"));
}

#[test]
fn an_output_wider_than_the_word_is_named() {
    let s = Mapped {
        f: |x, _| if x == 0x4321 { 0x1_0000 } else { x },
        base: b(1),
        widths: vec![16],
    };
    let f = whole(&s, w(16), 0).failure.unwrap();
    assert_eq!(
        f,
        SweepFailure::OutOfRange {
            input: 0x4321,
            output: 0x1_0000
        }
    );
    // At a chunk's first word too.
    let s = Mapped {
        f: |x, _| if x == 0x4320 { 0x1_0000 } else { x },
        base: b(1),
        widths: vec![16],
    };
    assert_eq!(
        whole(&s, w(16), 0).failure,
        Some(SweepFailure::OutOfRange {
            input: 0x4320,
            output: 0x1_0000
        })
    );
}

#[test]
fn failures_at_chunk_seams_are_found_inside_a_piece_and_between_pieces() {
    // Swap the first words of chunks 5 and 6 (0x50 and 0x60 at 16 bits in base 2: the seams
    // 0x4f/0x50 and 0x5f/0x60 see outputs from other subtrees).
    let s = swapped(1, 16, 0x50, 0x60);
    let plan = SweepPlan::new(w(16), b(1)).unwrap();
    let one = sweep(&s, &plan, 0, 0..plan.chunks(), &|_| {}).unwrap();
    let split: Vec<SweepPiece> = [0..5, 5..4096]
        .into_iter()
        .map(|r| sweep(&s, &plan, 0, r, &|_| {}).unwrap())
        .collect();
    let (a, c) = (combine(&[one]).unwrap(), combine(&split).unwrap());
    assert_eq!(a.failure, c.failure);
    match a.failure.unwrap() {
        SweepFailure::NotNested { inputs, .. } => assert_eq!(inputs, [0x4f, 0x50]),
        f => panic!("{f:?}"),
    }
}

#[test]
fn a_seam_whose_second_output_is_the_largest_word_is_still_checked() {
    // f(0x50) = 0xffff (and back): the seam 0x4f/0x50 between chunks 4 and 5 fails first, in
    // one piece or split at the seam.
    let s = Mapped {
        f: |x, _| match x {
            0x50 => 0xffff,
            0xffff => 0x50,
            x => x,
        },
        base: b(1),
        widths: vec![16],
    };
    let plan = SweepPlan::new(w(16), b(1)).unwrap();
    let split: Vec<SweepPiece> = [0..5, 5..4096]
        .into_iter()
        .map(|r| sweep(&s, &plan, 0, r, &|_| {}).unwrap())
        .collect();
    for v in [whole(&s, w(16), 0), combine(&split).unwrap()] {
        match v.failure.unwrap() {
            SweepFailure::NotNested {
                inputs, outputs, ..
            } => {
                assert_eq!((inputs, outputs), ([0x4f, 0x50], [0x4f, 0xffff]))
            }
            f => panic!("{f:?}"),
        }
    }
}

#[test]
fn pieces_combine_to_the_unsharded_verdict_for_any_split() {
    let s = oracle(2, 5);
    let plan = SweepPlan::new(w(14), b(2)).unwrap();
    let all = combine(&[sweep(&s, &plan, 1, 0..plan.chunks(), &|_| {}).unwrap()]).unwrap();
    assert!(all.passed);
    for n in [2, 3, 5, 7] {
        let mut pieces: Vec<SweepPiece> = (1..=n)
            .map(|i| {
                let r = shard_range(plan.chunks(), i, n);
                sweep(&s, &plan, 1, r, &|_| {}).unwrap()
            })
            .collect();
        pieces.reverse(); // any order
        assert_eq!(combine(&pieces).unwrap(), all, "{n} pieces");
    }
}

#[test]
fn missing_doubled_and_foreign_pieces_are_refused() {
    let s = oracle(1, 5);
    let plan = SweepPlan::new(w(14), b(1)).unwrap();
    let piece = |r: Range<u64>, dim| sweep(&s, &plan, dim, r, &|_| {}).unwrap();
    let (a, b_, c) = (piece(0..100, 0), piece(100..200, 0), piece(200..4096, 0));
    let err = |ps: &[SweepPiece]| combine(ps).unwrap_err().to_string();
    assert!(err(&[a.clone(), c.clone()]).contains("chunks 100..200"));
    assert!(err(&[a.clone(), b_.clone()]).contains("chunks 200..4096"));
    assert!(err(&[b_.clone(), c.clone()]).contains("chunks 0..100"));
    assert!(err(&[a.clone(), a.clone(), b_.clone(), c.clone()]).contains("covered twice"));
    assert!(err(&[a.clone(), b_.clone(), piece(200..4096, 1)]).contains("dimension 1"));
    assert!(err(&[]).contains("no pieces"));
    let mut short = b_.clone();
    short.images.pop();
    assert!(err(&[a.clone(), short, c.clone()]).contains("99 images"));
    let mut wrong = b_.clone();
    wrong.node_cells.pop();
    assert!(err(&[a.clone(), wrong, c.clone()]).contains("node laws"));
    let mut miscounted = b_.clone();
    miscounted.node_cells[0][0].1 += 1;
    assert!(err(&[a.clone(), miscounted, c.clone()]).contains("node laws count"));
    let mut overflowing = b_.clone();
    overflowing.node_cells[0][0].1 = u64::MAX;
    assert!(err(&[a.clone(), overflowing, c.clone()]).contains("node laws count"));
    let mut bad_image = b_.clone();
    bad_image.images[0] = 1 << 20;
    assert!(err(&[a, bad_image, c]).contains("out of range"));
    assert_eq!(
        sweep(&s, &plan, 0, 10..10, &|_| {}).unwrap_err(),
        SweepError::BadRange {
            start: 10,
            end: 10,
            chunks: 4096
        }
    );
    assert!(sweep(&s, &plan, 0, 0..4097, &|_| {}).is_err());
}

#[test]
fn shards_cut_every_unit_once_and_runs_split_across_segments() {
    for total in [0u64, 1, 7, 4096, 12_288] {
        for n in 1..=9 {
            let mut next = 0;
            for i in 1..=n {
                let r = shard_range(total, i, n);
                assert_eq!(r.start, next);
                assert!(r.end - r.start <= total.div_ceil(n));
                next = r.end;
            }
            assert_eq!(next, total);
        }
    }
    assert_eq!(
        split_run(&[10, 10, 5], 7..22),
        vec![(0, 7..10), (1, 0..10), (2, 0..2)]
    );
    assert_eq!(split_run(&[10, 10], 10..20), vec![(1, 0..10)]);
    assert!(split_run(&[10], 3..3).is_empty());
}

#[test]
fn widths_below_32_use_the_wide_batch_path_and_32_the_narrow_one() {
    // A map that answers differently on the two paths: the 32-bit sweep must see the u32 path.
    struct Paths;
    impl Scrambler for Paths {
        fn name(&self) -> String {
            "paths".into()
        }
        fn base(&self) -> PowerOfTwoBase {
            PowerOfTwoBase::B2
        }
        fn claim(&self) -> Claim {
            Claim::NESTED
        }
        fn scramble(&self, x: u64, _: Width, _: u32) -> u64 {
            x
        }
        fn scramble_batch_u32(&self, words: &mut [u32], _: u32) {
            for x in words.iter_mut() {
                if *x == 0xdead_beef {
                    *x = 0;
                }
            }
        }
        fn inverse(&self) -> Option<&dyn gartowen_core::Unscramble> {
            Some(self)
        }
    }

    impl gartowen_core::Unscramble for Paths {
        fn unscramble(&self, y: u64, _: Width, _: u32) -> u64 {
            y
        }
    }
    let plan = SweepPlan::new(Width::W32, PowerOfTwoBase::B2).unwrap();
    let c = 0xdead_beef >> 20;
    let piece = sweep(&Paths, &plan, 0, c..c + 1, &|_| {}).unwrap();
    assert!(matches!(
        piece.failure,
        Some(SweepFailure::NotNested {
            inputs: [0xdead_beee, 0xdead_beef],
            ..
        })
    ));
    let ok = whole(&Paths, w(20), 0);
    assert!(ok.passed);
}

#[test]
fn progress_counts_every_word_once() {
    use std::sync::atomic::{AtomicU64, Ordering};
    let s = oracle(4, 2);
    let plan = SweepPlan::new(w(18), b(4)).unwrap();
    let seen = AtomicU64::new(0);
    let p = sweep(&s, &plan, 0, 0..plan.chunks(), &|n| {
        seen.fetch_add(n, Ordering::Relaxed);
    })
    .unwrap();
    assert_eq!(seen.into_inner(), 1 << 18);
    assert_eq!(p.words, 1 << 18);
    assert_eq!(p.first_output, s.scramble(0, w(18), 0));
    assert_eq!(p.last_output, s.scramble((1 << 18) - 1, w(18), 0));
}

#[test]
fn the_largest_word_is_a_valid_output_at_a_chunk_start() {
    // Complementing every bit is nested and bijective; chunk 0 starts with output 0xffff.
    let s = Mapped {
        f: |x: u64, _| !x & 0xffff,
        base: b(1),
        widths: vec![16],
    };
    let v = whole(&s, w(16), 0);
    assert!(v.passed, "{}", v.statement);
}
