//! The period's inverses as analyses: the length a period (or a beat
//! rate) needs at an amplitude, and the amplitude a measured period
//! implies, with its interval from the period's uncertainty and its
//! conditioning. The command line's `length` and `amplitude` and Python's
//! `length` and `amplitude` are these calls.

use super::table::pendulum;
use super::Nominal;
use super::{amplitude_for_period, beats_per_hour, length_for_period};
use crate::analysis::{finite, require_finite, Refusal};
use crate::error::format_significant;
use crate::pendulum::{Amplitude, STANDARD_GRAVITY};
use crate::period::period_for_beat_rate;
use crate::warning::Warning;
use serde::Serialize;

/// The length a period needs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LengthResult {
    /// Length, m.
    pub length_m: f64,
    /// The period, s.
    pub period_s: f64,
    /// Beats per hour.
    pub beats_per_hour: f64,
    /// The amplitude it swings at, rad.
    pub amplitude_rad: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
}

/// The length for `nominal` (a period or a beat rate) at `amplitude` rad
/// (default 0) under `g` (default standard gravity).
///
/// # Examples
///
/// ```
/// use pendulum_theory::period::{inverse::length, Nominal};
/// use std::f64::consts::PI;
///
/// // The pendulum that beats seconds (a 2 s period) at a small swing: g/π².
/// let r = length(Nominal::Period(2.0), None, None)?;
/// assert!((r.length_m - pendulum_theory::STANDARD_GRAVITY / (PI * PI)).abs() < 1e-12);
/// assert!((r.length_m - 0.99362).abs() < 1e-5);
/// assert_eq!(r.beats_per_hour, 3600.0);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn length(
    nominal: Nominal,
    amplitude: Option<f64>,
    g: Option<f64>,
) -> Result<LengthResult, Refusal> {
    let field = nominal.field();
    let period = match nominal {
        Nominal::Period(p) => p,
        Nominal::BeatsPerHour(b) => {
            period_for_beat_rate(b).map_err(|e| Refusal::input(field, &e))?
        }
    };
    let amplitude = Amplitude::from_radians(amplitude.unwrap_or(0.0))
        .map_err(|e| Refusal::input("amplitude", &e))?;
    let g = require_finite("g", g.unwrap_or(STANDARD_GRAVITY))?;
    let length = length_for_period(period, amplitude, g).map_err(|e| match e.quantity {
        crate::error::Quantity::Gravity => Refusal::input("g", &e),
        crate::error::Quantity::Period if matches!(nominal, Nominal::BeatsPerHour(_)) => {
            Refusal::field(
                field,
                format!(
                    "out of range: the length it gives is beyond double precision, got {} \
                     beats/h",
                    format_significant(beats_per_hour(period), 6)
                ),
            )
        }
        _ => Refusal::input(field, &e),
    })?;
    Ok(LengthResult {
        length_m: length,
        period_s: period,
        beats_per_hour: beats_per_hour(period),
        amplitude_rad: amplitude.radians(),
        g_m_s2: g,
    })
}

/// The relative uncertainty double precision alone leaves in an amplitude
/// beyond which it is a warning.
pub const PRECISION_WARNING: f64 = 1e-6;

/// The amplitude a period implies.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AmplitudeResult {
    /// Amplitude, rad.
    pub amplitude_rad: f64,
    /// Amplitude, degrees.
    pub amplitude_deg: f64,
    /// `|d ln A0 / d ln T|`; null when infinite (the period equal to T0).
    pub condition_number: Option<f64>,
    /// Half the interval's width, rad, with an uncertainty.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_uncertainty_rad: Option<f64>,
    /// The amplitude of the period less its uncertainty (0 where that is
    /// below the small-angle period), rad.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_low_rad: Option<f64>,
    /// The amplitude of the period plus its uncertainty, rad.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_high_rad: Option<f64>,
    /// Set when the period less its uncertainty is below the small-angle
    /// period: the measurement only bounds the amplitude from above.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_upper_bound_rad: Option<f64>,
    /// The period, s.
    pub period_s: f64,
    /// The small-angle period, s.
    pub small_angle_period_s: f64,
    /// Length, m.
    pub length_m: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// The relative uncertainty double precision alone leaves in the
    /// amplitude (`κ ε`); null when infinite.
    pub precision_relative: Option<f64>,
    /// What to know before trusting the amplitude.
    pub warnings: Vec<Warning>,
}

/// The amplitude a pendulum of `length` m under `g` swings at to keep
/// `period` s, with the interval of `period ± uncertainty` if given. On a
/// suspension spring of elastic share `elastic_share` (none or 0: a rigid
/// pivot) the period is [`crate::suspension::period_ratio`]'s, inverted by
/// [`amplitude_on_spring`].
///
/// # Examples
///
/// ```
/// use pendulum_theory::period::inverse::amplitude;
/// use pendulum_theory::{Amplitude, Pendulum};
///
/// // The period a seconds pendulum keeps at 3° gives 3° back, close to the
/// // first-order inverse A = 4 √(T/T0 - 1) of T = T0 (1 + A²/16).
/// let p = Pendulum::with_standard_gravity(0.99362)?;
/// let period = p.period(Amplitude::from_degrees(3.0)?);
/// let r = amplitude(0.99362, None, period, None, None)?;
/// assert!((r.amplitude_deg - 3.0).abs() < 1e-6);
/// assert!((r.amplitude_rad - 4.0 * (period / r.small_angle_period_s - 1.0).sqrt()).abs() < 1e-5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn amplitude(
    length: f64,
    g: Option<f64>,
    period: f64,
    uncertainty: Option<f64>,
    elastic_share: Option<f64>,
) -> Result<AmplitudeResult, Refusal> {
    let pendulum = pendulum(length, g, "length")?;
    let share = crate::suspension::elastic_share(elastic_share)?;
    let solve = |t: f64| -> Result<Estimate, Refusal> {
        if share > 0.0 {
            let p = require_finite("period", t)?;
            let (radians, condition_number) =
                amplitude_on_spring(pendulum.small_angle_period(), p, share)?;
            Ok(Estimate {
                radians,
                condition_number,
            })
        } else {
            amplitude_for_period(&pendulum, t)
                .map(|e| Estimate {
                    radians: e.amplitude.radians(),
                    condition_number: e.condition_number,
                })
                .map_err(|e| Refusal::input("period", &e))
        }
    };
    let estimate = solve(period)?;
    let interval = match uncertainty {
        Some(dt) => {
            if require_finite("period_uncertainty", dt)? < 0.0 {
                return Err(Refusal::field(
                    "period_uncertainty",
                    format!("must not be negative, got {} s", format_significant(dt, 6)),
                ));
            }
            let t0 = pendulum.small_angle_period();
            let high = solve(period + dt)?.radians;
            let clipped = period - dt <= t0;
            let low = solve((period - dt).max(t0))?.radians;
            Some((low, high, clipped))
        }
        None => None,
    };
    let a = Amplitude::from_radians(estimate.radians).map_err(|e| Refusal::input("period", &e))?;
    let relative = estimate.condition_number * f64::EPSILON;
    let mut warnings = Vec::new();
    if relative.is_finite() && relative > PRECISION_WARNING {
        warnings.push(Warning::new(
            "amplitude_imprecise",
            format!(
                "the period is so close to T0 that double precision alone leaves the \
                 amplitude uncertain by {}%",
                format_significant(100.0 * relative, 2)
            ),
            Some("amplitude_rad"),
        ));
    }
    Ok(AmplitudeResult {
        amplitude_rad: a.radians(),
        amplitude_deg: a.degrees(),
        condition_number: finite(estimate.condition_number),
        amplitude_uncertainty_rad: interval.map(|i| 0.5 * (i.1 - i.0)),
        amplitude_low_rad: interval.map(|i| i.0),
        amplitude_high_rad: interval.map(|i| i.1),
        amplitude_upper_bound_rad: interval.filter(|i| i.2).map(|i| i.1),
        period_s: period,
        small_angle_period_s: pendulum.small_angle_period(),
        length_m: pendulum.length_m(),
        g_m_s2: pendulum.g_m_s2(),
        precision_relative: finite(relative),
        warnings,
    })
}

/// An amplitude and its conditioning `|d ln A / d ln T|`.
struct Estimate {
    radians: f64,
    condition_number: f64,
}

/// The amplitude, rad, at which a pendulum on a suspension spring of
/// elastic share `share` (0 to below 1) and small-swing period `t0` s
/// keeps `period` s, and its conditioning `|d ln A / d ln T|`: bisection
/// on [`crate::suspension::period_ratio`], which grows with the amplitude,
/// over `[0, π)` to 1e-15 relative (`period_ratio - 1` against `(T - T0)
/// / T0`, so that small swings keep their digits; the conditioning by a
/// central difference of ±1e-4 of the amplitude). Refused below `t0`, and
/// above the period at 180° (the model's end: a spring's pendulum has a
/// finite period there).
pub fn amplitude_on_spring(t0: f64, period: f64, share: f64) -> Result<(f64, f64), Refusal> {
    use crate::suspension::period_ratio;
    if period.is_nan() || period <= 0.0 {
        return Err(Refusal::field(
            "period",
            format!("must be positive, got {} s", format_significant(period, 6)),
        ));
    }
    if period < t0 {
        return Err(Refusal::field(
            "period",
            format!(
                "is below the small-angle period T0 = {} s, which no swing can keep, got {} s",
                format_significant(t0, 12),
                format_significant(period, 12)
            ),
        ));
    }
    let excess = (period - t0) / t0;
    let top = std::f64::consts::PI.next_down();
    let longest = period_ratio(top, share);
    if excess > longest - 1.0 {
        return Err(Refusal::field(
            "period",
            format!(
                "is longer than this pendulum keeps on its suspension spring at any swing below \
                 180° (at most {} s), got {} s",
                format_significant(t0 * longest, 8),
                format_significant(period, 8)
            ),
        ));
    }
    if excess == 0.0 {
        return Ok((0.0, f64::INFINITY));
    }
    let (mut low, mut high) = (0.0_f64, top);
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if period_ratio(mid, share) - 1.0 < excess {
            low = mid;
        } else {
            high = mid;
        }
        if high - low <= 1e-15 * high {
            break;
        }
    }
    let a = 0.5 * (low + high);
    let h = 1e-4 * a;
    let slope = (period_ratio((a + h).min(top), share) - period_ratio(a - h, share))
        / ((a + h).min(top) - (a - h));
    Ok((a, (1.0 + excess) / (a * slope)))
}
