//! ART's pair law as built: how often two inputs that first differ at digit k reach one symbol
//! below it, computed exactly from the grammar.
//!
//! The pending translations an ART node hands to its children depend on the node alone, so
//! two children of one node with the same symbol are the roots of the same map
//! (`proofs/ArtPair.v`, `art_shared_child`): inputs first differing at digit k by δ = a ⊕ a'
//! then get equal output digits below k whenever their digits below k are equal. Owen's
//! independent nodes give that with probability b^-(digits below k). Over a uniform root
//! symbol and uniform input digits above k (the dimension's uniform input shift makes them
//! so), the probability of a shared child is
//! ρ(k, δ) = Σ_s μ_k(s) · #{c : child(s, c) = child(s, c ⊕ δ)} / b,
//! with μ_k the law of the symbol at depth k: μ_0 uniform, μ_{j+1}(s') = Σ_s μ_j(s) ·
//! #{d : child(s, d) = s'} / b. The counts are kept as integers over |Σ|·b^(k+1).

use crate::Grammar;

/// ρ(k, δ) as an exact fraction: `shared` of `total` equally likely (root, digits) cases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SharedChild {
    /// Cases (root symbol, digits 0..k−1, digit c at k) whose children for c and c ⊕ δ
    /// share a symbol.
    pub shared: u128,
    /// All cases: |Σ|·b^(k+1).
    pub total: u128,
}

impl SharedChild {
    /// The probability as a float.
    pub fn probability(&self) -> f64 {
        self.shared as f64 / self.total as f64
    }
}

/// Why ρ cannot be computed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PairLawError {
    /// δ is 0 or not below b.
    BadDelta {
        /// The δ asked for.
        delta: u32,
        /// The base b = 2^q.
        base: u32,
    },
    /// |Σ|·b^(k+1) does not fit 128 bits.
    TooDeep {
        /// The depth asked for.
        depth: u32,
    },
}

impl std::fmt::Display for PairLawError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PairLawError::BadDelta { delta, base } => {
                write!(f, "δ = {delta}: the digits differ by δ in 1..{base}")
            }
            PairLawError::TooDeep { depth } => {
                write!(f, "depth {depth}: |Σ|·b^(k+1) exceeds 128 bits")
            }
        }
    }
}

impl std::error::Error for PairLawError {}

/// The number of (root, digits 0..k−1) cases that reach each symbol at depth k.
pub fn symbol_counts(grammar: &Grammar, depth: u32) -> Result<Vec<u128>, PairLawError> {
    let (n, b) = (grammar.symbols() as usize, 1u32 << grammar.q());
    let mut counts = vec![1u128; n];
    for _ in 0..depth {
        let mut next = vec![0u128; n];
        for (s, &c) in counts.iter().enumerate() {
            if c == 0 {
                continue;
            }
            for d in 0..b {
                let t = grammar.child(s as u32, d) as usize;
                next[t] = next[t]
                    .checked_add(c)
                    .ok_or(PairLawError::TooDeep { depth })?;
            }
        }
        counts = next;
    }
    Ok(counts)
}

/// ρ(k, δ): the exact probability that inputs first differing at digit `depth` by `delta`
/// reach one symbol below it (see the module documentation).
pub fn shared_child(
    grammar: &Grammar,
    depth: u32,
    delta: u32,
) -> Result<SharedChild, PairLawError> {
    let b = 1u32 << grammar.q();
    if delta == 0 || delta >= b {
        return Err(PairLawError::BadDelta { delta, base: b });
    }
    let counts = symbol_counts(grammar, depth)?;
    let too_deep = PairLawError::TooDeep { depth };
    let mut shared = 0u128;
    for (s, &c) in counts.iter().enumerate() {
        let pairs = (0..b)
            .filter(|&d| grammar.child(s as u32, d) == grammar.child(s as u32, d ^ delta))
            .count() as u128;
        shared = c
            .checked_mul(pairs)
            .and_then(|x| shared.checked_add(x))
            .ok_or(too_deep.clone())?;
    }
    let total = (u128::from(b))
        .checked_pow(depth + 1)
        .and_then(|x| x.checked_mul(grammar.symbols() as u128))
        .ok_or(too_deep)?;
    Ok(SharedChild { shared, total })
}
