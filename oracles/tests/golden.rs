//! Golden vectors of the oracle (hex words), freezing the documented keying: seed 2024,
//! dimension 1 (32-bit) and dimension 5 (64-bit). Printed by examples/print_oracle_golden.rs.

use gartowen_core::{PowerOfTwoBase, Scrambler, Width};
use gartowen_oracles::{FullTreeOwen, OwenVariant};

#[rustfmt::skip]
const GOLDEN: [(u32, OwenVariant, [u64; 4], u64); 20] = [
        (1, OwenVariant::Uniform, [0xd6012e41, 0x7eb6a4bc, 0xc5564067, 0x2b895c9d], 0x31754d9238646cd5),
        (1, OwenVariant::CyclicShift, [0x29fed1be, 0x81495b43, 0x3aa9bf98, 0xd476a362], 0xce8ab26dc79b932a),
        (1, OwenVariant::Xor, [0x29fed1be, 0x81495b43, 0x3aa9bf98, 0xd476a362], 0xce8ab26dc79b932a),
        (1, OwenVariant::Affine, [0xb05148cc, 0x0bae0684, 0xa17765f2, 0x4666d408], 0xfddd692551a7df16),
        (2, OwenVariant::Uniform, [0xf66fd80f, 0x543f05ba, 0xe7c22c4d, 0x01dc174a], 0x0dd027cb419801c5),
        (2, OwenVariant::CyclicShift, [0x1d86aef8, 0xb2c0fb25, 0x2f3d17f8, 0xfc8bc235], 0xa5a7fff29d8bdd90),
        (2, OwenVariant::Xor, [0x1d86aef8, 0xb2c0fb25, 0x0f3d97f8, 0xfe23e8b5], 0xa5a7fff89d8bdd1a),
        (2, OwenVariant::Affine, [0x8d7456de, 0x25d7dbb0, 0x9032fdd2, 0xdb381b25], 0xef9b37b57d07d5aa),
        (3, OwenVariant::Uniform, [0xbeefadea, 0xf732954e, 0xbb6c8544, 0x378be615], 0x00a17bcb7a763a06),
        (3, OwenVariant::CyclicShift, [0x2faa1497, 0xb3e4e1c9, 0x3d8698da, 0x13799df0], 0x92944182de70b4d5),
        (3, OwenVariant::Xor, [0x2faa1497, 0xb3e4e1c9, 0x3de61c1a, 0xc87419ea], 0x90d04158df662699),
        (3, OwenVariant::Affine, [0x8047fb81, 0x519d81d8, 0x9d978e72, 0x76a652d1], 0xd0fa5b2f9d018298),
        (4, OwenVariant::Uniform, [0x69296798, 0x12e5d7e8, 0xba9985b0, 0x2467a341], 0x464f5f8956f2953a),
        (4, OwenVariant::CyclicShift, [0x26f4a149, 0xa1caa94c, 0x39ac89de, 0x13569230], 0x9a7b3f7b1cc0e3f9),
        (4, OwenVariant::Xor, [0x26f4a149, 0xa1caa94c, 0x354c651e, 0xdb985cbe], 0x987bbf731a8eebf5),
        (4, OwenVariant::Affine, [0xa40960f2, 0xcbb94b1c, 0x614c94b2, 0x9d4aa739], 0xa1881f23cb024e1c),
        (8, OwenVariant::Uniform, [0x47c8f1d2, 0xb539897a, 0x246f3fd9, 0x272476e3], 0xfc680e560cf2c64a),
        (8, OwenVariant::CyclicShift, [0x2762f540, 0xa73b6459, 0x39f5ac1c, 0x262375e2], 0x9801e84e27778650),
        (8, OwenVariant::Xor, [0x2762f540, 0xa73b6459, 0x35f500dc, 0xd8db891c], 0x96fde6801767748e),
        (8, OwenVariant::Affine, [0x843a0591, 0x8c3cf108, 0x0931118a, 0x85b99178], 0xaba2f542a7c73ede),
];

#[test]
fn golden_vectors_for_each_base_and_variant() {
    let inputs = [0u64, 0x8000_0000, 0x1234_5678, 0xFFFF_FFFF];
    for (q, variant, out32, out64) in GOLDEN {
        let s = FullTreeOwen::new(PowerOfTwoBase::from_q(q).unwrap(), variant, 2024);
        for (x, y) in inputs.iter().zip(out32) {
            assert_eq!(
                s.scramble(*x, Width::W32, 1),
                y,
                "q={q} {variant:?} x={x:#x}"
            );
            assert_eq!(s.unscramble(y, Width::W32, 1), *x);
        }
        assert_eq!(
            s.scramble(0x0123_4567_89ab_cdef, Width::W64, 5),
            out64,
            "q={q} {variant:?} 64-bit"
        );
    }
}
