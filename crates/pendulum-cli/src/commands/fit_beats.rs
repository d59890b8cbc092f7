//! `pendulum fit beats`: what a timegrapher shows, from beat timestamps.

use super::common;
use crate::args::FitBeatsArgs;
use crate::data::{need, stream_table, Found, ReadOptions, Role};
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};

/// Intervals kept for the plot, at most.
const PLOT_LIMIT: usize = 8192;
use pendulum_theory::analysis::Refusal;
use pendulum_theory::fitting::beat_log::{BeatLog, Beats};
use pendulum_theory::fitting::photogate::{self, GateInput, GateLog};
use pendulum_theory::period::beats_per_hour;
use serde::Serialize;

/// What the command prints as JSON: the file read, then the analysis.
#[derive(Serialize)]
struct BeatsJson {
    file: String,
    format: crate::data::Format,
    /// A photogate log: the gate read, its shadows and the bob's speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    photogate: Option<GateLog>,
    /// The label of the gate read.
    #[serde(skip_serializing_if = "Option::is_none")]
    gate_label: Option<String>,
    #[serde(flatten)]
    analysis: Beats,
}

/// The rate for people: "12 s/day (gaining) against 3600 beats/hour
/// (seconds pendulum, 0.994 m: …)", the kind when the beat is a standard
/// rate.
pub(crate) fn rate_text(
    rate_s_per_day: Option<f64>,
    nominal_beat: Option<f64>,
    kind: Option<&str>,
) -> String {
    match (rate_s_per_day, nominal_beat) {
        (Some(r), Some(n)) => format!(
            "{} s/day ({}) against {} beats/hour{}",
            // Below a microsecond a day the sign is rounding, not the clock.
            num(if r.abs() < 1e-6 { 0.0 } else { r }, 4),
            if r >= 1e-6 {
                "gaining"
            } else if r <= -1e-6 {
                "losing"
            } else {
                "keeping time"
            },
            num(beats_per_hour(2.0 * n), 6),
            kind.map_or(String::new(), |k| format!(" ({k})"))
        ),
        _ => "unknown: give --bph or --period (no standard rate within 2%)".into(),
    }
}

/// `--tick-rate`: positive and finite.
fn tick_rate(rate: Option<crate::units::Hertz>) -> Result<Option<f64>, CliError> {
    match rate {
        // From a 1 Hz counter to a 1 THz clock: beyond, the times in
        // seconds are not numbers a log could hold.
        Some(r) if !(1.0..=1e12).contains(&r.0) => Err(CliError::flag(
            "--tick-rate",
            format!(
                "must be a positive number of ticks a second, from 1 to 10^12, got {}",
                crate::output::num(r.0, 6)
            ),
        )),
        r => Ok(r.map(|r| r.0)),
    }
}

pub fn run(args: &FitBeatsArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let nominal = common::nominal(args.period, args.bph);
    let known = common::known(&args.advice)?;
    pendulum_theory::advice::check(&known).map_err(|e| common::refused(&e))?;
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
        tick_rate: tick_rate(args.tick_rate)?,
        ..ReadOptions::default()
    };
    // A photogate log (a gate column, times in a clock's ticks, or a
    // gate's flags given) is read whole and its edges paired; any other
    // is streamed.
    let gate_flags = args.gate.is_some() || args.bob_diameter.is_some();
    let photogate = std::cell::Cell::new(false);
    let (mut gate_time, mut gate_of, mut gate_lines) = (Vec::new(), Vec::new(), Vec::new());
    // Streamed: a log of 10^7 beats takes no more memory than one of ten.
    // For the plot: every `stride`-th interval, the stride doubling whenever
    // the kept points reach their limit, so memory stays bounded.
    let mut previous = f64::NEG_INFINITY;
    let mut intervals: Vec<(f64, f64)> = Vec::new();
    let (mut stride, mut seen) = (1_u64, 0_u64);
    let chooser = |found: &[Found]| {
        let has = |r: Role| found.iter().any(|f| f.role == r);
        // A track (a Tracker project, a video's export) times video
        // frames, not beats: its rate would be the camera's.
        if has(Role::Angle) || has(Role::X) && has(Role::Y) {
            return Err(
                "is a tracked swing (an angle, or x and y, against time: a Tracker project or \
                 a video's export), whose times are the video's frames, not beats: fit it with \
                 fit trajectory (or fit decay); fit beats reads one time per beat or pass"
                    .to_string(),
            );
        }
        if has(Role::Gate) || has(Role::Ticks) || gate_flags {
            photogate.set(true);
            let mut roles = need(&[&[Role::Ticks, Role::Time]])(found)?;
            if has(Role::Gate) {
                roles.push(Role::Gate);
            }
            Ok(roles)
        } else {
            need(&[&[Role::Time]])(found)
        }
    };
    let (_, _, _, format) = stream_table(&args.file, &options, &chooser, |row, line| {
        if photogate.get() {
            gate_time.push(row[0]);
            gate_of.push(row.get(1).copied().unwrap_or(0.0));
            gate_lines.push(line);
            return Ok(());
        }
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
    let (analysis, gate_log) = if photogate.get() {
        let select = match &args.gate {
            Some(label) => Some(
                format
                    .gate_labels
                    .iter()
                    .position(|l| l.eq_ignore_ascii_case(label))
                    .ok_or_else(|| {
                        CliError::flag(
                            "--gate",
                            if format.gate_labels.is_empty() {
                                format!("{file} has no gate column")
                            } else {
                                format!(
                                    "'{label}' is not a gate of {file} ({})",
                                    format.gate_labels.join(", ")
                                )
                            },
                        )
                    })?,
            ),
            None => None,
        };
        let has_gates = !format.gate_labels.is_empty();
        let g = photogate::analyse(&GateInput {
            time: &gate_time,
            gate: has_gates.then_some(gate_of.as_slice()),
            select,
            bob_diameter: args.bob_diameter.map(|d| d.0),
            nominal,
        })
        .map_err(|r| {
            let line = match r.place {
                pendulum_theory::analysis::Place::Sample(_, i) => gate_lines.get(i).copied(),
                _ => None,
            };
            refused(&r, line)
        })?;
        if plot.is_some() {
            intervals = g
                .pass_times
                .windows(2)
                .map(|w| (w[1], 1e3 * (w[1] - w[0])))
                .collect();
        }
        (g.beats, Some(g.photogate))
    } else {
        (log.finish().map_err(|r| refused(&r, None))?, None)
    };
    let mut analysis = analysis;
    analysis
        .advise(&known, None, None, None)
        .map_err(|e| common::refused(&e))?;
    let a = &analysis;
    if let Some(target) = &plot {
        let mean = vec![
            (intervals.first().map_or(0.0, |p| p.0), 1e3 * a.mean_beat_s),
            (intervals.last().map_or(1.0, |p| p.0), 1e3 * a.mean_beat_s),
        ];
        // Repaired gaps (missed beats) would squash the scale: show the
        // intervals within half a beat of the mean. The beats alternate
        // (tick to tock, tock to tick), each in its own colour: a clock
        // out of beat shows two bands.
        let near = |p: &(f64, f64)| (p.1 - 1e3 * a.mean_beat_s).abs() < 500.0 * a.mean_beat_s;
        // A missed beat's interval spans two beats: it counts two, so the
        // sides keep their colours after it.
        let beat_ms = 1e3 * a.mean_beat_s;
        let mut beat = 0_usize;
        let (mut odd, mut even) = (Vec::new(), Vec::new());
        for p in &intervals {
            if near(p) {
                if beat % 2 == 0 { &mut odd } else { &mut even }.push(*p);
            }
            let spans = (p.1 / beat_ms).round();
            beat += if spans.is_finite() && spans >= 1.0 {
                spans as usize
            } else {
                1
            };
        }
        let allan = a
            .allan_deviation
            .iter()
            .map(|p| (p.tau_s, p.deviation_s_per_day))
            .collect();
        let figure = Figure {
            panels: vec![
                Panel::new(
                    "Beat intervals (ticks and tocks)",
                    crate::plot::TIME_AXIS,
                    "interval (ms)",
                    vec![
                        Series::dots("intervals 1, 3, 5, …", odd),
                        Series::dots("intervals 2, 4, 6, …", even),
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
    let gate_label = gate_log
        .as_ref()
        .and_then(|g| format.gate_labels.get(g.gate).cloned());
    let result = BeatsJson {
        file,
        format,
        photogate: gate_log,
        gate_label,
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
    .row(
        "Rate",
        rate_text(a.rate_s_per_day, a.nominal_beat_s, a.nominal_kind),
    )
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
    if let Some(g) = &result.photogate {
        s.row(
            "Photogate",
            format!(
                "gate {} of {}: {} events, {} passes{}",
                result.gate_label.as_deref().unwrap_or("1"),
                g.gates,
                g.events,
                g.passes,
                if g.unpaired_edges > 0 {
                    format!(", {} lone edges left out", g.unpaired_edges)
                } else {
                    String::new()
                }
            ),
        );
        if let (Some(w), Some(w0), Some(w1)) = (
            g.pulse_width_ms,
            g.pulse_width_start_ms,
            g.pulse_width_end_ms,
        ) {
            s.row(
                "Shadow",
                format!(
                    "{} ms (first passes {} ms, last {} ms)",
                    num(w, 4),
                    num(w0, 4),
                    num(w1, 4)
                ),
            );
        }
        if let (Some(v0), Some(v1)) = (g.gate_speed_start_m_s, g.gate_speed_end_m_s) {
            s.row(
                "Speed at gate",
                format!(
                    "{} m/s (first passes), {} m/s (last)",
                    num(v0, 4),
                    num(v1, 4)
                ),
            );
        }
    }
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
    out.push_str(&common::advice_text(&a.advice));
    Ok(out)
}
