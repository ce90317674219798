//! The ART grammar (`docs/design.md` §3.2): the alphabet Σ_L of distinct length-L factors of the
//! Thue–Morse word t (t(n) = popcount(n) mod 2) and, for branching 2^q, the child rule
//! child(w, d) = the length-L factor of σ^q(w) at offset (2^q − 1)(L − 1) + d.
//!
//! A symbol is represented during construction by the position of its first occurrence in t.
//! Since σ(t) = t maps the factor at position i to the factor at 2i of twice the length,
//! σ^q(w) for w at position i is t[2^q·i ..], so child(w, d) is the factor at position
//! 2^q·i + (2^q − 1)(L − 1) + d. Factors are read from t in 64-bit words — word k of t is
//! t[0..64] complemented when popcount(k) is odd — hashed, and compared exactly on a hash hit.
//! Only the child tables are kept.

use std::collections::HashMap;

/// The first 64 bits of Thue–Morse, bit j = t(j).
const TM64: u64 = {
    let mut w = 0u64;
    let mut j = 0;
    while j < 64 {
        w |= ((j as u64).count_ones() as u64 & 1) << j;
        j += 1;
    }
    w
};

/// Bits t[64k .. 64k+64] (bit j = t(64k + j)): popcount(64k + j) = popcount(k) + popcount(j).
#[inline]
fn tm_word(k: u64) -> u64 {
    if k.count_ones() & 1 == 1 {
        !TM64
    } else {
        TM64
    }
}

/// Bits t[p .. p+64] (bit j = t(p + j)), for any p.
#[inline]
fn tm_bits(p: u64) -> u64 {
    let (k, r) = (p / 64, p % 64);
    if r == 0 {
        tm_word(k)
    } else {
        (tm_word(k) >> r) | (tm_word(k + 1) << (64 - r))
    }
}

/// The length-L factor at position p, as 64-bit chunks (the last one masked).
fn factor_chunks(p: u64, len: u64) -> impl Iterator<Item = u64> {
    (0..len.div_ceil(64)).map(move |c| {
        let bits = tm_bits(p + 64 * c);
        let left = len - 64 * c;
        if left >= 64 {
            bits
        } else {
            bits & ((1u64 << left) - 1)
        }
    })
}

fn factor_hash(p: u64, len: u64) -> u64 {
    factor_chunks(p, len).fold(len, |h, c| gartowen_core::mix64(h ^ c).wrapping_add(c))
}

fn same_factor(p: u64, r: u64, len: u64) -> bool {
    factor_chunks(p, len).eq(factor_chunks(r, len))
}

/// Errors from building a grammar.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GrammarError {
    /// L = 0 or q outside 1..=8.
    BadParameters(String),
    /// A child factor is not in the alphabet (would contradict closure).
    NotClosed {
        /// The parent symbol.
        symbol: u32,
        /// The child digit whose factor is missing.
        digit: u32,
    },
    /// No L gives exactly this many symbols.
    NoSuchAlphabetSize {
        /// Symbols asked for.
        requested: usize,
        /// The nearest size below that exists.
        below: usize,
        /// The nearest size above that exists.
        above: usize,
    },
}

impl std::fmt::Display for GrammarError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GrammarError::BadParameters(s) => write!(f, "{s}"),
            GrammarError::NotClosed { symbol, digit } => {
                write!(f, "child of symbol {symbol} for digit {digit} is outside the alphabet")
            }
            GrammarError::NoSuchAlphabetSize { requested, below, above } => write!(
                f,
                "no Thue–Morse factor length gives {requested} symbols; nearest sizes are {below} and {above}"
            ),
        }
    }
}

impl std::error::Error for GrammarError {}

/// The alphabet Σ_L, indexed by first occurrence in t, with factor positions; construction only.
struct Alphabet {
    len: u64,
    positions: Vec<u64>,
    index: HashMap<u64, Vec<u32>>,
}

impl Alphabet {
    /// Every length-L factor, found by scanning t[0 .. 32L + 64]: Thue–Morse is linearly
    /// recurrent, so every factor occurs in every window of length well under 32L.
    fn new(len: u64) -> Self {
        let mut a = Alphabet {
            len,
            positions: Vec::new(),
            index: HashMap::new(),
        };
        for p in 0..32 * len + 64 {
            if a.find(p).is_none() {
                let s = a.positions.len() as u32;
                a.positions.push(p);
                a.index.entry(factor_hash(p, len)).or_default().push(s);
            }
        }
        a
    }

    /// The symbol whose factor equals the factor at position p.
    fn find(&self, p: u64) -> Option<u32> {
        self.index
            .get(&factor_hash(p, self.len))?
            .iter()
            .copied()
            .find(|&s| same_factor(self.positions[s as usize], p, self.len))
    }
}

/// Number of distinct length-L factors of Thue–Morse, p(L) (OEIS A005942).
pub fn alphabet_size(len: usize) -> usize {
    if len == 0 {
        return 1;
    }
    Alphabet::new(len as u64).positions.len()
}

/// p(L) by Brlek's closed form: p(0..=2) = 1, 2, 4; for L ≥ 3 write L = 2^r + m + 1 with
/// 0 < m ≤ 2^r, then p(L) = 3·2^r + 4m when 2m ≤ 2^r, else 4·2^r + 2m.
pub fn alphabet_size_formula(len: u64) -> u64 {
    match len {
        0 => 1,
        1 => 2,
        2 => 4,
        _ => {
            let r = 63 - (len - 2).leading_zeros() as u64; // 2^r < len − 1 ≤ 2^(r+1)
            let (pow, m) = (1u64 << r, len - 1 - (1u64 << r));
            if 2 * m <= pow {
                3 * pow + 4 * m
            } else {
                4 * pow + 2 * m
            }
        }
    }
}

/// The smallest L whose alphabet has exactly `symbols` symbols (from the closed form).
pub fn length_for_size(symbols: usize) -> Result<usize, GrammarError> {
    let target = symbols as u64;
    let mut below = 1;
    let mut len = 0u64;
    loop {
        let p = alphabet_size_formula(len);
        if p == target {
            return Ok(len as usize);
        }
        if p > target {
            return Err(GrammarError::NoSuchAlphabetSize {
                requested: symbols,
                below: below as usize,
                above: p as usize,
            });
        }
        below = p;
        len += 1;
    }
}

/// Grammars by (L, q), shared across scramblers.
type GrammarCache = HashMap<(usize, u32), std::sync::Arc<Grammar>>;

/// Child tables of the ART grammar for branching 2^q: `child(s, d)` for every symbol and digit.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Grammar {
    len: usize,
    q: u32,
    symbols: u32,
    /// children[s·2^q + d]
    children: Vec<u32>,
}

impl Grammar {
    /// The grammar of length-`len` factors with branching 2^q.
    pub fn new(len: usize, q: u32) -> Result<Self, GrammarError> {
        if len == 0 || !(1..=8).contains(&q) {
            return Err(GrammarError::BadParameters(format!(
                "need L ≥ 1 and q in 1..=8 (L = {len}, q = {q})"
            )));
        }
        let a = Alphabet::new(len as u64);
        let b = 1u64 << q;
        let offset = (b - 1) * (len as u64 - 1);
        let mut children = Vec::with_capacity(a.positions.len() * b as usize);
        for (s, &p) in a.positions.iter().enumerate() {
            for d in 0..b {
                let child = a.find(b * p + offset + d).ok_or(GrammarError::NotClosed {
                    symbol: s as u32,
                    digit: d as u32,
                })?;
                children.push(child);
            }
        }
        Ok(Grammar {
            len,
            q,
            symbols: a.positions.len() as u32,
            children,
        })
    }

    /// This grammar with every child replaced by its parent (the `NeverDescends` mutant).
    #[cfg(feature = "mutants")]
    pub(crate) fn never_descending(&self) -> Grammar {
        let b = 1usize << self.q;
        let mut g = self.clone();
        for (i, c) in g.children.iter_mut().enumerate() {
            *c = (i / b) as u32;
        }
        g
    }

    /// The grammar for (L, q) from a process-wide cache: grammars do not depend on seeds, so
    /// scramblers built for many seeds share one.
    pub fn shared(len: usize, q: u32) -> Result<std::sync::Arc<Grammar>, GrammarError> {
        use std::sync::{Arc, Mutex, OnceLock};
        static CACHE: OnceLock<Mutex<GrammarCache>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
        if let Some(g) = cache.lock().expect("cache lock").get(&(len, q)) {
            return Ok(g.clone());
        }
        let g = Arc::new(Grammar::new(len, q)?);
        cache
            .lock()
            .expect("cache lock")
            .insert((len, q), g.clone());
        Ok(g)
    }

    /// The factor length L.
    pub fn factor_len(&self) -> usize {
        self.len
    }

    /// Branching exponent q (2^q children per symbol).
    pub fn q(&self) -> u32 {
        self.q
    }

    /// |Σ_L|.
    pub fn symbols(&self) -> u32 {
        self.symbols
    }

    /// The child of symbol `s` for digit `d`.
    #[inline(always)]
    pub fn child(&self, s: u32, d: u32) -> u32 {
        self.children[((s as usize) << self.q) | d as usize]
    }

    /// Bytes of the child table.
    pub fn table_bytes(&self) -> usize {
        self.children.len() * 4
    }
}
