//! The method choice shared by `gartowen discrepancy --method` and the Python package:
//! what `auto` picks, against the bound it must prove.

use gartowen_core::Width;
use gartowen_discrepancy::choice::{compute, MethodChoice};
use gartowen_discrepancy::{Kind, Method, Points};
use gartowen_seq::SequenceKind;

/// The first n points of the d-dimensional Sobol sequence, row-major 32-bit words.
fn sobol_words(n: u64, d: usize) -> Vec<u64> {
    let seq = SequenceKind::Sobol.build(d, Width::W32).unwrap();
    (0..n)
        .flat_map(|i| (0..d).map(move |j| (i, j)))
        .map(|(i, j)| seq.point(i, j))
        .collect()
}

#[test]
fn method_choice_auto_picks_what_it_can_prove() {
    let words: Vec<u64> = sobol_words(48, 3);
    let p3 = Points {
        words: &words,
        dims: 3,
        width: Width::W32,
    };
    for kind in Kind::ALL {
        let exact = compute(p3, kind, MethodChoice::Exact).unwrap();
        assert_eq!(exact.method, Method::Exact);
        let auto = compute(p3, kind, MethodChoice::Auto).unwrap();
        assert_eq!(auto.method, Method::Compensated, "{kind:?}");
        assert!(auto.rel_error_bound.unwrap() <= 1e-12);
        assert!((auto.value - exact.value).abs() <= 1e-12 * exact.value);
        assert_eq!(
            compute(p3, kind, MethodChoice::Naive).unwrap().method,
            Method::Naive
        );
        assert_eq!(
            compute(p3, kind, MethodChoice::Compensated).unwrap().method,
            Method::Compensated
        );
        assert!(compute(p3, kind, MethodChoice::Fast).is_err());
    }
    let two = sobol_words(48, 2);
    let p2 = Points {
        words: &two,
        dims: 2,
        width: Width::W32,
    };
    assert_eq!(
        compute(p2, Kind::L2Star, MethodChoice::Auto)
            .unwrap()
            .method,
        Method::Fast
    );
    assert_eq!(
        compute(p2, Kind::Centered, MethodChoice::Auto)
            .unwrap()
            .method,
        Method::Compensated
    );
    // Where the compensated bound exceeds 1e-12 (8-D, 512 points, CD: about 2e-11), auto
    // falls back to the exact method; elsewhere it keeps the compensated value.
    let eight = sobol_words(512, 8);
    let p8 = Points {
        words: &eight,
        dims: 8,
        width: Width::W32,
    };
    let mut fell_back = 0;
    for kind in Kind::ALL {
        let c = compute(p8, kind, MethodChoice::Compensated).unwrap();
        let auto = compute(p8, kind, MethodChoice::Auto).unwrap();
        if c.rel_error_bound.unwrap() > 1e-12 {
            fell_back += 1;
            assert_eq!(auto.method, Method::Exact, "{kind:?}");
        } else {
            assert_eq!(auto.method, Method::Compensated, "{kind:?}");
            assert_eq!(auto.value, c.value);
        }
    }
    assert!(fell_back > 0, "no kind exercised the fallback");
    for name in ["auto", "naive", "compensated", "exact", "fast"] {
        assert_eq!(MethodChoice::parse(name).unwrap().name(), name);
    }
    assert_eq!(MethodChoice::parse("Auto"), None);
}

#[test]
fn exact_work_past_its_budget_is_refused_naming_the_cost_and_just_within_it_runs() {
    use gartowen_discrepancy::choice::{exact_cost, EXACT_MAX_BITS};
    // One point: the rational's size grows with d (2W + 2 bits a dimension).
    let max_d = ((EXACT_MAX_BITS - 128) / 66) as usize;
    let words = vec![1u64 << 31; max_d + 1];
    let over = Points {
        words: &words,
        dims: max_d + 1,
        width: Width::W32,
    };
    let within = Points {
        words: &words[..max_d],
        dims: max_d,
        width: Width::W32,
    };
    assert!(exact_cost(over).0 > EXACT_MAX_BITS && exact_cost(within).0 <= EXACT_MAX_BITS);
    for kind in Kind::ALL {
        let e = compute(over, kind, MethodChoice::Exact).unwrap_err();
        assert!(
            e.starts_with("method exact:") && e.contains("-bit rational"),
            "{e}"
        );
        assert!(e.contains(&format!("in {} dimensions", max_d + 1)), "{e}");
        // auto cannot prove its bound here (the compensated sum overflows) and says so.
        if let Err(e) = compute(over, kind, MethodChoice::Auto) {
            assert!(e.starts_with("method auto cannot prove"), "{e}");
        }
        // Compensated still answers (with whatever bound it can prove).
        assert!(compute(over, kind, MethodChoice::Compensated).is_ok());
    }
    assert_eq!(
        compute(within, Kind::WrapAround, MethodChoice::Exact)
            .unwrap()
            .method,
        Method::Exact
    );
    // Many points in few dimensions: the pair sum's N²/2 products.
    let many = vec![0u64; 1 << 20];
    let p = Points {
        words: &many,
        dims: 1,
        width: Width::W32,
    };
    let e = compute(p, Kind::L2Star, MethodChoice::Exact).unwrap_err();
    assert!(e.contains("limb products"), "{e}");
    assert_eq!(exact_cost(p).1, (1u64 << 20) * ((1 << 20) + 1) / 2);
}
