//! One ART table, many seeds: the scrambler a renderer ships. `art-owen-16p:table-seed=S` draws
//! its per-symbol tables once from S, and its own seed only keys every dimension's root symbol
//! and shifts ([`ArtOwen::scramble_batch_keyed`]). So the battery's thousands of seeds judge
//! the laws of one fixed table over keys, the question a shared table raises, and every
//! instance shares the one table (a cache keyed by variant, alphabet and table seed).

use crate::{ArtOwen, ArtVariant};
use gartowen_core::{Claim, PowerOfTwoBase, Scrambler, Width};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Tables already drawn, shared by every keyed instance of them.
type TableCache = Mutex<HashMap<(ArtVariant, usize, u64), Arc<ArtOwen>>>;

fn cache() -> &'static TableCache {
    static TABLES: OnceLock<TableCache> = OnceLock::new();
    TABLES.get_or_init(|| Mutex::new(HashMap::new()))
}

/// An ART table drawn from `table_seed`, keyed by `key` (see the module doc).
pub struct KeyedArt {
    art: Arc<ArtOwen>,
    table_seed: u64,
    key: u64,
}

impl KeyedArt {
    /// The table of `variant` with `symbols` symbols drawn from `table_seed` (drawn once per
    /// process and shared), keyed by `key`.
    pub fn new(
        variant: ArtVariant,
        symbols: usize,
        table_seed: u64,
        key: u64,
    ) -> Result<KeyedArt, crate::grammar::GrammarError> {
        let mut tables = cache().lock().unwrap_or_else(|e| e.into_inner());
        let art = match tables.get(&(variant, symbols, table_seed)) {
            Some(art) => art.clone(),
            None => {
                let art = Arc::new(ArtOwen::new(variant, symbols, table_seed)?);
                tables.insert((variant, symbols, table_seed), art.clone());
                art
            }
        };
        Ok(KeyedArt {
            art,
            table_seed,
            key,
        })
    }
}

impl Scrambler for KeyedArt {
    fn name(&self) -> String {
        format!("{}:table-seed={}", self.art.name(), self.table_seed)
    }
    fn base(&self) -> PowerOfTwoBase {
        self.art.base()
    }
    fn claim(&self) -> Claim {
        self.art.claim()
    }
    fn scramble(&self, x: u64, width: Width, dim: u32) -> u64 {
        let mut one = [x];
        self.art
            .scramble_batch_keyed(&mut one, width, dim, self.key);
        one[0]
    }
    fn scramble_batch(&self, words: &mut [u64], width: Width, dim: u32) {
        self.art.scramble_batch_keyed(words, width, dim, self.key)
    }
    fn supports_width(&self, width: Width) -> bool {
        self.art.supports_width(width)
    }
    /// The shared table's bytes (held once, whatever the number of keys).
    fn table_bytes(&self) -> usize {
        self.art.table_bytes()
    }
}
