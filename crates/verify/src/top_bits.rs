//! Judging only the top K bits of each word (`verify --bits K`): some libraries scramble the
//! ⌈log2 N⌉ bits their point count needs and leave the rest as they are. The candidate is seen
//! through a K-bit view: a K-bit word x is sent as the W-bit word x·2^(W−K) (zeros below) and
//! the reply's top K bits are the answer. Every check then runs on K-bit words, so no digit
//! below bit K is asked about: the tree has ⌈K/q⌉ digits and deeper depths are not tested.

use crate::candidate::Candidate;
use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, Width};

/// A K-bit view of a scrambler that works on `full`-bit words.
pub struct TopBits<'a> {
    inner: Box<dyn Scrambler + 'a>,
    full: Width,
    k: Width,
}

impl<'a> TopBits<'a> {
    /// The top `k` bits of `inner` on `full`-bit words (k ≤ full).
    pub fn new(inner: Box<dyn Scrambler + 'a>, full: Width, k: Width) -> TopBits<'a> {
        assert!(k.bits() <= full.bits(), "k ≤ W");
        TopBits { inner, full, k }
    }

    fn shift(&self) -> u32 {
        self.full.bits() - self.k.bits()
    }
}

impl Scrambler for TopBits<'_> {
    fn name(&self) -> String {
        format!("{} (top {} bits)", self.inner.name(), self.k.bits())
    }
    fn base(&self) -> PowerOfTwoBase {
        self.inner.base()
    }
    fn claim(&self) -> Claim {
        self.inner.claim()
    }
    fn supports_width(&self, width: Width) -> bool {
        width == self.k
    }
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        self.inner.scramble(x << self.shift(), self.full, dim) >> self.shift()
    }
    fn scramble_batch(&self, words: &mut [u64], _width: Width, dim: u32) {
        let shift = self.shift();
        for w in words.iter_mut() {
            *w <<= shift;
        }
        self.inner.scramble_batch(words, self.full, dim);
        for w in words.iter_mut() {
            *w >>= shift;
        }
    }
}

/// `c` judged on the top `k` bits of its `full`-bit words: its probe and every instance seen
/// through [`TopBits`]. Refused (naming the value) when k is not in q..=W (q = log2 of the
/// base: one digit at least), or for a base that is not a power of two, or with a twin (the
/// twin would scramble K-bit words itself, not the top bits of W-bit ones).
pub fn top_bits(c: Candidate<'_>, full: Width, k: u32) -> Result<Candidate<'_>, String> {
    if c.radix.is_some() {
        return Err(format!(
            "--bits {k}: bits are digits only in bases 2^q, not in base {}",
            c.base()
        ));
    }
    let q = c.probe.base().q();
    if k < q || k > full.bits() {
        return Err(format!(
            "--bits {k}: must be between {q} (one base-{} digit) and the word width {}",
            c.probe.base().base(),
            full.bits()
        ));
    }
    if c.twin.is_some() {
        return Err(format!("--bits {k} cannot be combined with --expect"));
    }
    let k = Width::new(k).map_err(|e| e.to_string())?;
    let with_seed = c.with_seed;
    let view = move |s: u64| -> Result<Box<dyn Scrambler + '_>, String> {
        Ok(Box::new(TopBits::new(with_seed(s)?, full, k)))
    };
    Ok(Candidate {
        name: format!("{} (top {} bits)", c.name, k.bits()),
        probe: Box::new(TopBits::new(c.probe, full, k)),
        with_seed: Box::new(view),
        many: None,
        ..c
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The identity, claiming base `.0`.
    struct InBase(PowerOfTwoBase);
    impl Scrambler for InBase {
        fn name(&self) -> String {
            "identity".into()
        }
        fn base(&self) -> PowerOfTwoBase {
            self.0
        }
        fn claim(&self) -> Claim {
            Claim::NESTED
        }
        fn scramble(&self, x: u64, _width: Width, _dim: u32) -> u64 {
            x
        }
    }

    /// Scrambles only the top `k` bits (flips them all), leaving the rest: a library that
    /// scrambles the bits its point count needs.
    struct TopFlip(u32);
    impl Scrambler for TopFlip {
        fn name(&self) -> String {
            "top-flip".into()
        }
        fn base(&self) -> PowerOfTwoBase {
            PowerOfTwoBase::B2
        }
        fn claim(&self) -> Claim {
            Claim::NESTED
        }
        fn scramble(&self, x: u64, width: Width, _dim: u32) -> u64 {
            x ^ (((1u64 << self.0) - 1) << (width.bits() - self.0))
        }
    }

    #[test]
    fn the_view_sends_zeros_below_and_keeps_the_top_bits() {
        let v = TopBits::new(Box::new(TopFlip(12)), Width::W32, Width::new(12).unwrap());
        assert!(v.supports_width(Width::new(12).unwrap()) && !v.supports_width(Width::W32));
        assert_eq!(v.scramble(0, Width::new(12).unwrap(), 0), 0xfff);
        assert_eq!(v.scramble(0xabc, Width::new(12).unwrap(), 0), 0xabc ^ 0xfff);
        let mut batch = [0u64, 1, 0xfff];
        v.scramble_batch(&mut batch, Width::new(12).unwrap(), 3);
        assert_eq!(batch, [0xfff, 0xffe, 0]);
        // A view of 8 of the 12 scrambled bits sees all of them flipped.
        let v = TopBits::new(Box::new(TopFlip(12)), Width::W32, Width::new(8).unwrap());
        assert_eq!(v.scramble(0x12, Width::new(8).unwrap(), 0), 0xed);
        assert_eq!(v.name(), "top-flip (top 8 bits)");
    }

    #[test]
    fn bits_outside_one_digit_to_the_width_are_refused() {
        let build = |k: u32, base: PowerOfTwoBase| {
            let c = Candidate::from_builder(
                "x",
                Claim::OWEN,
                Box::new(move |_| Ok(Box::new(InBase(base)) as Box<dyn Scrambler>)),
            )
            .unwrap();
            top_bits(c, Width::W32, k).map(|c| c.name)
        };
        assert_eq!(build(12, PowerOfTwoBase::B2).unwrap(), "x (top 12 bits)");
        // The bounds themselves are allowed: one digit, and the whole word.
        assert_eq!(build(1, PowerOfTwoBase::B2).unwrap(), "x (top 1 bits)");
        assert_eq!(build(4, PowerOfTwoBase::B16).unwrap(), "x (top 4 bits)");
        assert_eq!(build(32, PowerOfTwoBase::B2).unwrap(), "x (top 32 bits)");
        assert!(build(0, PowerOfTwoBase::B2)
            .unwrap_err()
            .contains("between 1"));
        assert!(build(33, PowerOfTwoBase::B2)
            .unwrap_err()
            .contains("word width 32"));
        assert!(build(3, PowerOfTwoBase::B16)
            .unwrap_err()
            .contains("between 4"));
    }
}

#[cfg(test)]
mod candidate_tests {
    use super::*;
    use crate::sampling::ManySeeds;

    #[test]
    fn the_probe_and_every_instance_are_views_and_batches_of_seeds_are_dropped() {
        let full = |_| Ok(Box::new(gartowen_core::Identity) as Box<dyn Scrambler>);
        let mut c = Candidate::from_builder("x", Claim::OWEN, Box::new(full)).unwrap();
        let many: Box<ManySeeds> =
            Box::new(|words: &[u64], _w, _d, _f, count| Ok(words.repeat(count as usize)));
        c.many = Some(many);
        let k = Width::new(12).unwrap();
        let c = top_bits(c, Width::W32, 12).unwrap();
        assert!(c.many.is_none(), "a batch of seeds would bypass the view");
        assert!(c.probe.supports_width(k) && !c.probe.supports_width(Width::W32));
        let s = (c.with_seed)(5).unwrap();
        assert!(s.supports_width(k) && !s.supports_width(Width::W32));
        assert_eq!(c.probe.scramble(0xabc, k, 0), 0xabc);
    }
}
