//! The ART grammar: alphabet sizes by three paths (brute-force scan of t, Brlek's closed form,
//! the DESIGN list), closure, and the base-2^q rule as q binary steps.

use gartowen_art::grammar::{alphabet_size, alphabet_size_formula, length_for_size, Grammar};
use std::collections::HashSet;

/// Distinct length-L factors of a long Thue–Morse prefix, one byte per letter.
fn brute_force_size(len: usize) -> usize {
    let t: Vec<u8> = (0..(64 * len + 256) as u32)
        .map(|n| (n.count_ones() & 1) as u8)
        .collect();
    t.windows(len.max(1))
        .map(|w| w.to_vec())
        .collect::<HashSet<_>>()
        .len()
}

#[test]
fn alphabet_sizes_are_oeis_a005942_for_l_up_to_64() {
    let design = [1usize, 2, 4, 6, 10, 12, 16, 20, 22, 24, 28, 32];
    for (len, &p) in design.iter().enumerate() {
        assert_eq!(alphabet_size(len), p, "DESIGN value at L = {len}");
    }
    for len in 1..=64 {
        let scan = alphabet_size(len);
        assert_eq!(scan, brute_force_size(len), "L = {len}");
        assert_eq!(scan as u64, alphabet_size_formula(len as u64), "L = {len}");
    }
    assert_eq!(alphabet_size(15), 44, "the 2017 ART table");
}

#[test]
fn power_of_two_sizes_at_l_5_2k_plus_1() {
    for k in 0..=6u32 {
        let len = 5 * (1usize << k) + 1;
        assert_eq!(alphabet_size_formula(len as u64), 1 << (k + 4));
        assert_eq!(length_for_size(1 << (k + 4)).unwrap(), len);
    }
    for k in 0..=3u32 {
        let len = 5 * (1usize << k) + 1;
        assert_eq!(alphabet_size(len), 1 << (k + 4), "scan at L = {len}");
    }
    assert!(length_for_size(45).is_err(), "45 is not an alphabet size");
}

#[test]
fn grammars_are_closed_for_every_q() {
    // Grammar::new fails with NotClosed if any child falls outside the alphabet.
    for len in [1usize, 2, 3, 6, 15, 21, 41] {
        for q in 1..=8 {
            let g = Grammar::new(len, q).unwrap();
            assert_eq!(g.symbols() as usize, alphabet_size(len));
        }
    }
}

#[test]
fn base_2q_rule_is_q_binary_steps_high_bit_first() {
    for len in [3usize, 15, 81] {
        let binary = Grammar::new(len, 1).unwrap();
        for q in 2..=8 {
            let g = Grammar::new(len, q).unwrap();
            for s in 0..g.symbols() {
                for d in 0..(1u32 << q) {
                    let stepped = (0..q)
                        .rev()
                        .fold(s, |sym, bit| binary.child(sym, (d >> bit) & 1));
                    assert_eq!(g.child(s, d), stepped, "L={len} q={q} s={s} d={d}");
                }
            }
        }
    }
}

#[test]
fn sixty_five_thousand_symbols() {
    // At least 2^16 symbols: L = 5·2^12 + 1 gives 65536.
    let len = length_for_size(1 << 16).unwrap();
    let g = Grammar::new(len, 1).unwrap();
    assert_eq!(g.symbols(), 1 << 16);
    // The table keeps children only: 2 per symbol.
    assert_eq!(g.table_bytes(), (1 << 16) * 2 * 4);
}
