//! `pendulum period`: the exact period at one amplitude, or a table over a
//! range of amplitudes (section 1-6 of the clock book).

use super::common::{self, ResolvedGravity};
use crate::args::PeriodArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};
use crate::units::{parse_range, Dimension};
use pendulum_theory::period::{circular_error, period_ratio, period_ratio_series, PeriodAnalysis};
use pendulum_theory::{Amplitude, Pendulum};
use serde::Serialize;

/// The JSON object for one amplitude. Keys are part of the interface.
#[derive(Serialize)]
struct PeriodJson {
    length_m: f64,
    g_m_s2: f64,
    g_source: &'static str,
    amplitude_rad: f64,
    amplitude_deg: f64,
    period_s: f64,
    small_angle_period_s: f64,
    period_ratio: f64,
    beats_per_hour: f64,
    circular_error: f64,
    circular_error_s_per_day: f64,
    circular_error_s_per_day_per_deg: f64,
    series: SeriesJson,
}

#[derive(Serialize)]
struct SeriesJson {
    terms: u32,
    period_s: f64,
    relative_error: f64,
    truncation_bound: f64,
}

/// One CSV row: the JSON keys, with the series flattened.
#[derive(Serialize)]
struct PeriodCsv {
    length_m: f64,
    g_m_s2: f64,
    amplitude_rad: f64,
    amplitude_deg: f64,
    period_s: f64,
    small_angle_period_s: f64,
    period_ratio: f64,
    beats_per_hour: f64,
    circular_error: f64,
    circular_error_s_per_day: f64,
    circular_error_s_per_day_per_deg: f64,
    series_terms: u32,
    series_period_s: f64,
    series_relative_error: f64,
}

/// The most rows a table may have.
const MAX_STEPS: u32 = 1_000_000;

pub fn run(args: &PeriodArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let gravity = common::gravity(&args.gravity)?;
    let pendulum = common::pendulum_of(args.length.as_deref(), args.design.as_deref(), &gravity)?;
    let amplitudes = amplitudes(args)?;
    if let Some(target) = &plot {
        let first = amplitudes[0].degrees();
        let last = amplitudes[amplitudes.len() - 1].degrees();
        let (from, to, working) = if amplitudes.len() > 1 {
            (first.min(last), first.max(last), None)
        } else {
            (0.0, (2.0 * first).clamp(10.0, 170.0), Some(first))
        };
        render(target, &figure(&pendulum, from, to, working))?;
    }
    let analyses = amplitudes
        .iter()
        .map(|&a| PeriodAnalysis::new(pendulum, a, args.series_terms))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| CliError::input("--series-terms", &e))?;
    let is_table = parse_range(&args.amplitude, Dimension::Angle).is_some();
    if args.format.csv {
        let rows: Vec<PeriodCsv> = analyses.iter().map(csv_row).collect();
        return output::csv(&rows);
    }
    if args.format.json {
        let rows: Vec<PeriodJson> = analyses.iter().map(|a| json_row(a, &gravity)).collect();
        return if is_table {
            output::json(&rows)
        } else {
            output::json(&rows[0])
        };
    }
    Ok(if is_table {
        text_table(&pendulum, &gravity, &analyses)
    } else {
        text_summary(&analyses[0], &gravity)
    })
}

/// One amplitude, or `steps` evenly spaced over `from..to` (both included).
fn amplitudes(args: &PeriodArgs) -> Result<Vec<Amplitude>, CliError> {
    let flag = "--amplitude";
    let Some(range) = parse_range(&args.amplitude, Dimension::Angle) else {
        return Ok(vec![common::amplitude(flag, &args.amplitude)?]);
    };
    let (from, to) = range.map_err(|e| CliError::flag(flag, e))?;
    // A range has two ends: at least two rows.
    if args.steps < 2 || args.steps > MAX_STEPS {
        return Err(CliError::flag(
            "--steps",
            format!(
                "must be between 2 and {MAX_STEPS} with a range of amplitudes, got {}",
                args.steps
            ),
        ));
    }
    common::amplitude_from_radians(flag, from)?;
    common::amplitude_from_radians(flag, to)?;
    // Spaced in degrees, the unit people type, so 1deg..10deg gives 1, 2, … 10
    // exactly rather than 2.0000000000000004.
    let (from_deg, to_deg) = (from.to_degrees(), to.to_degrees());
    let last = f64::from(args.steps - 1);
    (0..args.steps)
        .map(|i| {
            let t = f64::from(i) / last;
            let degrees = from_deg + (to_deg - from_deg) * t;
            common::amplitude_from_radians(flag, degrees.to_radians())
        })
        .collect()
}

fn json_row(a: &PeriodAnalysis, gravity: &ResolvedGravity) -> PeriodJson {
    PeriodJson {
        length_m: a.pendulum.length_m(),
        g_m_s2: a.pendulum.g_m_s2(),
        g_source: gravity.g_source,
        amplitude_rad: a.amplitude.radians(),
        amplitude_deg: a.amplitude.degrees(),
        period_s: a.period_s,
        small_angle_period_s: a.small_angle_period_s,
        period_ratio: a.period_ratio,
        beats_per_hour: a.beats_per_hour,
        circular_error: a.circular_error,
        circular_error_s_per_day: a.circular_error_s_per_day(),
        circular_error_s_per_day_per_deg: a.circular_error_s_per_day_per_deg(),
        series: SeriesJson {
            terms: a.series.terms,
            period_s: a.series_period_s(),
            relative_error: a.series.relative_error,
            truncation_bound: a.series.truncation_bound,
        },
    }
}

fn csv_row(a: &PeriodAnalysis) -> PeriodCsv {
    PeriodCsv {
        length_m: a.pendulum.length_m(),
        g_m_s2: a.pendulum.g_m_s2(),
        amplitude_rad: a.amplitude.radians(),
        amplitude_deg: a.amplitude.degrees(),
        period_s: a.period_s,
        small_angle_period_s: a.small_angle_period_s,
        period_ratio: a.period_ratio,
        beats_per_hour: a.beats_per_hour,
        circular_error: a.circular_error,
        circular_error_s_per_day: a.circular_error_s_per_day(),
        circular_error_s_per_day_per_deg: a.circular_error_s_per_day_per_deg(),
        series_terms: a.series.terms,
        series_period_s: a.series_period_s(),
        series_relative_error: a.series.relative_error,
    }
}

fn text_summary(a: &PeriodAnalysis, gravity: &ResolvedGravity) -> String {
    let mut s = Summary::default();
    s.row("Length", format!("{} m", num(a.pendulum.length_m(), 10)))
        .row("Gravity", gravity.describe())
        .row(
            "Amplitude",
            format!(
                "{}° ({} rad)",
                num(a.amplitude.degrees(), 10),
                num(a.amplitude.radians(), 6)
            ),
        )
        .row("Period", format!("{} s", num(a.period_s, 12)))
        .row(
            "Small-angle period",
            format!(
                "{} s  (T/T0 = {})",
                num(a.small_angle_period_s, 12),
                num(a.period_ratio, 12)
            ),
        )
        .row("Beats per hour", num(a.beats_per_hour, 10))
        .row(
            "Circular error",
            format!(
                "{} s/day lost against a vanishing swing; {} s/day more per degree",
                num(a.circular_error_s_per_day(), 6),
                num(a.circular_error_s_per_day_per_deg(), 6)
            ),
        )
        .row(
            &format!("Series, {} terms", a.series.terms),
            format!(
                "{} s  (relative error {})",
                num(a.series_period_s(), 12),
                num(a.series.relative_error, 3)
            ),
        );
    s.render()
}

fn text_table(pendulum: &Pendulum, gravity: &ResolvedGravity, rows: &[PeriodAnalysis]) -> String {
    let mut out = format!(
        "Pendulum of {} m under {}\n",
        num(pendulum.length_m(), 10),
        gravity.describe()
    );
    let terms = rows.first().map_or(0, |a| a.series.terms);
    let series_header = format!("series({terms}) rel. err");
    let header = [
        "amplitude °",
        "period s",
        "T/T0",
        "beats/h",
        "circular error s/day",
        "s/day per °",
        series_header.as_str(),
    ];
    let cells: Vec<Vec<String>> = rows
        .iter()
        .map(|a| {
            vec![
                num(a.amplitude.degrees(), 6),
                num(a.period_s, 10),
                num(a.period_ratio, 10),
                num(a.beats_per_hour, 8),
                num(a.circular_error_s_per_day(), 6),
                num(a.circular_error_s_per_day_per_deg(), 6),
                num(a.series.relative_error, 3),
            ]
        })
        .collect();
    out.push_str(&output::table(&header, &cells));
    out
}

/// The period against amplitude from `from_deg` to `to_deg`, with the
/// `working` amplitude (degrees) marked: T/T0 exact; the relative error of
/// the power series with 1 to 5 terms against it, on a log axis (errors
/// below 1e-15, under the exact value's own rounding, are not drawn); the
/// circular error in s/day.
pub fn figure(pendulum: &Pendulum, from_deg: f64, to_deg: f64, working: Option<f64>) -> Figure {
    let grid: Vec<Amplitude> = (0..=400)
        .filter_map(|i| {
            Amplitude::from_degrees(from_deg + (to_deg - from_deg) * f64::from(i) / 400.0).ok()
        })
        .collect();
    let curve = |f: &dyn Fn(Amplitude) -> f64| {
        grid.iter()
            .map(|&a| (a.degrees(), f(a)))
            .collect::<Vec<_>>()
    };
    let errors = (1..=5)
        .map(|terms| {
            let label = match terms {
                1 => "1 term (small-angle)".to_string(),
                n => format!("{n} terms"),
            };
            Series::line(
                label,
                curve(&|a| {
                    period_ratio_series(a, terms)
                        .map(|s| s.relative_error.abs())
                        .ok()
                        .filter(|e| *e >= 1e-15)
                        .unwrap_or(f64::NAN)
                }),
            )
        })
        .collect();
    let day = pendulum_theory::period::SECONDS_PER_DAY;
    // The working amplitude named in the first panel's legend only.
    let mark = |panel: Panel, named: bool| match working {
        Some(a) if named => panel.mark_x(a, format!("working amplitude, {}°", num(a, 4))),
        Some(a) => panel.mark_x(a, ""),
        None => panel,
    };
    Figure {
        panels: vec![
            mark(
                Panel::new(
                    format!(
                        "Period against amplitude, l = {} m",
                        num(pendulum.length_m(), 6)
                    ),
                    "amplitude (°)",
                    "T / T₀",
                    vec![Series::line(
                        "exact: 2K(sin²(A/2))/π",
                        curve(&|a| period_ratio(a)),
                    )],
                ),
                true,
            ),
            mark(
                Panel::new(
                    "The power series in sin²(A/2): its error against the exact period",
                    "amplitude (°)",
                    "|T_series / T − 1|",
                    errors,
                )
                .log_y(),
                false,
            ),
            mark(
                Panel::new(
                    "Circular error: what the clock loses against a vanishing swing",
                    "amplitude (°)",
                    "circular error (s/day)",
                    vec![Series::line(
                        "loss per day, 86400 s × (1 − T₀/T)",
                        curve(&|a| day * circular_error(a)),
                    )],
                ),
                false,
            ),
        ],
    }
}
