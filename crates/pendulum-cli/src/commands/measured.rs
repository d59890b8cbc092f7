//! What the `fit` commands share about their files: the reading options
//! from the command line, and a tracked swing (angle against time) read
//! from an angle column or from x/y positions about a pivot.

use crate::args::MeasurementArgs;
use crate::data::{read_table, AngleUnit, Found, ReadOptions, Role, Table, RATE_ROLES};
use crate::error::CliError;
use crate::units::parse_number;
use pendulum_theory::fitting::frames::{frame_grid, longest_run, FrameGrid};
use pendulum_theory::fitting::track::{angle_about, fit_circle};
use serde::Serialize;
use std::path::Path;

/// The reading options given on the command line.
pub fn read_options(args: &MeasurementArgs) -> Result<ReadOptions, CliError> {
    Ok(ReadOptions {
        angle_unit: angle_unit(args.angle_unit.as_deref()),
        columns: columns(args.columns.as_deref()),
        frame_rate: frame_rate(args.frame_rate)?,
        absolute_time: false,
        run: run(args.run)?,
        tick_rate: None,
        no_columns_flag: false,
        refuse_blank: false,
    })
}

/// `--angle-unit deg|rad` (clap has checked the value).
pub fn angle_unit(unit: Option<&str>) -> Option<AngleUnit> {
    unit.map(|u| match u {
        "rad" => AngleUnit::Radians,
        _ => AngleUnit::Degrees,
    })
}

/// `--run N`: at least 1.
pub fn run(n: Option<u64>) -> Result<Option<usize>, CliError> {
    match n {
        Some(0) => Err(CliError::flag(
            "--run",
            "must be at least 1 (the first run), got 0",
        )),
        n => Ok(n.map(|n| usize::try_from(n).unwrap_or(usize::MAX))),
    }
}

/// `--columns a,b,c` as names.
pub fn columns(text: Option<&str>) -> Option<Vec<String>> {
    text.map(|t| t.split(',').map(|c| c.trim().to_string()).collect())
}

fn frame_rate(fps: Option<crate::units::Hertz>) -> Result<Option<f64>, CliError> {
    fps.map(|f| {
        pendulum_theory::fitting::track::frame_rate(f.0)
            .map_err(|e| CliError::flag("--frame-rate", e.reason))
    })
    .transpose()
}

/// Whether the column of `role` was read as degrees: its header names
/// degrees (`amplitude_deg`, `θ (°)`), or names no angle unit and
/// `--angle-unit deg` was given.
pub fn declared_degrees(table: &Table, role: Role, angle_unit: Option<&str>) -> bool {
    let Some(i) = table.roles.iter().position(|&r| r == role) else {
        return false;
    };
    let header = table.names[i].to_lowercase();
    if header.contains("rad") {
        false
    } else if header.contains("deg") || header.contains('°') {
        true
    } else {
        angle_unit == Some("deg")
    }
}

/// Where the pivot of tracked positions came from, for the JSON output.
#[derive(Clone, Debug, Serialize)]
pub struct PivotJson {
    /// Horizontal position, file units.
    pub x: f64,
    /// Vertical position, file units.
    pub y: f64,
    /// `given`, `default` (0,0) or `fit`.
    pub source: &'static str,
}

/// A swing read from a file: times (s, from the first row) and angles (rad).
pub struct Track {
    /// What was read.
    pub table: Table,
    /// Times, s.
    pub time: Vec<f64>,
    /// Angles, rad (empty for a gyroscope's record).
    pub angle: Vec<f64>,
    /// A gyroscope's angular velocities, rad/s, one vector per axis read
    /// (empty for angles).
    pub angular_velocity: Vec<Vec<f64>>,
    /// The pivot, when the angles came from positions.
    pub pivot: Option<PivotJson>,
    /// The radius of the circle the bob traced (`--pivot fit`), file units.
    pub track_radius: Option<f64>,
    /// Its standard error.
    pub track_radius_error: Option<f64>,
    /// The times, written rounded, rebuilt on their frame grid.
    pub time_rebuilt: Option<FrameGrid>,
}

/// Whether the header holds a swing: time (or `rate`, a fixed sampling
/// rate given) with an angle, or with x and y.
pub fn has_track(found: &[Found], rate: bool) -> bool {
    let has = |r: Role| found.iter().any(|f| f.role == r);
    (has(Role::Time) || rate) && (has(Role::Angle) || has(Role::X) && has(Role::Y))
}

/// The roles of a swing: time and angle, or time, x and y; with `rate`
/// (a fixed sampling rate given) the time may be absent, made from the row
/// numbers.
pub fn track_roles(found: &[Found], rate: bool) -> Result<Vec<Role>, String> {
    let has = |r: Role| found.iter().any(|f| f.role == r);
    let time = has(Role::Time);
    if !time && !rate {
        return Err(
            "no time column. If a column holds the times under another name (a plot's x and \
             y are often time and angle), name the columns with --columns (e.g. --columns \
             time_s,angle_deg); for a logger that writes no times, give its rate with \
             --sample-rate HZ"
                .into(),
        );
    }
    let mut roles = if time { vec![Role::Time] } else { Vec::new() };
    if has(Role::Angle) {
        roles.push(Role::Angle);
        Ok(roles)
    } else if has(Role::X) && has(Role::Y) {
        roles.extend([Role::X, Role::Y]);
        Ok(roles)
    } else if RATE_ROLES.iter().any(|&r| has(r)) {
        Err(
            "no angle column (angle, theta, θ), nor x and y positions; a gyroscope's angular \
             velocity is fitted by fit trajectory"
                .into(),
        )
    } else {
        Err("no angle column (angle, theta, θ), nor x and y positions".into())
    }
}

/// The roles of a swing `fit trajectory` reads: [`track_roles`], or time
/// with a gyroscope's angular velocities (every axis the header has, to
/// choose the one the swing turns about once read).
pub fn trajectory_roles(found: &[Found], rate: bool) -> Result<Vec<Role>, String> {
    let has = |r: Role| found.iter().any(|f| f.role == r);
    let angles = has(Role::Angle) || has(Role::X) && has(Role::Y);
    let rates: Vec<Role> = RATE_ROLES.iter().copied().filter(|&r| has(r)).collect();
    if angles || rates.is_empty() {
        return track_roles(found, rate);
    }
    if !has(Role::Time) && !rate {
        // Its sentence: no time column, and how to give the rate.
        return track_roles(found, rate);
    }
    let mut roles = if has(Role::Time) {
        vec![Role::Time]
    } else {
        Vec::new()
    };
    roles.extend(rates);
    Ok(roles)
}

/// Reads a swing from `path`: angles, positions, or a gyroscope's
/// angular velocities.
pub fn read_track(path: &Path, args: &MeasurementArgs) -> Result<Track, CliError> {
    let options = read_options(args)?;
    let rate = options.frame_rate;
    let choose = |found: &[Found]| trajectory_roles(found, rate.is_some());
    let mut table = read_table(path, &options, &choose)?;
    let grid = rebuild_times(path, &options, &mut table, &choose)?;
    let mut track = track_of(table, &Positions::of(args)?, rate)?;
    track.time_rebuilt = grid;
    Ok(track)
}

/// Times written rounded, rebuilt on the frame grid they came from
/// ([`pendulum_theory::fitting::frames`]), in place in `table`: from the
/// times as written (the reader spreads a stamp shared by several rows
/// over the interval to the next, which shifts whole stretches of a
/// video's frames: those are read again as written). Nothing with
/// `--frame-rate` (the times are made from it), with `--run`, or when the
/// times are no rounded grid.
pub fn rebuild_times(
    path: &Path,
    options: &ReadOptions,
    table: &mut Table,
    choose: &crate::data::Choose<'_>,
) -> Result<Option<FrameGrid>, CliError> {
    let Some(k) = table.roles.iter().position(|&r| r == Role::Time) else {
        return Ok(None);
    };
    if options.frame_rate.is_some() || table.format.run.is_some() {
        return Ok(None);
    }
    let written: Vec<f64> = if table.format.readings_per_time.is_some() {
        let again = ReadOptions {
            absolute_time: true,
            ..options.clone()
        };
        let raw = read_table(path, &again, choose)?;
        match raw.column(Role::Time) {
            Some(t) if t.len() == table.values[k].len() => t.to_vec(),
            _ => return Ok(None),
        }
    } else {
        let origin = table.format.time_origin_s.unwrap_or(0.0);
        table.values[k].iter().map(|t| t + origin).collect()
    };
    let Some(grid) = frame_grid(&written) else {
        return Ok(None);
    };
    let start = grid.time[0];
    table.values[k] = grid.time.iter().map(|t| t - start).collect();
    table.format.readings_per_time = None;
    Ok(Some(grid))
}

/// A gyroscope's axes as read, with their header names: the library
/// finds the one the swing turns about. (A magnitude column, phyphox's
/// `Absolute`, would double the frequency, and is never read.)
fn gyroscope_axes(table: &Table) -> (Vec<Vec<f64>>, Vec<String>) {
    RATE_ROLES
        .iter()
        .filter_map(|&r| {
            let i = table.roles.iter().position(|&x| x == r)?;
            Some((table.values[i].clone(), table.names[i].clone()))
        })
        .unzip()
}

impl Track {
    /// The samples from `from` to `to` (s from the record's first sample,
    /// either open), for `--from` and `--to`; the window is noted in the
    /// format.
    pub fn window(mut self, from: Option<f64>, to: Option<f64>) -> Result<Track, CliError> {
        if from.is_none() && to.is_none() {
            return Ok(self);
        }
        for (flag, v) in [("--from", from), ("--to", to)] {
            if v.is_some_and(|v| !v.is_finite()) {
                return Err(CliError::flag(flag, "must be a finite time"));
            }
        }
        let (lo, hi) = (
            from.unwrap_or(f64::NEG_INFINITY),
            to.unwrap_or(f64::INFINITY),
        );
        if lo >= hi {
            return Err(CliError::flag(
                "--to",
                format!("must be after --from ({lo} s), got {hi} s"),
            ));
        }
        let keep: Vec<bool> = self.time.iter().map(|t| (lo..=hi).contains(t)).collect();
        let kept = keep.iter().filter(|&&k| k).count();
        if kept == 0 {
            let last = self.time.last().copied().unwrap_or(0.0);
            // The window as given (an open end is not a number to print).
            let window = match (from, to) {
                (Some(a), Some(b)) => format!(
                    "between {} s and {} s",
                    crate::output::num(a, 6),
                    crate::output::num(b, 6)
                ),
                (Some(a), None) => format!("from {} s on", crate::output::num(a, 6)),
                (None, Some(b)) => format!("up to {} s", crate::output::num(b, 6)),
                (None, None) => String::new(),
            };
            return Err(CliError::flag(
                if from.is_some() { "--from" } else { "--to" },
                format!(
                    "no sample lies {window} (the record runs from 0 to {} s)",
                    crate::output::num(last, 6)
                ),
            ));
        }
        let pick = |v: &[f64]| -> Vec<f64> {
            v.iter()
                .zip(&keep)
                .filter(|(_, &k)| k)
                .map(|(x, _)| *x)
                .collect()
        };
        self.time = pick(&self.time);
        if !self.angle.is_empty() {
            self.angle = pick(&self.angle);
        }
        self.angular_velocity = self.angular_velocity.iter().map(|a| pick(a)).collect();
        self.table.format.window_s = Some([
            self.time.first().copied().unwrap_or(0.0),
            self.time.last().copied().unwrap_or(0.0),
        ]);
        Ok(self)
    }
}

/// How x and y positions become angles: the pivot, the direction of y,
/// and the metres a unit of the file is.
#[derive(Clone, Debug, Default)]
pub struct Positions<'a> {
    /// `--pivot`: X,Y, `fit`, or none (0,0).
    pub pivot: Option<&'a str>,
    /// `--y-down`: image coordinates.
    pub y_down: bool,
    /// `--scale`: metres per file unit.
    pub scale: Option<f64>,
}

impl<'a> Positions<'a> {
    /// The flags given.
    pub fn of(args: &'a MeasurementArgs) -> Result<Self, CliError> {
        let scale = match args.scale {
            Some(s) if !(s.0 > 0.0 && s.0.is_finite()) => {
                return Err(CliError::flag(
                    "--scale",
                    format!("must be positive, got {} m", s.0),
                ))
            }
            s => s.map(|s| s.0),
        };
        Ok(Self {
            pivot: args.pivot.as_deref(),
            y_down: args.y_down,
            scale,
        })
    }
}

/// The swing of a table read with [`track_roles`]; without a time column
/// the times are the row numbers over `rate` (samples a second).
pub fn track_of(
    table: Table,
    positions: &Positions<'_>,
    rate: Option<f64>,
) -> Result<Track, CliError> {
    table.require_increasing(Role::Time)?;
    let time = match (table.column(Role::Time), rate) {
        (Some(t), _) => t.to_vec(),
        (None, Some(rate)) => {
            let rows = table.values.first().map_or(0, Vec::len);
            (0..rows).map(|i| i as f64 / rate).collect()
        }
        (None, None) => Vec::new(),
    };
    if table.column(Role::Angle).is_none() {
        let (rates, names) = gyroscope_axes(&table);
        if !rates.is_empty() {
            let mut table = table;
            table.format.angular_velocity_columns = names;
            return Ok(Track {
                table,
                time,
                angle: Vec::new(),
                angular_velocity: rates,
                pivot: None,
                track_radius: None,
                track_radius_error: None,
                time_rebuilt: None,
            });
        }
    }
    if let Some(angle) = table.column(Role::Angle) {
        let angle = angle.to_vec();
        return Ok(Track {
            table,
            time,
            angle,
            angular_velocity: Vec::new(),
            pivot: None,
            track_radius: None,
            track_radius_error: None,
            time_rebuilt: None,
        });
    }
    let x = table.column(Role::X).unwrap_or(&[]);
    let flip = if positions.y_down { -1.0 } else { 1.0 };
    let y: Vec<f64> = table
        .column(Role::Y)
        .unwrap_or(&[])
        .iter()
        .map(|v| flip * v)
        .collect();
    let y = y.as_slice();
    let (mut pivot, radius) = match positions.pivot.map(str::trim) {
        Some("fit") => {
            // The arc of the record's longest run: marks after a tracking
            // gap (a stray point elsewhere in the picture) are no part of
            // it, and the fits leave them out too.
            let run = match table.column(Role::Time) {
                Some(t) if t.len() == x.len() && t.len() == y.len() => longest_run(t).0,
                _ => 0..x.len().min(y.len()),
            };
            let circle = fit_circle(&x[run.clone()], &y[run]).map_err(|e| {
                CliError::flag(
                    "--pivot",
                    format!("no circle fits the positions of {}: {e}", table.file),
                )
            })?;
            (
                PivotJson {
                    x: circle.centre_x,
                    y: circle.centre_y,
                    source: "fit",
                },
                Some((circle.radius, circle.radius_standard_error)),
            )
        }
        Some(text) => {
            let parts: Vec<&str> = text.split(',').collect();
            let bad = || {
                CliError::flag(
                    "--pivot",
                    format!("give X,Y in the file's units (e.g. 0,0) or 'fit', got '{text}'"),
                )
            };
            if parts.len() != 2 {
                return Err(bad());
            }
            let px = parse_number(parts[0]).map_err(|_| bad())?;
            let py = flip * parse_number(parts[1]).map_err(|_| bad())?;
            (
                PivotJson {
                    x: px,
                    y: py,
                    source: "given",
                },
                None,
            )
        }
        None => (
            PivotJson {
                x: 0.0,
                y: 0.0,
                source: "default",
            },
            None,
        ),
    };
    let angle: Vec<f64> = x
        .iter()
        .zip(y)
        .map(|(&xi, &yi)| angle_about(xi, yi, pivot.x, pivot.y))
        .collect();
    // A bob above its pivot means the pivot is wrong, or y points down:
    // the advice names what was not tried.
    if let Some(i) = angle
        .iter()
        .position(|a| a.abs() >= std::f64::consts::FRAC_PI_2)
    {
        let image = !positions.y_down && pivot.source == "fit" && y.iter().all(|&yi| yi > pivot.y);
        let advice = if image {
            "the bob hangs above the centre of the circle it traces: the positions look like \
             image coordinates, y growing downward; give --y-down"
                .to_string()
        } else {
            let mut ways = Vec::new();
            if pivot.source != "given" {
                ways.push("give the pivot with --pivot X,Y");
            }
            if pivot.source != "fit" {
                ways.push("give --pivot fit to find it");
            }
            if !positions.y_down {
                ways.push("give --y-down if y grows downward (image coordinates)");
            }
            ways.join(", or ")
        };
        return Err(table.error_at(
            i,
            Role::Y,
            format!(
                "the bob is level with or above the pivot ({}, {}): {advice}",
                crate::output::num(pivot.x, 9),
                crate::output::num(flip * pivot.y, 9)
            ),
        ));
    }
    // Back in the file's coordinates for the JSON.
    pivot.y *= flip;
    let radius = radius.map(|(r, e)| match positions.scale {
        Some(s) => (r * s, e * s),
        None => (r, e),
    });
    Ok(Track {
        table,
        time,
        angle,
        angular_velocity: Vec::new(),
        pivot: Some(pivot),
        track_radius: radius.map(|r| r.0),
        track_radius_error: radius.map(|r| r.1),
        time_rebuilt: None,
    })
}
