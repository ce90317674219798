//! Reference lines and log-axis ticks of the report's figures: the segment drawn for a slope
//! is read back from the figure's data and must have exactly that slope and lie inside the
//! chart (the old drawing, from the anchor to the last x unclipped, left the box and plotters
//! clamped it to the bottom edge: −1 and −1.5 drawn on top of each other at a visible −0.87).

use gartowen_bench::figures::{chart_ranges, log_ticks, reference_segment, Series};

fn rmse_like() -> Vec<Series> {
    let ns: Vec<f64> = (4..=12).map(|k| 2f64.powi(k)).collect();
    vec![
        Series {
            label: "a".into(),
            points: ns.iter().map(|&n| (n, 0.3 * n.powf(-1.0))).collect(),
        },
        Series {
            label: "b".into(),
            points: ns.iter().map(|&n| (n, 0.2 * n.powf(-0.75))).collect(),
        },
    ]
}

fn log_slope([(x0, y0), (x1, y1)]: [(f64, f64); 2]) -> f64 {
    (y1.ln() - y0.ln()) / (x1.ln() - x0.ln())
}

#[test]
fn reference_lines_keep_their_slope_inside_the_chart() {
    let series = rmse_like();
    let (xr, yr) = chart_ranges(&series, 1.0);
    let anchor = series[0].points[0];
    let x_end = 4096.0;
    let mut segs = Vec::new();
    for slope in [-0.5, -1.0, -1.5, -2.0] {
        let seg = reference_segment(anchor, slope, x_end, xr, yr).expect("visible");
        assert!(
            (log_slope(seg) - slope).abs() < 1e-9,
            "slope {slope}: read back {}",
            log_slope(seg)
        );
        for (x, y) in seg {
            assert!(
                x >= xr.0 * (1.0 - 1e-12) && x <= xr.1 * (1.0 + 1e-12),
                "x = {x} outside {xr:?}"
            );
            assert!(
                y >= yr.0 * (1.0 - 1e-12) && y <= yr.1 * (1.0 + 1e-12),
                "y = {y} outside {yr:?}"
            );
        }
        // It starts at the anchor's x, 2× above the anchor.
        assert!((seg[0].0 / anchor.0 - 1.0).abs() < 1e-12);
        assert!((seg[0].1 / (2.0 * anchor.1) - 1.0).abs() < 1e-12);
        segs.push(seg);
    }
    // Steep lines leave through the bottom before the last x; shallow ones reach it.
    assert!((segs[0][1].0 / x_end - 1.0).abs() < 1e-12);
    assert!(segs[2][1].0 < x_end && (segs[2][1].1 / yr.0 - 1.0).abs() < 1e-9);
    // −1 and −1.5 are different lines.
    assert!(segs[1][1] != segs[2][1]);
    // A line entirely outside the box is not drawn.
    assert_eq!(reference_segment((16.0, 1e9), -1.0, x_end, xr, yr), None);
}

#[test]
fn log_axes_label_every_decade_and_every_power_of_the_base() {
    let has = |t: &[f64], v: f64| t.iter().any(|&x| (x / v - 1.0).abs() < 1e-9);
    // Base 2: every power of two; no decade next to one (they would print over each other).
    let t = log_ticks(10.0, 5000.0, Some(2.0));
    for k in 4..=12 {
        assert!(has(&t, 2f64.powi(k)), "2^{k} missing from {t:?}");
    }
    assert!(!has(&t, 100.0) && !has(&t, 1000.0), "{t:?}");
    assert!(t.windows(2).all(|w| w[0] < w[1]) && t.iter().all(|&x| (10.0..=5000.0).contains(&x)));
    // Base 16: its powers and the decades far from them.
    let t = log_ticks(2.0, 1e5, Some(16.0));
    for v in [16.0, 256.0, 4096.0, 65536.0, 10.0, 100.0, 1000.0, 10000.0] {
        assert!(has(&t, v), "{v} missing from {t:?}");
    }
    // No base: every decade.
    let t = log_ticks(1e-5, 0.5, None);
    for k in -5..=-1 {
        assert!(has(&t, 10f64.powi(k)), "1e{k} missing from {t:?}");
    }
    // Under two decades and no base: 2·10^k and 5·10^k as well.
    let y = log_ticks(1.5e-3, 4e-2, None);
    for v in [2e-3, 5e-3, 1e-2, 2e-2] {
        assert!(has(&y, v), "{v} missing from {y:?}");
    }
    assert!(!log_ticks(3e-4, 7e-4, None).is_empty());
}

/// The key's grey scale: black at or below 0.01, white at or above 4, darker for smaller values.
#[test]
fn spectrum_greys_follow_the_key() {
    use gartowen_bench::figures::spectrum_shade;
    let g = |v: f64| spectrum_shade(v).0;
    assert_eq!((g(1e-5), g(0.01), g(4.0), g(100.0)), (0, 0, 255, 255));
    let vs = [0.02, 0.05, 0.1, 0.3, 1.0, 2.0, 3.5];
    assert!(vs.windows(2).all(|w| g(w[0]) < g(w[1])), "{:?}", vs.map(g));
    let c = spectrum_shade(0.7);
    assert!(c.0 == c.1 && c.1 == c.2);
}
