//! `pendulum period`: the exact period at one amplitude, or a table over a
//! range of amplitudes (section 1-6 of the clock book).

use super::common::{self, ResolvedGravity};
use crate::args::PeriodArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};
use crate::units::{parse_range, Dimension};
use pendulum_theory::period::table::{table, Amplitudes, PeriodInput, PeriodRow};
use pendulum_theory::period::{circular_error, period_ratio, period_ratio_series};
use pendulum_theory::{Amplitude, Pendulum};
use serde::Serialize;

/// One row as the command prints it: where g came from, and the
/// library's row.
#[derive(Serialize)]
struct PeriodJson<'a> {
    g_source: &'static str,
    #[serde(flatten)]
    row: &'a PeriodRow,
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
    series_terms: Option<u32>,
    series_period_s: Option<f64>,
    series_relative_error: Option<f64>,
    elastic_share: f64,
}

pub fn run(args: &PeriodArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let gravity = common::gravity(&args.gravity)?;
    let common::Reduced {
        pendulum,
        elastic_share,
    } = common::reduced(
        args.pendulum.length,
        args.pendulum.design.as_deref(),
        &gravity,
    )?;
    let flag = "--amplitude";
    let amplitudes = match parse_range(&args.amplitude, Dimension::Angle) {
        Some(range) => {
            let (from, to) = range.map_err(|e| CliError::flag(flag, e))?;
            Amplitudes::Range {
                from,
                to,
                steps: args.steps.map(i64::from),
                step: args.step.map(|s| s.0),
            }
        }
        None => Amplitudes::One(
            crate::units::parse_quantity(&args.amplitude, Dimension::Angle)
                .map_err(|e| CliError::flag(flag, e))?,
        ),
    };
    let input = PeriodInput {
        length: pendulum.length_m(),
        g: Some(pendulum.g_m_s2()),
        amplitudes,
        series_terms: args.series_terms.map(i64::from),
        elastic_share: (elastic_share > 0.0).then_some(elastic_share),
    };
    let rows = table(&input).map_err(|e| common::refused(&e))?;
    if let Some(target) = &plot {
        let first = rows[0].amplitude_deg;
        let last = rows[rows.len() - 1].amplitude_deg;
        let (from, to, working) = if rows.len() > 1 {
            (first.min(last), first.max(last), None)
        } else {
            (0.0, (2.0 * first).clamp(10.0, 170.0), Some(first))
        };
        render(target, &figure(&pendulum, elastic_share, from, to, working))?;
    }
    let is_table = matches!(amplitudes, Amplitudes::Range { .. });
    if args.format.csv {
        let rows: Vec<PeriodCsv> = rows.iter().map(csv_row).collect();
        let all = output::csv(&rows)?;
        return match &args.columns {
            Some(names) => output::csv_columns(&all, names, "--columns"),
            None => Ok(all),
        };
    }
    if args.format.json {
        let rows: Vec<PeriodJson> = rows
            .iter()
            .map(|row| PeriodJson {
                g_source: gravity.g_source,
                row,
            })
            .collect();
        return if is_table {
            output::json(&rows)
        } else {
            output::json(&rows[0])
        };
    }
    Ok(if is_table {
        text_table(&pendulum, &gravity, &rows)
    } else {
        text_summary(&rows[0], &gravity)
    })
}

fn csv_row(a: &PeriodRow) -> PeriodCsv {
    PeriodCsv {
        length_m: a.length_m,
        g_m_s2: a.g_m_s2,
        amplitude_rad: a.amplitude_rad,
        amplitude_deg: a.amplitude_deg,
        period_s: a.period_s,
        small_angle_period_s: a.small_angle_period_s,
        period_ratio: a.period_ratio,
        beats_per_hour: a.beats_per_hour,
        circular_error: a.circular_error,
        circular_error_s_per_day: a.circular_error_s_per_day,
        circular_error_s_per_day_per_deg: a.circular_error_s_per_day_per_deg,
        series_terms: a.series.map(|s| s.terms),
        series_period_s: a.series.map(|s| s.period_s),
        series_relative_error: a.series.map(|s| s.relative_error),
        // A rigid pivot's share is 0 (the JSON leaves the key out).
        elastic_share: a.elastic_share.unwrap_or(0.0),
    }
}

fn text_summary(a: &PeriodRow, gravity: &ResolvedGravity) -> String {
    let mut s = Summary::default();
    s.row("Length", format!("{} m", num(a.length_m, 10)))
        .row("Gravity", gravity.describe())
        .row(
            "Amplitude",
            format!(
                "{}° ({} rad)",
                num(a.amplitude_deg, 10),
                num(a.amplitude_rad, 6)
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
                num(a.circular_error_s_per_day, 6),
                num(a.circular_error_s_per_day_per_deg, 6)
            ),
        );
    match (a.series, a.elastic_share) {
        (Some(series), _) => s.row(
            &format!("Series, {} terms", series.terms),
            format!(
                "{} s  (relative error {})",
                num(series.period_s, 12),
                num(series.relative_error, 3)
            ),
        ),
        (None, share) => s.row(
            "Suspension spring",
            format!(
                "elastic share {}: the period of θ'' = −ω²[(1 − ε) sin θ + ε θ] (no power \
                 series: the book's is a rigid pendulum's)",
                share.map_or("?".to_string(), |e| num(e, 4))
            ),
        ),
    };
    s.render()
}

fn text_table(pendulum: &Pendulum, gravity: &ResolvedGravity, rows: &[PeriodRow]) -> String {
    let mut out = format!(
        "Pendulum of {} m under {}\n",
        num(pendulum.length_m(), 10),
        gravity.describe()
    );
    let series_header = match rows.first().and_then(|a| a.series) {
        Some(series) => format!("series({}) rel. err", series.terms),
        None => "series (rigid only)".to_string(),
    };
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
                num(a.amplitude_deg, 6),
                num(a.period_s, 10),
                num(a.period_ratio, 10),
                num(a.beats_per_hour, 8),
                num(a.circular_error_s_per_day, 6),
                num(a.circular_error_s_per_day_per_deg, 6),
                a.series
                    .map_or("—".to_string(), |s| num(s.relative_error, 3)),
            ]
        })
        .collect();
    out.push_str(&output::table(&header, &cells));
    if let Some(e) = rows.first().and_then(|a| a.elastic_share) {
        out.push_str(&format!(
            "On a suspension spring of elastic share {}: θ'' = −ω²[(1 − ε) sin θ + ε θ]\n",
            num(e, 4)
        ));
    }
    out
}

/// The period against amplitude from `from_deg` to `to_deg`, with the
/// `working` amplitude (degrees) marked: T/T0 exact; the relative error of
/// the power series with 1 to 5 terms against it, on a log axis (errors
/// below 1e-15, under the exact value's own rounding, are not drawn); the
/// circular error in s/day. On a suspension spring of elastic share
/// `share` (0: a rigid pivot) the period is the spring's
/// ([`pendulum_theory::suspension::period_ratio`]) and there is no series
/// panel (the series is a rigid pendulum's).
pub fn figure(
    pendulum: &Pendulum,
    share: f64,
    from_deg: f64,
    to_deg: f64,
    working: Option<f64>,
) -> Figure {
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
    let ratio = |a: Amplitude| {
        if share > 0.0 {
            pendulum_theory::suspension::period_ratio(a.radians(), share)
        } else {
            period_ratio(a)
        }
    };
    let exact_label = if share > 0.0 {
        format!(
            "exact on the spring (ε = {}): θ'' = −ω²[(1 − ε) sin θ + ε θ]",
            num(share, 3)
        )
    } else {
        "exact: 2K(sin²(A/2))/π".to_string()
    };
    let mut panels = vec![mark(
        Panel::new(
            format!(
                "Period against amplitude, l = {} m",
                num(pendulum.length_m(), 6)
            ),
            "amplitude (°)",
            "T / T₀",
            vec![Series::line(exact_label, curve(&|a| ratio(a)))],
        ),
        true,
    )];
    if share == 0.0 {
        panels.push(mark(
            Panel::new(
                "The power series in sin²(A/2): its error against the exact period",
                "amplitude (°)",
                "|T_series / T − 1|",
                errors,
            )
            .log_y(),
            false,
        ));
    }
    panels.push(mark(
        Panel::new(
            "Circular error: what the clock loses against a vanishing swing",
            "amplitude (°)",
            "circular error (s/day)",
            vec![Series::line(
                "loss per day, 86400 s × (1 − T₀/T)",
                curve(&|a| {
                    if share > 0.0 {
                        day * (1.0 - 1.0 / ratio(a))
                    } else {
                        day * circular_error(a)
                    }
                }),
            )],
        ),
        false,
    ));
    Figure { panels }
}
