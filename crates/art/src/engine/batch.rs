//! The batch path: [`LANES`] words walk a step table together.
//!
//! One word's digit chain is serial (the next symbol is read from the entry the current one
//! selects), so a single word waits on one table load per step. Independent words do not: the
//! loops below advance [`LANES`] chains step by step, so their loads are in flight together
//! and the core overlaps them. Once the loads overlap, instructions per step are the cost, so
//! words of at most 32 bits use a table of wider steps (up to 8 bits) whose entries hold
//! everything a step contributes to the output in one word.
//!
//! **The contribution form.** A step with entry (local, carry, next) outputs
//! `local ⊕ top(G)` and passes `G' = (G ⊕ carry) << SB` on, where `G` holds the translations
//! pending from earlier steps in the step's relative frame and the carry's own top SB bits are
//! already in `local` (the scalar loop, `forward_fast`, reads both from one word, E_i below).
//! Unrolled, the output word (top-aligned) is
//!
//! ```text
//! Y = ⊕_i  E_i >> (SB·i),     E_i = (local_i << (64 − SB)) | (carry_i & (2^(64−SB) − 1)),
//! ```
//!
//! so a step is one load and one XOR. **Why 32 bits of E suffice for W ≤ 32**: `E_i >> SB·i`
//! only moves bits down, and the top W ≤ 32 bits of Y depend only on the top 32 bits of each
//! E_i. The batch table keeps those 32 bits above the next symbol (16 bits; the low bits of
//! the accumulator are never read), one 8-byte load per step. After the whole steps, the
//! pending translations for the digits left over are the accumulator shifted up by the bits
//! consumed (its top 32 bits, which are exact), and the scalar code finishes the word.
//!
//! Words wider than 32 bits walk the scalar path's table of whole 64-bit contributions E_i,
//! interleaved the same way. Both are bit-identical to the scalar path (tested on every
//! registry entry).

use super::lanes::{PrefixMemo, Word};
use super::{ArtOwen, Step, LANES};
use crate::dims::DimKey;
use gartowen_core::Width;
use std::sync::atomic::{AtomicU64, Ordering};

/// The fewest words left after the whole blocks that the gather kernels take as one
/// zero-padded block rather than leave to the portable lanes.
#[cfg(target_arch = "x86_64")]
const PADDED_BLOCK_MIN: usize = 16;

/// The most bytes the batch table may take; wider steps are used while it fits.
pub const BATCH_TABLE_BYTES: usize = 1 << 20;

/// Words an instance scrambles through its batch path before it builds the batch tables (for
/// 256 symbols they take 0.5–3 ms to build, the time the split-table lanes take for about
/// 2^18 words). Calls of at least this many words build them at once.
pub const BATCH_TABLES_AFTER_WORDS: u64 = 1 << 18;

/// The batch path's tables for words of at most 32 bits: the packed table, its narrow form
/// and the codes' top halves for the narrow kernel.
#[derive(Debug, Clone)]
pub(super) struct BatchTables {
    /// Symbol · 2^(step bits) + step digits → E's top 32 bits | next symbol.
    table: Vec<u64>,
    /// The table's entries as 32 bits (see [`narrow`]); empty unless the symbols fit in two
    /// steps' bits.
    narrow: Vec<u32>,
    /// Steps the narrow kernel walks in `table` before it turns to `narrow` (see
    /// [`narrow_wide_steps`]).
    wide_steps: u32,
    /// The top 32 bits of each symbol's code, for the narrow kernel's tail digit (empty
    /// without the narrow table).
    codes_top: Vec<u32>,
}

impl BatchTables {
    /// The tables of `art` for steps of `digits` digits, with the invariants the gather
    /// kernels' safety rests on (see `simd`) checked: every index (symbol << step bits |
    /// digits) and every symbol read lies inside its table.
    fn build(art: &ArtOwen, digits: u32) -> BatchTables {
        let step_bits = digits * art.q();
        let table = pack(&art.build_steps(digits), step_bits);
        let symbols = art.grammar.symbols() as u64;
        assert!(
            table.len() == (symbols as usize) << step_bits
                && art.codes.len() == symbols as usize
                && table.iter().all(|e| e & 0xFFFF < symbols),
            "batch table out of shape"
        );
        let wide_steps = narrow_wide_steps(step_bits, symbols).unwrap_or(0);
        let narrow = narrow(&table, step_bits, symbols);
        let codes_top = if narrow.is_empty() {
            Vec::new()
        } else {
            art.codes.iter().map(|&c| (c >> 32) as u32).collect()
        };
        assert!(
            narrow.is_empty()
                || (narrow.len() == table.len()
                    && codes_top.len() == art.codes.len()
                    && narrow
                        .iter()
                        .all(|&e| u64::from(e) & ((1 << (wide_steps * step_bits)) - 1) < symbols)),
            "narrow table out of shape"
        );
        BatchTables {
            table,
            narrow,
            wide_steps,
            codes_top,
        }
    }

    /// Bytes held.
    pub(super) fn bytes(&self) -> usize {
        self.table.len() * 8 + self.narrow.len() * 4 + self.codes_top.len() * 4
    }
}

/// What the split-table lanes are handed in place of batch tables (they never read it).
static NO_BATCH_TABLES: BatchTables = BatchTables {
    table: Vec::new(),
    narrow: Vec::new(),
    wide_steps: 0,
    codes_top: Vec::new(),
};

/// A count of words scrambled, cloned with its value (for [`ArtOwen`]'s `Clone`).
#[derive(Debug, Default)]
pub(super) struct WordsSeen(AtomicU64);

impl WordsSeen {
    /// Counts `more` words; the count after them.
    pub(super) fn add(&self, more: usize) -> u64 {
        self.0
            .fetch_add(more as u64, Ordering::Relaxed)
            .saturating_add(more as u64)
    }
}

impl Clone for WordsSeen {
    fn clone(&self) -> Self {
        WordsSeen(AtomicU64::new(self.0.load(Ordering::Relaxed)))
    }
}

/// Digits per batch step for base 2^q and `symbols` symbols: as many as fit in 8 bits while the
/// table (symbols · 2^(q·digits) entries of 8 bytes) stays within [`BATCH_TABLE_BYTES`].
pub(super) fn batch_digits(q: u32, symbols: u32) -> u32 {
    let mut m = (8 / q).max(1);
    while m > 1 && ((symbols as usize) << (q * m)) * 8 > BATCH_TABLE_BYTES {
        m -= 1;
    }
    m
}

/// The batch table's entries from the steps of `step_bits` bits: E's top 32 bits | next.
pub(super) fn pack(steps: &[Step], step_bits: u32) -> Vec<u64> {
    steps
        .iter()
        .map(|e| (e.contribution(step_bits) & 0xFFFF_FFFF_0000_0000) | e.next as u64)
        .collect()
}

/// The narrow table: the batch table's entries as 32 bits, `(E's top 32 bits with the low
/// k·step_bits cleared) | next`, where k = [`narrow_wide_steps`] (empty when there is none).
///
/// **Why the cleared bits are never missed.** Step i contributes `E_i >> (SB·i)` to the
/// accumulator's top 32 bits, so from step k on the low k·SB bits of E's top half shift out of
/// them. Only steps 0..k need all 32 bits, and they read the batch table (step 0 only its
/// root's row). Entries of 4 bytes halve the table the later steps' gathers walk (256 KiB for
/// 256 symbols and 8-bit steps): measured on a Zen 4 core (1 MiB L2, 72-entry L1 TLB), the
/// gathers were a quarter slower on a 512 KiB table than on 256 KiB.
pub(super) fn narrow(table: &[u64], step_bits: u32, symbols: u64) -> Vec<u32> {
    let Some(k) = narrow_wide_steps(step_bits, symbols) else {
        return Vec::new();
    };
    let low = (1u64 << (k * step_bits)) - 1;
    table
        .iter()
        .map(|&e| (((e >> 32) & !low) | (e & low)) as u32)
        .collect()
}

/// The steps k whose entries the narrow kernel reads from the batch table before it turns to
/// the narrow one: the fewest whose bits hold every symbol (the narrow entries keep the next
/// symbol in their low k·step_bits bits), 1 or 2; `None` when two steps' bits do not hold
/// them. (Steps have at most 8 bits, so k·step_bits ≤ 16, the batch entries' symbol field.)
/// Two steps serve 256 symbols in bases 8, 32, 64 and 128, whose batch steps have 6, 5, 6 and
/// 7 bits.
pub(super) fn narrow_wide_steps(step_bits: u32, symbols: u64) -> Option<u32> {
    debug_assert!(step_bits <= 8, "batch steps have at most 8 bits");
    (1..=2).find(|&k| symbols <= 1 << (k * step_bits))
}

/// Walks [`LANES`] words (W ≤ 32 bits) through `steps` whole steps of the batch `table`:
/// returns each lane's accumulator (the output and pending translations in its top 32 bits) and
/// its symbol after the steps. The steps all lanes share are walked once (`memo`).
#[inline(always)]
pub(super) fn walk_portable<const SB: u32>(
    table: &[u64],
    x: [u64; LANES],
    w: u32,
    steps: u32,
    root: u32,
    memo: &mut PrefixMemo,
) -> ([u64; LANES], [usize; LANES]) {
    // Words left-aligned: step i reads bits SB·i.. SB·(i + 1) from the top.
    let bits = x.map(|v| v << (64 - w));
    let diff = bits.iter().fold(0, |o, &b| o | (b ^ bits[0]));
    let start = memo.start::<SB>(table, bits[0], diff, steps, root);
    let mut lanes = PortableLanes {
        bits,
        s: [start.symbol as usize; LANES],
        acc: [start.acc; LANES],
    };
    if start.steps == 0 && steps == 32 / SB {
        // Constant bounds for the most common walk (32-bit words, nothing shared) unroll the
        // steps into immediate shifts.
        lanes.walk::<SB>(table, 0, 32 / SB);
    } else {
        lanes.walk::<SB>(table, start.steps, steps);
    }
    (lanes.acc, lanes.s)
}

/// The portable kernel's lanes: the words' bits (top-aligned, never written, so they need no
/// register of their own: eight lanes' symbols and accumulators already take more than the
/// free ones), symbol, accumulator.
struct PortableLanes {
    bits: [u64; LANES],
    s: [usize; LANES],
    acc: [u64; LANES],
}

impl PortableLanes {
    /// Steps `from..to` of the walk (numbered from the root), every lane advanced one step
    /// before the next step.
    #[inline(always)]
    fn walk<const SB: u32>(&mut self, table: &[u64], from: u32, to: u32) {
        for i in from..to {
            let shift = SB * i;
            let read = 64 - SB * (i + 1);
            for l in 0..LANES {
                let v = ((self.bits[l] >> read) & ((1 << SB) - 1)) as usize;
                let e = table[(self.s[l] << SB) | v];
                self.acc[l] ^= e >> shift;
                self.s[l] = (e & 0xFFFF) as usize;
            }
        }
    }
}

/// Which code walks the lanes of the batch path. Every kernel gives the same words (tested);
/// they differ in speed only.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BatchKernel {
    /// Plain Rust, eight chains interleaved (every platform).
    Portable,
    /// AVX-512F gathers of the 64-bit table entries: one instruction loads a step's entries
    /// for eight lanes (x86-64 CPUs that report AVX-512F at run time).
    Avx512,
    /// AVX-512F with sixteen 32-bit lanes per register: step 0 (and step 1 where the alphabet
    /// needs two steps' bits) gathers the 64-bit table, the later steps a narrow table of
    /// 32-bit entries (half the bytes; the layout is argued beside `narrow` in
    /// `engine/batch.rs`). Where the alphabet does not fit in two steps' bits there is no
    /// narrow table and this kernel runs [`BatchKernel::Avx512`].
    Avx512Narrow,
}

impl BatchKernel {
    /// The fastest kernel this CPU runs.
    pub fn detect() -> BatchKernel {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx512f") {
            return BatchKernel::Avx512Narrow;
        }
        BatchKernel::Portable
    }

    /// The kernels this CPU runs (the portable one always).
    pub fn available() -> Vec<BatchKernel> {
        let mut out = vec![BatchKernel::Portable];
        if BatchKernel::detect() == BatchKernel::Avx512Narrow {
            out.extend([BatchKernel::Avx512, BatchKernel::Avx512Narrow]);
        }
        out
    }
}

impl ArtOwen {
    /// The kernel that walks this scrambler's batch path.
    pub fn kernel(&self) -> BatchKernel {
        self.kernel
    }

    /// Bits per step of the batch path's table for words of at most 32 bits (0 when the
    /// alphabet is too large for it and the scalar step tables serve every width).
    pub fn batch_step_bits(&self) -> u32 {
        self.q() * self.batch_digits
    }

    /// Whether this scrambler has the narrow table that [`BatchKernel::Avx512Narrow`] walks
    /// (its alphabet fits in one batch step's bits); builds the batch tables if needed.
    pub fn has_narrow_table(&self) -> bool {
        self.batch_tables().is_some_and(|t| !t.narrow.is_empty())
    }

    /// Whether the batch tables have been built: after [`BATCH_TABLES_AFTER_WORDS`] words
    /// through the batch path, or by [`ArtOwen::with_kernel`], `has_narrow_table` or
    /// `table_bytes`. Outputs are the same either way.
    pub fn batch_tables_built(&self) -> bool {
        self.batch.get().is_some()
    }

    /// The batch tables, built on first use; `None` when the alphabet is too large for them.
    pub(super) fn batch_tables(&self) -> Option<&BatchTables> {
        (self.batch_digits > 0).then(|| {
            self.batch
                .get_or_init(|| BatchTables::build(self, self.batch_digits))
        })
    }

    /// The batch tables if they exist or `more` words bring the words seen to
    /// [`BATCH_TABLES_AFTER_WORDS`].
    fn batch_tables_for(&self, more: usize) -> Option<&BatchTables> {
        if let Some(t) = self.batch.get() {
            return Some(t);
        }
        if self.batch_words.add(more) >= BATCH_TABLES_AFTER_WORDS {
            self.batch_tables()
        } else {
            None
        }
    }

    /// This scrambler with its batch path walked by `kernel` (for tests and benchmarks; the
    /// default is [`BatchKernel::detect`]), its batch and step tables built so that every
    /// batch call walks that kernel. Returns `None` when this CPU cannot run it.
    pub fn with_kernel(&self, kernel: BatchKernel) -> Option<ArtOwen> {
        BatchKernel::available().contains(&kernel).then(|| {
            self.batch_tables();
            self.step_tables();
            ArtOwen {
                kernel,
                ..self.clone()
            }
        })
    }

    /// Forward scramble of `words` in place for dimension `dim`, equal to
    /// [`gartowen_core::Scrambler::scramble`] on each word.
    pub(super) fn forward_batch<T: Word>(&self, words: &mut [T], width: Width, key: DimKey) {
        debug_assert!(T::WIDE || width == Width::W32, "u32 words are 32 bits");
        // The step width as a constant, so the step's shifts are immediates.
        let packed = if width.bits() <= 32 {
            self.batch_tables_for(words.len())
        } else {
            None
        };
        if let Some(t) = packed {
            match self.batch_step_bits() {
                1 => self.batch_lanes::<1, true, T>(t, words, width, key),
                2 => self.batch_lanes::<2, true, T>(t, words, width, key),
                3 => self.batch_lanes::<3, true, T>(t, words, width, key),
                4 => self.batch_lanes::<4, true, T>(t, words, width, key),
                5 => self.batch_lanes::<5, true, T>(t, words, width, key),
                6 => self.batch_lanes::<6, true, T>(t, words, width, key),
                7 => self.batch_lanes::<7, true, T>(t, words, width, key),
                8 => self.batch_lanes::<8, true, T>(t, words, width, key),
                _ => unreachable!("batch steps are 1 to 8 bits"),
            }
        } else if self.step_tables_for(words.len()).is_none() {
            // Too few words yet to pay for the step tables: the digit-by-digit loop.
            let (root, a, d) = ArtOwen::shifts_at(key, width);
            for x in words.iter_mut() {
                *x = T::put(self.finish_digits(x.get() ^ a, width, 0, root, 0, 0) ^ d);
            }
        } else {
            match self.q() * self.step_digits {
                3 => self.batch_lanes::<3, false, T>(&NO_BATCH_TABLES, words, width, key),
                4 => self.batch_lanes::<4, false, T>(&NO_BATCH_TABLES, words, width, key),
                5 => self.batch_lanes::<5, false, T>(&NO_BATCH_TABLES, words, width, key),
                6 => self.batch_lanes::<6, false, T>(&NO_BATCH_TABLES, words, width, key),
                7 => self.batch_lanes::<7, false, T>(&NO_BATCH_TABLES, words, width, key),
                8 => self.batch_lanes::<8, false, T>(&NO_BATCH_TABLES, words, width, key),
                _ => unreachable!("scalar steps are 3 to 8 bits"),
            }
        }
    }

    /// [`LANES`] words at a time through the batch tables `t` (PACKED) or the scalar step tables.
    fn batch_lanes<const SB: u32, const PACKED: bool, T: Word>(
        &self,
        t: &BatchTables,
        words: &mut [T],
        width: Width,
        key: DimKey,
    ) {
        let (root, a, d) = ArtOwen::shifts_at(key, width);
        let w = width.bits();
        let steps = w / SB;
        let mut memo = PrefixMemo::new();
        #[cfg(target_arch = "x86_64")]
        let words = if PACKED && self.kernel != BatchKernel::Portable {
            use super::GROUPS;
            let mut blocks = words.chunks_exact_mut(GROUPS * LANES);
            for block in &mut blocks {
                self.gather_block::<SB, T>(t, block, root, a, d, w, &mut memo);
            }
            let rest = blocks.into_remainder();
            if rest.len() >= PADDED_BLOCK_MIN {
                // A zero-padded block: its GROUPS · LANES words cost about what
                // PADDED_BLOCK_MIN words cost in the portable lanes (3 ns against 9 ns a word).
                let mut block = [T::default(); GROUPS * LANES];
                block[..rest.len()].copy_from_slice(rest);
                self.gather_block::<SB, T>(t, &mut block, root, a, d, w, &mut memo);
                rest.copy_from_slice(&block[..rest.len()]);
                &mut []
            } else {
                rest
            }
        } else {
            words
        };
        let mut chunks = words.chunks_exact_mut(LANES);
        for chunk in &mut chunks {
            let chunk: &mut [T; LANES] = chunk.try_into().expect("chunks_exact");
            let x: [u64; LANES] = std::array::from_fn(|l| chunk[l].get() ^ a);
            let out = if PACKED {
                let (acc, s) = walk_portable::<SB>(&t.table, x, w, steps, root, &mut memo);
                self.finish_packed(&x, w, steps * SB, acc, s)
            } else {
                self.lanes_wide::<SB>(x, w, steps, root)
            };
            for l in 0..LANES {
                chunk[l] = T::put(out[l] ^ d);
            }
        }
        for w in chunks.into_remainder() {
            *w = T::put(self.forward_fast(w.get() ^ a, width, root) ^ d);
        }
    }

    /// One block of [`super::GROUPS`] · [`LANES`] words (W ≤ 32) through this
    /// scrambler's gather kernel, scrambled in place.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn gather_block<const SB: u32, T: Word>(
        &self,
        t: &BatchTables,
        block: &mut [T],
        root: u32,
        a: u64,
        d: u64,
        w: u32,
        memo: &mut PrefixMemo,
    ) {
        use super::simd::{walk_avx512, walk_avx512_narrow};
        let steps = w / SB;
        let table = &t.table;
        // SAFETY: the gather kernels are chosen only where the CPU reported AVX-512F, and
        // `BatchTables::build` checked the table invariants the kernels need.
        let walked = unsafe {
            if self.kernel == BatchKernel::Avx512 || t.narrow.is_empty() {
                let codes = &self.codes;
                walk_avx512::<SB, T>(table, codes, self.q(), block, a, d, w, steps, root, memo)
            } else {
                walk_avx512_narrow::<SB, T>(
                    table,
                    &t.narrow,
                    t.wide_steps,
                    &t.codes_top,
                    self.q(),
                    block,
                    a,
                    d,
                    w,
                    steps,
                    root,
                    memo,
                )
            }
        };
        let Some(walked) = walked else { return };
        for (g, (acc, s)) in walked.into_iter().enumerate() {
            let lanes = &mut block[g * LANES..(g + 1) * LANES];
            let x: [u64; LANES] = std::array::from_fn(|l| lanes[l].get() ^ a);
            let out = self.finish_packed(&x, w, steps * SB, acc, s);
            for l in 0..LANES {
                lanes[l] = T::put(out[l] ^ d);
            }
        }
    }

    /// Finishes [`LANES`] words (W ≤ 32) after `consumed` bits of whole steps: the output
    /// bits and pending translations are in the accumulators' top 32 bits.
    #[inline(always)]
    fn finish_packed(
        &self,
        x: &[u64; LANES],
        w: u32,
        consumed: u32,
        acc: [u64; LANES],
        s: [usize; LANES],
    ) -> [u64; LANES] {
        // The two common cases inline (a call per lane cost a third of the portable walk's
        // time): no digit left, or only the partial tail digit (translation only).
        if consumed == w {
            return acc.map(|a| a >> (64 - consumed));
        }
        let r = w - consumed;
        if r < self.q() {
            return std::array::from_fn(|l| {
                let out = if consumed == 0 {
                    0
                } else {
                    acc[l] >> (64 - consumed)
                };
                let g = (acc[l] & 0xFFFF_FFFF_0000_0000) << consumed;
                self.tail_digit(x[l], r, s[l] as u32, g, out)
            });
        }
        std::array::from_fn(|l| {
            let out = if consumed == 0 {
                0
            } else {
                acc[l] >> (64 - consumed)
            };
            if consumed == w {
                out
            } else {
                // Pending translations: the accumulator's exact top 32 bits, moved up.
                let g = (acc[l] & 0xFFFF_FFFF_0000_0000) << consumed;
                let width = Width::new(w).expect("a valid width");
                self.finish_digits(x[l], width, consumed, s[l] as u32, g, out)
            }
        })
    }

    /// [`LANES`] words of any width through the scalar path's step tables (whole 64-bit
    /// contributions), in the contribution form of the module docs: the accumulator's top
    /// `consumed` bits are the output, and the rest, moved up, the pending translations.
    #[inline(always)]
    fn lanes_wide<const SB: u32>(
        &self,
        x: [u64; LANES],
        w: u32,
        steps: u32,
        root: u32,
    ) -> [u64; LANES] {
        // Top-aligned words whose digits each step reads in place (see `PortableLanes`).
        let bits = x.map(|v| v << (64 - w));
        let tables = self.step_tables();
        let (contribution, next) = (&tables.contribution[..], &tables.next[..]);
        let mut s = [root; LANES];
        let mut acc = [0u64; LANES];
        for i in 0..steps {
            let (read, shift) = (64 - SB * (i + 1), SB * i);
            for l in 0..LANES {
                let v = ((bits[l] >> read) & ((1 << SB) - 1)) as usize;
                let idx = ((s[l] as usize) << SB) | v;
                acc[l] ^= contribution[idx] >> shift;
                s[l] = next[idx];
            }
        }
        let consumed = steps * SB;
        let width = Width::new(w).expect("a valid width");
        std::array::from_fn(|l| {
            let out = if consumed == 0 {
                0
            } else {
                acc[l] >> (64 - consumed)
            };
            if consumed == w {
                out
            } else {
                self.finish_digits(x[l], width, consumed, s[l], acc[l] << consumed, out)
            }
        })
    }
}
