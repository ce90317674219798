//! Q-ART with the linear part composed along the tree (`q-art-4:compose=linear`).
//!
//! Translation-only Q-ART ([`crate::ArtOwen`] with [`ArtVariant::QArt4`]) gives the node at
//! depth k the map d ↦ ψ_{s_k}(d) ⊕ F_k: the translation F composes down the path, the linear
//! part is the symbol's own. The Q-ART paper also describes composing the linear part, which it
//! reports makes "no noticeable difference"; this is that variant, so the claim can be tested:
//!
//! ```text
//! F = 0; M = I
//! for k in 0..digits:
//!     F ^= T[s_k] >> (q·k)
//!     M  = ψ_{s_k} · M                 // GL(2,2) product along the path
//!     y_k = M·x_k ⊕ F_k
//!     s_{k+1} = child(s_k, x_k)         // navigate by the ORIGINAL digit
//! ```
//!
//! With the same table (the Q-ART record), root, dimension shifts and tail rule as Q-ART, so
//! depth 0 is identical and only deeper nodes differ. Each node map is nested and bijective,
//! and since ψ_{s_k} is uniform in GL(2,2) and F_k uniform, M_k·d ⊕ F_k is uniform over
//! AGL(2,2) = S_4: the same marginal claim as Q-ART. The path state M has 6 values, so the
//! step tables of the engine do not apply; this is the scalar loop over the record.

use crate::dims::dimension_key;
use crate::record::ArtRecord;
use crate::ArtVariant;
use gartowen_core::Unscramble;
use gartowen_core::{Claim, DigitLayout, Gf2Matrix, PowerOfTwoBase, Scrambler, Width};

/// Q-ART with composed linear parts, from the Q-ART record of 64-bit words.
#[derive(Debug, Clone)]
pub struct QArtComposed {
    record: ArtRecord,
    seed: u64,
    /// ψ of every symbol as a matrix, and its inverse.
    matrices: Vec<(Gf2Matrix, Gf2Matrix)>,
}

impl QArtComposed {
    /// The scrambler with `symbols` Thue–Morse factors, the table drawn from `seed` exactly as
    /// Q-ART's.
    pub fn new(symbols: usize, seed: u64) -> Result<Self, crate::grammar::GrammarError> {
        let record = ArtRecord::draw(ArtVariant::QArt4, symbols, seed, Width::W64)?;
        let matrices = (0..record.grammar().symbols())
            .map(|s| {
                let m = record.psi_matrix(s).expect("Q-ART's ψ is linear");
                (m, m.inverse().expect("ψ ∈ GL(2,2)"))
            })
            .collect();
        Ok(QArtComposed {
            record,
            seed,
            matrices,
        })
    }

    fn run(&self, x: u64, width: Width, dim: u32, inverse: bool) -> u64 {
        let q = 2;
        let layout = DigitLayout::new(width, PowerOfTwoBase::B4);
        let top = 64 - width.bits();
        let key = dimension_key(self.seed, dim, self.record.grammar().symbols());
        let (a, d) = (key.input_shift >> top, key.output_shift >> top);
        let x = if inverse { x ^ d } else { x ^ a };
        let (mut s, mut f, mut out) = (key.root, 0u64, 0u64);
        let mut m = Gf2Matrix::identity(q).expect("q = 2");
        let mut m_inv = m;
        let digits = layout.num_digits();
        for k in 0..digits {
            f ^= self.record.code(s) >> (q * k);
            let fk = layout.get(f >> top, k);
            let d_in = layout.get(x, k);
            let (original, mapped) = if layout.digit_bits(k) < q {
                // Tail rule: the partial digit gets its translation only.
                let o = d_in ^ fk;
                (if inverse { o } else { d_in }, o)
            } else {
                let (psi, psi_inv) = self.matrices[s as usize];
                m = psi.mul(&m);
                m_inv = m_inv.mul(&psi_inv);
                if inverse {
                    let o = m_inv.apply(d_in ^ fk);
                    (o, o)
                } else {
                    (d_in, m.apply(d_in) ^ fk)
                }
            };
            out = layout.set(out, k, mapped);
            if k + 1 < digits {
                s = self.record.grammar().child(s, original);
            }
        }
        if inverse {
            out ^ a
        } else {
            out ^ d
        }
    }
}

impl Scrambler for QArtComposed {
    fn name(&self) -> String {
        format!(
            "q-art-4:compose=linear:table={}",
            self.record.grammar().symbols()
        )
    }

    fn base(&self) -> PowerOfTwoBase {
        PowerOfTwoBase::B4
    }

    fn claim(&self) -> Claim {
        ArtVariant::QArt4.claim()
    }

    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.run(x, width, dim, false)
    }

    /// The record (64-bit words) and the 6-entry matrix pairs per symbol, in bytes.
    fn table_bytes(&self) -> usize {
        self.record.bytes() + self.matrices.len() * 2 * std::mem::size_of::<Gf2Matrix>()
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for QArtComposed {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        self.run(y, width, dim, true)
    }
}
