//! The record of an ART-Owen table: the data a renderer must store or ship to run the scramble,
//! in the generalized paper's layouts, bit-packed, and a scalar path that reads nothing else.
//!
//! Per symbol the record holds one entry of `psi_bits + code_bits` bits (entries back to back
//! in a stream of u64 words, stream bit i = bit i mod 64 of word i / 64; an entry may straddle
//! two words). The grammar's child table is separate: it is static and shared by every seed.
//! The dimension keys are hashes of (seed, dimension) and take no storage (`dims.rs`).
//!
//! | variant | ψ field | code field |
//! |---|---|---|
//! | `art-owen-2`, `art-owen-t{q}` | none | W bits |
//! | `q-art-4` | 3 bits: index into GL(2,2)'s 6 matrices in increasing packed order | W bits |
//! | `art-owen-8p` | none: one 32-bit word whose top 24 bits pack ψ (entry d in 3-bit field d from the top); the same word with field 0 cleared is the code | (the 32-bit word) |
//! | `art-owen-16p` | 64 bits: ψ packed (entry d in 4-bit field d from the top) | min(W, 32) bits |
//! | `art-owen-m{q}` | q² bits: row i of the matrix in bits [q·i, q·i + q) | W bits |
//!
//! A code field holds the top bits of the top-aligned code: a W-bit word never reads the
//! others, since the loop only shifts codes down. The acceleration tables of
//! [`crate::ArtOwen`] (unpacked codes, ψ and ψ⁻¹ images, step tables, batch tables) are all
//! derived from the 64-bit record at construction.

use crate::dims::dimension_key;
use crate::grammar::{Grammar, GrammarError};
use crate::ArtVariant;
use gartowen_core::{derive_seed, Gf2Matrix, Permutation, SplitMix64, Width};
use std::sync::Arc;

/// The generalized paper's statements of record size against base-4 Q-ART (variant, ratio,
/// the paper's words), printed beside the measured ratios by `gartowen list`.
pub const PAPER_RECORD_RATIOS: [(&str, f64, &str); 2] = [
    (
        "art-owen-8p",
        1.0,
        "essentially the same table size as base-4 Q-ART",
    ),
    ("art-owen-16p", 3.0, "roughly three times Q-ART"),
];

/// Tag for the table stream (`derive_seed(seed, TABLE_TAG)`).
const TABLE_TAG: u64 = 0x0074_6162_6c65; // "table"

/// How a variant's ψ is stored in its record entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PsiLayout {
    /// ψ = identity (binary, translation-only).
    Identity,
    /// A 3-bit index into GL(2,2) (Q-ART).
    Gl2Index,
    /// The 8p word: ψ in the top 24 bits of the 32-bit code field.
    SharedWord,
    /// A 64-bit packed permutation of 16 digits.
    Packed16,
    /// A q×q GF(2) matrix in q² bits.
    Matrix,
}

/// The record of one ART-Owen table for words of one width: the per-symbol data in the paper's
/// layouts, bit-packed, with the seed (for the dimension keys) and the shared grammar.
#[derive(Debug, Clone)]
pub struct ArtRecord {
    variant: ArtVariant,
    width: Width,
    seed: u64,
    grammar: Arc<Grammar>,
    layout: PsiLayout,
    psi_bits: u32,
    code_bits: u32,
    /// The entry stream.
    stream: Vec<u64>,
    /// GL(2,2) in increasing packed order, for Q-ART's index (static: 6 matrices, no table data).
    gl2: &'static [Gf2Matrix],
}

/// Reads `bits` (≤ 64) bits at bit `offset` of an LSB-first stream.
#[inline(always)]
fn read_bits(stream: &[u64], offset: usize, bits: u32) -> u64 {
    let (word, shift) = (offset / 64, (offset % 64) as u32);
    let low = stream[word] >> shift;
    let value = if shift + bits > 64 {
        low | (stream[word + 1] << (64 - shift))
    } else {
        low
    };
    if bits == 64 {
        value
    } else {
        value & ((1u64 << bits) - 1)
    }
}

/// Writes `bits` (≤ 64) bits of `value` at bit `offset` of a zeroed LSB-first stream.
fn write_bits(stream: &mut [u64], offset: usize, bits: u32, value: u64) {
    let (word, shift) = (offset / 64, (offset % 64) as u32);
    stream[word] |= value << shift;
    if shift + bits > 64 {
        stream[word + 1] |= value >> (64 - shift);
    }
}

impl ArtRecord {
    /// The record of `variant` with `symbols` Thue–Morse factors for `width`-bit words, drawn
    /// from `seed` exactly as [`crate::ArtOwen::new`] draws its table (the same scrambles).
    pub fn draw(
        variant: ArtVariant,
        symbols: usize,
        seed: u64,
        width: Width,
    ) -> Result<Self, GrammarError> {
        let len = crate::grammar::length_for_size(symbols)?;
        let grammar = Grammar::shared(len, variant.q())?;
        let q = variant.q();
        let w = width.bits();
        let (layout, psi_bits, code_bits) = match variant {
            ArtVariant::ArtOwen2 | ArtVariant::Translation(_) => (PsiLayout::Identity, 0, w),
            ArtVariant::QArt4 => (PsiLayout::Gl2Index, 3, w),
            ArtVariant::ArtOwen8P => (PsiLayout::SharedWord, 0, 32),
            ArtVariant::ArtOwen16P => (PsiLayout::Packed16, 64, w.min(32)),
            ArtVariant::Matrix(_) => (PsiLayout::Matrix, q * q, w),
        };
        let gl2: &'static [Gf2Matrix] = if layout == PsiLayout::Gl2Index {
            crate::variants::gl2()
        } else {
            &[]
        };
        let n = grammar.symbols() as usize;
        let entry_bits = (psi_bits + code_bits) as usize;
        let mut stream = vec![0u64; (n * entry_bits).div_ceil(64)];
        let mut rng = SplitMix64::new(derive_seed(seed, TABLE_TAG));
        for s in 0..n {
            let (psi, code) = variant.draw_symbol(&mut rng);
            let psi_field = match layout {
                PsiLayout::Identity | PsiLayout::SharedWord => 0,
                PsiLayout::Gl2Index => {
                    let p = psi.as_ref().expect("Q-ART draws ψ");
                    gl2.iter()
                        .position(|m| (0..4).all(|d| m.apply(d) == p.apply(d)))
                        .expect("ψ ∈ GL(2,2)") as u64
                }
                PsiLayout::Packed16 => psi.as_ref().expect("16p draws ψ").pack64().expect("16"),
                PsiLayout::Matrix => {
                    // Column j of the matrix is ψ(e_j); row i collects bit i of every column.
                    let p = psi.as_ref().expect("M{q} draws ψ");
                    (0..q).fold(0u64, |acc, i| {
                        let row = (0..q)
                            .fold(0u64, |r, j| r | (((p.apply(1 << j) >> i) & 1) as u64) << j);
                        acc | row << (q * i)
                    })
                }
            };
            let code_field = if layout == PsiLayout::SharedWord {
                // The drawn code is the word with field 0 (ψ(0)) cleared: put ψ(0) back.
                let p = psi.as_ref().expect("8p draws ψ");
                (code >> 32) | ((p.apply(0) as u64) << 29)
            } else {
                code >> (64 - code_bits)
            };
            let at = s * entry_bits;
            write_bits(&mut stream, at, psi_bits, psi_field);
            write_bits(&mut stream, at + psi_bits as usize, code_bits, code_field);
        }
        Ok(ArtRecord {
            variant,
            width,
            seed,
            grammar,
            layout,
            psi_bits,
            code_bits,
            stream,
            gl2,
        })
    }

    /// The variant.
    pub fn variant(&self) -> ArtVariant {
        self.variant
    }

    /// The word width the record serves.
    pub fn width(&self) -> Width {
        self.width
    }

    /// The shared grammar (its child table is not part of the record).
    pub fn grammar(&self) -> &Arc<Grammar> {
        &self.grammar
    }

    /// Bits of one symbol's entry.
    pub fn entry_bits(&self) -> u32 {
        self.psi_bits + self.code_bits
    }

    /// Bytes of the record: every symbol's entry, packed, rounded up to whole bytes (the seed,
    /// 8 bytes, and the shared child table are not counted).
    pub fn bytes(&self) -> usize {
        (self.grammar.symbols() as usize * self.entry_bits() as usize).div_ceil(8)
    }

    /// Bytes of the record per symbol (entry bits / 8).
    pub fn bytes_per_symbol(&self) -> f64 {
        f64::from(self.entry_bits()) / 8.0
    }

    #[inline(always)]
    fn psi_field(&self, s: u32) -> u64 {
        read_bits(
            &self.stream,
            s as usize * self.entry_bits() as usize,
            self.psi_bits,
        )
    }

    #[inline(always)]
    fn code_field(&self, s: u32) -> u64 {
        let at = s as usize * self.entry_bits() as usize + self.psi_bits as usize;
        read_bits(&self.stream, at, self.code_bits)
    }

    /// Symbol `s`'s translation code, top-aligned in 64 bits (field j, the contribution j levels
    /// down, in bits [64 − q(j+1), 64 − qj)); bits below the record's width are zero.
    #[inline(always)]
    pub fn code(&self, s: u32) -> u64 {
        let field = self.code_field(s);
        if self.layout == PsiLayout::SharedWord {
            (field << 32) & !(0b111u64 << 61)
        } else {
            field << (64 - self.code_bits)
        }
    }

    /// ψ_s(d) for a full q-bit digit d, decoded from the record.
    #[inline(always)]
    pub fn psi_apply(&self, s: u32, d: u32) -> u32 {
        match self.layout {
            PsiLayout::Identity => d,
            PsiLayout::Gl2Index => self.gl2[self.psi_field(s) as usize].apply(d),
            PsiLayout::SharedWord => ((self.code_field(s) >> (29 - 3 * d)) & 7) as u32,
            PsiLayout::Packed16 => ((self.psi_field(s) >> (60 - 4 * d)) & 15) as u32,
            PsiLayout::Matrix => {
                let q = self.variant.q();
                let m = self.psi_field(s);
                (0..q).fold(0, |y, i| {
                    let row = ((m >> (q * i)) & ((1 << q) - 1)) as u32;
                    y | ((row & d).count_ones() & 1) << i
                })
            }
        }
    }

    /// Symbol `s`'s ψ as a GF(2) matrix, for the variants whose ψ is linear (Q-ART and the
    /// matrix variants); `None` for the others.
    pub fn psi_matrix(&self, s: u32) -> Option<Gf2Matrix> {
        match self.layout {
            PsiLayout::Gl2Index => Some(self.gl2[self.psi_field(s) as usize]),
            PsiLayout::Matrix => {
                let q = self.variant.q();
                let m = self.psi_field(s);
                let rows: [u8; 8] =
                    std::array::from_fn(|i| ((m >> (q * i as u32)) & ((1 << q) - 1)) as u8);
                Some(Gf2Matrix::from_rows(q, &rows[..q as usize]).expect("q ≤ 8 rows of q bits"))
            }
            _ => None,
        }
    }

    /// Symbol `s`'s ψ as a permutation, or `None` where ψ is the identity for every symbol.
    pub fn psi(&self, s: u32) -> Option<Permutation> {
        let mut images = Vec::new();
        self.psi_images_into(s, &mut images)
            .then(|| Permutation::from_images(&images).expect("a record's ψ is a bijection"))
    }

    /// Appends symbol `s`'s ψ images (ψ(0), …, ψ(2^q − 1)) to `out` without building the
    /// permutation; false (nothing appended) where ψ is the identity for every symbol. An
    /// instance of the engine reads its ψ table this way: a permutation per symbol was a fifth
    /// of its construction.
    pub fn psi_images_into(&self, s: u32, out: &mut Vec<u8>) -> bool {
        if self.layout == PsiLayout::Identity {
            return false;
        }
        match self.psi_matrix(s) {
            // Linear ψ: its images by linearity, the same values psi_apply decodes (tested).
            Some(m) => m.images_into(out),
            None => out.extend((0..1u32 << self.variant.q()).map(|d| self.psi_apply(s, d) as u8)),
        }
        true
    }

    /// The scramble of the record's width-bit word `x` in dimension `dim`, read from the record
    /// and the child table alone (what a GPU kernel would run): the digit-by-digit loop of
    /// [`crate::engine`], ψ and codes decoded from their packed fields at every step. Equal to
    /// [`crate::ArtOwen`]'s scramble at the same width (tested on every variant).
    pub fn scramble(&self, x: u64, dim: u32) -> u64 {
        let q = self.variant.q();
        let w = self.width.bits();
        let top = 64 - w;
        let key = dimension_key(self.seed, dim, self.grammar.symbols());
        let x = x ^ (key.input_shift >> top);
        let mask = (1u64 << q) - 1;
        let full = w / q;
        let (mut s, mut f, mut out) = (key.root, 0u64, 0u64);
        for k in 0..full {
            f ^= self.code(s) >> (q * k);
            let d = ((x >> (w - q * (k + 1))) & mask) as u32;
            let fk = (f >> (64 - q * (k + 1))) & mask;
            out = (out << q) | (u64::from(self.psi_apply(s, d)) ^ fk);
            s = self.grammar.child(s, d);
        }
        let r = w - q * full;
        if r != 0 {
            // Tail rule: the partial digit gets its translation only.
            f ^= self.code(s) >> (q * full);
            let t = (f >> (64 - q * full - r)) & ((1 << r) - 1);
            out = (out << r) | ((x & ((1 << r) - 1)) ^ t);
        }
        out ^ (key.output_shift >> top)
    }
}
