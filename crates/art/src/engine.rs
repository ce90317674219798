//! The ART-Owen loop (`DESIGN.md` §3.3), for any variant:
//!
//! ```text
//! F = 0
//! for k in 0..digits:
//!     F ^= T[s_k] >> (q·k)        // field 0 of T lands on digit k
//!     y_k = ψ_{s_k}(x_k) ⊕ F_k
//!     s_{k+1} = child(s_k, x_k)    // navigate by the ORIGINAL digit
//! ```
//!
//! Tail rule: when q does not divide W, the last digit has r < q bits; it gets the translation
//! F_k only (ψ acts on q-bit digits), which keeps the map a bijection. Inversion recovers
//! x_k = ψ^{-1}(y_k ⊕ F_k) before navigating.

use crate::{ArtVariant, Grammar};
use gartowen_core::{
    derive_seed, hash_words, DigitLayout, Permutation, PowerOfTwoBase, Scrambler, SplitMix64, Width,
};

/// Tag for the table stream (`derive_seed(seed, TABLE_TAG)`).
const TABLE_TAG: u64 = 0x7461_626c_65; // "table"
/// Tag for root selection (`hash_words([seed, dim, ROOT_TAG])`).
const ROOT_TAG: u64 = 0x726f_6f74; // "root"

/// An ART-Owen scrambler: grammar, per-symbol ψ and codes, and the seed that chose them.
#[derive(Debug, Clone)]
pub struct ArtOwen {
    variant: ArtVariant,
    seed: u64,
    grammar: std::sync::Arc<Grammar>,
    /// Top-aligned translation code per symbol.
    codes: Vec<u64>,
    /// ψ images per symbol (s·b + d), empty for identity.
    psi: Vec<u8>,
    /// ψ^{-1} images per symbol.
    psi_inv: Vec<u8>,
}

impl ArtOwen {
    /// The scrambler of `variant` with an alphabet of `symbols` Thue–Morse factors, tables drawn
    /// deterministically from `seed`.
    pub fn new(
        variant: ArtVariant,
        symbols: usize,
        seed: u64,
    ) -> Result<Self, crate::grammar::GrammarError> {
        let len = crate::grammar::length_for_size(symbols)?;
        let grammar = Grammar::shared(len, variant.q())?;
        let mut rng = SplitMix64::new(derive_seed(seed, TABLE_TAG));
        let b = 1usize << variant.q();
        let mut codes = Vec::with_capacity(symbols);
        let (mut psi, mut psi_inv) = (Vec::new(), Vec::new());
        for _ in 0..grammar.symbols() {
            let (p, code) = variant.draw_symbol(&mut rng);
            codes.push(code);
            if let Some(p) = p {
                psi.extend_from_slice(p.as_slice());
                let inv = p.inverse();
                psi_inv.extend_from_slice(&inv.as_slice()[..b]);
            }
        }
        Ok(ArtOwen {
            variant,
            seed,
            grammar,
            codes,
            psi,
            psi_inv,
        })
    }

    /// The variant.
    pub fn variant(&self) -> ArtVariant {
        self.variant
    }

    /// The grammar.
    pub fn grammar(&self) -> &Grammar {
        &self.grammar
    }

    /// The root symbol of dimension `dim`: hash of (seed, dim) reduced without bias.
    pub fn root(&self, dim: u32) -> u32 {
        SplitMix64::new(hash_words(&[self.seed, dim as u64, ROOT_TAG]))
            .bounded(self.grammar.symbols())
    }

    #[inline(always)]
    fn q(&self) -> u32 {
        self.variant.q()
    }

    #[inline(always)]
    fn psi_apply(&self, s: u32, d: u32) -> u32 {
        if self.psi.is_empty() {
            d
        } else {
            self.psi[((s as usize) << self.q()) | d as usize] as u32
        }
    }

    #[inline(always)]
    fn psi_invert(&self, s: u32, d: u32) -> u32 {
        if self.psi_inv.is_empty() {
            d
        } else {
            self.psi_inv[((s as usize) << self.q()) | d as usize] as u32
        }
    }

    #[inline]
    fn run(&self, x: u64, width: Width, dim: u32, inverse: bool) -> u64 {
        self.run_from(x, width, self.root(dim), inverse)
    }

    /// The scramble (or its inverse) starting from root symbol `root` instead of the hashed
    /// root of a dimension: lets tests cover every root symbol of a table.
    pub fn scramble_from_root(&self, x: u64, width: Width, root: u32, inverse: bool) -> u64 {
        assert!(root < self.grammar.symbols(), "root symbol out of range");
        self.run_from(x, width, root, inverse)
    }

    #[inline]
    fn run_from(&self, x: u64, width: Width, root: u32, inverse: bool) -> u64 {
        let q = self.q();
        let layout = DigitLayout::new(width, PowerOfTwoBase::from_q(q).expect("q ≤ 8"));
        let top = 64 - width.bits();
        let mut s = root;
        let mut f = 0u64;
        let mut out = 0u64;
        let digits = layout.num_digits();
        for k in 0..digits {
            f ^= self.codes[s as usize] >> (q * k);
            let fk = layout.get(f >> top, k);
            let d_in = layout.get(x, k);
            let full = layout.digit_bits(k) == q;
            let (original, mapped) = if inverse {
                let t = d_in ^ fk;
                let o = if full { self.psi_invert(s, t) } else { t };
                (o, o)
            } else {
                (
                    d_in,
                    (if full { self.psi_apply(s, d_in) } else { d_in }) ^ fk,
                )
            };
            out = layout.set(out, k, mapped);
            if k + 1 < digits {
                s = self.grammar.child(s, original);
            }
        }
        out
    }

    /// The permutation this scrambler applies at node (depth k, original prefix p) of `dim`:
    /// d ↦ ψ_{s_k}(d) ⊕ F_k, with s_k and F_k accumulated along the prefix (the explicit-tree
    /// bridge). The tail digit's node is d ↦ d ⊕ F_k on 2^r symbols.
    pub fn node_permutation(&self, width: Width, dim: u32, depth: u32, prefix: u64) -> Permutation {
        let q = self.q();
        let layout = DigitLayout::new(width, PowerOfTwoBase::from_q(q).expect("q ≤ 8"));
        let top = 64 - width.bits();
        let mut s = self.root(dim);
        let mut f = 0u64;
        for k in 0..=depth {
            f ^= self.codes[s as usize] >> (q * k);
            if k < depth {
                // Digit k of the prefix (prefix holds digits 0..depth, most significant first).
                let shift: u32 = (k + 1..depth).map(|j| layout.digit_bits(j)).sum();
                let d = ((prefix >> shift) & ((1u64 << layout.digit_bits(k)) - 1)) as u32;
                s = self.grammar.child(s, d);
            }
        }
        let fk = layout.get(f >> top, depth);
        let bits = layout.digit_bits(depth);
        let images: Vec<u8> = (0..1u32 << bits)
            .map(|d| ((if bits == q { self.psi_apply(s, d) } else { d }) ^ fk) as u8)
            .collect();
        Permutation::from_images(&images).expect("ψ ⊕ F is a bijection")
    }
}

impl Scrambler for ArtOwen {
    fn name(&self) -> String {
        format!("{}:table={}", self.variant.name(), self.grammar.symbols())
    }

    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::from_q(self.q()).expect("q ≤ 8")
    }

    fn claims_nested_uniform(&self) -> bool {
        self.variant.claims_nested_uniform()
    }

    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.run(x, width, dim, false)
    }

    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        self.run(y, width, dim, true)
    }

    fn table_bytes(&self) -> usize {
        self.grammar.table_bytes() + self.codes.len() * 8 + self.psi.len() + self.psi_inv.len()
    }
}
