//! The certificate reader and the every-word sweep's merge on arbitrary text: parsing, then the
//! pieces a sweep shard carries combined as `verify --merge` combines them. Errors are fine;
//! panics are not.

use gartowen_verify::certificate::Certificate;
use gartowen_verify::word_sweep::{combine, SweepPiece};

fn main() {
    afl::fuzz!(|data: &[u8]| {
        let Ok(text) = std::str::from_utf8(data) else {
            return;
        };
        if let Ok(cert) = Certificate::parse(text) {
            let back = Certificate::parse(&cert.to_json()).expect("a parsed certificate re-parses");
            assert_eq!(back, cert);
            if let Some(pieces) = cert.result["pieces"].as_array() {
                let pieces: Vec<SweepPiece> = pieces
                    .iter()
                    .filter_map(|p| serde_json::from_value(p["piece"].clone()).ok())
                    .collect();
                let _ = combine(&pieces);
            }
        }
        if let Ok(piece) = serde_json::from_str::<SweepPiece>(text) {
            let _ = combine(&[piece]);
        }
    });
}
