//! The battery's `nets` check: a nested scramble in base b = 2^q keeps the t-value of every
//! digital net in base b and in every base b^k = 2^(kq) ≤ 256 (theorem T2 with T4: a prefix
//! of j digits in base b^k is a prefix of jk digits in base b, so an elementary interval of
//! base b^k is mapped onto one of the same shape, one to one).
//!
//! Sequences per base: Sobol in base 2, sz4 in base 4, sz16 in base 16, and the Faure
//! sequence over GF(2^r) in bases 8, 32, 64, 128 and 256 (`faure:base=B`). Each is scrambled
//! dimension by dimension, cut to b^m points for every m up to a size bound of the level, and
//! its t-value by the counting path must equal the rank path's t-value for the unscrambled
//! generator matrices.
//!
//! Word tails: with W-bit words a net of B^m points has r·m ≤ W index bits, so every box ends
//! at or above bit W − r·m and a partial last digit (the 2-bit tail of base 8 in 32-bit
//! words) never enters one. The scramble still acts on the whole word, so a scrambler whose
//! tail handling disturbs a full digit is caught here; the tail digit itself is checked by
//! `nested` (16-bit words: base 8 has a 1-bit tail there).

use crate::level::Level;
use crate::verdict::Verdict;
use gartowen_core::{PowerOfTwoBase, Scrambler, Width};
use gartowen_netcheck::{counting::t_value, rank, CheckBase, PointSet};
use gartowen_seq::SequenceKind;

/// The dimensions a net check uses when only dimensions 0..`max_dims` are served: its own
/// (`dims`) where they are served, else the first `dims.len()` served dimensions (any
/// projection of these sequences is a net with a t-value the rank path computes).
pub fn served_dims(dims: Vec<usize>, max_dims: Option<u32>) -> Vec<usize> {
    match max_dims {
        Some(n) if dims.iter().any(|&d| d >= n as usize) => {
            (0..dims.len().min(n as usize)).collect()
        }
        _ => dims,
    }
}

/// The sequence and dimensions the check uses in base `base`.
pub fn net_sequence(base: PowerOfTwoBase) -> (SequenceKind, Vec<usize>) {
    match base.base() {
        2 => (SequenceKind::Sobol, vec![0, 1, 2]),
        4 => (SequenceKind::Sz4, vec![0, 1, 2, 3]),
        16 => (SequenceKind::Sz16, vec![0, 5, 10, 15]),
        b => (SequenceKind::Faure(base), vec![0, 1, b as usize - 1]),
    }
}

/// Every base 2^(kq) ≤ 256 a base-2^q scramble is nested in, its own first.
pub fn nested_bases(base: PowerOfTwoBase) -> Vec<PowerOfTwoBase> {
    let q = base.q();
    (1..=8 / q)
        .map(|k| PowerOfTwoBase::from_q(k * q).expect("k·q ≤ 8"))
        .collect()
}

/// The largest m the check uses in `base` at `level`: b^m within the level's size, but at
/// least 2 (in base 256, 65,536 points), so every base has boxes in two coordinates at once.
pub fn max_m(base: PowerOfTwoBase, level: Level) -> u32 {
    (level.plan().net_log2_points / base.q()).max(2)
}

/// The nets of one base that kept their t-values: the sequence, its dimensions and every m
/// up to `top_m`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetsKept {
    /// The sequence (`sobol`, `sz4`, `faure:base=8`, …).
    pub sequence: String,
    /// Its dimensions checked together.
    pub dims: Vec<usize>,
    /// Every m from 1 to this kept its t-value.
    pub top_m: u32,
}

impl std::fmt::Display for NetsKept {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} dims {:?} m ≤ {}",
            self.sequence, self.dims, self.top_m
        )
    }
}

/// The first net of one base whose t-value the scramble changed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetBroken {
    /// The sequence.
    pub sequence: String,
    /// Its dimensions.
    pub dims: Vec<usize>,
    /// The net's m (b^m points).
    pub m: u32,
    /// The t-value after scrambling.
    pub scrambled_t: u32,
    /// The t-value before (the generator matrices').
    pub t: u32,
}

impl std::fmt::Display for NetBroken {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} dims {:?}, m = {}: t = {} after scrambling, {} before",
            self.sequence, self.dims, self.m, self.scrambled_t, self.t
        )
    }
}

/// One base's net check: every m keeps its t-value, or the first m that does not. Uses
/// dimensions 0..`max_dims` only (see [`served_dims`]).
pub fn check_base(
    s: &dyn Scrambler,
    width: Width,
    base: PowerOfTwoBase,
    level: Level,
    max_dims: Option<u32>,
) -> Result<NetsKept, NetBroken> {
    let (kind, dims) = net_sequence(base);
    let dims = served_dims(dims, max_dims);
    let seq = kind
        .build(dims.iter().max().expect("dims") + 1, width)
        .expect("built-in sequence");
    let r = base.q();
    // A net of b^m points reads m digits: all of them must fit the word (K-bit views).
    let top = max_m(base, level).min(width.bits() / r);
    for m in 1..=top {
        let expected = rank::t_value(&seq, &dims, r, m).expect("rank path");
        let n = 1u64 << (r * m);
        let columns = dims
            .iter()
            .map(|&j| {
                let mut column: Vec<u64> = (0..n).map(|i| seq.point(i, j)).collect();
                s.scramble_batch(&mut column, width, j as u32);
                column
            })
            .collect();
        let p = PointSet::from_columns(width, columns).expect("points");
        let got =
            t_value(&p, CheckBase::new(base.base() as u64).expect("base"), m).expect("t-value");
        if got != expected {
            return Err(NetBroken {
                sequence: kind.name(),
                dims,
                m,
                scrambled_t: got,
                t: expected,
            });
        }
    }
    Ok(NetsKept {
        sequence: kind.name(),
        dims,
        top_m: top,
    })
}

/// The `nets` check: every base the scrambler is nested in (its own only with
/// `own_base_only`), in dimensions 0..`max_dims`.
pub fn check_nets(
    s: &dyn Scrambler,
    width: Width,
    level: Level,
    max_dims: Option<u32>,
    own_base_only: bool,
) -> (Verdict, String) {
    let mut kept = Vec::new();
    let bases = if own_base_only {
        vec![s.base()]
    } else {
        nested_bases(s.base())
    };
    for base in bases.into_iter().filter(|b| b.q() <= width.bits()) {
        match check_base(s, width, base, level, max_dims) {
            Ok(summary) => kept.push(summary.to_string()),
            Err(broken) => return (Verdict::Fail, broken.to_string()),
        }
    }
    (Verdict::Pass, format!("t-values kept: {}", kept.join("; ")))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bases(q: u32) -> Vec<u32> {
        nested_bases(PowerOfTwoBase::from_q(q).unwrap())
            .iter()
            .map(|b| b.base())
            .collect()
    }

    #[test]
    fn nets_keep_their_own_dimensions_where_served_and_take_the_first_ones_otherwise() {
        assert_eq!(served_dims(vec![0, 1, 255], None), [0, 1, 255]);
        assert_eq!(served_dims(vec![0, 1, 255], Some(256)), [0, 1, 255]);
        assert_eq!(served_dims(vec![0, 1, 255], Some(255)), [0, 1, 2]);
        assert_eq!(served_dims(vec![0, 5, 10, 15], Some(4)), [0, 1, 2, 3]);
        assert_eq!(served_dims(vec![0, 1, 2], Some(2)), [0, 1]);
        assert_eq!(served_dims(vec![0, 1, 2], Some(1)), [0]);
        // A sequence cut to served dimensions still checks every m of its base.
        let s = gartowen_core::Identity;
        let kept = check_base(&s, Width::W32, PowerOfTwoBase::B16, Level::Quick, Some(2));
        assert_eq!(kept.unwrap().dims, [0, 1]);
    }

    #[test]
    fn a_base_is_nested_in_its_powers_up_to_256() {
        assert_eq!(bases(1), vec![2, 4, 8, 16, 32, 64, 128, 256]);
        assert_eq!(bases(2), vec![4, 16, 64, 256]);
        assert_eq!(bases(3), vec![8, 64]);
        assert_eq!(bases(4), vec![16, 256]);
        for q in 5..=8 {
            assert_eq!(bases(q), vec![1 << q]);
        }
    }

    #[test]
    fn every_base_checks_a_multi_dimensional_zero_net() {
        for q in 1..=8 {
            let base = PowerOfTwoBase::from_q(q).unwrap();
            let (kind, dims) = net_sequence(base);
            assert_eq!(kind.base(), base);
            assert!(dims.len() >= 3, "base {}", base.base());
            let seq = kind
                .build(dims.iter().max().unwrap() + 1, Width::W32)
                .unwrap();
            // Sobol's dims 0..3 are a (1,3)-sequence; every other sequence here is (0,s).
            let t = if q == 1 { 1 } else { 0 };
            for m in 1..=max_m(base, Level::Quick) {
                assert!(
                    rank::t_value(&seq, &dims, q, m).unwrap() <= t,
                    "q {q} m {m}"
                );
            }
            assert!(base.base().pow(max_m(base, Level::Quick)) >= 256);
        }
        assert_eq!(max_m(PowerOfTwoBase::B2, Level::Full), 16);
        assert_eq!(max_m(PowerOfTwoBase::B256, Level::Exhaustive), 2);
    }
}
