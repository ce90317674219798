//! What a scrambler promises about its law, so that the verify battery judges each
//! implementation only on what it claims (and measures the rest).
//!
//! Every scrambler claims to be *nested* (a bijection that maps b-adic intervals of each level
//! onto intervals of the same level). On top of that it may claim:
//! * **marginal** uniformity: every node permutation, on its own, is uniform over a group `G`
//!   of digit permutations ([`NodeGroup`]: all of S_b, the affine group AGL(q,2), the XOR
//!   translations, or the cyclic shifts);
//! * **independence**: the node permutations of distinct nodes (across depths and dimensions)
//!   are independent. Marginal uniformity over S_b plus independence is Owen's nested uniform
//!   scrambling ([`Claim::OWEN`]).

use crate::CoreError;
use std::fmt;

/// A group of permutations of the b = 2^q digits that a node permutation may be uniform over.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NodeGroup {
    /// All of S_b (b! permutations).
    Symmetric,
    /// d ↦ A·d ⊕ u with A ∈ GL(q,2): AGL(q,2), equal to S_b for q ≤ 2.
    Affine,
    /// d ↦ d ⊕ u: the b translations (a nested digital shift node).
    Translation,
    /// d ↦ d + u mod b: the b cyclic shifts.
    Cyclic,
}

impl NodeGroup {
    /// Every group, largest first.
    pub const ALL: [NodeGroup; 4] = [
        NodeGroup::Symmetric,
        NodeGroup::Affine,
        NodeGroup::Translation,
        NodeGroup::Cyclic,
    ];

    /// Lower-case name (`symmetric`, `affine`, `translation`, `cyclic`).
    pub fn name(self) -> &'static str {
        match self {
            NodeGroup::Symmetric => "symmetric",
            NodeGroup::Affine => "affine",
            NodeGroup::Translation => "translation",
            NodeGroup::Cyclic => "cyclic",
        }
    }

    /// The group's usual symbol for base 2^q (`S_16`, `AGL(3,2)`, …).
    pub fn symbol(self, q: u32) -> String {
        let b = 1u32 << q;
        match self {
            NodeGroup::Symmetric => format!("S_{b}"),
            NodeGroup::Affine => format!("AGL({q},2)"),
            NodeGroup::Translation => format!("XOR translations of {b} digits"),
            NodeGroup::Cyclic => format!("Z_{b} shifts"),
        }
    }

    /// log2 of the group's order in base 2^q: log2(b!), log2(b·|GL(q,2)|), or q.
    ///
    /// ```
    /// use gartowen_core::NodeGroup;
    /// assert!((NodeGroup::Symmetric.log2_order(2) - 24f64.log2()).abs() < 1e-12);
    /// assert!((NodeGroup::Affine.log2_order(3) - 1344f64.log2()).abs() < 1e-12);
    /// assert_eq!(NodeGroup::Translation.log2_order(4), 4.0);
    /// ```
    pub fn log2_order(self, q: u32) -> f64 {
        let b = 1u64 << q;
        match self {
            NodeGroup::Symmetric => (2..=b).map(|k| (k as f64).log2()).sum(),
            // |GL(q,2)| = Π_{i<q} (2^q − 2^i).
            NodeGroup::Affine => {
                q as f64
                    + (0..q)
                        .map(|i| ((b - (1u64 << i)) as f64).log2())
                        .sum::<f64>()
            }
            NodeGroup::Translation | NodeGroup::Cyclic => q as f64,
        }
    }

    /// Whether the group is defined in every base b ≥ 2 (S_b and the cyclic shifts Z_b);
    /// the affine group and the XOR translations need b = 2^q.
    pub fn in_every_base(self) -> bool {
        matches!(self, NodeGroup::Symmetric | NodeGroup::Cyclic)
    }

    /// The group's symbol in base `b`: [`NodeGroup::symbol`] for b = 2^q, `S_b` or `Z_b shifts`
    /// otherwise (the groups of [`NodeGroup::in_every_base`]; others are named by their
    /// power-of-two form).
    ///
    /// ```
    /// use gartowen_core::NodeGroup;
    /// assert_eq!(NodeGroup::Symmetric.symbol_in_base(3), "S_3");
    /// assert_eq!(NodeGroup::Affine.symbol_in_base(8), "AGL(3,2)");
    /// ```
    pub fn symbol_in_base(self, b: u32) -> String {
        match self {
            _ if b.is_power_of_two() => self.symbol(b.trailing_zeros()),
            NodeGroup::Cyclic => format!("Z_{b} shifts"),
            _ => format!("S_{b}"),
        }
    }

    /// log2 of the group's order in base `b` ([`NodeGroup::log2_order`] for b = 2^q; log2(b!)
    /// and log2(b) for S_b and Z_b in other bases).
    pub fn log2_order_in_base(self, b: u32) -> f64 {
        match self {
            _ if b.is_power_of_two() => self.log2_order(b.trailing_zeros()),
            NodeGroup::Cyclic => (b as f64).log2(),
            _ => (2..=b).map(|k| (k as f64).log2()).sum(),
        }
    }

    /// Whether the permutation with `images` (`images[d]` = π(d), all b of them) is in the group.
    ///
    /// ```
    /// use gartowen_core::NodeGroup;
    /// assert!(NodeGroup::Translation.contains(&[2, 3, 0, 1]));
    /// assert!(!NodeGroup::Translation.contains(&[1, 2, 3, 0]));
    /// assert!(NodeGroup::Cyclic.contains(&[1, 2, 3, 0]));
    /// assert!(NodeGroup::Affine.contains(&[1, 2, 3, 0])); // S_4 = AGL(2,2)
    /// ```
    pub fn contains(self, images: &[u32]) -> bool {
        let b = images.len() as u32;
        if b == 0 || !(b.is_power_of_two() || self.in_every_base()) {
            return false;
        }
        let mut seen = vec![false; b as usize];
        for &y in images {
            if y >= b || std::mem::replace(&mut seen[y as usize], true) {
                return false;
            }
        }
        let t = images[0];
        match self {
            NodeGroup::Symmetric => true,
            NodeGroup::Translation => (0..b).all(|d| images[d as usize] == d ^ t),
            NodeGroup::Cyclic => (0..b).all(|d| images[d as usize] == (d + t) % b),
            // π ⊕ π(0) must be linear: additive on every pair.
            NodeGroup::Affine => (0..b).all(|x| {
                (0..b).all(|y| {
                    images[(x ^ y) as usize] ^ t
                        == (images[x as usize] ^ t) ^ (images[y as usize] ^ t)
                })
            }),
        }
    }

    /// Parses a group name as written by [`NodeGroup::name`].
    pub fn parse(text: &str) -> Option<NodeGroup> {
        NodeGroup::ALL.into_iter().find(|g| g.name() == text)
    }
}

/// What a scrambler promises beyond nestedness (always claimed).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Claim {
    /// Each node permutation is marginally uniform over this group (None: no law claimed).
    pub marginal: Option<NodeGroup>,
    /// Node permutations of distinct nodes, depths and dimensions are independent.
    pub independent: bool,
}

impl Claim {
    /// Nested only: a bijection that respects the b-adic tree, with no law claimed.
    pub const NESTED: Claim = Claim {
        marginal: None,
        independent: false,
    };
    /// Owen's nested uniform scrambling: independent node permutations uniform over S_b.
    pub const OWEN: Claim = Claim {
        marginal: Some(NodeGroup::Symmetric),
        independent: true,
    };

    /// Marginally uniform over `group`, with no independence claimed (the ART family).
    pub const fn marginal(group: NodeGroup) -> Claim {
        Claim {
            marginal: Some(group),
            independent: false,
        }
    }

    /// Independent node permutations, each uniform over `group` (the oracle's variants).
    pub const fn independent_over(group: NodeGroup) -> Claim {
        Claim {
            marginal: Some(group),
            independent: true,
        }
    }

    /// This claim, if it can be judged in base `b`: its group must exist there (S_b and Z_b
    /// in every base, the affine group and translations in bases 2^q only).
    ///
    /// ```
    /// use gartowen_core::{Claim, NodeGroup};
    /// assert!(Claim::OWEN.in_base(3).is_ok());
    /// assert!(Claim::marginal(NodeGroup::Affine).in_base(3).is_err());
    /// assert!(Claim::marginal(NodeGroup::Affine).in_base(8).is_ok());
    /// ```
    pub fn in_base(self, b: u32) -> Result<Claim, CoreError> {
        match self.marginal {
            Some(g) if !b.is_power_of_two() && !g.in_every_base() => {
                Err(CoreError::ClaimNeedsPowerOfTwo {
                    claim: self.to_string(),
                    base: b,
                })
            }
            _ => Ok(self),
        }
    }

    /// Whether this is exactly Owen's claim (independent and uniform over S_b).
    pub fn is_owen(&self) -> bool {
        *self == Claim::OWEN
    }

    /// Parses `nested`, `marginal[:GROUP]`, `owen` or `independent:GROUP` (GROUP one of
    /// symmetric, affine, translation, cyclic; `marginal` alone means symmetric).
    /// `per-depth[:GROUP]` (one permutation per dimension and depth, shared by every node of
    /// that depth: scrambled Halton) promises exactly the marginal law, so it is
    /// `marginal[:GROUP]`: its nodes are uniform, and the joint laws are measured, not judged.
    ///
    /// ```
    /// use gartowen_core::{Claim, NodeGroup};
    /// assert_eq!(Claim::parse("owen").unwrap(), Claim::OWEN);
    /// assert_eq!(Claim::parse("marginal:affine").unwrap(), Claim::marginal(NodeGroup::Affine));
    /// assert_eq!(Claim::parse("per-depth").unwrap(), Claim::marginal(NodeGroup::Symmetric));
    /// assert_eq!(Claim::parse("per-depth:cyclic").unwrap(), Claim::marginal(NodeGroup::Cyclic));
    /// assert!(Claim::parse("uniformish").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Claim, CoreError> {
        Claim::parse_exact(text).ok_or_else(|| CoreError::InvalidClaim {
            text: text.into(),
            lower_case: Claim::parse_exact(&text.to_lowercase()).map(|c| c.to_string()),
        })
    }

    fn parse_exact(text: &str) -> Option<Claim> {
        let (head, group) = match text.split_once(':') {
            Some((h, g)) => (h, Some(NodeGroup::parse(g)?)),
            None => (text, None),
        };
        match (head, group) {
            ("nested", None) => Some(Claim::NESTED),
            ("owen", None) => Some(Claim::OWEN),
            ("marginal" | "per-depth", g) => {
                Some(Claim::marginal(g.unwrap_or(NodeGroup::Symmetric)))
            }
            ("independent", Some(g)) => Some(Claim::independent_over(g)),
            _ => None,
        }
    }
}

impl std::str::FromStr for Claim {
    type Err = CoreError;
    /// [`Claim::parse`], for `"owen".parse::<Claim>()` (the CLI's and Python's vocabulary).
    fn from_str(text: &str) -> Result<Claim, CoreError> {
        Claim::parse(text)
    }
}

impl fmt::Display for Claim {
    /// The form [`Claim::parse`] reads back.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.marginal, self.independent) {
            (None, _) => write!(f, "nested"),
            (Some(NodeGroup::Symmetric), true) => write!(f, "owen"),
            (Some(g), true) => write!(f, "independent:{}", g.name()),
            (Some(g), false) => write!(f, "marginal:{}", g.name()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bad_claim_is_named_and_a_wrongly_cased_one_gets_its_spelling() {
        let e = Claim::parse("Owen").unwrap_err();
        assert_eq!(
            e,
            CoreError::InvalidClaim {
                text: "Owen".into(),
                lower_case: Some("owen".into())
            }
        );
        assert_eq!(
            e.to_string(),
            "unknown claim 'Owen'; claims are lower case: 'owen'"
        );
        assert_eq!(
            Claim::parse("Marginal:Affine").unwrap_err().to_string(),
            "unknown claim 'Marginal:Affine'; claims are lower case: 'marginal:affine'"
        );
        let e = Claim::parse("uniformish").unwrap_err().to_string();
        assert!(
            e.starts_with("unknown claim 'uniformish'; use nested, owen"),
            "{e}"
        );
        assert!(
            Claim::parse("independent").is_err(),
            "independent needs a group"
        );
        assert!(Claim::parse("marginal:bogus").is_err());
        assert_eq!(
            "independent:cyclic".parse::<Claim>(),
            Claim::parse("independent:cyclic")
        );
    }

    #[test]
    fn symbols_name_the_group_in_its_base() {
        assert_eq!(NodeGroup::Symmetric.symbol(4), "S_16");
        assert_eq!(NodeGroup::Affine.symbol(3), "AGL(3,2)");
        assert_eq!(
            NodeGroup::Translation.symbol(2),
            "XOR translations of 4 digits"
        );
        assert_eq!(NodeGroup::Cyclic.symbol(1), "Z_2 shifts");
    }

    #[test]
    fn only_owen_is_owen_and_s_b_and_z_b_exist_in_every_base() {
        assert!(Claim::OWEN.is_owen());
        assert!(!Claim::NESTED.is_owen());
        assert!(!Claim::marginal(NodeGroup::Symmetric).is_owen());
        assert!(!Claim::independent_over(NodeGroup::Affine).is_owen());
        // S_b and Z_b exist in every base; translations and affine maps need b = 2^q.
        assert!(NodeGroup::Symmetric.contains(&[2, 0, 1]));
        assert!(NodeGroup::Cyclic.contains(&[2, 0, 1]));
        assert!(!NodeGroup::Cyclic.contains(&[0, 2, 1]));
        assert!(!NodeGroup::Translation.contains(&[0, 1, 2]));
        assert!(!NodeGroup::Affine.contains(&[0, 1, 2]));
        assert!(!NodeGroup::Symmetric.contains(&[0, 1, 1]));
        assert!(!NodeGroup::Symmetric.contains(&[0, 1, 3]));
        assert_eq!(NodeGroup::Cyclic.symbol_in_base(5), "Z_5 shifts");
        assert_eq!(NodeGroup::Symmetric.symbol_in_base(16), "S_16");
        assert!((NodeGroup::Symmetric.log2_order_in_base(3) - 6f64.log2()).abs() < 1e-12);
        assert!((NodeGroup::Cyclic.log2_order_in_base(5) - 5f64.log2()).abs() < 1e-12);
        assert_eq!(
            NodeGroup::Affine.log2_order_in_base(16),
            NodeGroup::Affine.log2_order(4)
        );
        assert!(!NodeGroup::Symmetric.contains(&[]));
    }

    #[test]
    fn display_round_trips_through_parse() {
        for g in NodeGroup::ALL {
            for c in [Claim::marginal(g), Claim::independent_over(g)] {
                assert_eq!(Claim::parse(&c.to_string()).unwrap(), c);
            }
        }
        assert_eq!(Claim::parse("nested").unwrap().to_string(), "nested");
    }

    #[test]
    fn group_membership_counts_match_group_orders() {
        // Every map of 4 digits: the members of each group are exactly its order.
        let mut count = [0usize; 4];
        let items = [0u32, 1, 2, 3];
        for a in items {
            for b in items {
                for c in items {
                    for d in items {
                        let p = [a, b, c, d];
                        for (i, g) in NodeGroup::ALL.into_iter().enumerate() {
                            count[i] += g.contains(&p) as usize;
                        }
                    }
                }
            }
        }
        assert_eq!(count, [24, 24, 4, 4]);
        // In base 8, AGL(3,2) has 1344 elements: count over all 8! permutations is costly, so
        // check the order formula against the product instead.
        assert_eq!(NodeGroup::Affine.log2_order(3).exp2().round() as u64, 1344);
        assert_eq!(
            NodeGroup::Symmetric.log2_order(3).exp2().round() as u64,
            40320
        );
    }

    #[test]
    fn affine_membership_rejects_a_non_affine_permutation_of_eight() {
        let identity: Vec<u32> = (0..8).collect();
        assert!(NodeGroup::Affine.contains(&identity));
        // Swapping bits 0 and 1 of every digit is linear.
        let swapped: Vec<u32> = (0..8u32)
            .map(|d| (d & 4) | ((d & 1) << 1) | ((d >> 1) & 1))
            .collect();
        assert!(NodeGroup::Affine.contains(&swapped));
        let mut lone_swap = identity.clone();
        lone_swap.swap(1, 2); // only two images swapped: 1 ⊕ 4 = 5 would have to map to 6
        assert!(!NodeGroup::Affine.contains(&lone_swap));
        let mut broken = identity;
        broken.swap(3, 4); // 3 = e0 ⊕ e1 now maps to 4: not additive.
        assert!(!NodeGroup::Affine.contains(&broken));
        assert!(!NodeGroup::Symmetric.contains(&[0, 0, 1, 2]));
    }
}
