//! A swing read from a file: angle against time, from an angle column,
//! from x and y positions about a pivot (given or fitted), or a
//! gyroscope's angular velocities; times written rounded rebuilt on their
//! frame grid; a window of it. What the decay and trajectory fits of both
//! front ends read.

use crate::table::{read_table, AngleUnit, Choose, Found, ReadOptions, Role, Table, RATE_ROLES};
use crate::{ReadError, Source};
use pendulum_theory::error::format_significant as num;
use pendulum_theory::fitting::frames::{frame_grid, longest_run, FrameGrid};
use pendulum_theory::fitting::track::{angle_about, fit_circle};
use serde::Serialize;

/// Opens the file again (a reading with other options: the times as
/// written).
pub type Open<'a> = dyn Fn() -> Result<Source<'static>, ReadError> + 'a;

/// Whether the column of `role` was read as degrees: its header names
/// degrees (`amplitude_deg`, `θ (°)`), or names no angle unit and
/// `--angle-unit deg` was given.
pub fn declared_degrees(table: &Table, role: Role, angle_unit: Option<AngleUnit>) -> bool {
    let Some(i) = table.roles.iter().position(|&r| r == role) else {
        return false;
    };
    let header = table.names[i].to_lowercase();
    if header.contains("rad") {
        false
    } else if header.contains("deg") || header.contains('°') {
        true
    } else {
        angle_unit == Some(AngleUnit::Degrees)
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

/// Reads a swing from the file `open` opens: angles, positions, or a
/// gyroscope's angular velocities.
pub fn read_track(
    open: &Open<'_>,
    options: &ReadOptions,
    positions: &Positions,
) -> Result<Track, ReadError> {
    let rate = options.frame_rate;
    let choose = |found: &[Found]| trajectory_roles(found, rate.is_some());
    let mut table = read_table(open()?, options, &choose)?;
    let grid = rebuild_times(open, options, &mut table, &choose)?;
    let mut track = track_of(table, positions, rate)?;
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
    open: &Open<'_>,
    options: &ReadOptions,
    table: &mut Table,
    choose: &Choose<'_>,
) -> Result<Option<FrameGrid>, ReadError> {
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
        let raw = read_table(open()?, &again, choose)?;
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
    pub fn window(mut self, from: Option<f64>, to: Option<f64>) -> Result<Track, ReadError> {
        if from.is_none() && to.is_none() {
            return Ok(self);
        }
        for (option, v) in [("from", from), ("to", to)] {
            if v.is_some_and(|v| !v.is_finite()) {
                return Err(ReadError::option(option, "must be a finite time"));
            }
        }
        let (lo, hi) = (
            from.unwrap_or(f64::NEG_INFINITY),
            to.unwrap_or(f64::INFINITY),
        );
        if lo >= hi {
            return Err(ReadError::option(
                "to",
                format!("must be after --from ({lo} s), got {hi} s"),
            ));
        }
        let keep: Vec<bool> = self.time.iter().map(|t| (lo..=hi).contains(t)).collect();
        let kept = keep.iter().filter(|&&k| k).count();
        if kept == 0 {
            let last = self.time.last().copied().unwrap_or(0.0);
            // The window as given (an open end is not a number to print).
            let window = match (from, to) {
                (Some(a), Some(b)) => format!("between {} s and {} s", num(a, 6), num(b, 6)),
                (Some(a), None) => format!("from {} s on", num(a, 6)),
                (None, Some(b)) => format!("up to {} s", num(b, 6)),
                (None, None) => String::new(),
            };
            return Err(ReadError::option(
                if from.is_some() { "from" } else { "to" },
                format!(
                    "no sample lies {window} (the record runs from 0 to {} s)",
                    num(last, 6)
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

/// Where the pivot of x and y positions is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pivot {
    /// At these coordinates, in the file's units and its direction of y.
    At(f64, f64),
    /// The centre of the circle the bob traced, fitted.
    Fit,
}

impl Pivot {
    /// `X,Y` in the file's units, or `fit`.
    pub fn parse(text: &str) -> Result<Pivot, ReadError> {
        let text = text.trim();
        if text == "fit" {
            return Ok(Pivot::Fit);
        }
        let bad = || {
            ReadError::option(
                "pivot",
                format!("give X,Y in the file's units (e.g. 0,0) or 'fit', got '{text}'"),
            )
        };
        let number = |s: &str| {
            s.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(bad)
        };
        match text.split(',').collect::<Vec<_>>()[..] {
            [x, y] => Ok(Pivot::At(number(x)?, number(y)?)),
            _ => Err(bad()),
        }
    }
}

/// How x and y positions become angles: the pivot, the direction of y,
/// and the metres a unit of the file is.
#[derive(Clone, Debug, Default)]
pub struct Positions {
    /// The pivot: given, fitted, or none (0,0).
    pub pivot: Option<Pivot>,
    /// y grows downward (image coordinates).
    pub y_down: bool,
    /// Metres per file unit.
    pub scale: Option<f64>,
}

impl Positions {
    /// The pivot, the direction of y and the scale, checked.
    pub fn new(pivot: Option<Pivot>, y_down: bool, scale: Option<f64>) -> Result<Self, ReadError> {
        if let Some(s) = scale.filter(|s| !(*s > 0.0 && s.is_finite())) {
            return Err(ReadError::option(
                "scale",
                format!("must be positive, got {s} m"),
            ));
        }
        Ok(Self {
            pivot,
            y_down,
            scale,
        })
    }
}

/// Notes, among what the reader says, the options for x and y positions
/// (`--pivot`, `--y-down`, `--scale`) given for a file that holds `holds`
/// instead (angles, angular velocities, amplitudes): not taken for
/// nothing without a word.
pub fn note_unused(table: &mut Table, positions: &Positions, holds: &str) {
    let given: Vec<&str> = [
        (positions.pivot.is_some(), "--pivot"),
        (positions.y_down, "--y-down"),
        (positions.scale.is_some(), "--scale"),
    ]
    .into_iter()
    .filter_map(|(given, flag)| given.then_some(flag))
    .collect();
    if !given.is_empty() {
        let note = format!(
            "{}: {} {} for x and y positions, and the file holds {holds}: not used",
            table.file,
            given.join(", "),
            if given.len() == 1 { "is" } else { "are" }
        );
        table.format.notes.push(note);
    }
}

/// The swing of a table read with [`track_roles`]; without a time column
/// the times are the row numbers over `rate` (samples a second).
pub fn track_of(
    table: Table,
    positions: &Positions,
    rate: Option<f64>,
) -> Result<Track, ReadError> {
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
            note_unused(&mut table, positions, "angular velocities");
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
        let mut table = table;
        note_unused(&mut table, positions, "angles");
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
    let (mut pivot, radius) = pivot_of(&table, positions, x, y, flip)?;
    let angle: Vec<f64> = x
        .iter()
        .zip(y)
        .map(|(&xi, &yi)| angle_about(xi, yi, pivot.x, pivot.y))
        .collect();
    refuse_bob_above_pivot(&table, positions, &angle, y, &pivot, flip)?;
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

/// The pivot of x and y positions (`y` already flipped by `flip` when y
/// grows downward): given, the default (0,0), or the centre of the circle
/// the bob traced. Returns it, with the fitted circle's radius and its
/// standard error, in file units.
fn pivot_of(
    table: &Table,
    positions: &Positions,
    x: &[f64],
    y: &[f64],
    flip: f64,
) -> Result<(PivotJson, Option<(f64, f64)>), ReadError> {
    Ok(match positions.pivot {
        Some(Pivot::Fit) => {
            // The arc of the record's longest run: marks after a tracking
            // gap (a stray point elsewhere in the picture) are no part of
            // it, and the fits leave them out too.
            let run = match table.column(Role::Time) {
                Some(t) if t.len() == x.len() && t.len() == y.len() => longest_run(t).0,
                _ => 0..x.len().min(y.len()),
            };
            let circle = fit_circle(&x[run.clone()], &y[run]).map_err(|e| {
                ReadError::option(
                    "pivot",
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
        Some(Pivot::At(px, py)) => (
            PivotJson {
                x: px,
                y: flip * py,
                source: "given",
            },
            None,
        ),
        None => (
            PivotJson {
                x: 0.0,
                y: 0.0,
                source: "default",
            },
            None,
        ),
    })
}

/// Refuses angles that put the bob level with or above its pivot (`y`
/// and the pivot flipped by `flip` when y grows downward), naming the
/// first such row and the ways out not yet tried.
fn refuse_bob_above_pivot(
    table: &Table,
    positions: &Positions,
    angle: &[f64],
    y: &[f64],
    pivot: &PivotJson,
    flip: f64,
) -> Result<(), ReadError> {
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
                num(pivot.x, 9),
                num(flip * pivot.y, 9)
            ),
        ));
    }
    Ok(())
}
