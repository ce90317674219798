//! The nested-scramble inspector in a base b that is not a power of two, probe mode: the
//! definition of "nested in base b" checked on sampled nodes of base-b digit integers.
//!
//! For node (depth k, prefix p) it evaluates every digit d at depth k, each with two random
//! tails, and requires: every output's digits above k equal (they are the prefix's image),
//! digit k agrees between the two tails (nested), and the b images are distinct (bijective).
//! Outputs must stay below b^m. Depths are probed in turn, prefixes at random.

use crate::inspector::{Violation, ViolationKind};
use gartowen_core::{RadixLayout, SplitMix64};

/// Nodes evaluated per call of the map.
const PROBES_PER_BATCH: u64 = 64;

/// What a probe inspection found.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct RadixInspection {
    /// Nodes whose map was checked in full.
    pub nodes_checked: u64,
    /// Evaluations of the map.
    pub evaluations: u64,
    /// The first violation met, if any.
    pub first_violation: Option<Violation>,
}

/// Inspects `nodes` nodes of the map `f` (scrambling a batch of words in place) from `seed`.
pub fn inspect_radix_probes(
    f: &dyn Fn(&mut [u64]),
    layout: RadixLayout,
    nodes: u64,
    seed: u64,
) -> RadixInspection {
    let (b, m) = (layout.radix().get(), layout.num_digits());
    let mut rng = SplitMix64::new(seed);
    let mut report = RadixInspection {
        nodes_checked: 0,
        evaluations: 0,
        first_violation: None,
    };
    let prefix = |x: u64, k: u32| if k == 0 { 0 } else { x / layout.place(k - 1) };
    let mut first = 0u64;
    while first < nodes && report.first_violation.is_none() {
        let last = nodes.min(first + PROBES_PER_BATCH);
        let mut inputs = Vec::new();
        let mut probes = Vec::new();
        for probe in first..last {
            let k = (probe % m as u64) as u32;
            let base_word = layout.random_word(&mut rng);
            probes.push((k, inputs.len()));
            for d in 0..b {
                for _tail in 0..2 {
                    let mut x = layout.set(base_word, k, d);
                    for j in k + 1..m {
                        x = layout.set(x, j, rng.bounded(b));
                    }
                    inputs.push(x);
                }
            }
        }
        let mut outputs = inputs.clone();
        f(&mut outputs);
        report.evaluations += outputs.len() as u64;
        'probes: for &(k, at) in &probes {
            let mut owner: Vec<Option<(u64, u64)>> = vec![None; b as usize];
            let (x0, y0) = (inputs[at], outputs[at]);
            for d in 0..b as usize {
                let pair = [at + 2 * d, at + 2 * d + 1];
                let (ins, outs) = (pair.map(|i| inputs[i]), pair.map(|i| outputs[i]));
                let found = |kind, depth, inputs, outputs| Violation {
                    kind,
                    depth,
                    prefix: prefix(ins[0], depth),
                    inputs,
                    outputs,
                };
                if let Some(&y) = outs.iter().find(|&&y| layout.check(y).is_err()) {
                    let x = ins[outs.iter().position(|&o| o == y).unwrap_or(0)];
                    let v = found(ViolationKind::OutOfRange, k, [x, x], [y, y]);
                    report.first_violation = Some(v);
                    break 'probes;
                }
                for (&x, &y) in ins.iter().zip(&outs) {
                    if let Some(j) = (0..k).find(|&j| layout.get(y, j) != layout.get(y0, j)) {
                        let v = found(ViolationKind::NotNested, j, [x0, x], [y0, y]);
                        report.first_violation = Some(v);
                        break 'probes;
                    }
                }
                let (o0, o1) = (layout.get(outs[0], k), layout.get(outs[1], k));
                if o0 != o1 {
                    let v = found(ViolationKind::NotNested, k, ins, outs);
                    report.first_violation = Some(v);
                    break 'probes;
                }
                if let Some((xo, yo)) = owner[o0 as usize] {
                    let v = found(ViolationKind::NotBijective, k, [xo, ins[0]], [yo, outs[0]]);
                    report.first_violation = Some(v);
                    break 'probes;
                }
                owner[o0 as usize] = Some((ins[0], outs[0]));
            }
            report.nodes_checked += 1;
        }
        first = last;
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::{Radix, Width};

    fn layout(b: u64) -> RadixLayout {
        RadixLayout::new(Width::W32, Radix::new(b).unwrap()).unwrap()
    }

    /// Reverses the digits' order of a base-b word below b^m: not nested.
    fn reverse_digits(l: RadixLayout, x: u64) -> u64 {
        (0..l.num_digits()).fold(0, |y, k| l.set(y, l.num_digits() - 1 - k, l.get(x, k)))
    }

    #[test]
    fn a_digitwise_shift_is_nested_and_broken_maps_are_caught_at_the_right_depth() {
        let l = layout(3);
        // Adding 1 to every digit mod 3 is nested and bijective at every node.
        let shift = |w: &mut [u64]| {
            for x in w.iter_mut() {
                *x = (0..l.num_digits()).fold(*x, |y, k| l.set(y, k, (l.get(y, k) + 1) % 3));
            }
        };
        let ok = inspect_radix_probes(&shift, l, 200, 1);
        assert_eq!((ok.nodes_checked, ok.first_violation), (200, None));
        assert_eq!(ok.evaluations, 200 * 6);

        let reversed = |w: &mut [u64]| w.iter_mut().for_each(|x| *x = reverse_digits(l, *x));
        let v = inspect_radix_probes(&reversed, l, 200, 1)
            .first_violation
            .unwrap();
        assert_eq!(v.kind, ViolationKind::NotNested);

        // Digit 5 of every word forced to 0: not bijective at depth 5.
        let squash = |w: &mut [u64]| w.iter_mut().for_each(|x| *x = l.set(*x, 5, 0));
        let v = inspect_radix_probes(&squash, l, 200, 1)
            .first_violation
            .unwrap();
        assert_eq!((v.kind, v.depth), (ViolationKind::NotBijective, 5));
        assert_eq!(l.get(v.outputs[0], 5), l.get(v.outputs[1], 5));
        assert_ne!(l.get(v.inputs[0], 5), l.get(v.inputs[1], 5));

        // A word at or above b^m is out of range.
        let over = |w: &mut [u64]| w.iter_mut().for_each(|x| *x += l.capacity());
        let v = inspect_radix_probes(&over, l, 10, 1)
            .first_violation
            .unwrap();
        assert_eq!(v.kind, ViolationKind::OutOfRange);
    }

    #[test]
    fn the_identity_in_base_7_checks_every_depth() {
        let l = layout(7);
        let r = inspect_radix_probes(&|_: &mut [u64]| {}, l, 3 * l.num_digits() as u64, 9);
        assert_eq!(r.first_violation, None);
        assert_eq!(r.nodes_checked, 3 * l.num_digits() as u64);
    }
}
