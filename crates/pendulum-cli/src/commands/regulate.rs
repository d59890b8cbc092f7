//! `pendulum regulate`: from a clock's rate to the turns of its rating nut,
//! or the weight on a regulating tray.

use super::common;
use crate::args::RegulateArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::compound::regulate::{regulate, Nut, Regulated};

pub fn run(args: &RegulateArgs) -> Result<String, CliError> {
    let r = args.rate.0;
    let pendulum = match &args.pendulum.design {
        Some(path) => Regulated::Design(crate::design::read_design(path)?, args.part.clone()),
        None => Regulated::Length(
            args.pendulum
                .length
                .ok_or_else(|| CliError::flag("--length", "give --length or --design"))?
                .0,
        ),
    };
    let nut = Nut {
        pitch: args.nut_pitch.map(|p| p.0),
        tpi: args.nut_tpi.map(|t| t.0),
        divisions: args.nut_divisions,
    };
    let tray = args.tray.map(|t| t.0);
    let result = regulate(&pendulum, r, nut, tray).map_err(|e| common::refused(&e))?;
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
