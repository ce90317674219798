//! The Rust side of proofs/: bounded-size checks of the statements proved in Coq.
//! T2–T4 are exercised by the inspector and net-checker tests (see proofs/README.md); T1 and
//! T5 are checked here by enumeration and by the same counterexample.

use gartowen::core::{DigitLayout, PowerOfTwoBase, Width};
use gartowen::netcheck::counting::check_net;
use gartowen::netcheck::{CheckBase, PointSet};
use gartowen::oracles::exact_laws::all_permutations;
use gartowen::oracles::inspector::inspect_exhaustive;
use std::collections::HashSet;

/// T1 on S_4 and S_8: π = ψ ⊕ B with ψ(0) = 0 and B = π(0), uniquely; so b! = b·(b − 1)!.
#[test]
fn t1_factorization_over_s4_and_s8() {
    for (n, gl_size) in [(4usize, 6usize), (8, 168)] {
        let perms = all_permutations(n);
        let mut pairs = HashSet::new();
        let mut linear = 0;
        for p in &perms {
            let b = p.apply(0);
            let psi: Vec<u32> = (0..n as u32).map(|x| p.apply(x) ^ b).collect();
            assert_eq!(psi[0], 0);
            for x in 0..n as u32 {
                assert_eq!(p.apply(x), psi[x as usize] ^ b);
            }
            // Uniqueness: any (ψ', B') with ψ'(0) = 0 reproducing π has B' = π(0), hence ψ' = ψ.
            for b2 in 0..n as u32 {
                let psi2: Vec<u32> = (0..n as u32).map(|x| p.apply(x) ^ b2).collect();
                assert_eq!(psi2[0] == 0, b2 == b);
            }
            assert!(
                pairs.insert((psi.clone(), b)),
                "the map π ↦ (ψ, B) is injective"
            );
            linear += (0..n).all(|a| (0..n).all(|c| psi[a ^ c] == psi[a] ^ psi[c])) as usize;
        }
        let fact = |k: usize| (1..=k).product::<usize>();
        assert_eq!(perms.len(), fact(n));
        assert_eq!(pairs.len(), n * fact(n - 1), "b! = b·(b − 1)!");
        // Affine maps are those with linear ψ: |AGL(q,2)| = b·|GL(q,2)|; for b = 4 that is all of S_4.
        assert_eq!(linear, n * gl_size, "|AGL(q,2)| = b·|GL(q,2)|");
        assert_eq!(
            linear == perms.len(),
            n == 4,
            "AGL(2,2) = S_4, AGL(3,2) ≠ S_8"
        );
    }
}

/// T5: the base-4 root permutation 0→0, 3→1, 1→2, 2→3 on the first coordinate of the binary
/// (0,2,2)-net {(00,00), (10,10), (01,11), (11,01)} — the same example as proofs/Counterexample.v.
#[test]
fn t5_counterexample_through_the_rust_checker() {
    let w = Width::new(8).unwrap();
    let layout = DigitLayout::new(w, PowerOfTwoBase::B4);
    let top = |bits: u64| bits << 6; // two leading bits of an 8-bit word
    let xs = [0b00, 0b10, 0b01, 0b11].map(top);
    let ys = [0b00, 0b10, 0b11, 0b01].map(top);
    let before = PointSet::from_columns(w, vec![xs.to_vec(), ys.to_vec()]).unwrap();
    let base2 = CheckBase::new(2).unwrap();
    assert!(check_net(&before, base2, 2, 0).unwrap().holds);

    let perm4 = [0u32, 2, 3, 1]; // digit d ↦ perm4[d]
    let scramble = |x: u64| layout.set(x, 0, perm4[layout.get(x, 0) as usize]);
    let after_x: Vec<u64> = xs.iter().map(|&x| scramble(x)).collect();
    let after = PointSet::from_columns(w, vec![after_x, ys.to_vec()]).unwrap();
    let r = check_net(&after, base2, 2, 0).unwrap();
    let f = r.first_failure.expect("the binary net is broken");
    assert_eq!((f.shape.clone(), f.count), (vec![1, 1], 2));
    // The Coq proof exhibits the box [0,1/2) × [0,1/2); it holds two points too.
    let rows: Vec<Vec<u64>> = (0..4).map(|i| after.point(i)).collect();
    assert_eq!(
        gartowen::oracles::box_counting::count_in_box(&rows, 8, 2, &[1, 1], &[0, 0]),
        2
    );
    // The map is a base-4 nested scramble, and not a binary one.
    assert!(inspect_exhaustive(&scramble, w, PowerOfTwoBase::B4, 4).nested_scramble);
    assert!(!inspect_exhaustive(&scramble, w, PowerOfTwoBase::B2, 8).nested_scramble);
}
