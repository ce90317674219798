//! The nested-scramble inspector: decides from black-box evaluations whether a map of W-bit
//! words is a nested scramble in base 2^q, and reconstructs its node permutations.
//!
//! A map f is a nested scramble when, for every depth k, output digit k is a function of input
//! digits 0..=k only (nested), and for every node (k, p) the map d ↦ digit k of f(p, d, …) is a
//! bijection of the digit alphabet (bijective). Depths are checked in order, so the first
//! violation reported is the shallowest.
//!
//! * Exhaustive mode (W ≤ 16) evaluates every word.
//! * Probe mode samples nodes with a seeded generator: for node (k, p) it evaluates all b digits
//!   d at depth k, each with two independent random tails, and checks the digits above k agree
//!   with the node's prefix image, digit k agrees between tails, and the b images are distinct.

use gartowen_core::{DigitLayout, Permutation, PowerOfTwoBase, SplitMix64, Width};
use serde::Serialize;

/// What went wrong at a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ViolationKind {
    /// Output digit k changed although input digits 0..=k were equal.
    NotNested,
    /// Two different digits at the node map to the same output digit.
    NotBijective,
    /// An output word has bits above the width.
    OutOfRange,
}

/// The first violation: the node, two inputs and their outputs.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Violation {
    /// The kind of violation.
    pub kind: ViolationKind,
    /// Depth k of the node.
    pub depth: u32,
    /// Its prefix p: the first k input digits as an integer.
    pub prefix: u64,
    /// Two inputs that witness it.
    pub inputs: [u64; 2],
    /// Their outputs.
    pub outputs: [u64; 2],
}

/// How the inspection sampled the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum InspectMode {
    /// Every word evaluated.
    Exhaustive,
    /// `nodes` random nodes from `seed`.
    Probes {
        /// Nodes probed.
        nodes: u64,
        /// Seed choosing them.
        seed: u64,
    },
}

/// The empirical law of reconstructed node permutations against the uniform law on S_b.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NodeLaw {
    /// `"S_b ranks"` (b ≤ 4: each permutation is a cell) or `"(pi(0), pi(1))"` (larger b).
    pub cells_are: String,
    /// Count per cell.
    pub counts: Vec<u64>,
    /// Permutations tallied.
    pub total: u64,
    /// Pearson chi-square statistic against equal cell probabilities.
    pub chi_square: f64,
    /// Degrees of freedom (cells − 1).
    pub dof: u64,
    /// Total variation distance between the empirical and the uniform cell law.
    pub total_variation: f64,
}

impl NodeLaw {
    fn new(base: u32) -> Self {
        let (cells_are, cells) = if base <= 4 {
            ("S_b ranks", (1..=base as usize).product::<usize>())
        } else {
            ("(pi(0), pi(1))", (base * (base - 1)) as usize)
        };
        NodeLaw {
            cells_are: cells_are.into(),
            counts: vec![0; cells],
            total: 0,
            chi_square: 0.0,
            dof: cells as u64 - 1,
            total_variation: 0.0,
        }
    }

    /// The cell of a permutation (full-size nodes only).
    pub fn cell(p: &Permutation) -> usize {
        let b = p.len() as u32;
        if b <= 4 {
            p.rank() as usize
        } else {
            let (a, c) = (p.apply(0), p.apply(1));
            (a * (b - 1) + if c > a { c - 1 } else { c }) as usize
        }
    }

    fn add(&mut self, p: &Permutation) {
        self.counts[Self::cell(p)] += 1;
        self.total += 1;
    }

    fn finish(&mut self) {
        let cells = self.counts.len() as f64;
        let expected = self.total as f64 / cells;
        if self.total == 0 {
            return;
        }
        self.chi_square = self
            .counts
            .iter()
            .map(|&c| (c as f64 - expected).powi(2) / expected)
            .sum();
        self.total_variation = 0.5
            * self
                .counts
                .iter()
                .map(|&c| (c as f64 / self.total as f64 - 1.0 / cells).abs())
                .sum::<f64>();
    }
}

/// The inspector's verdict.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InspectReport {
    /// Word width W.
    pub width: u32,
    /// Base b = 2^q.
    pub base: u32,
    /// Depth K to which node permutations were reconstructed.
    pub depth: u32,
    /// How the map was sampled.
    pub mode: InspectMode,
    /// Evaluations of the map.
    pub evaluations: u64,
    /// Nodes whose permutation was reconstructed.
    pub nodes_checked: u64,
    /// No violation found.
    pub nested_scramble: bool,
    /// The first (shallowest) violation.
    pub first_violation: Option<Violation>,
    /// The law of reconstructed full-size node permutations.
    pub node_law: NodeLaw,
}

/// Inspects `f` on every `width`-bit word (W ≤ 16), reconstructing nodes to depth `depth`.
pub fn inspect_exhaustive(
    f: &dyn Fn(u64) -> u64,
    width: Width,
    base: PowerOfTwoBase,
    depth: u32,
) -> InspectReport {
    assert!(
        width.bits() <= 16,
        "exhaustive inspection is for widths ≤ 16"
    );
    let layout = DigitLayout::new(width, base);
    let digits = layout.num_digits();
    let depth = depth.min(digits);
    let ys: Vec<u64> = width.all_words().map(f).collect();
    let mut law = NodeLaw::new(base.base());
    let report = |violation: Option<Violation>, nodes: u64, law: NodeLaw| InspectReport {
        width: width.bits(),
        base: base.base(),
        depth,
        mode: InspectMode::Exhaustive,
        evaluations: ys.len() as u64,
        nodes_checked: nodes,
        nested_scramble: violation.is_none(),
        first_violation: violation,
        node_law: law,
    };
    if let Some((x, &y)) = ys
        .iter()
        .enumerate()
        .find(|(_, &y)| width.check(y).is_err())
    {
        let v = Violation {
            kind: ViolationKind::OutOfRange,
            depth: 0,
            prefix: 0,
            inputs: [x as u64, x as u64],
            outputs: [y, y],
        };
        return report(Some(v), 0, law);
    }
    let mut nodes = 0u64;
    for k in 0..digits {
        let bits = layout.digit_bits(k);
        let child_count = 1usize << bits;
        // For each input prefix of k+1 digits: the first input seen and its output digit k.
        let mut first: Vec<Option<(u64, u32)>> =
            vec![None; 1usize << (layout.prefix(width.mask(), k + 1).count_ones())];
        for (x, &y) in ys.iter().enumerate() {
            let x = x as u64;
            let key = layout.prefix(x, k + 1) as usize;
            let out = layout.get(y, k);
            match first[key] {
                None => first[key] = Some((x, out)),
                Some((x0, o0)) if o0 != out => {
                    let v = Violation {
                        kind: ViolationKind::NotNested,
                        depth: k,
                        prefix: layout.prefix(x, k),
                        inputs: [x0, x],
                        outputs: [ys[x0 as usize], y],
                    };
                    return report(Some(v), nodes, law);
                }
                _ => {}
            }
        }
        // Each node's digit map must be a bijection.
        for p in 0..(first.len() / child_count) {
            let mut images = vec![0u8; child_count];
            let mut hit: Vec<Option<u64>> = vec![None; child_count];
            for d in 0..child_count {
                let (x, out) = first[p * child_count + d].expect("every prefix occurs");
                if let Some(x_other) = hit[out as usize] {
                    let v = Violation {
                        kind: ViolationKind::NotBijective,
                        depth: k,
                        prefix: p as u64,
                        inputs: [x_other, x],
                        outputs: [ys[x_other as usize], ys[x as usize]],
                    };
                    return report(Some(v), nodes, law);
                }
                hit[out as usize] = Some(x);
                images[d] = out as u8;
            }
            if k < depth {
                nodes += 1;
                if bits == base.q() {
                    law.add(&Permutation::from_images(&images).expect("checked bijective"));
                }
            }
        }
    }
    law.finish();
    report(None, nodes, law)
}

/// Inspects `f` on `width`-bit words by probing `nodes` random nodes (seeded), at depths below
/// `depth`. Each probe costs 2b evaluations.
pub fn inspect_probes(
    f: &dyn Fn(u64) -> u64,
    width: Width,
    base: PowerOfTwoBase,
    depth: u32,
    nodes: u64,
    seed: u64,
) -> InspectReport {
    let batch = |words: &mut [u64]| {
        for w in words.iter_mut() {
            *w = f(*w);
        }
    };
    inspect_probes_batched(&batch, width, base, depth, nodes, seed)
}

/// Probes evaluated per call of the batch function of [`inspect_probes_batched`] (at most
/// 2·256·256 words per call in base 256).
const PROBES_PER_BATCH: u64 = 256;

/// [`inspect_probes`] with `f` applied to many words per call (`f(words)` scrambles them in
/// place): the same probes, in the same order, with the same report; an external or Python
/// implementation then answers a few large requests instead of 2b·nodes single words.
pub fn inspect_probes_batched(
    f: &dyn Fn(&mut [u64]),
    width: Width,
    base: PowerOfTwoBase,
    depth: u32,
    nodes: u64,
    seed: u64,
) -> InspectReport {
    let layout = DigitLayout::new(width, base);
    let depth = depth.min(layout.num_digits()).max(1);
    let mut rng = SplitMix64::new(seed);
    let mut law = NodeLaw::new(base.base());
    let mut evaluations = 0u64;
    let mut violation = None;
    let mut checked = 0u64;
    let mut first_probe = 0u64;
    'batches: while first_probe < nodes {
        let last_probe = nodes.min(first_probe + PROBES_PER_BATCH);
        // Draw every input of these probes first (f does not touch the generator, so the
        // inputs are those of one-at-a-time evaluation), then evaluate them in one call.
        let mut inputs = Vec::new();
        let mut probes = Vec::new();
        for probe in first_probe..last_probe {
            // Cycle through depths so every level is probed; the prefix is random.
            let k = (probe % depth as u64) as u32;
            let bits = layout.digit_bits(k);
            let base_word = rng.next_u64() & width.mask();
            probes.push((k, bits, layout.prefix(base_word, k), inputs.len()));
            for d in 0..(1u32 << bits) {
                for _tail in 0..2 {
                    let mut x = layout.set(base_word, k, d);
                    for j in k + 1..layout.num_digits() {
                        x = layout.set(x, j, (rng.next_u64() & 0xFF) as u32);
                    }
                    inputs.push(x);
                }
            }
        }
        let mut outputs = inputs.clone();
        f(&mut outputs);
        for &(k, bits, prefix, at) in &probes {
            let mut images = vec![0u8; 1 << bits];
            let mut owner: Vec<Option<(u64, u64)>> = vec![None; 1 << bits];
            let mut above: Option<(u64, u64)> = None; // an (input, output) fixing the digits above k
            for d in 0..(1usize << bits) {
                let mut outs = [0u64; 2];
                let mut ins = [0u64; 2];
                for tail in 0..2 {
                    let (x, y) = (inputs[at + 2 * d + tail], outputs[at + 2 * d + tail]);
                    evaluations += 1;
                    if width.check(y).is_err() {
                        violation = Some(Violation {
                            kind: ViolationKind::OutOfRange,
                            depth: k,
                            prefix,
                            inputs: [x, x],
                            outputs: [y, y],
                        });
                        break 'batches;
                    }
                    // Digits above k must be the same for every input under this prefix.
                    match above {
                        None => above = Some((x, y)),
                        Some((x0, y0)) => {
                            if let Some(j) = (0..k).find(|&j| layout.get(y, j) != layout.get(y0, j))
                            {
                                violation = Some(Violation {
                                    kind: ViolationKind::NotNested,
                                    depth: j,
                                    prefix: layout.prefix(x, j),
                                    inputs: [x0, x],
                                    outputs: [y0, y],
                                });
                                break 'batches;
                            }
                        }
                    }
                    ins[tail] = x;
                    outs[tail] = y;
                }
                let (o0, o1) = (layout.get(outs[0], k), layout.get(outs[1], k));
                if o0 != o1 {
                    violation = Some(Violation {
                        kind: ViolationKind::NotNested,
                        depth: k,
                        prefix,
                        inputs: ins,
                        outputs: outs,
                    });
                    break 'batches;
                }
                if let Some((x_other, y_other)) = owner[o0 as usize] {
                    violation = Some(Violation {
                        kind: ViolationKind::NotBijective,
                        depth: k,
                        prefix,
                        inputs: [x_other, ins[0]],
                        outputs: [y_other, outs[0]],
                    });
                    break 'batches;
                }
                owner[o0 as usize] = Some((ins[0], outs[0]));
                images[d] = o0 as u8;
            }
            checked += 1;
            if bits == base.q() {
                law.add(&Permutation::from_images(&images).expect("checked bijective"));
            }
        }
        first_probe = last_probe;
    }
    law.finish();
    InspectReport {
        width: width.bits(),
        base: base.base(),
        depth,
        mode: InspectMode::Probes { nodes, seed },
        evaluations,
        nodes_checked: checked,
        nested_scramble: violation.is_none(),
        first_violation: violation,
        node_law: law,
    }
}
