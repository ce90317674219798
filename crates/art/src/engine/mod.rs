//! The ART-Owen loop (`docs/design.md` §3.3), for any variant:
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
//!
//! **Dimensions.** One table per seed serves every dimension. A root symbol hash(seed, dim) mod
//! |Σ| alone lets two of 16 dimensions share the identical scramble for about 40% of seeds
//! (birthday bound with 256 symbols). So dimension j also gets an input shift A_j and an output
//! shift D_j (W-bit words, the top bits of 64-bit words drawn per dimension):
//!
//! ```text
//! scramble_j(x) = ART_{root_j}(x ⊕ A_j) ⊕ D_j
//! ```
//!
//! Both shifts are nested digital shifts, so the composition is still a nested scramble, and the
//! node permutations keep their marginal law (ψ(d ⊕ a) ⊕ c is uniform over S_b, AGL(q,2) or the
//! translations whenever ψ ⊕ c is). The top 32 bits of D_j are a bijection of j (a keyed
//! 32-bit mixer), so two dimensions with the same root and input shift differ on every word of
//! 32 bits or more: no two dimensions share a scramble by construction. A_j sends the two
//! dimensions through different regions of the tree, so sharing a root costs at most a
//! correlation between node permutations at different positions of one tree (measured by the
//! verify battery's dimension tests). Cost: two XORs per word.

mod batch;
mod lanes;
#[cfg(target_arch = "x86_64")]
mod simd;
mod steps;

pub use batch::{BatchKernel, BATCH_TABLES_AFTER_WORDS, BATCH_TABLE_BYTES};
pub use steps::STEP_TABLES_AFTER_WORDS;

/// Chains the batch path advances together: enough independent loads in flight to hide an L2
/// hit (one 512-bit register of the gather kernel).
const LANES: usize = 8;

/// Independent registers of eight lanes walked together, so that one register's gather
/// latency is hidden behind the others'.
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
const GROUPS: usize = 6;

use crate::dims::{dimension_key, DimKey};
use crate::record::ArtRecord;
use crate::{ArtVariant, Grammar};
use gartowen_core::Unscramble;
use gartowen_core::{DigitLayout, Permutation, PowerOfTwoBase, Scrambler, Width};

/// Precomputed effect of `digits` consecutive digits (one step) from a symbol.
#[derive(Debug, Clone, Copy, Default)]
struct Step {
    /// Σ_j T[s_j] >> (q·j) over the step's symbols, in the step's relative frame.
    carry: u64,
    /// The symbol after the step.
    next: u32,
    /// Output bits of the step before ancestors' translations: ψ(v_i) ⊕ in-step codes.
    local: u32,
}

impl Step {
    /// The step's whole contribution in one word: `E = (local << (64 − SB)) | (carry's low
    /// 64 − SB bits)` for steps of `step_bits` bits. With the pending translations G of the
    /// earlier steps, the step outputs `top_SB(G ⊕ E)` (= local ⊕ top_SB(G)) and passes
    /// `(G ⊕ E) << SB` on: the carry's own top SB bits, which E replaces by `local`, are
    /// shifted out there (and are already in `local`).
    fn contribution(&self, step_bits: u32) -> u64 {
        ((self.local as u64) << (64 - step_bits)) | (self.carry & (u64::MAX >> step_bits))
    }
}

/// Number of dimensions whose root symbol and shifts are precomputed.
const CACHED_ROOTS: u32 = 256;

/// How a dimension's root symbol and shifts are derived from (seed, dimension, symbols): the
/// real rule is [`dimension_key`]; deliberate defects (the `mutants` feature) substitute
/// another.
pub(crate) type DimensionRule = fn(u64, u32, u32) -> DimKey;

/// The tables an ART-Owen scrambler is built from: grammar, codes, ψ and ψ^{-1} images, and the
/// dimension rule. Everything else (step, batch and narrow tables, cached dimensions) is
/// derived from them.
pub(crate) struct ArtTables {
    pub(crate) grammar: std::sync::Arc<Grammar>,
    pub(crate) codes: Vec<u64>,
    pub(crate) psi: Vec<u8>,
    pub(crate) psi_inv: Vec<u8>,
    pub(crate) dimension_rule: DimensionRule,
}

impl ArtTables {
    /// The tables of `variant` with `symbols` symbols drawn from `seed`: the record's (64-bit
    /// words) and the real dimension rule.
    pub(crate) fn draw(
        variant: ArtVariant,
        symbols: usize,
        seed: u64,
    ) -> Result<Self, crate::grammar::GrammarError> {
        let record = ArtRecord::draw(variant, symbols, seed, Width::W64)?;
        let grammar = record.grammar().clone();
        let b = 1usize << variant.q();
        let mut codes = Vec::with_capacity(symbols);
        let (mut psi, mut psi_inv) = (Vec::new(), Vec::new());
        for s in 0..grammar.symbols() {
            codes.push(record.code(s));
            let start = psi.len();
            if !record.psi_images_into(s, &mut psi) {
                continue;
            }
            let images = &psi[start..];
            psi_inv.resize(start + b, 0);
            for (d, &y) in images.iter().enumerate() {
                psi_inv[start + y as usize] = d as u8;
            }
            assert!(
                (0..b).all(|y| images[psi_inv[start + y] as usize] as usize == y),
                "symbol {s}'s ψ is not a bijection"
            );
        }
        Ok(ArtTables {
            grammar,
            codes,
            psi,
            psi_inv,
            dimension_rule: dimension_key,
        })
    }
}

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
    /// Digits per step (4 bits of input for q ≤ 4, one digit otherwise).
    step_digits: u32,
    /// The scalar path's step tables, built once enough words have gone through the
    /// digit-by-digit loop to pay for them ([`STEP_TABLES_AFTER_WORDS`]).
    steps: std::sync::OnceLock<steps::StepTables>,
    /// Words scrambled so far (until the step tables exist).
    step_words: batch::WordsSeen,
    /// Digits per step of the batch path's table (up to 8 bits per step while the table stays
    /// within [`batch::BATCH_TABLE_BYTES`]); 0 when the alphabet has more than 2^16 symbols
    /// and there is no batch table.
    batch_digits: u32,
    /// The batch path's tables for words of at most 32 bits ([`batch::BatchTables`]), built
    /// once enough words have gone through the batch path to pay for them
    /// ([`BATCH_TABLES_AFTER_WORDS`]): most instances of a statistical battery scramble a few
    /// hundred words, and building the tables would cost them more than the words do.
    batch: std::sync::OnceLock<batch::BatchTables>,
    /// Words the batch path has scrambled so far (until the batch tables exist).
    batch_words: batch::WordsSeen,
    /// The code that walks the batch path's lanes.
    kernel: BatchKernel,
    /// Root symbols and shifts of dimensions 0..CACHED_ROOTS.
    dims: Vec<DimKey>,
    /// How the other dimensions' keys are derived.
    dimension_rule: DimensionRule,
}

impl ArtOwen {
    /// The scrambler of `variant` with an alphabet of `symbols` Thue–Morse factors, tables drawn
    /// deterministically from `seed`.
    pub fn new(
        variant: ArtVariant,
        symbols: usize,
        seed: u64,
    ) -> Result<Self, crate::grammar::GrammarError> {
        Ok(Self::from_tables(
            variant,
            seed,
            ArtTables::draw(variant, symbols, seed)?,
        ))
    }

    /// The scrambler built from `tables` (drawn from `seed`): caches the first dimensions'
    /// keys; the step, batch and narrow tables are derived when enough words need them.
    pub(crate) fn from_tables(variant: ArtVariant, seed: u64, tables: ArtTables) -> Self {
        let ArtTables {
            grammar,
            codes,
            psi,
            psi_inv,
            dimension_rule,
        } = tables;
        let mut art = ArtOwen {
            variant,
            seed,
            grammar,
            codes,
            psi,
            psi_inv,
            step_digits: (4 / variant.q()).max(1),
            steps: std::sync::OnceLock::new(),
            step_words: batch::WordsSeen::default(),
            batch_digits: 0,
            batch: std::sync::OnceLock::new(),
            batch_words: batch::WordsSeen::default(),
            kernel: BatchKernel::detect(),
            dims: Vec::new(),
            dimension_rule,
        };
        art.dims = (0..CACHED_ROOTS).map(|d| art.hashed_dim(d)).collect();
        if art.grammar.symbols() <= 1 << 16 {
            art.batch_digits = batch::batch_digits(variant.q(), art.grammar.symbols());
        }
        art
    }

    /// The variant.
    pub fn variant(&self) -> ArtVariant {
        self.variant
    }

    /// The translation code of every symbol: a top-aligned 64-bit word whose q-bit field j
    /// (bits 64 − q(j+1) .. 64 − qj) lands on the digit j levels below the symbol's node.
    pub fn codes(&self) -> &[u64] {
        &self.codes
    }

    /// The ψ table: the image of digit d under symbol s's ψ at index s·2^q + d; empty when ψ
    /// is the identity for every symbol (translation-only variants).
    pub fn psi_images(&self) -> &[u8] {
        &self.psi
    }

    /// The input shift A and output shift D of dimension `dim` for `width`-bit words (the low
    /// `width` bits): `scramble(x) = ART_root(x ⊕ A) ⊕ D`.
    pub fn dimension_shifts(&self, dim: u32, width: Width) -> (u64, u64) {
        let (_, a, d) = self.keys_at(dim, width);
        (a, d)
    }

    /// The grammar.
    pub fn grammar(&self) -> &Grammar {
        &self.grammar
    }

    /// The record of this table for `width`-bit words: the per-symbol data a renderer must
    /// store or ship, in the paper's layouts ([`ArtRecord`]; a mutant's defects are not in it).
    pub fn record(&self, width: Width) -> ArtRecord {
        ArtRecord::draw(
            self.variant,
            self.grammar.symbols() as usize,
            self.seed,
            width,
        )
        .expect("the table's own alphabet size")
    }

    /// Bytes of the acceleration tables, all derived from the record at construction:
    /// everything [`Scrambler::table_bytes`] counts except the shared child table.
    pub fn acceleration_bytes(&self) -> usize {
        self.table_bytes() - self.grammar.table_bytes()
    }

    /// The root symbol of dimension `dim`: hash of (seed, dim) reduced without bias.
    #[inline]
    pub fn root(&self, dim: u32) -> u32 {
        self.dim_key(dim).root
    }

    #[inline(always)]
    fn dim_key(&self, dim: u32) -> DimKey {
        match self.dims.get(dim as usize) {
            Some(&k) => k,
            None => self.hashed_dim(dim),
        }
    }

    #[cold]
    #[inline(never)]
    fn hashed_dim(&self, dim: u32) -> DimKey {
        self.key_for(self.seed, dim)
    }

    /// The key of `dim` that a table seeded `key_seed` would use (root symbol and shifts).
    fn key_for(&self, key_seed: u64, dim: u32) -> DimKey {
        (self.dimension_rule)(key_seed, dim, self.grammar.symbols())
    }

    #[inline(always)]
    fn child(&self, s: u32, d: u32) -> u32 {
        self.grammar.child(s, d)
    }

    /// The forward scramble through the step table, in the relative frame G = F << q·k (digit
    /// k at the top of G); digits left after the whole steps go one at a time. Equal to the
    /// digit-by-digit loop (tested).
    #[inline]
    fn forward_fast(&self, x: u64, width: Width, root: u32) -> u64 {
        let Some(tables) = self.step_tables_for(1) else {
            return self.finish_digits(x, width, 0, root, 0, 0);
        };
        let q = self.q();
        let w = width.bits();
        let step_bits = q * self.step_digits;
        let full_digits = w / q;
        let steps = full_digits / self.step_digits;
        let (mut s, mut g, mut out) = (root, 0u64, 0u64);
        let mask = (1u64 << step_bits) - 1;
        for i in 0..steps {
            let v = (x >> (w - step_bits * (i + 1))) & mask;
            let idx = ((s as usize) << step_bits) | v as usize;
            let t = g ^ tables.contribution[idx];
            out = (out << step_bits) | (t >> (64 - step_bits));
            g = t << step_bits;
            s = tables.next[idx];
        }
        self.finish_digits(x, width, steps * step_bits, s, g, out)
    }

    /// The digits left after the whole steps of [`Self::forward_fast`] (the first `consumed`
    /// bits of `x` are done, `s` and `g` are the state there), then the partial tail digit
    /// (translation only).
    #[inline]
    fn finish_digits(
        &self,
        x: u64,
        width: Width,
        mut consumed: u32,
        mut s: u32,
        mut g: u64,
        mut out: u64,
    ) -> u64 {
        let q = self.q();
        let w = width.bits();
        while consumed + q <= w {
            consumed += q;
            let d = ((x >> (w - consumed)) & ((1 << q) - 1)) as u32;
            g ^= self.codes[s as usize];
            out = (out << q) | (self.psi_apply(s, d) ^ (g >> (64 - q)) as u32) as u64;
            g <<= q;
            s = self.child(s, d);
        }
        let r = w - consumed;
        if r == 0 {
            out
        } else {
            self.tail_digit(x, r, s, g, out)
        }
    }

    /// The partial tail digit of `r` bits (0 < r < q; translation only): `out` with the word's
    /// last r bits appended, XORed with the top r bits of the pending translations `g` and of
    /// the code of `s`, the symbol reached.
    #[inline(always)]
    fn tail_digit(&self, x: u64, r: u32, s: u32, g: u64, out: u64) -> u64 {
        let g = g ^ self.codes[s as usize];
        (out << r) | ((x & ((1 << r) - 1)) ^ (g >> (64 - r)))
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

    /// Root symbol, input shift and output shift of dimension `dim` for `width`-bit words.
    #[inline(always)]
    fn keys_at(&self, dim: u32, width: Width) -> (u32, u64, u64) {
        Self::shifts_at(self.dim_key(dim), width)
    }

    /// Root symbol, input shift and output shift of `key` for `width`-bit words.
    #[inline(always)]
    fn shifts_at(k: DimKey, width: Width) -> (u32, u64, u64) {
        let top = 64 - width.bits();
        (k.root, k.input_shift >> top, k.output_shift >> top)
    }

    /// Scrambles `words` of dimension `dim` in place with this table keyed by `key_seed`: the
    /// root symbol and both dimension shifts are those a table seeded `key_seed` would use,
    /// the per-symbol tables stay this one's. So a renderer ships one table and keys each
    /// render (or pixel) by a seed of its own; keyed by the table's own seed this is
    /// [`Scrambler::scramble_batch`].
    pub fn scramble_batch_keyed(&self, words: &mut [u64], width: Width, dim: u32, key_seed: u64) {
        self.forward_batch(words, width, self.key_for(key_seed, dim))
    }

    /// One word of [`ArtOwen::scramble_batch_keyed`], by the plain digit-by-digit loop (the
    /// reference the batch path is tested against).
    pub fn scramble_keyed_digit_by_digit(
        &self,
        x: u64,
        width: Width,
        dim: u32,
        key_seed: u64,
    ) -> u64 {
        self.digit_loop(x, width, self.key_for(key_seed, dim))
    }

    /// The seed the tables were drawn from (the key [`ArtOwen::scramble_batch_keyed`] takes
    /// to give the scramble itself).
    pub fn seed(&self) -> u64 {
        self.seed
    }

    #[inline]
    fn run(&self, x: u64, width: Width, dim: u32, inverse: bool) -> u64 {
        let (root, a, d) = self.keys_at(dim, width);
        if inverse {
            self.run_from(x ^ d, width, root, true) ^ a
        } else {
            self.forward_fast(x ^ a, width, root) ^ d
        }
    }

    /// The forward scramble by the plain digit-by-digit loop (the reference for the step table).
    pub fn scramble_digit_by_digit(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.digit_loop(x, width, self.dim_key(dim))
    }

    /// The forward scramble under `key` by the digit-by-digit loop.
    fn digit_loop(&self, x: u64, width: Width, key: DimKey) -> u64 {
        let (root, a, d) = Self::shifts_at(key, width);
        self.run_from(x ^ a, width, root, false) ^ d
    }

    /// The table's scramble (or its inverse) starting from root symbol `root`, without the
    /// dimension shifts: lets tests cover every root symbol of a table.
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
            let d_in = layout.get(x, k);
            let full = layout.digit_bits(k) == q;
            let fk = layout.get(f >> top, k);
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
                s = self.child(s, original);
            }
        }
        out
    }

    /// The permutation this scrambler applies at node (depth k, original prefix p) of `dim`:
    /// d ↦ ψ_{s_k}(d ⊕ a_k) ⊕ F_k ⊕ D_k, with s_k and F_k accumulated along the prefix shifted
    /// by the dimension's input shift A, and a_k, D_k digit k of the dimension shifts (the explicit-tree
    /// bridge). The tail digit's node is d ↦ d ⊕ F_k on 2^r symbols.
    pub fn node_permutation(&self, width: Width, dim: u32, depth: u32, prefix: u64) -> Permutation {
        let q = self.q();
        let layout = DigitLayout::new(width, PowerOfTwoBase::from_q(q).expect("q ≤ 8"));
        let top = 64 - width.bits();
        let (root, a, dshift) = self.keys_at(dim, width);
        // The inner (unshifted) tree is walked by the shifted prefix.
        let prefix_bits: u32 = (0..depth).map(|j| layout.digit_bits(j)).sum();
        let prefix = if prefix_bits == 0 {
            prefix
        } else {
            prefix ^ (a >> (width.bits() - prefix_bits))
        };
        let (a_k, d_k) = (layout.get(a, depth), layout.get(dshift, depth));
        let mut s = root;
        let mut f = 0u64;
        for k in 0..=depth {
            f ^= self.codes[s as usize] >> (q * k);
            if k < depth {
                // Digit k of the prefix (prefix holds digits 0..depth, most significant first).
                let shift: u32 = (k + 1..depth).map(|j| layout.digit_bits(j)).sum();
                let d = ((prefix >> shift) & ((1u64 << layout.digit_bits(k)) - 1)) as u32;
                s = self.child(s, d);
            }
        }
        let fk = layout.get(f >> top, depth);
        let bits = layout.digit_bits(depth);
        let images: Vec<u8> = (0..1u32 << bits)
            .map(|d| {
                let z = d ^ a_k;
                ((if bits == q { self.psi_apply(s, z) } else { z }) ^ fk ^ d_k) as u8
            })
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

    fn claim(&self) -> gartowen_core::Claim {
        self.variant.claim()
    }

    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        self.run(x, width, dim, false)
    }

    /// Everything held once the batch path is warm, in bytes: child table, codes, ψ and ψ^{-1}
    /// images, the scalar step tables, the batch table and the narrow table with the codes'
    /// top halves (the step and batch tables are built here if they were not yet).
    fn table_bytes(&self) -> usize {
        self.grammar.table_bytes()
            + self.codes.len() * 8
            + self.psi.len()
            + self.psi_inv.len()
            + self.step_tables().bytes()
            + self.batch_tables().map_or(0, batch::BatchTables::bytes)
    }

    /// Interleaved chains through the step table (bit-identical to [`Scrambler::scramble`]).
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        self.forward_batch(words, width, self.dim_key(dim))
    }
    /// The same lanes walked on the 32-bit words themselves (no widened copy).
    fn scramble_batch_u32(&self, words: &mut [u32], dim: u32) {
        self.forward_batch(words, Width::W32, self.dim_key(dim))
    }
    fn inverse(&self) -> Option<&dyn Unscramble> {
        Some(self)
    }
}

impl Unscramble for ArtOwen {
    fn unscramble(&self, y: u64, width: Width, dim: u32) -> u64 {
        self.run(y, width, dim, true)
    }
}
