//! `pendulum log`: a clock's log, its rate model, its stability and its
//! periodic errors.

mod figures;

use crate::args::{LogArgs, LogKindArg};
use crate::data::{read_table, Found, ReadOptions, Role};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num, Summary};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::clock_log::{analyse, LogInput, LogKind, LogResult, LogWarning, TrainInput};
use pendulum_theory::period::Nominal;
use pendulum_theory::stability::StabilityRow;
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
        for r in [
            Role::Temperature,
            Role::Pressure,
            Role::Humidity,
            Role::Amplitude,
            Role::PulseWidth,
        ] {
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
    let epoch = match &args.start {
        Some(text) => Some(super::tide::instant(text, "--start")? + origin.unwrap_or(0.0)),
        None => origin.filter(|&o| o > UNIX_AFTER),
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
    let env = |role: Role, scale: f64| {
        table
            .column(role)
            .map(|c| c[skip..].iter().map(|v| v * scale).collect::<Vec<f64>>())
    };
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
        temperature_c: env(Role::Temperature, 1.0),
        pressure_hpa: env(Role::Pressure, 0.01),
        humidity_percent: env(Role::Humidity, 1.0),
        amplitude_deg: env(Role::Amplitude, 1f64.to_degrees()),
        pulse_width_s: env(Role::PulseWidth, 1.0),
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
    let result = analyse(&input).map_err(|r| refused(&r, &file, &table.lines, skip))?;
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
            "{} s/day at the mean time and weather",
            pm(
                Some(r.rate_s_per_day),
                Some(r.rate_standard_error_s_per_day),
                5
            )
            .unwrap_or_default()
        ),
    );
    if let Some(d) = pm(
        r.drift_s_per_day_per_day,
        r.drift_standard_error_s_per_day_per_day,
        3,
    ) {
        s.row("Drift", format!("{d} s/day a day"));
    }
    let c = &r.coefficients;
    let e = &r.standard_errors;
    if let Some(t) = pm(
        c.temperature_s_per_day_per_c,
        e.temperature_s_per_day_per_c,
        3,
    ) {
        let lag = r
            .temperature_lag_s
            .filter(|&l| l > 0.0)
            .map_or(String::new(), |l| {
                format!(", following the air {} h late", num(l / 3600.0, 2))
            });
        s.row("Temperature", format!("{t} s/day per °C{lag}"));
    }
    if let Some(p) = pm(
        c.pressure_s_per_day_per_hpa,
        e.pressure_s_per_day_per_hpa,
        3,
    ) {
        s.row("Pressure", format!("{p} s/day per hPa"));
    }
    if let Some(h) = pm(
        c.humidity_s_per_day_per_percent,
        e.humidity_s_per_day_per_percent,
        3,
    ) {
        s.row("Humidity", format!("{h} s/day per % RH"));
    }
    if let Some(a) = pm(
        c.amplitude_s_per_day_per_deg,
        e.amplitude_s_per_day_per_deg,
        3,
    ) {
        s.row("Amplitude", format!("{a} s/day per degree of swing"));
    }
    if let Some(k) = pm(c.tide_admittance, e.tide_admittance, 3) {
        s.row("Tide", format!("admittance {k} (1: the full body tide)"));
    }
    for (i, (v, se)) in c.steps_s_per_day.iter().zip(&e.steps_s_per_day).enumerate() {
        s.row(
            &format!("Step {}", i + 1),
            format!("{} ± {} s/day", num(*v, 4), num(*se, 2)),
        );
    }
    let dropped: Vec<&str> = r.terms.iter().filter(|t| !t.kept).map(|t| t.name).collect();
    if !dropped.is_empty() {
        s.row(
            "Left out",
            format!(
                "{} (the information criterion prefers the model without)",
                dropped.join(", ")
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
        let versus = |p: f64, diff: Option<f64>| match diff {
            Some(x) => format!(
                "{} (measured {} standard errors away)",
                num(p, 3),
                num(x, 2)
            ),
            None => format!("{} (not measured)", num(p, 3)),
        };
        s.row(
            "Design says",
            format!(
                "{} s/day per °C; {} s/day per hPa",
                versus(d.temperature_s_per_day_per_c, d.temperature_difference_se),
                versus(d.pressure_s_per_day_per_hpa, d.pressure_difference_se)
            ),
        );
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
        out.push_str(&format!("warning: {}\n", warning(w)));
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
                r.adev.map_or("–".into(), |v| num(v, 3)),
                match (r.adev_low, r.adev_high) {
                    (Some(l), Some(h)) => format!("{} … {}", num(l, 2), num(h, 2)),
                    _ => "–".into(),
                },
                r.adev_s_per_day.map_or("–".into(), |v| num(v, 3)),
                r.noise.map_or("–".into(), |n| n.name().to_string()),
            ]
        })
        .collect();
    output::table(&["τ (s)", "ADEV", "68% interval", "s/day", "noise"], &body)
}

/// A warning in words.
fn warning(w: &LogWarning) -> String {
    match w {
        LogWarning::WrapsUndone { count } => format!(
            "{count} whole-beat jumps of the offset undone (the reference slipped a tick)"
        ),
        LogWarning::Implausible { term, reason } => format!("{term}: {reason}"),
        LogWarning::TideAdmittance {
            admittance,
            from_one_se,
        } => format!(
            "the tide's admittance {} is {} standard errors from 1: something else shares the tide's periods (a daily temperature cycle?), or the times are not UTC",
            num(*admittance, 3),
            num(*from_one_se, 2)
        ),
        LogWarning::Short { what } => format!("the log is too short to tell the {what}"),
        LogWarning::TimesRepeated {
            dropped,
            first_time_s,
        } => format!(
            "{dropped} samples whose time did not advance left out (the first at {} s): a logger's repeated stamp, or files joined with an overlap",
            num(*first_time_s, 10)
        ),
        LogWarning::BeatsMissed { left_out } => format!(
            "{left_out} half periods under half or over 1.5 times the typical one left out (a transit the gate missed, a stray trigger): the beats they span count as a gap"
        ),
        LogWarning::EventIgnored { time_s, reason } => format!(
            "the event at {} s of the log is left out: {reason}",
            num(*time_s, 10)
        ),
        LogWarning::PulsesIgnored => "the pulse widths are left aside: give --flag-width and --gate-radius to read the swing's amplitude, Q and steadiness from them".to_string(),
        LogWarning::TrainBeat { train_bph, log_bph } => format!(
            "the train gives {} beats an hour, the log {}: check --train and --arbor-turns-per-hour",
            num(*train_bph, 6),
            num(*log_bph, 6)
        ),
        LogWarning::RateAgainstMean => {
            "no standard beat within 2% of the half periods: the rate is against their mean; give --bph or --period".to_string()
        }
    }
}
