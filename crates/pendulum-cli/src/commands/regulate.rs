//! `pendulum regulate`: from a clock's rate to the turns of its rating nut,
//! or the weight on a regulating tray.

use super::common;
use crate::args::RegulateArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::units::{parse_number, Dimension};
use pendulum_theory::compound::{length_regulation, RegulationError};
use serde::Serialize;

#[derive(Serialize)]
struct RegulateJson {
    rate_s_per_day: f64,
    equivalent_length_m: f64,
    /// How far to move the bob, m: positive down (lengthening: for a
    /// gaining clock), negative up.
    shift_m: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    nut_turns: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    nut_divisions: Option<f64>,
    /// With --design: the tray's place below the pivot and the mass to add
    /// there (negative: to take off).
    #[serde(skip_serializing_if = "Option::is_none")]
    tray_position_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tray_mass_kg: Option<f64>,
}

/// `+12s/day`, `-30 s/d`, `4`: s/day.
fn rate(text: &str) -> Result<f64, CliError> {
    let t = text.trim();
    let number = ["s/day", "s/d", "sec/day"]
        .iter()
        .find_map(|u| t.strip_suffix(u))
        .unwrap_or(t)
        .trim();
    let r = parse_number(number).map_err(|e| CliError::flag("--rate", e))?;
    if r.is_nan() || r.abs() >= 86_400.0 {
        return Err(CliError::flag(
            "--rate",
            format!("must be less than a day a day, got {text}"),
        ));
    }
    Ok(r)
}

pub fn run(args: &RegulateArgs) -> Result<String, CliError> {
    let r = rate(&args.rate)?;
    let pitch = match (&args.nut_pitch, args.nut_tpi) {
        (Some(p), _) => {
            let p = common::quantity("--nut-pitch", p, Dimension::Length)?;
            // Clock threads: 0.25 mm (M1) to a few millimetres.
            if !(1e-5..=0.05).contains(&p) {
                return Err(CliError::flag(
                    "--nut-pitch",
                    format!("must lie between 0.01 mm and 50 mm, got {} m", num(p, 6)),
                ));
            }
            Some(p)
        }
        (None, Some(tpi)) => {
            if !(0.5..=2540.0).contains(&tpi) {
                return Err(CliError::flag(
                    "--nut-tpi",
                    "must lie between 0.5 and 2540 threads per inch",
                ));
            }
            Some(0.0254 / tpi)
        }
        (None, None) => None,
    };
    let mut pitch = pitch;
    let mut nut_divisions = args.nut_divisions;
    let (length, shift, tray) = match &args.design {
        Some(path) => {
            let read = crate::design::read_design(path)?;
            let design = read.pendulum;
            let p = design.properties();
            let index = design
                .parts()
                .iter()
                .position(|q| q.name == args.part)
                .ok_or_else(|| {
                    CliError::flag(
                        "--part",
                        format!("{} has no part named '{}'", path.display(), args.part),
                    )
                })?;
            // The design's own thread, when the part moved is its nut and
            // no flag gives another.
            if let Some(t) = read.thread.filter(|t| t.part == index) {
                if pitch.is_none() {
                    pitch = Some(t.pitch);
                    nut_divisions = nut_divisions.or(t.divisions);
                }
            }
            let shift = design.regulation(index, r).map_err(|e| match e {
                RegulationError::RestsOnAnother { .. } => CliError::flag("--part", e),
                _ => CliError::flag("--rate", e),
            })?;
            let at = match &args.tray {
                Some(t) => common::quantity("--tray", t, Dimension::Length)?,
                None => p.equivalent_length / 3.0,
            };
            // A tray at the pivot does nothing: from 1% of the length down.
            if !(at >= 0.01 * p.equivalent_length && at < p.equivalent_length) {
                return Err(CliError::flag(
                    "--tray",
                    format!(
                        "must lie between 1% of the length below the pivot ({} mm) and the \
                         centre of oscillation ({} mm)",
                        num(10.0 * p.equivalent_length, 4),
                        num(1e3 * p.equivalent_length, 6)
                    ),
                ));
            }
            // A tray that cannot do it: refused when asked for, else left
            // out of the advice.
            let tray = match design.tray_mass(at, r) {
                Ok(mass) => Some((at, mass)),
                Err(e) if args.tray.is_some() => return Err(CliError::flag("--tray", e)),
                Err(_) => None,
            };
            (p.equivalent_length, shift, tray)
        }
        None => {
            if args.tray.is_some() {
                return Err(CliError::flag(
                    "--tray",
                    "needs --design: what a tray's mass does depends on the pendulum's parts",
                ));
            }
            let gravity = common::gravity_default();
            let pendulum = common::pendulum(args.length.as_deref().unwrap_or(""), &gravity)?;
            let l = pendulum.length_m();
            let shift = length_regulation(l, r).map_err(|e| CliError::flag("--rate", e))?;
            (l, shift, None)
        }
    };
    let turns = pitch.map(|p| shift / p);
    let divisions = match (turns, nut_divisions) {
        (Some(t), Some(d)) if d > 0 => Some(t * f64::from(d)),
        _ => None,
    };
    let result = RegulateJson {
        rate_s_per_day: r,
        equivalent_length_m: length,
        shift_m: shift,
        nut_turns: turns,
        nut_divisions: divisions,
        tray_position_m: tray.map(|t| t.0),
        tray_mass_kg: tray.map(|t| t.1),
    };
    if args.json {
        return output::json(&result);
    }
    let way = if shift >= 0.0 { "lower" } else { "raise" };
    let mut s = Summary::default();
    s.row(
        "Rate",
        format!(
            "{} s/day ({})",
            num(r, 6),
            if r > 0.0 {
                "gaining"
            } else if r < 0.0 {
                "losing"
            } else {
                "on time"
            }
        ),
    )
    .row("Bob", format!("{way} it {} mm", num(shift.abs() * 1e3, 4)));
    if let Some(t) = turns {
        let mut nut = format!(
            "{} turns {} ({} the bob)",
            num(t.abs(), 4),
            if shift >= 0.0 { "down" } else { "up" },
            if shift >= 0.0 { "lowering" } else { "raising" }
        );
        if let Some(d) = divisions {
            nut.push_str(&format!(", {} divisions", num(d.abs(), 4)));
        }
        s.row("Nut", nut);
    }
    if let Some((at, mu)) = tray {
        s.row(
            "Or a tray",
            format!(
                "{} {} g at {} mm below the pivot",
                if mu >= 0.0 { "add" } else { "take off" },
                num(mu.abs() * 1e3, 4),
                num(at * 1e3, 5)
            ),
        );
    }
    Ok(s.render())
}
