//! The paper's "no noticeable difference from full-tree Owen", as verdicts: each ART variant
//! against the Owen scramble of its base, by the two-one-sided-tests equivalence judgement of
//! [`gartowen::battery::equivalence`] (margin ±δ on a ratio, level α, Bonferroni over each
//! variant's statistics for "different"), on
//!
//! - **variance**: the estimator-variance ratio to the exact Owen variance at box levels 1–3
//!   ([`crate::fidelity`]; the reference is exact, so only the variant's standard error counts),
//!   at the levels with enough expected hits to judge ([`MIN_EXPECTED_HITS`]);
//! - **diagonal moments**: the second and fourth moments of the error of the diagonal-cell
//!   estimates against their exact Owen values ([`gartowen::battery::diagonal_cells`]): the
//!   fourth sees 4-point laws, where AGL(q,2) and dimension pairs sharing a table path differ
//!   from Owen while every variance agrees;
//! - **D²**: the mean L2-star D² of sz16 jointly in 16-D and of every pair (0, j), at each N of
//!   the discrepancy curves, against the curve of `owen-oracle:base=B` with its own seeds
//!   (independent means: delta method on the log ratio).
//!
//! The [`CONTROLS`] are judged the same way, so that the section shows each statistic failing
//! where it should: the binary digital shift on the coordinate mean, the AGL-only Owen scramble
//! on the fourth diagonal moment.

use crate::curves::DiscrepancyCurve;
use crate::fidelity::VarianceRow;
use gartowen::art::registry::variant_of;
use gartowen::battery::diagonal_cells::{owen_translate_rate, ORDERS};
use gartowen::battery::equivalence::{
    judge, ratio_of_means, Equivalence, EquivalenceSettings, EquivalenceVerdict,
};
use gartowen::battery::owen_equivalence::{expected_hits, MIN_EXPECTED_HITS};
use serde::{Deserialize, Serialize};

/// One statistic's equivalence verdict.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EquivalenceRow {
    /// The ART variant (registry request).
    pub scrambler: String,
    /// What it is compared with.
    pub reference: String,
    /// The statistic: `variance level K`, `D² joint 16-D` or `D² pair (0,j)`.
    pub statistic: String,
    /// Points, for D² statistics.
    pub n: Option<usize>,
    /// The judgement.
    pub result: Equivalence,
}

/// One statistic before judging: ratio, its log standard error and the seeds behind it.
struct Candidate {
    scrambler: String,
    reference: String,
    statistic: String,
    n: Option<usize>,
    ratio: f64,
    log_se: f64,
    seeds: u64,
}

/// The base 2^q of an ART registry request (options after `:` ignored).
fn art_base(request: &str) -> Option<u32> {
    variant_of(request.split(':').next()?).map(|v| 1 << v.q())
}

/// Controls judged beside the ART variants, each with its base, to show what each statistic
/// sees: a binary digital shift (Owen's box variances and mean D², not its coordinate mean's
/// variance) and Owen with every node uniform over AGL(4,2) instead of S_16 (Owen's every
/// variance, not the fourth diagonal moment).
pub const CONTROLS: [(&str, u32); 2] = [("digital-shift", 2), ("owen-oracle:affine:base=16", 16)];

/// The base a variance row is judged in: an ART variant's, or a control's.
fn judged_base(request: &str) -> Option<u32> {
    art_base(request).or_else(|| {
        CONTROLS
            .iter()
            .find(|(name, _)| *name == request)
            .map(|(_, base)| *base)
    })
}

/// A variance row's judgeable statistics (name, ratio to Owen, its standard error): the
/// coordinate means, and the box levels with at least [`MIN_EXPECTED_HITS`] expected hits at
/// `seeds` seeds.
fn row_statistics(row: &VarianceRow, seeds: u64) -> Vec<(String, f64, f64)> {
    let q = row.base.trailing_zeros();
    let means = row
        .mean_ratio
        .iter()
        .zip(&row.mean_ratio_se)
        .enumerate()
        .map(|(dim, (r, se))| (format!("variance of the mean, dim {dim}"), *r, *se));
    let diagonal = ORDERS
        .iter()
        .zip(row.diagonal_ratio.iter().zip(&row.diagonal_ratio_se))
        .map(|(order, (r, se))| (format!("diagonal moment {order}"), *r, *se));
    let boxes = row.levels.iter().enumerate().filter_map(move |(k, level)| {
        if expected_hits(seeds, q, *level) < MIN_EXPECTED_HITS {
            return None;
        }
        let (Some(Some(r)), Some(Some(se))) = (row.ratio.get(k), row.ratio_se.get(k)) else {
            return None;
        };
        Some((format!("variance box level {level}"), *r, *se))
    });
    means.chain(diagonal).chain(boxes).collect()
}

fn variance_candidates(rows: &[VarianceRow]) -> Vec<Candidate> {
    let mut out = Vec::new();
    for row in rows.iter().filter(|r| judged_base(&r.scrambler).is_some()) {
        for (statistic, ratio, se) in row_statistics(row, row.seeds) {
            out.push(Candidate {
                scrambler: row.scrambler.clone(),
                reference: format!("exact Owen variance, base {}", row.base),
                statistic,
                n: None,
                ratio,
                log_se: se / ratio,
                seeds: row.seeds,
            });
        }
    }
    out
}

fn discrepancy_candidates(curves: &[DiscrepancyCurve]) -> Vec<Candidate> {
    let mut out = Vec::new();
    for c in curves {
        let Some(base) = art_base(&c.scrambler) else {
            continue;
        };
        let direct = DIRECT_COMPARISONS
            .iter()
            .find(|(n, _)| *n == c.scrambler)
            .map(|(_, r)| r.to_string());
        for reference in std::iter::once(format!("owen-oracle:base={base}")).chain(direct) {
            let Some(r) = curves.iter().find(|o| o.scrambler == reference) else {
                continue;
            };
            compare_curves(c, r, &reference, &mut out);
        }
    }
    out
}

/// The D² statistics of curve `c` against curve `r` (named `reference`) at their common sizes.
fn compare_curves(
    c: &DiscrepancyCurve,
    r: &DiscrepancyCurve,
    reference: &str,
    out: &mut Vec<Candidate>,
) {
    for (k, &n) in c.n.iter().enumerate() {
        let Some(j) = r.n.iter().position(|&m| m == n) else {
            continue;
        };
        let seeds = c.seeds_at(k).min(r.seeds_at(j)) as u64;
        let mut push = |statistic: String, a: f64, sa: f64, b: f64, sb: f64| {
            if let Some((ratio, log_se)) = ratio_of_means(a, sa, b, sb) {
                out.push(Candidate {
                    scrambler: c.scrambler.clone(),
                    reference: reference.to_string(),
                    statistic,
                    n: Some(n),
                    ratio,
                    log_se,
                    seeds,
                });
            }
        };
        let se = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(f64::NAN);
        push(
            "D² joint 16-D".into(),
            c.joint[k],
            se(&c.joint_se, k),
            r.joint[j],
            se(&r.joint_se, j),
        );
        for (p, pair) in c.pairs.iter().enumerate() {
            let Some(q) = r.pairs.iter().position(|x| x == pair) else {
                continue;
            };
            let sa = c.pair_se.get(k).map_or(f64::NAN, |v| se(v, p));
            let sb = r.pair_se.get(j).map_or(f64::NAN, |v| se(v, q));
            push(
                format!("D² pair ({},{})", pair[0], pair[1]),
                c.pair_values[k][p],
                sa,
                r.pair_values[j][q],
                sb,
            );
        }
    }
}

/// Variants judged against another ART variant as well as against Owen: (variant, reference).
pub const DIRECT_COMPARISONS: [(&str, &str); 1] = [("q-art-4:compose=linear", "q-art-4")];

/// The variance statistics of `row` against those of `reference` (independent seeds of two
/// implementations: delta method), for [`DIRECT_COMPARISONS`].
fn direct_variance_candidates(rows: &[VarianceRow]) -> Vec<Candidate> {
    let mut out = Vec::new();
    for (name, reference) in DIRECT_COMPARISONS {
        let (Some(a), Some(b)) = (
            rows.iter().find(|r| r.scrambler == name),
            rows.iter().find(|r| r.scrambler == reference),
        ) else {
            continue;
        };
        let seeds = a.seeds.min(b.seeds);
        let theirs = row_statistics(b, seeds);
        for (statistic, ra, sa) in row_statistics(a, seeds) {
            let Some((_, rb, sb)) = theirs.iter().find(|(s, _, _)| *s == statistic) else {
                continue;
            };
            if let Some((ratio, log_se)) = ratio_of_means(ra, sa, *rb, *sb) {
                out.push(Candidate {
                    scrambler: name.into(),
                    reference: reference.into(),
                    statistic,
                    n: None,
                    ratio,
                    log_se,
                    seeds,
                });
            }
        }
    }
    out
}

/// Every equivalence verdict of the report: each ART variant's statistics judged with margin
/// `margin` and level `alpha`, "different" corrected over that variant's statistics.
pub fn equivalence_rows(
    variance: &[VarianceRow],
    curves: &[DiscrepancyCurve],
    margin: f64,
    alpha: f64,
) -> Vec<EquivalenceRow> {
    let mut all = variance_candidates(variance);
    all.extend(direct_variance_candidates(variance));
    all.extend(discrepancy_candidates(curves));
    all.iter()
        .map(|c| {
            let family = all.iter().filter(|o| o.scrambler == c.scrambler).count();
            let settings =
                EquivalenceSettings::new(margin, alpha, family).expect("valid report settings");
            EquivalenceRow {
                scrambler: c.scrambler.clone(),
                reference: c.reference.clone(),
                statistic: c.statistic.clone(),
                n: c.n,
                result: judge(c.ratio, c.log_se, c.seeds, settings),
            }
        })
        .collect()
}

/// The report's section: the settings, a per-variant summary and every verdict on the
/// variance and joint statistics (pairs are summarized; report.json has each one).
pub fn markdown(rows: &[EquivalenceRow]) -> String {
    let Some(first) = rows.first() else {
        return String::new();
    };
    let s = first.result.settings;
    let mut md = format!(
        "\n## Equivalence to full-tree Owen\n\n\
         Each ART variant, a renderer's fixed table (`{fixed}`: one table, each seed keying \
         roots and shifts only), and each control (a binary digital shift; Owen with AGL(4,2) \
         nodes), against the Owen scramble of its base, as a ratio (variant / Owen). \
         **equivalent within ±{pct:.0}%**: the {tost:.0}% interval of the ratio lies inside \
         [{lo:.2}, {hi:.2}] (two one-sided tests at level α = {a}; the verdict for all of a \
         variant's statistics together needs no correction). **different**: the two-sided \
         interval at level α/m excludes 1, m = the variant's number of statistics (Bonferroni: \
         at most α false 'different' per variant). **inconclusive**: neither; the seeds that would \
         decide it at the current estimate are named. 'Detectable' is the change the difference \
         test finds with 80% power. Variance: the variance over seeds of the coordinate mean \
         (which sees the joint law inside a dimension) and of box-volume estimates (levels 1–3, \
         where enough points are expected: these see only nestedness and uniform outputs) \
         against the exact Owen values; diagonal moments: the second and fourth moments of the \
         error of b-point diagonal-cell estimates over 16 dimension pairs (the fourth reads \
         4-point laws, which every variance misses: AGL(q,2) has 5/4 of Owen's, and so does \
         a pair of dimensions whose scrambles are translates); D²: the mean L2-star D² of sz16 against \
         `owen-oracle` of the same base with its own seeds.\n\n\
         | scrambler | equivalent | different | inconclusive |\n|---|---|---|---|\n",
        fixed = crate::curves::FIXED_TABLE,
        pct = s.margin * 100.0,
        tost = (1.0 - 2.0 * s.alpha) * 100.0,
        lo = 1.0 - s.margin,
        hi = 1.0 + s.margin,
        a = s.alpha,
    );
    let mut names: Vec<&str> = Vec::new();
    for r in rows {
        if !names.contains(&r.scrambler.as_str()) {
            names.push(&r.scrambler);
        }
    }
    for name in &names {
        let count = |v: EquivalenceVerdict| {
            rows.iter()
                .filter(|r| r.scrambler == *name && r.result.verdict == v)
                .count()
        };
        md += &format!(
            "| {name} | {} | {} | {} |\n",
            count(EquivalenceVerdict::Equivalent),
            count(EquivalenceVerdict::Different),
            count(EquivalenceVerdict::Inconclusive)
        );
    }
    md += "\n| scrambler | statistic | N | seeds | ratio | 90% interval | detectable | verdict |\n\
           |---|---|---|---|---|---|---|---|\n";
    for r in rows.iter().filter(|r| !r.statistic.starts_with("D² pair")) {
        let e = &r.result;
        md += &format!(
            "| {} | {} | {} | {} | {:.3} | [{:.3}, {:.3}] | ±{:.0}% | {} |\n",
            r.scrambler,
            r.statistic,
            r.n.map_or("–".into(), |n| n.to_string()),
            e.seeds,
            e.ratio,
            e.tost_interval[0],
            e.tost_interval[1],
            e.detectable * 100.0,
            e.words()
        );
    }
    md
}

/// The translate-pair diagnosis of the fourth diagonal moment, one row per variance row in
/// base ≥ 8: how often a pair of dimensions got scrambles that are translates of each other at
/// the top digit (Owen's probability is b/b!, 7.6e-13 per pair in base 16).
pub fn translate_markdown(rows: &[VarianceRow]) -> String {
    let mut md = String::new();
    for r in rows {
        let Some([translates, pairs]) = r.translate_pairs else {
            continue;
        };
        if md.is_empty() {
            md += "\nDimension pairs whose two scrambles were translates of each other at the top \
                   digit (all b diagonal-cell points on one diagonal), which the fourth diagonal \
                   moment weighs most: an ART table that gives two dimensions the same root \
                   symbol does this in a fraction of them.\n\n\
                   | scrambler | translate pairs | pairs read | per pair | Owen's per pair |\n\
                   |---|---|---|---|---|\n";
        }
        let owen = owen_translate_rate(r.base);
        md += &format!(
            "| {} | {translates} | {pairs} | {:.2e} | {owen:.2e} |\n",
            r.scrambler,
            translates as f64 / pairs.max(1) as f64
        );
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(name: &str, joint: f64, se: f64, seeds: usize) -> DiscrepancyCurve {
        DiscrepancyCurve {
            scrambler: name.into(),
            n: vec![16, 32],
            joint: vec![joint, joint / 2.0],
            pairs: vec![[0, 1]],
            pair_values: vec![vec![joint], vec![joint / 2.0]],
            seeds,
            joint_se: vec![se, se / 2.0],
            pair_se: vec![vec![se], vec![se / 2.0]],
            seeds_per_n: vec![],
        }
    }

    #[test]
    fn each_art_curve_is_judged_against_the_oracle_of_its_base() {
        let curves = vec![
            curve("art-owen-16p", 1.02, 0.005, 1000),
            curve("owen-oracle:base=16", 1.0, 0.005, 1000),
            curve("art-owen-2", 1.5, 0.005, 1000),
            curve("owen-oracle:base=2", 1.0, 0.005, 1000),
            curve("lk-hash", 3.0, 0.005, 1000),
        ];
        let rows = equivalence_rows(&[], &curves, 0.1, 0.05);
        // Two ART curves × two sizes × (joint + one pair); lk-hash and the oracles are not judged.
        assert_eq!(rows.len(), 8);
        assert!(rows
            .iter()
            .filter(|r| r.scrambler == "art-owen-16p")
            .all(|r| r.reference == "owen-oracle:base=16"
                && r.result.verdict == EquivalenceVerdict::Equivalent));
        assert!(rows
            .iter()
            .filter(|r| r.scrambler == "art-owen-2")
            .all(|r| r.result.verdict == EquivalenceVerdict::Different));
        // The family is the variant's own statistics: 4.
        assert!(rows.iter().all(|r| r.result.settings.family == 4));
        let md = markdown(&rows);
        assert!(md.contains("| art-owen-16p | 4 | 0 | 0 |"), "{md}");
        assert!(md.contains("| art-owen-2 | 0 | 4 | 0 |"), "{md}");
        assert_eq!(
            md.matches("| art-owen-2 | 0 | 4 | 0 |").count(),
            1,
            "one summary row each"
        );
    }

    #[test]
    fn variance_rows_are_judged_against_the_exact_variance() {
        let rows = vec![VarianceRow {
            scrambler: "q-art-4".into(),
            base: 4,
            seeds: 1000,
            levels: vec![1, 2, 3],
            ratio: vec![Some(1.0), Some(1.4), None],
            ratio_se: vec![Some(0.02), Some(0.03), None],
            mean_ratio: vec![0.5, 1.01],
            mean_ratio_se: vec![0.01, 0.01],
            diagonal_ratio: vec![],
            diagonal_ratio_se: vec![],
            translate_pairs: None,
        }];
        let out = equivalence_rows(&rows, &[], 0.1, 0.05);
        assert_eq!(
            out.len(),
            4,
            "two means, and a level without a ratio is skipped"
        );
        assert_eq!(out[0].statistic, "variance of the mean, dim 0");
        assert_eq!(out[0].result.verdict, EquivalenceVerdict::Different);
        assert_eq!(out[1].result.verdict, EquivalenceVerdict::Equivalent);
        assert_eq!(out[2].result.verdict, EquivalenceVerdict::Equivalent);
        assert_eq!(out[3].result.verdict, EquivalenceVerdict::Different);
        assert!((out[3].result.log_se - 0.03 / 1.4).abs() < 1e-12);
        assert_eq!(out[2].reference, "exact Owen variance, base 4");
    }

    #[test]
    fn diagonal_moments_and_controls_are_judged() {
        let row = |name: &str, base: u32, fourth: f64| VarianceRow {
            scrambler: name.into(),
            base,
            seeds: 10_000,
            levels: vec![],
            ratio: vec![],
            ratio_se: vec![],
            mean_ratio: vec![],
            mean_ratio_se: vec![],
            diagonal_ratio: vec![1.0, fourth],
            diagonal_ratio_se: vec![0.005, 0.02],
            translate_pairs: None,
        };
        let rows = vec![
            row("owen-oracle:affine:base=16", 16, 1.25),
            row("art-owen-16p", 16, 1.0),
            row("lk-hash", 2, 3.0),
        ];
        let out = equivalence_rows(&rows, &[], 0.1, 0.05);
        // The control and the ART variant, two moments each; lk-hash is neither.
        assert_eq!(out.len(), 4, "{out:?}");
        let verdict = |name: &str, statistic: &str| {
            out.iter()
                .find(|r| r.scrambler == name && r.statistic == statistic)
                .unwrap()
                .result
                .verdict
        };
        use EquivalenceVerdict::*;
        assert_eq!(
            verdict("owen-oracle:affine:base=16", "diagonal moment 2"),
            Equivalent
        );
        assert_eq!(
            verdict("owen-oracle:affine:base=16", "diagonal moment 4"),
            Different
        );
        assert_eq!(verdict("art-owen-16p", "diagonal moment 4"), Equivalent);
        assert_eq!(out[0].reference, "exact Owen variance, base 16");
        assert_eq!(judged_base("digital-shift"), Some(2));
        assert_eq!(judged_base("lms-shift"), None);
        // The diagnosis table lists the rows that carry one.
        let mut with = row("art-owen-16p", 16, 1.2);
        with.translate_pairs = Some([35, 160_000]);
        let md = translate_markdown(&[row("art-owen-2", 2, 1.0), with]);
        assert!(
            md.contains("| art-owen-16p | 35 | 160000 | 2.19e-4 | 7.65e-13 |"),
            "{md}"
        );
        assert!(!md.contains("art-owen-2"));
        assert_eq!(translate_markdown(&[row("art-owen-2", 2, 1.0)]), "");
    }

    #[test]
    fn composed_q_art_is_also_judged_against_q_art() {
        let row = |name: &str, mean: f64| VarianceRow {
            scrambler: name.into(),
            base: 4,
            seeds: 8000,
            levels: vec![1, 2, 3],
            ratio: vec![Some(1.0), Some(1.0), Some(1.0)],
            ratio_se: vec![Some(0.01), Some(0.01), Some(0.01)],
            mean_ratio: vec![mean, 1.0],
            mean_ratio_se: vec![0.01, 0.01],
            diagonal_ratio: vec![],
            diagonal_ratio_se: vec![],
            translate_pairs: None,
        };
        let rows = vec![row("q-art-4", 1.0), row("q-art-4:compose=linear", 1.3)];
        let curves = vec![
            curve("q-art-4", 1.0, 0.005, 1000),
            curve("q-art-4:compose=linear", 1.01, 0.005, 1000),
            curve("owen-oracle:base=4", 1.0, 0.005, 1000),
        ];
        let out = equivalence_rows(&rows, &curves, 0.1, 0.05);
        let direct: Vec<_> = out.iter().filter(|r| r.reference == "q-art-4").collect();
        // Two means and three box levels (8000 seeds: level 3 has 8,000 expected hits), then
        // two sizes × (joint + one pair) of D².
        assert_eq!(direct.len(), 5 + 4, "{direct:?}");
        assert!(direct
            .iter()
            .all(|r| r.scrambler == "q-art-4:compose=linear"));
        let mean0 = direct
            .iter()
            .find(|r| r.statistic == "variance of the mean, dim 0")
            .unwrap();
        assert_eq!(mean0.result.verdict, EquivalenceVerdict::Different);
        assert!((mean0.result.ratio - 1.3).abs() < 1e-12);
        let joint = direct
            .iter()
            .find(|r| r.statistic == "D² joint 16-D")
            .unwrap();
        assert_eq!(joint.result.verdict, EquivalenceVerdict::Equivalent);
        // Against Owen too.
        assert!(out.iter().any(
            |r| r.scrambler == "q-art-4:compose=linear" && r.reference == "owen-oracle:base=4"
        ));
    }
}
