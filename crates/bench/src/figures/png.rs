//! The figures' PNG files: plotters draws into an RGB buffer and the `png` crate encodes it.
//! (plotters' own file encoder needs the `image` crate, with JPEG and BMP besides PNG: about 30
//! of the 700 CPU-seconds of a cold test build.)

use super::FigureError;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Draws a figure of `size` = (width, height) pixels with `draw` and writes it to `path` as an
/// 8-bit RGB PNG. The file is encoded in memory and written in one call, so a write error (a
/// full disk) is returned, never lost in a buffered writer's drop.
pub(crate) fn png_figure(
    path: &Path,
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), FigureError>,
) -> Result<(), FigureError> {
    let bytes = (size.0 as usize)
        .checked_mul(size.1 as usize)
        .and_then(|n| n.checked_mul(3))
        .ok_or_else(|| {
            FigureError(format!(
                "{}: a {}×{} figure is too large",
                path.display(),
                size.0,
                size.1
            ))
        })?;
    let mut rgb = vec![0u8; bytes];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
        draw(&root)?;
        root.present().map_err(|e| FigureError(e.to_string()))?;
    }
    let encoded =
        encode(size, &rgb).map_err(|e| FigureError(format!("{}: {e}", path.display())))?;
    std::fs::write(path, encoded)
        .map_err(|e| FigureError(format!("cannot write {}: {e}", path.display())))
}

/// `rgb` (row-major, 3 bytes per pixel) as the bytes of a PNG file.
fn encode((width, height): (u32, u32), rgb: &[u8]) -> Result<Vec<u8>, png::EncodingError> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A drawn figure decodes to its size and its pixels: white background, one red pixel.
    #[test]
    fn a_figure_round_trips_through_its_png_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("f.png");
        png_figure(&path, (5, 3), |root| {
            root.fill(&WHITE).map_err(|e| FigureError(e.to_string()))?;
            root.draw_pixel((4, 2), &RED)
                .map_err(|e| FigureError(e.to_string()))
        })
        .unwrap();
        let decoder = png::Decoder::new(std::fs::File::open(&path).unwrap());
        let mut reader = decoder.read_info().unwrap();
        let mut pixels = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut pixels).unwrap();
        assert_eq!((info.width, info.height), (5, 3));
        assert_eq!(info.color_type, png::ColorType::Rgb);
        let at = |x: usize, y: usize| &pixels[(y * 5 + x) * 3..][..3];
        assert_eq!(at(4, 2), [255, 0, 0]);
        assert_eq!(at(0, 0), [255, 255, 255]);
        assert_eq!(at(3, 2), [255, 255, 255]);
        // A path that cannot be written is an error naming it.
        let bad = dir.path().join("no/such/folder/f.png");
        let e = png_figure(&bad, (2, 2), |_| Ok(())).unwrap_err();
        assert!(e.0.contains("no/such/folder"), "{e}");
    }
}
