//! The built-in sequences by name.

use crate::{faure, sobol, sz, DigitalSequence, SeqError};
use gartowen_core::{PowerOfTwoBase, Width};
use std::str::FromStr;

/// A built-in sequence: `sobol`, `sz4`, `sz16`, `faure:base=B` or `faure-net:base=B:m=M`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SequenceKind {
    /// Sobol with Joe–Kuo 6.21201 direction numbers (base 2).
    Sobol,
    /// The published 4-D SZ sequence, a (0,4)-sequence in base 4 ([`sz::sz4`]).
    Sz4,
    /// A (0,16)-sequence in base 16 whose first quad is the 4-D SZ ([`sz::sz16`]).
    Sz16,
    /// gartowen's earlier reconstruction of sz4 ([`sz::sz4_faure`]).
    Sz4Faure,
    /// gartowen's earlier reconstruction of sz16 ([`sz::sz16_faure`]).
    Sz16Faure,
    /// The Faure (0,b)-sequence over GF(b), b = 2^q, q = 1..8 ([`faure::faure`]).
    Faure(PowerOfTwoBase),
    /// The (0,m,b+1)-net in base b: i/b^m, then the Faure sequence ([`faure::faure_net`]).
    FaureNet(PowerOfTwoBase, u32),
}

impl SequenceKind {
    /// The fixed built-in sequences (the Faure families take a base; see
    /// [`SequenceKind::faure_all`]).
    pub const ALL: [SequenceKind; 3] = [SequenceKind::Sobol, SequenceKind::Sz4, SequenceKind::Sz16];

    /// Every sequence with a fixed name: [`SequenceKind::ALL`] and the earlier
    /// reconstructions kept for reproducing old results.
    pub const NAMED: [SequenceKind; 5] = [
        SequenceKind::Sobol,
        SequenceKind::Sz4,
        SequenceKind::Sz16,
        SequenceKind::Sz4Faure,
        SequenceKind::Sz16Faure,
    ];

    /// The Faure sequence in every base 2^q, q = 1..8.
    pub fn faure_all() -> Vec<SequenceKind> {
        (1..=8)
            .map(|q| SequenceKind::Faure(PowerOfTwoBase::from_q(q).expect("q ≤ 8")))
            .collect()
    }

    /// The command-line name.
    pub fn name(self) -> String {
        match self {
            SequenceKind::Sobol => "sobol".into(),
            SequenceKind::Sz4 => "sz4".into(),
            SequenceKind::Sz16 => "sz16".into(),
            SequenceKind::Sz4Faure => "sz4-faure".into(),
            SequenceKind::Sz16Faure => "sz16-faure".into(),
            SequenceKind::Faure(b) => faure::faure_name(b),
            SequenceKind::FaureNet(b, m) => format!("faure-net:base={}:m={m}", b.base()),
        }
    }

    /// The base the sequence is built for; scramblers default to it.
    pub fn base(self) -> PowerOfTwoBase {
        match self {
            SequenceKind::Sobol => PowerOfTwoBase::B2,
            SequenceKind::Sz4 | SequenceKind::Sz4Faure => PowerOfTwoBase::B4,
            SequenceKind::Sz16 | SequenceKind::Sz16Faure => PowerOfTwoBase::B16,
            SequenceKind::Faure(b) | SequenceKind::FaureNet(b, _) => b,
        }
    }

    /// The largest number of dimensions defined.
    pub fn max_dims(self) -> usize {
        match self {
            SequenceKind::Sobol => sobol::MAX_DIMS,
            SequenceKind::Sz4 | SequenceKind::Sz4Faure => sz::SZ4_DIMS,
            SequenceKind::Sz16 | SequenceKind::Sz16Faure => sz::SZ16_DIMS,
            SequenceKind::Faure(b) => faure::faure_max_dims(b),
            SequenceKind::FaureNet(b, _) => faure::faure_max_dims(b) + 1,
        }
    }

    /// The first `dims` dimensions with `width`-bit words.
    pub fn build(self, dims: usize, width: Width) -> Result<DigitalSequence, SeqError> {
        match self {
            SequenceKind::Sobol => sobol::sequence(dims, width),
            SequenceKind::Sz4 => sz::sz4(dims, width),
            SequenceKind::Sz16 => sz::sz16(dims, width),
            SequenceKind::Sz4Faure => sz::sz4_faure(dims, width),
            SequenceKind::Sz16Faure => sz::sz16_faure(dims, width),
            SequenceKind::Faure(b) => faure::faure(b, dims, width),
            SequenceKind::FaureNet(b, m) => faure::faure_net(b, m, dims, width),
        }
    }

    /// Where the sequence's generator matrices come from.
    pub fn provenance(self) -> Provenance {
        match self {
            SequenceKind::Sobol => Provenance::Published(
                "Sobol (1967) with the Joe–Kuo 6.21201 direction numbers (2008)",
            ),
            SequenceKind::Sz4 => Provenance::ThirdPartyDerived(
                "the 4-D SZ of Ahmed, Pharr, Ostromoukhov, Huang, ACM TOG 44(6), 2025, as \
                 public third-party code fixes it (identity, Pascal P, P4(β), P·P4(β))",
            ),
            SequenceKind::Sz16 => Provenance::Own(
                "first quad the 4-D SZ; the other three quads and the ensemble are gartowen's \
                 own (the paper does not publish them)",
            ),
            SequenceKind::Sz4Faure | SequenceKind::Sz16Faure => Provenance::Own(
                "gartowen's earlier SZ-style reconstruction (GF(4)/GF(16) Faure matrices with \
                 output transforms), kept for reproducing older results",
            ),
            SequenceKind::Faure(_) | SequenceKind::FaureNet(..) => Provenance::Published(
                "Faure (1982) over GF(2^q), generalized by Niederreiter (1987)",
            ),
        }
    }
}

/// Where a sequence's generator matrices come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Provenance {
    /// Defined in a published paper.
    Published(&'static str),
    /// Published in words; the bits follow public third-party code.
    ThirdPartyDerived(&'static str),
    /// gartowen's own construction.
    Own(&'static str),
}

impl Provenance {
    /// `published`, `third-party-derived` or `gartowen's own`.
    pub fn label(self) -> &'static str {
        match self {
            Provenance::Published(_) => "published",
            Provenance::ThirdPartyDerived(_) => "third-party-derived",
            Provenance::Own(_) => "gartowen's own",
        }
    }

    /// The source, in words.
    pub fn source(self) -> &'static str {
        match self {
            Provenance::Published(s) | Provenance::ThirdPartyDerived(s) | Provenance::Own(s) => s,
        }
    }
}

/// The value of `key=V` among `parts`, once; an error names a repeated, unknown or bad key.
fn parameters(name: &str, parts: &[&str], keys: &[&str]) -> Result<Vec<u64>, SeqError> {
    let bad = |why: String| SeqError::UnknownSequence(format!("{name} ({why})"));
    let mut values: Vec<Option<u64>> = vec![None; keys.len()];
    for part in parts {
        let (k, v) = part
            .split_once('=')
            .ok_or_else(|| bad(format!("'{part}' is not key=value")))?;
        let i = keys
            .iter()
            .position(|x| *x == k)
            .ok_or_else(|| bad(format!("unknown parameter '{k}'")))?;
        if values[i].is_some() {
            return Err(bad(format!("'{k}' given twice")));
        }
        values[i] = Some(
            v.parse()
                .map_err(|_| bad(format!("'{v}' is not a number")))?,
        );
    }
    keys.iter()
        .zip(values)
        .map(|(k, v)| v.ok_or_else(|| bad(format!("'{k}=' is required"))))
        .collect()
}

impl FromStr for SequenceKind {
    type Err = SeqError;
    fn from_str(s: &str) -> Result<Self, SeqError> {
        if let Some(k) = SequenceKind::NAMED.into_iter().find(|k| k.name() == s) {
            return Ok(k);
        }
        let mut parts = s.split(':');
        let head = parts.next().unwrap_or("");
        let rest: Vec<&str> = parts.collect();
        let base = |b: u64| {
            PowerOfTwoBase::from_base(b).map_err(|_| {
                SeqError::UnknownSequence(format!("{s} (base {b} is not 2, 4, 8, …, 256)"))
            })
        };
        match head {
            "faure" => {
                let v = parameters(s, &rest, &["base"])?;
                Ok(SequenceKind::Faure(base(v[0])?))
            }
            "faure-net" => {
                let v = parameters(s, &rest, &["base", "m"])?;
                let b = base(v[0])?;
                let m = u32::try_from(v[1])
                    .ok()
                    .filter(|m| (1..=64 / b.q()).contains(m))
                    .ok_or_else(|| {
                        SeqError::UnknownSequence(format!(
                            "{s} (m must be 1..{} in base {})",
                            64 / b.q(),
                            b.base()
                        ))
                    })?;
                Ok(SequenceKind::FaureNet(b, m))
            }
            _ => Err(SeqError::UnknownSequence(s.to_string())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn provenance_says_which_sequences_are_published_and_which_are_ours() {
        let of = |k: SequenceKind| (k.provenance().label(), k.provenance().source());
        assert_eq!(of(SequenceKind::Sobol).0, "published");
        assert!(of(SequenceKind::Sobol).1.contains("Joe–Kuo"));
        assert_eq!(of(SequenceKind::Sz4).0, "third-party-derived");
        assert!(of(SequenceKind::Sz4)
            .1
            .contains("Ahmed, Pharr, Ostromoukhov, Huang"));
        for k in [
            SequenceKind::Sz16,
            SequenceKind::Sz4Faure,
            SequenceKind::Sz16Faure,
        ] {
            assert_eq!(of(k).0, "gartowen's own", "{}", k.name());
        }
        assert!(of(SequenceKind::Sz16).1.contains("first quad the 4-D SZ"));
        assert!(of(SequenceKind::Sz16Faure).1.contains("earlier"));
        assert_eq!(of(SequenceKind::Faure(PowerOfTwoBase::B8)).0, "published");
    }

    #[test]
    fn names_parse_back_and_bad_parameters_are_named() {
        let mut kinds = SequenceKind::NAMED.to_vec();
        let bases: Vec<u32> = SequenceKind::faure_all()
            .iter()
            .map(|k| k.base().base())
            .collect();
        assert_eq!(bases, vec![2, 4, 8, 16, 32, 64, 128, 256]);
        kinds.extend(SequenceKind::faure_all());
        kinds.push(SequenceKind::FaureNet(PowerOfTwoBase::B8, 3));
        for k in kinds {
            assert_eq!(k.name().parse::<SequenceKind>().unwrap(), k);
        }
        assert_eq!(
            "faure:base=256".parse::<SequenceKind>().unwrap().max_dims(),
            256
        );
        let net: SequenceKind = "faure-net:base=8:m=21".parse().unwrap();
        assert_eq!(net.max_dims(), 9);
        assert!("faure-net:base=8:m=22".parse::<SequenceKind>().is_err());
        for (bad, fragment) in [
            ("faure", "'base=' is required"),
            ("faure:base=6", "base 6"),
            ("faure:base=8:base=8", "given twice"),
            ("faure:b=8", "unknown parameter 'b'"),
            ("faure:base=x", "not a number"),
            ("faure-net:base=8", "'m=' is required"),
            ("faure-net:base=8:m=0", "m must be 1..21"),
            ("halton", "unknown sequence 'halton'"),
        ] {
            let e = bad.parse::<SequenceKind>().unwrap_err().to_string();
            assert!(e.contains(fragment), "{bad}: {e}");
        }
    }
}
