//! Figure 2a's binary pair at the full report's seeds: sz16 in 16-D under `art-owen-2` and under
//! exact binary Owen (`owen-oracle:base=2`), the mean L2-star D² per N with its standard error,
//! and the ratio with a 95% interval (delta method on the log, independent seeds). The quick
//! report's 16 seeds once showed binary ART 1.5–1.9× binary Owen; this settles it.
//!
//!     cargo run --release -p gartowen-bench --example figure2a_binary [MAX_N]

use gartowen::seq::SequenceKind;
use gartowen_bench::curves::measure_curve;

fn main() {
    let max_n: usize = std::env::args()
        .nth(1)
        .map_or(4096, |a| a.parse().expect("MAX_N: a number of points"));
    let registry = gartowen::registry();
    let art = measure_curve(&registry, SequenceKind::Sz16, "art-owen-2", max_n, false);
    let owen = measure_curve(
        &registry,
        SequenceKind::Sz16,
        "owen-oracle:base=2",
        max_n,
        false,
    );
    println!(
        "| N | seeds | art-owen-2 mean D² ± SE | owen-oracle:base=2 mean D² ± SE | ratio [95%] |"
    );
    println!("|---:|---:|---|---|---|");
    for (k, &n) in art.n.iter().enumerate() {
        let (a, sa, b, sb) = (
            art.joint[k],
            art.joint_se[k],
            owen.joint[k],
            owen.joint_se[k],
        );
        let log_se = ((sa / a).powi(2) + (sb / b).powi(2)).sqrt();
        let r = a / b;
        println!(
            "| {n} | {} | {a:.4e} ± {sa:.1e} | {b:.4e} ± {sb:.1e} | {r:.3} [{:.3}, {:.3}] |",
            art.seeds_at(k),
            r * (-1.96 * log_se).exp(),
            r * (1.96 * log_se).exp()
        );
    }
}
