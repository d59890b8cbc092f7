//! `pendulum train`: a going train's beat and the pendulum it needs, or
//! the trains that give a beat.

use super::common;
use crate::args::TrainArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::compound::RegulationError;
use pendulum_theory::period::length_for_period;
use pendulum_theory::train::{beats_per_hour, trains_for};
use pendulum_theory::Amplitude;
use serde::Serialize;

#[derive(Serialize)]
struct TrainJson {
    wheels: Vec<u32>,
    pinions: Vec<u32>,
    arbor_turns_per_hour: f64,
    beats_per_hour: f64,
    period_s: f64,
    /// The simple pendulum of that period (small swings).
    length_m: f64,
    g_m_s2: f64,
    /// With --design: how far its nut (or bob) must move down, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    design_shift_m: Option<f64>,
}

#[derive(Serialize)]
struct Candidate {
    wheels: [u32; 3],
    pinions: [u32; 2],
    beats_per_hour: f64,
}

pub fn run(args: &TrainArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    if let Some(bph) = args.bph {
        // A turret clock's minute jump (60 an hour) to 100 beats a second.
        if !(1.0..=360_000.0).contains(&bph) {
            return Err(CliError::flag(
                "--bph",
                format!(
                    "must lie between 1 and 360000 beats an hour, got {}",
                    crate::work::count(bph)
                ),
            ));
        }
        if !(args.tolerance > 0.0 && args.tolerance < 0.1) {
            return Err(CliError::flag("--tolerance", "must be between 0 and 0.1"));
        }
        let escape = args.escape_teeth.unwrap_or(30);
        if escape == 0 {
            return Err(CliError::flag("--escape-teeth", "must be positive"));
        }
        let found: Vec<Candidate> = trains_for(bph, escape, args.tolerance, 20)
            .into_iter()
            .map(|(w, p, b)| Candidate {
                wheels: w,
                pinions: p,
                beats_per_hour: b,
            })
            .collect();
        if args.json {
            return output::json(&found);
        }
        if found.is_empty() {
            return Ok(format!(
                "No train of wheels 40-120 and pinions 6-16 with a {escape}-tooth escape wheel gives {} beats/hour within {}.\n",
                num(bph, 6),
                args.tolerance
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
    if args.wheels.is_empty() {
        return Err(CliError::flag(
            "--wheels",
            "give the wheel counts, or --bph",
        ));
    }
    let turns = args.arbor_turns_per_hour;
    if !(turns > 0.0 && turns <= 3600.0) {
        return Err(CliError::flag(
            "--arbor-turns-per-hour",
            format!(
                "must lie between 0 and 3600 (a turn a second), got {}",
                crate::work::count(turns)
            ),
        ));
    }
    let bph = beats_per_hour(&args.wheels, &args.pinions, turns).ok_or_else(|| {
        CliError::flag(
            "--pinions",
            format!(
                "give one fewer pinion than wheels (the last wheel is the escape wheel), none zero; got {} wheels and {} pinions",
                args.wheels.len(),
                args.pinions.len()
            ),
        )
    })?;
    // No clock beats faster than 100 a second (a typing error otherwise).
    if bph.is_nan() || bph > 360_000.0 {
        // Said of the arbor's turns when they were given, else of the wheels.
        let flag = if turns == 1.0 {
            "--wheels"
        } else {
            "--arbor-turns-per-hour"
        };
        return Err(CliError::flag(
            flag,
            format!(
                "give {} beats/hour: no clock beats faster than 100 a second",
                crate::work::count(bph)
            ),
        ));
    }
    let period = 7200.0 / bph;
    let small = Amplitude::from_radians(0.0).map_err(|e| CliError::input("--wheels", &e))?;
    let length = length_for_period(period, small, gravity.g_m_s2)
        .map_err(|e| CliError::input("--wheels", &e))?;
    let design_shift = match &args.design {
        Some(path) => {
            let design = crate::design::read(path)?;
            let l = design.properties().equivalent_length;
            let rate = 86_400.0 * ((length / l).sqrt() - 1.0);
            let index = design
                .parts()
                .iter()
                .position(|p| p.name == "nut")
                .or_else(|| design.parts().iter().position(|p| p.name == "bob"))
                .ok_or_else(|| {
                    CliError::flag("--design", "has no part named 'nut' or 'bob' to move")
                })?;
            let shift = design.regulation(index, rate).map_err(|e| match e {
                RegulationError::RestsOnAnother { .. } => CliError::flag(
                    "--design",
                    "its nut or bob is placed on another part; place it by its centre",
                ),
                _ => CliError::flag(
                    "--design",
                    format!(
                        "cannot be brought to {} beats an hour by its {}: {e}",
                        num(bph, 6),
                        design.parts()[index].name
                    ),
                ),
            })?;
            Some(shift)
        }
        None => None,
    };
    let result = TrainJson {
        wheels: args.wheels.clone(),
        pinions: args.pinions.clone(),
        arbor_turns_per_hour: args.arbor_turns_per_hour,
        beats_per_hour: bph,
        period_s: period,
        length_m: length,
        g_m_s2: gravity.g_m_s2,
        design_shift_m: design_shift,
    };
    if args.json {
        return output::json(&result);
    }
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
    if let Some(shift) = design_shift {
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
