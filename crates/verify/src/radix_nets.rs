//! The battery's `nets` check in a base b that is not a power of two: a nested scramble in
//! base b maps every elementary interval of base b onto one of the same shape, one to one
//! (theorem T2 read in base b), so a (0,m,s)-net in base b stays one.
//!
//! Nets per base: in a prime base p, the first p^m points of the Faure (0,s)-sequence in
//! dimensions 0, 1, 2 (`gartowen_seq::radix::faure_prime`); in any other base, the Hammersley
//! net (i/b^m, φ_b(i)), i < b^m, a (0,m,2)-net in every base (φ_b the radical inverse: the
//! Halton coordinate of base b). Coordinate j is scrambled as dimension j, as base-b digit
//! words, for every m up to the level's size bound, and the t-value is counted again.
//!
//! From digits to the counting path: the checker reads W-bit binary words, so the scrambled
//! word y (value y·b^-M, M digits) enters as x = ⌈y·2^W / b^M⌉. Since b^M ≤ 2^W, x·2^-W lies
//! in [y·b^-M, (y+1)·b^-M), which sits inside every base-b elementary interval that holds
//! y·b^-M: the box counts are exactly those of the digit words.

use crate::level::Level;
use crate::nets::{NetBroken, NetsKept};
use crate::verdict::Verdict;
use gartowen_core::{Radix, RadixLayout, Scrambler, Width};
use gartowen_netcheck::{counting::t_value, CheckBase, PointSet};
use gartowen_seq::radix::{faure_prime, is_prime, radical_inverse};

/// The most points a base-b net of the battery holds: 2^18, whatever the level (so that
/// base 257 and above, whose m = 2 would need b² > 2^16 points, still get m = 1).
const MOST_POINTS_LOG2: u32 = 18;

/// The net family of base `radix`: its name and how many coordinates it has.
pub fn radix_net_family(radix: Radix) -> (String, usize) {
    let b = radix.get() as u64;
    if is_prime(b) {
        (format!("faure:base={b}"), 3)
    } else {
        (format!("hammersley:base={b}"), 2)
    }
}

/// The largest m the check uses in base `radix` at `level`: b^m within the level's net size
/// (2^12 quick, 2^16 full, 2^18 exhaustive) but at least 2 while b² ≤ 2^18, and at least 1.
pub fn radix_max_m(radix: Radix, level: Level) -> u32 {
    let b = radix.get() as u64;
    let fits = |log2: u32| {
        let (mut m, mut p) = (0, b);
        while p <= 1u64 << log2 {
            m += 1;
            p *= b;
        }
        m
    };
    fits(level.plan().net_log2_points)
        .max(fits(MOST_POINTS_LOG2).min(2))
        .max(1)
}

/// The b^m points of base `radix`'s net, `dims` coordinates (at most the family's), each an
/// integer below b^m (the value is k·b^-m), coordinate-major.
pub fn radix_net_digits(radix: Radix, m: u32, dims: usize) -> Vec<Vec<u64>> {
    let b = radix.get() as u64;
    let n = b.pow(m);
    if is_prime(b) {
        let flat = faure_prime(b, n, dims).expect("b^m < 2^53 and dims ≤ 3 ≤ p");
        (0..dims)
            .map(|j| flat.iter().skip(j).step_by(dims).map(|f| f.numer).collect())
            .collect()
    } else {
        let coordinate = |j: usize, i: u64| match j {
            0 => i,
            _ => radical_inverse(i, b, m).numer,
        };
        (0..dims)
            .map(|j| (0..n).map(|i| coordinate(j, i)).collect())
            .collect()
    }
}

/// The binary word ⌈y·2^W / b^M⌉ whose value lies in the base-b cell of the digit word `y`.
pub fn binary_word(layout: RadixLayout, y: u64) -> u64 {
    let w = layout.width().bits();
    let cap = layout.capacity() as u128;
    ((y as u128) << w).div_ceil(cap) as u64
}

/// The net check in base `radix`: every m keeps t = 0, or the first m that does not (or the
/// first word out of range). Uses dimensions 0..`max_dims` only.
pub fn check_radix_nets(
    s: &dyn Scrambler,
    width: Width,
    radix: Radix,
    level: Level,
    max_dims: Option<u32>,
) -> (Verdict, String) {
    let Ok(layout) = RadixLayout::new(width, radix) else {
        return (
            Verdict::Skipped,
            format!(
                "no base-{} digit fits a {}-bit word",
                radix.get(),
                width.bits()
            ),
        );
    };
    let (sequence, family_dims) = radix_net_family(radix);
    let dims = family_dims.min(max_dims.map_or(usize::MAX, |n| n as usize));
    if dims == 0 {
        return (Verdict::Skipped, "not run: needs dimension 0".into());
    }
    let base = CheckBase::new(radix.get() as u64).expect("b ≥ 3");
    let top = radix_max_m(radix, level).min(layout.num_digits());
    for m in 1..=top {
        let shift = (radix.get() as u64).pow(layout.num_digits() - m);
        let mut columns = Vec::with_capacity(dims);
        for (j, digits) in radix_net_digits(radix, m, dims).into_iter().enumerate() {
            let mut words: Vec<u64> = digits.iter().map(|&k| k * shift).collect();
            s.scramble_batch(&mut words, width, j as u32);
            if let Some(&y) = words.iter().find(|&&y| layout.check(y).is_err()) {
                return (
                    Verdict::Fail,
                    format!(
                        "{sequence} dimension {j}, m = {m}: output word {y} is not below {}^{}",
                        radix.get(),
                        layout.num_digits()
                    ),
                );
            }
            columns.push(words.iter().map(|&y| binary_word(layout, y)).collect());
        }
        let points = PointSet::from_columns(width, columns).expect("equal columns");
        let got = t_value(&points, base, m).expect("b^m points");
        if got != 0 {
            let broken = NetBroken {
                sequence,
                dims: (0..dims).collect(),
                m,
                scrambled_t: got,
                t: 0,
            };
            return (Verdict::Fail, broken.to_string());
        }
    }
    let kept = NetsKept {
        sequence,
        dims: (0..dims).collect(),
        top_m: top,
    };
    (Verdict::Pass, format!("t-values kept: {kept}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::{Claim, Identity, PowerOfTwoBase};

    fn radix(b: u64) -> Radix {
        Radix::new(b).unwrap()
    }

    #[test]
    fn the_unscrambled_nets_have_t_zero_and_a_squashed_digit_breaks_them() {
        for b in [3, 5, 6, 7, 10, 12] {
            let (verdict, detail) =
                check_radix_nets(&Identity, Width::W32, radix(b), Level::Quick, None);
            assert_eq!(verdict, Verdict::Pass, "base {b}: {detail}");
            let family = if is_prime(b) { "faure" } else { "hammersley" };
            assert!(detail.contains(family), "{detail}");
        }
        // Sending digit 1 of the leading place to 0 keeps words in range but merges boxes.
        struct Squash;
        impl Scrambler for Squash {
            fn name(&self) -> String {
                "squash".into()
            }
            fn base(&self) -> PowerOfTwoBase {
                PowerOfTwoBase::B2
            }
            fn claim(&self) -> Claim {
                Claim::OWEN
            }
            fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 {
                let l = RadixLayout::new(width, radix(3)).unwrap();
                if l.get(x, 0) == 1 {
                    l.set(x, 0, 0)
                } else {
                    x
                }
            }
        }
        let (verdict, detail) = check_radix_nets(&Squash, Width::W32, radix(3), Level::Quick, None);
        assert_eq!(verdict, Verdict::Fail);
        assert!(
            detail.contains("m = 1: t = 1 after scrambling, 0 before"),
            "{detail}"
        );
    }

    #[test]
    fn words_out_of_range_fail_and_served_dimensions_bound_the_net() {
        struct TooLarge;
        impl Scrambler for TooLarge {
            fn name(&self) -> String {
                "too-large".into()
            }
            fn base(&self) -> PowerOfTwoBase {
                PowerOfTwoBase::B2
            }
            fn claim(&self) -> Claim {
                Claim::OWEN
            }
            fn scramble(&self, x: u64, _width: Width, _dim: u32) -> u64 {
                x + 3u64.pow(20)
            }
        }
        let (verdict, detail) =
            check_radix_nets(&TooLarge, Width::W32, radix(3), Level::Quick, None);
        assert_eq!(verdict, Verdict::Fail);
        assert!(detail.contains("not below 3^20"), "{detail}");
        let (verdict, detail) =
            check_radix_nets(&Identity, Width::W64, radix(5), Level::Quick, Some(2));
        assert_eq!(verdict, Verdict::Pass);
        assert!(detail.contains("dims [0, 1] m ≤ 5"), "{detail}");
        let (verdict, _) = check_radix_nets(&Identity, Width::W32, radix(5), Level::Quick, Some(0));
        assert_eq!(verdict, Verdict::Skipped);
    }

    #[test]
    fn sizes_follow_the_level_and_stay_bounded_in_large_bases() {
        assert_eq!(radix_max_m(radix(3), Level::Quick), 7); // 3^7 = 2187 ≤ 4096 < 3^8
        assert_eq!(radix_max_m(radix(3), Level::Full), 10);
        assert_eq!(radix_max_m(radix(3), Level::Exhaustive), 11);
        assert_eq!(radix_max_m(radix(100), Level::Quick), 2); // 10^4 points: m = 2 kept
        assert_eq!(radix_max_m(radix(513), Level::Quick), 1); // 513² > 2^18
        assert_eq!(radix_max_m(radix(65535), Level::Exhaustive), 1);
    }

    #[test]
    fn the_binary_word_lies_in_the_digit_words_cell() {
        for (w, b) in [(Width::W32, 3u64), (Width::W64, 7), (Width::W32, 65535)] {
            let l = RadixLayout::new(w, radix(b)).unwrap();
            let cap = l.capacity() as u128;
            for y in [0, 1, 2, l.capacity() / 3, l.capacity() - 1] {
                let x = binary_word(l, y) as u128;
                // y/b^M ≤ x/2^W < (y+1)/b^M
                assert!(x * cap >= (y as u128) << w.bits(), "b {b} y {y}");
                assert!(x * cap < ((y as u128 + 1) << w.bits()), "b {b} y {y}");
            }
        }
    }
}
