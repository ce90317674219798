//! sz4/sz16 against the check values and identities of docs/design.md §2.

use gartowen_core::Width;
use gartowen_seq::field::{expand_gf4_matrix, gf16_mul, gf4_mul, SmallField, OMEGA};
use gartowen_seq::{sobol, sz};

/// A 32×32 binary matrix, `m[r][c]`, row 0 the most significant output bit.
type Bits = [[u8; 32]; 32];

/// binom(c, r) mod 2 for r, c < 32, by Pascal's rule (not Lucas, which production uses).
fn pascal_mod2() -> Bits {
    let mut b = [[0u8; 32]; 32];
    for c in 0..32 {
        b[0][c] = 1;
        for r in 1..=c {
            b[r][c] = b[r - 1][c - 1] ^ b[r][c - 1];
        }
    }
    b
}

fn mul2(a: [[u8; 2]; 2], b: [[u8; 2]; 2]) -> [[u8; 2]; 2] {
    let mut c = [[0u8; 2]; 2];
    for (i, row) in c.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = (a[i][0] & b[0][j]) ^ (a[i][1] & b[1][j]);
        }
    }
    c
}

const I2: [[u8; 2]; 2] = [[1, 0], [0, 1]];
const ALPHA: [[u8; 2]; 2] = [[0, 1], [1, 1]];
const BETA: [[u8; 2]; 2] = [[1, 1], [1, 0]];

/// P4(x): 2×2 block (I, J) is x^(J−I) where binom(J, I) is odd, else 0; inside a block, row 0
/// is the more significant output bit and column 0 the less significant index bit, so the
/// block's entry (u, v) is the matrix's entry (2I + u, 2J + v). x^0 is the identity, for x = 0
/// too.
fn p4(x: [[u8; 2]; 2]) -> Bits {
    let binom = pascal_mod2();
    let mut m = [[0u8; 32]; 32];
    for big_i in 0..16 {
        for big_j in big_i..16 {
            if binom[big_i][big_j] == 0 {
                continue;
            }
            let block = (0..big_j - big_i).fold(I2, |acc, _| mul2(acc, x));
            for u in 0..2 {
                for v in 0..2 {
                    m[2 * big_i + u][2 * big_j + v] = block[u][v];
                }
            }
        }
    }
    m
}

fn mul32(a: &Bits, b: &Bits) -> Bits {
    let mut c = [[0u8; 32]; 32];
    for r in 0..32 {
        for k in 0..32 {
            if a[r][k] == 1 {
                for col in 0..32 {
                    c[r][col] ^= b[k][col];
                }
            }
        }
    }
    c
}

/// diag(U, U, …) with U = [[1,1],[0,1]] on each 2-bit output digit.
fn diag_u() -> Bits {
    let mut m = [[0u8; 32]; 32];
    for d in 0..16 {
        m[2 * d][2 * d] = 1;
        m[2 * d][2 * d + 1] = 1;
        m[2 * d + 1][2 * d + 1] = 1;
    }
    m
}

/// Column c as a word, row 0 in the most significant bit.
fn column_words(m: &Bits) -> Vec<u64> {
    (0..32)
        .map(|c| (0..32).fold(0u64, |w, r| w | ((m[r][c] as u64) << (31 - r))))
        .collect()
}

fn add2(a: [[u8; 2]; 2], b: [[u8; 2]; 2]) -> [[u8; 2]; 2] {
    [
        [a[0][0] ^ b[0][0], a[0][1] ^ b[0][1]],
        [a[1][0] ^ b[1][0], a[1][1] ^ b[1][1]],
    ]
}

#[test]
fn the_block_identities_of_the_published_quad_hold() {
    // α² = β, α³ = I, I + α = β: {0, I, α, β} is GF(4).
    assert_eq!(mul2(ALPHA, ALPHA), BETA);
    assert_eq!(mul2(mul2(ALPHA, ALPHA), ALPHA), I2);
    assert_eq!(add2(I2, ALPHA), BETA);
    // The pair relation: P·P4(β) = diag(U)·P4(α).
    let binary_pascal = pascal_mod2();
    assert_eq!(
        mul32(&binary_pascal, &p4(BETA)),
        mul32(&diag_u(), &p4(ALPHA))
    );
    // Faure's group law: P4(a)·P4(b) = P4(a + b) for a, b in GF(4).
    let field = [[[0u8; 2]; 2], I2, ALPHA, BETA];
    for a in field {
        for b in field {
            assert_eq!(mul32(&p4(a), &p4(b)), p4(add2(a, b)), "{a:?} + {b:?}");
        }
    }
}

#[test]
fn sz4_is_the_published_4d_sz_bit_for_bit() {
    let dim2 = column_words(&p4(BETA));
    let dim3 = column_words(&mul32(&pascal_mod2(), &p4(BETA)));
    // The first columns, pinned as hex words (row 0 = MSB, W = 32).
    assert_eq!(
        dim2[..8],
        [
            0x80000000, 0x40000000, 0xe0000000, 0x90000000, 0x48000000, 0xc4000000, 0x9e000000,
            0x79000000
        ]
    );
    assert_eq!(
        dim3[..8],
        [
            0x80000000, 0xc0000000, 0xe0000000, 0x70000000, 0x48000000, 0x8c000000, 0x9e000000,
            0xe7000000
        ]
    );
    let s = sz::sz4(4, Width::W32).unwrap();
    assert_eq!(s.columns(2), &dim2[..], "dimension 2 = P4(β)");
    assert_eq!(s.columns(3), &dim3[..], "dimension 3 = P·P4(β)");
    assert_eq!(
        s.columns(1),
        &column_words(&pascal_mod2())[..],
        "dimension 1 = P"
    );
    // 64-bit words: the same matrices, continued (the top 32 rows of the first 32 columns
    // are the 32-bit ones).
    let wide = sz::sz4(4, Width::W64).unwrap();
    for j in 0..4 {
        for c in 0..32 {
            assert_eq!(
                wide.column(j, c) >> 32,
                s.column(j, c),
                "dim {j} column {c}"
            );
        }
    }
    // The earlier reconstruction differs in dimensions 2 and 3 only, from point 4 on.
    let old = sz::sz4_faure(4, Width::W32).unwrap();
    for j in 0..4 {
        let first_differing = (0..64u64).find(|&n| old.point(n, j) != s.point(n, j));
        assert_eq!(
            first_differing,
            [None, None, Some(4), Some(4)][j],
            "dim {j}"
        );
    }
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
fn sz16_faure_uses_all_sixteen_field_elements_in_its_own_order() {
    // The earlier construction: quad β holds α_k² + β·y, the alphabet (0, 1, ω, ω²).
    for j in 0..16 {
        let (beta, k) = ((j / 4) as u32, j % 4);
        let alpha = [0, 1, OMEGA, 3][k];
        assert_eq!(
            sz::sz16_faure_parameters(j).0,
            gf4_mul(alpha, alpha) | (beta << 2),
            "dim {j}"
        );
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

#[test]
fn sz4_faure_keeps_the_earlier_check_columns() {
    let s = sz::sz4_faure(4, Width::W32).unwrap();
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
    // sz16-faure's first quad is sz4-faure, as sz16's is sz4.
    let q = sz::sz16_faure(4, Width::W32).unwrap();
    for j in 0..4 {
        assert_eq!(q.columns(j), s.columns(j), "dim {j}");
    }
}

#[test]
fn the_packed_outer_transforms_are_the_identity_and_beta() {
    use gartowen_core::Gf2Matrix;
    let outers: Vec<u64> = sz::SZ16_QUADS.iter().map(|q| q.outer).collect();
    let id = Gf2Matrix::identity(2).unwrap().packed();
    // β = [[1,1],[1,0]]: row 0 = (1, 1), row 1 = (1, 0), bit j of a row = column j.
    let beta = Gf2Matrix::from_rows(2, &[0b11, 0b01]).unwrap().packed();
    assert_eq!(SmallField::Gf4.mult_matrix(3).packed(), beta, "β = M4(ω²)");
    assert!(outers.iter().all(|&o| o == id || o == beta), "{outers:x?}");
    assert_eq!(outers[0], id, "quad 0 is sz4 itself");
}
