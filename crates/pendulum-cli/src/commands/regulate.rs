//! `pendulum regulate`: from a clock's rate to the turns of its rating nut,
//! or the weight on a regulating tray.

use super::common;
use crate::args::RegulateArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::compound::regulate::{regulate, Regulated};

pub fn run(args: &RegulateArgs) -> Result<String, CliError> {
    let r = args.rate.0;
    let pendulum = match (&args.design, args.length, args.bph) {
        (Some(path), _, _) => {
            Regulated::Design(crate::design::read_design(path)?, args.part.clone())
        }
        (None, Some(l), _) => Regulated::Length(l.0),
        (None, None, Some(b)) => Regulated::Length(
            pendulum_theory::advice::length_for_bph(b.0).map_err(|e| common::refused(&e))?,
        ),
        (None, None, None) => {
            return Err(CliError::flag(
                "--length",
                "give --length, --design or --bph",
            ))
        }
    };
    let nut = args.nut.nut();
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
    if let (None, None, Some(b)) = (&args.design, args.length, args.bph) {
        s.row(
            "Figured for",
            format!(
                "the simple pendulum of {} beats an hour, {} m (give --length or --design if \
                 yours differs)",
                num(b.0, 6),
                num(result.equivalent_length_m, 5)
            ),
        );
    }
    if let Some(t) = turns {
        let mut nut = format!(
            "{} turns {} ({} the bob): {} seen from below",
            num(t.abs(), 4),
            if shift >= 0.0 { "down" } else { "up" },
            if shift >= 0.0 { "lowering" } else { "raising" },
            if shift >= 0.0 {
                "anticlockwise"
            } else {
                "clockwise"
            }
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
        s.row("WARNING", w.to_string());
    }
    Ok(s.render())
}
