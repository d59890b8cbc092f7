//! What the `fit` commands share about their files: the reading options
//! and the positions' pivot from the command line. The swing itself is
//! read by `pendulum_data::measured`, which the browser page shares.

use crate::args::MeasurementArgs;
use crate::data::{AngleUnit, ReadOptions};
use crate::error::CliError;
use pendulum_data::measured::{Pivot, Positions};
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
    Ok(n.map(pendulum_data::run_number).transpose()?)
}

/// `--columns a,b,c` as names.
pub fn columns(text: Option<&str>) -> Option<Vec<String>> {
    text.map(|t| t.split(',').map(|c| c.trim().to_string()).collect())
}

fn frame_rate(fps: Option<crate::units::Hertz>) -> Result<Option<f64>, CliError> {
    Ok(fps.map(|f| pendulum_data::frame_rate(f.0)).transpose()?)
}

/// `--pivot`, `--y-down` and `--scale`.
pub fn positions(args: &MeasurementArgs) -> Result<Positions, CliError> {
    let pivot = args.pivot.as_deref().map(Pivot::parse).transpose()?;
    Ok(Positions::new(pivot, args.y_down, args.scale.map(|s| s.0))?)
}

/// Opens `path` for the reader (again, when the times are read twice).
pub fn opener(
    path: &Path,
) -> impl Fn() -> Result<pendulum_data::Source<'static>, pendulum_data::ReadError> + '_ {
    move || crate::data::source(path).map_err(|e| pendulum_data::ReadError::other(e.to_string()))
}
