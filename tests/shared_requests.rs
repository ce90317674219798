//! The request and report code the CLI and the Python package share: the generate plan and
//! the net-check report (the discrepancy method choice is tested in its crate). Each is checked against an independent
//! path (the sequence and scrambler called directly, brute-force box counts, the exact method).

use gartowen::core::{BuildContext, PowerOfTwoBase, Width};
use gartowen::generate::{
    width_from_bits, GeneratePlan, GenerateRequest, PointCount, PointOrder, RequestError,
};
use gartowen::net_check::{check_points, describe_failure, NetQuery, Progress, Silent};
use gartowen::netcheck::{CheckBase, PointSet};
use gartowen::seq::{gray_code, SequenceKind};
use std::sync::Mutex;

fn request(seq: &str, dims: usize, count: PointCount, scramble: &str) -> GenerateRequest {
    GenerateRequest {
        seq: seq.into(),
        dims,
        count,
        start: 0,
        bits: 32,
        scramble: scramble.into(),
        seed: 9,
        scramble_base: None,
    }
}

#[test]
fn plan_words_equal_the_sequence_scrambled_word_by_word() {
    for (seq, dims, scramble, bits, start) in [
        ("sobol", 3, "owen-oracle", 32, 5u64),
        ("sz16", 4, "art-owen-16p", 64, 0),
        ("sz4", 2, "none", 32, 17),
    ] {
        let mut r = request(seq, dims, PointCount::Exact(40), scramble);
        r.bits = bits;
        r.start = start;
        let plan = GeneratePlan::new(&r).unwrap();
        let width = width_from_bits(bits).unwrap();
        assert_eq!(plan.width(), width);
        let kind: SequenceKind = seq.parse().unwrap();
        let direct_seq = kind.build(dims, width).unwrap();
        let direct = gartowen::registry()
            .build_with(
                scramble,
                &BuildContext {
                    seed: 9,
                    default_base: kind.base(),
                },
            )
            .unwrap();
        for order in [PointOrder::Natural, PointOrder::Gray] {
            let words = plan.words(order).unwrap();
            assert_eq!(words.len(), 40 * dims);
            let mut row = vec![0u64; dims];
            for i in 0..40u64 {
                let index = match order {
                    PointOrder::Natural => start + i,
                    PointOrder::Gray => gray_code(start + i),
                };
                assert_eq!(plan.index(i, order), index);
                plan.row(i, order, &mut row);
                for j in 0..dims {
                    let want = direct.scramble(direct_seq.point(index, j), width, j as u32);
                    assert_eq!(words[i as usize * dims + j], want, "{seq} row {i} dim {j}");
                    assert_eq!(row[j], want);
                }
            }
        }
    }
}

#[test]
fn plan_counts_and_scramble_base() {
    let plan = GeneratePlan::new(&request("sobol", 2, PointCount::Log2(5), "none")).unwrap();
    assert_eq!(plan.count, 32);
    // The sequence's base is the default base of a base-parameter scrambler; a given base the
    // scrambler does not take (its own option, or a fixed base) is refused, naming both.
    let base_of = |seq: &str, scramble: &str, base: Option<u64>| {
        let mut r = request(seq, 2, PointCount::Exact(4), scramble);
        r.scramble_base = base;
        GeneratePlan::new(&r).unwrap().scrambler.base()
    };
    assert_eq!(base_of("sz16", "owen-oracle", None), PowerOfTwoBase::B16);
    assert_eq!(base_of("sobol", "owen-oracle", None), PowerOfTwoBase::B2);
    assert_eq!(base_of("sobol", "owen-oracle", Some(8)).base(), 8);
    assert_eq!(base_of("sobol", "owen-oracle:base=4", None).base(), 4);
    assert_eq!(base_of("sobol", "owen-oracle:base=4", Some(4)).base(), 4);
    for (scramble, base) in [
        ("owen-oracle:base=4", 8),
        ("lk-hash", 4),
        ("art-owen-m8", 16),
    ] {
        let mut r = request("sobol", 2, PointCount::Exact(4), scramble);
        r.scramble_base = Some(base);
        let e = GeneratePlan::new(&r).err().expect("a conflict").to_string();
        assert!(
            e.starts_with(&format!("--scramble-base {base} conflicts with "))
                && e.contains("drop one"),
            "{e}"
        );
    }
}

#[test]
fn plan_refusals_name_the_bad_value() {
    let refuse = |r: GenerateRequest| match GeneratePlan::new(&r) {
        Ok(_) => panic!("accepted {r:?}"),
        Err(e) => e,
    };
    let e = refuse(request("sobol", 2, PointCount::Exact(0), "none"));
    assert_eq!(e.to_string(), "n must be at least 1");
    let e = refuse(request("sz16", 2, PointCount::Log2(40), "none"));
    assert!(
        matches!(e, RequestError::Invalid(_)) && e.to_string().contains("40"),
        "{e}"
    );
    let e = refuse(request("sobol", 2, PointCount::Log2(64), "none"));
    assert!(e.to_string().contains("64"), "{e}");
    let e = refuse(request("halton", 2, PointCount::Exact(4), "none"));
    assert!(matches!(e, RequestError::Sequence(_)) && e.to_string().contains("halton"));
    let e = refuse(request("sobol", 2, PointCount::Exact(4), "nope"));
    assert!(matches!(e, RequestError::Scrambler(_)) && e.to_string().contains("nope"));
    let mut r = request("sobol", 2, PointCount::Exact(4), "lk-hash");
    r.bits = 64;
    let e = refuse(r);
    assert!(
        e.to_string().contains("lk-hash") && e.to_string().contains("64-bit"),
        "{e}"
    );
    let mut r = request("sobol", 2, PointCount::Exact(4), "none");
    r.bits = 16;
    assert_eq!(refuse(r).to_string(), "bits must be 32 or 64, not 16");
    let mut r = request("sobol", 2, PointCount::Exact(4), "owen-oracle");
    r.scramble_base = Some(3);
    let e = refuse(r.clone());
    assert!(
        matches!(e, RequestError::Invalid(_)) && e.to_string().contains("base-2 sequence"),
        "{e}"
    );
    r.scramble_base = Some(1);
    assert!(matches!(refuse(r), RequestError::Scrambler(_)));
    // The range past the index bits is the sequence's refusal.
    let mut r = request("sz4", 2, PointCount::Exact(4), "none");
    r.start = u64::MAX - 1;
    assert!(matches!(refuse(r), RequestError::Sequence(_)));
    assert_eq!(width_from_bits(32).unwrap(), Width::W32);
    assert_eq!(width_from_bits(64).unwrap(), Width::W64);
}

#[test]
fn words_refuses_sizes_past_the_address_space() {
    let mut plan = GeneratePlan::new(&request("sobol", 3, PointCount::Exact(4), "none")).unwrap();
    plan.count = u64::MAX / 2;
    let e = plan.words(PointOrder::Natural).unwrap_err();
    assert!(e.to_string().contains("do not fit in memory"), "{e}");
    plan.count = (isize::MAX as u64) / 8 / 3 + 1;
    assert!(plan.words(PointOrder::Natural).is_err());
}

/// Records what a check reports as progress.
#[derive(Default)]
struct Recorder(Mutex<Vec<(String, u64)>>);

impl Progress for Recorder {
    fn start(&self, total: u64, what: &str) {
        self.0
            .lock()
            .unwrap()
            .push((format!("start {what}"), total));
    }
    fn advance(&self, k: u64) {
        self.0.lock().unwrap().push(("advance".into(), k));
    }
    fn finish(&self) {
        self.0.lock().unwrap().push(("finish".into(), 0));
    }
}

fn sobol_set(n: u64, dims: usize) -> PointSet {
    let seq = SequenceKind::Sobol.build(dims, Width::W32).unwrap();
    let all: Vec<usize> = (0..dims).collect();
    PointSet::from_sequence(&seq, &all, n, |x, _| x).unwrap()
}

/// Points of `set` in the box of `shape`/`index` in base 2, counted directly.
fn count_in_box(set: &PointSet, shape: &[u32], index: &[u64]) -> u64 {
    (0..set.len())
        .filter(|&i| {
            set.point(i)
                .iter()
                .zip(shape.iter().zip(index))
                .all(|(&x, (&d, &a))| d == 0 || x >> (32 - d) == a)
        })
        .count() as u64
}

#[test]
fn net_check_reports_t_values_verdicts_and_real_boxes() {
    let base = CheckBase::new(2).unwrap();
    let good = sobol_set(64, 2);
    let out = check_points(&good, base, &NetQuery::default(), &Silent).unwrap();
    assert!(out.holds);
    assert_eq!(out.result_json()["t"], 0);
    assert_eq!(out.result_json()["m"], 6);
    assert!(
        out.text.contains("t = 0 (m = 6, s = 2, base 2)"),
        "{}",
        out.text
    );

    // Break it: the verdict fails and names a box that really holds the wrong count.
    let mut bad = good.clone();
    bad.set(3, 0, good.point(4)[0]);
    bad.set(3, 1, good.point(4)[1]);
    let rec = Recorder::default();
    let q = NetQuery {
        t: Some(0),
        ..NetQuery::default()
    };
    let out = check_points(&bad, base, &q, &rec).unwrap();
    assert!(!out.holds);
    let f = &out.result_json()["first_failure"];
    let shape: Vec<u32> = serde_json::from_value(f["shape"].clone()).unwrap();
    let index: Vec<u64> = serde_json::from_value(f["box_index"].clone()).unwrap();
    assert_eq!(
        count_in_box(&bad, &shape, &index),
        f["count"].as_u64().unwrap()
    );
    assert_ne!(f["count"], f["expected"]);
    assert!(out.text.contains("FAILS") && out.text.contains("first failure"));
    let events = rec.0.lock().unwrap().clone();
    assert_eq!(events.first().unwrap(), &("start shapes".to_string(), 7));
    assert_eq!(events.last().unwrap().0, "finish");
    // Without t, the t-value is positive and its witness is the failing box at t - 1.
    let out = check_points(&bad, base, &NetQuery::default(), &Silent).unwrap();
    assert!(out.holds, "a t-value alone is not a verdict");
    assert!(out.result_json()["t"].as_u64().unwrap() > 0);
    assert!(out.text.contains("not a ("), "{}", out.text);
}

#[test]
fn net_check_projections_and_sequences() {
    let base = CheckBase::new(2).unwrap();
    let set = sobol_set(256, 4);
    let q = NetQuery {
        projections: Some("pairs".into()),
        ..NetQuery::default()
    };
    let out = check_points(&set, base, &q, &Silent).unwrap();
    let json = out.result_json();
    let list = json.as_array().unwrap();
    assert_eq!(list.len(), 6);
    assert_eq!(out.results.len(), 6);
    for (item, typed) in list.iter().zip(&out.results) {
        assert_eq!(item["projection"], serde_json::json!(typed.projection()));
        let dims: Vec<usize> = serde_json::from_value(item["projection"].clone()).unwrap();
        let direct = check_points(
            &set.project(&dims).unwrap(),
            base,
            &NetQuery::default(),
            &Silent,
        )
        .unwrap();
        assert_eq!(item["t"], direct.result_json()["t"]);
    }
    // The (t,s)-sequence check: the least t holding equals the verdict's threshold.
    let q = NetQuery {
        sequence: true,
        ..NetQuery::default()
    };
    let out = check_points(&set, base, &q, &Silent).unwrap();
    let t = out.result_json()["t"].as_u64().unwrap() as u32;
    assert_eq!(out.result_json()["max_m"], 8);
    let holds_at = |t: u32| {
        let q = NetQuery {
            sequence: true,
            t: Some(t),
            ..NetQuery::default()
        };
        check_points(&set, base, &q, &Silent).unwrap().holds
    };
    assert!(holds_at(t));
    if t > 0 {
        assert!(!holds_at(t - 1));
    }
    // Histograms come with a verdict.
    let q = NetQuery {
        t: Some(0),
        histograms: true,
        projections: Some("0,1".into()),
        ..NetQuery::default()
    };
    let out = check_points(&set, base, &q, &Silent).unwrap();
    assert!(out.result_json()[0]["histograms"].is_array());
    // Bad projections and m are refused with their value named.
    let q = NetQuery {
        projections: Some("0,9".into()),
        ..NetQuery::default()
    };
    assert!(check_points(&set, base, &q, &Silent)
        .unwrap_err()
        .contains('9'));
    let q = NetQuery {
        m: Some(9),
        ..NetQuery::default()
    };
    assert!(check_points(&set, base, &q, &Silent).is_err());
}

#[test]
fn describe_failure_names_only_refined_dimensions() {
    let f = gartowen::netcheck::BoxFailure {
        shape: vec![2, 0, 1],
        box_index: vec![3, 0, 1],
        count: 2,
        expected: 1,
    };
    assert_eq!(
        describe_failure(&f, 4),
        "shape [2, 0, 1]: the box dim 0 in [3, 4)/4^2, dim 2 in [1, 2)/4^1 holds 2 points, \
         every box must hold 1"
    );
    let whole = gartowen::netcheck::BoxFailure {
        shape: vec![0, 0],
        box_index: vec![0, 0],
        count: 3,
        expected: 4,
    };
    assert!(describe_failure(&whole, 2).contains("[0,1)^s"));
}
