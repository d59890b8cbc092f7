//! `pendulum regulate`: from a clock's rate to the turns of its rating nut,
//! or the weight on a regulating tray.

use super::common;
use crate::args::RegulateArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::units::{parse_number, Dimension};
use pendulum_theory::compound::regulate::{regulate, Nut, Regulated};

/// `+12s/day`, `-30 s/d`, `4`: s/day.
fn rate(text: &str) -> Result<f64, CliError> {
    let t = text.trim();
    let number = ["s/day", "s/d", "sec/day"]
        .iter()
        .find_map(|u| t.strip_suffix(u))
        .unwrap_or(t)
        .trim();
    parse_number(number).map_err(|e| CliError::flag("--rate", e))
}

pub fn run(args: &RegulateArgs) -> Result<String, CliError> {
    let r = rate(&args.rate)?;
    let pendulum = match &args.design {
        Some(path) => Regulated::Design(crate::design::read_design(path)?, args.part.clone()),
        None => Regulated::Length(common::quantity(
            "--length",
            args.length.as_deref().unwrap_or(""),
            Dimension::Length,
        )?),
    };
    let nut = Nut {
        pitch: args
            .nut_pitch
            .as_deref()
            .map(|p| common::quantity("--nut-pitch", p, Dimension::Length))
            .transpose()?,
        tpi: args.nut_tpi,
        divisions: args.nut_divisions,
    };
    let tray = args
        .tray
        .as_deref()
        .map(|t| common::quantity("--tray", t, Dimension::Length))
        .transpose()?;
    let no_file = |_: Option<(&'static str, usize)>, reason: &str| CliError::other(reason);
    let result =
        regulate(&pendulum, r, nut, tray).map_err(|e| CliError::refused(&e, &[], &no_file))?;
    if args.json {
        return output::json(&result);
    }
    let (shift, turns, divisions) = (result.shift_m, result.nut_turns, result.nut_divisions);
    let tray = result.tray_position_m.zip(result.tray_mass_kg);
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
    for w in &result.warnings {
        s.row("WARNING", w.clone());
    }
    Ok(s.render())
}
