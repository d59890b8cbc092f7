//! Reading the arguments every command shares: quantities with units, the
//! pendulum, the amplitude, and where g comes from.

use crate::args::GravityArgs;
use crate::error::CliError;
use crate::units::{parse_quantity, Dimension};
use pendulum_theory::gravity::normal_gravity;
use pendulum_theory::{Amplitude, Pendulum, Quantity, STANDARD_GRAVITY};
use serde::Serialize;

/// Reads `text` given to `flag` as a quantity of `dimension`, in SI.
pub fn quantity(flag: &str, text: &str, dimension: Dimension) -> Result<f64, CliError> {
    parse_quantity(text, dimension).map_err(|e| CliError::flag(flag, e))
}

/// Reads an amplitude given to `flag`.
pub fn amplitude(flag: &str, text: &str) -> Result<Amplitude, CliError> {
    amplitude_from_radians(flag, quantity(flag, text, Dimension::Angle)?)
}

/// Checks an amplitude in radians, attributing a refusal to `flag`.
pub fn amplitude_from_radians(flag: &str, radians: f64) -> Result<Amplitude, CliError> {
    Amplitude::from_radians(radians).map_err(|e| CliError::input(flag, &e))
}

/// The value of g and where it came from, echoed in the output.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ResolvedGravity {
    /// m/s².
    pub g_m_s2: f64,
    /// `"standard"`, `"given"` or `"wgs84"`.
    pub g_source: &'static str,
}

impl ResolvedGravity {
    /// A phrase for people: "9.80665 m/s^2 (standard gravity)".
    pub fn describe(&self) -> String {
        let source = match self.g_source {
            "standard" => "standard gravity",
            "wgs84" => "WGS 84 normal gravity",
            _ => "given",
        };
        format!("{} m/s^2 ({source})", crate::output::num(self.g_m_s2, 10))
    }
}

/// g from `--g`, from `--latitude`/`--height`, or standard gravity.
pub fn gravity(args: &GravityArgs) -> Result<ResolvedGravity, CliError> {
    if let Some(text) = &args.g {
        let g = quantity("--g", text, Dimension::Acceleration)?;
        // Let the library judge it, so the message matches every other check.
        Pendulum::new(1.0, g).map_err(|e| CliError::input("--g", &e))?;
        return Ok(ResolvedGravity {
            g_m_s2: g,
            g_source: "given",
        });
    }
    if let Some(text) = &args.latitude {
        let g = wgs84(text, args.height.as_deref())?;
        return Ok(ResolvedGravity {
            g_m_s2: g,
            g_source: "wgs84",
        });
    }
    Ok(ResolvedGravity {
        g_m_s2: STANDARD_GRAVITY,
        g_source: "standard",
    })
}

/// Normal gravity at the latitude and height typed, in m/s².
pub fn wgs84(latitude: &str, height: Option<&str>) -> Result<f64, CliError> {
    let latitude_deg = latitude_degrees(latitude)?;
    let height_m = height_metres(height)?;
    normal_gravity(latitude_deg, height_m).map_err(|e| match e.quantity {
        Quantity::Height => CliError::input("--height", &e),
        _ => CliError::input("--latitude", &e),
    })
}

/// The latitude typed, in degrees.
pub fn latitude_degrees(text: &str) -> Result<f64, CliError> {
    Ok(quantity("--latitude", text, Dimension::Angle)?.to_degrees())
}

/// The height typed, in metres (0 when absent).
pub fn height_metres(text: Option<&str>) -> Result<f64, CliError> {
    text.map_or(Ok(0.0), |t| quantity("--height", t, Dimension::Length))
}

/// The pendulum of `--length` under `gravity`.
pub fn pendulum(length_text: &str, gravity: &ResolvedGravity) -> Result<Pendulum, CliError> {
    let length = quantity("--length", length_text, Dimension::Length)?;
    Pendulum::new(length, gravity.g_m_s2).map_err(|e| match e.quantity {
        Quantity::Gravity => CliError::input("--g", &e),
        _ => CliError::input("--length", &e),
    })
}

/// Infinite or NaN values become JSON `null` rather than a string.
pub fn finite(value: f64) -> Option<f64> {
    value.is_finite().then_some(value)
}
