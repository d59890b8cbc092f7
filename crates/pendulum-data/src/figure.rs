//! Figures as data: panels of named series (models as lines, data as
//! dots), with their titles, axis labels in units and scales. Each fit
//! builds its figure here; the command line draws it with plotters to SVG
//! or PNG, the browser page to SVG, by the same conventions (the preferred
//! model wide, its rivals thin, data over models, log axes where values
//! span decades, a time axis in the unit its span suits).

use serde::Serialize;

/// Picture size in CSS pixels (SVG user units) for one or two panels.
pub const SIZE: (u32, u32) = (960, 640);

/// How values map onto an axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scale {
    /// Equal steps for equal differences.
    Linear,
    /// Equal steps for equal ratios (a quantity that spans decades);
    /// values that are not positive cannot be shown.
    Log,
}

impl Scale {
    /// `value` in axis units, or `None` when the axis cannot show it (not
    /// finite; not positive on a log axis).
    pub fn to_axis(self, value: f64) -> Option<f64> {
        match self {
            Scale::Linear => value.is_finite().then_some(value),
            Scale::Log => (value.is_finite() && value > 0.0).then(|| value.log10()),
        }
    }

    /// The value at `u` axis units.
    pub fn value_at(self, u: f64) -> f64 {
        match self {
            Scale::Linear => u,
            Scale::Log => 10_f64.powf(u),
        }
    }
}

/// Points of a curve, in the panel's units.
pub type Points = Vec<(f64, f64)>;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Style {
    /// A line through the points.
    Line,
    /// A dot at each point.
    Dots,
}

/// How heavily a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Weight {
    /// The usual width.
    Normal,
    /// Wider: the model a figure prefers.
    Strong,
    /// Thinner: the alternatives beside it.
    Light,
}

/// One named series of points.
#[derive(Clone, Debug, Serialize)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// The points, in the panel's units.
    pub points: Vec<(f64, f64)>,
    /// Line or dots.
    pub style: Style,
    /// A palette index to share another series' colour.
    pub color: Option<usize>,
    /// A line's weight.
    pub weight: Weight,
    /// Dots' error bars: the low and high value at each point.
    pub bars: Option<Vec<(f64, f64)>>,
}

impl Series {
    /// A line.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            label: label.into(),
            points,
            style: Style::Line,
            color: None,
            weight: Weight::Normal,
            bars: None,
        }
    }

    /// The same drawn wider (the preferred model).
    pub fn strong(mut self) -> Self {
        self.weight = Weight::Strong;
        self
    }

    /// The same drawn thinner (an alternative).
    pub fn light(mut self) -> Self {
        self.weight = Weight::Light;
        self
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
            weight: Weight::Normal,
            bars: None,
        }
    }

    /// Dots with an error bar each: `(x, y, low, high)`.
    pub fn dots_with_bars(label: impl Into<String>, points: Vec<(f64, f64, f64, f64)>) -> Self {
        let mut s = Self::dots(label, points.iter().map(|p| (p.0, p.1)).collect());
        s.bars = Some(points.iter().map(|p| (p.2, p.3)).collect());
        s
    }
}

/// A vertical line across a panel at `x`, marking a working point.
#[derive(Clone, Debug, Serialize)]
pub struct Mark {
    /// Where, in the panel's horizontal units.
    pub x: f64,
    /// Legend text.
    pub label: String,
}

/// One chart: a title, two axis labels (with units) and its series.
#[derive(Clone, Debug, Serialize)]
pub struct Panel {
    /// Title.
    pub title: String,
    /// Horizontal axis label, with its unit.
    pub x_label: String,
    /// Vertical axis label, with its unit.
    pub y_label: String,
    /// The series: models (lines) drawn first, data (markers) over them;
    /// a line that lies on an earlier one is drawn dashed.
    pub series: Vec<Series>,
    /// The horizontal axis's scale.
    pub x_scale: Scale,
    /// The vertical axis's scale.
    pub y_scale: Scale,
    /// Vertical marks.
    pub marks: Vec<Mark>,
    /// A second vertical axis on the right: the same values in another
    /// unit (a log axis only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub y_twin: Option<Twin>,
}

/// A second vertical axis: the values times `factor`, in `label`'s unit.
#[derive(Clone, Debug, Serialize)]
pub struct Twin {
    /// Axis label, with its unit.
    pub label: String,
    /// What a value on the main axis is in the second axis's unit.
    pub factor: f64,
}

impl Panel {
    /// A panel on linear axes; its legend goes where it covers nothing.
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
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            marks: Vec::new(),
            y_twin: None,
        }
    }

    /// The same with a second vertical axis on the right, the values
    /// times `factor` (drawn on log–log panels).
    pub fn twin_y(mut self, label: impl Into<String>, factor: f64) -> Self {
        self.y_twin = Some(Twin {
            label: label.into(),
            factor,
        });
        self
    }

    /// The same on logarithmic axes (a quantity and its argument that
    /// both span decades; values that are not positive are not shown).
    pub fn log_log(mut self) -> Self {
        self.x_scale = Scale::Log;
        self.y_scale = Scale::Log;
        self
    }

    /// The same with a logarithmic vertical axis.
    pub fn log_y(mut self) -> Self {
        self.y_scale = Scale::Log;
        self
    }

    /// The same with a logarithmic vertical axis when every value is
    /// positive and they span more than `decades` decades.
    pub fn log_y_beyond(self, decades: f64) -> Self {
        let ys = || {
            self.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.1))
        };
        let positive = ys().filter(|y| y.is_finite()).all(|y| y > 0.0);
        let (lo, hi) = ys()
            .filter(|y| y.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
                (a.min(y), b.max(y))
            });
        if positive && lo.is_finite() && (hi / lo).log10() > decades {
            self.log_y()
        } else {
            self
        }
    }

    /// The same with a dashed vertical line at `x`, named in the legend.
    pub fn mark_x(mut self, x: f64, label: impl Into<String>) -> Self {
        self.marks.push(Mark {
            x,
            label: label.into(),
        });
        self
    }
}

/// Panels stacked top to bottom.
#[derive(Clone, Debug, Serialize)]
pub struct Figure {
    /// The panels.
    pub panels: Vec<Panel>,
}

impl Figure {
    /// The picture's size in CSS pixels: 960 wide, 640 high for one or
    /// two panels and 300 a panel for more.
    pub fn size(&self) -> (u32, u32) {
        let n = u32::try_from(self.panels.len()).unwrap_or(u32::MAX);
        (SIZE.0, SIZE.1.max(n.saturating_mul(300)).min(3000))
    }
}

/// The label of a time axis in seconds; such an axis is shown in the unit
/// that suits its span.
pub const TIME_AXIS: &str = "time (s)";

/// The unit a linear time axis spanning `span` seconds is shown in: s up
/// to 10 min, min up to 10 h, h up to 3 days, days beyond (a week is 7
/// days, not 604800 s).
pub fn time_unit(span: f64) -> (&'static str, f64) {
    if span <= 600.0 {
        ("s", 1.0)
    } else if span <= 36_000.0 {
        ("min", 60.0)
    } else if span <= 259_200.0 {
        ("h", 3600.0)
    } else {
        ("days", 86_400.0)
    }
}

/// `figure` with each linear time axis in seconds ([`TIME_AXIS`]) put in
/// the unit its span suits.
pub fn in_time_units(figure: &Figure) -> Figure {
    let mut figure = figure.clone();
    for panel in &mut figure.panels {
        if panel.x_label != TIME_AXIS || panel.x_scale != Scale::Linear {
            continue;
        }
        let xs = panel
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.0))
            .chain(panel.marks.iter().map(|m| m.x))
            .filter(|x| x.is_finite());
        let (lo, hi) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
        let (unit, factor) = time_unit(hi - lo);
        if factor == 1.0 {
            continue;
        }
        panel.x_label = format!("time ({unit})");
        for series in &mut panel.series {
            for p in &mut series.points {
                p.0 /= factor;
            }
        }
        for m in &mut panel.marks {
            m.x /= factor;
        }
    }
    figure
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
