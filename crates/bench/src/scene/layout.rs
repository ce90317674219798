//! Sampler layouts: which sequence dimension serves each coordinate of a scene's slots, and the
//! layouts worth measuring (the first slot fixed at dimension 0, the others moved through the
//! pairs and quads of a 16-D sequence, plus scattered ones).

use super::Slot;
use gartowen::core::SplitMix64;
use serde::{Deserialize, Serialize};

/// Dimensions of the sequences the scenes draw from (sz16 has 16).
pub const SEQUENCE_DIMS: usize = 16;

/// Coordinate i of a sample is sequence dimension `dims[i]` (distinct dimensions).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Layout {
    /// Sequence dimension of each coordinate, in slot order.
    pub dims: Vec<usize>,
}

/// A layout that does not fit a scene's slots.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LayoutError {
    /// Not `slot=d[,d…]` items separated by `;`.
    Syntax(String),
    /// A slot the scene does not have.
    UnknownSlot {
        /// The name given.
        name: String,
        /// The scene's slots.
        known: Vec<String>,
    },
    /// A slot left out or named twice.
    SlotCount(String),
    /// A slot given the wrong number of dimensions.
    WrongCount {
        /// The slot.
        slot: String,
        /// Its coordinates.
        expected: usize,
        /// Dimensions given.
        got: usize,
    },
    /// A dimension used twice (the estimate would be biased).
    Repeated(usize),
    /// A dimension past the sequences' last.
    TooHigh(usize),
}

impl std::fmt::Display for LayoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LayoutError::Syntax(s) => write!(
                f,
                "layout item '{s}': expected slot=DIM[,DIM…] items separated by ';' (e.g. 'light=0,1;bsdf=4,5')"
            ),
            LayoutError::UnknownSlot { name, known } => {
                write!(f, "no slot '{name}' (slots: {})", known.join(", "))
            }
            LayoutError::SlotCount(s) => write!(f, "slot '{s}' must be given exactly once"),
            LayoutError::WrongCount {
                slot,
                expected,
                got,
            } => write!(f, "slot '{slot}' reads {expected} dimension(s), {got} given"),
            LayoutError::Repeated(d) => write!(
                f,
                "dimension {d} serves two coordinates (they would be identical, the estimate biased)"
            ),
            LayoutError::TooHigh(d) => write!(
                f,
                "dimension {d}: the scene sequences have dimensions 0..{}",
                SEQUENCE_DIMS - 1
            ),
        }
    }
}

impl std::error::Error for LayoutError {}

/// Where the other slots sit relative to the first slot's dimensions, in the pair/quad
/// structure of a base-16 sequence (sz16 builds dimensions in pairs 2i, 2i+1 and quads
/// 4i..4i+3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Relation {
    /// Some other coordinate shares a pair with the first slot.
    SamePair,
    /// None shares a pair, some shares a quad.
    SameQuad,
    /// All other coordinates lie in other quads.
    AcrossQuads,
}

impl Relation {
    /// `same pair`, `same quad` or `across quads`.
    pub fn words(self) -> &'static str {
        match self {
            Relation::SamePair => "same pair",
            Relation::SameQuad => "same quad",
            Relation::AcrossQuads => "across quads",
        }
    }
}

impl Layout {
    /// Dimensions 0, 1, …: the naive renderer's layout.
    pub fn packed(coordinates: usize) -> Layout {
        Layout {
            dims: (0..coordinates).collect(),
        }
    }

    /// Parses `slot=d[,d…];…` naming every slot once.
    pub fn parse(text: &str, slots: &[Slot]) -> Result<Layout, LayoutError> {
        let mut given: Vec<Option<Vec<usize>>> = vec![None; slots.len()];
        for item in text.split(';').map(str::trim).filter(|s| !s.is_empty()) {
            let (name, dims) = item
                .split_once('=')
                .ok_or_else(|| LayoutError::Syntax(item.into()))?;
            let name = name.trim();
            let k = slots.iter().position(|s| s.name == name).ok_or_else(|| {
                LayoutError::UnknownSlot {
                    name: name.into(),
                    known: slots.iter().map(|s| s.name.to_string()).collect(),
                }
            })?;
            if given[k].is_some() {
                return Err(LayoutError::SlotCount(name.into()));
            }
            let parsed: Result<Vec<usize>, _> =
                dims.split(',').map(|d| d.trim().parse::<usize>()).collect();
            let parsed = parsed.map_err(|_| LayoutError::Syntax(item.into()))?;
            if parsed.len() != slots[k].dims {
                return Err(LayoutError::WrongCount {
                    slot: name.into(),
                    expected: slots[k].dims,
                    got: parsed.len(),
                });
            }
            given[k] = Some(parsed);
        }
        let mut dims = Vec::new();
        for (slot, g) in slots.iter().zip(given) {
            dims.extend(g.ok_or_else(|| LayoutError::SlotCount(slot.name.into()))?);
        }
        let layout = Layout { dims };
        layout.validate()?;
        Ok(layout)
    }

    /// Distinct dimensions below [`SEQUENCE_DIMS`].
    pub fn validate(&self) -> Result<(), LayoutError> {
        for (i, &d) in self.dims.iter().enumerate() {
            if d >= SEQUENCE_DIMS {
                return Err(LayoutError::TooHigh(d));
            }
            if self.dims[..i].contains(&d) {
                return Err(LayoutError::Repeated(d));
            }
        }
        Ok(())
    }

    /// `slot=d,d;…`, the form [`Layout::parse`] reads.
    pub fn describe(&self, slots: &[Slot]) -> String {
        let mut at = 0;
        slots
            .iter()
            .map(|s| {
                let d: Vec<String> = self.dims[at..at + s.dims]
                    .iter()
                    .map(|d| d.to_string())
                    .collect();
                at += s.dims;
                format!("{}={}", s.name, d.join(","))
            })
            .collect::<Vec<_>>()
            .join(";")
    }

    /// Where the other slots' dimensions sit relative to the first slot's.
    pub fn relation(&self, slots: &[Slot]) -> Relation {
        let first = slots.first().map_or(0, |s| s.dims);
        let (head, rest) = self.dims.split_at(first.min(self.dims.len()));
        let shares = |group: usize| {
            rest.iter()
                .any(|&d| head.iter().any(|&h| h / group == d / group))
        };
        if shares(2) {
            Relation::SamePair
        } else if shares(4) {
            Relation::SameQuad
        } else {
            Relation::AcrossQuads
        }
    }
}

/// The layouts worth measuring for `slots`: the first slot at dimensions 0.. and the other
/// coordinates contiguous from each possible start j (so they meet the first slot in its pair,
/// its quad, and every other quad), then `scattered` layouts with every coordinate placed at
/// random (seeded), skipping repeats.
pub fn candidate_layouts(slots: &[Slot], scattered: usize, seed: u64) -> Vec<Layout> {
    let k: usize = slots.iter().map(|s| s.dims).sum();
    let head = slots.first().map_or(0, |s| s.dims);
    let mut out: Vec<Layout> = Vec::new();
    for j in head..=SEQUENCE_DIMS.saturating_sub(k - head) {
        let layout = Layout {
            dims: (0..head).chain(j..j + (k - head)).collect(),
        };
        // A scene of one slot has one such layout, whatever j.
        if !out.contains(&layout) {
            out.push(layout);
        }
    }
    let mut rng = SplitMix64::new(seed);
    let mut tries = 0;
    let wanted = out.len() + scattered;
    while out.len() < wanted && tries < 100 * (scattered + 1) {
        tries += 1;
        // A partial Fisher–Yates shuffle of 0..16 picks k distinct dimensions.
        let mut pool: Vec<usize> = (0..SEQUENCE_DIMS).collect();
        for i in 0..k {
            let r = i + (rng.next_u64() % (SEQUENCE_DIMS - i) as u64) as usize;
            pool.swap(i, r);
        }
        let layout = Layout {
            dims: pool[..k].to_vec(),
        };
        if !out.contains(&layout) {
            out.push(layout);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const SLOTS: &[Slot] = &[
        Slot {
            name: "roulette",
            dims: 1,
        },
        Slot {
            name: "bounce",
            dims: 2,
        },
    ];

    #[test]
    fn parse_and_describe_round_trip() {
        let l = Layout::parse("bounce=5,6; roulette=0", SLOTS).unwrap();
        assert_eq!(l.dims, vec![0, 5, 6]);
        assert_eq!(l.describe(SLOTS), "roulette=0;bounce=5,6");
        assert_eq!(Layout::parse(&l.describe(SLOTS), SLOTS).unwrap(), l);
    }

    #[test]
    fn bad_layouts_are_named() {
        let e = |t| Layout::parse(t, SLOTS).unwrap_err();
        assert!(matches!(e("roulette=0"), LayoutError::SlotCount(s) if s == "bounce"));
        assert!(matches!(
            e("roulette=0;bounce=1"),
            LayoutError::WrongCount { got: 1, .. }
        ));
        assert!(matches!(
            e("roulette=0;bounce=0,1"),
            LayoutError::Repeated(0)
        ));
        assert!(matches!(
            e("roulette=16;bounce=0,1"),
            LayoutError::TooHigh(16)
        ));
        assert!(matches!(
            e("lens=0;bounce=1,2"),
            LayoutError::UnknownSlot { .. }
        ));
        assert!(matches!(e("roulette 0"), LayoutError::Syntax(_)));
        assert!(matches!(e("roulette=x;bounce=1,2"), LayoutError::Syntax(_)));
        assert!(matches!(
            e("roulette=0;roulette=1;bounce=2,3"),
            LayoutError::SlotCount(_)
        ));
        assert!(e("lens=0").to_string().contains("roulette, bounce"));
    }

    #[test]
    fn relations_follow_pairs_and_quads() {
        let r = |d: &[usize]| Layout { dims: d.to_vec() }.relation(SLOTS);
        assert_eq!(r(&[0, 1, 2]), Relation::SamePair);
        assert_eq!(r(&[0, 2, 3]), Relation::SameQuad);
        assert_eq!(r(&[0, 4, 5]), Relation::AcrossQuads);
        assert_eq!(r(&[5, 3, 4]), Relation::SamePair);
        assert_eq!(r(&[5, 6, 8]), Relation::SameQuad);
        assert_eq!(r(&[9, 8, 0]), Relation::SamePair);
        assert_eq!(r(&[14, 12, 1]), Relation::SameQuad);
        assert_eq!(r(&[14, 3, 1]), Relation::AcrossQuads);
        let words = [
            Relation::SamePair.words(),
            Relation::SameQuad.words(),
            Relation::AcrossQuads.words(),
        ];
        assert_eq!(words, ["same pair", "same quad", "across quads"]);
    }

    #[test]
    fn candidates_cover_every_start_and_are_valid() {
        let c = candidate_layouts(SLOTS, 3, 1);
        // Starts 1..=14 for the bounce pair, then 3 scattered layouts.
        assert_eq!(c.len(), 14 + 3);
        assert_eq!(c[0].dims, vec![0, 1, 2]);
        assert_eq!(c[13].dims, vec![0, 14, 15]);
        for l in &c {
            l.validate().unwrap();
        }
        for (i, a) in c.iter().enumerate() {
            assert!(!c[..i].contains(a));
        }
        let rel: Vec<Relation> = c[..14].iter().map(|l| l.relation(SLOTS)).collect();
        assert!(rel.contains(&Relation::SamePair));
        assert!(rel.contains(&Relation::SameQuad));
        assert!(rel.contains(&Relation::AcrossQuads));
        assert_eq!(candidate_layouts(SLOTS, 3, 1), c);
    }

    #[test]
    fn a_one_coordinate_scene_gets_each_dimension_once_and_the_search_ends() {
        const ONE: &[Slot] = &[Slot { name: "u", dims: 1 }];
        // Only 16 layouts exist; asking for more ends when the tries run out.
        let c = candidate_layouts(ONE, 40, 5);
        let mut dims: Vec<usize> = c.iter().map(|l| l.dims[0]).collect();
        dims.sort_unstable();
        assert_eq!(dims, (0..16).collect::<Vec<_>>());
    }
}
