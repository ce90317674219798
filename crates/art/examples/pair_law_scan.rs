//! Scans ρ(k, δ) (`gartowen_art::pair_law`) over variants and table sizes.
use gartowen_art::pair_law::shared_child;
use gartowen_art::{ArtOwen, ArtVariant};
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let sizes: Vec<usize> = args.get(1).map_or(vec![256], |s| {
        s.split(',').map(|x| x.parse().unwrap()).collect()
    });
    for variant in ArtVariant::all() {
        for &symbols in &sizes {
            let Ok(art) = ArtOwen::new(variant, symbols, 1) else {
                continue;
            };
            let q = variant.q();
            for depth in 0..8 {
                let mut worst = (0.0f64, 0);
                let mut mean = 0.0;
                for delta in 1..(1u32 << q) {
                    if let Ok(s) = shared_child(art.grammar(), depth, delta) {
                        mean += s.probability() / ((1u32 << q) - 1) as f64;
                        if s.probability() > worst.0 {
                            worst = (s.probability(), delta);
                        }
                    }
                }
                if worst.0 > 0.0 {
                    println!("{variant:?} |Σ| = {}: k = {depth}: max ρ = {:.6} at δ = {}, mean over δ {:.6}", art.grammar().symbols(), worst.0, worst.1, mean);
                }
            }
        }
    }
}
