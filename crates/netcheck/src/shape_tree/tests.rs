//! Unit tests of the walk's plan and passes against their single-leaf references.

use super::{least_completion, ShapeWalk, Walk, MAX_MASK_BYTES};
use crate::CheckBase;
use gartowen_core::{PowerOfTwoBase, SplitMix64, Width};
use gartowen_seq::faure::faure;

/// A walk over the prefixes at depth `k` of 32-bit word columns, k = m (t = 0).
fn walk_of<'a>(prefix: &'a [&'a [u32]], b: u64, k: u32) -> ShapeWalk<'a> {
    ShapeWalk {
        prefix,
        depth: k,
        base: CheckBase::new(b).unwrap(),
        k,
        t_count: 1,
        n: prefix[0].len(),
    }
}

/// The narrow columns as `run` builds them.
fn narrow_of(prefix: &[&[u32]], q: u32, depth: u32) -> Vec<Vec<u8>> {
    let cut = q * depth - 8;
    prefix
        .iter()
        .map(|c| c.iter().map(|&x| (x >> cut) as u8).collect())
        .collect()
}

#[test]
fn every_lane_of_a_packed_pass_agrees_with_its_own_bitmap_pass() {
    // Two paths per leaf: its lane in the shared pass and its own b^k-bit map. Sets: Faure
    // (0,m,s)-nets (every lane full) and the same with the last dimension's values swapped
    // between random pairs of points (its lane broken, the others of its group full),
    // bases 2..64; parent
    // keys of every single-part inner node and of the root, every group the walk forms.
    let mut rng = SplitMix64::new(20261202);
    let (mut lanes_checked, mut mixed_groups) = (0, 0);
    for (q, m, dims) in [
        (1u32, 8u32, 2usize),
        (2, 4, 4),
        (3, 3, 6),
        (4, 3, 6),
        (6, 2, 5),
    ] {
        let b = 1u64 << q;
        let seq = faure(PowerOfTwoBase::from_q(q).unwrap(), dims, Width::W32).unwrap();
        let n = b.pow(m) as usize;
        let net: Vec<Vec<u32>> = (0..dims)
            .map(|j| {
                (0..n)
                    .map(|i| (seq.point(i as u64, j) >> (32 - q * m)) as u32)
                    .collect()
            })
            .collect();
        for swaps in 0..4 {
            let mut set = net.clone();
            for _ in 0..swaps {
                let (i, k) = (
                    rng.bounded(n as u32) as usize,
                    rng.bounded(n as u32) as usize,
                );
                set[dims - 1].swap(i, k);
            }
            let prefix: Vec<&[u32]> = set.iter().map(|c| c.as_slice()).collect();
            let query = walk_of(&prefix, b, m);
            let walk = Walk {
                query: &query,
                narrow: if q * m >= 8 {
                    narrow_of(&prefix, q, m)
                } else {
                    Vec::new()
                },
            };
            // (parent keys, Σd of the parent, first dimension after it)
            let mut parents = vec![(None, 0u32, 0usize)];
            for p0 in 0..dims {
                for sum in 1..m {
                    parents.push((Some(walk.extend_all(None, p0, sum)), sum, p0 + 1));
                }
            }
            for (keys, sum, next) in &parents {
                let v = m - sum;
                let Some(lanes) = walk.lanes(*sum, v) else {
                    continue;
                };
                let leaves: Vec<usize> = (*next..dims).collect();
                for group in leaves.chunks(lanes) {
                    let packed = walk.distinct_packed(keys.as_deref(), group, v);
                    assert_eq!(packed.len(), group.len());
                    for (&p, &full) in group.iter().zip(&packed) {
                        let own = walk.distinct_keys(keys.as_deref(), p, v);
                        assert_eq!(full, own, "base {b} swaps {swaps} Σd {sum} dim {p}");
                        assert!(swaps > 0 || full, "a net's lane is full");
                        lanes_checked += 1;
                    }
                    mixed_groups += usize::from(packed.contains(&true) && packed.contains(&false));
                }
            }
        }
    }
    assert!(lanes_checked >= 300, "{lanes_checked} lanes");
    assert!(
        mixed_groups > 10,
        "{mixed_groups} groups with full and broken lanes"
    );
}

#[test]
fn the_bit_passes_decide_every_shape_of_a_net_and_defer_the_rest() {
    // On a t = 0 net in base 2^q no leaf reaches the general count (packed lanes for parts
    // of ≤ 64-bit lanes, one bitmap for the rest); at t = 1 every leaf does; a broken set
    // sends its failing leaves there.
    // (Bases 4 with m = 2 and 64 with m = 1 pack the root's leaves too: b^m ≤ 64.)
    let cases = [
        (1u32, 8u32, 2usize),
        (2, 4, 4),
        (2, 2, 4),
        (4, 3, 6),
        (6, 2, 5),
        (6, 1, 5),
    ];
    for (q, m, dims) in cases {
        let b = 1u64 << q;
        let seq = faure(PowerOfTwoBase::from_q(q).unwrap(), dims, Width::W32).unwrap();
        let n = b.pow(m) as usize;
        let mut set: Vec<Vec<u32>> = (0..dims)
            .map(|j| {
                (0..n)
                    .map(|i| (seq.point(i as u64, j) >> (32 - q * m)) as u32)
                    .collect()
            })
            .collect();
        let shapes = |k: u32| crate::shapes::shapes(k, dims).unwrap().len() as u64;
        for broken in [false, true] {
            if broken {
                set[dims - 1][1] = set[dims - 1][n / 2 + 3];
            }
            let prefix: Vec<&[u32]> = set.iter().map(|c| c.as_slice()).collect();
            let t0 = walk_of(&prefix, b, m);
            let (failure, general) = t0.run_counted(true, &|_| {});
            assert_eq!(failure.is_some(), broken, "base {b}");
            if broken {
                assert!((1..shapes(m)).contains(&general), "base {b}: {general}");
            } else {
                assert_eq!(general, 0, "base {b}: leaves left to the general count");
            }
            let t1 = ShapeWalk {
                k: m - 1,
                t_count: b,
                ..walk_of(&prefix, b, m)
            };
            let (failure, general) = t1.run_counted(true, &|_| {});
            if failure.is_none() {
                assert_eq!(general, shapes(m - 1), "base {b} t = 1");
            } else {
                // Shapes after the least failing one are skipped.
                assert!((1..=shapes(m - 1)).contains(&general), "base {b} t = 1");
            }
        }
    }
}

#[test]
fn leaves_share_a_word_exactly_when_their_lanes_fit() {
    let column = vec![0u32; 1];
    let prefix = [column.as_slice()];
    // Base 16: a one-digit lane is 16 bits (4 per word), two digits are 256 bits (none).
    let w16 = walk_of(&prefix, 16, 5);
    let walk = Walk {
        query: &w16,
        narrow: Vec::new(),
    };
    assert_eq!(walk.lanes(4, 1), Some(4));
    assert_eq!(walk.lanes(3, 2), None);
    // Base 2: 2-bit to 64-bit lanes; the words of 2^19 parent boxes fit, 2^20 do not.
    let w2 = walk_of(&prefix, 2, 21);
    let walk = Walk {
        query: &w2,
        narrow: Vec::new(),
    };
    assert_eq!(walk.lanes(5, 1), Some(32));
    assert_eq!(walk.lanes(5, 6), Some(1));
    assert_eq!(walk.lanes(5, 7), None);
    assert_eq!((1usize << 19) * 8, MAX_MASK_BYTES);
    assert_eq!(walk.lanes(19, 1), Some(32));
    assert_eq!(walk.lanes(20, 1), None);
    // Only t = 0 (one point per box) is decided by set bits.
    let t1 = ShapeWalk {
        t_count: 2,
        ..walk_of(&prefix, 16, 5)
    };
    let walk = Walk {
        query: &t1,
        narrow: Vec::new(),
    };
    assert_eq!(walk.lanes(4, 1), None);
    assert!(!walk.bit_pass());
    let prime = ShapeWalk {
        base: CheckBase::new(3).unwrap(),
        ..walk_of(&prefix, 16, 5)
    };
    assert!(!Walk {
        query: &prime,
        narrow: Vec::new()
    }
    .bit_pass());
}

#[test]
fn the_least_completion_of_a_partial_shape_is_the_least_of_all() {
    // Brute force: every shape of Σd = k over 4 dimensions that agrees with a partial
    // shape up to its last nonzero part; the least in lexicographic order must be ours.
    let k = 4u32;
    let all: Vec<Vec<u32>> = (0..5u32.pow(4))
        .map(|c| {
            (0..4)
                .map(|j| (c / 5u32.pow(3 - j)) % 5)
                .collect::<Vec<u32>>()
        })
        .filter(|s: &Vec<u32>| s.iter().sum::<u32>() == k)
        .collect();
    for partial in &all {
        for cut in 0..4 {
            // The partial shape: the first `cut + 1` parts, zeros after (sum ≤ k).
            let mut p = partial.clone();
            p[cut + 1..].iter_mut().for_each(|d| *d = 0);
            if p[cut] == 0 {
                continue;
            }
            let least = all
                .iter()
                .filter(|s| s[..=cut] == p[..=cut])
                .min()
                .expect("the partial shape extends");
            assert_eq!(&least_completion(&p, k), least, "{p:?}");
        }
    }
}
