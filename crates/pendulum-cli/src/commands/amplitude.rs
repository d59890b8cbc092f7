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
    /// The amplitudes of the period minus and plus its uncertainty (the
    /// lower clipped at 0 where that period is below the small-angle one).
    #[serde(skip_serializing_if = "Option::is_none")]
    amplitude_low_rad: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    amplitude_high_rad: Option<f64>,
    /// Set when the period minus its uncertainty is below the small-angle
    /// period: the measurement then only bounds the amplitude from above.
    #[serde(skip_serializing_if = "Option::is_none")]
    amplitude_upper_bound_rad: Option<f64>,
    period_s: f64,
    small_angle_period_s: f64,
    length_m: f64,
    g_m_s2: f64,
    g_source: &'static str,
}

pub fn run(args: &AmplitudeArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let pendulum = common::pendulum_of(args.length.as_deref(), args.design.as_deref(), &gravity)?;
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
            Some(amplitude_interval(&pendulum, period, dt)?)
        }
        None => None,
    };
    let a = estimate.amplitude;
    let result = AmplitudeJson {
        amplitude_rad: a.radians(),
        amplitude_deg: a.degrees(),
        condition_number: finite(estimate.condition_number),
        amplitude_uncertainty_rad: uncertainty.map(|i| 0.5 * (i.high - i.low)),
        amplitude_low_rad: uncertainty.map(|i| i.low),
        amplitude_high_rad: uncertainty.map(|i| i.high),
        amplitude_upper_bound_rad: uncertainty.filter(|i| i.clipped).map(|i| i.high),
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
        // Below T0 the measurement bounds the amplitude only from above.
        Some(i) if i.clipped => format!(
            "{}°  ({} rad); not determined within the period's uncertainty: \
             at most {}°",
            num(a.degrees(), 8),
            num(a.radians(), 8),
            num(i.high.to_degrees(), 3)
        ),
        // A symmetric ± where the interval is nearly so, else its ends.
        Some(i)
            if (i.high - a.radians() - (a.radians() - i.low)).abs() < 0.1 * (i.high - i.low) =>
        {
            format!(
                "{}° ± {}°  ({} rad)",
                num(a.degrees(), 8),
                num(0.5 * (i.high - i.low).to_degrees(), 3),
                num(a.radians(), 8)
            )
        }
        Some(i) => format!(
            "{}°, between {}° and {}°  ({} rad)",
            num(a.degrees(), 8),
            num(i.low.to_degrees(), 3),
            num(i.high.to_degrees(), 3),
            num(a.radians(), 8)
        ),
        None => format!("{}°  ({} rad)", num(a.degrees(), 8), num(a.radians(), 8)),
    };
    let conditioning = if estimate.condition_number.is_finite() {
        format!(
            "{}: an error of 1 ppm in the period moves the amplitude by {} ppm",
            num(estimate.condition_number, 3),
            num(estimate.condition_number, 3)
        )
    } else {
        "not determined: at the small-angle period the amplitude has no finite \
         sensitivity to the period"
            .to_string()
    };
    s.row("Amplitude", amplitude)
        .row("Conditioning", conditioning)
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

/// The amplitudes implied by `period ± dt`.
#[derive(Clone, Copy)]
struct Interval {
    low: f64,
    high: f64,
    /// `period - dt` was below the small-angle period (`low` is then 0).
    clipped: bool,
}

/// The amplitudes implied by `period ± dt`: the lower end clipped at the
/// small-angle period, where the amplitude is zero; the upper end always
/// below 180°, since the period grows without bound there.
fn amplitude_interval(pendulum: &Pendulum, period: f64, dt: f64) -> Result<Interval, CliError> {
    let t0 = pendulum.small_angle_period();
    let high = solve(pendulum, period + dt)?.amplitude.radians();
    let clipped = period - dt <= t0;
    let low = solve(pendulum, (period - dt).max(t0))?.amplitude.radians();
    Ok(Interval { low, high, clipped })
}
