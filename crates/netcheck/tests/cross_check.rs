//! The counting path, the rank path and the brute-force oracle decide the same facts.

use gartowen_core::PowerOfTwoBase;
use gartowen_core::{SplitMix64, Width};
use gartowen_netcheck::counting::{check_net, check_sequence, t_value};
use gartowen_netcheck::rank::{self, RowMatrices};
use gartowen_netcheck::{CheckBase, PointSet, ProjectionSpec};
use gartowen_oracles::box_counting;
use gartowen_seq::{sobol, sz, DigitalSequence};
use proptest::prelude::*;

/// The first n points (natural order) of the given dimensions, as a point set.
fn points(seq: &DigitalSequence, dims: &[usize], n: u64) -> PointSet {
    PointSet::from_sequence(seq, dims, n, |x, _| x).unwrap()
}

fn rows_of(p: &PointSet) -> Vec<Vec<u64>> {
    (0..p.len()).map(|i| p.point(i)).collect()
}

fn random_sequence(seed: u64, dims: usize, width: Width) -> DigitalSequence {
    let mut rng = SplitMix64::new(seed);
    let cols: Vec<Vec<u64>> = (0..dims)
        .map(|_| {
            (0..width.bits())
                .map(|_| rng.next_u64() & width.mask())
                .collect()
        })
        .collect();
    DigitalSequence::from_columns("random", width, PowerOfTwoBase::B2, &cols).unwrap()
}

/// Counting over 2^m points against the rank of the generator matrices for pairs of the first
/// 32 Sobol dimensions: every pair up to m = `every_pair_to`, then up to m = 20 the pairs
/// `sampled` (every pair when `None`). Returns the t-values found, keyed (i, j, m).
fn sobol_pair_t_values(
    every_pair_to: u32,
    sampled: Option<&[[usize; 2]]>,
) -> std::collections::BTreeMap<(usize, usize, u32), u32> {
    let seq = sobol::sequence(32, Width::W32).unwrap();
    let base = CheckBase::new(2).unwrap();
    let all_pairs = ProjectionSpec::Pairs.expand(32).unwrap();
    assert_eq!(all_pairs.len(), 496);
    let all_points = points(&seq, &(0..32).collect::<Vec<_>>(), 1 << 20);
    let mut table = std::collections::BTreeMap::new();
    for m in 1..=20u32 {
        let prefix = all_points.prefix(1 << m);
        let pairs: Vec<Vec<usize>> = match sampled {
            Some(sample) if m > every_pair_to => sample.iter().map(|p| p.to_vec()).collect(),
            _ => all_pairs.clone(),
        };
        for pair in &pairs {
            let by_rank = rank::t_value(&seq, pair, 1, m).unwrap();
            let by_count = t_value(&prefix.project(pair).unwrap(), base, m).unwrap();
            assert_eq!(by_count, by_rank, "pair {pair:?} m {m}");
            table.insert((pair[0], pair[1], m), by_rank);
        }
    }
    table
}

/// A sample frozen as a regression table (both paths agree on it). Dimensions 0 and 1 form a
/// (0,2)-sequence; pairs with higher dimensions reach larger t.
fn assert_sobol_golden(table: &std::collections::BTreeMap<(usize, usize, u32), u32>) {
    for m in 1..=20 {
        assert_eq!(table[&(0, 1, m)], 0);
    }
    let golden = [
        ((0, 2, 20), 1),
        ((1, 2, 20), 1),
        ((2, 3, 12), 2),
        ((4, 7, 10), 1),
        ((30, 31, 20), 2),
    ];
    for (key, t) in golden {
        assert_eq!(table[&key], t, "golden {key:?}");
    }
}

#[test]
fn sobol_pairs_of_the_first_32_dims_agree_to_m_14_and_a_sample_to_m_20() {
    // All 496 pairs to m = 14; beyond, the golden pairs and a spread of 11 others (every
    // dimension 0..31 appears). The whole sweep to m = 20 is the large tier's test below.
    let sample = [
        [0, 1],
        [0, 2],
        [1, 2],
        [30, 31],
        [3, 17],
        [4, 29],
        [5, 23],
        [6, 11],
        [8, 27],
        [9, 14],
        [10, 21],
        [12, 19],
        [13, 26],
        [15, 24],
        [16, 28],
        [7, 18],
        [20, 25],
        [22, 31],
    ];
    let table = sobol_pair_t_values(14, Some(&sample));
    assert_eq!(table.len(), 496 * 14 + sample.len() * 6);
    assert_sobol_golden(&table);
}

#[test]
#[ignore = "large tier (scripts/test-large.sh): every pair to m = 20, about 4 minutes"]
fn sobol_pairs_of_the_first_32_dims_agree_for_m_1_to_20() {
    let table = sobol_pair_t_values(20, None);
    assert_eq!(table.len(), 496 * 20);
    assert_sobol_golden(&table);
}

#[test]
fn counting_agrees_with_brute_force_on_tiny_sets() {
    // Exhaustive over small m in bases 2, 3, 4 and 5 (non-power bases use exact u128 digits).
    let mut rng = SplitMix64::new(11);
    for b in [2u64, 3, 4, 5] {
        for m in 1..=3u32 {
            let n = b.pow(m) as usize;
            if n > 125 {
                continue;
            }
            for trial in 0..30 {
                let w = 12u32;
                let width = Width::new(w).unwrap();
                let rows: Vec<Vec<u64>> = (0..n)
                    .map(|_| (0..2).map(|_| rng.next_u64() & width.mask()).collect())
                    .collect();
                let p = PointSet::from_rows(width, &rows).unwrap();
                let base = CheckBase::new(b).unwrap();
                let t_fast = t_value(&p, base, m).unwrap();
                assert_eq!(
                    t_fast,
                    box_counting::t_value(&rows, w, b, m),
                    "b {b} m {m} trial {trial}"
                );
                for t in 0..=m {
                    let fast = check_net(&p, base, m, t).unwrap();
                    let brute = box_counting::first_failure(&rows, w, b, m, t);
                    assert_eq!(fast.holds, brute.is_none());
                    if let (Some(f), Some(bf)) = (&fast.first_failure, &brute) {
                        assert_eq!(f.shape, bf.shape, "first failing shape");
                        assert_eq!(
                            f.count,
                            box_counting::count_in_box(&rows, w, b, &f.shape, &f.box_index),
                            "reported count of the reported box"
                        );
                        assert!(f.count > f.expected);
                    }
                }
            }
        }
    }
}

#[test]
fn sz4_is_a_0_4_sequence_in_base_4_and_its_pairs_are_binary_0_2() {
    let seq = sz::sz4(4, Width::W32).unwrap();
    // Rank path to 24 index bits (m = 12 base-4 digits; binary m = 24).
    assert_eq!(
        rank::sequence_t_value(&seq, &[0, 1, 2, 3], 2, 12).unwrap(),
        0
    );
    for pair in [[0, 1], [2, 3]] {
        assert_eq!(
            rank::sequence_t_value(&seq, &pair, 1, 24).unwrap(),
            0,
            "{pair:?}"
        );
    }
    // Counting path: base 4 to m = 8 (65536 points), every block of every size.
    let p = points(&seq, &[0, 1, 2, 3], 1 << 16);
    let r = check_sequence(&p, CheckBase::new(4).unwrap(), 0, 8).unwrap();
    assert!(r.holds, "{r:?}");
    for pair in [[0, 1], [2, 3]] {
        let r = check_sequence(
            &p.project(&pair).unwrap(),
            CheckBase::new(2).unwrap(),
            0,
            16,
        )
        .unwrap();
        assert!(r.holds, "{pair:?}: {r:?}");
    }
}

#[test]
fn sz16_is_a_0_16_sequence_in_base_16_with_0_4_quads_and_binary_0_2_pairs() {
    for seq in [
        sz::sz16(16, Width::W32).unwrap(),
        sz::sz16_faure(16, Width::W32).unwrap(),
    ] {
        sz16_properties(&seq);
    }
}

/// The worst binary t-value of the 120 pairs of sz16 over m ≤ 16: 5 for the searched quads,
/// 6 for the earlier construction (whose pairs (0,4), (0,8), (0,12) shared leading digits);
/// and no pair across quads is a binary (0,2)-sequence (they are not claimed to be).
#[test]
fn sz16s_searched_quads_improve_the_worst_binary_pair() {
    let worst = |seq: &gartowen_seq::DigitalSequence| {
        let mut ts = Vec::new();
        for i in 0..16 {
            for j in i + 1..16 {
                ts.push(rank::sequence_t_value(seq, &[i, j], 1, 16).unwrap());
            }
        }
        let w = *ts.iter().max().unwrap();
        (w, ts.iter().filter(|&&t| t == w).count())
    };
    assert_eq!(worst(&sz::sz16(16, Width::W32).unwrap()), (5, 24));
    assert_eq!(worst(&sz::sz16_faure(16, Width::W32).unwrap()), (6, 12));
    // The earlier artefact: dimensions 0 and 4 agree in their leading base-16 digit over
    // the first 16 points; the searched quads do not.
    let old = sz::sz16_faure(5, Width::W32).unwrap();
    let new = sz::sz16(5, Width::W32).unwrap();
    let lead = |s: &gartowen_seq::DigitalSequence, j, n| s.point(n, j) >> 28;
    assert!((0..16).all(|n| lead(&old, 0, n) == lead(&old, 4, n)));
    assert!((0..16).any(|n| lead(&new, 0, n) != lead(&new, 4, n)));
}

fn sz16_properties(seq: &gartowen_seq::DigitalSequence) {
    let seq = seq.clone();
    let all: Vec<usize> = (0..16).collect();
    assert_eq!(
        rank::sequence_t_value(&seq, &all, 4, 6).unwrap(),
        0,
        "rank path, 24 index bits"
    );
    for quad in ProjectionSpec::Blocks(4).expand(16).unwrap() {
        assert_eq!(
            rank::sequence_t_value(&seq, &quad, 2, 12).unwrap(),
            0,
            "quad {quad:?}"
        );
    }
    for pair in ProjectionSpec::Blocks(2).expand(16).unwrap() {
        assert_eq!(
            rank::sequence_t_value(&seq, &pair, 1, 24).unwrap(),
            0,
            "pair {pair:?}"
        );
    }
    // Counting path: base 16 to m = 4 (65536 points, 3876 shapes per net at m = 4).
    let p = points(&seq, &all, 1 << 16);
    let r = check_net(&p, CheckBase::new(16).unwrap(), 4, 0).unwrap();
    assert!(r.holds && r.shapes_checked == 3876, "{r:?}");
    let r = check_sequence(&p.prefix(1 << 12), CheckBase::new(16).unwrap(), 0, 3).unwrap();
    assert!(r.holds, "{r:?}");
}

#[test]
fn cross_group_pair_0_2_is_not_binary_0_2_at_m_2() {
    for seq in [
        sz::sz4(4, Width::W32).unwrap(),
        sz::sz16(4, Width::W32).unwrap(),
    ] {
        assert!(rank::t_value(&seq, &[0, 2], 1, 2).unwrap() > 0);
        let p = points(&seq, &[0, 2], 4);
        let r = check_net(&p, CheckBase::new(2).unwrap(), 2, 0).unwrap();
        assert!(!r.holds, "expected: cross-group pairs are not binary (0,2)");
        assert_eq!(
            Some(r.first_failure.unwrap().shape),
            RowMatrices::new(&seq, &[0, 2], 1, 2)
                .unwrap()
                .first_failure(0)
                .unwrap()
        );
    }
}

#[test]
fn a_mutated_point_is_caught_with_the_failing_shape() {
    let seq = sobol::sequence(2, Width::W32).unwrap();
    let mut p = points(&seq, &[0, 1], 1 << 10);
    assert!(
        check_net(&p, CheckBase::new(2).unwrap(), 10, 0)
            .unwrap()
            .holds
    );
    // Move point 5 onto point 6's box in dimension 0 at full depth: shape (10, 0) collides.
    let x6 = p.column(0)[6];
    p.set(5, 0, x6 ^ 1);
    let r = check_net(&p, CheckBase::new(2).unwrap(), 10, 0).unwrap();
    assert!(!r.holds);
    let rows = rows_of(&p);
    let brute = box_counting::first_failure(&rows, 32, 2, 10, 0).unwrap();
    let f = r.first_failure.unwrap();
    assert_eq!(f.shape, brute.shape);
    assert_eq!(f.count, 2);
    assert_eq!(
        box_counting::count_in_box(&rows, 32, 2, &f.shape, &f.box_index),
        2
    );
}

#[test]
fn a_mutated_matrix_is_caught_by_both_paths_with_the_same_shape() {
    let seq = sobol::sequence(2, Width::W32).unwrap();
    let mut cols: Vec<Vec<u64>> = (0..2).map(|j| seq.columns(j).to_vec()).collect();
    cols[1][3] = cols[1][2]; // two equal columns: dependent rows
    let broken =
        DigitalSequence::from_columns("broken", Width::W32, PowerOfTwoBase::B2, &cols).unwrap();
    let by_rank = RowMatrices::new(&broken, &[0, 1], 1, 6)
        .unwrap()
        .first_failure(0)
        .unwrap();
    let r = check_net(
        &points(&broken, &[0, 1], 64),
        CheckBase::new(2).unwrap(),
        6,
        0,
    )
    .unwrap();
    assert!(by_rank.is_some() && !r.holds);
    assert_eq!(Some(r.first_failure.unwrap().shape), by_rank);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn random_binary_matrices_both_paths_agree(seed in any::<u64>(), m in 1u32..=9, s in 2usize..=4) {
        let seq = random_sequence(seed, s, Width::new(16).unwrap());
        let dims: Vec<usize> = (0..s).collect();
        let p = points(&seq, &dims, 1 << m);
        let base = CheckBase::new(2).unwrap();
        for t in 0..=m {
            let fast = check_net(&p, base, m, t).unwrap();
            let by_rank = RowMatrices::new(&seq, &dims, 1, m).unwrap().first_failure(t).unwrap();
            prop_assert_eq!(fast.first_failure.map(|f| f.shape), by_rank);
        }
    }

    #[test]
    fn random_base_4_matrices_both_paths_agree(seed in any::<u64>(), m in 1u32..=4) {
        let seq = random_sequence(seed, 3, Width::new(16).unwrap());
        let p = points(&seq, &[0, 1, 2], 1 << (2 * m));
        let base = CheckBase::new(4).unwrap();
        let t_count = t_value(&p, base, m).unwrap();
        prop_assert_eq!(t_count, rank::t_value(&seq, &[0, 1, 2], 2, m).unwrap());
    }
}

/// The 2-D Hammersley set in base b with b^m points, as 32-bit words ⌈v · 2^32⌉.
fn hammersley(b: u64, m: u32) -> PointSet {
    let n = b.pow(m);
    let word = |num: u64, den: u64| ((num << 32).div_ceil(den)).min(u32::MAX as u64);
    let x: Vec<u64> = (0..n).map(|i| word(i, n)).collect();
    let y: Vec<u64> = (0..n)
        .map(|i| {
            let (mut rev, mut rest) = (0u64, i);
            for _ in 0..m {
                rev = rev * b + rest % b;
                rest /= b;
            }
            word(rev, n)
        })
        .collect();
    PointSet::from_columns(Width::W32, vec![x, y]).unwrap()
}

#[test]
fn the_shape_tree_walk_equals_the_per_shape_path_report_for_report() {
    // Two paths to every net verdict: the tree walk (incremental keys, parallel, early exit,
    // the fused t = 0 pass) and the plain per-shape path. Sets: digital nets (hold at their t,
    // fail below), the same with one coordinate moved (fail at some deep shape), and random
    // words (fail early); bases 2, 3, 4, 5, 8, 16; t from 0 up.
    use gartowen_netcheck::counting::check_net_per_shape;
    let mut rng = gartowen_core::SplitMix64::new(19);
    let mut compared = 0;
    for (b, m, dims) in [
        (2u64, 10u32, 5usize),
        (3, 5, 3),
        (4, 5, 4),
        (5, 3, 4),
        (8, 3, 6),
        (16, 3, 8),
    ] {
        let base = CheckBase::new(b).unwrap();
        let n = b.pow(m) as usize;
        let width = Width::W32;
        // A digital net in base 2^q where b is one; random words otherwise.
        let net: Option<PointSet> = match b {
            2 => Some(points(
                &sobol::sequence(dims, width).unwrap(),
                &(0..dims).collect::<Vec<_>>(),
                n as u64,
            )),
            4 => Some(points(
                &sz::sz4(dims, width).unwrap(),
                &(0..dims).collect::<Vec<_>>(),
                n as u64,
            )),
            16 => Some(points(
                &sz::sz16(dims, width).unwrap(),
                &(0..dims).collect::<Vec<_>>(),
                n as u64,
            )),
            _ => None,
        };
        let random = PointSet::from_columns(
            width,
            (0..dims)
                .map(|_| (0..n).map(|_| rng.next_u32() as u64).collect())
                .collect(),
        )
        .unwrap();
        let mut sets = vec![random];
        if dims == 3 || dims == 4 {
            // Base 3 and 5: the Hammersley (0,m,2)-net (i/b^m, radical inverse of i), words
            // rounded up so that floor(x · b^k) is exact; with a moved point as well.
            let net = hammersley(b, m);
            let mut moved = net.clone();
            moved.set(n / 2, 1, net.column(1)[n / 3]);
            sets.push(net);
            sets.push(moved);
        }
        if let Some(net) = net {
            let mut moved = net.clone();
            let (i, j) = (
                rng.bounded(n as u32) as usize,
                rng.bounded(dims as u32) as usize,
            );
            moved.set(i, j, net.column(j)[i] ^ 1 << 20);
            sets.push(net);
            sets.push(moved);
        }
        for set in &sets {
            if set.dims() == 2 && b % 2 == 1 && set == &sets[1] {
                // The Hammersley set is a (0, m, 2)-net: the walk must reach its two-part leaves.
                assert!(
                    check_net(set, base, m, 0).unwrap().holds,
                    "Hammersley base {b}"
                );
            }
            for t in 0..=m.min(3) {
                let fast = check_net(set, base, m, t).unwrap();
                let plain = check_net_per_shape(set, base, m, t).unwrap();
                assert_eq!(fast, plain, "base {b} m {m} t {t} dims {dims}");
                compared += 1;
            }
        }
    }
    assert!(compared >= 40, "{compared} reports compared");
}

/// The owned path (each dimension's words freed once its digits are read) gives the same
/// report as the borrowed one: nets, nets with a moved point, random sets, bases 2, 3 and 16.
#[test]
fn the_owned_check_reports_exactly_what_the_borrowed_one_does() {
    use gartowen_netcheck::counting::check_net_owned;
    let sobol = sobol::sequence(4, Width::W32).unwrap();
    let sz16 = sz::sz16(4, Width::W32).unwrap();
    let mut cases: Vec<(PointSet, u64, u32)> = vec![
        (points(&sobol, &[0, 1, 2, 3], 1 << 10), 2, 10),
        (points(&sz16, &[0, 1, 2, 3], 1 << 12), 16, 3),
    ];
    let mut moved = points(&sobol, &[0, 1, 2], 1 << 8);
    moved.set(3, 1, moved.column(1)[4]);
    cases.push((moved, 2, 8));
    let mut rng = SplitMix64::new(5);
    let random: Vec<Vec<u64>> = (0..3)
        .map(|_| (0..243).map(|_| rng.next_u32() as u64).collect())
        .collect();
    cases.push((PointSet::from_columns(Width::W32, random).unwrap(), 3, 5));
    for (set, b, m) in cases {
        let base = CheckBase::new(b).unwrap();
        for t in 0..=2 {
            let borrowed = check_net(&set, base, m, t).unwrap();
            let owned = check_net_owned(set.clone(), base, m, t, &|_| {}).unwrap();
            assert_eq!(owned, borrowed, "b {b} m {m} t {t}");
        }
    }
}

/// The packed leaf pass (lanes of b^v bits sharing a word per parent box, up to the single
/// 64-bit lane of base 64) and the bitmap pass against the per-shape path, on
/// Faure (0,m,s)-nets in bases 2, 4, 8, 16 and 64 with one digit moved: every dimension (so
/// every lane position of a group) and every digit position (so leaves of every part v and
/// parents of every depth see the collision). Each moved set fails t = 0, and both paths must
/// name the same first failing shape and box, at t = 0 and at t = 1.
#[test]
fn packed_leaf_lanes_find_every_moved_digit_like_the_per_shape_path() {
    use gartowen_netcheck::counting::check_net_per_shape;
    use gartowen_seq::faure::faure;
    let mut compared = 0;
    // A (0,m,s)-net in base b has s ≤ b + 1 (Faure gives s ≤ b).
    for (q, m, dims) in [
        (1u32, 8u32, 2usize),
        (2, 4, 4),
        (3, 3, 5),
        (4, 3, 6),
        (6, 2, 5),
    ] {
        let b = 1u64 << q;
        let base = CheckBase::new(b).unwrap();
        let seq = faure(PowerOfTwoBase::from_q(q).unwrap(), dims, Width::W32).unwrap();
        let n = b.pow(m);
        let net = points(&seq, &(0..dims).collect::<Vec<_>>(), n);
        assert!(check_net(&net, base, m, 0).unwrap().holds, "base {b}");
        for j in 0..dims {
            for r in 0..m {
                // Point i's digit r of dimension j plus one (mod b).
                let i = ((r as usize * 7 + j * 3) % n as usize).max(1);
                let shift = 32 - q * (r + 1);
                let x = net.column(j)[i];
                let digit = (x >> shift) & (b - 1);
                let moved_x = (x & !((b - 1) << shift)) | (((digit + 1) % b) << shift);
                let mut moved = net.clone();
                moved.set(i, j, moved_x);
                let fast = check_net(&moved, base, m, 0).unwrap();
                let plain = check_net_per_shape(&moved, base, m, 0).unwrap();
                assert!(
                    !fast.holds,
                    "base {b}: dim {j} digit {r} moved, still a net"
                );
                assert_eq!(fast, plain, "base {b} dim {j} digit {r}");
                // t = 1: boxes of b points, one now holding b + 1 and another b − 1, none
                // empty. Only the counting check may decide it: a pass that asks whether every
                // box was hit would call it a net.
                let fast = check_net(&moved, base, m, 1).unwrap();
                assert_eq!(fast, check_net_per_shape(&moved, base, m, 1).unwrap());
                compared += 1;
            }
        }
    }
    assert_eq!(compared, 2 * 8 + 4 * 4 + 5 * 3 + 6 * 3 + 5 * 2);
}

/// Bases that are not powers of two build inner nodes' keys by multiplication and division,
/// chunk by chunk: with more points than one chunk (3^8 = 6561 > 2048) the Hammersley
/// (0,8,2)-net in base 3 holds, and with one coordinate moved both paths name the same
/// failure at t = 0 and t = 1.
#[test]
fn base_3_sets_larger_than_a_chunk_match_the_per_shape_path() {
    use gartowen_netcheck::counting::check_net_per_shape;
    let base = CheckBase::new(3).unwrap();
    let net = hammersley(3, 8);
    assert!(check_net(&net, base, 8, 0).unwrap().holds);
    let mut moved = net.clone();
    moved.set(5000, 1, net.column(1)[100]);
    for t in [0, 1] {
        let fast = check_net(&moved, base, 8, t).unwrap();
        assert!(!fast.holds, "t = {t}");
        assert_eq!(
            fast,
            check_net_per_shape(&moved, base, 8, t).unwrap(),
            "t = {t}"
        );
    }
}
