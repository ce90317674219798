//! PNG figures with plotters. Text uses DejaVu Sans embedded through the `dejavu` crate and
//! rasterized by ab_glyph, so figures build on a machine without system font libraries.

use plotters::coord::combinators::WithKeyPoints;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

pub(crate) mod png;

/// A figure that could not be drawn or written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FigureError(pub String);

impl std::fmt::Display for FigureError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "figure: {}", self.0)
    }
}

impl std::error::Error for FigureError {}

fn fail(e: impl std::fmt::Display) -> FigureError {
    FigureError(e.to_string())
}

const FONT: &str = "sans-serif";

fn register_fonts() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // The font is static data of the dejavu crate; registration fails only on bad bytes.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular());
    });
}

/// A labelled line or point series in data coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// (x, y) points.
    pub points: Vec<(f64, f64)>,
}

fn log_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    if lo > hi {
        return (0.1, 10.0);
    }
    (lo / 1.5, hi * 1.5)
}

/// Tick labels for log axes: 1e-5 rather than 9.99999999e-6.
fn short_number(v: f64) -> String {
    if (1e-2..1e5).contains(&v.abs()) {
        let s = format!("{v:.2}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.0e}")
    }
}

fn color(i: usize) -> RGBColor {
    let c = Palette99::pick(i).to_rgba();
    RGBColor(c.0, c.1, c.2)
}

type LogAxis = WithKeyPoints<LogCoord<f64>>;
type LogLogChart<'a> = ChartContext<'a, BitMapBackend<'a>, Cartesian2d<LogAxis, LogAxis>>;

/// The x and y ranges of a log-log chart fitted to `series` (data range widened by 1.5 on each
/// side; x's upper end stretched by `x_stretch` to leave room for labels).
pub fn chart_ranges(series: &[Series], x_stretch: f64) -> ((f64, f64), (f64, f64)) {
    let all = || series.iter().flat_map(|s| s.points.iter());
    let (x0, x1) = log_range(all().map(|p| p.0));
    let (y0, y1) = log_range(all().map(|p| p.1));
    ((x0, x1 * x_stretch), (y0, y1))
}

/// Tick positions of a log axis over [lo, hi]: every power of ten; with a `base`, every power
/// of the base instead (point counts N = 16, 32, 64, … read off the axis), keeping only the
/// decades farther than a factor 1.4 from every power (for base 2 every decade lies within √2
/// of one, and the two labels would print over each other). With fewer than two decades and
/// no base, 2·10^k and 5·10^k are added so the axis is never unlabelled.
pub fn log_ticks(lo: f64, hi: f64, base: Option<f64>) -> Vec<f64> {
    let mut ticks = Vec::new();
    let powers = |b: f64, ticks: &mut Vec<f64>| {
        let mut k = (lo.ln() / b.ln()).floor() as i32;
        while b.powi(k) <= hi {
            let v = b.powi(k);
            if v >= lo {
                ticks.push(v);
            }
            k += 1;
        }
    };
    powers(10.0, &mut ticks);
    if let Some(b) = base.filter(|b| *b > 1.0) {
        let mut base_ticks = Vec::new();
        powers(b, &mut base_ticks);
        ticks.retain(|&d| base_ticks.iter().all(|&p| (d / p).max(p / d) > 1.4));
        ticks.extend(base_ticks);
    } else if ticks.len() < 2 {
        for m in [2.0, 5.0] {
            let mut k = (lo / m).log10().floor() as i32;
            while m * 10f64.powi(k) <= hi {
                let v = m * 10f64.powi(k);
                if v >= lo {
                    ticks.push(v);
                }
                k += 1;
            }
        }
    }
    ticks.sort_by(f64::total_cmp);
    ticks.dedup_by(|a, b| (*a / *b - 1.0).abs() < 1e-12);
    ticks
}

/// The base whose powers every x value is (2 for point counts 16, 32, …), if any.
fn power_base(xs: impl Iterator<Item = f64>) -> Option<f64> {
    let mut any = false;
    for x in xs {
        any = true;
        if !(x > 0.0 && x.log2().fract() == 0.0) {
            return None;
        }
    }
    any.then_some(2.0)
}

/// The reference line of `slope` through (ax, 2·ay), for x from ax to `x_end`, clipped to the
/// chart's box: both ends lie inside `x_range` × `y_range` and the segment's slope in log-log
/// coordinates is exactly `slope` (plotters would clamp points outside the box to its edge,
/// which bends the drawn slope). `None` when no part of the line is inside the box.
pub fn reference_segment(
    (ax, ay): (f64, f64),
    slope: f64,
    x_end: f64,
    x_range: (f64, f64),
    y_range: (f64, f64),
) -> Option<[(f64, f64); 2]> {
    // In log coordinates the line is Y = c + slope·X; clip X, then the X where Y leaves the box.
    let c = (2.0 * ay).ln() - slope * ax.ln();
    let (mut lo, mut hi) = (ax.max(x_range.0).ln(), x_end.min(x_range.1).ln());
    let (y0, y1) = (y_range.0.ln(), y_range.1.ln());
    if slope == 0.0 {
        if !(y0..=y1).contains(&c) {
            return None;
        }
    } else {
        let (xa, xb) = ((y0 - c) / slope, (y1 - c) / slope);
        lo = lo.max(xa.min(xb));
        hi = hi.min(xa.max(xb));
    }
    (lo < hi).then(|| [lo, hi].map(|x| (x.exp(), (c + slope * x).exp())))
}

/// A 900×620 log-log chart fitted to `series` (x range stretched by `x_stretch` to leave room
/// for labels), with a captioned, labelled mesh.
fn log_log_chart<'a>(
    root: &DrawingArea<BitMapBackend<'a>, Shift>,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
    x_stretch: f64,
) -> Result<LogLogChart<'a>, FigureError> {
    root.fill(&WHITE).map_err(fail)?;
    let ((x0, x1), (y0, y1)) = chart_ranges(series, x_stretch);
    let base = power_base(series.iter().flat_map(|s| s.points.iter()).map(|p| p.0));
    let mut chart = ChartBuilder::on(root)
        .caption(title, (FONT, 22))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(
            (x0..x1)
                .log_scale()
                .with_key_points(log_ticks(x0, x1, base)),
            (y0..y1)
                .log_scale()
                .with_key_points(log_ticks(y0, y1, None)),
        )
        .map_err(fail)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| short_number(*v))
        .y_label_formatter(&|v| short_number(*v))
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .draw()
        .map_err(fail)?;
    Ok(chart)
}

/// Log-log lines with reference slopes drawn through the first point of the first series.
pub fn loglog_lines(
    path: &Path,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
    reference_slopes: &[f64],
) -> Result<(), FigureError> {
    loglog_lines_banded(path, title, x_desc, y_desc, series, &[], reference_slopes)
}

/// [`loglog_lines`] with a shaded band per series: `bands[i][k]` = (low, high) around point k
/// of series i (for example the mean ± 2 standard errors). A low end at or below 0, which a
/// log axis cannot show, is drawn at the bottom of the chart. Series past `bands.len()` get
/// no band.
pub fn loglog_lines_banded(
    path: &Path,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
    bands: &[Vec<(f64, f64)>],
    reference_slopes: &[f64],
) -> Result<(), FigureError> {
    register_fonts();
    png::png_figure(path, (900, 620), |root| {
        let mut chart = log_log_chart(root, title, x_desc, y_desc, series, 1.0)?;
        let (x_range, y_range) = chart_ranges(series, 1.0);
        let x_end = series
            .iter()
            .flat_map(|s| s.points.iter())
            .map(|p| p.0)
            .fold(f64::MIN, f64::max);
        if let Some(&(ax, ay)) = series.first().and_then(|s| s.points.first()) {
            for (k, &slope) in reference_slopes.iter().enumerate() {
                let grey = RGBColor(150, 150, 150);
                let style = ShapeStyle::from(&grey).stroke_width(1 + k as u32);
                let Some(line) = reference_segment((ax, ay), slope, x_end, x_range, y_range) else {
                    continue;
                };
                chart
                    .draw_series(LineSeries::new(line, style))
                    .map_err(fail)?
                    .label(format!("slope {slope}"))
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
            }
        }
        for (i, (s, band)) in series.iter().zip(bands).enumerate() {
            // The band as one polygon: the high ends left to right, the low ends back.
            let mut outline: Vec<(f64, f64)> = s
                .points
                .iter()
                .zip(band)
                .map(|(p, b)| (p.0, b.1.min(y_range.1)))
                .collect();
            outline.extend(
                s.points
                    .iter()
                    .zip(band)
                    .rev()
                    .map(|(p, b)| (p.0, b.0.max(y_range.0))),
            );
            if outline
                .iter()
                .all(|p| p.0 > 0.0 && p.1 > 0.0 && p.1.is_finite())
            {
                chart
                    .draw_series(std::iter::once(Polygon::new(
                        outline,
                        color(i).mix(0.15).filled(),
                    )))
                    .map_err(fail)?;
            }
        }
        for (i, s) in series.iter().enumerate() {
            let c = color(i);
            let pts: Vec<(f64, f64)> = s.points.iter().copied().filter(|p| p.1 > 0.0).collect();
            chart
                .draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))
                .map_err(fail)?
                .label(s.label.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                });
            chart
                .draw_series(pts.into_iter().map(|p| Circle::new(p, 3, c.filled())))
                .map_err(fail)?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .label_font((FONT, 12))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(fail)?;
        Ok(())
    })
}

/// Log-log points (one per series, its first point): the speed-against-error picture. Every
/// point carries its number, and the legend names each number (the points crowd, so names
/// beside them would overlap).
pub fn loglog_points(
    path: &Path,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    points: &[Series],
) -> Result<(), FigureError> {
    register_fonts();
    png::png_figure(path, (900, 620), |root| {
        let mut chart = log_log_chart(root, title, x_desc, y_desc, points, 3.0)?;
        for (i, s) in points.iter().enumerate() {
            let c = color(i);
            let number = (i + 1).to_string();
            chart
                .draw_series(s.points.iter().take(1).map(|&p| {
                    EmptyElement::at(p)
                        + Circle::new((0, 0), 4, c.filled())
                        + Text::new(number.clone(), (6, -6), (FONT, 12).into_font())
                }))
                .map_err(fail)?
                .label(format!("{}: {}", i + 1, s.label))
                .legend(move |(x, y)| Circle::new((x, y), 4, c.filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, 11))
            .draw()
            .map_err(fail)?;
        Ok(())
    })
}

/// One panel of a point-set grid.
#[derive(Debug, Clone, PartialEq)]
pub enum Panel {
    /// Points in the unit square.
    Scatter(Vec<[f64; 2]>),
    /// A power spectrum on the (2F+1)² grid (see [`crate::spectrum::power_spectrum`]).
    Spectrum {
        /// Row-major values.
        values: Vec<f64>,
        /// F.
        max_freq: usize,
    },
}

/// Spectrum grey levels on a log scale: black at 0.01 or less, white at 4 or more (the DC term
/// is drawn white).
const SHADE_RANGE: (f64, f64) = (1e-2, 4.0);

/// The grey of spectrum value `v` (black at 0.01 or less, white at 4 or more).
pub fn spectrum_shade(v: f64) -> RGBColor {
    let (lo, hi) = SHADE_RANGE;
    let t = ((v.max(lo).ln() - lo.ln()) / (hi.ln() - lo.ln())).clamp(0.0, 1.0);
    let g = (t * 255.0) as u8;
    RGBColor(g, g, g)
}

/// The grey-scale key of the spectra: a vertical bar from 0.01 (black) to 4 (white) with
/// labelled values, its top-left corner at (x, y).
fn draw_grey_key(
    root: &DrawingArea<BitMapBackend, Shift>,
    (x, y): (i32, i32),
    height: i32,
) -> Result<(), FigureError> {
    let (lo, hi) = SHADE_RANGE;
    root.draw(&Text::new(
        "|spectrum|²/N",
        (x - 10, y - 16),
        (FONT, 12).into_font(),
    ))
    .map_err(fail)?;
    for k in 0..height {
        // Top = white (large), bottom = black (small), log spaced.
        let t = 1.0 - k as f64 / (height - 1) as f64;
        let v = (lo.ln() + t * (hi.ln() - lo.ln())).exp();
        root.draw(&Rectangle::new(
            [(x, y + k), (x + 16, y + k + 1)],
            spectrum_shade(v).filled(),
        ))
        .map_err(fail)?;
    }
    root.draw(&Rectangle::new([(x, y), (x + 16, y + height)], BLACK))
        .map_err(fail)?;
    for (v, label) in [(hi, "≥ 4"), (1.0, "1"), (0.1, "0.1"), (lo, "≤ 0.01")] {
        let t = (v.ln() - lo.ln()) / (hi.ln() - lo.ln());
        let yy = y + ((1.0 - t) * (height - 1) as f64) as i32;
        root.draw(&Text::new(label, (x + 20, yy - 6), (FONT, 11).into_font()))
            .map_err(fail)?;
    }
    root.draw(&Text::new(
        "(DC white)",
        (x - 4, y + height + 6),
        (FONT, 11).into_font(),
    ))
    .map_err(fail)?;
    Ok(())
}

fn draw_panel(
    area: &DrawingArea<BitMapBackend, Shift>,
    caption: &str,
    panel: &Panel,
) -> Result<(), FigureError> {
    match panel {
        Panel::Scatter(pts) => {
            let mut chart = ChartBuilder::on(area)
                .caption(caption, (FONT, 12))
                .margin(4)
                .build_cartesian_2d(0f64..1f64, 0f64..1f64)
                .map_err(fail)?;
            chart
                .plotting_area()
                .draw(&Rectangle::new([(0.0, 0.0), (1.0, 1.0)], BLACK))
                .map_err(fail)?;
            chart
                .draw_series(
                    pts.iter()
                        .map(|p| Circle::new((p[0], p[1]), 1, BLACK.filled())),
                )
                .map_err(fail)?;
        }
        Panel::Spectrum { values, max_freq } => {
            let f = *max_freq as i64;
            let side = (2 * f + 1) as usize;
            let mut chart = ChartBuilder::on(area)
                .caption(caption, (FONT, 12))
                .margin(4)
                .build_cartesian_2d(-f..f + 1, -f..f + 1)
                .map_err(fail)?;
            let shade = spectrum_shade;
            chart
                .draw_series((0..side * side).map(|k| {
                    let (r, c) = ((k / side) as i64 - f, (k % side) as i64 - f);
                    let v = if r == 0 && c == 0 { 1e9 } else { values[k] };
                    Rectangle::new([(c, r), (c + 1, r + 1)], shade(v).filled())
                }))
                .map_err(fail)?;
        }
    }
    Ok(())
}

/// A grid of panels: one row per entry (its label drawn at the left), panels left to right.
pub fn panel_grid(
    path: &Path,
    title: &str,
    column_labels: &[String],
    rows: &[(String, Vec<Panel>)],
) -> Result<(), FigureError> {
    register_fonts();
    let cols = rows.iter().map(|r| r.1.len()).max().unwrap_or(1);
    let cell = 150u32;
    let (left, top) = (150u32, 40u32);
    let key = rows
        .iter()
        .any(|r| r.1.iter().any(|p| matches!(p, Panel::Spectrum { .. })));
    let key_width = if key { 110 } else { 0 };
    let size = (
        left + cell * cols as u32 + key_width,
        top + cell * rows.len() as u32,
    );
    png::png_figure(path, size, |root| {
        root.fill(&WHITE).map_err(fail)?;
        root.draw(&Text::new(
            title.to_string(),
            (10, 8),
            (FONT, 18).into_font(),
        ))
        .map_err(fail)?;
        for (r, (label, panels)) in rows.iter().enumerate() {
            let y = (top + cell * r as u32) as i32;
            root.draw(&Text::new(
                label.clone(),
                (6, y + cell as i32 / 2 - 8),
                (FONT, 12).into_font(),
            ))
            .map_err(fail)?;
            for (c, panel) in panels.iter().enumerate() {
                let x = (left + cell * c as u32) as i32;
                let area = root.clone().shrink((x, y), (cell, cell));
                let caption = column_labels.get(c).cloned().unwrap_or_default();
                draw_panel(&area, &caption, panel)?;
            }
        }
        if key {
            let x = (left + cell * cols as u32 + 30) as i32;
            draw_grey_key(root, (x, top as i32 + 30), 200)?;
        }
        Ok(())
    })
}

/// All pairs of `dims` coordinates as a matrix: cell (row i, column j) for i < j shows the
/// scatter of coordinates (i, j), cell (j, i) below the diagonal its power spectrum, with the
/// grey-scale key at the right. `scatter(i, j)` gives the points of a pair and `spectrum(i, j)`
/// its spectrum on the (2·`max_freq` + 1)² grid (one realisation's, or a mean over seeds).
pub fn pair_matrix(
    path: &Path,
    title: &str,
    dims: usize,
    scatter: &dyn Fn(usize, usize) -> Vec<[f64; 2]>,
    spectrum: &dyn Fn(usize, usize) -> Vec<f64>,
    max_freq: usize,
) -> Result<(), FigureError> {
    register_fonts();
    let cell = 112u32;
    let (left, top, key_width) = (30u32, 40u32, 120u32);
    let side = cell * dims as u32;
    png::png_figure(path, (left + side + key_width, top + side + 10), |root| {
        root.fill(&WHITE).map_err(fail)?;
        root.draw(&Text::new(
            title.to_string(),
            (10, 8),
            (FONT, 16).into_font(),
        ))
        .map_err(fail)?;
        for i in 0..dims {
            for j in i + 1..dims {
                let pts = scatter(i, j);
                let at = |r: usize, c: usize| {
                    root.clone().shrink(
                        (
                            (left + cell * c as u32) as i32,
                            (top + cell * r as u32) as i32,
                        ),
                        (cell, cell),
                    )
                };
                draw_panel(
                    &at(i, j),
                    &format!("dims {i},{j}"),
                    &Panel::Scatter(pts.clone()),
                )?;
                let values = spectrum(i, j);
                draw_panel(
                    &at(j, i),
                    &format!("spectrum {i},{j}"),
                    &Panel::Spectrum { values, max_freq },
                )?;
            }
        }
        draw_grey_key(root, ((left + side + 40) as i32, top as i32 + 40), 240)?;
        Ok(())
    })
}
