//! Points in bases that are not powers of two, read from floats: the snapping rule
//! (`gartowen::netcheck::snap`) against exact integer references (Halton, prime-base Faure),
//! the counting path against the brute-force oracle, and the floor reading it replaces.

use gartowen::core::Width;
use gartowen::net_check::{check_points, snap_floats, NetQuery, Silent};
use gartowen::netcheck::{CheckBase, PointSet};
use gartowen::oracles::box_counting;
use gartowen::seq::radix::{faure_prime, halton, Fraction};

/// Column `dim` of row-major fractions with `dims` per point, as floats.
fn floats(points: &[Fraction], dims: usize, dim: usize) -> Vec<f64> {
    points
        .iter()
        .skip(dim)
        .step_by(dims)
        .map(|f| f.to_f64())
        .collect()
}

/// The t-value of float values (flat, `dims` per point) in base b at m, snapped or floored.
fn t_of(values: &[f64], dims: usize, b: u64, m: u32, snap: bool) -> u32 {
    let set = PointSet::from_f64_floor(dims, values).unwrap();
    let base = CheckBase::new(b).unwrap();
    let q = NetQuery {
        m: Some(m),
        ..NetQuery::default()
    };
    let (set, _) = if snap {
        snap_floats(set, base, &q).unwrap()
    } else {
        (set, None)
    };
    let out = check_points(&set, base, &q, &Silent).unwrap();
    out.result_json()["t"].as_u64().unwrap() as u32
}

#[test]
fn halton_in_f64_is_a_0_m_1_net_in_each_coordinates_own_base() {
    // 3^12 points: coordinates in bases 2, 3 and 5.
    let n = 3u64.pow(12);
    let h = halton(n, 3).unwrap();
    for (dim, b, top) in [(0usize, 2u64, 12u32), (1, 3, 12), (2, 5, 8)] {
        let column = floats(&h, 3, dim);
        for m in 1..=top {
            let count = b.pow(m) as usize;
            assert_eq!(t_of(&column[..count], 1, b, m, true), 0, "base {b} m {m}");
        }
    }
    // Read by floor, the base-3 coordinate is not even a (0,1,1)-net: 1/3 and 2/3 are stored
    // below themselves and fall into the box before theirs.
    let column = floats(&h, 3, 1);
    assert_eq!(t_of(&column[..3], 1, 3, 1, false), 1);
    let floored: Vec<u32> = (1..=8)
        .map(|m| t_of(&column[..3usize.pow(m)], 1, 3, m, false))
        .collect();
    assert!(floored.iter().all(|&t| t > 0), "{floored:?}");
}

#[test]
fn prime_base_faure_nets_agree_with_the_brute_force_oracle() {
    for (p, top) in [(3u64, 5u32), (5, 3), (7, 2)] {
        let dims = p as usize;
        for m in 1..=top {
            let n = p.pow(m);
            let f = faure_prime(p, n, dims).unwrap();
            let values: Vec<f64> = f.iter().map(|x| x.to_f64()).collect();
            assert_eq!(t_of(&values, dims, p, m, true), 0, "p {p} m {m}");
            // The oracle on the snapped words: two paths, one fact.
            let set = PointSet::from_f64_floor(dims, &values).unwrap();
            let q = NetQuery {
                m: Some(m),
                ..NetQuery::default()
            };
            let (snapped, summary) = snap_floats(set, CheckBase::new(p).unwrap(), &q).unwrap();
            assert!(summary.unwrap().snapped > 0);
            let rows: Vec<Vec<u64>> = (0..snapped.len()).map(|i| snapped.point(i)).collect();
            let few: Vec<Vec<u64>> = rows.iter().map(|r| r[..3.min(dims)].to_vec()).collect();
            if n <= 243 {
                assert_eq!(box_counting::t_value(&few, 64, p, m), 0, "p {p} m {m}");
            }
        }
    }
    // Two equal dimensions (the same Pascal power) are not a net, snapped or not.
    let f = faure_prime(3, 27, 2).unwrap();
    let twins: Vec<f64> = f
        .iter()
        .step_by(2)
        .flat_map(|x| [x.to_f64(), x.to_f64()])
        .collect();
    assert!(t_of(&twins, 2, 3, 3, true) > 0);
}

#[test]
fn input_rounded_more_coarsely_than_a_float_is_refused_naming_the_point() {
    // Halton base 3 truncated to 44 bits: many values land 1–4 radii of 2^-46 from their grid
    // point.
    let h = halton(81, 2).unwrap();
    let values: Vec<f64> = floats(&h, 2, 1)
        .iter()
        .map(|&v| ((v * 2f64.powi(44)).floor()) / 2f64.powi(44))
        .collect();
    let set = PointSet::from_f64_floor(1, &values).unwrap();
    let q = NetQuery {
        m: Some(4),
        ..NetQuery::default()
    };
    let e = snap_floats(set.clone(), CheckBase::new(3).unwrap(), &q).unwrap_err();
    assert!(e.contains("point ") && e.contains("coordinate 0"), "{e}");
    assert!(e.contains("radii"), "{e}");
    // Powers of two are never snapped: binary floats are exact there.
    let (same, none) = snap_floats(set.clone(), CheckBase::new(4).unwrap(), &q).unwrap();
    assert!(none.is_none() && same.column(0) == set.column(0));
    let _ = Width::W64;
}
