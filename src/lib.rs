//! gartowen: generate, scramble and verify quasi-Monte Carlo point sets in bases 2^q and,
//! through the base-b oracle and digit words, in every other base b ≥ 3.
//!
//! This facade re-exports the workspace crates and assembles the one scrambler [`registry`].

pub use gartowen_art as art;
pub use gartowen_core as core;
pub use gartowen_discrepancy as discrepancy;
pub use gartowen_netcheck as netcheck;
pub use gartowen_oracles as oracles;
pub use gartowen_owen as owen;
pub use gartowen_seq as seq;
pub use gartowen_verify as battery;

use gartowen_core::Registry;

pub use gartowen_verify::{audit, certificate, external, external_pool, word_sweep};

pub mod generate;
pub mod net_check;
pub mod point_files;
pub mod radix_points;
pub mod reports;
pub mod testing;

/// The conformance battery (`gartowen verify`), from the `gartowen-verify` crate.
pub mod verify {
    pub use gartowen_verify::battery::*;
    pub use gartowen_verify::sampling::{ManySeeds, SeedBuilder};
    pub use gartowen_verify::subtest::{Requirement, SubTest};
    pub use gartowen_verify::{
        collisions, dimensions, family, flip_rank, law_runner, level, marginal, nets, pair_law,
        pair_lemma, stats, structure,
    };
}

/// Every scrambler gartowen knows, in one list; cross-checks iterate over it.
pub fn registry() -> Registry {
    let mut r = Registry::with_core();
    for spec in gartowen_owen::registry::specs()
        .into_iter()
        .chain(gartowen_art::registry::specs())
    {
        r.add(spec);
    }
    r
}

/// Every registry entry as JSON, as `gartowen list --json` prints it: name, base, table bytes
/// (default configuration, seed 0), claim and summary.
pub fn registry_listing() -> Result<Vec<serde_json::Value>, gartowen_core::CoreError> {
    let registry = registry();
    registry
        .specs()
        .iter()
        .map(|spec| {
            let ctx = gartowen_core::BuildContext {
                seed: 0,
                default_base: spec.default_base,
            };
            let s = (spec.build)(&gartowen_core::ScramblerRequest::parse(spec.name)?, &ctx)?;
            let mut row = serde_json::json!({
                "name": spec.name, "base": s.base().base(), "table_bytes": s.table_bytes(),
                "claims_nested_uniform": spec.claim.is_owen(), "claim": spec.claim.to_string(),
                "summary": spec.summary,
            });
            if let Some(memory) = art_memory(spec.name) {
                row.as_object_mut()
                    .expect("an object")
                    .extend(memory.as_object().expect("an object").clone());
            }
            Ok(row)
        })
        .collect()
}

/// An ART variant's memory in the default configuration (256 symbols, seed 0), as `gartowen
/// list --json` adds it: the record a renderer ships (bytes for 32- and 64-bit words, bytes per
/// symbol for 32-bit words), the shared child table, the acceleration tables derived from the
/// record, and, where the generalized paper states one, its ratio of record sizes to Q-ART's
/// beside the measured one. `None` for names that are not ART variants.
pub fn art_memory(name: &str) -> Option<serde_json::Value> {
    use gartowen_art::record::PAPER_RECORD_RATIOS;
    let variant = gartowen_art::registry::variant_of(name)?;
    let symbols = gartowen_art::registry::DEFAULT_SYMBOLS;
    let art = gartowen_art::ArtOwen::new(variant, symbols, 0).expect("the default table builds");
    let record = art.record(gartowen_core::Width::W32);
    let mut out = serde_json::json!({
        "symbols": symbols,
        "record_bytes": record.bytes(),
        "record_bytes_64": art.record(gartowen_core::Width::W64).bytes(),
        "record_bytes_per_symbol": record.bytes_per_symbol(),
        "child_table_bytes": art.grammar().table_bytes(),
        "acceleration_bytes": art.acceleration_bytes(),
    });
    if let Some((_, paper, quote)) = PAPER_RECORD_RATIOS.iter().find(|(n, _, _)| *n == name) {
        let q_art = gartowen_art::ArtOwen::new(gartowen_art::ArtVariant::QArt4, symbols, 0)
            .expect("the default table builds")
            .record(gartowen_core::Width::W32)
            .bytes();
        let extra = serde_json::json!({
            "record_ratio_to_q_art_4": record.bytes() as f64 / q_art as f64,
            "paper_ratio_to_q_art_4": paper,
            "paper_says": quote,
        });
        out.as_object_mut()
            .expect("an object")
            .extend(extra.as_object().expect("an object").clone());
    }
    Some(out)
}
