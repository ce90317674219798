//! sz4/sz16 against the check values and identities of docs/design.md §2.

use gartowen_core::Width;
use gartowen_seq::field::{expand_gf4_matrix, gf16_mul, gf4_mul, SmallField, OMEGA};
use gartowen_seq::{sobol, sz};

#[test]
fn sz4_check_columns_from_the_design() {
    let s = sz::sz4(4, Width::W32).unwrap();
    let dim2 = [
        0x80000000u64,
        0x40000000,
        0x60000000,
        0xd0000000,
        0xc8000000,
        0x84000000,
        0xb6000000,
        0x6d000000,
    ];
    let dim3 = [
        0x80000000u64,
        0xc0000000,
        0x60000000,
        0xb0000000,
        0xc8000000,
        0x4c000000,
        0xb6000000,
        0xdb000000,
    ];
    assert_eq!(&s.columns(2)[..8], &dim2);
    assert_eq!(&s.columns(3)[..8], &dim3);
}

#[test]
fn sz4_dimension_0_is_identity_and_dimension_1_is_binary_pascal() {
    let s = sz::sz4(2, Width::W32).unwrap();
    let sob = sobol::sequence(2, Width::W32).unwrap();
    for c in 0..32 {
        assert_eq!(s.column(0, c), 1 << (31 - c));
        assert_eq!(s.column(1, c), sob.column(1, c), "column {c}");
    }
}

#[test]
fn sz16_first_quad_reproduces_sz4_exactly() {
    for w in [12, 32, 64] {
        let width = Width::new(w).unwrap();
        let a = sz::sz4(4, width).unwrap();
        let b = sz::sz16(4, width).unwrap();
        for j in 0..4 {
            assert_eq!(a.columns(j), b.columns(j), "W={w} dim {j}");
        }
    }
}

#[test]
fn sz16_uses_all_sixteen_field_elements() {
    let mut seen = [false; 16];
    for j in 0..16 {
        seen[sz::sz16_parameters(j).0 as usize] = true;
        assert!(sz::sz16_parameters(j).1.is_invertible());
    }
    assert!(seen.iter().all(|&s| s));
}

#[test]
fn gf4_and_gf16_are_fields() {
    for (f, mul) in [(4u32, gf4_mul as fn(u32, u32) -> u32), (16, gf16_mul)] {
        for a in 0..f {
            for b in 0..f {
                assert_eq!(mul(a, b), mul(b, a));
                for c in 0..f {
                    assert_eq!(mul(mul(a, b), c), mul(a, mul(b, c)));
                    assert_eq!(mul(a, b ^ c), mul(a, b) ^ mul(a, c));
                }
            }
            if a != 0 {
                assert_eq!(
                    (0..f).filter(|&b| mul(a, b) == 1).count(),
                    1,
                    "inverse of {a}"
                );
            }
        }
    }
    // ω² = ω + 1 and y² = y + ω.
    assert_eq!(gf4_mul(OMEGA, OMEGA), 3);
    assert_eq!(gf16_mul(4, 4), 4 | OMEGA);
}

#[test]
fn m16_by_the_design_formula_equals_the_multiplication_matrix() {
    // DESIGN: M16(a) is the GF(4) matrix G of multiplication by a in the basis (1, y), each
    // entry expanded by M4, entry (2i+u, 2j+v). For a = α + βy: a·1 = α + βy and
    // a·y = βω + (α+β)y, so G = [[α, βω], [β, α+β]].
    for a in 0..16u32 {
        let (alpha, beta) = (a & 3, a >> 2);
        let g = [[alpha, gf4_mul(beta, OMEGA)], [beta, alpha ^ beta]];
        let by_design = expand_gf4_matrix(g);
        assert_eq!(SmallField::Gf16.mult_matrix(a), by_design, "a = {a}");
    }
}

#[test]
fn faure_over_gf2_is_the_binary_pascal_matrix() {
    use gartowen_seq::faure::faure_columns;
    let sob = sobol::sequence(2, Width::W32).unwrap();
    assert_eq!(
        faure_columns(SmallField::Gf2, 1, Width::W32, 32),
        sob.columns(1)
    );
    assert_eq!(
        faure_columns(SmallField::Gf2, 0, Width::W32, 32),
        sob.columns(0)
    );
}

#[test]
fn dimension_limits() {
    assert!(sz::sz4(5, Width::W32).is_err());
    assert!(sz::sz16(17, Width::W32).is_err());
    assert!(sz::sz16(0, Width::W32).is_err());
}
