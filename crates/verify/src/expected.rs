//! The exact laws the families test against: a uniform element of a node group acting on two
//! digits, and the uniform law.

use crate::sampling::{fold, folded_size};
use gartowen_core::NodeGroup;

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
