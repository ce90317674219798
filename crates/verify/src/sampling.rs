//! How the law tests see a scrambler: as a black box evaluated on fixed words for many
//! independent seeds. A test plans [`Probe`]s (a dimension, the words, and how many seeds need
//! them); [`evaluate`] builds each seed's instance once, sends every probe of one dimension in
//! one [`Scrambler::scramble_batch`] call (one request for an external program), and returns the
//! outputs in seed order, whatever the thread count.
//!
//! Node words: the node (depth k, prefix p) of a base-2^q tree is reached by the word whose
//! first k digits are p; its permutation's image of digit d is digit k of the scramble of the
//! word (p, d, 0, 0, …), for any nested scramble.

use crate::error::BatteryError;
use gartowen_core::{DigitLayout, PowerOfTwoBase, RadixLayout, Scrambler, SplitMix64, Width};
use rayon::prelude::*;

/// Builds the instance of an implementation for one seed.
pub type SeedBuilder<'a> =
    dyn Fn(u64) -> Result<Box<dyn Scrambler + 'a>, String> + Send + Sync + 'a;

/// Scrambles the same words for consecutive seeds in one call: given `(words, width, dim,
/// first, count)`, returns `count · words.len()` words, seed `first + i`'s scramble of
/// `words[k]` at `i · words.len() + k`. Offered by implementations whose calls cost more than
/// their words (a Python function); it must equal the instances of [`SeedBuilder`] word for word.
pub type ManySeeds<'a> =
    dyn Fn(&[u64], Width, u32, u64, u64) -> Result<Vec<u64>, String> + Send + Sync + 'a;

/// The most words one [`ManySeeds`] call is given (seeds × words per seed).
pub const MANY_SEEDS_WORDS: usize = 1 << 20;

/// Words to scramble in one dimension for the first `seeds` seeds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Probe {
    /// The dimension.
    pub dim: u32,
    /// The input words.
    pub words: Vec<u64>,
    /// Evaluated for seeds `0..seeds` of the run only.
    pub seeds: u64,
}

/// Outputs of a run: `[seed][probe]` holds the scrambled words (empty when the probe was not
/// evaluated for that seed).
pub type Outputs = Vec<Vec<Vec<u64>>>;

/// [`evaluate`], through `many` when the implementation offers it: for each dimension and
/// each run of seeds that need the same probes, one call per [`MANY_SEEDS_WORDS`] words
/// instead of one per seed. The outputs are the same.
pub fn evaluate_with(
    with_seed: &SeedBuilder,
    many: Option<&ManySeeds>,
    width: Width,
    seed_base: u64,
    probes: &[Probe],
) -> Result<Outputs, BatteryError> {
    let Some(many) = many else {
        return evaluate(with_seed, width, seed_base, probes);
    };
    let seeds = probes.iter().map(|p| p.seeds).max().unwrap_or(0);
    let mut out: Outputs = vec![vec![Vec::new(); probes.len()]; seeds as usize];
    let mut dims: Vec<u32> = probes.iter().map(|p| p.dim).collect();
    dims.sort_unstable();
    dims.dedup();
    for dim in dims {
        // Seeds lo..hi need the same probes: those of this dimension asking for ≥ hi seeds.
        let mut bounds: Vec<u64> = probes
            .iter()
            .filter(|p| p.dim == dim)
            .map(|p| p.seeds)
            .collect();
        bounds.sort_unstable();
        bounds.dedup();
        let mut lo = 0;
        for hi in bounds {
            let active: Vec<usize> = (0..probes.len())
                .filter(|&k| probes[k].dim == dim && probes[k].seeds >= hi)
                .collect();
            let words: Vec<u64> = active
                .iter()
                .flat_map(|&k| probes[k].words.iter().copied())
                .collect();
            let per_call = (MANY_SEEDS_WORDS / words.len().max(1)).max(1) as u64;
            let mut first = lo;
            while first < hi {
                let count = per_call.min(hi - first);
                let seed = seed_base.wrapping_add(first);
                let scrambled = many(&words, width, dim, seed, count)
                    .map_err(|message| BatteryError::Instance { seed, message })?;
                if scrambled.len() != words.len() * count as usize {
                    return Err(BatteryError::Instance {
                        seed,
                        message: format!(
                            "{} words back for {} seeds of {} words",
                            scrambled.len(),
                            count,
                            words.len()
                        ),
                    });
                }
                for (i, row) in scrambled.chunks(words.len().max(1)).enumerate() {
                    let mut at = 0;
                    for &k in &active {
                        let n = probes[k].words.len();
                        out[(first + i as u64) as usize][k] = row[at..at + n].to_vec();
                        at += n;
                    }
                }
                first += count;
            }
            lo = hi;
        }
    }
    Ok(out)
}

/// Scrambles every probe for seeds `seed_base + i`, i in `0..max(probe.seeds)`.
pub fn evaluate(
    with_seed: &SeedBuilder,
    width: Width,
    seed_base: u64,
    probes: &[Probe],
) -> Result<Outputs, BatteryError> {
    let seeds = probes.iter().map(|p| p.seeds).max().unwrap_or(0);
    let mut dims: Vec<u32> = probes.iter().map(|p| p.dim).collect();
    dims.sort_unstable();
    dims.dedup();
    (0..seeds)
        .into_par_iter()
        .map(|i| {
            let seed = seed_base.wrapping_add(i);
            let s = with_seed(seed).map_err(|message| BatteryError::Instance { seed, message })?;
            let mut out = vec![Vec::new(); probes.len()];
            for &dim in &dims {
                let active: Vec<usize> = (0..probes.len())
                    .filter(|&k| probes[k].dim == dim && i < probes[k].seeds)
                    .collect();
                let mut batch: Vec<u64> = active
                    .iter()
                    .flat_map(|&k| probes[k].words.iter().copied())
                    .collect();
                s.scramble_batch(&mut batch, width, dim);
                let mut at = 0;
                for &k in &active {
                    let n = probes[k].words.len();
                    out[k] = batch[at..at + n].to_vec();
                    at += n;
                }
            }
            Ok(out)
        })
        .collect()
}

/// How a tree's words hold digits: base 2^q bits, or an integer of base-b digits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TreeDigits {
    /// Base 2^q, digits in the word's bits (tail digit included).
    PowerOfTwo(DigitLayout),
    /// A base that is not a power of two: the word is an integer below b^m.
    Radix(RadixLayout),
}

/// Node addressing in one layout: words for nodes and digits of outputs.
#[derive(Debug, Clone, Copy)]
pub struct Tree {
    /// How the words hold digits.
    pub digits: TreeDigits,
}

impl Tree {
    /// The tree of `width`-bit words in base 2^q.
    pub fn new(layout: DigitLayout) -> Self {
        Tree {
            digits: TreeDigits::PowerOfTwo(layout),
        }
    }

    /// The tree of base-b digit integers (b not a power of two).
    pub fn radix(layout: RadixLayout) -> Self {
        Tree {
            digits: TreeDigits::Radix(layout),
        }
    }

    /// The word width.
    pub fn width(&self) -> Width {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.width(),
            TreeDigits::Radix(l) => l.width(),
        }
    }

    /// The base 2^q, when the base is a power of two.
    pub fn power_of_two(&self) -> Option<PowerOfTwoBase> {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => Some(l.base()),
            TreeDigits::Radix(_) => None,
        }
    }

    /// The base b.
    pub fn b(&self) -> u32 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.base().base(),
            TreeDigits::Radix(l) => l.radix().get(),
        }
    }

    /// log2 of the base.
    pub fn log2_b(&self) -> f64 {
        (self.b() as f64).log2()
    }

    /// Full digits in a word (of b values each; a power-of-two layout's tail digit excluded).
    pub fn full_digits(&self) -> u32 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.full_digits(),
            TreeDigits::Radix(l) => l.num_digits(),
        }
    }

    /// Digits in a word, a power-of-two layout's tail digit included.
    pub fn num_digits(&self) -> u32 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.num_digits(),
            TreeDigits::Radix(l) => l.num_digits(),
        }
    }

    /// Digit `k` of `y`.
    pub fn digit(&self, y: u64, k: u32) -> u32 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.get(y, k),
            TreeDigits::Radix(l) => l.get(y, k),
        }
    }

    /// `x` with digit `k` replaced by `d`.
    pub fn set(&self, x: u64, k: u32, d: u32) -> u64 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.set(x, k, d),
            TreeDigits::Radix(l) => l.set(x, k, d),
        }
    }

    /// The word with digits `prefix` (most significant first), then `d` at position
    /// `prefix.len()` (when the word has that digit; d must then be 0 otherwise), then zeros.
    pub fn word(&self, prefix: &[u32], d: u32) -> u64 {
        let mut x = 0u64;
        for (k, &p) in prefix.iter().enumerate() {
            x = self.set(x, k as u32, p);
        }
        let at = prefix.len() as u32;
        if at < self.num_digits() {
            x = self.set(x, at, d);
        } else {
            debug_assert_eq!(d, 0, "no digit {at} to hold {d}");
        }
        x
    }

    /// A uniformly random word (every W-bit word, or every integer below b^m).
    pub fn random_word(&self, rng: &mut SplitMix64) -> u64 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => rng.next_u64() & l.width().mask(),
            TreeDigits::Radix(l) => l.random_word(rng),
        }
    }

    /// Whether `y` is a word of the tree (W bits, or below b^m).
    pub fn holds(&self, y: u64) -> bool {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.width().check(y).is_ok(),
            TreeDigits::Radix(l) => l.check(y).is_ok(),
        }
    }

    /// The largest word (2^W − 1, or b^m − 1).
    pub fn largest_word(&self) -> u64 {
        match self.digits {
            TreeDigits::PowerOfTwo(l) => l.width().mask(),
            TreeDigits::Radix(l) => l.capacity() - 1,
        }
    }

    /// A pseudo-random prefix of `depth` full digits.
    pub fn random_prefix(&self, depth: u32, rng: &mut SplitMix64) -> Vec<u32> {
        (0..depth).map(|_| rng.bounded(self.b())).collect()
    }

    /// The difference of two digits that cancels the group's translation part: XOR in base
    /// 2^q, subtraction mod b otherwise.
    pub fn digit_difference(&self, y: u32, origin: u32) -> u32 {
        match self.digits {
            TreeDigits::PowerOfTwo(_) => y ^ origin,
            TreeDigits::Radix(_) => (y + self.b() - origin) % self.b(),
        }
    }
}

/// Folds a digit to at most 16 values (its low 4 bits): keeps χ² tables at ≤ 256 cells.
#[inline]
pub fn fold(d: u32, b: u32) -> u32 {
    if b > 16 {
        d & 15
    } else {
        d
    }
}

/// The number of folded values of a base-b digit.
pub fn folded_size(b: u32) -> u32 {
    b.min(16)
}

/// Renders a prefix as hex digits `0x5.3.a` (depth 0: `root`).
pub fn prefix_name(prefix: &[u32]) -> String {
    if prefix.is_empty() {
        "root".into()
    } else {
        prefix
            .iter()
            .map(|d| format!("{d:x}"))
            .collect::<Vec<_>>()
            .join(".")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::Identity;

    #[test]
    fn a_refused_seed_is_named_with_the_builders_words() {
        let picky: Box<SeedBuilder> = Box::new(|seed| {
            if seed == 7 {
                Err("the license server is down".into())
            } else {
                Ok(Box::new(Identity))
            }
        });
        let probe = Probe {
            dim: 0,
            words: vec![1, 2],
            seeds: 4,
        };
        let fine = evaluate(picky.as_ref(), Width::W32, 0, std::slice::from_ref(&probe));
        assert_eq!(fine.unwrap()[3][0], vec![1, 2]);
        let refused = evaluate(picky.as_ref(), Width::W32, 5, &[probe]).unwrap_err();
        assert_eq!(
            refused,
            BatteryError::Instance {
                seed: 7,
                message: "the license server is down".into()
            }
        );
        assert_eq!(
            refused.to_string(),
            "no instance for seed 7: the license server is down"
        );
    }

    #[test]
    fn many_seeds_per_call_give_the_outputs_of_one_instance_per_seed() {
        use std::sync::atomic::{AtomicU64, Ordering};
        // A per-seed XOR-multiply scramble, as instances and as one call for many seeds.
        let scramble = |x: u64, dim: u32, seed: u64| {
            (x ^ seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ u64::from(dim) << 7) & 0xFFFF_FFFF
        };
        struct Keyed<F>(u64, F);
        impl<F: Fn(u64, u32, u64) -> u64 + Send + Sync> gartowen_core::Scrambler for Keyed<F> {
            fn name(&self) -> String {
                "keyed".into()
            }
            fn base(&self) -> gartowen_core::PowerOfTwoBase {
                gartowen_core::PowerOfTwoBase::B2
            }
            fn claim(&self) -> gartowen_core::Claim {
                gartowen_core::Claim::NESTED
            }
            fn scramble(&self, x: u64, _w: Width, dim: u32) -> u64 {
                (self.1)(x, dim, self.0)
            }
        }
        let builder: Box<SeedBuilder> = Box::new(move |seed| Ok(Box::new(Keyed(seed, scramble))));
        let calls = AtomicU64::new(0);
        let many = |words: &[u64], _w: Width, dim: u32, first: u64, count: u64| {
            calls.fetch_add(1, Ordering::Relaxed);
            Ok((0..count)
                .flat_map(|i| words.iter().map(move |&x| scramble(x, dim, first + i)))
                .collect())
        };
        // Two dimensions, probes needing 3, 5 and 700 seeds; one probe large enough that a
        // call holds fewer seeds than its run.
        let probes = vec![
            Probe {
                dim: 1,
                words: vec![1, 2, 3],
                seeds: 5,
            },
            Probe {
                dim: 0,
                words: vec![7],
                seeds: 3,
            },
            Probe {
                dim: 1,
                words: (0..2000).collect(),
                seeds: 700,
            },
            Probe {
                dim: 0,
                words: vec![9, 10],
                seeds: 700,
            },
        ];
        let one_by_one = evaluate(builder.as_ref(), Width::W32, 40, &probes).unwrap();
        let batched =
            evaluate_with(builder.as_ref(), Some(&many), Width::W32, 40, &probes).unwrap();
        assert_eq!(batched, one_by_one);
        // dim 0: seeds 0..3 and 3..700; dim 1: 0..5, then 5..700 in calls of ≤ 524 seeds.
        assert_eq!(calls.load(Ordering::Relaxed), 5);
        // A reply of the wrong length is an error naming the first seed of the call.
        let short = |_: &[u64], _: Width, _: u32, _: u64, _: u64| Ok(vec![0u64]);
        let e = evaluate_with(builder.as_ref(), Some(&short), Width::W32, 40, &probes[..1])
            .unwrap_err();
        assert_eq!(
            e,
            BatteryError::Instance {
                seed: 40,
                message: "1 words back for 5 seeds of 3 words".into()
            }
        );
    }

    #[test]
    fn a_probe_is_evaluated_for_its_own_seeds_only() {
        let identity: Box<SeedBuilder> = Box::new(|_| Ok(Box::new(Identity)));
        let long = Probe {
            dim: 0,
            words: vec![7],
            seeds: 3,
        };
        let short = Probe {
            dim: 0,
            words: vec![9, 10],
            seeds: 1,
        };
        let out = evaluate(identity.as_ref(), Width::W32, 0, &[long, short]).unwrap();
        assert_eq!(out.len(), 3, "the most seeds any probe asks for");
        assert_eq!(out[0], vec![vec![7], vec![9, 10]]);
        assert_eq!(
            out[1],
            vec![vec![7], vec![]],
            "seed 1 is past the short probe's seeds"
        );
        assert_eq!(out[2], vec![vec![7], vec![]]);
    }
}
