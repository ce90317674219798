//! What the batch kernels share besides the tables: the word types they scramble in place
//! and the steps a group of lanes shares (walked once per group).

/// A word type the batch path scrambles in place: `u64` (any width) or `u32` (32-bit words,
/// walked without widening them first).
pub(super) trait Word: Copy + Default {
    /// Whether the word is 64 bits (else 32); the gather kernels load and store by it.
    const WIDE: bool;
    /// The word as 64 bits.
    fn get(self) -> u64;
    /// The low bits of `v` as a word.
    fn put(v: u64) -> Self;
}

impl Word for u64 {
    const WIDE: bool = true;
    #[inline(always)]
    fn get(self) -> u64 {
        self
    }
    #[inline(always)]
    fn put(v: u64) -> u64 {
        v
    }
}

impl Word for u32 {
    const WIDE: bool = false;
    #[inline(always)]
    fn get(self) -> u64 {
        u64::from(self)
    }
    #[inline(always)]
    fn put(v: u64) -> u32 {
        v as u32
    }
}

/// Where a group of lanes begins its walk: the whole steps that all its words share (taken once
/// for the group) and the accumulator and symbol after them.
///
/// **Why sharing pays.** Words with the same leading k·SB bits (after the input shift, which is
/// the same for every word of a call) read the same k table entries, so the walk of one word
/// gives every lane's state after k steps. Consecutive words, as the every-word sweep and
/// index scrambling feed them, share all but their last step within a group of 16; one table
/// read per word replaces four. Words that share nothing (k = 0) walk as before.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct GroupStart {
    /// Whole steps already taken (0 to the word's whole steps).
    pub(super) steps: u32,
    /// The accumulator after them (as the walks keep it: top-aligned contributions).
    pub(super) acc: u64,
    /// The symbol reached.
    pub(super) symbol: u32,
}

impl GroupStart {
    /// No step taken: the walk begins at `root`.
    pub(super) fn at(root: u32) -> GroupStart {
        GroupStart {
            steps: 0,
            acc: 0,
            symbol: root,
        }
    }
}

/// The last shared prefix walked in a call, so runs of groups with one prefix walk it once.
#[derive(Debug)]
pub(super) struct PrefixMemo {
    /// (steps << 32) | the prefix's bits; never a real key before the first walk.
    key: u64,
    acc: u64,
    symbol: u32,
}

impl PrefixMemo {
    /// An empty memo (for one call: one root, input shift and width).
    pub(super) fn new() -> PrefixMemo {
        PrefixMemo {
            key: u64::MAX,
            acc: 0,
            symbol: 0,
        }
    }

    /// The start of a group of lanes whose words' left-aligned bits (the input shift applied,
    /// the word's first bit at bit 63) are `bits` in its first lane and differ from them in
    /// the bits set in `diff`: the whole steps they all share (at most `steps`), walked from
    /// `root` through `table` (memoized).
    #[inline(always)]
    pub(super) fn start<const SB: u32>(
        &mut self,
        table: &[u64],
        bits: u64,
        diff: u64,
        steps: u32,
        root: u32,
    ) -> GroupStart {
        let shared = (diff.leading_zeros() / SB).min(steps);
        if shared == 0 {
            return GroupStart::at(root);
        }
        let key = (u64::from(shared) << 32) | (bits >> (64 - shared * SB));
        if key != self.key {
            let (mut acc, mut symbol) = (0u64, root as usize);
            for i in 0..shared {
                let v = ((bits << (SB * i)) >> (64 - SB)) as usize;
                let e = table[(symbol << SB) | v];
                acc ^= e >> (SB * i);
                symbol = (e & 0xFFFF) as usize;
            }
            *self = PrefixMemo {
                key,
                acc,
                symbol: symbol as u32,
            };
        }
        GroupStart {
            steps: shared,
            acc: self.acc,
            symbol: self.symbol,
        }
    }
}
