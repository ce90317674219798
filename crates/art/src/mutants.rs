//! Deliberate defects of ART-Owen (the `mutants` feature), for tests that show the verify
//! battery and the differential tests catch broken implementations. Each table defect is an
//! edit of the tables a real scrambler is built from, so the production type and its loops
//! carry no test branch; the tail defect wraps a real scrambler.

use crate::dims::{root_symbol, DimKey};
use crate::engine::{ArtOwen, ArtTables};
use crate::grammar::GrammarError;
use crate::ArtVariant;
use gartowen_core::Unscramble;
use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, Width};

/// A defect of the tables.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ArtMutant {
    /// No defect: the real scrambler.
    #[default]
    None,
    /// The grammar never descends: child(s, d) = s, so every node at a depth has the root's
    /// symbol and (for ψ = identity) the same permutation.
    NeverDescends,
    /// One code for every symbol: the translation depends on the depth only.
    OneCodePerDepth,
    /// Every dimension starts at one root with no dimension shifts: all dimensions coincide.
    OneRoot,
    /// The top bit of every code (field 0's most significant bit) stuck at 0.
    StuckCodeBit,
    /// The design before dimension shifts: hashed roots only, so dimensions can coincide.
    RootOnlyDimensions,
}

impl ArtMutant {
    /// Every table defect, [`ArtMutant::None`] first.
    pub const ALL: [ArtMutant; 6] = [
        ArtMutant::None,
        ArtMutant::NeverDescends,
        ArtMutant::OneCodePerDepth,
        ArtMutant::OneRoot,
        ArtMutant::StuckCodeBit,
        ArtMutant::RootOnlyDimensions,
    ];
}

impl ArtOwen {
    /// The scrambler of [`ArtOwen::new`] with the defect `mutant` edited into its tables.
    pub fn with_mutant(
        variant: ArtVariant,
        symbols: usize,
        seed: u64,
        mutant: ArtMutant,
    ) -> Result<ArtOwen, GrammarError> {
        let mut tables = ArtTables::draw(variant, symbols, seed)?;
        match mutant {
            ArtMutant::None => {}
            ArtMutant::NeverDescends => {
                tables.grammar = std::sync::Arc::new(tables.grammar.never_descending());
            }
            ArtMutant::OneCodePerDepth => {
                let first = tables.codes[0];
                tables.codes.iter_mut().for_each(|c| *c = first);
            }
            ArtMutant::StuckCodeBit => tables.codes.iter_mut().for_each(|c| *c &= !(1u64 << 63)),
            ArtMutant::OneRoot => tables.dimension_rule = |_, _, _| DimKey::default(),
            ArtMutant::RootOnlyDimensions => {
                tables.dimension_rule = |seed, dim, symbols| DimKey {
                    root: root_symbol(seed, dim, symbols),
                    ..DimKey::default()
                }
            }
        }
        Ok(ArtOwen::from_tables(variant, seed, tables))
    }
}

/// A real scrambler whose partial tail digit (the last W mod q bits, when q does not divide
/// W) gets no translation: the flipped tail rule the extracted differential test must catch.
/// The digits above are untouched (a nested scramble's tail never reaches them), so
/// the defect is exact on every path.
#[derive(Debug, Clone)]
pub struct TailUntranslated(pub ArtOwen);

impl TailUntranslated {
    /// The mask of the tail digit's bits for `width`-bit words (0 when q divides W).
    fn tail(&self, width: Width) -> u64 {
        let r = width.bits() % self.0.variant().q();
        (1u64 << r) - 1
    }
}

impl Scrambler for TailUntranslated {
    fn name(&self) -> String {
        format!("{}:tail-untranslated", self.0.name())
    }

    fn base(&self) -> PowerOfTwoBase {
        self.0.base()
    }

    fn claim(&self) -> Claim {
        self.0.claim()
    }

    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        let tail = self.tail(width);
        (self.0.scramble(x, width, dim) & !tail) | (x & tail)
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for TailUntranslated {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        let tail = self.tail(width);
        (self.0.unscramble(y, width, dim) & !tail) | (y & tail)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dims::dimension_key;

    #[test]
    fn the_dimension_mutants_really_drop_the_shifts() {
        let art = ArtOwen::new(ArtVariant::ArtOwen2, 44, 9).unwrap();
        let old = ArtOwen::with_mutant(ArtVariant::ArtOwen2, 44, 9, ArtMutant::RootOnlyDimensions)
            .unwrap();
        assert_eq!(old.root(300), art.root(300));
        assert_eq!(old.dimension_shifts(300, Width::W64), (0, 0));
        assert_eq!(old.dimension_shifts(3, Width::W64), (0, 0));
        let (a, d) = art.dimension_shifts(300, Width::W64);
        let key = dimension_key(9, 300, 44);
        assert_eq!(art.root(300), key.root);
        assert!(a != 0 && d != 0, "the real scrambler shifts dimension 300");
        let one = ArtOwen::with_mutant(ArtVariant::ArtOwen2, 44, 9, ArtMutant::OneRoot).unwrap();
        assert_eq!(one.root(5), 0);
        assert_eq!(one.root(300), 0);
    }

    #[test]
    fn table_mutants_edit_only_their_table() {
        let v = ArtVariant::ArtOwen16P;
        let art = ArtOwen::new(v, 256, 3).unwrap();
        let stuck = ArtOwen::with_mutant(v, 256, 3, ArtMutant::StuckCodeBit).unwrap();
        assert!(stuck.codes().iter().all(|c| c >> 63 == 0));
        assert!(art.codes().iter().any(|c| c >> 63 == 1));
        let one = ArtOwen::with_mutant(v, 256, 3, ArtMutant::OneCodePerDepth).unwrap();
        assert!(one.codes().iter().all(|&c| c == art.codes()[0]));
        let flat = ArtOwen::with_mutant(v, 256, 3, ArtMutant::NeverDescends).unwrap();
        assert!((0..256).all(|s| (0..16).all(|d| flat.grammar().child(s, d) == s)));
        let none = ArtOwen::with_mutant(v, 256, 3, ArtMutant::None).unwrap();
        assert_eq!(
            none.scramble(0x1234_5678, Width::W32, 7),
            art.scramble(0x1234_5678, Width::W32, 7)
        );
    }

    #[test]
    fn the_tail_mutant_keeps_the_input_tail_and_everything_above() {
        // q = 3 on 32-bit words: a 2-bit tail digit.
        let art = ArtOwen::new(ArtVariant::Translation(3), 256, 5).unwrap();
        let bad = TailUntranslated(art.clone());
        let w = Width::W32;
        let mut differs = 0;
        for x in (0..4000u64).map(|i| i.wrapping_mul(0x9E37_79B9) & w.mask()) {
            let (y, z) = (art.scramble(x, w, 1), bad.scramble(x, w, 1));
            assert_eq!(y >> 2, z >> 2);
            assert_eq!(z & 3, x & 3);
            assert_eq!(bad.unscramble(z, w, 1), x);
            differs += usize::from(y != z);
        }
        assert!(differs > 2000, "the real tail is translated: {differs}");
        // q = 4 divides 32: no tail, no defect.
        let even = ArtOwen::new(ArtVariant::ArtOwen16P, 256, 5).unwrap();
        assert_eq!(
            TailUntranslated(even.clone()).scramble(77, w, 0),
            even.scramble(77, w, 0)
        );
    }
}
