//! `pendulum length`: the length for a period or a beat rate (one library
//! call, [`pendulum_theory::period::inverse::length`]).

use super::common;
use crate::args::LengthArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::period::inverse::{length, LengthResult};
use serde::Serialize;

/// The command's JSON: where g came from, and the library's result.
#[derive(Serialize)]
struct LengthJson<'a> {
    #[serde(flatten)]
    result: &'a LengthResult,
    g_source: &'static str,
}

pub fn run(args: &LengthArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let nominal = common::nominal(args.period, args.bph)
        .ok_or_else(|| CliError::other("give --period or --bph"))?;
    let amplitude = args.amplitude.map(|a| a.0);
    let r = length(nominal, amplitude, Some(gravity.g_m_s2)).map_err(|e| common::refused(&e))?;
    if args.json {
        return output::json(&LengthJson {
            result: &r,
            g_source: gravity.g_source,
        });
    }
    let mut s = Summary::default();
    s.row(
        "Length",
        format!(
            "{} m  ({} mm)",
            num(r.length_m, 10),
            num(r.length_m * 1000.0, 8)
        ),
    )
    .row("Period", format!("{} s", num(r.period_s, 12)))
    .row("Beats per hour", num(r.beats_per_hour, 10))
    .row(
        "Amplitude",
        format!("{}°", num(r.amplitude_rad.to_degrees(), 10)),
    )
    .row("Gravity", gravity.describe());
    Ok(s.render())
}
