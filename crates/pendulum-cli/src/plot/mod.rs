//! Pictures: line and point charts in panels, drawn with plotters to SVG
//! or PNG. The font (DejaVu Sans) is compiled into the binary and
//! registered once, so no system font library is needed.
//!
//! A [`Figure`] is data (panels of named series: models as lines, data as
//! markers); [`render`] turns it into a file through the same
//! all-or-nothing writer as every other output. Every figure has one look
//! (`style`): the Okabe–Ito palette, legends where they cover nothing
//! (`legend`), robust axis ranges and tick labels with the digits they
//! need (`axis`), curves clipped to the frame (`clip`), PNGs at twice the
//! pixel density.

mod axis;
mod clip;
mod draw;
mod legend;
mod style;

pub use pendulum_data::figure::*;

use crate::error::CliError;
use crate::file::AtomicFile;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Once;
use style::Look;

/// The file formats a plot can be written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics.
    Png,
}

/// Where a plot goes, and in what format.
#[derive(Clone, Debug)]
pub struct Target {
    /// The file.
    pub path: PathBuf,
    /// Its format, from its extension.
    pub format: Format,
    /// The flag that named it, for messages.
    pub flag: &'static str,
}

impl Target {
    /// Checks the extension of `path` (given to `flag`): `.svg` or `.png`;
    /// `-` is SVG on standard output.
    pub fn new(path: &Path, flag: &'static str) -> Result<Self, CliError> {
        if crate::file::is_stdout(path) {
            return Ok(Self {
                path: path.to_path_buf(),
                format: Format::Svg,
                flag,
            });
        }
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        let format = match extension.as_deref() {
            Some("svg") => Format::Svg,
            Some("png") => Format::Png,
            other => {
                let got = other.map_or("no extension".to_string(), |e| format!("'.{e}'"));
                return Err(CliError::flag(
                    flag,
                    format!(
                        "{got} in '{}'; a plot is written as .svg or .png",
                        path.display()
                    ),
                ));
            }
        };
        Ok(Self {
            path: path.to_path_buf(),
            format,
            flag,
        })
    }
}

static FONT: Once = Once::new();

/// Registers the embedded DejaVu Sans as "sans-serif", once per process.
fn register_font() {
    FONT.call_once(|| {
        // The bytes are a valid TrueType file compiled in: this cannot fail.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            dejavu::sans::regular(),
        );
    });
}

/// SVG coordinate units per CSS pixel: coordinates to a tenth of a pixel.
pub const SVG_DENSITY: u32 = 10;

/// PNG pixels per CSS pixel: twice, so lines and letters are smooth (the
/// bitmap backend draws without anti-aliasing).
pub const PNG_DENSITY: u32 = 2;

/// Draws `figure` into `target`; returns the file's path.
pub fn render(target: &Target, figure: &Figure) -> Result<String, CliError> {
    register_font();
    // Words in a figure are checked as printed text is: no "inf" or "NaN".
    for panel in &figure.panels {
        let words = [&panel.title, &panel.x_label, &panel.y_label];
        for text in words
            .into_iter()
            .chain(panel.series.iter().map(|s| &s.label))
        {
            crate::output::check_finite_text(text)?;
        }
    }
    let fail = |e: String| CliError::flag(target.flag, format!("could not draw the plot: {e}"));
    let figure = &in_time_units(figure);
    let (w, h) = figure.size();
    let bytes = match target.format {
        Format::Svg => {
            // Drawn at ten device units a CSS pixel (the backend's
            // coordinates are whole numbers) and shown at the figure's
            // size: every coordinate to a tenth of a pixel, so curves stay
            // smooth when zoomed or printed.
            let mut text = String::new();
            let (dw, dh) = (w * SVG_DENSITY, h * SVG_DENSITY);
            {
                let root = SVGBackend::with_string(&mut text, (dw, dh)).into_drawing_area();
                draw::figure(
                    &root,
                    figure,
                    Look {
                        density: SVG_DENSITY,
                    },
                )
                .map_err(fail)?;
                root.present().map_err(|e| fail(e.to_string()))?;
            }
            let drawn = format!(r#"<svg width="{dw}" height="{dh}" viewBox="0 0 {dw} {dh}""#);
            let shown = format!(r#"<svg width="{w}" height="{h}" viewBox="0 0 {dw} {dh}""#);
            if !text.starts_with(&drawn) {
                return Err(fail("the SVG backend wrote an unexpected header".into()));
            }
            text.replacen(&drawn, &shown, 1).into_bytes()
        }
        Format::Png => {
            let (w, h) = (w * PNG_DENSITY, h * PNG_DENSITY);
            let mut pixels = vec![0_u8; (w * h * 3) as usize];
            {
                let root = BitMapBackend::with_buffer(&mut pixels, (w, h)).into_drawing_area();
                draw::figure(
                    &root,
                    figure,
                    Look {
                        density: PNG_DENSITY,
                    },
                )
                .map_err(fail)?;
                root.present().map_err(|e| fail(e.to_string()))?;
            }
            let mut png = Vec::new();
            let mut encoder = png::Encoder::new(&mut png, w, h);
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            encoder
                .write_header()
                .and_then(|mut writer| writer.write_image_data(&pixels))
                .map_err(|e| fail(e.to_string()))?;
            png
        }
    };
    let mut file = AtomicFile::create(&target.path, target.flag)?;
    file.writer()
        .write_all(&bytes)
        .map_err(|e| file.write_error(e))?;
    file.commit()
}
