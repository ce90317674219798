//! The CLI's net check on a set it owns (words freed as their digits are read) against the
//! borrowed check: one outcome for every kind of query.

use gartowen::core::Width;
use gartowen::net_check::{check_points, NetQuery, Silent};
use gartowen::netcheck::{CheckBase, PointSet};

/// `check_points_owned` (the CLI's path, which frees words early) and `check_points` give
/// the same outcome for every kind of query, passing and failing.
#[test]
fn the_owned_and_borrowed_checks_give_one_outcome() {
    use gartowen::net_check::check_points_owned;
    use gartowen::seq::SequenceKind;
    let seq = SequenceKind::Sz16.build(3, Width::W32).unwrap();
    let good = PointSet::from_sequence(&seq, &[0, 1, 2], 4096, |x, _| x).unwrap();
    let mut bad = good.clone();
    bad.set(7, 2, bad.column(2)[8]);
    let queries = [
        NetQuery {
            t: Some(0),
            ..NetQuery::default()
        },
        NetQuery {
            t: Some(1),
            m: Some(3),
            ..NetQuery::default()
        },
        NetQuery::default(),
        NetQuery {
            t: Some(0),
            projections: Some("pairs".into()),
            ..NetQuery::default()
        },
        NetQuery {
            t: Some(0),
            histograms: true,
            ..NetQuery::default()
        },
    ];
    let base = CheckBase::new(16).unwrap();
    for set in [good, bad] {
        for q in &queries {
            let borrowed = check_points(&set, base, q, &Silent).unwrap();
            let owned = check_points_owned(set.clone(), base, q, &Silent).unwrap();
            assert_eq!(owned, borrowed, "{q:?}");
        }
    }
}
