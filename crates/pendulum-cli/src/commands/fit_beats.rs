//! `pendulum fit beats`: what a timegrapher shows, from beat timestamps.

use super::common;
use crate::args::FitBeatsArgs;
use crate::data::{need, stream_table, ReadOptions, Role};
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};

/// Intervals kept for the plot, at most.
const PLOT_LIMIT: usize = 8192;
use pendulum_theory::analysis::Refusal;
use pendulum_theory::fitting::beat_log::{BeatLog, Beats};
use pendulum_theory::period::beats_per_hour;
use serde::Serialize;

/// What the command prints as JSON: the file read, then the analysis.
#[derive(Serialize)]
struct BeatsJson {
    file: String,
    format: crate::data::Format,
    #[serde(flatten)]
    analysis: Beats,
}

/// The rate for people: "12 s/day (gaining) against 3600 beats/hour".
pub(crate) fn rate_text(rate_s_per_day: Option<f64>, nominal_beat: Option<f64>) -> String {
    match (rate_s_per_day, nominal_beat) {
        (Some(r), Some(n)) => format!(
            "{} s/day ({}) against {} beats/hour",
            // Below a microsecond a day the sign is rounding, not the clock.
            num(if r.abs() < 1e-6 { 0.0 } else { r }, 4),
            if r >= 1e-6 {
                "gaining"
            } else if r <= -1e-6 {
                "losing"
            } else {
                "keeping time"
            },
            num(beats_per_hour(2.0 * n), 6)
        ),
        _ => "unknown: give --bph or --period (no standard rate within 2%)".into(),
    }
}

pub fn run(args: &FitBeatsArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let nominal = common::nominal(args.period, args.bph);
    let file = args.file.display().to_string();
    let refused = |r: &Refusal, line: Option<u64>| {
        CliError::refused(r, &[], &|at, reason| match (at, line) {
            (Some(_), Some(line)) => CliError::other(format!("{file}: line {line}: {reason}")),
            _ => CliError::other(format!("{file}: {reason}")),
        })
    };
    let mut log = BeatLog::new(nominal).map_err(|r| refused(&r, None))?;
    let options = ReadOptions {
        columns: super::measured::columns(args.columns.as_deref()),
        run: super::measured::run(args.run)?,
        ..ReadOptions::default()
    };
    // Streamed: a log of 10^7 beats takes no more memory than one of ten.
    // For the plot: every `stride`-th interval, the stride doubling whenever
    // the kept points reach their limit, so memory stays bounded.
    let mut previous = f64::NEG_INFINITY;
    let mut intervals: Vec<(f64, f64)> = Vec::new();
    let (mut stride, mut seen) = (1_u64, 0_u64);
    let groups: &[&[Role]] = &[&[Role::Time]];
    let chooser = need(groups);
    let (_, _, _, format) = stream_table(&args.file, &options, &chooser, |row, line| {
        let t = row[0];
        if plot.is_some() && previous.is_finite() {
            if seen % stride == 0 {
                intervals.push((t, 1e3 * (t - previous)));
                if intervals.len() >= PLOT_LIMIT {
                    stride *= 2;
                    let mut keep = 0;
                    intervals.retain(|_| {
                        keep += 1;
                        keep % 2 == 1
                    });
                }
            }
            seen += 1;
        }
        previous = t;
        log.push(t).map_err(|r| refused(&r, Some(line)))
    })?;
    let analysis = log.finish().map_err(|r| refused(&r, None))?;
    let a = &analysis;
    if let Some(target) = &plot {
        let mean = vec![
            (intervals.first().map_or(0.0, |p| p.0), 1e3 * a.mean_beat_s),
            (intervals.last().map_or(1.0, |p| p.0), 1e3 * a.mean_beat_s),
        ];
        // Repaired gaps (missed beats) would squash the scale: show the
        // intervals within half a beat of the mean.
        let intervals: Vec<(f64, f64)> = intervals
            .into_iter()
            .filter(|p| (p.1 - 1e3 * a.mean_beat_s).abs() < 500.0 * a.mean_beat_s)
            .collect();
        let allan = a
            .allan_deviation
            .iter()
            .map(|p| (p.tau_s, p.deviation_s_per_day))
            .collect();
        let figure = Figure {
            panels: vec![
                Panel::new(
                    "Beat intervals (ticks and tocks)",
                    "time (s)",
                    "interval (ms)",
                    vec![
                        Series::dots("interval", intervals),
                        Series::line("mean beat", mean),
                    ],
                ),
                Panel::new(
                    "Allan deviation of the rate",
                    "averaging time (s)",
                    "Allan deviation (s/day)",
                    vec![Series::dots("overlapping Allan deviation", allan)],
                )
                .log_log(),
            ],
        };
        render(target, &figure)?;
    }
    let result = BeatsJson {
        file,
        format,
        analysis: analysis.clone(),
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    s.row(
        "Beats",
        format!(
            "{} ({} missed filled in, {} doubled dropped)",
            a.beats, a.repaired.missed, a.repaired.doubled
        ),
    )
    .row(
        "Mean beat",
        format!(
            "{} s  ({} beats/hour)",
            num(a.mean_beat_s, 10),
            num(a.beats_per_hour, 8)
        ),
    )
    .row("Rate", rate_text(a.rate_s_per_day, a.nominal_beat_s))
    .row(
        "Beat error",
        format!(
            "{} ms (first beats {} ms, last {} ms)",
            num(a.beat_error_ms, 3),
            num(a.beat_error_start_ms, 3),
            num(a.beat_error_end_ms, 3)
        ),
    )
    .row("Jitter", format!("{} ms", num(a.jitter_ms, 3)));
    let mut out = s.render();
    for w in &a.warnings {
        out.push_str(&format!("WARNING: {w}\n"));
    }
    if !a.allan_deviation.is_empty() {
        out.push_str("\nAllan deviation of the rate\n");
        let rows: Vec<Vec<String>> = a
            .allan_deviation
            .iter()
            .map(|p| {
                vec![
                    p.beats.to_string(),
                    num(p.tau_s, 6),
                    num(p.deviation, 3),
                    num(p.deviation_s_per_day, 3),
                ]
            })
            .collect();
        out.push_str(&output::table(
            &["beats", "tau s", "deviation", "s/day"],
            &rows,
        ));
    }
    Ok(out)
}
