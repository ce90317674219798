//! Scramblers in a base that is not a power of two (3, 5, 6, 7, …) as the battery reaches
//! them: through [`RadixWords`], their digits read through [`radix_tree`].

use crate::sampling::Tree;
use gartowen_core::{
    Claim, CoreError, PowerOfTwoBase, Radix, RadixLayout, RadixScrambler, Scrambler, Unscramble,
    Width,
};

/// A base-b scrambler as a map of words, for the battery's shared machinery (evaluation
/// passes, the `function` and `expect` comparisons). The words are base-b digit integers;
/// [`Scrambler::base`] answers base 2 only because the trait needs a power of two: no check
/// of a candidate with [`crate::candidate::Candidate::radix`] set reads it.
pub struct RadixWords(pub Box<dyn RadixScrambler>);

impl Scrambler for RadixWords {
    fn name(&self) -> String {
        self.0.name()
    }
    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B2
    }
    fn claim(&self) -> Claim {
        self.0.claim()
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.0.scramble(x, width, dim)
    }
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        self.0.scramble_batch(words, width, dim)
    }
    fn supports_width(&self, width: Width) -> bool {
        RadixLayout::new(width, self.0.radix()).is_ok() && self.0.supports_width(width)
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        self.0
            .unscramble(0, Width::W32, 0)
            .is_some()
            .then_some(self as &dyn Unscramble)
    }
}

impl Unscramble for RadixWords {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        self.0
            .unscramble(y, width, dim)
            .expect("inverse() offers it only when present")
    }
}

/// The tree of `width`-bit words in base `radix`.
pub fn radix_tree(radix: Radix, width: Width) -> Result<Tree, CoreError> {
    Ok(Tree::radix(RadixLayout::new(width, radix)?))
}
