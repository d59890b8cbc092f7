//! Pictures: line and point charts in panels, drawn with plotters to SVG
//! or PNG. The font (DejaVu Sans) is compiled into the binary and
//! registered once, so no system font library is needed.
//!
//! A [`Figure`] is data (panels of named series); [`render`] turns it into
//! a file through the same all-or-nothing writer as every other output.

use crate::error::CliError;
use crate::file::AtomicFile;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Once;

/// Picture size in pixels (SVG user units).
pub const SIZE: (u32, u32) = (960, 640);

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

/// Points of a curve, in the panel's units.
pub type Points = Vec<(f64, f64)>;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// A line through the points.
    Line,
    /// A dot at each point.
    Dots,
}

/// One named series of points.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// The points, in the panel's units.
    pub points: Vec<(f64, f64)>,
    /// Line or dots.
    pub style: Style,
    /// A palette index to share another series' colour.
    pub color: Option<usize>,
}

impl Series {
    /// A line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            label: label.into(),
            points,
            style: Style::Line,
            color: None,
        }
    }

    /// The same drawn in palette colour `index` (an unlabelled companion
    /// of another series, like the lower half of an envelope).
    pub fn colored(mut self, index: usize) -> Self {
        self.color = Some(index);
        self
    }

    /// Dots.
    pub fn dots(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            label: label.into(),
            points,
            style: Style::Dots,
            color: None,
        }
    }
}

/// One chart: a title, two axis labels (with units) and its series.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Title.
    pub title: String,
    /// Horizontal axis label, with its unit.
    pub x_label: String,
    /// Vertical axis label, with its unit.
    pub y_label: String,
    /// The series, drawn in order.
    pub series: Vec<Series>,
    /// Where the legend goes (out of the data's way).
    pub legend: SeriesLabelPosition,
    /// Both axes logarithmic (a quantity that spans decades).
    pub log_log: bool,
}

impl Panel {
    /// A panel with its legend at the upper right.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
        series: Vec<Series>,
    ) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series,
            legend: SeriesLabelPosition::UpperRight,
            log_log: false,
        }
    }

    /// The same on logarithmic axes (positive values only; others are left
    /// out).
    pub fn log_log(mut self) -> Self {
        self.log_log = true;
        self
    }

    /// The same with the legend at the lower left (for curves that fall
    /// to the right).
    pub fn legend_lower_left(mut self) -> Self {
        self.legend = SeriesLabelPosition::LowerLeft;
        self
    }

    /// The same with the legend at the upper left (for rising curves).
    pub fn legend_upper_left(mut self) -> Self {
        self.legend = SeriesLabelPosition::UpperLeft;
        self
    }
}

/// Panels stacked top to bottom.
#[derive(Clone, Debug)]
pub struct Figure {
    /// The panels.
    pub panels: Vec<Panel>,
}

/// Colours for successive series (a colour-blind-safe palette, Okabe & Ito 2008).
const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
    RGBColor(240, 228, 66),
];

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

/// Draws `figure` into `target`; returns the file's path.
pub fn render(target: &Target, figure: &Figure) -> Result<String, CliError> {
    register_font();
    let fail = |e: String| CliError::flag(target.flag, format!("could not draw the plot: {e}"));
    let bytes = match target.format {
        Format::Svg => {
            let mut text = String::new();
            {
                let root = SVGBackend::with_string(&mut text, SIZE).into_drawing_area();
                draw(&root, figure).map_err(fail)?;
                root.present().map_err(|e| fail(e.to_string()))?;
            }
            text.into_bytes()
        }
        Format::Png => {
            let (w, h) = SIZE;
            let mut pixels = vec![0_u8; (w * h * 3) as usize];
            {
                let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
                draw(&root, figure).map_err(fail)?;
                root.present().map_err(|e| fail(e.to_string()))?;
            }
            let image = image::RgbImage::from_raw(w, h, pixels)
                .ok_or_else(|| fail("the pixel buffer has the wrong size".into()))?;
            let mut png = std::io::Cursor::new(Vec::new());
            image
                .write_to(&mut png, image::ImageOutputFormat::Png)
                .map_err(|e| fail(e.to_string()))?;
            png.into_inner()
        }
    };
    let mut file = AtomicFile::create(&target.path, target.flag)?;
    file.writer()
        .write_all(&bytes)
        .map_err(|e| file.write_error(e))?;
    file.commit()
}

/// Draws every panel of `figure`, stacked, on `root`.
fn draw<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, figure: &Figure) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let areas = root.split_evenly((figure.panels.len().max(1), 1));
    for (area, panel) in areas.iter().zip(&figure.panels) {
        draw_panel(area, panel)?;
    }
    Ok(())
}

/// The data's range with a 5% margin (and a unit width when it is flat).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo <= f64::EPSILON * hi.abs().max(lo.abs()).max(1e-300) {
        let pad = if lo == 0.0 { 1.0 } else { 0.05 * lo.abs() };
        return (lo - pad, hi + pad);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

/// The positive data's range with a margin of 5% of its decades (a
/// factor of ten either way when it is one value).
fn log_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite() && *v > 0.0) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.1, 10.0);
    }
    if hi <= lo {
        return (lo / 10.0, hi * 10.0);
    }
    let pad = (hi / lo).powf(0.05);
    (lo / pad, hi * pad)
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
) -> Result<(), String> {
    let points = || panel.series.iter().flat_map(|s| s.points.iter());
    let mut builder = ChartBuilder::on(area);
    builder
        .caption(&panel.title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(80);
    if panel.log_log {
        let (x0, x1) = log_range(points().map(|p| p.0));
        let (y0, y1) = log_range(points().map(|p| p.1));
        let mut chart = builder
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(|e| e.to_string())?;
        // On a log axis a label's digits follow its own size.
        let tick = |v: &f64| tick_label(*v, v.abs());
        draw_mesh(&mut chart, panel, &tick, &tick)?;
        let positive = |p: &(f64, f64)| p.0 > 0.0 && p.1 > 0.0;
        draw_series(&mut chart, panel, positive)
    } else {
        let (x0, x1) = range(points().map(|p| p.0));
        let (y0, y1) = range(points().map(|p| p.1));
        let mut chart = builder
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| e.to_string())?;
        let (x_span, y_span) = (x1 - x0, y1 - y0);
        let x_tick = move |v: &f64| tick_label(*v, x_span);
        let y_tick = move |v: &f64| tick_label(*v, y_span);
        draw_mesh(&mut chart, panel, &x_tick, &y_tick)?;
        draw_series(&mut chart, panel, |_| true)
    }
}

/// The grid, the tick labels (by `x_tick` and `y_tick`) and the axis
/// titles of `panel` on `chart`.
fn draw_mesh<'a, DB, X, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    panel: &Panel,
    x_tick: &dyn Fn(&f64) -> String,
    y_tick: &dyn Fn(&f64) -> String,
) -> Result<(), String>
where
    DB: DrawingBackend + 'a,
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    chart
        .configure_mesh()
        .x_label_formatter(x_tick)
        .y_label_formatter(y_tick)
        .x_desc(&panel.x_label)
        .y_desc(&panel.y_label)
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(|e| e.to_string())
}

/// The panel's series and legend on `chart`, the points `keep` accepts
/// (finite ones always).
fn draw_series<'a, DB, X, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    panel: &Panel,
    keep: impl Fn(&(f64, f64)) -> bool + Copy,
) -> Result<(), String>
where
    DB: DrawingBackend + 'a,
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let shown = move |p: &(f64, f64)| p.0.is_finite() && p.1.is_finite() && keep(p);
    for (i, series) in panel.series.iter().enumerate() {
        let color = PALETTE[series.color.unwrap_or(i) % PALETTE.len()];
        let drawn = match series.style {
            Style::Line => chart.draw_series(LineSeries::new(
                series.points.iter().copied().filter(shown),
                color.stroke_width(2),
            )),
            Style::Dots => chart.draw_series(
                series
                    .points
                    .iter()
                    .filter(|p| shown(p))
                    .map(|&p| Circle::new(p, 3, color.filled())),
            ),
        }
        .map_err(|e| e.to_string())?;
        if !series.label.is_empty() {
            drawn.label(&series.label).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
            });
        }
    }
    if panel.series.len() > 1 || panel.series.first().is_some_and(|s| !s.label.is_empty()) {
        chart
            .configure_series_labels()
            .label_font(("sans-serif", 14))
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(150, 150, 150))
            .position(panel.legend.clone())
            .draw()
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// A tick label with the digits the axis needs and no more: rounded to a
/// hundredth of the axis's `span` (ticks fall at about a tenth of it), then
/// trailing zeros dropped (`1400`, `2.5`, never `1400.0`), and never `-0`.
/// Values of a million and more, or spans below 1e-4, in exponent form
/// (`1.5e-5`).
pub fn tick_label(value: f64, span: f64) -> String {
    if !value.is_finite() {
        return String::new();
    }
    let magnitude = value.abs();
    let text = if magnitude >= 1e6 || (span > 0.0 && span < 1e-4 && magnitude > 0.0) {
        // Significant digits down to a hundredth of the span.
        let digits = if span > 0.0 && magnitude > 0.0 {
            (magnitude.log10().floor() - (span / 100.0).log10().floor() + 1.0).clamp(1.0, 12.0)
                as usize
        } else {
            3
        };
        let t = format!("{:.*e}", digits.saturating_sub(1), value);
        let (mantissa, exponent) = t.split_once('e').unwrap_or((&t, "0"));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        format!("{mantissa}e{exponent}")
    } else {
        let decimals = if span > 0.0 {
            (-(span / 100.0).log10()).ceil().clamp(0.0, 12.0) as usize
        } else {
            6
        };
        let t = format!("{value:.decimals$}");
        if t.contains('.') {
            t.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            t
        }
    };
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".to_string()
    } else {
        text
    }
}

/// At most `limit` points, evenly thinned, keeping the first and the last.
pub fn thin(points: Vec<(f64, f64)>, limit: usize) -> Vec<(f64, f64)> {
    if points.len() <= limit || limit < 2 {
        return points;
    }
    let step = (points.len() - 1) as f64 / (limit - 1) as f64;
    (0..limit)
        .map(|i| points[((i as f64 * step).round() as usize).min(points.len() - 1)])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::tick_label;

    #[test]
    fn tick_labels_carry_the_digits_they_need() {
        assert_eq!(tick_label(1400.0, 1000.0), "1400");
        assert_eq!(tick_label(2.5, 2.0), "2.5");
        assert_eq!(tick_label(2.0, 2.0), "2");
        assert_eq!(tick_label(-0.0, 1.0), "0");
        assert_eq!(tick_label(-1e-17, 1.0), "0");
        assert_eq!(tick_label(0.99362, 0.001), "0.99362");
        assert_eq!(tick_label(1.5e-5, 2e-5), "1.5e-5");
        assert_eq!(tick_label(2.0e7, 1e7), "2e7");
        assert_eq!(tick_label(-3.25, 1.0), "-3.25");
        assert_eq!(tick_label(f64::NAN, 1.0), "");
    }
}
