//! Sobol against SciPy's unscrambled output (hex golden files made by tools/extract_joe_kuo.py)
//! and internal consistency of random access, Gray-code iteration and lookup tables.

use gartowen_core::Width;
use gartowen_seq::{gray_code, sobol};
use proptest::prelude::*;

/// Rows of hex words; comment lines start with '#'.
fn read_hex(text: &str) -> Vec<Vec<u64>> {
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            l.split_whitespace()
                .map(|h| u64::from_str_radix(h, 16).unwrap())
                .collect()
        })
        .collect()
}

fn assert_matches_scipy(text: &str, dims: usize, first_dim: usize, width: Width) {
    let seq = sobol::sequence(dims, width).unwrap();
    let rows = read_hex(text);
    assert!(rows.len() >= 128);
    for (n, row) in rows.iter().enumerate() {
        assert_eq!(row.len(), dims - first_dim);
        for (k, &expected) in row.iter().enumerate() {
            let got = seq.point(gray_code(n as u64), first_dim + k);
            assert_eq!(got, expected, "row {n} dim {}", first_dim + k);
        }
    }
}

#[test]
fn equals_scipy_32_bit_first_40_dims() {
    assert_matches_scipy(
        include_str!("data/scipy_sobol_d40_n512_b32.hex"),
        40,
        0,
        Width::W32,
    );
}

#[test]
fn equals_scipy_64_bit() {
    assert_matches_scipy(
        include_str!("data/scipy_sobol_d8_n256_b64.hex"),
        8,
        0,
        Width::W64,
    );
}

#[test]
fn equals_scipy_on_the_last_dimensions_of_the_table() {
    assert_matches_scipy(
        include_str!("data/scipy_sobol_last12_n128_b32.hex"),
        21201,
        21189,
        Width::W32,
    );
    assert!(sobol::sequence(21202, Width::W32).is_err());
    assert!(sobol::sequence(0, Width::W32).is_err());
}

#[test]
fn gray_iteration_equals_random_access_on_2_16_points_64_dims() {
    let seq = sobol::sequence(64, Width::W32).unwrap();
    let mut it = seq.gray_iter(0, 1 << 16).unwrap();
    let mut n = 0u64;
    while let Some((index, point)) = it.next_point() {
        assert_eq!(index, gray_code(n));
        for (j, &x) in point.iter().enumerate() {
            assert_eq!(x, seq.point(index, j), "position {n} dim {j}");
        }
        n += 1;
    }
    assert_eq!(n, 1 << 16);
}

#[test]
fn gray_iteration_from_an_offset_and_range_checks() {
    let seq = sobol::sequence(3, Width::new(12).unwrap()).unwrap();
    let mut it = seq.gray_iter(1000, 4096).unwrap();
    let mut n = 1000;
    while let Some((index, point)) = it.next_point() {
        assert_eq!(point[2], seq.point(index, 2));
        n += 1;
    }
    assert_eq!(n, 4096);
    assert!(
        seq.gray_iter(0, 4097).is_err(),
        "12 index bits hold 4096 points"
    );
    assert!(seq.try_point(4096, 0).is_err());
}

#[test]
fn lookup_tables_equal_random_access() {
    let seq = sobol::sequence(16, Width::W32).unwrap();
    let t = seq.lookup_tables();
    let mut rng = gartowen_core::SplitMix64::new(9);
    for _ in 0..20_000 {
        let i = rng.next_u32();
        let j = rng.bounded(16) as usize;
        assert_eq!(t.point_u32(i, j), seq.point(i as u64, j));
    }
}

#[test]
fn first_columns_are_the_textbook_ones() {
    // Dimension 0 is van der Corput (identity matrix), dimension 1 the binary Pascal matrix.
    let seq = sobol::sequence(2, Width::W32).unwrap();
    for c in 0..32u64 {
        assert_eq!(seq.column(0, c as usize), 1 << (31 - c));
        let mut pascal = 0u64;
        for r in 0..32u64 {
            if r <= c && (r & !c) == 0 {
                pascal |= 1 << (31 - r);
            }
        }
        assert_eq!(seq.column(1, c as usize), pascal, "column {c}");
    }
}

proptest! {
    #[test]
    fn points_are_linear_in_the_index(i in any::<u32>(), j in any::<u32>(), d in 0usize..50) {
        let seq = sobol::sequence(50, Width::W32).unwrap();
        let (i, j) = (i as u64, j as u64);
        prop_assert_eq!(seq.point(i ^ j, d), seq.point(i, d) ^ seq.point(j, d));
    }

    #[test]
    fn narrow_words_are_the_top_bits_of_wide_ones(d in 0usize..300, c in 0usize..16) {
        let c64 = sobol::columns(d, Width::W64).unwrap();
        let c32 = sobol::columns(d, Width::W32).unwrap();
        let c16 = sobol::columns(d, Width::new(16).unwrap()).unwrap();
        prop_assert_eq!(c64[c] >> 32, c32[c]);
        prop_assert_eq!(c32[c] >> 16, c16[c]);
    }
}

#[test]
fn incremental_fills_equal_random_access_in_both_orders() {
    use gartowen_seq::{gray_code, SequenceKind};
    for kind in SequenceKind::ALL {
        let seq = kind.build(3, gartowen_core::Width::W32).unwrap();
        for first in [0u64, 1, 7, 1000, (1 << 20) - 3] {
            for len in [0usize, 1, 2, 77] {
                for dim in 0..3 {
                    let mut natural = vec![0u64; len];
                    seq.fill_points(dim, first, &mut natural);
                    let mut gray = vec![0u64; len];
                    seq.fill_points_gray(dim, first, &mut gray);
                    for k in 0..len {
                        let i = first + k as u64;
                        assert_eq!(natural[k], seq.point(i, dim), "{} natural {i}", kind.name());
                        assert_eq!(
                            gray[k],
                            seq.point(gray_code(i), dim),
                            "{} gray {i}",
                            kind.name()
                        );
                    }
                }
            }
        }
    }
}

/// The Faure sequence in base 2 is Sobol's first two dimensions, column for column (the
/// docs/conventions.md says so): the identity and the Pascal matrix mod 2.
#[test]
fn faure_in_base_2_is_the_first_two_sobol_dimensions() {
    let sobol = gartowen_seq::sobol::sequence(2, Width::W32).unwrap();
    let faure =
        gartowen_seq::faure::faure(gartowen_core::PowerOfTwoBase::B2, 2, Width::W32).unwrap();
    for j in 0..2 {
        assert_eq!(faure.columns(j), sobol.columns(j), "dim {j}");
    }
}
