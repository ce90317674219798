//! A renderer's own samplers, as a user of gartowen would have them: a per-bit hashed Owen
//! scramble and a random digital shift, both on 32-bit words. `tests/battery.rs` gates them
//! with `gartowen::testing` exactly as a user's test suite would.

/// SplitMix64's finalizer.
fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Binary Owen scrambling of 32-bit words: bit k flips by one hashed bit of (seed, dimension,
/// k, the k bits above it).
pub struct PerBitOwen {
    seed: u64,
}

impl PerBitOwen {
    /// The scramble for `seed`.
    pub fn new(seed: u64) -> Self {
        PerBitOwen { seed }
    }

    /// The scrambled word.
    pub fn scramble(&self, x: u32, dim: u32) -> u32 {
        let key = mix64(self.seed ^ mix64(dim as u64 + 1));
        let mut y = x;
        for k in 0..32u32 {
            let prefix = if k == 0 { 0 } else { (x >> (32 - k)) as u64 };
            let flip = mix64(key ^ mix64(((k as u64) << 40) ^ prefix)) & 1;
            y ^= (flip as u32) << (31 - k);
        }
        y
    }
}

/// A random digital shift: x XOR one random word per (seed, dimension). Cheap, and every bit
/// is a fair coin, but it is not an Owen scramble.
pub struct DigitalShift {
    seed: u64,
}

impl DigitalShift {
    /// The shift for `seed`.
    pub fn new(seed: u64) -> Self {
        DigitalShift { seed }
    }

    /// The scrambled word.
    pub fn scramble(&self, x: u32, dim: u32) -> u32 {
        x ^ (mix64(self.seed ^ mix64(dim as u64 + 1)) >> 32) as u32
    }
}
