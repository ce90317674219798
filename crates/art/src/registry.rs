//! Registry entries: every ART-Owen variant (`NAME[:table=SYMBOLS]`, default 256 symbols) and
//! the hash peers.

use crate::peers::{DigitalShift, LinearMatrixScramble, LkFlavor, LkHash, PerBitOwen};
use crate::{ArtOwen, ArtVariant, KeyedArt, QArtComposed};
use gartowen_core::registry::BuildContext;
use gartowen_core::{
    Claim, CoreError, NodeGroup, PowerOfTwoBase, Scrambler, ScramblerRequest, ScramblerSpec,
};

/// Default alphabet size (L = 81).
pub const DEFAULT_SYMBOLS: usize = 256;

/// The largest `:table=N` accepted (tables of N × 2^q entries; 2^16 symbols in base 256 is
/// 16 M entries).
pub const MAX_TABLE_SYMBOLS: usize = 1 << 16;

/// The variant a registry name stands for.
pub fn variant_of(name: &str) -> Option<ArtVariant> {
    let q_of = |rest: &str| rest.parse::<u32>().ok().filter(|q| (1..=8).contains(q));
    match name {
        "art-owen-2" => Some(ArtVariant::ArtOwen2),
        "q-art-4" => Some(ArtVariant::QArt4),
        "art-owen-8p" => Some(ArtVariant::ArtOwen8P),
        "art-owen-16p" => Some(ArtVariant::ArtOwen16P),
        _ => {
            if let Some(rest) = name.strip_prefix("art-owen-m") {
                q_of(rest).map(ArtVariant::Matrix)
            } else {
                name.strip_prefix("art-owen-t")
                    .and_then(q_of)
                    .map(ArtVariant::Translation)
            }
        }
    }
}

fn build_art(req: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    let variant = variant_of(&req.name).expect("registered names parse");
    if variant == ArtVariant::QArt4 {
        req.allow_only(&["table", "compose", "table-seed"])?;
    } else {
        req.allow_only(&["table", "table-seed"])?;
    }
    if req.flag("compose") {
        return Err(CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "compose".into(),
            reason: "needs a value: compose=translation or compose=linear".into(),
        });
    }
    let composed = match req.option("compose") {
        None | Some("translation") => false,
        Some("linear") => true,
        Some(other) => {
            return Err(CoreError::InvalidOption {
                scrambler: req.name.clone(),
                option: "compose".into(),
                reason: format!("'{other}': expected translation (the default) or linear"),
            })
        }
    };
    let symbols = match req.option("table") {
        None => DEFAULT_SYMBOLS,
        Some(t) => t.parse().map_err(|_| CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "table".into(),
            reason: format!("'{t}' is not a number of symbols"),
        })?,
    };
    if symbols > MAX_TABLE_SYMBOLS {
        // The grammar's length grows linearly with the symbols and its tables with
        // symbols × base: refuse before building (2^32 symbols once hung for minutes).
        return Err(CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "table".into(),
            reason: format!("{symbols} symbols: at most {MAX_TABLE_SYMBOLS}"),
        });
    }
    let table_seed = match req.option("table-seed") {
        None => None,
        Some(t) => Some(t.parse::<u64>().map_err(|_| CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "table-seed".into(),
            reason: format!("'{t}' is not a seed (an integer in [0, 2^64))"),
        })?),
    };
    if let Some(table_seed) = table_seed {
        if composed {
            return Err(CoreError::InvalidOption {
                scrambler: req.name.clone(),
                option: "table-seed".into(),
                reason: "not with compose=linear (its tables compose ψ along the tree)".into(),
            });
        }
        return KeyedArt::new(variant, symbols, table_seed, ctx.seed)
            .map(|s| Box::new(s) as Box<dyn Scrambler>)
            .map_err(|e| CoreError::InvalidOption {
                scrambler: req.name.clone(),
                option: "table".into(),
                reason: e.to_string(),
            });
    }
    let built = if composed {
        QArtComposed::new(symbols, ctx.seed).map(|s| Box::new(s) as Box<dyn Scrambler>)
    } else {
        ArtOwen::new(variant, symbols, ctx.seed).map(|s| Box::new(s) as Box<dyn Scrambler>)
    };
    built.map_err(|e| CoreError::InvalidOption {
        scrambler: req.name.clone(),
        option: "table".into(),
        reason: e.to_string(),
    })
}

fn build_lk(req: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&[])?;
    let flavor = if req.name == "lk-hash" {
        LkFlavor::Classic
    } else {
        LkFlavor::Improved
    };
    Ok(Box::new(LkHash::new(flavor, ctx.seed)))
}

fn build_per_bit(
    req: &ScramblerRequest,
    ctx: &BuildContext,
) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&[])?;
    Ok(Box::new(PerBitOwen::new(ctx.seed)))
}

fn build_digital_shift(
    req: &ScramblerRequest,
    ctx: &BuildContext,
) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&[])?;
    Ok(Box::new(DigitalShift::new(ctx.seed)))
}

fn build_lms(req: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&[])?;
    Ok(Box::new(LinearMatrixScramble::new(ctx.seed)))
}

const MATRIX_NAMES: [&str; 8] = [
    "art-owen-m1",
    "art-owen-m2",
    "art-owen-m3",
    "art-owen-m4",
    "art-owen-m5",
    "art-owen-m6",
    "art-owen-m7",
    "art-owen-m8",
];
const TRANSLATION_NAMES: [&str; 8] = [
    "art-owen-t1",
    "art-owen-t2",
    "art-owen-t3",
    "art-owen-t4",
    "art-owen-t5",
    "art-owen-t6",
    "art-owen-t7",
    "art-owen-t8",
];

/// Every ART and peer entry.
pub fn specs() -> Vec<ScramblerSpec> {
    let art = |name: &'static str, summary: &'static str| {
        let v = variant_of(name).expect("known");
        ScramblerSpec {
            name,
            default_base: PowerOfTwoBase::from_q(v.q()).expect("q ≤ 8"),
            claim: v.claim(),
            summary,
            build: build_art,
        }
    };
    let mut out = vec![
        art(
            "art-owen-2",
            "binary ART-Owen: XOR codes down the Thue–Morse tree; :table=SYMBOLS",
        ),
        art(
            "q-art-4",
            "Q-ART base 4: psi in GL(2,2) plus codes; :table=SYMBOLS, :compose=linear (psi composed along the tree too)",
        ),
        art(
            "art-owen-8p",
            "base-8 ART-Owen: packed permutation reused as codes; :table=SYMBOLS",
        ),
        art(
            "art-owen-16p",
            "base-16 ART-Owen: packed permutation plus 32-bit code; :table=SYMBOLS, :table-seed=S (one table drawn from S, the seed keying roots and shifts: a renderer's fixed table)",
        ),
    ];
    for name in MATRIX_NAMES {
        out.push(art(
            name,
            "ART-Owen with psi uniform in GL(q,2) plus codes; :table=SYMBOLS",
        ));
    }
    for name in TRANSLATION_NAMES {
        out.push(art(
            name,
            "ART-Owen translation only (nested digital shift); :table=SYMBOLS",
        ));
    }
    for (name, summary) in [
        (
            "lk-hash",
            "Laine–Karras hash on reversed bits (32-bit words)",
        ),
        (
            "lk-hash-improved",
            "improved LK hash on reversed bits (32-bit words)",
        ),
    ] {
        out.push(ScramblerSpec {
            name,
            default_base: PowerOfTwoBase::B2,
            claim: Claim::NESTED,
            summary,
            build: build_lk,
        });
    }
    out.push(ScramblerSpec {
        name: "owen-per-bit-hash",
        default_base: PowerOfTwoBase::B2,
        claim: Claim::OWEN,
        summary: "binary Owen scramble with one hashed flip per bit (pbrt-style)",
        build: build_per_bit,
    });
    out.push(ScramblerSpec {
        name: "digital-shift",
        default_base: PowerOfTwoBase::B2,
        claim: Claim::marginal(NodeGroup::Translation),
        summary: "random digital shift: XOR with one random word per dimension (an imitation)",
        build: build_digital_shift,
    });
    out.push(ScramblerSpec {
        name: "lms-shift",
        default_base: PowerOfTwoBase::B2,
        claim: Claim::marginal(NodeGroup::Translation),
        summary: "random linear matrix scramble + digital shift (SciPy's Sobol scrambling; an imitation)",
        build: build_lms,
    });
    out
}
