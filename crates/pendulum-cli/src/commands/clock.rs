//! `pendulum clock`: a pendulum kept going by an escapement: its steady
//! state, the isochronism curve, and long runs.

use super::common;
use crate::args::{ClockArgs, EscapementArg};
use crate::data::{read_table, Found, ReadOptions, Role};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::interrupt;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};
use crate::units::{parse_number, parse_quantity, Dimension};
use pendulum_theory::air::{PRESSURE_RANGE_PA, TEMPERATURE_RANGE_C};
use pendulum_theory::clock::escapement::spec::{Drive, Kind, Spec};
use pendulum_theory::clock::long_run::{
    period_factor, piecewise_linear, run as long_run, Ending, LongRun,
};
use pendulum_theory::clock::plan::plan_run;
use pendulum_theory::clock::{Clock, ClockError, HalfSwingMethod, Steady};
use serde::Serialize;
use std::path::Path;

/// The default bob mass, kg (as `report`'s).
const DEFAULT_MASS_KG: f64 = 5.0;

#[derive(Serialize)]
struct SteadyJson {
    drive_factor: f64,
    amplitude_rad: f64,
    amplitude_deg: f64,
    period_s: f64,
    free_period_s: f64,
    small_angle_period_s: f64,
    /// Against a small-angle clock, positive gaining.
    rate_s_per_day: f64,
    circular_rate_s_per_day: f64,
    /// The circular error as `period` gives it: positive, lost.
    circular_error_s_per_day: f64,
    escapement_rate_s_per_day: f64,
    /// Airy's first-order integral.
    escapement_rate_airy_s_per_day: f64,
    energy_per_beat_j: f64,
    power_w: f64,
}

impl SteadyJson {
    fn of(s: &Steady) -> Self {
        Self {
            drive_factor: s.drive,
            amplitude_rad: s.amplitude,
            amplitude_deg: s.amplitude.to_degrees(),
            period_s: s.period,
            free_period_s: s.free_period,
            small_angle_period_s: s.small_angle_period,
            rate_s_per_day: s.rate,
            circular_rate_s_per_day: s.circular_rate,
            circular_error_s_per_day: -s.circular_rate,
            escapement_rate_s_per_day: s.escapement_rate,
            escapement_rate_airy_s_per_day: s.escapement_rate_first_order,
            energy_per_beat_j: s.energy_per_beat,
            power_w: s.power,
        }
    }
}

#[derive(Serialize)]
struct ClockJson {
    escapement: &'static str,
    q: f64,
    length_m: f64,
    mass_kg: f64,
    lift_angle_rad: f64,
    drive_torque_n_m: Option<f64>,
    drive_energy_j: Option<f64>,
    minimum_drive_factor: f64,
    steady: SteadyJson,
    #[serde(skip_serializing_if = "Option::is_none")]
    isochronism: Option<Vec<IsoJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    long_run: Option<RunJson>,
}

#[derive(Serialize)]
struct IsoJson {
    drive_factor: f64,
    /// `None` where the pendulum stops.
    #[serde(flatten)]
    steady: Option<SteadyJson>,
    stops: bool,
}

#[derive(Serialize)]
struct RunJson {
    duration_s: f64,
    beats: u64,
    final_amplitude_rad: f64,
    final_rate_s_per_day: f64,
    time_error_s: f64,
    stopped: bool,
    /// Why the run ended: duration, pendulum_stopped.
    ending: &'static str,
    half_swings_stepped: u64,
    multi_beat_steps: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    swings_file: Option<String>,
}

/// A plain number flag.
fn number(flag: &str, text: &str) -> Result<f64, CliError> {
    parse_number(text).map_err(|e| CliError::flag(flag, e))
}

/// The drive: a torque, or an energy per beat.
fn drive(text: &str) -> Result<Drive, CliError> {
    match (
        parse_quantity(text, Dimension::Torque),
        parse_quantity(text, Dimension::Energy),
    ) {
        (Ok(t), _) => Ok(Drive::Torque(t)),
        (_, Ok(e)) => Ok(Drive::Energy(e)),
        _ => Err(CliError::flag(
            "--drive",
            format!("'{text}' is neither a torque (2e-4Nm, 0.2mNm) nor an energy per beat (20uJ, 0.02mJ)"),
        )),
    }
}

/// What changes with time in a long run, from a measurement file read by
/// the shared reader (any separator, decimal commas, units in the header):
/// a time column and any of a drive factor, a temperature (°C) and a
/// pressure (hPa without a unit; Pa, kPa, inHg, mmHg named); linear
/// between rows, held beyond them. Times are the run's own: a file that
/// starts at day 3 holds its first row until then.
struct Schedule {
    times: Vec<f64>,
    /// One column per quantity, in the order of [`COLUMNS`], when given
    /// (pressure in hPa).
    columns: [Option<Vec<f64>>; 3],
}

/// The schedule's quantities, with their names in messages.
const COLUMNS: [(Role, &str); 3] = [
    (Role::DriveFactor, "drive_factor"),
    (Role::Temperature, "temperature_c"),
    (Role::Pressure, "pressure_hpa"),
];

impl Schedule {
    fn read(path: &Path) -> Result<Self, CliError> {
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
            ..ReadOptions::default()
        };
        let table = read_table(path, &options, &choose).map_err(flag)?;
        let times = table.column(Role::Time).unwrap_or_default().to_vec();
        if times.is_empty() {
            return Err(flag(CliError::other(format!(
                "{}: has no rows",
                table.file
            ))));
        }
        if let Some(i) = (1..times.len()).find(|&i| times[i] <= times[i - 1]) {
            return Err(flag(table.error_at(
                i,
                Role::Time,
                "the times must increase (sort the file by time)",
            )));
        }
        let mut columns: [Option<Vec<f64>>; 3] = [None, None, None];
        for (k, &(role, name)) in COLUMNS.iter().enumerate() {
            let Some(values) = table.column(role) else {
                continue;
            };
            // Pressure is read in Pa; the schedule keeps hPa.
            let values: Vec<f64> = if role == Role::Pressure {
                values.iter().map(|p| p / 100.0).collect()
            } else {
                values.to_vec()
            };
            // The weather's ranges are the library's air density's.
            let (t, p) = (TEMPERATURE_RANGE_C, PRESSURE_RANGE_PA);
            let (low, high, range) = match role {
                Role::DriveFactor => (0.0, f64::INFINITY, "at least 0".to_string()),
                Role::Temperature => (
                    t.0,
                    t.1,
                    format!(
                        "{} to {} °C, where the air's density is known (CIPM-2007)",
                        t.0, t.1
                    ),
                ),
                _ => (
                    p.0 / 100.0,
                    p.1 / 100.0,
                    format!("{} to {} hPa", p.0 / 100.0, p.1 / 100.0),
                ),
            };
            let ok = |v: f64| (low..=high).contains(&v);
            if let Some(i) = values.iter().position(|&v| !ok(v)) {
                return Err(flag(table.error_at(
                    i,
                    role,
                    format!("{name} {} out of range ({range})", num(values[i], 6)),
                )));
            }
            columns[k] = Some(values);
        }
        Ok(Self { times, columns })
    }

    /// Column `k` at time `t`, if given.
    fn at(&self, k: usize, t: f64) -> Option<f64> {
        let values = self.columns[k].as_ref()?;
        Some(piecewise_linear(&self.times, values, t))
    }
}

fn clock_error(e: ClockError, given: &str) -> CliError {
    match e {
        ClockError::Stops {
            minimum_factor,
            unlocking_deg,
        } if minimum_factor.is_finite() => CliError::flag(
            "--drive",
            format!(
                "the pendulum stops: drive below {} × {given}; it must carry the swing past {}° to unlock the escapement",
                num(minimum_factor, 4),
                num(unlocking_deg, 4)
            ),
        ),
        ClockError::Stops { unlocking_deg, .. } => CliError::flag(
            "--drive",
            format!(
                "the pendulum stops: at the start there is no drive (its factor is 0) to \
                 carry the swing past {}° and unlock the escapement",
                num(unlocking_deg, 4)
            ),
        ),
        ClockError::OverTheTop => CliError::flag("--drive", e),
        ClockError::Undamped => CliError::flag("--q", e),
        ClockError::Integration(a) => CliError::flag(
            "--drive",
            format!(
                "at a {}° swing the pendulum cannot complete a half swing: the escapement's friction or recoil holds it, or it goes over the top; give less drive",
                num(a.to_degrees(), 4)
            ),
        ),
    }
}

pub fn run(args: &ClockArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let pendulum = common::pendulum_of(args.length.as_deref(), args.design.as_deref(), &gravity)?;
    let mass = match (&args.mass, &args.design) {
        (Some(t), _) => {
            let m = common::quantity("--mass", t, Dimension::Mass)?;
            if m.is_nan() || m <= 0.0 {
                return Err(CliError::flag(
                    "--mass",
                    format!("must be positive, got {t}"),
                ));
            }
            m
        }
        (None, Some(path)) => crate::design::read(path)?.properties().effective_mass(),
        (None, None) => DEFAULT_MASS_KG,
    };
    let scale = mass * gravity.g_m_s2 * pendulum.length_m();
    let q = number("--q", &args.q)?;
    if q.is_nan() || q <= 0.5 {
        return Err(CliError::flag(
            "--q",
            format!("must exceed 0.5 (an underdamped pendulum), got {}", args.q),
        ));
    }
    let lift = common::quantity("--lift-angle", &args.lift_angle, Dimension::Angle)?;
    let angle = common::quantity("--impulse-angle", &args.impulse_angle, Dimension::Angle)?;
    let given = drive(&args.drive)?;
    let spec = Spec {
        kind: match args.escapement {
            EscapementArg::Impulse => Kind::Impulse,
            EscapementArg::Deadbeat => Kind::Deadbeat,
            EscapementArg::Recoil => Kind::Recoil,
            EscapementArg::ConstantForce => Kind::ConstantForce,
            EscapementArg::Free => Kind::Free,
        },
        lift,
        drive: given,
        friction: number("--friction", &args.friction)?,
        recoil: number("--recoil", &args.recoil)?,
        angle,
        every: args.every_beats,
    };
    let escapement = spec.build(scale).map_err(|e| {
        let flag = match e.field {
            "lift_angle" => "--lift-angle",
            "friction" => "--friction",
            "recoil" => "--recoil",
            "impulse_angle" => "--impulse-angle",
            "every_beats" => "--every-beats",
            _ => "--drive",
        };
        CliError::flag(flag, e.message)
    })?;
    let name = escapement.name();
    let clock = Clock {
        pendulum,
        q,
        escapement,
        torque_scale: scale,
    };
    let steady = clock
        .steady(HalfSwingMethod::Direct, 1.0)
        .map_err(|e| clock_error(e, &args.drive))?;

    let isochronism = match &args.drive_range {
        Some(text) => Some(isochronism_curve(&clock, text, args.steps)?),
        None => None,
    };

    let long = match &args.duration {
        Some(text) => Some(run_long(&clock, args, text, &steady)?),
        None => None,
    };

    if let Some(path) = &args.plot {
        let target = Target::new(path, "--plot")?;
        let figure = match (&isochronism, &long) {
            (Some(rows), _) => isochronism_figure(rows, name),
            (None, Some((_, points))) => run_figure(points),
            _ => {
                return Err(CliError::flag(
                    "--plot",
                    "draws the isochronism curve (--drive-range) or a long run (--duration)",
                ))
            }
        };
        render(&target, &figure)?;
    }

    let result = ClockJson {
        escapement: name,
        q,
        length_m: pendulum.length_m(),
        mass_kg: mass,
        lift_angle_rad: lift,
        drive_torque_n_m: match given {
            Drive::Torque(t) => Some(t),
            Drive::Energy(_) => None,
        },
        drive_energy_j: match given {
            Drive::Energy(e) => Some(e),
            Drive::Torque(_) => None,
        },
        minimum_drive_factor: clock.minimum_drive(),
        steady: SteadyJson::of(&steady),
        isochronism,
        long_run: long.map(|(r, _)| r),
    };
    if args.json {
        return output::json(&result);
    }
    Ok(render_text(&result))
}

fn isochronism_curve(clock: &Clock, text: &str, steps: usize) -> Result<Vec<IsoJson>, CliError> {
    let parse = |s: &str| -> Result<f64, CliError> {
        let v = number("--drive-range", s.trim().trim_end_matches(['x', 'X']))?;
        if v.is_nan() || v <= 0.0 {
            return Err(CliError::flag(
                "--drive-range",
                format!("factors must be positive, got {s}"),
            ));
        }
        Ok(v)
    };
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| CliError::flag("--drive-range", "give two factors as 0.5x..2x"))?;
    let (a, b) = (parse(a)?, parse(b)?);
    if a >= b {
        return Err(CliError::flag(
            "--drive-range",
            "the first factor must be the smaller",
        ));
    }
    if !(2..=1000).contains(&steps) {
        return Err(CliError::flag("--steps", "must lie between 2 and 1000"));
    }
    let mut rows = Vec::with_capacity(steps);
    for i in 0..steps {
        // Geometric steps: drive factors span a ratio.
        let f = a * (b / a).powf(i as f64 / (steps - 1) as f64);
        if interrupt::requested() {
            return Err(interrupt::error());
        }
        match clock.steady(HalfSwingMethod::Direct, f) {
            Ok(s) => rows.push(IsoJson {
                drive_factor: f,
                steady: Some(SteadyJson::of(&s)),
                stops: false,
            }),
            Err(ClockError::Stops { .. }) => rows.push(IsoJson {
                drive_factor: f,
                steady: None,
                stops: true,
            }),
            Err(e) => return Err(clock_error(e, "the drive")),
        }
    }
    Ok(rows)
}

/// (time s, amplitude rad, time error s) of a long run, for its plot.
type RunPoints = Vec<(f64, f64, f64)>;

/// Bytes of one row of a long run's file, rounded up.
const BYTES_PER_ROW: f64 = 100.0;

fn run_long(
    clock: &Clock,
    args: &ClockArgs,
    text: &str,
    steady: &Steady,
) -> Result<(RunJson, RunPoints), CliError> {
    let duration = common::quantity("--duration", text, Dimension::Time)?;
    let every = args
        .every
        .as_deref()
        .map(|t| common::quantity("--every", t, Dimension::Time))
        .transpose()?;
    let plan = plan_run(clock, steady.period, duration, every, args.force)
        .map_err(|r| CliError::refused(&r, &[], &|_, reason| CliError::other(reason)))?;
    let rows = plan.rows;
    if let Some(path) = &args.swings {
        crate::work::check_space("--swings", path, rows * BYTES_PER_ROW)?;
    }
    let schedule = match &args.drive_file {
        Some(p) => Some(Schedule::read(p)?),
        None => None,
    };
    let column = |k: usize, t: f64| schedule.as_ref().and_then(|s| s.at(k, t));
    let drive_at = |t: f64| column(0, t).unwrap_or(1.0);
    // Temperature and pressure move the period by the design's
    // coefficients, against their values at the start (where the clock
    // was regulated).
    let weather = schedule
        .as_ref()
        .is_some_and(|s| s.columns[1].is_some() || s.columns[2].is_some());
    let (per_c, per_hpa) =
        match (&args.design, weather) {
            (_, false) => (0.0, 0.0),
            (Some(path), true) => {
                let design = crate::design::read(path)?;
                let (t0, p0) = (
                    column(1, 0.0).unwrap_or(20.0),
                    column(2, 0.0).unwrap_or(1013.25),
                );
                (
                    design.temperature_coefficient(),
                    design.pressure_coefficient(p0 * 100.0, t0, 0.5),
                )
            }
            (None, true) => return Err(CliError::flag(
                "--drive-file",
                "temperature_c and pressure_hpa need --design (the pendulum's own coefficients)",
            )),
        };
    let stretch = |t: f64| {
        let rate = column(1, t).map_or(0.0, |c| per_c * (c - column(1, 0.0).unwrap_or(c)))
            + column(2, t).map_or(0.0, |p| per_hpa * (p - column(2, 0.0).unwrap_or(p)));
        period_factor(rate)
    };
    // Start in the steady state of the drive at the start, regulated to it.
    let start = clock
        .steady(HalfSwingMethod::Averaged, drive_at(0.0))
        .map_err(|e| clock_error(e, &args.drive))?;
    let mut csv = match &args.swings {
        Some(p) => Some(CsvFile::create(
            p,
            "--swings",
            "time_s,beats,amplitude_rad,rate_s_per_day,time_error_s,drive_factor",
        )?),
        None => None,
    };
    let mut points = Vec::new();
    let mut failure: Option<CliError> = None;
    // At most about 20,000 points drawn.
    let expected_rows = duration / every.unwrap_or(0.5 * steady.period);
    let keep_every = (expected_rows as usize / 20_000).max(1);
    let mut count = 0usize;
    let finish = long_run(
        clock,
        &drive_at,
        &stretch,
        &LongRun::from_steady(&start, duration, every),
        &mut |row| {
            if count % keep_every == 0 {
                points.push((row.time, row.amplitude, row.time_error));
            }
            count += 1;
            if let Some(c) = csv.as_mut() {
                c.number(Some(row.time))
                    .integer(row.beats)
                    .number(Some(row.amplitude))
                    .number(Some(row.rate))
                    .number(Some(row.time_error))
                    .number(Some(row.drive));
                if let Err(e) = c.end_row() {
                    failure = Some(e);
                    return false;
                }
            }
            !(count % 4096 == 0 && interrupt::requested())
        },
    );
    if let Some(e) = failure {
        return Err(e);
    }
    if interrupt::requested() {
        return Err(interrupt::error());
    }
    let flag = if args.drive_file.is_some() {
        "--drive-file"
    } else {
        "--drive"
    };
    let when = format!("{} days into the run", num(finish.last.time / 86_400.0, 4));
    // The half swing that failed lies within a row's step of the last row.
    let failed_at = (finish.last.time + every.unwrap_or(steady.period)).min(duration);
    match finish.ending {
        Ending::OverTheTop => {
            return Err(CliError::flag(
                flag,
                format!(
                    "{when} the drive (rising to {} × the given) carries the pendulum over \
                     the top; give less drive",
                    num(drive_at(failed_at).max(finish.last.drive), 4)
                ),
            ))
        }
        Ending::RateOutOfRange => {
            return Err(CliError::flag(
                "--drive-file",
                format!(
                    "{when} the temperature and pressure move the rate by a day per day or \
                     more: no clock runs so; check the file's units"
                ),
            ))
        }
        Ending::Duration | Ending::Sink | Ending::PendulumStopped => {}
    }
    let swings_file = match csv {
        Some(c) => Some(c.commit()?),
        None => None,
    };
    let last = finish.last;
    Ok((
        RunJson {
            duration_s: last.time,
            beats: last.beats,
            final_amplitude_rad: last.amplitude,
            final_rate_s_per_day: last.rate,
            time_error_s: last.time_error,
            stopped: finish.stopped,
            ending: finish.ending.name(),
            half_swings_stepped: finish.single_steps,
            multi_beat_steps: finish.multi_steps,
            swings_file,
        },
        points,
    ))
}

fn isochronism_figure(rows: &[IsoJson], name: &str) -> Figure {
    let pick = |f: &dyn Fn(&SteadyJson) -> f64| -> Vec<(f64, f64)> {
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
    let days = |t: f64| t / 86_400.0;
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

fn render_text(r: &ClockJson) -> String {
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
            format!("{} × the drive", num(r.minimum_drive_factor, 4)),
        );
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
                num(run.duration_s / 86_400.0, 6),
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
                "{}°, {} s/day, {} s {} of true time",
                num(run.final_amplitude_rad.to_degrees(), 5),
                num(run.final_rate_s_per_day, 4),
                num(run.time_error_s.abs(), 5),
                if run.time_error_s >= 0.0 {
                    "ahead"
                } else {
                    "behind"
                }
            ),
        );
        if let Some(f) = &run.swings_file {
            o.row("Written", f.clone());
        }
        text.push('\n');
        text.push_str(&o.render());
    }
    text
}
