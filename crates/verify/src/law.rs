//! What every law test reports, and the settings they share.

use crate::sampling::{fold, folded_size, Tree};
use gartowen_core::{Claim, NodeGroup};
use serde::{Deserialize, Serialize};

/// The part of a claim a sub-test judges: it gets a verdict only when the implementation
/// claims it, and is measured otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Requirement {
    /// A law for each node permutation on its own (or for distinct dimensions).
    Marginal,
    /// Independence of distinct nodes, depths and dimensions.
    Independent,
}

impl Requirement {
    /// Whether `claim` promises what this requirement tests.
    pub fn claimed_by(self, claim: Claim) -> bool {
        match self {
            Requirement::Marginal => claim.marginal.is_some(),
            Requirement::Independent => claim.marginal.is_some() && claim.independent,
        }
    }
}

/// One statistical (or exact) test inside a check family.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SubTest {
    /// What was tested, e.g. `siblings at depth 3 (0x5.3.1 | 0x5.3.7)`.
    pub name: String,
    /// The tree depth it concerns (for the per-depth profile), if any.
    pub depth: Option<u32>,
    /// What claim it judges.
    pub requires: Requirement,
    /// The statistic (χ², collision count, rank deficiency, violations).
    pub statistic: f64,
    /// The p-value under the claimed law (an upper bound for exact tests).
    pub p_value: f64,
    /// Observations (seeds, nodes or pairs).
    pub n: u64,
    /// χ² degrees of freedom, when the test is a χ² test (its power is then stated as the
    /// smallest Cohen's w detected at power 0.9).
    pub dof: Option<usize>,
    /// What an exact test detects, in words (for χ² tests this is filled in by the battery).
    pub power: String,
    /// Whether p fell below the per-test level (filled in by the battery).
    #[serde(default)]
    pub deviates: bool,
}

impl SubTest {
    /// A χ² sub-test.
    pub fn chi(
        name: String,
        depth: Option<u32>,
        requires: Requirement,
        c: crate::stats::ChiSquare,
    ) -> SubTest {
        SubTest {
            name,
            depth,
            requires,
            statistic: c.statistic,
            p_value: c.p_value,
            n: c.n,
            dof: Some(c.dof),
            power: String::new(),
            deviates: false,
        }
    }
}

/// Settings shared by the law families.
#[derive(Debug, Clone, Copy)]
pub struct LawConfig {
    /// Layout of the words the battery sends.
    pub tree: Tree,
    /// The claim being judged (or, when nothing is claimed, the law measured against: Owen).
    pub claim: Claim,
    /// Independent seeds for the per-seed laws.
    pub seeds: u64,
    /// Deepest tree depth tested.
    pub max_depth: u32,
    /// Level multiplier: 1 at quick, larger at full and exhaustive.
    pub scale: u64,
}

impl LawConfig {
    /// The group node permutations are tested against: the claimed one, else S_b.
    pub fn group(&self) -> NodeGroup {
        self.claim.marginal.unwrap_or(NodeGroup::Symmetric)
    }

    /// Depths 0..=max_depth that have a full digit.
    pub fn depths(&self) -> std::ops::RangeInclusive<u32> {
        0..=self
            .max_depth
            .min(self.tree.full_digits().saturating_sub(1))
    }
}

/// The probability that a uniform element π of `group` (base b) maps digit x to a and digit y
/// to c, summed over the folded cells: a table `[fold(a) * F + fold(c)]` with F folded values.
pub fn pair_image_law(group: NodeGroup, b: u32, x: u32, y: u32) -> Vec<f64> {
    let f = folded_size(b);
    let mut law = vec![0.0; (f * f) as usize];
    for a in 0..b {
        for c in 0..b {
            let p = if x == y {
                if a == c {
                    1.0 / b as f64
                } else {
                    0.0
                }
            } else {
                match group {
                    // Both are 2-transitive: (π(x), π(y)) is uniform over distinct pairs.
                    NodeGroup::Symmetric | NodeGroup::Affine => {
                        if a != c {
                            1.0 / (b as f64 * (b - 1) as f64)
                        } else {
                            0.0
                        }
                    }
                    NodeGroup::Translation => {
                        if c == a ^ x ^ y {
                            1.0 / b as f64
                        } else {
                            0.0
                        }
                    }
                    NodeGroup::Cyclic => {
                        if c == (a + y + b - x) % b {
                            1.0 / b as f64
                        } else {
                            0.0
                        }
                    }
                }
            };
            law[(fold(a, b) * f + fold(c, b)) as usize] += p;
        }
    }
    law
}

/// The uniform law on `cells` cells.
pub fn uniform(cells: usize) -> Vec<f64> {
    vec![1.0 / cells as f64; cells]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pair_laws_sum_to_one_and_respect_the_group() {
        for b in [2u32, 4, 8, 32] {
            for g in NodeGroup::ALL {
                for (x, y) in [(0, 1), (1, 3 % b), (2 % b, 2 % b)] {
                    let law = pair_image_law(g, b, x, y);
                    assert!((law.iter().sum::<f64>() - 1.0).abs() < 1e-12);
                }
            }
        }
        // Translations in base 4 map 0 and 1 to (a, a ⊕ 1) only.
        let law = pair_image_law(NodeGroup::Translation, 4, 0, 1);
        assert_eq!(law[1], 0.25);
        assert_eq!(law[2], 0.0);
    }
}
