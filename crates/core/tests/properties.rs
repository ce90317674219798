//! Property tests of the core arithmetic: digits, permutations, GF(2) matrices, floats.

use gartowen_core::{
    word_from_f64, word_to_f32, word_to_f64, DigitLayout, Gf2Matrix, Permutation, PowerOfTwoBase,
    SplitMix64, Width,
};
use proptest::prelude::*;

fn layout(w: u32, q: u32) -> DigitLayout {
    DigitLayout::new(Width::new(w).unwrap(), PowerOfTwoBase::from_q(q).unwrap())
}

fn perm(n: usize, seed: u64) -> Permutation {
    Permutation::random(n, &mut SplitMix64::new(seed)).unwrap()
}

proptest! {
    #[test]
    fn digit_set_then_get_round_trips(w in 1u32..=64, q in 1u32..=8, x in any::<u64>(), d in any::<u32>(), k in 0u32..64) {
        let l = layout(w, q);
        let x = x & Width::new(w).unwrap().mask();
        let k = k % l.num_digits();
        let bits = l.digit_bits(k);
        let d = d & ((1u32 << bits) - 1);
        let y = l.set(x, k, d);
        prop_assert_eq!(l.get(y, k), d);
        // Other digits are untouched.
        for other in (0..l.num_digits()).filter(|&o| o != k) {
            prop_assert_eq!(l.get(y, other), l.get(x, other));
        }
        // Setting a digit to its own value is the identity.
        prop_assert_eq!(l.set(x, k, l.get(x, k)), x);
    }

    #[test]
    fn prefixes_nest(w in 1u32..=64, q in 1u32..=8, x in any::<u64>()) {
        let l = layout(w, q);
        let x = x & Width::new(w).unwrap().mask();
        for k in 1..=l.num_digits() {
            let p = l.prefix(x, k);
            prop_assert_eq!(p >> l.digit_bits(k - 1), l.prefix(x, k - 1));
            prop_assert_eq!(p & ((1 << l.digit_bits(k - 1)) - 1), l.get(x, k - 1) as u64);
        }
        prop_assert_eq!(l.prefix(x, l.num_digits()), x);
    }

    #[test]
    fn permutation_group_laws(n in 1usize..=256, a in any::<u64>(), b in any::<u64>(), c in any::<u64>()) {
        let (p, r, s) = (perm(n, a), perm(n, b), perm(n, c));
        let id = Permutation::identity(n).unwrap();
        prop_assert_eq!(p.compose(&r).compose(&s), p.compose(&r.compose(&s)));
        prop_assert_eq!(p.compose(&id), p.clone());
        prop_assert_eq!(id.compose(&p), p.clone());
        prop_assert_eq!(p.compose(&p.inverse()), id.clone());
        prop_assert_eq!(p.inverse().compose(&p), id);
        prop_assert_eq!(p.compose(&r).inverse(), r.inverse().compose(&p.inverse()));
        for d in 0..n as u32 {
            prop_assert_eq!(p.compose(&r).apply(d), p.apply(r.apply(d)));
        }
    }

    #[test]
    fn packed_forms_round_trip(a in any::<u64>()) {
        let p8 = perm(8, a);
        prop_assert_eq!(Permutation::unpack24(p8.pack24().unwrap()).unwrap(), p8.clone());
        prop_assert!(p8.pack24().unwrap() < 1 << 24);
        let p16 = perm(16, a);
        prop_assert_eq!(Permutation::unpack64(p16.pack64().unwrap()).unwrap(), p16);
        let p4 = perm(4, a);
        prop_assert_eq!(Permutation::unpack(p4.pack(2).unwrap(), 4, 2).unwrap(), p4);
    }

    #[test]
    fn gf2_inverse_and_rank(q in 1u32..=8, seed in any::<u64>(), raw in any::<u64>()) {
        let mut rng = SplitMix64::new(seed);
        let a = Gf2Matrix::random_invertible(q, &mut rng).unwrap();
        let id = Gf2Matrix::identity(q).unwrap();
        let inv = a.inverse().unwrap();
        prop_assert_eq!(a.mul(&inv), id);
        prop_assert_eq!(inv.mul(&a), id);
        prop_assert_eq!(a.rank(), q);
        for x in 0..(1u32 << q) {
            prop_assert_eq!(inv.apply(a.apply(x)), x);
        }
        // A random matrix: invertible iff rank q iff x ↦ Ax is injective.
        let mask = if q == 8 { u64::MAX } else { (1u64 << (8 * q)) - 1 };
        let rows: Vec<u8> = (0..q).map(|i| ((raw & mask) >> (8 * i)) as u8 & (((1u32 << q) - 1) as u8)).collect();
        let m = Gf2Matrix::from_rows(q, &rows).unwrap();
        let image: std::collections::HashSet<u32> = (0..(1u32 << q)).map(|x| m.apply(x)).collect();
        prop_assert_eq!(image.len() as u32, 1 << m.rank());
        prop_assert_eq!(m.inverse().is_some(), m.rank() == q);
        // Multiplication is composition of the maps.
        for x in 0..(1u32 << q) {
            prop_assert_eq!(m.mul(&a).apply(x), m.apply(a.apply(x)));
        }
    }

    #[test]
    fn float_conversion_truncates_and_round_trips(w in 1u32..=64, x in any::<u64>()) {
        let width = Width::new(w).unwrap();
        let x = x & width.mask();
        let f = word_to_f64(x, width);
        prop_assert!((0.0..1.0).contains(&f));
        let g = word_to_f32(x, width);
        prop_assert!((0.0..1.0).contains(&g));
        // Truncation: the float never exceeds the exact value, and the gap is below one ulp step.
        let exact = x as f64 * 2f64.powi(-(w as i32)); // exact for w ≤ 53
        if w <= 53 {
            prop_assert_eq!(f, exact);
            prop_assert_eq!(word_from_f64(f, width), Ok(x));
        }
        let back = word_from_f64(f, width).unwrap();
        prop_assert!(back <= x && x - back < (1u64 << w.saturating_sub(53)).max(1));
    }
}

#[test]
fn random_invertible_is_uniform_over_gl22() {
    // 6 matrices; 60_000 draws; chi-square with 5 dof at α = 1e-4 has critical value 25.7.
    let all = Gf2Matrix::all_invertible(2);
    let mut counts = vec![0f64; all.len()];
    let mut rng = SplitMix64::new(77);
    let n = 60_000;
    for _ in 0..n {
        let m = Gf2Matrix::random_invertible(2, &mut rng).unwrap();
        counts[all.iter().position(|a| *a == m).unwrap()] += 1.0;
    }
    let e = n as f64 / 6.0;
    let chi2: f64 = counts.iter().map(|c| (c - e) * (c - e) / e).sum();
    assert!(chi2 < 25.7, "chi2 = {chi2}, counts {counts:?}");
}

#[test]
fn random_permutations_are_uniform_over_s4() {
    // 24 cells; 240_000 draws; chi-square 23 dof at α = 1e-4 has critical value 55.0.
    let mut counts = [0f64; 24];
    let mut rng = SplitMix64::new(3);
    let n = 240_000;
    for _ in 0..n {
        counts[Permutation::random(4, &mut rng).unwrap().rank() as usize] += 1.0;
    }
    let e = n as f64 / 24.0;
    let chi2: f64 = counts.iter().map(|c| (c - e) * (c - e) / e).sum();
    assert!(chi2 < 55.0, "chi2 = {chi2}");
}
