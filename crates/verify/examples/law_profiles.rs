//! Prints the law checks' verdicts and per-depth profile of the ART variants and their
//! deliberate mutants, judged as Owen scrambles (`cargo run --release -p gartowen-verify
//! --example law_profiles`): the real variants depart only where their finite tables show,
//! each mutant departs where its defect is.
use gartowen_art::{ArtMutant, ArtOwen, ArtVariant};
use gartowen_core::{Claim, Scrambler};
use gartowen_verify::battery::{check_candidate, Candidate, Level};

fn main() {
    let mutants = ArtMutant::ALL;
    for variant in [ArtVariant::ArtOwen2, ArtVariant::ArtOwen16P] {
        for mutant in mutants {
            let build = move |seed: u64| {
                ArtOwen::with_mutant(variant, 256, seed, mutant)
                    .map(|s| Box::new(s) as Box<dyn Scrambler>)
                    .map_err(|e| e.to_string())
            };
            let c = Candidate::from_builder(
                format!("{}:{mutant:?}", variant.name()),
                Claim::OWEN,
                Box::new(build),
            )
            .unwrap();
            let r = check_candidate(&c, Level::Quick, 1);
            let verdicts: Vec<String> = r
                .checks
                .iter()
                .map(|c| format!("{}={:?}", c.check, c.verdict))
                .collect();
            println!("{}: {}", r.name, verdicts.join(" "));
            for (family, row) in &r.profile {
                println!("    {family:<11} {row}");
            }
        }
    }
}
