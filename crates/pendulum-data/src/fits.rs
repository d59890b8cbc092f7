//! The fits of a measurement file, from its bytes to the JSON both front
//! ends print: a run-down's decay (`fit decay`), a tracked swing's
//! trajectory (`fit trajectory`) and a table of periods (`fit period`).
//! The command line adds what only it does (the files it writes, the
//! plot, the text); the browser page draws the same series.
//!
//! A refusal of the library's analysis is said of the option it concerns
//! by the library's field name (`length_standard_error`; `time` for the
//! file's times as a whole), or of the file's line and column.

use crate::figure::{Figure, Panel, Series, TIME_AXIS};
use crate::measured::{
    declared_degrees, has_track, rebuild_times, track_of, track_roles, Open, PivotJson, Positions,
    Track,
};
use crate::table::{need, read_table, Format, Found, ReadOptions, Role, RATE_ROLES};
use crate::ReadError;
use pendulum_theory::analysis::{Place, Refusal};
use pendulum_theory::error::format_significant as num;
use pendulum_theory::fitting::decay::{swings_to_time, DecayFit, DecayModel};
use pendulum_theory::fitting::frames::longest_run;
use pendulum_theory::fitting::period_table::{self, Against, PeriodTable, PeriodTableInput};
use pendulum_theory::fitting::rundown::{self, RunDown, RunDownInput, RunDownWarning};
use pendulum_theory::fitting::tracked::{self, LengthSource, TimeRebuilt, TrackInput};
use pendulum_theory::fitting::turning::{turning_points, Turns};
use serde::Serialize;

/// Says a refusal of one sample (its array and index) or of the data as a
/// whole (`None`), naming the file and where it can the line.
type SaySample<'a> = dyn Fn(Option<(&'static str, usize)>, &str) -> ReadError + 'a;

/// Says a refusal of the analysis: a field as its option, a sample or the
/// data by `data`.
fn refused(refusal: &Refusal, data: &SaySample<'_>) -> ReadError {
    match refusal.place {
        Place::Field(field) => ReadError::option(field, refusal.reason.clone()),
        Place::Sample(field, i) => data(Some((field, i)), &refusal.reason),
        Place::Data => data(None, &refusal.reason),
    }
}

/// A name the library reads (`parse`), `None` when not given; its
/// refusal is its option's (`--model: 'x' is not one of …`).
fn parsed<T>(
    name: Option<&str>,
    parse: fn(&str) -> Result<Option<T>, Refusal>,
) -> Result<Option<T>, ReadError> {
    match name {
        None => Ok(None),
        Some(name) => {
            parse(name).map_err(|r| refused(&r, &|_, reason| ReadError::other(reason.to_string())))
        }
    }
}

/// What a decay is fitted with, beside the file.
#[derive(Clone, Debug, Default)]
pub struct DecayOptions {
    /// How the file is read.
    pub read: ReadOptions,
    /// How x and y positions become angles.
    pub positions: Positions,
    /// The damping law to fit alone (`viscous`, `dry`, …); all by default.
    pub model: Option<String>,
    /// The period, s (a swing column's times; the library's checks).
    pub period: Option<f64>,
    /// The pendulum's length, m, and g, m/s² (for g's and Q's figures).
    pub length: Option<(f64, f64)>,
    /// The length's standard error, m.
    pub length_standard_error: Option<f64>,
    /// The bob's effective mass, kg (for the damping force).
    pub mass: Option<f64>,
    /// Fit what the checks would refuse.
    pub force: bool,
}

/// What `fit decay --json` prints: the file read, then the analysis.
#[derive(Clone, Debug, Serialize)]
pub struct DecayJson {
    /// The file, as named.
    pub file: String,
    /// What was read.
    pub format: Format,
    /// With a track: the zero of the swing removed from the turning angles.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zero_offset_rad: Option<f64>,
    /// The file the turning points were written to (the command line's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub turning_points_file: Option<String>,
    /// A track's times, written rounded, rebuilt on their frame grid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_rebuilt: Option<TimeRebuilt>,
    /// The analysis.
    #[serde(flatten)]
    pub analysis: RunDown,
}

/// A decay fitted: the JSON, and the series fitted (for figures).
pub struct Decay {
    /// What is printed.
    pub json: DecayJson,
    /// The times of the amplitudes fitted, s.
    pub time: Vec<f64>,
    /// The amplitudes fitted, rad.
    pub amplitude: Vec<f64>,
    /// A track's turning points (none for a table of amplitudes).
    pub turns: Option<Turns>,
}

/// The columns of a decay: a track (angle, or x and y, against time) to
/// find the amplitudes in, else a column of amplitudes. A track wins:
/// Tracker files carry per-frame columns a user may have called "amp".
fn decay_columns(found: &[Found], rate: bool) -> Result<Vec<Role>, String> {
    if has_track(found, rate) {
        track_roles(found, rate)
    } else if found.iter().any(|f| f.role == Role::Amplitude) {
        need(&[&[Role::Time, Role::Swing], &[Role::Amplitude]])(found)
    } else if found.iter().any(|f| RATE_ROLES.contains(&f.role)) {
        Err(
            "no amplitude column, nor a track: a gyroscope's angular velocity is fitted \
             by fit trajectory (its damping laws and Q)"
                .to_string(),
        )
    } else {
        Err(
            "no amplitude column (amplitude_deg, amplitude (rad), …), nor a track \
             (time with angle, or with x and y)"
                .to_string(),
        )
    }
}

/// Fits the decay of the file `open` opens; `started` hears the number
/// of amplitudes about to be fitted (for a progress estimate).
pub fn decay(
    open: &Open<'_>,
    options: &DecayOptions,
    started: &mut dyn FnMut(usize),
) -> Result<Decay, ReadError> {
    let rate = options.read.frame_rate;
    let choose = |found: &[Found]| decay_columns(found, rate.is_some());
    let mut table = read_table(open()?, &options.read, &choose)?;
    if table.column(Role::Amplitude).is_some() {
        crate::measured::note_unused(&mut table, &options.positions, "amplitudes");
    }
    let file = table.file.clone();
    let format = table.format.clone();
    if options.length_standard_error.is_some() && options.length.is_none() {
        return Err(ReadError::option(
            "length_standard_error",
            "is the uncertainty of --length (or of --design's length): give the length too",
        ));
    }
    let input = RunDownInput {
        model: parsed(options.model.as_deref(), rundown::parse_model)?,
        period: options.period,
        length: options.length.map(|l| l.0),
        length_standard_error: options.length_standard_error,
        g: options.length.map(|l| l.1),
        mass: options.mass,
        force: options.force,
        ..RunDownInput::default()
    };
    let angle_unit = options.read.angle_unit;
    if table.column(Role::Amplitude).is_some() {
        // Out of order times named as the file has them (the library sees
        // them less the first).
        table.require_increasing(Role::Time)?;
        let amplitude = table.column(Role::Amplitude).unwrap_or(&[]).to_vec();
        let first = table.values[0].clone();
        // A swing is a half period: with a period each takes half of it;
        // else half the exact period at its amplitude, from the length.
        let pendulum = match options.length {
            Some((l, g)) => Some(
                pendulum_theory::Pendulum::new(l, g)
                    .map_err(|e| ReadError::option("length", e.detail()))?,
            ),
            None => None,
        };
        let time = match (table.roles[0] == Role::Swing, options.period, &pendulum) {
            (false, _, _) => first,
            (true, Some(p), _) => first.iter().map(|s| (s - first[0]) * 0.5 * p).collect(),
            (true, None, Some(p)) => swings_to_time(p, &first, &amplitude),
            (true, None, None) => {
                return Err(ReadError::option(
                    "length",
                    format!(
                        "is needed to turn the swing column of {file} into time (or \
                         --period: a swing is half of it)"
                    ),
                ))
            }
        };
        // g comes from a track's turning times: a table of amplitudes
        // gives none for the length's uncertainty to go in.
        if options.length_standard_error.is_some() {
            return Err(ReadError::option(
                "length_standard_error",
                format!(
                    "goes in g, which {file} (amplitudes, no times of turning points) does not \
                     give: g comes from a track (angle, or x and y, against time)"
                ),
            ));
        }
        let declared = declared_degrees(&table, Role::Amplitude, angle_unit);
        started(time.len());
        let analysis = rundown::analyse(&RunDownInput {
            time: &time,
            amplitude: &amplitude,
            declared_degrees: declared,
            ..input
        })
        .map_err(|r| {
            refused(&r, &|at, reason| match at {
                Some((field, i)) => {
                    let role = if field == "amplitude" {
                        Role::Amplitude
                    } else {
                        table.roles[0]
                    };
                    table.error_at(i, role, reason)
                }
                None => ReadError::other(format!("{file}: {reason}")),
            })
        })?;
        let json = DecayJson {
            file,
            format,
            zero_offset_rad: None,
            turning_points_file: None,
            time_rebuilt: None,
            analysis,
        };
        return Ok(Decay {
            json,
            time,
            amplitude,
            turns: None,
        });
    }
    let declared = declared_degrees(&table, Role::Angle, angle_unit);
    let rebuilt = rebuild_times(open, &options.read, &mut table, &choose)?;
    let track = track_of(table, &options.positions, rate)?;
    decay_of_track(
        track,
        rebuilt.as_ref().map(TimeRebuilt::from),
        declared,
        input,
        started,
    )
}

/// The decay of a swing: its turning points' amplitudes, fitted.
fn decay_of_track(
    track: Track,
    time_rebuilt: Option<TimeRebuilt>,
    declared: bool,
    input: RunDownInput<'_>,
    started: &mut dyn FnMut(usize),
) -> Result<Decay, ReadError> {
    let file = track.table.file.clone();
    // A record in pieces: its longest run (turning points across a gap
    // are no swing's).
    let (kept, others) = longest_run(&track.time);
    let left_out = (!others.is_empty()).then(|| RunDownWarning::SamplesLeftOut {
        kept: [track.time[kept.start], track.time[kept.end - 1]],
        left: others
            .iter()
            .map(|r| [track.time[r.start], track.time[r.end - 1], r.len() as f64])
            .collect(),
    });
    let track_time = track.time[kept.clone()].to_vec();
    let track_angle = track.angle[kept].to_vec();
    let found = turning_points(&track_time, &track_angle);
    if found.turns.len() < 4 {
        // A short table of angles is more likely a list of amplitudes
        // under an angle's name than a track.
        let hint = if track_time.len() < 200 {
            format!(
                " (the file was read as a track of angle against time, {} rows of {}; if \
                 its angles are the amplitudes of successive swings, call that column \
                 amplitude: --columns with amplitude_rad or amplitude_deg in its place)",
                track_time.len(),
                track.table.names.join(", ")
            )
        } else {
            String::new()
        };
        return Err(ReadError::other(format!(
            "{file}: only {} turning points found in the track; a decay needs more \
             swings{hint}",
            found.turns.len()
        )));
    }
    let time: Vec<f64> = found.turns.iter().map(|t| t.time).collect();
    let amplitude: Vec<f64> = found.turns.iter().map(|t| t.amplitude).collect();
    let count = found.half_swings();
    started(time.len());
    let mut analysis = rundown::analyse(&RunDownInput {
        time: &time,
        amplitude: &amplitude,
        turning_half_period: found.half_period(),
        turning_count: Some(&count),
        declared_degrees: declared,
        ..input
    })
    .map_err(|r| {
        refused(&r, &|at, reason| match at {
            Some((_, i)) => ReadError::other(format!(
                "{file}: turning point {} (at {} s): {reason}",
                i + 1,
                num(time[i], 8)
            )),
            None => ReadError::other(format!("{file}: {reason}")),
        })
    })?;
    analysis.warnings.extend(left_out);
    let json = DecayJson {
        file,
        format: track.table.format.clone(),
        zero_offset_rad: Some(found.offset),
        turning_points_file: None,
        time_rebuilt,
        analysis,
    };
    Ok(Decay {
        json,
        time,
        amplitude,
        turns: Some(found),
    })
}

/// What a trajectory is fitted with, beside the file.
#[derive(Clone, Debug, Default)]
pub struct TrajectoryOptions {
    /// How the file is read.
    pub read: ReadOptions,
    /// How x and y positions become angles.
    pub positions: Positions,
    /// The first and last times fitted, s from the record's first sample.
    pub from: Option<f64>,
    /// See `from`.
    pub to: Option<f64>,
    /// The model to fit (`small`, `exact`, …); the library's choice by
    /// default.
    pub model: Option<String>,
    /// The drag law the nonlinear fit tries (a name of the simulation's
    /// list); the library's by default.
    pub drag_law: Option<String>,
    /// The pendulum's length, m, and whether it came from a design.
    pub length: Option<(f64, LengthSource)>,
    /// The length's standard error, m.
    pub length_standard_error: Option<f64>,
    /// Fit what the checks would refuse.
    pub force: bool,
}

/// What `fit trajectory --json` prints: the file read, then the analysis.
#[derive(Clone, Debug, Serialize)]
pub struct TrajectoryJson {
    /// The file, as named.
    pub file: String,
    /// The file the residuals were written to (the command line's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residuals_file: Option<String>,
    /// What was read.
    pub format: Format,
    /// The pivot, when the angles came from x/y positions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pivot: Option<PivotJson>,
    /// The radius of the circle the bob traced (a fitted pivot), file units.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub track_radius: Option<f64>,
    /// Its standard error, carried into g's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub track_radius_standard_error: Option<f64>,
    /// The analysis.
    #[serde(flatten)]
    pub analysis: tracked::Track,
}

/// A trajectory fitted: the JSON, and the values fitted (the angle, or a
/// gyroscope's rate about the swing's axis) at the analysis's times.
pub struct Trajectory {
    /// What is printed.
    pub json: TrajectoryJson,
    /// The values fitted, rad or rad/s, one per `json.analysis.time`.
    pub values: Vec<f64>,
    /// Whether they are angular velocities (rad/s).
    pub rate: bool,
}

/// Fits the trajectory of the file `open` opens; `started` hears the
/// number of samples about to be fitted.
pub fn trajectory(
    open: &Open<'_>,
    options: &TrajectoryOptions,
    started: &mut dyn FnMut(usize),
) -> Result<Trajectory, ReadError> {
    if options.length_standard_error.is_some() && options.length.is_none() {
        return Err(ReadError::option(
            "length_standard_error",
            "is the uncertainty of --length (or of --design's length): give the length too",
        ));
    }
    let track = crate::measured::read_track(open, &options.read, &options.positions)?
        .window(options.from, options.to)?;
    // Without a length, a fitted pivot's radius is the length (in the
    // file's units, which Tracker calibrates to metres).
    let length = match (options.length, track.track_radius) {
        (Some(l), _) => Some(l),
        (None, Some(r)) => Some((r, LengthSource::TrackRadius)),
        (None, None) => None,
    };
    let rate = !track.angular_velocity.is_empty();
    let axes: Vec<&[f64]> = track.angular_velocity.iter().map(Vec::as_slice).collect();
    let file = track.table.file.clone();
    started(track.time.len());
    let mut analysis = tracked::analyse(&TrackInput {
        time: &track.time,
        angle: &track.angle,
        angular_velocity: &axes,
        model: parsed(options.model.as_deref(), tracked::parse_model)?,
        drag_law: parsed(options.drag_law.as_deref(), tracked::parse_drag_law)?,
        length,
        length_standard_error: match options.length {
            Some(_) => options.length_standard_error,
            None => track.track_radius_error,
        },
        force: options.force,
        angle_from_positions: track.pivot.is_some(),
        declared_degrees: declared_degrees(&track.table, Role::Angle, options.read.angle_unit),
    })
    .map_err(|r| {
        refused(&r, &|at, reason| match at {
            Some((_, i)) => ReadError::other(format!("{file}: sample {}: {reason}", i + 1)),
            None => ReadError::other(format!("{file}: {reason}")),
        })
    })?;
    if analysis.time_rebuilt.is_none() {
        analysis.time_rebuilt = track.time_rebuilt.as_ref().map(TimeRebuilt::from);
    }
    // The samples fitted: after a gap, from the run fitted on; a
    // gyroscope's rate about the swing's axis.
    let rows = analysis.first_row..analysis.first_row + analysis.time.len();
    let values: Vec<f64> = match &analysis.gyroscope_axis {
        Some(d) => rows
            .map(|i| axes.iter().zip(d).map(|(a, c)| a[i] * c).sum())
            .collect(),
        None => track.angle[rows].to_vec(),
    };
    let json = TrajectoryJson {
        file,
        residuals_file: None,
        format: track.table.format.clone(),
        pivot: track.pivot.clone(),
        track_radius: track.track_radius,
        track_radius_standard_error: track.track_radius_error,
        analysis,
    };
    Ok(Trajectory { json, values, rate })
}

/// What a table of periods is fitted with, beside the file.
#[derive(Clone, Debug, Default)]
pub struct PeriodOptions {
    /// How the file is read (its times are periods, not times from a
    /// start: kept as written).
    pub read: ReadOptions,
    /// The pendulum's length, m (periods against amplitude: g).
    pub pendulum_length: Option<f64>,
    /// Its standard error, m.
    pub pendulum_length_standard_error: Option<f64>,
    /// The bob's radius, m (periods against length: the physical
    /// pendulum's correction).
    pub bob_radius: Option<f64>,
}

/// What `fit period --json` prints: the file read, then the analysis.
#[derive(Clone, Debug, Serialize)]
pub struct PeriodJson {
    /// The file, as named.
    pub file: String,
    /// What was read.
    pub format: Format,
    /// The analysis.
    #[serde(flatten)]
    pub analysis: PeriodTable,
}

/// A table of periods fitted: the JSON, and the columns fitted.
pub struct Periods {
    /// What is printed.
    pub json: PeriodJson,
    /// The periods, s.
    pub period: Vec<f64>,
    /// Their amplitudes, rad, when the table has them.
    pub amplitude: Option<Vec<f64>>,
}

/// The columns of a period table: the period (a column named for it, or a
/// time column), then what is there of its uncertainty, the amplitude (or
/// an angle) and the length.
fn period_columns(found: &[Found]) -> Result<Vec<Role>, String> {
    let has = |r: Role| found.iter().any(|f| f.role == r);
    let period = if has(Role::Period) {
        Role::Period
    } else if has(Role::Time) {
        Role::Time
    } else {
        return Err("no period column (period_s, T (s), …)".to_string());
    };
    let mut roles = vec![period];
    if has(Role::PeriodError) {
        roles.push(Role::PeriodError);
    }
    if has(Role::Amplitude) {
        roles.push(Role::Amplitude);
    } else if has(Role::Angle) {
        roles.push(Role::Angle);
    }
    if has(Role::Length) {
        roles.push(Role::Length);
    }
    if roles.len() == 1 || roles == [period, Role::PeriodError] {
        return Err(
            "no amplitude or length column to fit the periods against (amplitude_deg, \
             length_m, …)"
                .to_string(),
        );
    }
    Ok(roles)
}

/// Fits the table of periods of the file `open` opens.
pub fn periods(open: &Open<'_>, options: &PeriodOptions) -> Result<Periods, ReadError> {
    let read = ReadOptions {
        absolute_time: true,
        ..options.read.clone()
    };
    let table = read_table(open()?, &read, &period_columns)?;
    let file = table.file.clone();
    let period = table.values[0].clone();
    let amplitude = table
        .column(Role::Amplitude)
        .or_else(|| table.column(Role::Angle))
        .map(|a| a.iter().map(|v| v.abs()).collect::<Vec<f64>>());
    let analysis = period_table::analyse(&PeriodTableInput {
        period: &period,
        period_standard_error: table.column(Role::PeriodError),
        amplitude: amplitude.as_deref(),
        length: table.column(Role::Length),
        pendulum_length: options.pendulum_length,
        pendulum_length_standard_error: options.pendulum_length_standard_error,
        bob_radius: options.bob_radius,
        force: false,
    })
    .map_err(|r| {
        refused(&r, &|at, reason| match at {
            Some((field, i)) => {
                let role = match field {
                    "period_standard_error" => Role::PeriodError,
                    "amplitude" if table.column(Role::Amplitude).is_some() => Role::Amplitude,
                    "amplitude" => Role::Angle,
                    "length" => Role::Length,
                    _ => table.roles[0],
                };
                table.error_at(i, role, reason)
            }
            None => ReadError::other(format!("{file}: {reason}")),
        })
    })?;
    let json = PeriodJson {
        file,
        format: table.format.clone(),
        analysis,
    };
    Ok(Periods {
        json,
        period,
        amplitude,
    })
}

impl Decay {
    /// The amplitudes over the fitted laws (the preferred one wide), and
    /// the preferred law's residuals.
    pub fn figure(&self) -> Figure {
        let analysis = &self.json.analysis;
        let best = analysis
            .fits
            .iter()
            .find(|f| Some(f.model.name()) == analysis.preferred);
        decay_figure(
            &self.time,
            &self.amplitude,
            &analysis.fits,
            best.map(|f| f.model),
        )
    }
}

impl Trajectory {
    /// The values fitted over the fitted motion, and the residuals.
    pub fn figure(&self) -> Figure {
        let a = &self.json.analysis;
        trajectory_figure(&a.time, &self.values, &a.residuals, self.rate)
    }
}

impl Periods {
    /// The periods over the fitted law, and the residuals.
    pub fn figure(&self) -> Figure {
        periods_figure(&self.json.analysis, &self.period, self.amplitude.as_deref())
    }
}

/// How many rival laws the decay figure draws beside the preferred one:
/// more hide it (all are in the JSON and the text's table).
const RIVALS_DRAWN: usize = 2;

/// The data with the preferred law and its closest rivals (by BIC, each
/// labelled with how much worse it fits), and the preferred law's
/// residuals.
fn decay_figure(
    time: &[f64],
    amplitude: &[f64],
    fits: &[DecayFit],
    best: Option<DecayModel>,
) -> Figure {
    let data: Vec<(f64, f64)> = time
        .iter()
        .zip(amplitude)
        .map(|(t, a)| (*t, a.to_degrees()))
        .collect();
    let (t0, t1) = (time[0], time[time.len() - 1]);
    let curve_of = |f: &DecayFit| -> Vec<(f64, f64)> {
        (0..=300)
            .map(|i| {
                let t = t0 + (t1 - t0) * f64::from(i) / 300.0;
                (t, f.model.amplitude(t, &f.fit.parameters).to_degrees())
            })
            // A law whose amplitude reaches zero has stopped the
            // pendulum: its curve ends there.
            .filter(|p: &(f64, f64)| p.1 >= 0.0)
            .collect()
    };
    let preferred = fits.iter().find(|f| Some(f.model) == best);
    let mut rivals: Vec<&DecayFit> = fits.iter().filter(|f| Some(f.model) != best).collect();
    rivals.sort_by(|a, b| a.fit.bic.total_cmp(&b.fit.bic));
    let mut curves = vec![Series::dots("measured", data)];
    // The preferred law wide, the rivals thin over it in their own colours
    // (dashed where they run along it): each stays visible.
    if let Some(f) = preferred {
        curves.push(Series::line(format!("{} (preferred)", f.model.name()), curve_of(f)).strong());
    }
    for f in rivals.iter().take(RIVALS_DRAWN) {
        let label = match preferred.map(|p| f.fit.bic - p.fit.bic) {
            Some(worse) if worse.is_finite() => format!("{} (BIC +{worse:.1})", f.model.name()),
            _ => f.model.name().to_string(),
        };
        curves.push(Series::line(label, curve_of(f)).light());
    }
    let mut panels = vec![Panel::new(
        "Amplitude decay and the fitted laws",
        TIME_AXIS,
        "amplitude (°)",
        curves,
    )
    .log_y_beyond(1.5)];
    if let Some(f) = fits.iter().find(|f| Some(f.model) == best) {
        let residuals = time
            .iter()
            .zip(&f.fit.residuals)
            .map(|(t, r)| (*t, r.to_degrees()))
            .collect();
        panels.push(Panel::new(
            format!("Residuals of the preferred law ({})", f.model.name()),
            TIME_AXIS,
            "measured − fitted (°)",
            vec![Series::dots("residual", residuals)],
        ));
    }
    Figure { panels }
}

/// The tracked angle (or angular velocity) with the fitted curve (the
/// data less the residuals), and the residuals.
fn trajectory_figure(time: &[f64], theta: &[f64], residuals: &[f64], rate: bool) -> Figure {
    let (title, unit, residual_unit) = if rate {
        (
            "Angular velocity and the fitted motion's",
            "angular velocity (°/s)",
            "measured − fitted (°/s)",
        )
    } else {
        (
            "Tracked angle and the fitted motion",
            "angle (°)",
            "measured − fitted (°)",
        )
    };
    let deg = |v: f64| v.to_degrees();
    let data: Vec<(f64, f64)> = time.iter().zip(theta).map(|(t, y)| (*t, deg(*y))).collect();
    let fitted: Vec<(f64, f64)> = time
        .iter()
        .zip(theta.iter().zip(residuals))
        .map(|(t, (y, r))| (*t, deg(y - r)))
        .collect();
    let res = time
        .iter()
        .zip(residuals)
        .map(|(t, r)| (*t, deg(*r)))
        .collect();
    let motion = |name: &str, from: f64, to: f64| {
        let within = |p: &&(f64, f64)| p.0 >= from && p.0 <= to;
        Panel::new(
            name,
            TIME_AXIS,
            unit,
            vec![
                Series::dots("measured", data.iter().filter(within).copied().collect()),
                Series::line("fitted", fitted.iter().filter(within).copied().collect()),
            ],
        )
    };
    // A long record's swings drawn whole are a band of points over the
    // curve: its first and last swings are drawn instead, where the fit
    // can be seen against them.
    let mut panels = match swing_period(&fitted) {
        Some(period) if time[time.len() - 1] - time[0] > SWINGS_SHOWN * period * 3.0 => {
            let (t0, t1) = (time[0], time[time.len() - 1]);
            let span = SWINGS_SHOWN * period;
            vec![
                motion(&format!("{title}: the first swings"), t0, t0 + span),
                motion(&format!("{title}: the last swings"), t1 - span, t1),
            ]
        }
        _ => vec![motion(title, f64::NEG_INFINITY, f64::INFINITY)],
    };
    panels.push(Panel::new(
        "Residuals",
        TIME_AXIS,
        residual_unit,
        vec![Series::dots("residual", res)],
    ));
    Figure { panels }
}

/// How many periods of a long record's start and end the trajectory
/// figure draws.
const SWINGS_SHOWN: f64 = 3.0;

/// The period of a fitted motion from its upward crossings of its mean
/// (none with fewer than three crossings).
fn swing_period(curve: &[(f64, f64)]) -> Option<f64> {
    let mean = curve.iter().map(|p| p.1).sum::<f64>() / curve.len() as f64;
    let ups: Vec<f64> = curve
        .windows(2)
        .filter(|w| w[0].1 < mean && w[1].1 >= mean)
        .map(|w| w[1].0)
        .collect();
    (ups.len() >= 3).then(|| (ups[ups.len() - 1] - ups[0]) / (ups.len() - 1) as f64)
}

/// The periods measured, as points, above the fitted law.
fn periods_figure(a: &PeriodTable, period: &[f64], amplitude: Option<&[f64]>) -> Figure {
    let (x, label): (Vec<f64>, &str) = match (a.against, amplitude) {
        (Against::Length, _) => (a.equivalent_length.clone(), "length (m)"),
        (_, Some(amp)) => (
            amp.iter().map(|v| v.to_degrees()).collect(),
            "amplitude (°)",
        ),
        (_, None) => ((1..=period.len()).map(|i| i as f64).collect(), "row"),
    };
    let mut order: Vec<usize> = (0..x.len()).collect();
    order.sort_by(|&i, &j| x[i].total_cmp(&x[j]));
    let data = order.iter().map(|&i| (x[i], period[i])).collect();
    let fitted = order.iter().map(|&i| (x[i], a.fitted_period[i])).collect();
    let residuals = order
        .iter()
        .map(|&i| (x[i], (period[i] - a.fitted_period[i]) * 1e3))
        .collect();
    let law = match a.against {
        Against::Length => "fitted: T² = 4π² (L + offset) / g",
        Against::Amplitude => "fitted: the exact law, T₀ · 2K(sin²(A/2))/π",
        Against::Repeats => "fitted: their mean",
    };
    Figure {
        panels: vec![
            Panel::new(
                "Measured periods and the fitted law",
                label,
                "period (s)",
                vec![Series::dots("measured", data), Series::line(law, fitted)],
            ),
            Panel::new(
                "Residuals",
                label,
                "measured − fitted (ms)",
                vec![Series::dots("residual", residuals)],
            ),
        ],
    }
}
