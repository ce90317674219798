//! Minimal little-endian u64-limb arithmetic for exact sums of products (no allocation in the
//! inner loop: callers reuse buffers).

/// `v << s` as three limbs (v < 2^64, s + 64 ≤ 192).
pub fn shl_small(v: u64, s: u32) -> [u64; 3] {
    let mut out = [0u64; 3];
    let (limb, bit) = ((s / 64) as usize, s % 64);
    out[limb] = v << bit;
    if bit != 0 && limb + 1 < 3 {
        out[limb + 1] = v >> (64 - bit);
    }
    out
}

/// A u128 as three limbs.
pub fn from_u128(v: u128) -> [u64; 3] {
    [v as u64, (v >> 64) as u64, 0]
}

/// Three-limb left shift by s < 64.
pub fn shl_limbs(v: [u64; 3], s: u32) -> [u64; 3] {
    if s == 0 {
        return v;
    }
    [
        v[0] << s,
        (v[1] << s) | (v[0] >> (64 - s)),
        (v[2] << s) | (v[1] >> (64 - s)),
    ]
}

/// a − b for three-limb numbers with a ≥ b.
pub fn sub3(a: [u64; 3], b: [u64; 3]) -> [u64; 3] {
    let (r0, c0) = a[0].overflowing_sub(b[0]);
    let (r1, c1a) = a[1].overflowing_sub(b[1]);
    let (r1, c1b) = r1.overflowing_sub(c0 as u64);
    let r2 = a[2].wrapping_sub(b[2]).wrapping_sub((c1a || c1b) as u64);
    [r0, r1, r2]
}

/// acc ← acc · f, where f has up to three limbs; `scratch` is reused.
pub fn mul_assign(acc: &mut Vec<u64>, f: &[u64; 3], scratch: &mut Vec<u64>) {
    let flen = if f[2] != 0 {
        3
    } else if f[1] != 0 {
        2
    } else {
        1
    };
    scratch.clear();
    scratch.resize(acc.len() + flen, 0);
    for (j, &fj) in f.iter().take(flen).enumerate() {
        let mut carry = 0u128;
        for (i, &ai) in acc.iter().enumerate() {
            let t = ai as u128 * fj as u128 + scratch[i + j] as u128 + carry;
            scratch[i + j] = t as u64;
            carry = t >> 64;
        }
        let mut k = acc.len() + j;
        while carry != 0 {
            let t = scratch[k] as u128 + carry;
            scratch[k] = t as u64;
            carry = t >> 64;
            k += 1;
        }
    }
    while scratch.len() > 1 && *scratch.last().unwrap() == 0 {
        scratch.pop();
    }
    std::mem::swap(acc, scratch);
}

/// sum ← sum + (x << shift_bits), growing as needed.
pub fn add_shifted(sum: &mut Vec<u64>, x: &[u64], shift_bits: u32) {
    let (limb, bit) = ((shift_bits / 64) as usize, shift_bits % 64);
    let need = x.len() + limb + 2;
    if sum.len() < need {
        sum.resize(need, 0);
    }
    let mut carry = 0u128;
    let mut prev = 0u64;
    for (i, &xi) in x.iter().chain(std::iter::once(&0)).enumerate() {
        let part = if bit == 0 {
            xi
        } else {
            (xi << bit) | (prev >> (64 - bit))
        };
        prev = xi;
        let t = sum[i + limb] as u128 + part as u128 + carry;
        sum[i + limb] = t as u64;
        carry = t >> 64;
    }
    let mut k = x.len() + 1 + limb;
    while carry != 0 {
        if k == sum.len() {
            sum.push(0);
        }
        let t = sum[k] as u128 + carry;
        sum[k] = t as u64;
        carry = t >> 64;
        k += 1;
    }
}

/// sum ← sum + other.
pub fn add_assign(sum: &mut Vec<u64>, other: &[u64]) {
    add_shifted(sum, other, 0);
}

/// The limbs as a BigUint.
pub fn to_biguint(v: &[u64]) -> num_bigint::BigUint {
    let mut bytes = Vec::with_capacity(v.len() * 8);
    for limb in v {
        bytes.extend_from_slice(&limb.to_le_bytes());
    }
    num_bigint::BigUint::from_bytes_le(&bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigUint;

    #[test]
    fn products_and_sums_match_biguint() {
        let mut rng = gartowen_core::SplitMix64::new(4);
        for _ in 0..500 {
            let mut acc = vec![1u64];
            let mut big = BigUint::from(1u32);
            let mut scratch = Vec::new();
            for _ in 0..(rng.bounded(12) + 1) {
                let f = [
                    rng.next_u64(),
                    rng.next_u64() >> rng.bounded(64),
                    (rng.next_u64() >> 62) * rng.bounded(2) as u64,
                ];
                mul_assign(&mut acc, &f, &mut scratch);
                big *= to_biguint(&f);
            }
            assert_eq!(to_biguint(&acc), big);
            let mut sum = vec![rng.next_u64()];
            let mut bsum = to_biguint(&sum);
            let shift = rng.bounded(130);
            add_shifted(&mut sum, &acc, shift);
            bsum += &big << shift as usize;
            assert_eq!(to_biguint(&sum), bsum);
        }
        let three = shl_small(3, 128);
        let v = sub3(three, from_u128(u128::MAX));
        assert_eq!(
            to_biguint(&v),
            (BigUint::from(3u32) << 128usize) - BigUint::from(u128::MAX)
        );
    }
}
