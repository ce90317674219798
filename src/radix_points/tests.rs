use super::*;
use gartowen_netcheck::PointSet;

fn radix(b: u64) -> Radix {
    Radix::new(b).unwrap()
}

#[test]
fn faure_words_are_the_exact_fractions_scaled_to_the_word() {
    let all = faure_points(3, 0, 9, 2, Width::W32).unwrap();
    let exact = faure_prime(3, 9, 2).unwrap();
    for (k, f) in exact.iter().enumerate() {
        assert_eq!(f.denom, 9);
        assert_eq!(all.columns[k % 2][k / 2], f.numer * 3u64.pow(18));
    }
    // A later start is the tail of the same points (indices past 9 need a third digit).
    let tail = faure_points(3, 4, 5, 2, Width::W32).unwrap();
    assert_eq!(tail.columns[1], all.columns[1][4..]);
    assert_eq!(tail.len(), 5);
    let e = faure_points(3, 0, 1 << 26, 2, Width::W32).unwrap_err();
    assert!(
        e.to_string().contains("at most 67108864 coordinates"),
        "{e}"
    );
    assert!(faure_points(9, 0, 4, 2, Width::W32).is_err()); // not a prime
    assert!(faure_points(3, u64::MAX, 2, 1, Width::W32).is_err());
    // 16-bit words hold one base-257 digit: 257 points fit, the 258th needs a second digit.
    let w16 = Width::new(16).unwrap();
    assert_eq!(
        faure_points(257, 0, 257, 1, w16).unwrap().columns[0][256],
        256
    );
    let e = faure_points(257, 0, 258, 1, w16).unwrap_err().to_string();
    assert!(
        e.contains("needs 2 base-257 digits; 16-bit words hold 1"),
        "{e}"
    );
}

#[test]
fn floats_of_a_base_3_net_snap_back_to_their_exact_digits() {
    let layout = RadixLayout::new(Width::W64, radix(3)).unwrap();
    let exact = faure_prime(3, 27, 3).unwrap();
    let values: Vec<f64> = exact.iter().map(|f| f.to_f64()).collect();
    let points = PointSet::from_f64(3, &values).unwrap();
    let read = from_floats(&points, layout, None).unwrap();
    let mut truncated_wrong = 0;
    for (k, f) in exact.iter().enumerate() {
        let want = f.numer * 3u64.pow(40 - 3);
        assert_eq!(read.columns[k % 3][k / 3], want, "coordinate {k}");
        let x = points.column(k % 3)[k / 3] as u128;
        truncated_wrong += usize::from(((x * layout.capacity() as u128) >> 64) as u64 != want);
    }
    // Without snapping, floats stored below k/3^n would read the wrong digits.
    assert!(truncated_wrong > 0);
    // 27 points: three digits by default.
    assert_eq!(digits_for(radix(3), 27), 3);
    let e = from_floats(&points, layout, Some(28))
        .unwrap_err()
        .to_string();
    assert!(e.contains("resolve at most 27 base-3 digits"), "{e}");
    assert!(from_floats(&points, layout, Some(27)).is_ok());
    assert!(from_floats(&points, layout, Some(0)).is_err());
    assert_eq!((read.len(), read.is_empty()), (27, false));
    let none = RadixPoints {
        layout,
        columns: vec![],
    };
    assert_eq!((none.len(), none.is_empty()), (0, true));
}

#[test]
fn a_float_just_off_the_grid_is_refused_naming_it() {
    let layout = RadixLayout::new(Width::W64, radix(3)).unwrap();
    let near = 1.0 / 3.0 + 2.0 * (2f64).powi(-46);
    let points = PointSet::from_f64(1, &[0.0, near, 0.9]).unwrap();
    let e = from_floats(&points, layout, None).unwrap_err().to_string();
    assert!(
        e.contains("point 1") && e.contains("too near the base-3 grid"),
        "{e}"
    );
}

#[test]
fn digit_words_must_be_below_b_to_the_m() {
    let layout = RadixLayout::new(Width::W32, radix(3)).unwrap();
    let ok = PointSet::from_flat(Width::W32, 1, &[0, 3u64.pow(20) - 1]).unwrap();
    assert_eq!(
        from_digit_words(&ok, layout).unwrap().columns,
        [vec![0, 3u64.pow(20) - 1]]
    );
    let bad = PointSet::from_flat(Width::W32, 1, &[0, 3u64.pow(20)]).unwrap();
    let e = from_digit_words(&bad, layout).unwrap_err().to_string();
    assert!(
        e.contains("point 1 coordinate 0") && e.contains("below 3^20"),
        "{e}"
    );
}

#[test]
fn digits_index_every_point() {
    let three = radix(3);
    for (n, d) in [
        (0, 1),
        (1, 1),
        (3, 1),
        (4, 2),
        (9, 2),
        (10, 3),
        (2187, 7),
        (2188, 8),
    ] {
        assert_eq!(digits_for(three, n), d, "n {n}");
    }
}

#[test]
fn requests_name_their_base_and_only_the_oracle_serves_base_b() {
    let base = |r: &str, b| radix_of_request(r, b).unwrap().map(|r| r.get());
    assert_eq!(base("owen-oracle", Some(3)), Some(3));
    assert_eq!(base("owen-oracle:base=5", None), Some(5));
    assert_eq!(base("owen-oracle", Some(4)), None);
    assert_eq!(base("owen-oracle", None), None);
    assert_eq!(base("none", Some(7)), Some(7));
    assert_eq!(base("none", None), None);
    assert!(radix_of_request("owen-oracle", Some(1)).is_err());
    assert!(radix_of_request("none", Some(0)).is_err());
    assert!(radix_scrambler("none", radix(3), 0).unwrap().is_none());
    let s = radix_scrambler("owen-oracle:cyclic", radix(3), 4)
        .unwrap()
        .unwrap();
    assert_eq!(s.name(), "owen-oracle:cyclic:base=3");
    assert!(radix_scrambler("art-owen-2", radix(3), 0).is_err());
    assert_eq!(radix_sequence("faure:base=3"), Some(3));
    assert_eq!(radix_sequence("faure:base=4"), None);
    assert_eq!(radix_sequence("sobol"), None);
}

#[test]
fn scrambling_keeps_every_word_in_range_and_each_column_is_its_own_dimension() {
    let mut p = faure_points(5, 0, 25, 2, Width::W32).unwrap();
    let before = p.clone();
    let s = radix_scrambler("owen-oracle", radix(5), 9)
        .unwrap()
        .unwrap();
    p.scramble(&s);
    for j in 0..2 {
        let mut want = before.columns[j].clone();
        s.scramble_batch(&mut want, Width::W32, j as u32);
        assert_eq!(p.columns[j], want);
        assert!(p.columns[j].iter().all(|&y| y < p.layout.capacity()));
    }
    assert_ne!(p.columns, before.columns);
}
