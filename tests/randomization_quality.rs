//! Randomization quality against uniform node permutations, for every registry entry (and ART
//! table sizes 44 and 256): over R independent seeds, the permutation at one fixed node
//! (dimension 0, depth 2, prefix 1), reconstructed from black-box evaluations.
//!
//! Cells: S_b ranks for b ≤ 4, (π(0), π(1)) for b = 8 and 16, π(0) for b ≥ 32. Verdicts use
//! α = 0.001 with Bonferroni over the entries that claim nested uniformity, so a correct family
//! fails with probability ≤ 0.001; seeds are fixed, so the run is deterministic. The affine
//! fraction (share of nodes with π(3) = π(0)⊕π(1)⊕π(2)) is 1 for affine families and 1/(b−3)
//! for uniform S_b, b ≥ 8: it exposes GL(q,2)-based ψ that the pair law cannot (AGL(q,2) is
//! 2-transitive). The table is written to the test's target directory and printed.

use gartowen::core::ScramblerExt;
use gartowen::core::{BuildContext, DigitLayout, Permutation, PowerOfTwoBase, Scrambler, Width};
use gartowen::oracles::inspector::NodeLaw;
use statrs::distribution::{ChiSquared, ContinuousCDF};

const SEEDS: u64 = 3000;

fn node(s: &dyn Scrambler, base: PowerOfTwoBase) -> Permutation {
    let layout = DigitLayout::new(Width::W32, base);
    let prefix = layout.set(0, 1, 1); // digits (0, 1) above the node
    let images: Vec<u8> = (0..base.base())
        .map(|d| layout.get(s.scramble(layout.set(prefix, 2, d), Width::W32, 0), 2) as u8)
        .collect();
    Permutation::from_images(&images).expect("a nested scramble's node map is a bijection")
}

struct Row {
    name: String,
    base: u32,
    claims: bool,
    chi2: f64,
    critical: f64,
    tv: f64,
    affine_fraction: Option<f64>,
    table_bytes: usize,
}

#[test]
fn randomization_quality_table() {
    let registry = gartowen::registry();
    let mut requests: Vec<String> = Vec::new();
    for spec in registry.specs() {
        if spec.name == "none" {
            continue;
        }
        if gartowen::art::registry::variant_of(spec.name).is_some() {
            requests.push(format!("{}:table=44", spec.name));
        }
        requests.push(spec.name.to_string());
    }
    // Controls with known defects: oracle variants that are not uniform over S_b.
    requests.extend(
        [
            "owen-oracle:xor:base=16",
            "owen-oracle:cyclic:base=4",
            "owen-oracle:affine:base=8",
        ]
        .map(String::from),
    );
    let claiming = requests.len(); // Bonferroni family bound (claims are a subset)
    let mut rows = Vec::new();
    for req in &requests {
        let probe = registry.build(req, 0).unwrap();
        let base = probe.base();
        let b = base.base();
        let cells = match b {
            2..=4 => (1..=b as usize).product::<usize>(),
            8 | 16 => (b * (b - 1)) as usize,
            _ => b as usize,
        };
        let mut counts = vec![0u64; cells];
        let mut affine = 0u64;
        for seed in 0..SEEDS {
            let ctx = BuildContext {
                seed,
                default_base: base,
            };
            let s = registry.build_with(req, &ctx).unwrap();
            let p = node(s.as_ref(), base);
            let cell = if b <= 16 {
                NodeLaw::cell(&p)
            } else {
                p.apply(0) as usize
            };
            counts[cell] += 1;
            if b >= 8 {
                affine += (p.apply(3) == p.apply(0) ^ p.apply(1) ^ p.apply(2)) as u64;
            }
        }
        let e = SEEDS as f64 / cells as f64;
        let chi2: f64 = counts.iter().map(|&c| (c as f64 - e).powi(2) / e).sum();
        let tv = 0.5
            * counts
                .iter()
                .map(|&c| (c as f64 / SEEDS as f64 - 1.0 / cells as f64).abs())
                .sum::<f64>();
        let critical = ChiSquared::new((cells - 1) as f64)
            .unwrap()
            .inverse_cdf(1.0 - 1e-3 / claiming as f64);
        rows.push(Row {
            name: probe.name(),
            base: b,
            claims: probe.claims_nested_uniform(),
            chi2,
            critical,
            tv,
            affine_fraction: (b >= 8).then(|| affine as f64 / SEEDS as f64),
            table_bytes: probe.table_bytes(),
        });
    }
    let mut md = String::from(
        "| scrambler | base | claims uniform | chi-square | critical (α=1e-3, Bonferroni) | total variation | affine fraction | table bytes |\n|---|---|---|---|---|---|---|---|\n",
    );
    for r in &rows {
        md += &format!(
            "| {} | {} | {} | {:.1} | {:.1} | {:.3} | {} | {} |\n",
            r.name,
            r.base,
            if r.claims { "yes" } else { "no" },
            r.chi2,
            r.critical,
            r.tv,
            r.affine_fraction
                .map_or("-".to_string(), |a| format!("{a:.3}")),
            r.table_bytes
        );
    }
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("randomization-quality.md");
    std::fs::write(&path, &md).unwrap();
    eprintln!("{md}\nwritten to {}", path.display());

    for r in &rows {
        // Translation-only and shift-like families: visibly non-uniform wherever the cells can
        // see it (b ≤ 16); for b ≥ 8 the affine fraction exposes them as well.
        let translation_only = r.name.starts_with("art-owen-t") && r.base > 2;
        let xor_like = r.name.contains(":xor") || r.name.contains(":cyclic");
        if (translation_only || r.name.contains(":xor")) && r.base >= 8 {
            assert_eq!(
                r.affine_fraction,
                Some(1.0),
                "{} is a translation family",
                r.name
            );
        }
        if r.claims {
            assert!(
                r.chi2 < r.critical,
                "{} claims uniform but chi2 {:.1} ≥ {:.1}",
                r.name,
                r.chi2,
                r.critical
            );
            if let Some(a) = r.affine_fraction {
                assert!(
                    a < 0.5,
                    "{} claims uniform but looks affine ({a:.3})",
                    r.name
                );
            }
        }
        if (translation_only || xor_like) && r.base <= 16 {
            assert!(
                r.tv > 0.5,
                "{} should be visibly non-uniform (TV {:.3})",
                r.name,
                r.tv
            );
        }
        if (r.name.starts_with("art-owen-m") || r.name.contains(":affine")) && r.base >= 8 {
            assert_eq!(r.affine_fraction, Some(1.0), "{} is affine", r.name);
        }
    }
}
