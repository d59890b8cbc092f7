//! What the `fit` commands share about their files: the reading options
//! from the command line, and a tracked swing (angle against time) read
//! from an angle column or from x/y positions about a pivot.

use crate::args::MeasurementArgs;
use crate::data::{read_table, AngleUnit, Found, ReadOptions, Role, Table};
use crate::error::CliError;
use crate::units::parse_number;
use pendulum_theory::fitting::track::{angle_about, fit_circle};
use serde::Serialize;
use std::path::Path;

/// The reading options given on the command line.
pub fn read_options(args: &MeasurementArgs) -> Result<ReadOptions, CliError> {
    Ok(ReadOptions {
        angle_unit: args.angle_unit.as_deref().map(|u| match u {
            "rad" => AngleUnit::Radians,
            _ => AngleUnit::Degrees,
        }),
        columns: columns(args.columns.as_deref()),
        frame_rate: frame_rate(args.frame_rate)?,
        absolute_time: false,
    })
}

/// `--columns a,b,c` as names.
pub fn columns(text: Option<&str>) -> Option<Vec<String>> {
    text.map(|t| t.split(',').map(|c| c.trim().to_string()).collect())
}

fn frame_rate(fps: Option<crate::units::Number>) -> Result<Option<f64>, CliError> {
    fps.map(|f| {
        pendulum_theory::fitting::track::frame_rate(f.0)
            .map_err(|e| CliError::flag("--frame-rate", e.reason))
    })
    .transpose()
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
    /// Angles, rad.
    pub angle: Vec<f64>,
    /// The pivot, when the angles came from positions.
    pub pivot: Option<PivotJson>,
    /// The radius of the circle the bob traced (`--pivot fit`), file units.
    pub track_radius: Option<f64>,
    /// Its standard error.
    pub track_radius_error: Option<f64>,
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
            "no time column; for a logger that samples at a fixed rate give --sample-rate HZ"
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
    } else {
        Err("no angle column (angle, theta, θ), nor x and y positions".into())
    }
}

/// Reads a swing from `path`.
pub fn read_track(path: &Path, args: &MeasurementArgs) -> Result<Track, CliError> {
    let options = read_options(args)?;
    let rate = options.frame_rate;
    let table = read_table(path, &options, &|found: &[Found]| {
        track_roles(found, rate.is_some())
    })?;
    track_of(table, args.pivot.as_deref(), rate)
}

/// The swing of a table read with [`track_roles`]; without a time column
/// the times are the row numbers over `rate` (samples a second).
pub fn track_of(table: Table, pivot: Option<&str>, rate: Option<f64>) -> Result<Track, CliError> {
    table.require_increasing(Role::Time)?;
    let time = match (table.column(Role::Time), rate) {
        (Some(t), _) => t.to_vec(),
        (None, Some(rate)) => {
            let rows = table.values.first().map_or(0, Vec::len);
            (0..rows).map(|i| i as f64 / rate).collect()
        }
        (None, None) => Vec::new(),
    };
    if let Some(angle) = table.column(Role::Angle) {
        let angle = angle.to_vec();
        return Ok(Track {
            table,
            time,
            angle,
            pivot: None,
            track_radius: None,
            track_radius_error: None,
        });
    }
    let (x, y) = (
        table.column(Role::X).unwrap_or(&[]),
        table.column(Role::Y).unwrap_or(&[]),
    );
    let (pivot, radius) = match pivot.map(str::trim) {
        Some("fit") => {
            let circle = fit_circle(x, y).map_err(|e| {
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
            let py = parse_number(parts[1]).map_err(|_| bad())?;
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
    // A bob above its pivot means the pivot is wrong (or y points down).
    if let Some(i) = angle
        .iter()
        .position(|a| a.abs() >= std::f64::consts::FRAC_PI_2)
    {
        return Err(table.error_at(
            i,
            Role::Y,
            format!(
                "the bob is level with or above the pivot ({}, {}): give the pivot with \
                 --pivot X,Y, or --pivot fit",
                pivot.x, pivot.y
            ),
        ));
    }
    Ok(Track {
        table,
        time,
        angle,
        pivot: Some(pivot),
        track_radius: radius.map(|r| r.0),
        track_radius_error: radius.map(|r| r.1),
    })
}
