//! The batch paths of this crate against their scalar paths, bit for bit: every ART variant
//! with every batch kernel this CPU runs (tables small and large, a mutant grammar, widths
//! with and without partial tail digits, word counts leaving remainders after the SIMD blocks
//! and the interleaved lanes), and the LK and per-bit hashes. The registry-wide version is
//! the root test `tests/batch_paths.rs`.

use gartowen_art::peers::{LkFlavor, LkHash, PerBitOwen};
use gartowen_art::{ArtMutant, ArtOwen, ArtVariant, BatchKernel};
use gartowen_core::ScramblerExt;
use gartowen_core::{Scrambler, SplitMix64, Width};

fn words(seed: u64, len: usize) -> Vec<u64> {
    let mut rng = SplitMix64::new(seed);
    (0..len).map(|_| rng.next_u64()).collect()
}

fn assert_batch_equals_scalar(s: &dyn Scrambler, reference: &dyn Scrambler, label: &str) {
    // 64·3 + 8·2 + 5 = 213 words: four gather blocks of 48 and 21 words, which the gather
    // kernels take as a padded block; the u32 input below leaves 45 after its whole blocks.
    // The portable kernel walks 26 lanes of eight and finishes 5 words one by one. (The root
    // test `tests/batch_paths.rs` leaves gather kernels remainders under 16 words as well.)
    let input = words(7, 64 * 3 + 8 * 2 + 5);
    for bits in [1u32, 5, 8, 13, 24, 26, 28, 30, 31, 32, 33, 48, 64] {
        let width = Width::new(bits).unwrap();
        if !s.supports_width(width) {
            continue;
        }
        for dim in [0u32, 4, 1000] {
            let mut batch: Vec<u64> = input.iter().map(|&w| w & width.mask()).collect();
            let original = batch.clone();
            s.scramble_batch(&mut batch, width, dim);
            for (i, (&x, &y)) in original.iter().zip(&batch).enumerate() {
                assert_eq!(
                    y,
                    reference.scramble(x, width, dim),
                    "{label}: width {bits} dim {dim} word {i} ({x:#x})"
                );
            }
        }
    }
    if s.supports_width(Width::W32) {
        // Two whole chunks of the default u32 path, then a partial one.
        let input: Vec<u32> = words(8, 2 * gartowen_core::U32_BATCH_CHUNK + 45)
            .iter()
            .map(|&w| w as u32)
            .collect();
        let mut batch = input.clone();
        s.scramble_batch_u32(&mut batch, 2);
        for (&x, &y) in input.iter().zip(&batch) {
            assert_eq!(y, reference.scramble_u32(x, 2), "{label}: u32 batch {x:#x}");
        }
    }
}

#[test]
fn every_art_kernel_equals_the_scalar_path() {
    let kernels = BatchKernel::available();
    assert!(kernels.contains(&BatchKernel::Portable));
    assert_eq!(
        kernels.contains(&BatchKernel::Avx512),
        BatchKernel::detect() == BatchKernel::Avx512Narrow
    );
    assert_eq!(
        kernels.contains(&BatchKernel::Avx512Narrow),
        kernels.contains(&BatchKernel::Avx512)
    );
    for variant in ArtVariant::all() {
        for (symbols, mutant) in [
            (2usize, ArtMutant::None),
            (256, ArtMutant::None),
            (1024, ArtMutant::None),
            (256, ArtMutant::NeverDescends),
            (256, ArtMutant::StuckCodeBit),
        ] {
            let art = ArtOwen::with_mutant(variant, symbols, 11, mutant).unwrap();
            // The narrow table exists exactly when the alphabet fits in two steps' bits, so
            // both gather kernels are walked here (2 and 256 symbols narrow in every base,
            // with one or two wide steps; 1024 only where the steps are wide).
            let n = art.grammar().symbols() as usize;
            let sb = art.batch_step_bits();
            assert_eq!(
                art.has_narrow_table(),
                sb > 0 && n <= 1 << (2 * sb),
                "{} table {symbols}",
                variant.name()
            );
            for &kernel in &kernels {
                let s = art.with_kernel(kernel).expect("an available kernel");
                let label = format!("{} table {symbols} {mutant:?} {kernel:?}", variant.name());
                assert_batch_equals_scalar(&s, &art, &label);
            }
        }
    }
}

#[test]
fn the_digit_loop_equals_the_step_tables_on_every_width() {
    // The scalar path's step tables against the plain digit-by-digit loop: the batch tables
    // are built from the same steps, so this anchors both.
    for variant in ArtVariant::all() {
        let art = ArtOwen::new(variant, 256, 5).unwrap().with_step_tables();
        for bits in [3u32, 7, 16, 29, 32, 40, 64] {
            let width = Width::new(bits).unwrap();
            for x in words(9, 50) {
                let x = x & width.mask();
                assert_eq!(
                    art.scramble(x, width, 3),
                    art.scramble_digit_by_digit(x, width, 3),
                    "{} width {bits}",
                    variant.name()
                );
            }
        }
    }
}

#[test]
fn hash_batches_equal_their_scalar_paths() {
    for flavor in [LkFlavor::Classic, LkFlavor::Improved] {
        let s = LkHash::new(flavor, 3);
        assert_batch_equals_scalar(&s, &s.clone(), &format!("{flavor:?}"));
    }
    let s = PerBitOwen::new(3);
    assert_batch_equals_scalar(&s, &s.clone(), "per-bit");
}

#[test]
fn a_kernel_is_only_offered_where_it_runs() {
    let art = ArtOwen::new(ArtVariant::ArtOwen2, 256, 1).unwrap();
    assert!(art.with_kernel(BatchKernel::Portable).is_some());
    assert_eq!(
        art.with_kernel(BatchKernel::Avx512).is_some(),
        BatchKernel::available().contains(&BatchKernel::Avx512)
    );
}

#[test]
fn with_kernel_really_switches_the_kernel() {
    let art = ArtOwen::new(ArtVariant::ArtOwen2, 256, 1).unwrap();
    for kernel in BatchKernel::available() {
        assert_eq!(art.with_kernel(kernel).unwrap().kernel(), kernel);
    }
    assert_eq!(art.kernel(), BatchKernel::detect());
}

#[test]
fn batch_steps_are_as_wide_as_the_table_budget_allows() {
    // The rule: m = ⌊8/q⌋ digits per step (at least 1), reduced while symbols · 2^(q·m) · 8
    // bytes exceed BATCH_TABLE_BYTES; the table holds exactly symbols · 2^(q·m) entries.
    use gartowen_art::BATCH_TABLE_BYTES;
    for variant in ArtVariant::all() {
        let q = variant.q();
        for symbols in [2usize, 256, 1024] {
            let art = ArtOwen::new(variant, symbols, 1).unwrap();
            let n = art.grammar().symbols() as usize;
            let mut m = (8 / q).max(1);
            while m > 1 && (n << (q * m)) * 8 > BATCH_TABLE_BYTES {
                m -= 1;
            }
            assert_eq!(
                art.batch_step_bits(),
                q * m,
                "{} with {n} symbols",
                variant.name()
            );
            assert!(m == 1 || (n << (q * m)) * 8 <= BATCH_TABLE_BYTES);
        }
    }
}

#[test]
fn large_tables_take_narrow_steps_and_still_equal_the_scalar_path() {
    // 16,384 and 65,536 symbols push binary and base-4 tables down to 1- to 4-bit steps.
    for variant in [ArtVariant::ArtOwen2, ArtVariant::QArt4] {
        for symbols in [16_384usize, 65_536] {
            let art = ArtOwen::new(variant, symbols, 3).unwrap();
            assert!(art.batch_step_bits() <= 4, "{}", art.batch_step_bits());
            for kernel in BatchKernel::available() {
                let s = art.with_kernel(kernel).unwrap();
                let label = format!("{} table {symbols} {kernel:?}", variant.name());
                assert_batch_equals_scalar(&s, &art, &label);
            }
        }
    }
}

#[test]
fn batch_tables_are_built_once_the_words_pay_for_them_and_change_no_output() {
    use gartowen_art::BATCH_TABLES_AFTER_WORDS;
    let after = BATCH_TABLES_AFTER_WORDS as usize;
    for variant in [
        ArtVariant::ArtOwen2,
        ArtVariant::ArtOwen16P,
        ArtVariant::Matrix(8),
    ] {
        let check = |art: &ArtOwen, input: &[u64], label: &str| {
            let mut batch = input.to_vec();
            art.scramble_batch(&mut batch, Width::W32, 5);
            for (&x, &y) in input.iter().zip(&batch) {
                assert_eq!(y, art.scramble(x, Width::W32, 5), "{label} {x:#x}");
            }
        };
        let small: Vec<u64> = words(1, 1000).iter().map(|w| w & 0xFFFF_FFFF).collect();
        let rest: Vec<u64> = words(2, after - 1000)
            .iter()
            .map(|w| w & 0xFFFF_FFFF)
            .collect();
        // Small calls walk the split tables; their words count towards the build.
        let art = ArtOwen::new(variant, 256, 4).unwrap();
        assert!(
            !art.batch_tables_built(),
            "{} built eagerly",
            variant.name()
        );
        check(&art, &small, "before");
        let mut wide = small.clone();
        art.scramble_batch(&mut wide, Width::W64, 5);
        assert!(!art.batch_tables_built(), "{}", variant.name());
        check(&art, &rest[..after - 2001], "still short");
        assert!(!art.batch_tables_built(), "{} built early", variant.name());
        // A clone keeps the count: its next words pay as the original's would.
        let twin = art.clone();
        check(&twin, &rest[after - 2001..], "the clone's word that pays");
        assert!(twin.batch_tables_built() && !art.batch_tables_built());
        check(&art, &rest[after - 2001..], "the word that pays");
        assert!(art.batch_tables_built(), "{} never built", variant.name());
        check(&art, &small, "after");
        // One call of that many words builds them at once, and a clone keeps them.
        let fresh = ArtOwen::new(variant, 256, 4).unwrap();
        let mut all = rest.clone();
        all.extend_from_slice(&small);
        check(&fresh, &all, "one call");
        assert!(fresh.batch_tables_built() && fresh.clone().batch_tables_built());
    }
}

#[test]
fn step_tables_are_built_once_the_words_pay_for_them_and_change_no_output() {
    use gartowen_art::STEP_TABLES_AFTER_WORDS;
    let after = STEP_TABLES_AFTER_WORDS as usize;
    for variant in [
        ArtVariant::ArtOwen2,
        ArtVariant::QArt4,
        ArtVariant::ArtOwen16P,
        ArtVariant::Matrix(8),
    ] {
        let name = variant.name();
        let reference = ArtOwen::new(variant, 256, 4).unwrap().with_step_tables();
        let xs = words(3, after);
        let expected = |width: Width, range: std::ops::Range<usize>| -> Vec<u64> {
            xs[range]
                .iter()
                .map(|&x| reference.scramble_digit_by_digit(x & width.mask(), width, 5))
                .collect()
        };
        let art = ArtOwen::new(variant, 256, 4).unwrap();
        assert!(!art.step_tables_built(), "{name} built eagerly");
        // Single words and a 64-bit batch (the scalar lanes) count towards the build.
        let singles: Vec<u64> = xs[..100]
            .iter()
            .map(|&x| art.scramble(x, Width::W64, 5))
            .collect();
        assert_eq!(singles, expected(Width::W64, 0..100), "{name} single words");
        let mut batch: Vec<u64> = xs[100..after - 1].to_vec();
        art.scramble_batch(&mut batch, Width::W64, 5);
        assert_eq!(batch, expected(Width::W64, 100..after - 1), "{name} batch");
        assert!(!art.step_tables_built(), "{name} built one word early");
        // A clone keeps the count: its next word pays as the original's would.
        let twin = art.clone();
        let last = xs[after - 1];
        assert_eq!(
            twin.scramble(last, Width::W64, 5),
            expected(Width::W64, after - 1..after)[0]
        );
        assert!(
            twin.step_tables_built() && !art.step_tables_built(),
            "{name}"
        );
        assert_eq!(
            art.scramble(last, Width::W64, 5),
            expected(Width::W64, after - 1..after)[0]
        );
        assert!(art.step_tables_built(), "{name} never built");
        // One call of that many words builds them at once, and a clone keeps them.
        let fresh = ArtOwen::new(variant, 256, 4).unwrap();
        let mut all: Vec<u64> = xs.iter().map(|&x| x & Width::W32.mask()).collect();
        fresh.scramble_batch(&mut all, Width::W32, 5);
        assert_eq!(all, expected(Width::W32, 0..after), "{name} one call");
        assert!(fresh.step_tables_built() && fresh.clone().step_tables_built());
    }
}

/// Words that share their leading bits in every amount: for each j in 0..=W, a run of words
/// equal to one base above bit W − j and random below it (so a group of lanes shares exactly j
/// bits, give or take the chance that every lane agrees on more), then runs of consecutive
/// words from random starts and a run of one repeated word. The runs are not aligned to the
/// kernels' groups, so groups also straddle two runs. `shift` is XORed into the paired runs
/// at the end (the dimension's input shift, so the kernels see the prefixes as built).
fn words_sharing_prefixes(seed: u64, w: u32, shift: u64) -> Vec<u64> {
    let mut rng = SplitMix64::new(seed);
    let mask = Width::new(w).unwrap().mask();
    let mut out = Vec::new();
    for j in 0..=w {
        let base = rng.next_u64() & mask;
        let low = if j == w { 0 } else { mask >> j };
        let run = 21 + (rng.next_u64() % 40) as usize;
        out.extend((0..run).map(|_| base ^ (rng.next_u64() & low)));
    }
    for _ in 0..4 {
        let start = rng.next_u64() & mask;
        out.extend((0..300u64).map(|i| start.wrapping_add(i) & mask));
    }
    let same = rng.next_u64() & mask;
    out.extend(std::iter::repeat_n(same, 70));
    // Pairs of runs of 48 words (a whole gather block, six lanes of eight) whose shared
    // prefixes spell the same number at two depths j1 < j2: the top j1 bits are v in the
    // first run and the top j2 bits are v in the second, so a group's shared steps are known
    // only by their count and bits together.
    out.resize(out.len().next_multiple_of(48), 0);
    for j1 in 1..w {
        for j2 in j1 + 1..=(j1 + 8).min(w) {
            let v = rng.next_u64() & (mask >> (w - j1));
            for j in [j1, j2] {
                let low = mask >> j;
                out.extend((0..48).map(|_| ((v << (w - j)) | (rng.next_u64() & low)) ^ shift));
            }
        }
    }
    out
}

#[test]
fn words_sharing_leading_steps_equal_the_scalar_path() {
    // The batch kernels walk the steps that all words of a group share once for the group;
    // every sharing depth, from none to the whole word, must give the scalar path's words.
    for variant in ArtVariant::all() {
        for symbols in [2usize, 256, 1024] {
            let art = ArtOwen::new(variant, symbols, 13).unwrap();
            for &kernel in &BatchKernel::available() {
                let s = art.with_kernel(kernel).unwrap();
                for bits in [5u32, 8, 13, 24, 30, 31, 32] {
                    let width = Width::new(bits).unwrap();
                    let (shift, _) = art.dimension_shifts(6, width);
                    let input = words_sharing_prefixes(u64::from(bits), bits, shift);
                    let mut batch = input.clone();
                    s.scramble_batch(&mut batch, width, 6);
                    for (i, (&x, &y)) in input.iter().zip(&batch).enumerate() {
                        assert_eq!(
                            y,
                            art.scramble(x, width, 6),
                            "{} table {symbols} {kernel:?} width {bits} word {i} ({x:#x})",
                            variant.name()
                        );
                    }
                    if bits == 32 {
                        // The u32 path walks the 32-bit words themselves.
                        let mut batch32: Vec<u32> = input.iter().map(|&x| x as u32).collect();
                        s.scramble_batch_u32(&mut batch32, 6);
                        for (i, (&y, &y32)) in batch.iter().zip(&batch32).enumerate() {
                            assert_eq!(y, u64::from(y32), "{} u32 word {i}", variant.name());
                        }
                    }
                }
            }
        }
    }
}

/// One table keyed by other seeds (a renderer's fixed table with per-pixel seeds): the batch
/// path equals the digit-by-digit loop for every variant and width, keyed by the table's own
/// seed it is the scrambler itself, and other keys give other scrambles of the same table.
#[test]
fn a_fixed_table_keyed_by_other_seeds_equals_the_digit_loop() {
    for variant in ArtVariant::all() {
        let art = ArtOwen::new(variant, 256, 7).unwrap().with_step_tables();
        for width in [Width::W32, Width::W64] {
            let xs: Vec<u64> = words(variant.q() as u64, 300)
                .into_iter()
                .map(|w| w & width.mask())
                .collect();
            let mut own = xs.clone();
            art.scramble_batch_keyed(&mut own, width, 3, art.seed());
            let mut plain = xs.clone();
            art.scramble_batch(&mut plain, width, 3);
            assert_eq!(own, plain, "{variant:?} {width:?}: keyed by its own seed");
            for key in [0u64, 1, 0xDEAD_BEEF] {
                let mut keyed = xs.clone();
                art.scramble_batch_keyed(&mut keyed, width, 3, key);
                let reference: Vec<u64> = xs
                    .iter()
                    .map(|&x| art.scramble_keyed_digit_by_digit(x, width, 3, key))
                    .collect();
                assert_eq!(keyed, reference, "{variant:?} {width:?} key {key}");
                assert_ne!(
                    keyed, plain,
                    "{variant:?} {width:?} key {key}: the key matters"
                );
            }
        }
    }
}

/// `:table-seed=S` is one table drawn from S keyed by each instance's seed: keyed by S itself
/// it is the plain scrambler of seed S, keyed otherwise it is `scramble_batch_keyed`, and every
/// instance of one table seed shares the table's tables.
#[test]
fn a_table_seed_request_is_the_fixed_table_keyed_by_each_seed() {
    use gartowen_core::registry::{BuildContext, Registry};
    use gartowen_core::PowerOfTwoBase;
    let mut registry = Registry::with_core();
    for spec in gartowen_art::registry::specs() {
        registry.add(spec);
    }
    let build = |request: &str, seed: u64| {
        registry
            .build_with(
                request,
                &BuildContext {
                    seed,
                    default_base: PowerOfTwoBase::B2,
                },
            )
            .unwrap()
    };
    let xs: Vec<u64> = words(5, 200).into_iter().map(|w| w & 0xFFFF_FFFF).collect();
    let run = |s: &dyn Scrambler| {
        let mut w = xs.clone();
        s.scramble_batch(&mut w, Width::W32, 2);
        w
    };
    for name in ["art-owen-2", "art-owen-16p", "q-art-4:table=64"] {
        let keyed_by_itself = build(&format!("{name}:table-seed=7"), 7);
        assert_eq!(
            run(keyed_by_itself.as_ref()),
            run(build(name, 7).as_ref()),
            "{name}"
        );
        assert_eq!(
            keyed_by_itself.name(),
            format!("{}:table-seed=7", build(name, 7).name())
        );
        let keyed = build(&format!("{name}:table-seed=7"), 9);
        let symbols = if name.contains("table=64") { 64 } else { 256 };
        let variant = gartowen_art::registry::variant_of(name.split(':').next().unwrap()).unwrap();
        let mut want = xs.clone();
        ArtOwen::new(variant, symbols, 7)
            .unwrap()
            .scramble_batch_keyed(&mut want, Width::W32, 2, 9);
        assert_eq!(run(keyed.as_ref()), want, "{name}");
        let one: Vec<u64> = xs
            .iter()
            .map(|&x| keyed.scramble(x, Width::W32, 2))
            .collect();
        assert_eq!(one, want, "{name}: word by word");
        // The table's words and bytes are the table's own.
        let plain = build(name, 7);
        for w in [Width::W32, Width::W64] {
            assert_eq!(
                keyed.supports_width(w),
                plain.supports_width(w),
                "{name} {w:?}"
            );
            assert!(keyed.supports_width(w), "{name} {w:?}");
        }
        assert!(keyed.table_bytes() > 0);
        assert_eq!(keyed.table_bytes(), plain.table_bytes(), "{name}");
    }
    for bad in [
        "art-owen-16p:table-seed=x",
        "q-art-4:compose=linear:table-seed=1",
    ] {
        let e = registry
            .build_with(
                bad,
                &BuildContext {
                    seed: 0,
                    default_base: PowerOfTwoBase::B2,
                },
            )
            .err()
            .unwrap_or_else(|| panic!("{bad} accepted"))
            .to_string();
        assert!(e.contains("table-seed"), "{bad}: {e}");
    }
}
