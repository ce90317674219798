//! One chunk's scan: the consecutive-pair nestedness test (or, in base 2, the exact-sharing
//! test), injectivity by blocks and node digits, and the node laws of the depths below the
//! chunk's.

use super::{SweepFailure, SweepPlan};

/// The cell of a node permutation given by its digit images, as the inspector's `NodeLaw`
/// numbers them: the Lehmer rank for b ≤ 4, else the pair (π(0), π(1)) as π(0)·(b−1) + rank of
/// π(1) among the other digits. `None` when π(0) = π(1) (not a permutation).
pub fn node_cell(images: &[u8]) -> Option<u32> {
    let b = images.len() as u32;
    if b <= 4 {
        let mut rank = 0u32;
        for i in 0..images.len() {
            let smaller_later = images[i + 1..].iter().filter(|&&v| v < images[i]).count() as u32;
            rank = rank * (b - i as u32) + smaller_later;
        }
        return Some(rank);
    }
    let (a, c) = (images[0] as u32, images[1] as u32);
    if a == c {
        return None;
    }
    Some(a * (b - 1) + if c > a { c - 1 } else { c })
}

/// Cells of the node law in base `b`: b! for b ≤ 4, else b(b−1).
pub fn node_cells(b: u32) -> usize {
    if b <= 4 {
        (1..=b as usize).product()
    } else {
        (b * (b - 1)) as usize
    }
}

/// Most low bits of a block, the subtree whose outputs one bitmap holds (see [`ChunkScan`]),
/// unless a whole digit has more: 2^5 bits, held in a register by the scalar scan and in one
/// 32-bit lane by the sixteen-word scan (`group_scan`).
const BLOCK_BITS: u32 = 5;

/// The depth d′ ≥ d of the blocks whose outputs one bitmap holds: the shallowest whose
/// subtrees have at most 2^max([`BLOCK_BITS`], q) words (whole digits always reach it: after
/// them fewer than q bits are left).
pub(super) fn block_digits(plan: &SweepPlan) -> u32 {
    let (w, q) = (plan.width().bits(), plan.base().q());
    let mut k = plan.chunk_digits();
    while w - q * k > BLOCK_BITS.max(q) {
        k += 1;
    }
    k
}

/// Low bits of a block's words, W − q·d′.
pub(super) fn block_low_bits(plan: &SweepPlan) -> u32 {
    plan.width().bits() - plan.base().q() * block_digits(plan)
}

/// The scan's running state inside one chunk.
///
/// **Injectivity by blocks.** The chunk (depth d) is cut into the blocks of depth d′ ≥ d; the
/// bitmap holds one block's outputs (their low W − q·d′ bits) and is cleared at each block's
/// first word. With the chunk nested (the consecutive test), f is injective on it iff it is
/// injective on every block and every node of depths d..d′ sends its children to distinct
/// digits: then blocks have distinct image prefixes, and within a block the bitmap decides.
/// (Only if: two children sent to one digit map, each injectively and so onto, into the same
/// subtree.) The children's digits are checked at their first words, one set per depth.
pub(super) struct ChunkScan<'a> {
    plan: &'a SweepPlan,
    /// W, q and d, read per block.
    width: u32,
    q: u32,
    chunk_digits: u32,
    /// By trailing zeros of x: the low bits in which f(x − 1) and f(x) may differ.
    pub(super) free_bits: [u8; 65],
    /// By trailing zeros of x: the shallowest depth k ≥ d whose child x starts (its low
    /// W − q(k + 1) bits are zero).
    first_child_depth: [u8; 65],
    /// Low bits of a block (W − q·d′) as a mask. A block's first word has them zero, and
    /// so has every child start of depths d..d′ − 1; inside a chunk no other word does (when
    /// d′ = d the block is the chunk, whose first word the caller handles).
    pub(super) low_mask: u64,
    /// Child starts of the law depths have these bits zero (every bit when there are none).
    pub(super) law_mask: u64,
    /// Per depth d..d′, the output digits the current node's children have taken.
    taken: Vec<[u64; 4]>,
    /// The bitmap word [`ChunkScan::mark`] holds, and its value (newer than the bitmap's).
    word: usize,
    bits: u64,
    /// The sixteen-word scan's one-hot OR of the current block's outputs so far.
    pub(super) block_hot: u32,
    pub(super) prev: u64,
    pub(super) cells: Vec<Vec<u64>>,
}

impl<'a> ChunkScan<'a> {
    /// The state at the start of a chunk of `plan` (the bitmap cleared by the caller).
    pub(super) fn new(plan: &'a SweepPlan) -> ChunkScan<'a> {
        let (w, q, d) = (plan.width().bits(), plan.base().q(), plan.chunk_digits());
        let laws = plan.law_depths() - d;
        let mut free_bits = [0u8; 65];
        for (tz, slot) in free_bits.iter_mut().enumerate().take(w as usize) {
            *slot = plan.free_bits_after(1u64 << tz) as u8;
        }
        let cells = node_cells(plan.base().base());
        let blocks = block_digits(plan);
        let mut first_child_depth = [0u8; 65];
        for (zeros, slot) in first_child_depth.iter_mut().enumerate() {
            let zeros = (zeros as u32).min(w);
            *slot = (w - zeros).div_ceil(q).saturating_sub(1).max(d) as u8;
        }
        ChunkScan {
            plan,
            width: w,
            q,
            chunk_digits: d,
            free_bits,
            first_child_depth,
            low_mask: (1u64 << block_low_bits(plan)) - 1,
            // Child starts of depths d..L have their low W − qL bits zero; none when no depth
            // lies below the chunk's.
            law_mask: if laws == 0 {
                u64::MAX
            } else {
                (1u64 << (w - q * plan.law_depths())) - 1
            },
            taken: vec![[0; 4]; (blocks - d) as usize],
            // The bitmap is cleared just below.
            word: 0,
            bits: 0,
            block_hot: 0,
            prev: 0,
            cells: vec![vec![0; cells]; laws as usize],
        }
    }

    /// Records the node-law digits of child start `x` (output `y`) at depths d..L.
    #[cold]
    pub(super) fn record_law(&mut self, x: u64, y: u64, node: &mut [Vec<u8>]) {
        let (w, q, d) = (
            self.plan.width().bits(),
            self.plan.base().q(),
            self.plan.chunk_digits(),
        );
        let digit_mask = (1u64 << q) - 1;
        for k in (d..self.plan.law_depths()).rev() {
            let free = w - q * (k + 1);
            if x & ((1u64 << free) - 1) != 0 {
                break;
            }
            let e = ((x >> free) & digit_mask) as usize;
            let images = &mut node[(k - d) as usize];
            images[e] = ((y >> free) & digit_mask) as u8;
            if e as u64 == digit_mask {
                if let Some(cell) = node_cell(images) {
                    self.cells[(k - d) as usize][cell as usize] += 1;
                }
            }
        }
    }

    /// Scans the outputs of words `start..start + out.len()`; the first word of the chunk must
    /// have been handled by the caller (it has no predecessor inside the chunk).
    ///
    /// With `BINARY` (base 2) the bitmap is not used: a nested map is a bijection iff every
    /// node's two children map to different digits, and the children of node (s, p) meet exactly
    /// once among consecutive inputs, at x − 1 = p0 1…1 and x = p1 0…0, which share s digits.
    /// So the outputs of every consecutive pair must share exactly as many digits as the inputs:
    /// `(f(x−1) ⊕ f(x)) >> (free − 1) == 1`. A failure of that test is only located, not named:
    /// the caller rescans the chunk with the bitmap to name it as the general scan does. (For
    /// b > 2 a per-depth set of the digits a node's children took would do the same, but its
    /// read-modify-write of one word per step measured slower than the bitmap.)
    #[inline]
    pub(super) fn scan<T: Copy + Into<u64>, const BINARY: bool>(
        &mut self,
        start: u64,
        out: &[T],
        bitmap: &mut [u64],
        node: &mut [Vec<u8>],
    ) -> Result<(), (u64, SweepFailure)> {
        let mask = self.plan.width().mask();
        // The mark's bitmap word and the previous output live in registers for the frame.
        let (mut word, mut bits, mut prev) = (self.word, self.bits, self.prev);
        for (i, &y) in out.iter().enumerate() {
            let x = start + i as u64;
            let y: u64 = y.into();
            if y > mask {
                return Err((
                    x,
                    SweepFailure::OutOfRange {
                        input: x,
                        output: y,
                    },
                ));
            }
            let free = self.free_bits[x.trailing_zeros() as usize];
            if BINARY {
                if (prev ^ y) >> (free - 1) != 1 {
                    return Err((
                        x,
                        SweepFailure::Collision {
                            inputs: [x - 1, x],
                            output: y,
                        },
                    ));
                }
            } else {
                if (prev ^ y) >> free != 0 {
                    let f = self.plan.step_failure(x, prev, y).expect("failed step");
                    return Err((x, f));
                }
                if x & self.low_mask == 0 {
                    // A new block: the bitmap is cleared, so is the word held.
                    self.child_start(x, y, bitmap)?;
                    (word, bits) = (0, 0);
                }
                mark(x, y, self.low_mask, bitmap, &mut word, &mut bits)?;
            }
            if x & self.law_mask == 0 {
                self.record_law(x, y, node);
            }
            prev = y;
        }
        (self.word, self.bits, self.prev) = (word, bits, prev);
        Ok(())
    }

    /// At the first word `x` (output `y`) of a block, which starts a child of one or more
    /// nodes of depths d..d′: checks each such child's digit against those its siblings took,
    /// and clears the bitmap. A repeated digit is a collision (its partner found by a rescan,
    /// so it is reported as input 0 here).
    #[cold]
    pub(super) fn child_start(
        &mut self,
        x: u64,
        y: u64,
        bitmap: &mut [u64],
    ) -> Result<(), (u64, SweepFailure)> {
        if !self.child_digits(x, y) {
            return Err(unpartnered_collision(x, y));
        }
        match bitmap {
            [only] => *only = 0,
            _ => bitmap.fill(0),
        }
        (self.word, self.bits) = (0, 0);
        Ok(())
    }

    /// At a block's first word `x` (output `y`): takes the digit of each child it starts at
    /// depths d..d′ in that depth's set (emptied at a node's first child); false when a sibling
    /// already took it.
    #[inline]
    pub(super) fn child_digits(&mut self, x: u64, y: u64) -> bool {
        let (w, q, d) = (self.width, self.q, self.chunk_digits);
        let digit_mask = (1u64 << q) - 1;
        let depths = self.taken.len() as u32;
        let shallowest = u32::from(self.first_child_depth[x.trailing_zeros() as usize]);
        for k in shallowest..d + depths {
            let free = w - q * (k + 1);
            let taken = &mut self.taken[(k - d) as usize];
            if (x >> free) & digit_mask == 0 {
                *taken = [0; 4];
            }
            let digit = ((y >> free) & digit_mask) as usize;
            if taken[digit / 64] >> (digit % 64) & 1 != 0 {
                return false;
            }
            taken[digit / 64] |= 1 << (digit % 64);
        }
        true
    }

    /// [`mark`] with the word this scan holds.
    pub(super) fn mark(
        &mut self,
        x: u64,
        y: u64,
        bitmap: &mut [u64],
    ) -> Result<(), (u64, SweepFailure)> {
        mark(x, y, self.low_mask, bitmap, &mut self.word, &mut self.bits)
    }
}

/// Marks output `y` of input `x` in the block's bitmap (its low bits, `low_mask`); a second
/// mark is a collision (the other input is found by a rescan, so it is reported as input 0
/// here).
///
/// The bitmap word last touched is held in `bits` (index `word`) and written back only when
/// another word is touched: a node's children land in one word, and a load that waits on the
/// store just before it would chain every word's mark to the previous one.
#[inline(always)]
fn mark(
    x: u64,
    y: u64,
    low_mask: u64,
    bitmap: &mut [u64],
    word: &mut usize,
    bits: &mut u64,
) -> Result<(), (u64, SweepFailure)> {
    let low = y & low_mask;
    let (at, bit) = ((low >> 6) as usize, 1u64 << (low & 63));
    if at != *word {
        bitmap[*word] = *bits;
        *word = at;
        *bits = bitmap[at];
    }
    if *bits & bit != 0 {
        return Err(unpartnered_collision(x, y));
    }
    *bits |= bit;
    Ok(())
}

/// A collision at input `x` (output `y`) whose earlier partner the caller finds by a rescan
/// (input 0 stands for it until then).
fn unpartnered_collision(x: u64, y: u64) -> (u64, SweepFailure) {
    (
        x,
        SweepFailure::Collision {
            inputs: [0, x],
            output: y,
        },
    )
}
