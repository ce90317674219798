//! Byte lookup tables: the XOR of the columns selected by each byte of a 32-bit index, so a
//! point costs four loads instead of one step per set index bit.

use crate::DigitalSequence;

/// Per dimension, for each of the 4 low index bytes, the 256 XOR combinations of its 8 columns
/// (8 KiB per dimension).
pub struct LookupTables {
    tables: Vec<[[u64; 256]; 4]>,
}

impl LookupTables {
    /// Builds the tables for every dimension of `seq`.
    pub fn new(seq: &DigitalSequence) -> Self {
        let tables = (0..seq.dims())
            .map(|j| {
                let mut t = [[0u64; 256]; 4];
                for (byte, table) in t.iter_mut().enumerate() {
                    for v in 1..256usize {
                        // Build each entry from the entry without its lowest bit.
                        let low = v.trailing_zeros() as usize;
                        table[v] = table[v & (v - 1)] ^ seq.column(j, 8 * byte + low);
                    }
                }
                t
            })
            .collect();
        LookupTables { tables }
    }

    /// Coordinate `dim` of point `index` (equal to [`DigitalSequence::point`]).
    #[inline(always)]
    pub fn point_u32(&self, index: u32, dim: usize) -> u64 {
        let t = &self.tables[dim];
        let b = index.to_le_bytes();
        t[0][b[0] as usize] ^ t[1][b[1] as usize] ^ t[2][b[2] as usize] ^ t[3][b[3] as usize]
    }

    /// Bytes held by the tables.
    pub fn table_bytes(&self) -> usize {
        self.tables.len() * std::mem::size_of::<[[u64; 256]; 4]>()
    }
}
