//! `pendulum amplitude`: the amplitude a measured period implies.

use super::common::{self, finite};
use crate::args::AmplitudeArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::units::Dimension;
use pendulum_theory::period::amplitude_for_period;
use pendulum_theory::Pendulum;
use serde::Serialize;

#[derive(Serialize)]
struct AmplitudeJson {
    amplitude_rad: f64,
    amplitude_deg: f64,
    /// |d ln A0 / d ln T|; null when infinite (period equal to T0).
    condition_number: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    amplitude_uncertainty_rad: Option<f64>,
    period_s: f64,
    small_angle_period_s: f64,
    length_m: f64,
    g_m_s2: f64,
    g_source: &'static str,
}

pub fn run(args: &AmplitudeArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let pendulum = common::pendulum(&args.length, &gravity)?;
    let period = common::quantity("--period", &args.period, Dimension::Time)?;
    let estimate = solve(&pendulum, period)?;
    let uncertainty = match &args.period_uncertainty {
        Some(text) => {
            let dt = common::quantity("--period-uncertainty", text, Dimension::Time)?;
            if dt < 0.0 {
                return Err(CliError::flag(
                    "--period-uncertainty",
                    format!("must not be negative, got {dt} s"),
                ));
            }
            Some(amplitude_uncertainty(&pendulum, period, dt)?)
        }
        None => None,
    };
    let a = estimate.amplitude;
    let result = AmplitudeJson {
        amplitude_rad: a.radians(),
        amplitude_deg: a.degrees(),
        condition_number: finite(estimate.condition_number),
        amplitude_uncertainty_rad: uncertainty,
        period_s: period,
        small_angle_period_s: pendulum.small_angle_period(),
        length_m: pendulum.length_m(),
        g_m_s2: gravity.g_m_s2,
        g_source: gravity.g_source,
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    let amplitude = match uncertainty {
        Some(da) => format!(
            "{}° ± {}°  ({} rad)",
            num(a.degrees(), 8),
            num(da.to_degrees(), 3),
            num(a.radians(), 8)
        ),
        None => format!("{}°  ({} rad)", num(a.degrees(), 8), num(a.radians(), 8)),
    };
    s.row("Amplitude", amplitude)
        .row(
            "Conditioning",
            format!(
                "{}: an error of 1 ppm in the period moves the amplitude by {} ppm",
                num(estimate.condition_number, 3),
                num(estimate.condition_number, 3)
            ),
        )
        .row("Precision", precision_note(estimate.condition_number))
        .row("Period", format!("{} s", num(period, 12)))
        .row(
            "Small-angle period",
            format!("{} s", num(pendulum.small_angle_period(), 12)),
        )
        .row("Length", format!("{} m", num(pendulum.length_m(), 10)))
        .row("Gravity", gravity.describe());
    Ok(s.render())
}

/// How much of the amplitude the period's last bit already decides: the
/// period and T0 each carry half an ulp, so double precision alone leaves
/// the amplitude uncertain by about `κ ε` relative.
fn precision_note(condition_number: f64) -> String {
    let relative = condition_number * f64::EPSILON;
    if !relative.is_finite() {
        "the period equals the small-angle period: the amplitude is zero or too small to tell"
            .into()
    } else if relative > 1e-6 {
        format!(
            "warning: the period is so close to T0 that double precision alone leaves the amplitude uncertain by {}%",
            num(100.0 * relative, 2)
        )
    } else {
        format!(
            "the amplitude is determined to {} relative by a double-precision period",
            num(relative, 2)
        )
    }
}

fn solve(
    pendulum: &Pendulum,
    period: f64,
) -> Result<pendulum_theory::period::AmplitudeEstimate, CliError> {
    // Every refusal here is about the period: too short, or not positive.
    amplitude_for_period(pendulum, period).map_err(|e| CliError::input("--period", &e))
}

/// Half the spread of the amplitudes implied by `period ± dt` (the lower
/// end clamped at the small-angle period, where the amplitude is zero).
fn amplitude_uncertainty(pendulum: &Pendulum, period: f64, dt: f64) -> Result<f64, CliError> {
    let t0 = pendulum.small_angle_period();
    let high = solve(pendulum, period + dt)?.amplitude.radians();
    let low = solve(pendulum, (period - dt).max(t0))?.amplitude.radians();
    Ok(0.5 * (high - low))
}
