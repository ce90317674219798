//! The scene pictures: RMSE against N per scene (median layout, band from best to worst
//! layout), and the image scene's reference, renderings and per-pixel error maps.

use super::measure::extremes;
use super::report::SceneReport;
use crate::figures::{loglog_lines_banded, FigureError, Series};
use plotters::prelude::*;
use std::path::Path;

/// RMSE against N of every method on `scene`: the line is the median layout, the band spans
/// the best to the worst layout.
pub fn curves_figure(path: &Path, report: &SceneReport, scene: &str) -> Result<(), FigureError> {
    let results: Vec<_> = report.results.iter().filter(|r| r.scene == scene).collect();
    let series: Vec<Series> = results
        .iter()
        .map(|r| Series {
            label: r.method.clone(),
            points: (0..r.n.len())
                .map(|s| (r.n[s] as f64, extremes(r, s)[1].1))
                .collect(),
        })
        .collect();
    let bands: Vec<Vec<(f64, f64)>> = results
        .iter()
        .map(|r| {
            (0..r.n.len())
                .map(|s| {
                    let e = extremes(r, s);
                    (e[0].1, e[2].1)
                })
                .collect()
        })
        .collect();
    loglog_lines_banded(
        path,
        &format!("{scene}: RMSE against N (line: median layout; band: best to worst layout)"),
        "N",
        "RMSE",
        &series,
        &bands,
        &[-0.5, -1.0],
    )
}

fn fail(e: impl std::fmt::Display) -> FigureError {
    FigureError(e.to_string())
}

/// Grey level of radiance `v`: linear from black at 0 to white at `max`.
fn grey(v: f64, max: f64) -> RGBColor {
    let t = (v / max).clamp(0.0, 1.0);
    let g = (t * 255.0).round() as u8;
    RGBColor(g, g, g)
}

/// Diverging colour of error `e` on ±`max`: blue below, white at 0, red above.
fn diverging(e: f64, max: f64) -> RGBColor {
    let t = (e / max).clamp(-1.0, 1.0);
    let fade = (255.0 * (1.0 - t.abs())).round() as u8;
    if t >= 0.0 {
        RGBColor(255, fade, fade)
    } else {
        RGBColor(fade, fade, 255)
    }
}

/// The reference image, one rendering per method, and under each its error map (rendering −
/// reference, on one shared ±scale). Images are row-major, `side` × `side`, row 0 at the top.
pub fn image_figure(
    path: &Path,
    title: &str,
    side: usize,
    reference: &[f64],
    renders: &[(String, Vec<f64>)],
) -> Result<(), FigureError> {
    let scale = (192 / side.max(1)).max(1) as i32;
    let cell = side as i32 * scale;
    let (gap, top, label) = (12i32, 40i32, 18i32);
    let cols = renders.len() as i32 + 1;
    let width = (gap + cols * (cell + gap)) as u32;
    let height = (top + 2 * (cell + label + gap) + 30) as u32;
    crate::figures::png::png_figure(path, (width, height), |root| {
        root.fill(&WHITE).map_err(fail)?;
        let font = ("sans-serif", 13).into_font();
        root.draw(&Text::new(
            title.to_string(),
            (gap, 10),
            ("sans-serif", 16).into_font(),
        ))
        .map_err(fail)?;
        let max = reference.iter().copied().fold(0.0, f64::max).max(1e-12);
        let err_max = renders
            .iter()
            .flat_map(|(_, r)| r.iter().zip(reference).map(|(a, b)| (a - b).abs()))
            .filter(|e| e.is_finite())
            .fold(0.0, f64::max)
            .max(1e-12);
        let draw = |col: i32, row: i32, caption: &str, color: &dyn Fn(usize) -> RGBColor| {
            let x0 = gap + col * (cell + gap);
            let y0 = top + row * (cell + label + gap) + label;
            root.draw(&Text::new(
                caption.to_string(),
                (x0, y0 - label),
                font.clone(),
            ))
            .map_err(fail)?;
            for k in 0..side * side {
                // Row 0 of the image (lowest y) at the bottom, as the plane is seen from above.
                let (i, j) = ((k % side) as i32, (side - 1 - k / side) as i32);
                let (x, y) = (x0 + i * scale, y0 + j * scale);
                root.draw(&Rectangle::new(
                    [(x, y), (x + scale, y + scale)],
                    color(k).filled(),
                ))
                .map_err(fail)?;
            }
            Ok::<(), FigureError>(())
        };
        draw(0, 0, "reference", &|k| grey(reference[k], max))?;
        for (c, (name, img)) in renders.iter().enumerate() {
            draw(c as i32 + 1, 0, name, &|k| grey(img[k], max))?;
            draw(c as i32 + 1, 1, "error", &|k| {
                diverging(img[k] - reference[k], err_max)
            })?;
        }
        root.draw(&Text::new(
            format!("error maps: blue −{err_max:.3}, white 0, red +{err_max:.3}"),
            (gap, height as i32 - 24),
            font.clone(),
        ))
        .map_err(fail)?;
        Ok(())
    })
}
