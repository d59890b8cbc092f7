//! `pendulum amplitude`: the amplitude a measured period implies.

use super::common;
use crate::args::AmplitudeArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::period::inverse::{amplitude, AmplitudeResult};
use serde::Serialize;

/// The command's JSON: where g came from, and the library's result.
#[derive(Serialize)]
struct AmplitudeJson<'a> {
    #[serde(flatten)]
    result: &'a AmplitudeResult,
    g_source: &'static str,
}

pub fn run(args: &AmplitudeArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let common::Reduced {
        pendulum,
        elastic_share,
    } = common::reduced(
        args.pendulum.length,
        args.pendulum.design.as_deref(),
        &gravity,
    )?;
    let period = args.period.0;
    let uncertainty = args.period_uncertainty.map(|t| t.0);
    let r = amplitude(
        pendulum.length_m(),
        Some(pendulum.g_m_s2()),
        period,
        uncertainty,
        (elastic_share > 0.0).then_some(elastic_share),
    )
    .map_err(|e| common::refused(&e))?;
    let result = AmplitudeJson {
        result: &r,
        g_source: gravity.g_source,
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    let a = r.amplitude_rad;
    let interval = r.amplitude_low_rad.zip(r.amplitude_high_rad);
    let amplitude = match interval {
        // Below T0 the measurement bounds the amplitude only from above.
        Some((_, high)) if r.amplitude_upper_bound_rad.is_some() => format!(
            "{}°  ({} rad); not determined within the period's uncertainty: \
             at most {}°",
            num(r.amplitude_deg, 8),
            num(a, 8),
            num(high.to_degrees(), 3)
        ),
        // A symmetric ± where the interval is nearly so, else its ends.
        Some((low, high)) if (high - a - (a - low)).abs() < 0.1 * (high - low) => {
            format!(
                "{}° ± {}°  ({} rad)",
                num(r.amplitude_deg, 8),
                num(0.5 * (high - low).to_degrees(), 3),
                num(a, 8)
            )
        }
        Some((low, high)) => format!(
            "{}°, between {}° and {}°  ({} rad)",
            num(r.amplitude_deg, 8),
            num(low.to_degrees(), 3),
            num(high.to_degrees(), 3),
            num(a, 8)
        ),
        None => format!("{}°  ({} rad)", num(r.amplitude_deg, 8), num(a, 8)),
    };
    let conditioning = if let Some(k) = r.condition_number {
        format!(
            "{}: an error of 1 ppm in the period moves the amplitude by {} ppm",
            num(k, 3),
            num(k, 3)
        )
    } else {
        "not determined: at the small-angle period the amplitude has no finite \
         sensitivity to the period"
            .to_string()
    };
    s.row("Amplitude", amplitude)
        .row("Conditioning", conditioning)
        .row("Precision", precision_note(&r))
        .row("Period", format!("{} s", num(r.period_s, 12)))
        .row(
            "Small-angle period",
            format!("{} s", num(r.small_angle_period_s, 12)),
        )
        .row("Length", format!("{} m", num(r.length_m, 10)))
        .row("Gravity", gravity.describe());
    Ok(s.render())
}

/// How much of the amplitude the period's last bit already decides (the
/// library's warning when that is much).
fn precision_note(r: &AmplitudeResult) -> String {
    match (r.precision_relative, r.warnings.first()) {
        (_, Some(w)) => format!("warning: {w}"),
        (Some(relative), None) => format!(
            "the amplitude is determined to {} relative by a double-precision period",
            num(relative, 2)
        ),
        (None, None) => {
            "the period equals the small-angle period: the amplitude is zero or too small to tell"
                .into()
        }
    }
}
