//! A [`Figure`] onto a plotters drawing area: panels stacked, each with
//! its axes, its series clipped to the frame and its legend placed where
//! it covers nothing.

use super::axis::{
    label_offset, log_tick_label, log_ticks, offset_label, span, tick_label, Scale, Span,
};
use super::clip::{self, Point};
use super::legend::{self, Drawn, Place, Rect};
use super::style::{Look, GRID, LEGEND_BORDER, MARK, PALETTE};
use super::{Figure, Panel, Style, Weight};
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

type Failure = String;

fn fail<E: std::fmt::Display>(e: E) -> Failure {
    e.to_string()
}

/// Draws every panel of `figure`, stacked, on `root`.
pub fn figure<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    figure: &Figure,
    look: Look,
) -> Result<(), Failure> {
    root.fill(&WHITE).map_err(fail)?;
    let areas = root.split_evenly((figure.panels.len().max(1), 1));
    // A legend that goes beside its plot narrows every panel alike, so
    // that stacked panels keep one horizontal axis.
    let mut reserve = 0;
    for (area, panel) in areas.iter().zip(&figure.panels) {
        reserve = reserve.max(draw_panel(area, panel, look, 0, false)?);
    }
    for (area, panel) in areas.iter().zip(&figure.panels) {
        draw_panel(area, panel, look, reserve, true)?;
    }
    Ok(())
}

/// One series in axis units, ready to draw.
struct Prepared {
    /// Line pieces inside the frame, or markers inside it.
    pieces: Vec<Vec<Point>>,
    /// The style.
    style: Style,
    /// Palette colour.
    color: RGBColor,
    /// Legend text with the count of points off-scale, if any.
    label: String,
    /// A line's weight.
    weight: Weight,
    /// Drawn dashed (the n-th dash pattern, from 1): it lies on a line
    /// drawn before it; 0 for a solid line.
    dashed: usize,
    /// Error bars inside the frame, axis units.
    bars: Vec<(Point, Point)>,
}

/// One legend entry: its swatch and text.
struct Entry {
    style: Option<Style>,
    color: RGBColor,
    text: String,
    weight: Weight,
    dashed: usize,
    /// Markers drawn open (many of them over lines).
    open: bool,
}

/// The axis spans of `panel` (before any room is made for the legend).
fn spans(panel: &Panel) -> (Span, Span) {
    let (mut mx, mut my, mut dx, mut dy) = (vec![], vec![], vec![], vec![]);
    for s in &panel.series {
        let (xs, ys) = match s.style {
            Style::Line => (&mut mx, &mut my),
            Style::Dots => (&mut dx, &mut dy),
        };
        for &(x, y) in &s.points {
            if let (Some(u), Some(v)) = (panel.x_scale.to_axis(x), panel.y_scale.to_axis(y)) {
                xs.push(u);
                ys.push(v);
            }
        }
        for (&(x, _), &(lo, hi)) in s.points.iter().zip(s.bars.iter().flatten()) {
            if panel.x_scale.to_axis(x).is_some() {
                ys.extend([lo, hi].iter().filter_map(|&v| panel.y_scale.to_axis(v)));
            }
        }
    }
    mx.extend(
        panel
            .marks
            .iter()
            .filter_map(|m| panel.x_scale.to_axis(m.x)),
    );
    (span(panel.x_scale, &mx, &dx), span(panel.y_scale, &my, &dy))
}

/// The series of `panel` clipped to `x` × `y` (axis units).
fn prepare(panel: &Panel, x: Span, y: Span) -> Vec<Prepared> {
    panel
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let color = PALETTE[s.color.unwrap_or(i) % PALETTE.len()];
            let axis: Vec<Option<Point>> = s
                .points
                .iter()
                .map(|&(a, b)| Some((panel.x_scale.to_axis(a)?, panel.y_scale.to_axis(b)?)))
                .collect();
            let (pieces, off) = match s.style {
                Style::Line => (clip::polyline(&axis, x, y), 0),
                Style::Dots => {
                    let inside: Vec<Point> = axis
                        .iter()
                        .flatten()
                        .copied()
                        .filter(|p| x.contains(p.0) && y.contains(p.1))
                        .collect();
                    // Off-scale: outside the frame, or not showable (a
                    // value that is not positive on a log axis).
                    let off = s.points.len() - inside.len();
                    (vec![inside], off)
                }
            };
            let label = match (s.label.is_empty(), off) {
                (_, 0) => s.label.clone(),
                (true, n) => format!("{n} points off-scale"),
                (false, n) => format!("{} ({n} off-scale)", s.label),
            };
            // Each bar clipped to the frame; a low end that a log axis
            // cannot show is drawn from the frame's edge.
            let bars = s
                .points
                .iter()
                .zip(s.bars.iter().flatten())
                .filter_map(|(&(a, _), &(lo, hi))| {
                    let u = panel.x_scale.to_axis(a)?;
                    let top = panel.y_scale.to_axis(hi)?;
                    let bottom = panel.y_scale.to_axis(lo).unwrap_or(y.lo);
                    clip::segment((u, bottom), (u, top), x, y)
                })
                .collect();
            Prepared {
                pieces,
                style: s.style,
                color,
                label,
                weight: s.weight,
                dashed: 0,
                bars,
            }
        })
        .collect()
}

/// Maps axis units to device pixels inside `plot`.
#[derive(Clone, Copy)]
struct Map {
    plot: Rect,
    x: Span,
    y: Span,
}

impl Map {
    fn px(&self, p: Point) -> (f64, f64) {
        (
            self.plot.x0 + (p.0 - self.x.lo) / self.x.width() * (self.plot.x1 - self.plot.x0),
            self.plot.y1 - (p.1 - self.y.lo) / self.y.width() * self.plot.height(),
        )
    }
}

/// Marks dashed each named line that runs along a line of another colour
/// drawn before it (most of its length within two pixels of it), so that
/// both stay visible: the earlier line shows between the later one's
/// dashes. (Unnamed companions, as a portrait's many loops, stay solid.)
fn dash_coincident(prepared: &mut [Prepared], map: Map, look: Look) {
    let cell = f64::from(look.px(2));
    let step = f64::from(look.px(2));
    let mut drawn: std::collections::HashMap<(i64, i64), RGBColor> =
        std::collections::HashMap::new();
    let mut dashes = 0;
    for p in prepared.iter_mut().filter(|p| p.style == Style::Line) {
        let mut trace = Drawn::default();
        for piece in &p.pieces {
            for w in piece.windows(2) {
                trace.trace(map.px(w[0]), map.px(w[1]), step);
            }
        }
        let cells: Vec<(i64, i64)> = trace
            .lines
            .iter()
            .map(|&(x, y)| ((x / cell).floor() as i64, (y / cell).floor() as i64))
            .collect();
        let color = p.color;
        let near = |&(i, j): &(i64, i64)| {
            (-1..=1).any(|di| {
                (-1..=1).any(|dj| drawn.get(&(i + di, j + dj)).is_some_and(|&c| c != color))
            })
        };
        let on_earlier = cells.iter().filter(|c| near(c)).count();
        if !p.label.is_empty() && !cells.is_empty() && on_earlier as f64 >= 0.6 * cells.len() as f64
        {
            dashes += 1;
            p.dashed = dashes;
        }
        for c in cells {
            drawn.insert(c, color);
        }
    }
}

/// Whether the markers of `p` are drawn open: many of them (over 50) in a
/// panel with lines, so that the lines show through them.
/// More data points than a law drawn under them can be seen through.
const DENSE_CLOUD: usize = 400;

fn open_markers(prepared: &[Prepared], p: &Prepared) -> bool {
    p.pieces.first().is_some_and(|points| points.len() > 50)
        && prepared.iter().any(|q| q.style == Style::Line)
}

/// The n-th dash pattern (from 1), dash and gap in device pixels: long
/// dashes, then dots, then short dashes, so that two dashed lines on one
/// another still show apart.
fn dash_pattern(n: usize, look: Look) -> (u32, u32) {
    match n % 3 {
        1 => (look.px(8), look.px(5)),
        2 => (look.px(2), look.px(4)),
        _ => (look.px(4), look.px(3)),
    }
}

/// Everything drawn in `plot`, in device pixels, for placing the legend.
fn drawn(prepared: &[Prepared], panel: &Panel, map: Map, look: Look) -> Drawn {
    let mut d = Drawn::default();
    let step = f64::from(look.px(3));
    for p in prepared {
        match p.style {
            Style::Line => {
                for piece in &p.pieces {
                    for w in piece.windows(2) {
                        d.trace(map.px(w[0]), map.px(w[1]), step);
                    }
                }
            }
            Style::Dots => {
                let r = f64::from(look.marker_radius(p.pieces[0].len()));
                d.markers.extend(p.pieces[0].iter().map(|&q| {
                    let (x, y) = map.px(q);
                    (x, y, r)
                }));
            }
        }
        for (a, b) in &p.bars {
            d.trace(map.px(*a), map.px(*b), step);
        }
    }
    for m in &panel.marks {
        if let Some(u) = panel.x_scale.to_axis(m.x) {
            d.trace(map.px((u, map.y.lo)), map.px((u, map.y.hi)), step);
        }
    }
    d
}

/// Lays out one panel with `reserve` pixels kept free on the right, and
/// draws it when `paint`; returns the width its legend needs beside the
/// plot (0 when it goes inside).
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    look: Look,
    reserve: i32,
    paint: bool,
) -> Result<i32, Failure> {
    let (x, y) = spans(panel);
    let mut prepared = prepare(panel, x, y);
    let m = look.margin() as i32;
    let inner = area.margin(m, m, m, m);
    let title_style: TextStyle = ("sans-serif", look.title_font()).into();
    let (_, text_h) = inner
        .estimate_text_size(&panel.title, &title_style)
        .map_err(fail)?;
    let title_pad = (text_h / 2).min(look.px(5));
    let title_h = text_h + 2 * title_pad;
    let (title_area, titled) = inner.split_vertically(title_h);

    // The legend's entries and size.
    let font: TextStyle = ("sans-serif", look.label_font()).into();
    // The plot rectangle as ChartBuilder will lay it out, in the titled
    // area's own pixels.
    let (w, h) = titled.dim_in_pixel();
    // A second axis on the right takes a label area's width there.
    let twin = panel
        .y_twin
        .as_ref()
        .filter(|_| panel.x_scale == Scale::Log && panel.y_scale == Scale::Log);
    let twin_w = if twin.is_some() {
        look.y_label_area() as i32
    } else {
        0
    };
    let predicted = Rect {
        x0: f64::from(look.y_label_area()),
        y0: 0.0,
        x1: f64::from(w) - f64::from(reserve) - f64::from(twin_w),
        y1: f64::from(h) - f64::from(look.x_label_area()),
    };
    dash_coincident(
        &mut prepared,
        Map {
            plot: predicted,
            x,
            y,
        },
        look,
    );
    let mut entries: Vec<Entry> = prepared
        .iter()
        .filter(|p| !p.label.is_empty())
        .map(|p| Entry {
            style: Some(p.style),
            color: p.color,
            text: p.label.clone(),
            weight: p.weight,
            dashed: p.dashed,
            open: p.style == Style::Dots && open_markers(&prepared, p),
        })
        .collect();
    entries.extend(
        panel
            .marks
            .iter()
            .filter(|m| !m.label.is_empty())
            .map(|m| Entry {
                style: None,
                color: MARK,
                text: m.label.clone(),
                weight: Weight::Light,
                dashed: 1,
                open: false,
            }),
    );
    let pad = f64::from(look.px(6));
    let swatch = f64::from(look.px(24));
    let row = f64::from(look.label_font()) * 1.35;
    let mut text_width = 0.0_f64;
    for e in &entries {
        let (w, _) = titled.estimate_text_size(&e.text, &font).map_err(fail)?;
        text_width = text_width.max(f64::from(w));
    }
    let size = (
        pad + swatch + pad + text_width + pad,
        2.0 * pad + row * entries.len() as f64,
    );
    let inset = f64::from(look.px(8));
    let gap = f64::from(look.px(3));

    let place = if entries.is_empty() {
        Place::Inside((1.0, 0.0))
    } else {
        let map = Map {
            plot: predicted,
            x,
            y,
        };
        legend::place(
            predicted,
            size,
            inset,
            gap,
            &drawn(&prepared, panel, map, look),
        )
    };
    // Room above the data: the span grows so that the data end `need`
    // pixels below the top.
    let y_drawn = match place {
        Place::Above => {
            let need = size.1 + 2.0 * inset;
            let height = predicted.height();
            Span {
                lo: y.lo,
                hi: (y.hi * height - y.lo * need) / (height - need),
            }
        }
        _ => y,
    };
    let beside = match place {
        Place::Beside => (size.0 + 2.0 * inset).ceil() as i32,
        _ => 0,
    };
    if !paint {
        return Ok(beside);
    }
    title_area
        .draw_text(
            &panel.title,
            &title_style.pos(Pos::new(HPos::Center, VPos::Top)),
            (
                // Centred over the plot, not over the legend beside it.
                (look.y_label_area() as i32 + w as i32 - beside.max(reserve)) / 2,
                i32::try_from(title_pad).unwrap_or(0),
            ),
        )
        .map_err(fail)?;
    let chart_area = titled.margin(0, 0, 0, beside.max(reserve));
    let mut builder = ChartBuilder::on(&chart_area);
    builder
        .x_label_area_size(look.x_label_area())
        .y_label_area_size(look.y_label_area())
        .right_y_label_area_size(twin_w.max(0) as u32);
    let (x0, x1) = (panel.x_scale.value_at(x.lo), panel.x_scale.value_at(x.hi));
    let (y0, y1) = (
        panel.y_scale.value_at(y_drawn.lo),
        panel.y_scale.value_at(y_drawn.hi),
    );
    let contents = Contents {
        prepared: &prepared,
        panel,
        y: y_drawn,
        look,
    };
    let plot = match (panel.x_scale, panel.y_scale) {
        (Scale::Linear, Scale::Linear) => {
            let mut c = builder.build_cartesian_2d(x0..x1, y0..y1).map_err(fail)?;
            contents.draw(&mut c)?
        }
        (Scale::Log, Scale::Linear) => {
            let mut c = builder
                .build_cartesian_2d((x0..x1).log_scale().with_key_points(log_ticks(x)), y0..y1)
                .map_err(fail)?;
            contents.draw(&mut c)?
        }
        (Scale::Linear, Scale::Log) => {
            let mut c = builder
                .build_cartesian_2d(
                    x0..x1,
                    (y0..y1).log_scale().with_key_points(log_ticks(y_drawn)),
                )
                .map_err(fail)?;
            contents.draw(&mut c)?
        }
        (Scale::Log, Scale::Log) => {
            let c = builder
                .build_cartesian_2d(
                    (x0..x1).log_scale().with_key_points(log_ticks(x)),
                    (y0..y1).log_scale().with_key_points(log_ticks(y_drawn)),
                )
                .map_err(fail)?;
            match twin {
                None => {
                    let mut c = c;
                    contents.draw(&mut c)?
                }
                Some(t) => {
                    let shift = t.factor.log10();
                    let twin_span = Span {
                        lo: y_drawn.lo + shift,
                        hi: y_drawn.hi + shift,
                    };
                    let mut c = c.set_secondary_coord(
                        (x0..x1).log_scale(),
                        (y0 * t.factor..y1 * t.factor)
                            .log_scale()
                            .with_key_points(log_ticks(twin_span)),
                    );
                    let pixels = contents.draw(&mut c)?;
                    let tick = |v: &f64| log_tick_label(*v);
                    c.configure_secondary_axes()
                        .y_desc(&t.label)
                        .y_label_formatter(&tick)
                        .label_style(("sans-serif", look.label_font()))
                        .axis_desc_style(("sans-serif", look.axis_font()))
                        .axis_style(BLACK.stroke_width(look.px(1)))
                        .set_all_tick_mark_size(look.px(5))
                        .draw()
                        .map_err(fail)?;
                    pixels
                }
            }
        }
    };
    if entries.is_empty() {
        return Ok(beside);
    }
    // The plot's pixels relative to `area`.
    let (bx, by) = area.get_base_pixel();
    let plot = Rect {
        x0: f64::from(plot.0.start - bx),
        y0: f64::from(plot.1.start - by),
        x1: f64::from(plot.0.end - bx),
        y1: f64::from(plot.1.end - by),
    };
    let at = match place {
        Place::Inside(spot) => legend::box_at(plot, size, inset, spot),
        Place::Above => legend::box_at(plot, size, inset, (1.0, 0.0)),
        Place::Beside => Rect {
            x0: plot.x1 + f64::from(twin_w) + inset,
            y0: plot.y0,
            x1: plot.x1 + f64::from(twin_w) + inset + size.0,
            y1: plot.y0 + size.1,
        },
    };
    draw_legend(area, at, &entries, look, pad, swatch, row)?;
    Ok(beside)
}

/// The series, the marks and the axes of one panel.
struct Contents<'p> {
    prepared: &'p [Prepared],
    panel: &'p Panel,
    /// The vertical span drawn (axis units), for the marks.
    y: Span,
    look: Look,
}

impl Contents<'_> {
    /// Draws on `chart`; returns the plot's pixel range.
    fn draw<'a, DB, X, Y>(
        &self,
        chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
    ) -> Result<(std::ops::Range<i32>, std::ops::Range<i32>), Failure>
    where
        DB: DrawingBackend + 'a,
        X: Ranged<ValueType = f64> + ValueFormatter<f64>,
        Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
    {
        let (panel, look) = (self.panel, self.look);
        let x_range = chart.x_range();
        let y_range = chart.y_range();
        let (x_span, y_span) = (x_range.end - x_range.start, y_range.end - y_range.start);
        // On a log axis every label takes one form: exponents when the
        // axis reaches below 1e-3 or to 1e5, plain numbers otherwise.
        // A linear axis whose values differ only far down their digits is
        // labelled from an offset, named in its title.
        let offset = |scale: Scale, range: &std::ops::Range<f64>| match scale {
            Scale::Linear => label_offset(range.start, range.end),
            Scale::Log => None,
        };
        let (x_offset, y_offset) = (
            offset(panel.x_scale, &x_range),
            offset(panel.y_scale, &y_range),
        );
        let title = |label: &str, offset: Option<f64>, span: f64| match offset {
            Some(o) => format!("{label} − {}", offset_label(o, span)),
            None => label.to_string(),
        };
        let x_title = title(&panel.x_label, x_offset, x_span);
        let y_title = title(&panel.y_label, y_offset, y_span);
        let x_tick = move |v: &f64| match panel.x_scale {
            Scale::Linear => tick_label(*v - x_offset.unwrap_or(0.0), x_span),
            Scale::Log => log_tick_label(*v),
        };
        let y_tick = move |v: &f64| match panel.y_scale {
            Scale::Linear => tick_label(*v - y_offset.unwrap_or(0.0), y_span),
            Scale::Log => log_tick_label(*v),
        };
        chart
            .configure_mesh()
            .x_label_formatter(&x_tick)
            .y_label_formatter(&y_tick)
            .x_desc(&x_title)
            .y_desc(&y_title)
            .label_style(("sans-serif", look.label_font()))
            .axis_desc_style(("sans-serif", look.axis_font()))
            .axis_style(BLACK.stroke_width(look.px(1)))
            .bold_line_style(GRID.stroke_width(look.px(1)))
            .light_line_style(TRANSPARENT)
            .set_all_tick_mark_size(look.px(5))
            .draw()
            .map_err(fail)?;
        let (xs, ys) = (panel.x_scale, panel.y_scale);
        let value = move |p: &Point| (xs.value_at(p.0), ys.value_at(p.1));
        for m in &panel.marks {
            if xs.to_axis(m.x).is_some() {
                chart
                    .draw_series(std::iter::once(DashedPathElement::new(
                        vec![(m.x, ys.value_at(self.y.lo)), (m.x, ys.value_at(self.y.hi))],
                        look.px(6),
                        look.px(4),
                        MARK.stroke_width(look.px(1)),
                    )))
                    .map_err(fail)?;
            }
        }
        // Models first, the data over them: measured points are never
        // hidden by a law; a dense cloud is drawn half transparent so the
        // law shows through it. A cloud of more points than a law can be
        // seen through (a log's hourly rates) is drawn first, the law
        // over it.
        let dense = self
            .prepared
            .iter()
            .any(|p| p.style == Style::Dots && p.pieces[0].len() > DENSE_CLOUD);
        let order = if dense {
            [Style::Dots, Style::Line]
        } else {
            [Style::Line, Style::Dots]
        };
        for phase in order {
            if phase == Style::Line {
                for p in self.prepared.iter().filter(|p| p.style == Style::Line) {
                    let stroke = p.color.stroke_width(look.weighted_width(p.weight));
                    for piece in &p.pieces {
                        if p.dashed > 0 {
                            let (dash, gap) = dash_pattern(p.dashed, look);
                            chart
                                .draw_series(std::iter::once(DashedPathElement::new(
                                    piece.iter().map(value).collect::<Vec<_>>(),
                                    dash,
                                    gap,
                                    stroke,
                                )))
                                .map_err(fail)?;
                        } else {
                            chart
                                .draw_series(LineSeries::new(piece.iter().map(value), stroke))
                                .map_err(fail)?;
                        }
                    }
                }
            } else {
                for p in self.prepared.iter().filter(|p| !p.bars.is_empty()) {
                    let stroke = p.color.stroke_width(look.px(1));
                    chart
                        .draw_series(
                            p.bars
                                .iter()
                                .map(|(a, b)| PathElement::new(vec![value(a), value(b)], stroke)),
                        )
                        .map_err(fail)?;
                }
                for p in self.prepared.iter().filter(|p| p.style == Style::Dots) {
                    let count = p.pieces[0].len();
                    let r = look.marker_radius(count);
                    let style = if open_markers(self.prepared, p) {
                        p.color.stroke_width(look.px(1))
                    } else {
                        p.color.filled()
                    };
                    chart
                        .draw_series(p.pieces[0].iter().map(|q| Circle::new(value(q), r, style)))
                        .map_err(fail)?;
                }
            }
        }
        Ok(chart.plotting_area().get_pixel_range())
    }
}

/// The legend box at `at` (pixels of `area`): a white box with a grey
/// border, a swatch and a text per entry.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    at: Rect,
    entries: &[Entry],
    look: Look,
    pad: f64,
    swatch: f64,
    row: f64,
) -> Result<(), Failure> {
    let corner = |x: f64, y: f64| (x.round() as i32, y.round() as i32);
    let (a, b) = (corner(at.x0, at.y0), corner(at.x1, at.y1));
    area.draw(&Rectangle::new([a, b], WHITE.mix(0.9).filled()))
        .map_err(fail)?;
    area.draw(&Rectangle::new(
        [a, b],
        LEGEND_BORDER.stroke_width(look.px(1)),
    ))
    .map_err(fail)?;
    let font = ("sans-serif", look.label_font())
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    for (i, e) in entries.iter().enumerate() {
        let y = at.y0 + pad + row * (i as f64 + 0.5);
        let x = at.x0 + pad;
        let (l, r) = (corner(x, y), corner(x + swatch, y));
        match e.style {
            Some(Style::Line) if e.dashed > 0 => area
                .draw(&DashedPathElement::new(
                    vec![l, r],
                    dash_pattern(e.dashed, look).0,
                    dash_pattern(e.dashed, look).1,
                    e.color
                        .stroke_width(look.weighted_width(e.weight) + look.px(1)),
                ))
                .map_err(fail)?,
            Some(Style::Line) => area
                .draw(&PathElement::new(
                    vec![l, r],
                    e.color
                        .stroke_width(look.weighted_width(e.weight) + look.px(1)),
                ))
                .map_err(fail)?,
            Some(Style::Dots) => {
                // A marker drawn as a polygon, so that the only circles
                // in a picture are data.
                let c = (x + swatch / 2.0, y);
                let radius = f64::from(look.px(3));
                let ring: Vec<(i32, i32)> = (0..16)
                    .map(|k| {
                        let t = std::f64::consts::TAU * f64::from(k) / 16.0;
                        corner(c.0 + radius * t.cos(), c.1 + radius * t.sin())
                    })
                    .collect();
                if e.open {
                    let mut closed = ring.clone();
                    closed.push(ring[0]);
                    area.draw(&PathElement::new(closed, e.color.stroke_width(look.px(1))))
                        .map_err(fail)?;
                } else {
                    area.draw(&Polygon::new(ring, e.color.filled()))
                        .map_err(fail)?;
                }
            }
            None => area
                .draw(&DashedPathElement::new(
                    vec![l, r],
                    look.px(6),
                    look.px(4),
                    e.color.stroke_width(look.px(1)),
                ))
                .map_err(fail)?,
        }
        area.draw_text(&e.text, &font, corner(x + swatch + pad, y))
            .map_err(fail)?;
    }
    Ok(())
}
