//! The generalized paper's Section 4 trade-off as one table: per ART variant, the record a
//! renderer ships ([`gartowen::art::ArtRecord`]), the acceleration tables derived from it, and
//! the time per coordinate of the record-only path (what a GPU kernel or a memory-bound renderer
//! runs) against the batch path (the acceleration tables).
//!
//! Times: 4096 random 32-bit words, dimensions 0..8, in rounds that alternate the two paths so a
//! slow stretch of the machine moves both; each figure is the median over rounds (this machine,
//! this run; compare ratios, not absolute times, across machines).

use crate::fidelity::VarianceRow;
use crate::speed::median;
use gartowen::art::record::PAPER_RECORD_RATIOS;
use gartowen::art::registry::DEFAULT_SYMBOLS;
use gartowen::art::{ArtOwen, ArtRecord, ArtVariant};
use gartowen::core::{Scrambler, SplitMix64, Width};
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// One ART variant's memory and speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TradeoffRow {
    /// Registry name.
    pub scrambler: String,
    /// Base 2^q.
    pub base: u32,
    /// Alphabet size.
    pub symbols: usize,
    /// Record bytes for 32-bit words (packed).
    pub record_bytes: usize,
    /// Record bytes per symbol for 32-bit words.
    pub record_bytes_per_symbol: f64,
    /// Record bytes for 64-bit words.
    pub record_bytes_64: usize,
    /// Record bytes (32-bit words) / those of `q-art-4`.
    pub record_ratio_to_q_art_4: f64,
    /// The paper's statement of that ratio, where it makes one.
    pub paper_ratio_to_q_art_4: Option<f64>,
    /// The shared, static child table's bytes.
    pub child_table_bytes: usize,
    /// The acceleration tables' bytes.
    pub acceleration_bytes: usize,
    /// ns per 32-bit coordinate on the record-only path (median over rounds).
    pub ns_record: f64,
    /// ns per 32-bit coordinate on the batch path (median over rounds).
    pub ns_batch: f64,
}

/// ns per word of `passes` passes of `f` over `words` (dimension = index mod 8).
fn time_ns(words: &[u32], passes: u32, f: &mut dyn FnMut(&mut [u32], u32)) -> f64 {
    let mut buf = words.to_vec();
    let t = Instant::now();
    for _ in 0..passes {
        for (dim, chunk) in buf.chunks_mut(512).enumerate() {
            f(chunk, dim as u32 & 7);
        }
    }
    std::hint::black_box(&buf);
    t.elapsed().as_secs_f64() * 1e9 / (f64::from(passes) * words.len() as f64)
}

/// The trade-off table over every ART variant (256 symbols, seed 1): `rounds` rounds of
/// `passes` passes per path.
pub fn measure_tradeoff_rounds(passes: u32, rounds: usize) -> Vec<TradeoffRow> {
    let mut rng = SplitMix64::new(0x7472_6164); // "trad"
    let words: Vec<u32> = (0..4096).map(|_| rng.next_u32()).collect();
    let q_art_bytes = ArtRecord::draw(ArtVariant::QArt4, DEFAULT_SYMBOLS, 1, Width::W32)
        .expect("the default table builds")
        .bytes();
    ArtVariant::all()
        .into_iter()
        .map(|variant| {
            let art = ArtOwen::new(variant, DEFAULT_SYMBOLS, 1).expect("the default table builds");
            let record = art.record(Width::W32);
            let (mut ns_record, mut ns_batch) = (Vec::new(), Vec::new());
            for _ in 0..rounds {
                ns_record.push(time_ns(&words, passes, &mut |chunk, dim| {
                    for w in chunk.iter_mut() {
                        *w = record.scramble(u64::from(*w), dim) as u32;
                    }
                }));
                ns_batch.push(time_ns(&words, passes, &mut |chunk, dim| {
                    art.scramble_batch_u32(chunk, dim)
                }));
            }
            let name = variant.name();
            TradeoffRow {
                base: 1 << variant.q(),
                symbols: DEFAULT_SYMBOLS,
                record_bytes: record.bytes(),
                record_bytes_per_symbol: record.bytes_per_symbol(),
                record_bytes_64: art.record(Width::W64).bytes(),
                record_ratio_to_q_art_4: record.bytes() as f64 / q_art_bytes as f64,
                paper_ratio_to_q_art_4: PAPER_RECORD_RATIOS
                    .iter()
                    .find(|(n, _, _)| *n == name)
                    .map(|(_, r, _)| *r),
                child_table_bytes: art.grammar().table_bytes(),
                acceleration_bytes: art.acceleration_bytes(),
                ns_record: median(&ns_record),
                ns_batch: median(&ns_batch),
                scrambler: name,
            }
        })
        .collect()
}

/// The report's trade-off table: 2 passes × 3 rounds quick, 8 × 7 full.
pub fn measure_tradeoff(quick: bool) -> Vec<TradeoffRow> {
    if quick {
        measure_tradeoff_rounds(2, 3)
    } else {
        measure_tradeoff_rounds(8, 7)
    }
}

/// The report's section: the trade-off table, with each variant's law profile (`profile(name)`,
/// the `verify --level quick` characters of its node-law and pair-law families) and its
/// variance ratios to Owen at box levels 1–3 from `variance`.
pub fn markdown(
    rows: &[TradeoffRow],
    variance: &[VarianceRow],
    profile: &dyn Fn(&str) -> Option<String>,
) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "\n## Memory and speed: the paper's trade-off\n\n\
         The record is what a renderer must store or ship per table (256 symbols, bit-packed, \
         for 32-bit words; 64-bit words in its own column), in the paper's layouts \
         (`crates/art/src/record.rs`); the child table is shared by every seed and static; the \
         acceleration tables are derived from the record when the scrambler is built. \
         ns/coord: the record-only path (decodes the record at every digit, what a GPU kernel \
         runs) against the batch path (acceleration tables), medians over alternating rounds. \
         Var. ratio: estimator variance / exact Owen variance at box levels 1, 2, 3.\n\n\
         | scrambler | base | record B | B/symbol | record B (64-bit) | × q-art-4 (paper) | child table B | acceleration B | ns record | ns batch | var. ratio 1 / 2 / 3 | node-law / pair-law |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let paper = r
            .paper_ratio_to_q_art_4
            .map_or(String::new(), |p| format!(" (about {p})"));
        let var =
            variance
                .iter()
                .find(|v| v.scrambler == r.scrambler)
                .map_or("–".to_string(), |v| {
                    v.ratio
                        .iter()
                        .map(|x| x.map_or("–".to_string(), |x| format!("{x:.2}")))
                        .collect::<Vec<_>>()
                        .join(" / ")
                });
        md += &format!(
            "| {} | {} | {} | {:.3} | {} | {:.2}{paper} | {} | {} | {:.1} | {:.1} | {var} | {} |\n",
            r.scrambler,
            r.base,
            r.record_bytes,
            r.record_bytes_per_symbol,
            r.record_bytes_64,
            r.record_ratio_to_q_art_4,
            r.child_table_bytes,
            r.acceleration_bytes,
            r.ns_record,
            r.ns_batch,
            profile(&r.scrambler).unwrap_or_else(|| "–".into())
        );
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_has_a_row_with_its_record_and_positive_times() {
        let rows = measure_tradeoff_rounds(1, 1);
        assert_eq!(rows.len(), ArtVariant::all().len());
        let row = |n: &str| rows.iter().find(|r| r.scrambler == n).unwrap();
        assert_eq!(row("q-art-4").record_ratio_to_q_art_4, 1.0);
        assert_eq!(row("art-owen-16p").record_bytes, 3072);
        assert_eq!(row("art-owen-16p").paper_ratio_to_q_art_4, Some(3.0));
        assert_eq!(row("art-owen-8p").paper_ratio_to_q_art_4, Some(1.0));
        assert_eq!(row("art-owen-2").paper_ratio_to_q_art_4, None);
        assert_eq!(row("art-owen-m8").base, 256);
        assert_eq!(row("art-owen-m8").record_bytes_64, 4096);
        for r in &rows {
            assert!(r.ns_record > 0.0 && r.ns_batch > 0.0, "{r:?}");
            assert!(r.acceleration_bytes > r.record_bytes, "{r:?}");
        }
    }
}
