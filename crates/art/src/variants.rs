//! The ART-Owen variants and how each one's per-symbol table is drawn from a seed.
//!
//! Per symbol, in symbol order, ψ is drawn first and then the translation code. Codes are kept
//! top-aligned in 64 bits (field j, the contribution j levels down, in bits
//! [64 − q(j+1), 64 − qj)), so 32- and 64-bit words share one table.

use gartowen_core::{Claim, Gf2Matrix, NodeGroup, Permutation, SplitMix64};

/// A member of the ART-Owen family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ArtVariant {
    /// q = 1, ψ = identity: binary ART-Owen (XOR codes composed down the tree).
    ArtOwen2,
    /// q = 2, ψ ∈ GL(2,2) (a 3-bit index into the 6 matrices) plus codes: Q-ART.
    QArt4,
    /// q = 3: one 32-bit word per symbol; its top 24 bits are a packed permutation of 8 digits,
    /// and its 3-bit fields 1.. are the translation code for descendants (field 0 cleared).
    ArtOwen8P,
    /// q = 4: a packed permutation of 16 digits plus a 32-bit translation code.
    ArtOwen16P,
    /// ψ uniform in GL(q,2) plus a 64-bit code (not uniform over S_b for q ≥ 3).
    Matrix(u32),
    /// ψ = identity, codes only: a nested digital shift in base 2^q (not uniform for q ≥ 2).
    Translation(u32),
}

impl ArtVariant {
    /// Every variant: the four named ones, then Matrix(1..=8) and Translation(1..=8).
    pub fn all() -> Vec<ArtVariant> {
        let mut v = vec![
            ArtVariant::ArtOwen2,
            ArtVariant::QArt4,
            ArtVariant::ArtOwen8P,
            ArtVariant::ArtOwen16P,
        ];
        v.extend((1..=8).map(ArtVariant::Matrix));
        v.extend((1..=8).map(ArtVariant::Translation));
        v
    }

    /// Digit size q.
    pub fn q(self) -> u32 {
        match self {
            ArtVariant::ArtOwen2 => 1,
            ArtVariant::QArt4 => 2,
            ArtVariant::ArtOwen8P => 3,
            ArtVariant::ArtOwen16P => 4,
            ArtVariant::Matrix(q) | ArtVariant::Translation(q) => q,
        }
    }

    /// The registry name.
    pub fn name(self) -> String {
        match self {
            ArtVariant::ArtOwen2 => "art-owen-2".into(),
            ArtVariant::QArt4 => "q-art-4".into(),
            ArtVariant::ArtOwen8P => "art-owen-8p".into(),
            ArtVariant::ArtOwen16P => "art-owen-16p".into(),
            ArtVariant::Matrix(q) => format!("art-owen-m{q}"),
            ArtVariant::Translation(q) => format!("art-owen-t{q}"),
        }
    }

    /// What the variant promises: nested, and every node permutation marginally uniform over
    /// S_b (binary, Q-ART, 8P, 16P), AGL(q,2) (M{q}) or the translations (T{q}). Node
    /// permutations are not independent (nodes of one symbol share ψ and code), so no
    /// independence is claimed; the verify battery measures the joint laws instead.
    pub fn claim(self) -> Claim {
        Claim::marginal(match self {
            ArtVariant::ArtOwen2
            | ArtVariant::QArt4
            | ArtVariant::ArtOwen8P
            | ArtVariant::ArtOwen16P => NodeGroup::Symmetric,
            ArtVariant::Matrix(_) => NodeGroup::Affine,
            ArtVariant::Translation(_) => NodeGroup::Translation,
        })
    }

    /// Draws one symbol's (ψ images or None for identity, top-aligned code).
    pub fn draw_symbol(self, rng: &mut SplitMix64) -> (Option<Permutation>, u64) {
        let q = self.q();
        let images = |f: &dyn Fn(u32) -> u32| {
            Permutation::from_images(&(0..1u32 << q).map(|d| f(d) as u8).collect::<Vec<_>>())
                .expect("bijection")
        };
        match self {
            ArtVariant::ArtOwen2 | ArtVariant::Translation(_) => (None, rng.next_u64()),
            ArtVariant::QArt4 => {
                let a = gl2()[rng.bounded(6) as usize];
                (Some(images(&|d| a.apply(d))), rng.next_u64())
            }
            ArtVariant::Matrix(_) => {
                let a = Gf2Matrix::random_invertible(q, rng).expect("q ≤ 8");
                let p = Permutation::from_images(&a.images()).expect("invertible");
                (Some(p), rng.next_u64())
            }
            ArtVariant::ArtOwen8P => {
                let p = Permutation::random(8, rng).expect("8");
                let word = (p.pack24().expect("8 symbols") << 8) | (rng.next_u32() & 0xFF);
                // Fields 1.. of the word translate descendants; field 0 (own level) is ψ's job.
                let code = ((word as u64) << 32) & !(0b111u64 << 61);
                (Some(p), code)
            }
            ArtVariant::ArtOwen16P => {
                let p = Permutation::random(16, rng).expect("16");
                (Some(p), (rng.next_u32() as u64) << 32)
            }
        }
    }
}

/// GL(2,2) in increasing packed order (Q-ART's ψ group and its record's index), enumerated
/// once: an instance draws ψ for each of its symbols.
pub(crate) fn gl2() -> &'static [Gf2Matrix] {
    static GL2: std::sync::OnceLock<Vec<Gf2Matrix>> = std::sync::OnceLock::new();
    GL2.get_or_init(|| Gf2Matrix::all_invertible(2))
}
