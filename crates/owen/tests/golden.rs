//! Golden vectors of the oracle (hex words), freezing the documented keying: seed 2024,
//! dimension 1 (32-bit) and dimension 5 (64-bit). Printed by examples/print_oracle_golden.rs.
//! Regenerated once for issue 19's incremental keys (one mix per node, six base-2 levels per
//! key, Fisher–Yates indices from one word for b ≤ 16); in base 2 the four laws coincide on
//! S_2 and so do their vectors.

use gartowen_core::Unscramble;
use gartowen_core::{PowerOfTwoBase, Scrambler, Width};
use gartowen_owen::{FullTreeOwen, OwenVariant};

#[rustfmt::skip]
const GOLDEN: [(u32, OwenVariant, [u64; 4], u64); 20] = [
        (1, OwenVariant::Uniform, [0x0ed0bd42, 0xdd99678d, 0x166ad92f, 0x89fbe33c], 0x42b6939df285b871),
        (1, OwenVariant::CyclicShift, [0x0ed0bd42, 0xdd99678d, 0x166ad92f, 0x89fbe33c], 0x42b6939df285b871),
        (1, OwenVariant::Xor, [0x0ed0bd42, 0xdd99678d, 0x166ad92f, 0x89fbe33c], 0x42b6939df285b871),
        (1, OwenVariant::Affine, [0x0ed0bd42, 0xdd99678d, 0x166ad92f, 0x89fbe33c], 0x42b6939df285b871),
        (2, OwenVariant::Uniform, [0x8218f064, 0x6efdfd60, 0x9029e4e9, 0x2875232a], 0x28d4a98a7e41b760),
        (2, OwenVariant::CyclicShift, [0x76a7079d, 0xf20101ee, 0x4bf691b7, 0x1f6572c5], 0xeb35647380bc46d4),
        (2, OwenVariant::Xor, [0x76a7079d, 0xf20101ee, 0x6bf61937, 0x9f4578e5], 0xeb35667b82be44d6),
        (2, OwenVariant::Affine, [0x71ae6cf2, 0x9ad25e61, 0x504cdda3, 0xe00b715f], 0x3f4aac0ffa319466),
        (3, OwenVariant::Uniform, [0x45e336e0, 0x22eddf4d, 0x42590242, 0x00e657c1], 0xa432f8bc26bbeb1f),
        (3, OwenVariant::CyclicShift, [0x5dcb1705, 0xcbf4389e, 0x4dcff37e, 0x2d1ed6fc], 0xf372c5684391855c),
        (3, OwenVariant::Xor, [0x5dcb1705, 0xcbf4389e, 0x4daff37e, 0xae5ee0fe], 0xf372c56343851610),
        (3, OwenVariant::Affine, [0x5c3e47d7, 0xcef65250, 0x4a28a67f, 0x06eb02b1], 0x0de0cd645ae6fff0),
        (4, OwenVariant::Uniform, [0x255b36ee, 0xc413dc61, 0x43df374e, 0x653ae9e6], 0x3b6bac5b5a2f96ac),
        (4, OwenVariant::CyclicShift, [0x4f78b94e, 0xc3f93e55, 0x5b8856d1, 0x37698f68], 0xf9dcc11d7056b530),
        (4, OwenVariant::Xor, [0x4f78b94e, 0xc3f93e55, 0x5b605611, 0xb7856f86], 0xf99ac9d17e1035be),
        (4, OwenVariant::Affine, [0x8ea78cff, 0xd3b94e0f, 0x376969fd, 0xcaca41ec], 0x493d7054afc373b9),
        (8, OwenVariant::Uniform, [0x52fc63ff, 0xf6464d0f, 0x6eea617d, 0x78428429], 0x1ef79cfe8249990b),
        (8, OwenVariant::CyclicShift, [0x45fd7884, 0xc56d4505, 0x57bb14be, 0x448d2ae3], 0xf7bf6038492662c0),
        (8, OwenVariant::Xor, [0x45fd7884, 0xc56d4505, 0x57b3e83e, 0xba71d41b], 0xf7bf5eb649d0583e),
        (8, OwenVariant::Affine, [0xc3ee513b, 0xb8460f7f, 0x6ea6806b, 0x1780162b], 0x03e4e17cecbc156b),
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
