//! The node laws a sweep reports: cells numbered as the inspector numbers them, counts equal
//! to the inspector's reconstruction, a translation scramble told from a uniform one, and each
//! depth's stated distance and test.

use super::chunk_scan::{node_cell, node_cells};
use super::tests::{b, w, whole};
use super::*;
use gartowen_core::{Permutation, SplitMix64};
use gartowen_oracles::inspector::{inspect_exhaustive, NodeLaw};
use gartowen_owen::{FullTreeOwen, OwenVariant};

#[test]
fn node_cells_number_permutations_as_the_inspector_does() {
    for n in [2usize, 3, 4] {
        let mut seen = vec![false; node_cells(n as u32)];
        let mut rng = SplitMix64::new(9);
        for _ in 0..500 {
            let p = Permutation::random(n, &mut rng).unwrap();
            let cell = node_cell(p.as_slice()).unwrap() as usize;
            assert_eq!(cell, NodeLaw::cell(&p));
            seen[cell] = true;
        }
        assert!(seen.iter().all(|&s| s), "every cell of S_{n} is reached");
    }
    let mut rng = SplitMix64::new(10);
    for n in [8usize, 16, 256] {
        for _ in 0..200 {
            let p = Permutation::random(n, &mut rng).unwrap();
            assert_eq!(node_cell(p.as_slice()).unwrap() as usize, NodeLaw::cell(&p));
            assert!((node_cell(p.as_slice()).unwrap() as usize) < node_cells(n as u32));
        }
    }
    assert_eq!(node_cell(&[3, 3, 0, 1, 2, 4, 5, 6]), None);
    assert_eq!((node_cells(2), node_cells(4), node_cells(8)), (2, 24, 56));
}

#[test]
fn node_laws_equal_the_inspectors_reconstruction() {
    // Two independent paths to the same node permutations: the inspector reconstructs every
    // node from all words; the sweep reads depths < d from π and deeper ones from the scan.
    for (q, variant) in [
        (1, OwenVariant::Uniform),
        (2, OwenVariant::Uniform),
        (2, OwenVariant::Xor),
        (3, OwenVariant::Affine),
        (4, OwenVariant::CyclicShift),
        (8, OwenVariant::Uniform),
    ] {
        let s = FullTreeOwen::new(b(q), variant, 21);
        let v = whole(&s, w(16), 2);
        let plan = SweepPlan::new(w(16), b(q)).unwrap();
        assert_eq!(v.node_laws.len() as u32, plan.law_depths());
        let mut summed = vec![0u64; node_cells(1 << q)];
        for (k, law) in v.node_laws.iter().enumerate() {
            assert_eq!(law.depth, k as u32);
            assert_eq!(law.nodes, 1 << (q * k as u32), "q {q} depth {k}");
            for &(cell, n) in &law.counts {
                summed[cell as usize] += n;
            }
        }
        let inspected = inspect_exhaustive(&|x| s.scramble(x, w(16), 2), w(16), b(q), 16);
        assert_eq!(summed, inspected.node_law.counts, "q {q} {variant:?}");
    }
}

#[test]
fn a_translation_scramble_shows_in_the_node_law_and_a_uniform_one_does_not() {
    // Base 4, 16 bits: depth 5 has 1024 nodes over 24 cells. Xor nodes only reach 4 cells.
    let xor = whole(&FullTreeOwen::new(b(2), OwenVariant::Xor, 1), w(16), 0);
    let uni = whole(&FullTreeOwen::new(b(2), OwenVariant::Uniform, 1), w(16), 0);
    let (lx, lu) = (&xor.node_laws[5], &uni.node_laws[5]);
    assert_eq!(lx.counts.len(), 4);
    assert!(lx.p_value < 1e-12 && lx.total_variation > 0.8);
    assert!(lu.p_value > 1e-4, "{lu:?}");
}

#[test]
fn a_depth_law_states_its_cells_distance_and_test() {
    use super::combine::depth_law;
    // Base 4: 24 cells, all mass in 4 of them equally: TV = 1 − 4/24.
    let mut counts = vec![0u64; 24];
    for c in [0, 5, 10, 23] {
        counts[c] = 25;
    }
    let law = depth_law(3, 4, counts);
    assert_eq!(law.cells_are, "S_b ranks");
    assert_eq!((law.depth, law.nodes, law.dof), (3, 100, 23));
    assert!((law.total_variation - (1.0 - 4.0 / 24.0)).abs() < 1e-12);
    assert_eq!(law.counts, vec![(0, 25), (5, 25), (10, 25), (23, 25)]);
    assert!(law.p_value < 1e-20);
    // Base 8: (π(0), π(1)) cells; a perfectly even law has TV 0 and p = 1.
    let even = depth_law(1, 8, vec![2; 56]);
    assert_eq!(even.cells_are, "(pi(0), pi(1))");
    assert!(even.total_variation.abs() < 1e-12 && even.chi_square == 0.0);
    assert!(even.p_value > 0.999);
    // Half the mass in one of two cells more than uniform: TV = 0.25.
    let tilted = depth_law(0, 2, vec![3, 1]);
    assert!((tilted.total_variation - 0.25).abs() < 1e-12);
}
