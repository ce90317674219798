//! Prints the oracle's golden vectors (hex) for tests/golden.rs: outputs for fixed inputs,
//! per base and variant. Regenerate only on a deliberate change of the documented keying.
use gartowen_core::{PowerOfTwoBase, Scrambler, Width};
use gartowen_owen::{FullTreeOwen, OwenVariant};

fn main() {
    let inputs = [0u64, 0x8000_0000, 0x1234_5678, 0xFFFF_FFFF];
    for q in [1u32, 2, 3, 4, 8] {
        for v in OwenVariant::ALL {
            let s = FullTreeOwen::new(PowerOfTwoBase::from_q(q).unwrap(), v, 2024);
            let out: Vec<String> = inputs
                .iter()
                .map(|&x| format!("0x{:08x}", s.scramble(x, Width::W32, 1)))
                .collect();
            let out64 = format!(
                "0x{:016x}",
                s.scramble(0x0123_4567_89ab_cdef, Width::W64, 5)
            );
            println!(
                "        ({q}, OwenVariant::{v:?}, [{}], {out64}),",
                out.join(", ")
            );
        }
    }
}
