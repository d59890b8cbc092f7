//! `pendulum log`: a clock's log, its rate model, its stability and its
//! periodic errors.

mod figures;

use crate::args::{LogArgs, LogKindArg};
use crate::data::{read_table, Found, ReadOptions, Role};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num, Summary};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::clock_log::terms::columns;
use pendulum_theory::clock_log::{
    analyse, LogColumn, LogInput, LogKind, LogResult, Source, TrainInput, TERMS,
};
use pendulum_theory::compound::regulate::Regulated;
use pendulum_theory::period::Nominal;
use pendulum_theory::stability::{StabilityRow, ADEV};
use pendulum_theory::tide::Station;
use serde::Serialize;

/// What the command prints as JSON.
#[derive(Serialize)]
struct LogJson<'a> {
    file: String,
    format: crate::data::Format,
    #[serde(flatten)]
    analysis: &'a LogResult,
}

/// Unix times look like this (after 1973): a column of dates.
const UNIX_AFTER: f64 = 1e8;

/// A log read and analysed, with what its reader found.
pub(crate) struct Analysed {
    /// The file, as named.
    pub file: String,
    /// How it was read.
    pub format: crate::data::Format,
    /// The log time of its first row, s (Unix time for dated logs).
    pub origin: Option<f64>,
    /// The analysis.
    pub result: LogResult,
}

pub fn run(args: &LogArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_ref()
        .map(|p| figures::Prefix::new(p))
        .transpose()?;
    if let Some(prefix) = &plot {
        // The figures' files checked with the other outputs, before work.
        let mut outputs: Vec<(String, std::path::PathBuf)> = prefix
            .paths()
            .into_iter()
            .map(|p| ("--plot".to_string(), p))
            .collect();
        if let Some(r) = &args.residuals {
            outputs.push(("--residuals".to_string(), r.0.clone()));
        }
        let inputs: Vec<(String, std::path::PathBuf)> = [
            ("FILE", Some(&args.file)),
            ("--events", args.events.as_ref()),
            ("--design", args.design.as_ref()),
        ]
        .into_iter()
        .filter_map(|(flag, p)| Some((flag.to_string(), p?.0.clone())))
        .collect();
        crate::file::check_outputs(&outputs, &inputs)?;
    }
    let Analysed {
        file,
        format,
        origin,
        result,
    } = analyse_file(args)?;
    let mut written = Vec::new();
    if let Some(path) = &args.residuals {
        let mut csv = CsvFile::create(
            path,
            "--residuals",
            "time_s,rate_s_per_day,model_s_per_day,residual_s_per_day",
        )?;
        for row in &result.per_bin {
            csv.number(Some(row[0] + origin.unwrap_or(0.0)))
                .number(Some(row[1]))
                .number(Some(row[2]))
                .number(Some(row[3]));
            csv.end_row()?;
        }
        written.push(csv.commit()?);
    }
    if let Some(prefix) = &plot {
        written.extend(figures::write(prefix, &result)?);
    }
    if args.json {
        return output::json(&LogJson {
            file,
            format,
            analysis: &result,
        });
    }
    let mut out = text(&file, &result);
    for w in written {
        out.push_str(&format!("Wrote {w}\n"));
    }
    Ok(out)
}

/// The figures of a log's analysis, named (`rate`, `stability`, …).
pub(crate) fn figures(r: &LogResult) -> Vec<(&'static str, crate::plot::Figure)> {
    figures::all(r)
}

/// Reads the log `args` names and analyses it.
pub(crate) fn analyse_file(args: &LogArgs) -> Result<Analysed, CliError> {
    let file = args.file.display().to_string();
    let wanted = args.kind;
    let chooser = |found: &[Found]| {
        let has = |r: Role| found.iter().any(|f| f.role == r);
        if !has(Role::Time) {
            return Err("no time column (named time, t, timestamp, …)".to_string());
        }
        let value = match wanted {
            Some(LogKindArg::Offset) => Some(Role::Offset),
            Some(LogKindArg::Rate) => Some(Role::Frequency),
            Some(LogKindArg::HalfPeriods) => Some(Role::HalfPeriod),
            Some(LogKindArg::Beats) => None,
            None => [Role::Offset, Role::Frequency, Role::HalfPeriod]
                .into_iter()
                .find(|&r| has(r)),
        };
        let mut roles = vec![Role::Time];
        if let Some(v) = value {
            if !has(v) {
                return Err(format!("no {} column", crate::data::role_name(v)));
            }
            roles.push(v);
        }
        // The columns the model's table of terms reads, and pulse widths.
        let weather = columns()
            .filter_map(|c| crate::data::role_named(c.name))
            .chain([Role::PulseWidth]);
        for r in weather {
            if has(r) {
                roles.push(r);
            }
        }
        Ok(roles)
    };
    let options = ReadOptions {
        columns: super::measured::columns(args.columns.as_deref()),
        angle_unit: Some(crate::data::AngleUnit::Degrees),
        ..ReadOptions::default()
    };
    let table = read_table(&args.file, &options, &chooser)?;
    let origin = table.format.time_origin_s;
    // The Unix time of the log's first row: its date, or --start plus
    // the first row's seconds.
    let dated = origin.filter(|&o| o > UNIX_AFTER);
    let epoch = match (&args.start, dated) {
        (Some(_), Some(first)) => {
            return Err(CliError::flag(
                "--start",
                format!(
                    "the log's times are already dates (its first is {}); --start is for a log timed in seconds from its start",
                    super::tide::iso(first)
                ),
            ))
        }
        (Some(text), None) => Some(super::tide::instant(text, "--start")? + origin.unwrap_or(0.0)),
        (None, dated) => dated,
    };
    let times = table.column(Role::Time).unwrap_or(&[]).to_vec();
    let (kind, time_s, values) = match table.roles.get(1) {
        Some(Role::Offset) => (LogKind::Offset, times, table.values[1].clone()),
        Some(Role::Frequency) => (
            LogKind::Rate,
            times,
            table.values[1].iter().map(|f| f * 86_400.0).collect(),
        ),
        Some(Role::HalfPeriod) => (LogKind::HalfPeriods, times, table.values[1].clone()),
        // Beat times alone: each half period ends at its beat.
        _ => (
            LogKind::HalfPeriods,
            times[1..].to_vec(),
            times.windows(2).map(|w| w[1] - w[0]).collect(),
        ),
    };
    let skip = usize::from(values.len() < table.lines.len());
    // Each column the table of terms reads, in its SI unit as the reader
    // gives it.
    let weather: Vec<LogColumn> = columns()
        .filter_map(|c| {
            let values = table.column(crate::data::role_named(c.name)?)?;
            Some(LogColumn::new(c.name, values[skip..].to_vec()))
        })
        .collect();
    let pulses = table.column(Role::PulseWidth).map(|c| c[skip..].to_vec());
    let events = match &args.events {
        Some(path) => read_events(path, origin.unwrap_or(0.0), epoch)?,
        None => Vec::new(),
    };
    let design = args
        .design
        .as_deref()
        .map(crate::design::read_design)
        .transpose()?;
    let station = match (args.latitude, args.longitude) {
        (Some(lat), Some(lon)) => Some(Station {
            latitude_deg: lat.0.to_degrees(),
            longitude_deg: lon.0.to_degrees(),
            height_m: args.height.map_or(0.0, |h| h.0),
        }),
        _ => None,
    };
    let nominal = match (args.bph, args.period) {
        (Some(b), _) => Some(Nominal::BeatsPerHour(b.0)),
        (_, Some(p)) => Some(Nominal::Period(p.0)),
        _ => None,
    };
    let input = LogInput {
        epoch_unix_s: epoch,
        kind: Some(kind),
        columns: weather,
        pulse_width_s: pulses,
        flag_width_m: args.flag_width.map(|w| w.0),
        gate_radius_m: args.gate_radius.map(|r| r.0),
        time_s,
        values,
        nominal,
        beat_s: args.beat.map(|b| b.0),
        station,
        tides: args.tides,
        events_s: events,
        bin_s: args.bin.map(|b| b.0),
        design,
        force: args.force,
        skip_stability: false,
        train: args.train.as_ref().map(|t| TrainInput {
            wheels: t.wheels.clone(),
            pinions: t.pinions.clone(),
            arbor_turns_per_hour: args.arbor_turns_per_hour.map(|n| n.0),
        }),
    };
    let mut result = analyse(&input).map_err(|r| refused(&r, &file, &table.lines, skip))?;
    let pendulum = match (input.design, args.length) {
        (Some(d), _) => Some(Regulated::Design(d, None)),
        (None, Some(l)) => Some(Regulated::Length(l.0)),
        (None, None) => None,
    };
    let known = pendulum_theory::advice::Known {
        pendulum,
        nut: args.nut.nut(),
        ..Default::default()
    };
    result
        .advise(&known)
        .map_err(|e| crate::commands::common::refused(&e))?;
    Ok(Analysed {
        file,
        format: table.format,
        origin,
        result,
    })
}

/// The library's refusal in the tool's words: a flag, or a file line.
fn refused(r: &Refusal, file: &str, lines: &[u64], skip: usize) -> CliError {
    CliError::refused(
        r,
        &[
            ("bin", "--bin"),
            ("latitude", "--latitude"),
            ("height", "--height"),
            ("time", "--start"),
            ("flag_width", "--flag-width"),
            ("period", "--period"),
            ("bph", "--bph"),
            ("gate_radius", "--gate-radius"),
            ("train", "--train"),
            ("arbor_turns_per_hour", "--arbor-turns-per-hour"),
        ],
        &|at, reason| match at {
            Some((_, i)) => CliError::other(format!(
                "{file}: line {}: {reason}",
                lines.get(i + skip).copied().unwrap_or(0)
            )),
            None => CliError::other(format!("{file}: {reason}")),
        },
    )
}

/// The event times of `path` as the log's times (s from its first row).
fn read_events(
    path: &std::path::Path,
    origin: f64,
    epoch: Option<f64>,
) -> Result<Vec<f64>, CliError> {
    let options = ReadOptions {
        absolute_time: true,
        columns: crate::data::headerless_width(path).map(|_| vec!["time".to_string()]),
        ..ReadOptions::default()
    };
    let table = read_table(path, &options, &|found: &[Found]| {
        if found.iter().any(|f| f.role == Role::Time) {
            Ok(vec![Role::Time])
        } else {
            Err("no time column".to_string())
        }
    })?;
    let shift = table.format.time_origin_s.unwrap_or(0.0);
    Ok(table
        .column(Role::Time)
        .unwrap_or(&[])
        .iter()
        .map(|&t| {
            let t = t + shift;
            // Dates are placed by the log's epoch; plain seconds are on
            // the log's own time column.
            match epoch {
                Some(e) if t > UNIX_AFTER => t - e,
                _ => t - origin,
            }
        })
        .collect())
}

/// "+0.123 ± 0.004".
fn pm(v: Option<f64>, se: Option<f64>, digits: usize) -> Option<String> {
    Some(format!("{} ± {}", num(v?, digits), num(se?, 2)))
}

/// The whole for people.
pub(crate) fn text(file: &str, r: &LogResult) -> String {
    let mut s = Summary::default();
    s.row("File", file).row(
        "Log",
        format!(
            "{} samples of {} over {} days, in {} bins of {} s",
            r.samples,
            match r.kind {
                LogKind::Offset => "offsets",
                LogKind::Rate => "rates",
                LogKind::HalfPeriods => "half periods",
            },
            num(r.span_s / 86_400.0, 4),
            r.bins,
            num(r.bin_s, 4)
        ),
    );
    s.row(
        "Rate",
        format!(
            "{} s/day over the log, at its mean weather{}",
            pm(
                Some(r.rate_s_per_day),
                Some(r.rate_standard_error_s_per_day),
                5
            )
            .unwrap_or_default(),
            if (r.rate_at_end_s_per_day - r.rate_s_per_day).abs()
                > 2.0 * r.rate_standard_error_s_per_day
            {
                format!("; {} s/day at its end", num(r.rate_at_end_s_per_day, 4))
            } else {
                String::new()
            }
        ),
    );
    let c = &r.coefficients;
    let e = &r.standard_errors;
    for term in TERMS.iter() {
        let value = match term.source {
            Source::Time => r.drift_s_per_day_per_day,
            _ => c.get(term.name),
        };
        let se = match term.source {
            Source::Time => r.drift_standard_error_s_per_day_per_day,
            _ => e.get(term.name),
        };
        let Some(text) = pm(value, se, 3) else {
            continue;
        };
        let lag = match (term.source, r.temperature_lag_s, r.temperature_lag_range_s) {
            (Source::LaggedColumn, Some(l), Some([lo, hi])) if l > 0.0 => format!(
                ", following the air {} h late ({} to {} h)",
                num(l / 3600.0, 3),
                num(lo / 3600.0, 3),
                num(hi / 3600.0, 3)
            ),
            (Source::LaggedColumn, Some(_), Some([_, hi])) => format!(
                ", following the air within {} h (no lag told from none)",
                num(hi / 3600.0, 2)
            ),
            _ => String::new(),
        };
        s.row(term.label, format!("{text} {}{lag}", term.unit));
    }
    for (i, (v, se)) in c.steps_s_per_day.iter().zip(&e.steps_s_per_day).enumerate() {
        s.row(
            &format!("Step {}", i + 1),
            format!("{} ± {} s/day", num(*v, 4), num(*se, 2)),
        );
    }
    let dropped: Vec<String> = r
        .terms
        .iter()
        .filter(|t| !t.kept)
        .map(|t| {
            let unit = TERMS
                .iter()
                .find(|m| m.name == t.name)
                .map_or("", |m| m.unit);
            match pm(t.estimate, t.standard_error, 2) {
                Some(v) => format!("{}: {v} {unit}", t.name.replace('_', " ")),
                None => t.name.replace('_', " "),
            }
        })
        .collect();
    if !dropped.is_empty() {
        s.row(
            "Left out",
            format!(
                "{} (the information criterion prefers the model without)",
                dropped.join("; ")
            ),
        );
    }
    s.row(
        "Noise",
        format!(
            "{} s/day white a bin, a random walk of {} s/day a day; residuals {} s/day RMS",
            num(r.white_noise_s_per_day, 3),
            num(r.random_walk_s_per_day_per_day, 3),
            num(r.residual_rms_s_per_day, 3)
        ),
    );
    if let Some(d) = &r.design {
        let parts: Vec<String> = d
            .predictions
            .iter()
            .map(|p| match p.difference_se {
                Some(x) => format!(
                    "{} {} (measured {} standard errors away)",
                    num(p.predicted, 3),
                    p.term.unit,
                    num(x, 2)
                ),
                None => format!("{} {} (not measured)", num(p.predicted, 3), p.term.unit),
            })
            .collect();
        s.row("Design says", parts.join("; "));
    }
    let mut out = s.render();
    for (title, rows) in [
        ("Stability of the log", &r.stability),
        ("Stability after the model", &r.residual_stability),
    ] {
        out.push_str(&format!("\n{title}:\n"));
        out.push_str(&stability_table(rows));
    }
    out.push_str(&periodic(r));
    for w in &r.warnings {
        out.push_str(&format!("warning: {w}\n"));
    }
    if r.advice.is_empty() && r.beat_s.is_none() {
        out.push_str(
            "(For the move of the bob that brings it to time, give --length or --design.)\n",
        );
    } else {
        out.push_str(&crate::commands::common::advice_text(&r.advice));
    }
    out
}

/// The lines, the folds and the swing, for people.
fn periodic(r: &LogResult) -> String {
    let mut out = String::new();
    if let Some(s) = r.spectrum.as_ref().filter(|s| !s.lines.is_empty()) {
        out.push_str("\nPeriodic errors (the rate's spectrum):\n");
        let rows: Vec<Vec<String>> = s
            .lines
            .iter()
            .map(|l| {
                vec![
                    l.name.clone(),
                    num(l.period_s / 3600.0, 5),
                    match l.amplitude_standard_error_s_per_day {
                        Some(e) => format!("{} ± {}", num(l.amplitude_s_per_day, 3), num(e, 2)),
                        None => num(l.amplitude_s_per_day, 3),
                    },
                    l.signal_to_noise.map_or("–".into(), |x| num(x, 2)),
                    match (&l.blended_with, l.seen) {
                        (Some(o), true) => {
                            format!("seen, blended with {o} (a longer log parts them)")
                        }
                        (Some(o), false) => format!("not above the noise (blended with {o})"),
                        (None, true) => "seen".into(),
                        (None, false) => "not above the noise".into(),
                    },
                ]
            })
            .collect();
        out.push_str(&output::table(
            &[
                "line",
                "period (h)",
                "amplitude (s/day)",
                "signal/noise",
                "verdict",
            ],
            &rows,
        ));
    }
    for f in &r.folds {
        out.push_str(&format!(
            "The {} turns in {} s ({} turns logged): {} s/day peak to peak over the turn, a time error of {} s within it; {} ({}).\n",
            f.arbor,
            num(f.period_s, 6),
            num(f.turns, 4),
            num(f.peak_to_peak_s_per_day, 3),
            num(f.time_error_peak_to_peak_s, 3),
            if f.seen { "a pattern the wheel makes" } else { "no pattern above the scatter" },
            figures::p_text(f.p_value)
        ));
    }
    let fast: Vec<&str> = r
        .arbors
        .iter()
        .filter(|a| !r.folds.iter().any(|f| f.arbor == a.name))
        .map(|a| a.name.as_str())
        .collect();
    if !fast.is_empty() {
        out.push_str(&format!(
            "Not folded: the {} (a turn needs 4 samples and the log 3 turns; a photogate's half periods resolve every wheel).\n",
            fast.join(", the ")
        ));
    }
    if let Some(b) = r.beat_error_s {
        out.push_str(&format!(
            "Beat error {} ms: alternate half periods differ by twice it (taken out before the folds).\n",
            num(b * 1e3, 3)
        ));
    }
    if let Some(w) = &r.swing {
        let mut s = Summary::default();
        s.row(
            "Swing",
            format!(
                "{} half swings, mean amplitude {}°",
                w.half_swings,
                num(w.mean_amplitude_deg, 4)
            ),
        );
        match (w.q, w.q_standard_error, w.half_swings_per_impulse) {
            (Some(q), Some(e), Some(every)) => s.row(
                "Q",
                format!(
                    "{} ± {} from the decay between impulses (one every {} half swings)",
                    num(q, 4),
                    num(e, 2),
                    num(every, 4)
                ),
            ),
            _ => s.row(
                "Q",
                "not seen while the clock goes (no decay between impulses: impulsed every swing?); a run-down measures it: pendulum fit decay",
            ),
        };
        s.row(
            "Energy scatter",
            format!(
                "{} ppm from half swing to half swing (the gate's noise included)",
                num(w.energy_scatter_ppm, 3)
            ),
        );
        out.push('\n');
        out.push_str(&s.render());
    }
    out
}

/// A short table of stability rows.
fn stability_table(rows: &[StabilityRow]) -> String {
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                num(r.tau_s, 5),
                r.adev().map_or("–".into(), |v| num(v, 3)),
                match r.interval(&ADEV) {
                    Some((l, h)) => format!("{} … {}", num(l, 2), num(h, 2)),
                    _ => "–".into(),
                },
                r.adev_s_per_day.map_or("–".into(), |v| num(v, 3)),
                match r.noise {
                    Some(n) => n.name().to_string(),
                    None if r.periodic => "periodic signal".into(),
                    None => "–".into(),
                },
            ]
        })
        .collect();
    output::table(&["τ (s)", "ADEV", "68% interval", "s/day", "noise"], &body)
}
