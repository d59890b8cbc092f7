//! Reading the arguments every command shares: quantities with units, the
//! pendulum, the amplitude, and where g comes from.

use crate::args::{DampingArgs, GravityArgs, SwingArgs};
use crate::error::CliError;
use crate::units::{Length, Number, Time};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::damped::analysis::DampingGiven;
use pendulum_theory::damping::Damping;
use pendulum_theory::{Amplitude, Pendulum, Quantity};
use serde::Serialize;

/// A library refusal of a field said of its flag (`--field-name`), with
/// no file to name.
pub fn refused(e: &Refusal) -> CliError {
    CliError::refused(e, &[], &|_, reason| CliError::other(reason))
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

/// g from `--g`, from `--latitude`/`--height`, or standard gravity: the
/// library's choice.
pub fn gravity(args: &GravityArgs) -> Result<ResolvedGravity, CliError> {
    resolve(
        args.g.map(|g| g.0),
        args.latitude.map(|l| l.0.to_degrees()),
        args.height.map(|h| h.0),
    )
}

/// Standard gravity, for commands that need a pendulum only for its length.
pub fn gravity_default() -> Result<ResolvedGravity, CliError> {
    resolve(None, None, None)
}

/// The library's g of `g`, or at a latitude (degrees) and height (m).
pub fn resolve(
    g: Option<f64>,
    latitude: Option<f64>,
    height: Option<f64>,
) -> Result<ResolvedGravity, CliError> {
    let r = pendulum_theory::gravity::resolve(g, latitude, height).map_err(|e| refused(&e))?;
    Ok(ResolvedGravity {
        g_m_s2: r.g_m_s2,
        g_source: r.g_source,
    })
}

/// The pendulum of `--length`, or of `--design` (its equivalent simple
/// length, `I / (m d)`: the same small-swing equation of motion), with the
/// elastic share of a design's suspension spring (0 for a rigid pivot).
pub struct Reduced {
    /// The simple pendulum of the same small-swing period.
    pub pendulum: Pendulum,
    /// The suspension spring's share of the restoring torque (0: none).
    pub elastic_share: f64,
}

/// The pendulum of `--length` or `--design` with its spring's share.
pub fn reduced(
    length: Option<Length>,
    design: Option<&std::path::Path>,
    gravity: &ResolvedGravity,
) -> Result<Reduced, CliError> {
    match (length, design) {
        (_, Some(path)) => {
            let design = crate::design::read(path)?.in_gravity(gravity.g_m_s2);
            let length = design.properties().equivalent_length;
            let pendulum = Pendulum::new(length, gravity.g_m_s2).map_err(|e| match e.quantity {
                Quantity::Gravity => CliError::input("--g", &e),
                _ => CliError::input("--design", &e),
            })?;
            Ok(Reduced {
                pendulum,
                elastic_share: design.spring_effect().map_or(0.0, |e| e.elastic_share),
            })
        }
        (Some(length), None) => Ok(Reduced {
            pendulum: pendulum(length, gravity)?,
            elastic_share: 0.0,
        }),
        (None, None) => Err(CliError::flag("--length", "give --length or --design")),
    }
}

/// The pendulum of `--length` or `--design` (see [`reduced`]).
pub fn pendulum_of(
    length: Option<Length>,
    design: Option<&std::path::Path>,
    gravity: &ResolvedGravity,
) -> Result<Pendulum, CliError> {
    reduced(length, design, gravity).map(|r| r.pendulum)
}

/// The pendulum of `--length`.
pub fn pendulum(length: Length, gravity: &ResolvedGravity) -> Result<Pendulum, CliError> {
    Pendulum::new(length.0, gravity.g_m_s2).map_err(|e| match e.quantity {
        Quantity::Gravity => CliError::input("--g", &e),
        _ => CliError::input("--length", &e),
    })
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
pub fn damping_given(args: &DampingArgs) -> Result<Option<DampingGiven>, CliError> {
    let number = |n: &Option<Number>| n.map(|n| n.0);
    let given = match damping_field(args) {
        "q" => number(&args.q),
        "log_decrement" => number(&args.log_decrement),
        "decay_time" => args.decay_time.map(|t: Time| t.0),
        "damping_coefficient" => number(&args.damping_coefficient),
        _ => number(&args.zeta),
    };
    given
        .map(|v| DampingGiven::parse(damping_field(args), v))
        .transpose()
        .map_err(|e| refused(&e))
}

/// The damping form given, converted by the library for `p` (with a
/// bob of `mass` kg for a damping coefficient); `None` when none was given.
pub fn damping(
    args: &DampingArgs,
    mass: Option<f64>,
    p: &Pendulum,
) -> Result<Option<Damping>, CliError> {
    let Some(given) = damping_given(args)? else {
        return Ok(None);
    };
    pendulum_theory::damped::analysis::damping_given(given, p, mass)
        .map(|(d, _)| Some(d))
        .map_err(|e| refused(&e))
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
    /// A design's suspension spring's elastic share (0: none).
    pub elastic_share: f64,
}

/// Reads the pendulum, its release and its losses.
pub fn swing(args: &SwingArgs) -> Result<Swing, CliError> {
    let gravity = gravity(&args.gravity)?;
    let Reduced {
        pendulum,
        elastic_share,
    } = reduced(
        args.pendulum.length,
        args.pendulum.design.as_deref(),
        &gravity,
    )?;
    let amplitude = amplitude_from_radians("--amplitude", args.amplitude.0)?;
    let mass = args.mass.map(|m| m.0);
    let damping = damping(&args.damping, mass, &pendulum)?;
    let friction_angle = args.friction_angle.map_or(0.0, |r| r.0);
    Ok(Swing {
        pendulum,
        amplitude,
        damping,
        friction_angle,
        elastic_share,
    })
}

/// The beat a clock is meant to keep, from `--period` or `--bph`.
pub fn nominal(
    period: Option<Time>,
    bph: Option<crate::units::BeatsPerHour>,
) -> Option<pendulum_theory::fitting::beat_log::Nominal> {
    use pendulum_theory::fitting::beat_log::Nominal;
    match (period, bph) {
        (Some(t), _) => Some(Nominal::Period(t.0)),
        (None, Some(b)) => Some(Nominal::BeatsPerHour(b.0)),
        (None, None) => None,
    }
}

/// What the user said of the clock, for the advice.
pub fn known(args: &crate::args::AdviceArgs) -> Result<pendulum_theory::advice::Known, CliError> {
    use pendulum_theory::compound::regulate::Regulated;
    let pendulum = match (&args.design, args.length) {
        (Some(path), _) => Some(Regulated::Design(crate::design::read_design(path)?, None)),
        (None, Some(l)) => Some(Regulated::Length(l.0)),
        (None, None) => None,
    };
    Ok(pendulum_theory::advice::Known {
        pendulum,
        nut: args.nut.nut(),
        crutch_m: args.crutch.map(|c| c.0),
        amplitude_rad: args.amplitude.map(|a| a.0),
    })
}

/// The findings in plain words, one to a line, under "What it shows:"
/// (nothing when there are none).
pub fn findings_text(findings: &[pendulum_theory::findings::Finding]) -> String {
    listed("What it shows:", findings.iter().map(|f| f.sentence()))
}

/// The advice as the text's last lines: "What to do:" and one line each.
pub fn advice_text(advice: &[pendulum_theory::advice::Advice]) -> String {
    listed("What to do:", advice.iter().map(|a| a.sentence()))
}

/// `heading` and each of `lines` as a dashed item under it; nothing when
/// there are no lines.
fn listed(heading: &str, lines: impl Iterator<Item = String>) -> String {
    let items: String = lines.map(|l| format!("  - {l}\n")).collect();
    if items.is_empty() {
        return String::new();
    }
    format!("{heading}\n{items}")
}

/// The drag laws of `--drag NAME=VALUE` (repeated), each read by the
/// library's list: the law and its coefficient in its own units.
pub fn drag_laws(
    given: &[String],
) -> Result<Vec<(&'static dyn pendulum_theory::forces::DragLaw, f64)>, CliError> {
    given
        .iter()
        .map(|t| {
            let (name, value) = t.split_once('=').ok_or_else(|| {
                CliError::flag(
                    "--drag",
                    format!("give NAME=VALUE (e.g. three_halves_drag=0.002), got '{t}'"),
                )
            })?;
            let value = crate::units::parse_number(value)
                .map_err(|e| CliError::flag(&format!("--drag {name}"), e))?;
            let law = pendulum_theory::simulation::analysis::parse_drag_law(name.trim())
                .map_err(|e| refused(&e))?;
            Ok((law, value))
        })
        .collect()
}

/// The flags the drag laws' refusals are said of (`--drag NAME`, the
/// field being the law's name), but for the laws in `except`.
pub fn drag_flags(except: &[&str]) -> Vec<(&'static str, String)> {
    pendulum_theory::forces::DRAG_LAWS
        .iter()
        .filter(|l| !except.contains(&l.name()))
        .map(|l| (l.name(), format!("--drag {}", l.name())))
        .collect()
}
