//! The external protocol's decoders on arbitrary bytes: a request frame (the child's side) and
//! a reply of any count and width. They must return an error, never panic or over-allocate.

use gartowen_core::Width;
use gartowen_external::{decode_reply, decode_request, encode_request, ProtocolBase};

fn main() {
    afl::fuzz!(|data: &[u8]| {
        if let Ok((header, words)) = decode_request(data) {
            // A frame that decodes encodes back to the same bytes.
            let again = encode_request(&header, &words).expect("a decoded request re-encodes");
            assert_eq!(again, data);
        }
        let count = data.first().map_or(0, |&b| b as usize);
        for width in [Width::W32, Width::W64] {
            for base in [2, 3, 65_535].map(|b| ProtocolBase::from_base(b).expect("a base")) {
                if let Ok(words) = decode_reply(data, count, width, base, 1) {
                    assert_eq!(words.len(), count);
                    assert!(words.iter().all(|&w| w <= base.largest_word(width)));
                }
            }
        }
    });
}
