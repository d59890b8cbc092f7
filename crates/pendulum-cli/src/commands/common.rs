//! Reading the arguments every command shares: quantities with units, the
//! pendulum, the amplitude, and where g comes from.

use crate::args::{DampingArgs, GravityArgs, SwingArgs};
use crate::error::CliError;
use crate::units::{parse_number, parse_quantity, Dimension};
use pendulum_theory::damping::Damping;
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
    /// A phrase for people: "9.80665 m/s² (standard gravity)".
    pub fn describe(&self) -> String {
        let source = match self.g_source {
            "standard" => "standard gravity",
            "wgs84" => "WGS 84 normal gravity",
            _ => "given",
        };
        format!("{} m/s² ({source})", crate::output::num(self.g_m_s2, 10))
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

/// Standard gravity, for commands that need a pendulum only for its length.
pub fn gravity_default() -> ResolvedGravity {
    ResolvedGravity {
        g_m_s2: STANDARD_GRAVITY,
        g_source: "standard",
    }
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

/// The pendulum of `--length`, or of `--design` (its equivalent simple
/// length, `I / (m d)`: the same equation of motion).
pub fn pendulum_of(
    length_text: Option<&str>,
    design: Option<&std::path::Path>,
    gravity: &ResolvedGravity,
) -> Result<Pendulum, CliError> {
    match (length_text, design) {
        (_, Some(path)) => {
            let design = crate::design::read(path)?;
            let length = design.properties().equivalent_length;
            Pendulum::new(length, gravity.g_m_s2).map_err(|e| match e.quantity {
                Quantity::Gravity => CliError::input("--g", &e),
                _ => CliError::input("--design", &e),
            })
        }
        (Some(text), None) => pendulum(text, gravity),
        (None, None) => Err(CliError::flag("--length", "give --length or --design")),
    }
}

/// The pendulum of `--length`.
pub fn pendulum(length_text: &str, gravity: &ResolvedGravity) -> Result<Pendulum, CliError> {
    let length = quantity("--length", length_text, Dimension::Length)?;
    Pendulum::new(length, gravity.g_m_s2).map_err(|e| match e.quantity {
        Quantity::Gravity => CliError::input("--g", &e),
        _ => CliError::input("--length", &e),
    })
}

/// The flag the damping was given with.
pub fn damping_flag(d: &crate::args::DampingArgs) -> &'static str {
    match damping_field(d) {
        "q" => "--q",
        "log_decrement" => "--log-decrement",
        "decay_time" => "--decay-time",
        "damping_coefficient" => "--damping-coefficient",
        _ => "--zeta",
    }
}

/// The library's name of the damping input given (`zeta` when none).
pub fn damping_field(d: &crate::args::DampingArgs) -> &'static str {
    if d.q.is_some() {
        "q"
    } else if d.log_decrement.is_some() {
        "log_decrement"
    } else if d.decay_time.is_some() {
        "decay_time"
    } else if d.damping_coefficient.is_some() {
        "damping_coefficient"
    } else {
        "zeta"
    }
}

/// The damping form given, by the library's name, with its value (a
/// decay time in seconds); `None` when none was given.
pub fn damping_given(args: &DampingArgs) -> Result<Option<(String, f64)>, CliError> {
    let field = damping_field(args);
    let text = match field {
        "q" => &args.q,
        "log_decrement" => &args.log_decrement,
        "decay_time" => &args.decay_time,
        "damping_coefficient" => &args.damping_coefficient,
        _ => &args.zeta,
    };
    let Some(text) = text.as_deref() else {
        return Ok(None);
    };
    let flag = damping_flag(args);
    let value = if field == "decay_time" {
        quantity(flag, text, Dimension::Time)?
    } else {
        parse_number(text).map_err(|e| CliError::flag(flag, e))?
    };
    Ok(Some((field.to_string(), value)))
}

/// The damping form given, converted by the library for `p` (with a
/// bob of `mass` kg for a damping coefficient); `None` when none was given.
pub fn damping(
    args: &DampingArgs,
    mass: Option<f64>,
    p: &Pendulum,
) -> Result<Option<Damping>, CliError> {
    let Some((field, value)) = damping_given(args)? else {
        return Ok(None);
    };
    let no_data = |_: Option<(&'static str, usize)>, reason: &str| CliError::other(reason);
    pendulum_theory::damped::analysis::damping_given(&field, value, p, mass)
        .map(|(d, _)| Some(d))
        .map_err(|e| CliError::refused(&e, &[], &no_data))
}

/// What `damped` and `simulate` read from [`SwingArgs`].
pub struct Swing {
    /// The pendulum.
    pub pendulum: Pendulum,
    /// The release amplitude.
    pub amplitude: Amplitude,
    /// The viscous damping, if given.
    pub damping: Option<Damping>,
    /// The dry friction angle (0 if not given), rad.
    pub friction_angle: f64,
}

/// Reads the pendulum, its release and its losses.
pub fn swing(args: &SwingArgs) -> Result<Swing, CliError> {
    let gravity = gravity(&args.gravity)?;
    let pendulum = pendulum_of(args.length.as_deref(), args.design.as_deref(), &gravity)?;
    let amplitude = amplitude("--amplitude", &args.amplitude)?;
    let mass = args
        .mass
        .as_deref()
        .map(|t| quantity("--mass", t, Dimension::Mass))
        .transpose()?;
    let damping = damping(&args.damping, mass, &pendulum)?;
    let friction_angle = args
        .friction_angle
        .as_deref()
        .map(|t| quantity("--friction-angle", t, Dimension::Angle))
        .transpose()?
        .unwrap_or(0.0);
    Ok(Swing {
        pendulum,
        amplitude,
        damping,
        friction_angle,
    })
}

/// The beat a clock is meant to keep, from `--period` or `--bph`.
pub fn nominal(
    period: Option<&str>,
    bph: Option<&str>,
) -> Result<Option<pendulum_theory::fitting::beat_log::Nominal>, CliError> {
    use pendulum_theory::fitting::beat_log::Nominal;
    Ok(match (period, bph) {
        (Some(t), _) => Some(Nominal::Period(quantity("--period", t, Dimension::Time)?)),
        (None, Some(t)) => Some(Nominal::BeatsPerHour(
            parse_number(t).map_err(|e| CliError::flag("--bph", e))?,
        )),
        (None, None) => None,
    })
}
