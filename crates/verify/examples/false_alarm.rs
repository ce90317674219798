//! The battery's false-alarm rate on a true Owen scramble: `RUNS` independent quick runs
//! (seed bases far apart) of the law checks on `NAME`, judged as Owen; prints the number of runs
//! with a failing family and the share of χ² p-values below 0.01, 0.05 and 0.1.
//!
//! `cargo run --release -p gartowen-verify --example false_alarm -- owen-oracle 200`
use gartowen_core::{Claim, Registry};
use gartowen_verify::battery::{judge_families, registry_candidate, Level, Verdict};
use gartowen_verify::law_runner::run_laws;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = args.get(1).map_or("owen-oracle", |s| s.as_str());
    let runs: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(200);
    let mut registry = Registry::with_core();
    for spec in gartowen_owen::registry::specs()
        .into_iter()
        .chain(gartowen_art::registry::specs())
    {
        registry.add(spec);
    }
    let c = registry_candidate(&registry, name, 0).expect("registry name");
    let (mut failed_runs, mut p_values) = (0, Vec::new());
    let t = std::time::Instant::now();
    for run in 0..runs {
        let families = run_laws(&c, Level::Quick, (run + 1) << 40).expect("instances");
        let checks = judge_families(families, Claim::OWEN, 1, 0.0);
        if checks.iter().any(|c| c.verdict == Verdict::Fail) {
            failed_runs += 1;
            for c in checks.iter().filter(|c| c.verdict == Verdict::Fail) {
                println!("run {run}: {}: {}", c.check, c.detail);
            }
        }
        p_values.extend(
            checks
                .iter()
                .flat_map(|c| c.tests.iter())
                .filter(|t| t.dof.is_some())
                .map(|t| t.p_value),
        );
    }
    let n = p_values.len() as f64;
    println!(
        "{name}: {runs} runs in {:.1} s, {failed_runs} with a failing family (stated family-wise level 1e-3)",
        t.elapsed().as_secs_f64()
    );
    for level in [0.01, 0.05, 0.1] {
        let share = p_values.iter().filter(|&&p| p < level).count() as f64 / n;
        println!("  P(p < {level}) = {share:.4} over {n} chi-square sub-tests");
    }
}
