//! The scalar path's step tables, built when an instance has scrambled enough words to pay
//! for them.
//!
//! A step table holds, for every symbol and every value of `step_digits` input digits, the
//! loop's effect with the ancestors' translations left out (they are XOR-ed in at run time).
//! For 256 symbols it takes 30–700 µs to build (65,536 entries in base 256), while most
//! instances of a statistical battery scramble a few hundred words: the digit-by-digit loop
//! serves those, with the same outputs, and the tables are built after
//! [`STEP_TABLES_AFTER_WORDS`] words.

use super::{ArtOwen, Step};

/// Words an instance scrambles through the digit-by-digit loop before it builds its step
/// tables (in base 2 a word costs about 60 ns more by the loop, so the tables of 256 symbols
/// pay for themselves after about two thousand words). Calls of at least this many words
/// build them at once.
pub const STEP_TABLES_AFTER_WORDS: u64 = 1 << 12;

/// The scalar step tables, split by field so the serial symbol chain reads only the compact
/// `next` array: index s·2^(q·step_digits) + v.
#[derive(Debug, Clone)]
pub(super) struct StepTables {
    /// The symbol after each step.
    pub(super) next: Vec<u32>,
    /// Each step's [`Step::contribution`], at the same index.
    pub(super) contribution: Vec<u64>,
}

impl StepTables {
    /// Bytes held.
    pub(super) fn bytes(&self) -> usize {
        self.next.len() * 4 + self.contribution.len() * 8
    }
}

impl ArtOwen {
    /// Whether the step tables have been built: after [`STEP_TABLES_AFTER_WORDS`] words, or by
    /// [`ArtOwen::with_step_tables`], [`ArtOwen::with_kernel`] or `table_bytes`. Outputs are
    /// the same either way.
    pub fn step_tables_built(&self) -> bool {
        self.steps.get().is_some()
    }

    /// This scrambler with its step tables built now (a renderer that wants every call to cost
    /// the same, and tests of the table path).
    pub fn with_step_tables(self) -> ArtOwen {
        self.step_tables();
        self
    }

    /// The step tables, built on first use.
    pub(super) fn step_tables(&self) -> &StepTables {
        self.steps.get_or_init(|| self.build_step_tables())
    }

    /// The step tables if they exist or `more` words bring the words seen to
    /// [`STEP_TABLES_AFTER_WORDS`]; `None` means the digit-by-digit loop.
    #[inline]
    pub(super) fn step_tables_for(&self, more: usize) -> Option<&StepTables> {
        if let Some(t) = self.steps.get() {
            return Some(t);
        }
        self.count_towards_steps(more)
    }

    #[cold]
    #[inline(never)]
    fn count_towards_steps(&self, more: usize) -> Option<&StepTables> {
        (self.step_words.add(more) >= STEP_TABLES_AFTER_WORDS).then(|| self.step_tables())
    }

    fn build_step_tables(&self) -> StepTables {
        if self.step_digits == 1 {
            return self.build_single_digit_steps();
        }
        let steps = self.build_steps(self.step_digits);
        let step_bits = self.step_digits * self.q();
        StepTables {
            next: steps.iter().map(|e| e.next).collect(),
            contribution: steps.iter().map(|e| e.contribution(step_bits)).collect(),
        }
    }

    /// The steps of `m` digits from every symbol: the loop's effect with ancestors'
    /// translations left out (also the batch tables' source).
    pub(super) fn build_steps(&self, m: u32) -> Vec<Step> {
        let q = self.q();
        let bits = q * m;
        let mut out = Vec::with_capacity((self.grammar.symbols() as usize) << bits);
        for s0 in 0..self.grammar.symbols() {
            for v in 0..1u32 << bits {
                let (mut s, mut g, mut local) = (s0, 0u64, 0u32);
                for i in 0..m {
                    let d = (v >> (bits - q * (i + 1))) & ((1 << q) - 1);
                    g ^= self.codes[s as usize] >> (q * i);
                    let f = ((g >> (64 - q * (i + 1))) & ((1 << q) - 1)) as u32;
                    local = (local << q) | (self.psi_apply(s, d) ^ f);
                    s = self.child(s, d);
                }
                out.push(Step {
                    carry: g,
                    next: s,
                    local,
                });
            }
        }
        out
    }

    /// The split step tables for steps of one digit (q ≥ 5), written directly: the entry of
    /// (s, d) is [`ArtOwen::build_steps`]'s for m = 1 — carry T[s], next child(s, d), local
    /// ψ_s(d) ⊕ T[s]'s top digit — without the intermediate list.
    fn build_single_digit_steps(&self) -> StepTables {
        let q = self.q();
        let n = (self.grammar.symbols() as usize) << q;
        let (mut next, mut contribution) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for s in 0..self.grammar.symbols() {
            let code = self.codes[s as usize];
            let top = (code >> (64 - q)) as u32;
            for d in 0..1u32 << q {
                next.push(self.child(s, d));
                let step = Step {
                    carry: code,
                    next: 0,
                    local: self.psi_apply(s, d) ^ top,
                };
                contribution.push(step.contribution(q));
            }
        }
        StepTables { next, contribution }
    }
}
