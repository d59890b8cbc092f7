//! The figures of `pendulum log --plot PREFIX`: the rate and its
//! residuals against time with the weather, the rate against each
//! weather term, the stability with its intervals and noise slopes, the
//! spectrum with its lines, and the folds over the wheels' turns.

use crate::commands::stability::adev_bars;
use crate::error::CliError;
use crate::output::num;
use crate::plot::{render, thin, Figure, Panel, Series, Target, TIME_AXIS};
use pendulum_theory::clock_log::{LogResult, ModelTerm, Source};
use std::path::{Path, PathBuf};

/// The figures' names.
const NAMES: [&str; 5] = ["rate", "weather", "stability", "spectrum", "folds"];

/// Points a panel shows at most (more are thinned evenly).
const SHOWN: usize = 5000;

/// Where the figures go: `PREFIX-name.svg`, or `.png` when the prefix
/// ends in `.png`.
#[derive(Clone, Debug)]
pub struct Prefix {
    stem: PathBuf,
    extension: &'static str,
}

impl Prefix {
    /// Checks `--plot PREFIX`: a path (not `-`), its extension `.svg`,
    /// `.png` or none.
    pub fn new(prefix: &Path) -> Result<Self, CliError> {
        if crate::file::is_stdout(prefix) {
            return Err(CliError::flag(
                "--plot",
                "names several files (PREFIX-rate.svg, …); standard output cannot hold them",
            ));
        }
        let text = prefix.to_string_lossy();
        let lower = text.to_ascii_lowercase();
        let (stem, extension) = if let Some(s) = lower.strip_suffix(".png") {
            (&text[..s.len()], "png")
        } else if let Some(s) = lower.strip_suffix(".svg") {
            (&text[..s.len()], "svg")
        } else {
            (&text[..], "svg")
        };
        Ok(Self {
            stem: PathBuf::from(stem),
            extension,
        })
    }

    fn path(&self, name: &str) -> PathBuf {
        let mut file = self.stem.clone().into_os_string();
        file.push(format!("-{name}.{}", self.extension));
        PathBuf::from(file)
    }

    fn target(&self, name: &str) -> Result<Target, CliError> {
        Target::new(&self.path(name), "--plot")
    }

    /// Every file the prefix may name, for the check of outputs made
    /// before any work.
    pub fn paths(&self) -> Vec<PathBuf> {
        NAMES.iter().map(|n| self.path(n)).collect()
    }
}

/// Draws every figure the result has; returns the files written.
pub fn write(prefix: &Prefix, r: &LogResult) -> Result<Vec<String>, CliError> {
    all(r)
        .into_iter()
        .map(|(name, figure)| render(&prefix.target(name)?, &figure))
        .collect()
}

/// Every figure the result has, named.
pub fn all(r: &LogResult) -> Vec<(&'static str, Figure)> {
    let mut figures = vec![("rate", rate(r))];
    if !r.partials.is_empty() {
        figures.push(("weather", weather(r)));
    }
    if !r.stability.is_empty() {
        figures.push(("stability", stability(r)));
    }
    if let Some(f) = spectrum(r) {
        figures.push(("spectrum", f));
    }
    if !r.folds.is_empty() {
        figures.push(("folds", folds(r)));
    }
    figures
}

/// "p = 0.03", or "p < 1e-12" where the value is lost below rounding.
pub fn p_text(p: f64) -> String {
    if p < 1e-12 {
        "p < 1e-12".to_string()
    } else {
        format!("p = {}", num(p, 2))
    }
}

/// A term's axis label: its name and its variable's unit, from the
/// library's table of terms.
fn weather_label(term: &ModelTerm) -> String {
    match term.source {
        Source::Tide => "tidal rate (s/day)".to_string(),
        _ => format!("{} ({})", term.name, term.variable_unit),
    }
}

/// The rate and the model, the residuals, and the weather against time
/// from the log's start.
fn rate(r: &LogResult) -> Figure {
    let at = |k: usize| -> Vec<(f64, f64)> {
        thin(r.per_bin.iter().map(|b| (b[0], b[k])).collect(), SHOWN)
    };
    let mut panels = vec![
        Panel::new(
            format!(
                "The clock's rate in bins of {} s, and the model with the wander it found",
                num(r.bin_s, 4)
            ),
            TIME_AXIS,
            "rate (s/day)",
            vec![Series::line("model", at(2)), Series::dots("rate", at(1))],
        ),
        Panel::new(
            format!(
                "Residuals after the model: {} s/day RMS",
                num(r.residual_rms_s_per_day, 3)
            ),
            TIME_AXIS,
            "residual (s/day)",
            vec![Series::dots("residual", at(3))],
        ),
    ];
    for (term, values) in &r.weather_per_bin {
        let points = r
            .per_bin
            .iter()
            .zip(values)
            .filter(|(_, v)| v.is_finite())
            .map(|(b, &v)| (b[0], v))
            .collect();
        panels.push(Panel::new(
            format!("The {}", term.name),
            TIME_AXIS,
            weather_label(term),
            vec![Series::dots(term.name, thin(points, SHOWN))],
        ));
    }
    Figure { panels }
}

/// The rate with every other term taken out, against each term.
fn weather(r: &LogResult) -> Figure {
    let panels = r
        .partials
        .iter()
        .map(|p| {
            let (lo, hi) =
                p.x.iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                        (a.min(x), b.max(x))
                    });
            let line = |x: f64| (x, p.at_mean + p.slope * (x - p.mean));
            let lag = match (p.term.source, r.temperature_lag_s) {
                (Source::LaggedColumn, Some(l)) if l > 0.0 => {
                    format!(", lagged {} h", num(l / 3600.0, 2))
                }
                _ => String::new(),
            };
            let unit = p.term.unit;
            Panel::new(
                format!(
                    "The rate against the {}{lag} (every other term and the wander taken out)",
                    p.term.name
                ),
                weather_label(p.term),
                "rate less the other terms (s/day)",
                vec![
                    Series::line(
                        format!("fit: {} {unit}", num(p.slope, 3)),
                        vec![line(lo), line(hi)],
                    ),
                    Series::dots(
                        "bins",
                        thin(
                            p.x.iter().copied().zip(p.y.iter().copied()).collect(),
                            SHOWN,
                        ),
                    ),
                ],
            )
        })
        .collect();
    Figure { panels }
}

/// ADEV with its 68% intervals, before and after the model, with the
/// slope of each noise found.
fn stability(r: &LogResult) -> Figure {
    let mut series = Vec::new();
    // Each noise's slope through the taus it was found at: ADEV goes as
    // τ^(μ/2), μ = −α − 1 (−2 at most), NIST SP 1065 table 5.
    // The residuals' noises are the clock's own (the weather's cycles
    // taken out), the log's when there are none.
    let noisy = if r.residual_stability.is_empty() {
        &r.stability
    } else {
        &r.residual_stability
    };
    // A run is broken by a row of another noise or of none (a periodic
    // signal rules there): a guide drawn across such a row would average
    // points that do not follow its slope. Rows whose noise is carried
    // from the row before extend the guide without placing it.
    type Run = (pendulum_theory::stability::Noise, Vec<(f64, f64)>, f64);
    let mut runs: Vec<Run> = Vec::new();
    let mut open = false;
    for s in noisy {
        match (s.noise, s.adev(), s.noise_carried, runs.last_mut()) {
            (Some(n), Some(a), false, Some((m, points, end))) if open && *m == n => {
                points.push((s.tau_s, a));
                *end = s.tau_s;
            }
            (Some(n), Some(a), false, _) => {
                runs.push((n, vec![(s.tau_s, a)], s.tau_s));
                open = true;
            }
            (Some(_), Some(_), true, Some((_, _, end))) if open => *end = s.tau_s,
            (Some(_), Some(_), true, _) => {}
            _ => open = false,
        }
    }
    for (noise, points, end) in runs.iter().filter(|(_, p, _)| p.len() >= 2) {
        let slope = f64::from((-noise.alpha() - 1).max(-2)) / 2.0;
        let centre = points
            .iter()
            .map(|(t, a)| a.ln() - slope * t.ln())
            .sum::<f64>()
            / points.len() as f64;
        let guide = |t: f64| (t, (centre + slope * t.ln()).exp());
        let (first, last) = (points[0].0, *end);
        series.push(
            Series::line(
                format!("{}: slope τ^{}", noise.name(), num(slope, 2)),
                vec![guide(first), guide(last)],
            )
            .light(),
        );
    }
    series.push(Series::dots_with_bars(
        "the log, ADEV with 68% interval",
        adev_bars(&r.stability),
    ));
    series.push(Series::dots_with_bars(
        "after the model",
        adev_bars(&r.residual_stability),
    ));
    Figure {
        panels: vec![Panel::new(
            "Frequency stability",
            "averaging time τ (s)",
            crate::commands::stability::deviation_axis("Allan deviation"),
            series,
        )
        .log_log()
        .twin_y(
            crate::commands::stability::S_PER_DAY_AXIS.0,
            crate::commands::stability::S_PER_DAY_AXIS.1,
        )],
    }
}

/// The rate's spectrum with the named lines.
fn spectrum(r: &LogResult) -> Option<Figure> {
    let s = r.spectrum.as_ref()?;
    let hours = |p: f64| p / 3600.0;
    let mut series = vec![Series::line(
        "spectrum of the rate",
        s.points
            .iter()
            .map(|p| (hours(p.period_s), p.amplitude_s_per_day))
            .collect(),
    )
    .light()];
    for line in &s.lines {
        let verdict = match (line.seen, line.blended_with.is_some()) {
            (true, true) => "seen, blended",
            (true, false) => "seen",
            (false, true) => "not seen, blended",
            (false, false) => "not seen",
        };
        series.push(Series::dots(
            format!(
                "{} ({} h): {} s/day, {verdict}",
                line.name,
                num(hours(line.period_s), 4),
                num(line.amplitude_s_per_day, 2)
            ),
            vec![(hours(line.period_s), line.amplitude_s_per_day)],
        ));
    }
    Some(Figure {
        panels: vec![Panel::new(
            "Periodic errors: the rate's spectrum (Lomb–Scargle)",
            "period (h)",
            "amplitude (s/day)",
            series,
        )
        .log_log()],
    })
}

/// The rate over each arbor's turn.
fn folds(r: &LogResult) -> Figure {
    let panels = r
        .folds
        .iter()
        .map(|f| {
            Panel::new(
                format!(
                    "The {} ({} s a turn): {} s/day peak to peak, {}",
                    f.arbor,
                    num(f.period_s, 5),
                    num(f.peak_to_peak_s_per_day, 2),
                    p_text(f.p_value)
                ),
                "position in the turn (°)",
                "rate less its running mean (s/day)",
                vec![Series::dots_with_bars(
                    "mean with its standard error",
                    f.bins
                        .iter()
                        .map(|b| {
                            (
                                b.phase * 360.0,
                                b.rate_s_per_day,
                                b.rate_s_per_day - b.standard_error_s_per_day,
                                b.rate_s_per_day + b.standard_error_s_per_day,
                            )
                        })
                        .collect(),
                )],
            )
        })
        .collect();
    Figure { panels }
}
