//! Witnesses of net verdicts, for re-checking by the checker extracted from the Coq proofs.
//!
//! A witness holds the points as the checker read them (32-bit words) and what the verdict
//! rests on: for "fails at t" the first failing shape, box and count; for "holds at t" the
//! claim; for "the t-value is T" the claim and the first failing box at T − 1, which with the
//! net property's monotonicity in t rules out every smaller t. `proofs/extracted/revalidate.ml`
//! re-checks the file with definitions proved in `proofs/Witness.v` (`revalidate_sound`): a
//! failing box is counted directly (O(N)); "holds" is re-decided in full.

use crate::counting::{check_net, implied_m, t_value_with_witness, BoxFailure};
use crate::{CheckBase, NetError, PointSet};
use std::io::{self, Write};

/// The largest b^m the extracted re-checker accepts (its OCaml integers stay below 2^62).
pub const REVALIDATE_MAX_CELLS: u64 = 1 << 29;

/// What a witness claims of the whole set at m digits.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum WitnessClaim {
    /// A (t,m,s)-net.
    Holds {
        /// The t checked.
        t: u32,
    },
    /// Not a (t,m,s)-net: `failure` holds a count other than b^t.
    Fails {
        /// The t checked.
        t: u32,
        /// The first failing shape and box.
        failure: BoxFailure,
    },
    /// The t-value is `t`; for t > 0, `below` is the first failing box at t − 1.
    TValue {
        /// The least t.
        t: u32,
        /// The failing box at t − 1 (none when t = 0).
        below: Option<BoxFailure>,
    },
}

/// A net verdict with the words it was reached on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetWitness {
    /// The base b.
    pub base: u64,
    /// Bits per word (≤ 32): coordinate x is the word / 2^bits.
    pub bits: u32,
    /// Dimensions s.
    pub dims: usize,
    /// m with N = b^m.
    pub m: u32,
    /// The words, point by point (N·s of them).
    pub words: Vec<u32>,
    /// The verdict and its evidence.
    pub claim: WitnessClaim,
}

/// The words as ≤ 32-bit words with the same first m base-b digits: as they are when the set
/// has ≤ 32 bits; the top 32 bits in base 2^q (b^m ≤ 2^29 makes q·m ≤ 29, so the m digits
/// are read from those bits alone).
fn words32(points: &PointSet, base: CheckBase, m: u32) -> Result<(u32, Vec<u32>), NetError> {
    let w = points.width().bits();
    let shift = if w <= 32 {
        0
    } else {
        match base.log2() {
            Some(_) => w - 32,
            None => {
                return Err(NetError::BadShape(format!(
                    "a witness holds 32-bit words: {w}-bit words in base {} at m = {m} have \
                     digits past the top 32 bits",
                    base.get()
                )))
            }
        }
    };
    let columns: Vec<&[u64]> = (0..points.dims()).map(|j| points.column(j)).collect();
    let mut words = Vec::with_capacity(points.len() * points.dims());
    for i in 0..points.len() {
        words.extend(columns.iter().map(|c| (c[i] >> shift) as u32));
    }
    Ok((w - shift, words))
}

/// Checks the whole set (the (t,m,s)-net property at `t`, or its t-value when `t` is `None`)
/// and returns the verdict with its witness. `m` defaults to the one N = b^m implies.
pub fn net_witness(
    points: &PointSet,
    base: CheckBase,
    m: Option<u32>,
    t: Option<u32>,
) -> Result<NetWitness, NetError> {
    let m = match m {
        Some(m) => m,
        None => implied_m(points, base)?,
    };
    match base.pow(m) {
        Some(cells) if cells <= REVALIDATE_MAX_CELLS => {}
        _ => {
            return Err(NetError::BadShape(format!(
                "a witness is re-checked up to b^m = 2^29 points; base {} at m = {m} is more",
                base.get()
            )))
        }
    }
    let (bits, words) = words32(points, base, m)?;
    let claim = match t {
        Some(t) => {
            let r = check_net(points, base, m, t)?;
            match r.first_failure {
                None => WitnessClaim::Holds { t },
                Some(failure) => WitnessClaim::Fails { t, failure },
            }
        }
        None => {
            let (t, report) = t_value_with_witness(points, base, m)?;
            WitnessClaim::TValue {
                t,
                below: report.and_then(|r| r.first_failure),
            }
        }
    };
    Ok(NetWitness {
        base: base.get(),
        bits,
        dims: points.dims(),
        m,
        words,
        claim,
    })
}

fn write_box(out: &mut dyn Write, f: &BoxFailure) -> io::Result<()> {
    write!(out, "box")?;
    for d in &f.shape {
        write!(out, " {d}")?;
    }
    for a in &f.box_index {
        write!(out, " {a}")?;
    }
    writeln!(out, " count {}", f.count)
}

impl NetWitness {
    /// Writes the witness in the text format `revalidate` reads (documented in
    /// `proofs/extracted/revalidate.ml`).
    pub fn write(&self, out: &mut dyn Write) -> io::Result<()> {
        writeln!(out, "gartowen-witness 1")?;
        writeln!(
            out,
            "base {} width {} dims {} m {} points {}",
            self.base,
            self.bits,
            self.dims,
            self.m,
            self.words.len() / self.dims
        )?;
        match &self.claim {
            WitnessClaim::Holds { t } => writeln!(out, "claim holds {t}")?,
            WitnessClaim::Fails { t, failure } => {
                writeln!(out, "claim fails {t}")?;
                write_box(out, failure)?;
            }
            WitnessClaim::TValue { t, below } => {
                writeln!(out, "claim tvalue {t}")?;
                if let Some(f) = below {
                    write_box(out, f)?;
                }
            }
        }
        writeln!(out, "words")?;
        for point in self.words.chunks(self.dims) {
            let line: Vec<String> = point.iter().map(|x| format!("{x:x}")).collect();
            writeln!(out, "{}", line.join(" "))?;
        }
        writeln!(out, "end")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gartowen_core::Width;

    fn set(width: Width, rows: &[Vec<u64>]) -> PointSet {
        PointSet::from_rows(width, rows).unwrap()
    }

    #[test]
    fn wide_words_keep_their_top_32_bits_in_base_2_to_the_q_and_are_refused_otherwise() {
        let rows = vec![vec![0x1234_5678_9abc_def0], vec![0x8765_4321_0fed_cba9]];
        let b2 = CheckBase::new(2).unwrap();
        let w = net_witness(&set(Width::W64, &rows), b2, None, None).unwrap();
        assert_eq!(w.bits, 32);
        assert_eq!(w.words, vec![0x1234_5678, 0x8765_4321]);
        assert_eq!(w.claim, WitnessClaim::TValue { t: 0, below: None });
        let rows3: Vec<Vec<u64>> = (0..3u64).map(|i| vec![i * (u64::MAX / 3)]).collect();
        let e = net_witness(
            &set(Width::W64, &rows3),
            CheckBase::new(3).unwrap(),
            None,
            None,
        );
        assert!(e.unwrap_err().to_string().contains("32-bit words"));
        // 16-bit words stay 16-bit words.
        let narrow = net_witness(
            &set(Width::new(16).unwrap(), &[vec![0x8000], vec![0]]),
            b2,
            None,
            Some(0),
        )
        .unwrap();
        assert_eq!((narrow.bits, narrow.words.clone()), (16, vec![0x8000, 0]));
        assert_eq!(narrow.claim, WitnessClaim::Holds { t: 0 });
    }

    #[test]
    fn the_text_names_the_claim_and_the_box_and_refuses_sets_past_2_to_the_29() {
        let b2 = CheckBase::new(2).unwrap();
        // Two points in the same half: not a (0,1,1)-net, t-value 1.
        let p = set(Width::W32, &[vec![0x1000_0000], vec![0x2000_0000]]);
        let w = net_witness(&p, b2, None, None).unwrap();
        let mut out = Vec::new();
        w.write(&mut out).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "gartowen-witness 1\nbase 2 width 32 dims 1 m 1 points 2\nclaim tvalue 1\n\
             box 1 0 count 2\nwords\n10000000\n20000000\nend\n"
        );
        let w = net_witness(&p, b2, None, Some(0)).unwrap();
        assert!(matches!(w.claim, WitnessClaim::Fails { t: 0, ref failure } if failure.count == 2));
        let e = net_witness(&p, CheckBase::new(1 << 30).unwrap(), Some(1), Some(0));
        assert!(e.unwrap_err().to_string().contains("2^29"));
    }
}
