//! gartowen: generate, scramble and verify quasi-Monte Carlo point sets in bases 2^q.
//!
//! This facade re-exports the workspace crates and assembles the one scrambler [`registry`].

pub use gartowen_art as art;
pub use gartowen_core as core;
pub use gartowen_discrepancy as discrepancy;
pub use gartowen_netcheck as netcheck;
pub use gartowen_oracles as oracles;
pub use gartowen_seq as seq;
pub use gartowen_verify as battery;

use gartowen_core::Registry;

pub use gartowen_verify::{certificate, external, external_pool, word_sweep};

pub mod generate;
pub mod net_check;
pub mod reports;
pub mod testing;

/// The conformance battery (`gartowen verify`), from the `gartowen-verify` crate.
pub mod verify {
    pub use gartowen_verify::battery::*;
    pub use gartowen_verify::law::{Requirement, SubTest};
    pub use gartowen_verify::sampling::SeedBuilder;
    pub use gartowen_verify::{dimensions, joint, laws, marginal, nets, pair_lemma, stats};
}

/// Every scrambler gartowen knows, in one list; cross-checks iterate over it.
pub fn registry() -> Registry {
    let mut r = Registry::with_core();
    for spec in gartowen_oracles::registry::specs()
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
            Ok(serde_json::json!({
                "name": spec.name, "base": s.base().base(), "table_bytes": s.table_bytes(),
                "claims_nested_uniform": spec.claim.is_owen(), "claim": spec.claim.to_string(),
                "summary": spec.summary,
            }))
        })
        .collect()
}
