//! `pendulum length`: the length for a period or a beat rate.

use super::common;
use crate::args::LengthArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::period::{beats_per_hour, length_for_period};
use pendulum_theory::Amplitude;
use serde::Serialize;

#[derive(Serialize)]
struct LengthJson {
    length_m: f64,
    period_s: f64,
    beats_per_hour: f64,
    amplitude_rad: f64,
    g_m_s2: f64,
    g_source: &'static str,
}

pub fn run(args: &LengthArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    // A bad period is refused by the library below, named --period.
    let period = common::period_or_beat_rate(args.period.as_deref(), args.bph.as_deref())?
        .ok_or_else(|| CliError::other("give --period or --bph"))?;
    let amplitude = match &args.amplitude {
        Some(text) => common::amplitude("--amplitude", text)?,
        None => Amplitude::from_radians(0.0).expect("zero is a valid amplitude"),
    };
    // The period came from --bph when --period was not given.
    let flag = if args.period.is_some() {
        "--period"
    } else {
        "--bph"
    };
    let length = length_for_period(period, amplitude, gravity.g_m_s2).map_err(|e| {
        if args.period.is_none() && e.quantity == pendulum_theory::Quantity::Period {
            let bph = beats_per_hour(period);
            CliError::flag(
                flag,
                format!(
                    "out of range: the length it gives is beyond double precision, got {} beats/h",
                    num(bph, 6)
                ),
            )
        } else {
            CliError::input(flag, &e)
        }
    })?;
    let result = LengthJson {
        length_m: length,
        period_s: period,
        beats_per_hour: beats_per_hour(period),
        amplitude_rad: amplitude.radians(),
        g_m_s2: gravity.g_m_s2,
        g_source: gravity.g_source,
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    s.row(
        "Length",
        format!("{} m  ({} mm)", num(length, 10), num(length * 1000.0, 8)),
    )
    .row("Period", format!("{} s", num(period, 12)))
    .row("Beats per hour", num(result.beats_per_hour, 10))
    .row("Amplitude", format!("{}°", num(amplitude.degrees(), 10)))
    .row("Gravity", gravity.describe());
    Ok(s.render())
}
