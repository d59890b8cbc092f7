//! `pendulum clock`: a pendulum kept going by an escapement: its steady
//! state, the isochronism curve, and long runs. The clock is one library
//! call ([`pendulum_theory::clock::analysis::analyse`]); this reads the
//! arguments and the drive file, writes the rows and renders the result.

use super::common;
use crate::args::ClockArgs;
use crate::data::{read_table, Found, ReadOptions, Role, Table};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::interrupt;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};
use crate::units::parse_number;
use pendulum_theory::clock::analysis::{
    analyse, ClockInput, ClockPendulum, ClockResult, DriveFactors, IsochronismPoint, RunInput,
    RunSink, Schedule, SteadyState, Weather,
};
use pendulum_theory::clock::long_run::Row;
use pendulum_theory::clock::plan::RunPlan;
use std::path::Path;

/// The library's field names that are not `--` and the field.
const FLAGS: &[(&str, &str)] = &[
    ("drive_schedule", "--drive-file"),
    ("rate_schedule", "--drive-file"),
    ("weather", "--drive-file"),
    ("humidity", "--drive-file"),
    ("gradient", "--drive-file"),
];

/// A plain number flag.
fn number(flag: &str, text: &str) -> Result<f64, CliError> {
    parse_number(text).map_err(|e| CliError::flag(flag, e))
}

/// The columns a drive file may have besides its times.
const COLUMNS: [(Role, &str); 6] = [
    (Role::DriveFactor, "drive_factor"),
    (Role::RateChange, "rate_change_s_per_day"),
    (Role::Temperature, "temperature_c"),
    (Role::Pressure, "pressure_hpa"),
    (Role::Humidity, "humidity_percent"),
    (Role::Gradient, "gradient_k_per_m"),
];

/// A drive file's schedules: the drive's factors, the rate's changes from
/// outside, the weather.
struct Schedules {
    drive: Option<Schedule>,
    rate: Option<Schedule>,
    weather: Option<Weather>,
}

/// A drive file read by the shared reader (any separator, decimal commas,
/// units in the header): times and any of a drive factor, a change of
/// rate from outside (s/day), a temperature, a pressure (hPa without a
/// unit), a relative humidity (%) and a vertical temperature gradient
/// (K/m, warmer upwards).
fn read_schedule(path: &Path) -> Result<(Table, Schedules), CliError> {
    let flag = |e: CliError| e.of_flag("--drive-file");
    let choose = |found: &[Found]| -> Result<Vec<Role>, String> {
        let has = |r: Role| found.iter().any(|f| f.role == r);
        if !has(Role::Time) {
            return Err("needs a time column (time_s)".to_string());
        }
        let mut roles = vec![Role::Time];
        roles.extend(COLUMNS.iter().map(|c| c.0).filter(|&r| has(r)));
        if roles.len() == 1 {
            let names: Vec<&str> = COLUMNS.iter().map(|c| c.1).collect();
            return Err(format!(
                "needs one of the columns {} besides time_s",
                names.join(", ")
            ));
        }
        Ok(roles)
    };
    let options = ReadOptions {
        absolute_time: true,
        no_columns_flag: true,
        refuse_blank: true,
        ..ReadOptions::default()
    };
    let table = read_table(path, &options, &choose).map_err(flag)?;
    let time = table.column(Role::Time).unwrap_or_default().to_vec();
    if time.is_empty() {
        return Err(flag(CliError::other(format!(
            "{}: has no rows",
            table.file
        ))));
    }
    let column = |r: Role| table.column(r).map(<[f64]>::to_vec);
    let drive = column(Role::DriveFactor).map(|value| Schedule {
        time: time.clone(),
        value,
    });
    let rate = column(Role::RateChange).map(|value| Schedule {
        time: time.clone(),
        value,
    });
    let weather = Weather {
        time: time.clone(),
        temperature_c: column(Role::Temperature),
        pressure_pa: column(Role::Pressure),
        humidity_percent: column(Role::Humidity),
        gradient_k_per_m: column(Role::Gradient),
    };
    let weather = weather.any().then_some(weather);
    Ok((
        table,
        Schedules {
            drive,
            rate,
            weather,
        },
    ))
}

/// The isochronism curve's range, `0.5x..2x`.
fn drive_range(text: &str, steps: Option<usize>) -> Result<DriveFactors, CliError> {
    let parse = |s: &str| number("--drive-range", s.trim().trim_end_matches(['x', 'X']));
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| CliError::flag("--drive-range", "give two factors as 0.5x..2x"))?;
    Ok(DriveFactors::Range {
        from: parse(a)?,
        to: parse(b)?,
        steps,
    })
}

/// (time s, amplitude rad, time error s) of a long run, for its plot.
type RunPoints = Vec<(f64, f64, f64)>;

/// Bytes of one row of a long run's file, rounded up.
const BYTES_PER_ROW: f64 = 100.0;

/// Where a long run's rows go: the `--swings` file and the plot's points.
struct Rows<'a> {
    path: Option<&'a Path>,
    csv: Option<CsvFile>,
    points: RunPoints,
    keep_every: usize,
    count: usize,
    failure: Option<CliError>,
}

impl RunSink for Rows<'_> {
    fn begin(&mut self, plan: &RunPlan) -> bool {
        // At most about 20,000 points drawn.
        self.keep_every = (plan.rows as usize / 20_000).max(1);
        let Some(path) = self.path else { return true };
        let opened = crate::work::check_space("--swings", path, plan.rows * BYTES_PER_ROW)
            .and_then(|()| {
                CsvFile::create(
                    path,
                    "--swings",
                    "time_s,beats,amplitude_rad,rate_s_per_day,time_error_s,drive_factor",
                )
            });
        match opened {
            Ok(c) => self.csv = Some(c),
            Err(e) => self.failure = Some(e),
        }
        self.failure.is_none()
    }

    fn row(&mut self, row: &Row) -> bool {
        if self.count % self.keep_every == 0 {
            self.points.push((row.time, row.amplitude, row.time_error));
        }
        self.count += 1;
        if let Some(c) = self.csv.as_mut() {
            c.number(Some(row.time))
                .integer(row.beats)
                .number(Some(row.amplitude))
                .number(Some(row.rate))
                .number(Some(row.time_error))
                .number(Some(row.drive));
            if let Err(e) = c.end_row() {
                self.failure = Some(e);
                return false;
            }
        }
        !(self.count % 4096 == 0 && interrupt::requested())
    }

    fn proceed(&mut self) -> bool {
        !interrupt::requested()
    }
}

pub fn run(args: &ClockArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let pendulum = match (&args.pendulum.length, &args.pendulum.design) {
        (_, Some(path)) => ClockPendulum::Design(crate::design::read(path)?),
        (Some(l), None) => ClockPendulum::Length(l.0),
        (None, None) => return Err(CliError::flag("--length", "give --length or --design")),
    };
    let mut file = None;
    let run = match args.duration {
        Some(duration) => {
            let schedules = match &args.drive_file {
                Some(p) => {
                    let (table, schedules) = read_schedule(p)?;
                    file = Some(table);
                    schedules
                }
                None => Schedules {
                    drive: None,
                    rate: None,
                    weather: None,
                },
            };
            Some(RunInput {
                duration: duration.0,
                every: args.every.map(|t| t.0),
                drive_schedule: schedules.drive,
                weather: schedules.weather,
                rate_schedule: schedules.rate,
                force: args.force,
                gas: args
                    .gas
                    .as_deref()
                    .map(pendulum_theory::gas::Gas::parse)
                    .transpose()
                    .map_err(|e| super::common::refused(&e))?,
            })
        }
        None => None,
    };
    let input = ClockInput {
        pendulum,
        g: Some(gravity.g_m_s2),
        mass: args.mass.map(|m| m.0),
        q: args.q.map(|q| q.0),
        drag: common::drag_laws(&args.drag)?,
        escapement: args.escapement,
        lift_angle: args.lift_angle.map(|a| a.0),
        drive: Some(args.drive.0),
        friction: args.friction.map(|f| f.0),
        recoil: args.recoil.map(|r| r.0),
        impulse_angle: args.impulse_angle.map(|a| a.0),
        every_beats: args.every_beats,
        beat_error: args.beat_error.map(|b| b.0),
        isochronism: args
            .drive_range
            .as_deref()
            .map(|t| drive_range(t, args.steps))
            .transpose()?,
        run,
    };
    let target = match &args.plot {
        Some(path) if args.drive_range.is_none() && args.duration.is_none() => {
            return Err(CliError::flag(
                "--plot",
                "draws the isochronism curve (--drive-range) or a long run (--duration)",
            ))
        }
        Some(path) => Some(Target::new(path, "--plot")?),
        None => None,
    };
    let mut rows = Rows {
        path: args.swings.as_deref(),
        csv: None,
        points: Vec::new(),
        keep_every: 1,
        count: 0,
        failure: None,
    };
    let data = |which: Option<(&'static str, usize)>, reason: &str| {
        let role = match which {
            Some(("drive_schedule", _)) => Role::DriveFactor,
            Some(("rate_schedule", _)) => Role::RateChange,
            Some(("temperature_c", _)) => Role::Temperature,
            Some(("pressure", _)) => Role::Pressure,
            Some(("humidity", _)) => Role::Humidity,
            Some(("gradient", _)) => Role::Gradient,
            _ => Role::Time,
        };
        match (&file, which) {
            (Some(table), Some((_, i))) => {
                CliError::from(table.error_at(i, role, reason)).of_flag("--drive-file")
            }
            _ => CliError::other(reason),
        }
    };
    let law_flags = common::drag_flags(&[]);
    let flags: Vec<(&str, &str)> = FLAGS
        .iter()
        .copied()
        .chain(law_flags.iter().map(|(n, f)| (*n, f.as_str())))
        .collect();
    let result = analyse(&input, &mut rows).map_err(|r| CliError::refused(&r, &flags, &data))?;
    if let Some(e) = rows.failure {
        return Err(e);
    }
    if interrupt::requested() {
        return Err(interrupt::error());
    }
    let swings_file = match rows.csv {
        Some(c) => Some(c.commit()?),
        None => None,
    };
    if let Some(target) = &target {
        let figure = match &result.isochronism {
            Some(points) => isochronism_figure(points, result.escapement),
            None => run_figure(&rows.points),
        };
        render(target, &figure)?;
    }
    if args.json {
        let mut value =
            serde_json::to_value(&result).map_err(|e| CliError::other(e.to_string()))?;
        if let (Some(f), Some(run)) = (swings_file, value.get_mut("long_run")) {
            run["swings_file"] = serde_json::Value::String(f);
        }
        return output::json(&value);
    }
    Ok(render_text(&result, swings_file.as_deref()))
}

fn isochronism_figure(rows: &[IsochronismPoint], name: &str) -> Figure {
    let pick = |f: &dyn Fn(&SteadyState) -> f64| -> Vec<(f64, f64)> {
        rows.iter()
            .filter_map(|r| r.steady.as_ref().map(|s| (r.drive_factor, f(s))))
            .collect()
    };
    Figure {
        panels: vec![
            Panel::new(
                format!("Isochronism of the {name} escapement: amplitude"),
                "drive factor (× the given drive)",
                "amplitude (°)",
                vec![Series::line("steady amplitude", pick(&|s| s.amplitude_deg))],
            ),
            Panel::new(
                "Rate against the drive",
                "drive factor (× the given drive)",
                "rate (s/day, + gaining)",
                vec![
                    Series::line("rate (total)", pick(&|s| s.rate_s_per_day)),
                    Series::line(
                        "circular error's part",
                        pick(&|s| s.circular_rate_s_per_day),
                    ),
                    Series::line("escapement's part", pick(&|s| s.escapement_rate_s_per_day)),
                ],
            ),
        ],
    }
}

fn run_figure(points: &[(f64, f64, f64)]) -> Figure {
    let days = |t: f64| t / pendulum_theory::period::SECONDS_PER_DAY;
    Figure {
        panels: vec![
            Panel::new(
                "Amplitude",
                "time (days)",
                "amplitude (°)",
                vec![Series::line(
                    "amplitude",
                    points
                        .iter()
                        .map(|p| (days(p.0), p.1.to_degrees()))
                        .collect(),
                )],
            ),
            Panel::new(
                "Time error against a perfect clock",
                "time (days)",
                "error (s, + ahead)",
                vec![Series::line(
                    "clock − true time",
                    // Below the rounding of the elapsed time itself an
                    // error is noise: drawn as zero.
                    points
                        .iter()
                        .map(|p| {
                            let resolution = 8.0 * f64::EPSILON * p.0.abs();
                            (days(p.0), if p.2.abs() <= resolution { 0.0 } else { p.2 })
                        })
                        .collect(),
                )],
            ),
        ],
    }
}

fn render_text(r: &ClockResult, swings_file: Option<&str>) -> String {
    let s = &r.steady;
    let mut out = Summary::default();
    out.row("Escapement", format!("{} (Q = {})", r.escapement, num(r.q, 6)))
        .row(
            "Amplitude",
            format!("{}° either side (steady)", num(s.amplitude_deg, 6)),
        )
        .row(
            "Period",
            format!(
                "{} s (free at that amplitude {} s, small-angle {} s)",
                num(s.period_s, 10),
                num(s.free_period_s, 10),
                num(s.small_angle_period_s, 10)
            ),
        )
        .row(
            "Rate",
            format!(
                "{} s/day against a small-angle clock: circular error {}, escapement {} (Airy's integral: {})",
                num(s.rate_s_per_day, 5),
                num(s.circular_rate_s_per_day, 5),
                num(s.escapement_rate_s_per_day, 4),
                num(s.escapement_rate_airy_s_per_day, 4)
            ),
        )
        .row(
            "Energy",
            format!(
                "{} µJ per beat, {} µW",
                num(s.energy_per_beat_j * 1e6, 5),
                num(s.power_w * 1e6, 5)
            ),
        )
        .row(
            "Stops below",
            if r.minimum_drive_factor > 0.0 {
                format!("{} × the drive", num(r.minimum_drive_factor, 4))
            } else {
                "never for want of drive (its impulse does not depend on the drive)".into()
            },
        );
    if let Some(change) = r.out_of_beat_rate_s_per_day {
        out.row(
            "Out of beat",
            format!(
                "{}° off the rest: beat error {} ms, {} s/day against the clock in beat",
                num(r.out_of_beat_deg, 4),
                num(s.beat_error_ms, 4),
                num(change, 4)
            ),
        );
    }
    for w in &r.warnings {
        out.row("WARNING", w.to_string());
    }
    let mut text = out.render();
    if let Some(rows) = &r.isochronism {
        let table: Vec<Vec<String>> = rows
            .iter()
            .map(|row| match &row.steady {
                Some(s) => vec![
                    num(row.drive_factor, 4),
                    num(s.amplitude_deg, 5),
                    num(s.rate_s_per_day, 5),
                    num(s.circular_rate_s_per_day, 5),
                    num(s.escapement_rate_s_per_day, 4),
                ],
                None => vec![
                    num(row.drive_factor, 4),
                    "stops".into(),
                    String::new(),
                    String::new(),
                    String::new(),
                ],
            })
            .collect();
        text.push('\n');
        text.push_str(&output::table(
            &[
                "drive",
                "amplitude °",
                "rate s/day",
                "circular",
                "escapement",
            ],
            &table,
        ));
    }
    if let Some(run) = &r.long_run {
        let mut o = Summary::default();
        o.row(
            "Run",
            format!(
                "{} days, {} beats{}",
                num(run.duration_s / pendulum_theory::period::SECONDS_PER_DAY, 6),
                run.beats,
                if run.stopped {
                    " (the pendulum stopped)"
                } else {
                    ""
                }
            ),
        )
        .row(
            "At the end",
            format!(
                "{}°, {} s/day, {} s {} true time",
                num(run.final_amplitude_rad.to_degrees(), 5),
                num(run.final_rate_s_per_day, 4),
                num(run.time_error_s.abs(), 5),
                if run.time_error_s >= 0.0 {
                    "ahead of"
                } else {
                    "behind"
                }
            ),
        );
        if let Some(f) = swings_file {
            o.row("Written", f.to_string());
        }
        for w in &run.warnings {
            o.row("WARNING", w.to_string());
        }
        text.push('\n');
        text.push_str(&o.render());
    }
    text
}
