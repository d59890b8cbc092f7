//! `pendulum train`: a going train's beat and the pendulum it needs, or
//! the trains that give a beat.

use super::common;
use crate::args::TrainArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::train::analysis::{train, train_for};

pub fn run(args: &TrainArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let refused = |r: pendulum_theory::analysis::Refusal| common::refused(&r);
    if let Some(bph) = args.bph.map(|b| b.0) {
        let found =
            train_for(bph, args.escape_teeth, args.tolerance.map(|t| t.0)).map_err(refused)?;
        if args.json {
            return output::json(&found);
        }
        let escape = found
            .first()
            .map_or(args.escape_teeth.unwrap_or_default(), |c| c.wheels[2]);
        if found.is_empty() {
            use pendulum_theory::train::{PINION_LEAVES, WHEEL_TEETH};
            return Ok(format!(
                "No train of wheels {}-{} and pinions {}-{} with the escape wheel given gives {} beats/hour within the tolerance.\n",
                WHEEL_TEETH.start(),
                WHEEL_TEETH.end(),
                PINION_LEAVES.start(),
                PINION_LEAVES.end(),
                num(bph, 6),
            ));
        }
        let mut text = format!(
            "Trains for {} beats/hour (centre arbor once an hour, {escape}-tooth escape wheel):\n",
            num(bph, 6)
        );
        for c in &found {
            text.push_str(&format!(
                "  {}/{} x {}/{} x {}: {} beats/hour\n",
                c.wheels[0],
                c.pinions[0],
                c.wheels[1],
                c.pinions[1],
                c.wheels[2],
                num(c.beats_per_hour, 8)
            ));
        }
        return Ok(text);
    }
    let design = args
        .design
        .as_deref()
        .map(crate::design::read)
        .transpose()?;
    let result = train(
        &args.wheels,
        &args.pinions,
        args.arbor_turns_per_hour.map(|n| n.0),
        Some(gravity.g_m_s2),
        design.as_ref(),
    )
    .map_err(refused)?;
    if args.json {
        return output::json(&result);
    }
    let (bph, period, length) = (result.beats_per_hour, result.period_s, result.length_m);
    let mut s = Summary::default();
    s.row("Beats", format!("{} beats/hour", num(bph, 8)))
        .row("Period", format!("{} s (two beats)", num(period, 8)))
        .row(
            "Pendulum",
            format!(
                "{} m simple length (small swings, g = {})",
                num(length, 6),
                gravity.describe()
            ),
        );
    if let Some(shift) = result.design_shift_m {
        s.row(
            "Design",
            format!(
                "move the nut {} {} mm",
                if shift >= 0.0 { "down" } else { "up" },
                num(shift.abs() * 1e3, 4)
            ),
        );
    }
    Ok(s.render())
}
