//! Typed errors for inputs that no physics can be computed from.
//!
//! The library says *which* quantity is wrong and *why*, in SI units; the
//! command-line program adds the name of the flag the user typed. Messages
//! read well after a flag name: `--length: must be positive, got -1 m`.

use std::fmt;

/// The physical input a problem is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Pendulum length (m).
    Length,
    /// Gravitational acceleration (m/s²).
    Gravity,
    /// Amplitude of swing (rad; shown in degrees).
    Amplitude,
    /// Period of a full swing (s).
    Period,
    /// Beats per hour (1/h).
    BeatRate,
    /// Geodetic latitude (degrees).
    Latitude,
    /// Height above the ellipsoid (m).
    Height,
    /// Number of terms of a series.
    SeriesTerms,
    /// Viscous damping ratio ζ (dimensionless).
    DampingRatio,
    /// Quality factor Q (dimensionless).
    QualityFactor,
    /// Logarithmic decrement per full period (dimensionless).
    LogDecrement,
    /// The seed's viscous damping coefficient c (N s).
    DampingCoefficient,
    /// Bob mass (kg).
    Mass,
    /// Amplitude decay time (s).
    DecayTime,
    /// Coulomb friction angle (rad; shown in degrees).
    FrictionAngle,
    /// Quadratic drag coefficient (per radian).
    QuadraticDrag,
    /// Simulated duration (s).
    Duration,
    /// Integration tolerance (dimensionless).
    Tolerance,
    /// Time between samples (s).
    SampleInterval,
    /// An escapement's lift: the angle over which it impulses the
    /// pendulum (rad).
    LiftAngle,
    /// The time the pendulum takes to cross the lift (s).
    LiftTime,
}

impl Quantity {
    /// A short name for messages ("length", "amplitude").
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Length => "length",
            Quantity::Gravity => "gravity",
            Quantity::Amplitude => "amplitude",
            Quantity::Period => "period",
            Quantity::BeatRate => "beat rate",
            Quantity::Latitude => "latitude",
            Quantity::Height => "height",
            Quantity::SeriesTerms => "series terms",
            Quantity::DampingRatio => "damping ratio",
            Quantity::QualityFactor => "Q",
            Quantity::LogDecrement => "logarithmic decrement",
            Quantity::DampingCoefficient => "damping coefficient",
            Quantity::Mass => "mass",
            Quantity::DecayTime => "decay time",
            Quantity::FrictionAngle => "friction angle",
            Quantity::QuadraticDrag => "quadratic drag",
            Quantity::Duration => "duration",
            Quantity::Tolerance => "tolerance",
            Quantity::SampleInterval => "sample interval",
            Quantity::LiftAngle => "lift angle",
            Quantity::LiftTime => "lift time",
        }
    }

    /// Formats a value of this quantity (given in SI, angles in radians,
    /// latitude in degrees) with its unit, to ten significant digits.
    pub fn format_value(self, value: f64) -> String {
        match self {
            Quantity::Length | Quantity::Height => format!("{} m", significant(value)),
            Quantity::Gravity => format!("{} m/s²", significant(value)),
            Quantity::Amplitude | Quantity::FrictionAngle | Quantity::LiftAngle => {
                format!("{}°", significant(value.to_degrees()))
            }
            Quantity::Period
            | Quantity::DecayTime
            | Quantity::Duration
            | Quantity::SampleInterval
            | Quantity::LiftTime => {
                format!("{} s", significant(value))
            }
            Quantity::DampingCoefficient => format!("{} N s", significant(value)),
            Quantity::Mass => format!("{} kg", significant(value)),
            Quantity::DampingRatio
            | Quantity::QualityFactor
            | Quantity::LogDecrement
            | Quantity::QuadraticDrag
            | Quantity::Tolerance => significant(value),
            Quantity::BeatRate => format!("{} beats/h", significant(value)),
            Quantity::Latitude => format!("{}°", significant(value)),
            Quantity::SeriesTerms => significant(value),
        }
    }
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why a value was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Problem {
    /// NaN or infinite.
    NotFinite,
    /// Zero or negative where only positive values mean anything.
    NotPositive,
    /// Negative where zero is allowed.
    Negative,
    /// An amplitude of 180 degrees or more.
    AmplitudeAtLeastHalfTurn,
    /// A period shorter than the small-angle period, which no amplitude gives.
    PeriodBelowSmallAngle {
        /// The small-angle period `2π sqrt(l/g)`, s.
        small_angle_period: f64,
    },
    /// A latitude outside [-90, 90] degrees.
    LatitudeOutOfRange,
    /// More than the largest supported value.
    AboveMaximum {
        /// The largest value accepted, in the quantity's units.
        maximum: f64,
    },
    /// Less than the smallest supported value.
    BelowMinimum {
        /// The smallest value accepted, in the quantity's units.
        minimum: f64,
    },
    /// So large or small that a result computed from it overflows (or
    /// underflows to zero).
    ResultOverflows {
        /// What overflows ("the length").
        result: &'static str,
    },
}

/// A refused input: which quantity, the value given, and why.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{quantity}: {}", self.detail())]
pub struct InputError {
    /// The quantity that was wrong.
    pub quantity: Quantity,
    /// The value given, in SI (angles in radians, latitude in degrees).
    pub value: f64,
    /// What is wrong with it.
    pub problem: Problem,
}

impl InputError {
    /// Builds the error.
    pub fn new(quantity: Quantity, value: f64, problem: Problem) -> Self {
        Self {
            quantity,
            value,
            problem,
        }
    }

    /// The message without the quantity's name, for a caller that prefixes
    /// its own (a flag name): `must be positive, got -1 m`.
    pub fn detail(&self) -> String {
        let got = if self.value.is_finite() {
            self.quantity.format_value(self.value)
        } else if self.value.is_nan() {
            "a value that is not a number".to_string()
        } else {
            "an infinite value".to_string()
        };
        let q = self.quantity;
        match self.problem {
            Problem::NotFinite => format!("must be a finite number, got {got}"),
            Problem::NotPositive => format!("must be positive, got {got}"),
            Problem::Negative => format!("must not be negative, got {got}"),
            Problem::AmplitudeAtLeastHalfTurn => format!(
                "must be less than 180°, got {got}: the pendulum would balance inverted and never return"
            ),
            Problem::PeriodBelowSmallAngle { small_angle_period } => format!(
                "must be at least the small-angle period {}, got {got}: no amplitude gives a shorter period",
                q.format_value(small_angle_period)
            ),
            Problem::LatitudeOutOfRange => {
                format!("must lie between -90° and 90°, got {got}")
            }
            Problem::AboveMaximum { maximum } => {
                format!("must be at most {}, got {got}", q.format_value(maximum))
            }
            Problem::BelowMinimum { minimum } => {
                format!("must be at least {}, got {got}", q.format_value(minimum))
            }
            Problem::ResultOverflows { result } => {
                format!("out of range: {result} it gives is beyond double precision, got {got}")
            }
        }
    }
}

/// Checks that `value` is finite and positive.
pub(crate) fn require_positive(quantity: Quantity, value: f64) -> Result<f64, InputError> {
    if !value.is_finite() {
        Err(InputError::new(quantity, value, Problem::NotFinite))
    } else if value <= 0.0 {
        Err(InputError::new(quantity, value, Problem::NotPositive))
    } else {
        Ok(value)
    }
}

/// Checks that `value` is finite and not negative.
pub(crate) fn require_non_negative(quantity: Quantity, value: f64) -> Result<f64, InputError> {
    if !value.is_finite() {
        Err(InputError::new(quantity, value, Problem::NotFinite))
    } else if value < 0.0 {
        Err(InputError::new(quantity, value, Problem::Negative))
    } else {
        Ok(value)
    }
}

/// Checks a friction angle (rad): not negative, and below a half turn
/// (friction that holds the pendulum at every angle is no friction law).
pub(crate) fn require_friction_angle(value: f64) -> Result<f64, InputError> {
    let r = require_non_negative(Quantity::FrictionAngle, value)?;
    if r >= std::f64::consts::PI {
        return Err(InputError::new(
            Quantity::FrictionAngle,
            r,
            Problem::AboveMaximum {
                maximum: std::f64::consts::PI,
            },
        ));
    }
    Ok(r)
}

/// Checks that `value` is finite.
pub(crate) fn require_finite(quantity: Quantity, value: f64) -> Result<f64, InputError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(InputError::new(quantity, value, Problem::NotFinite))
    }
}

/// Ten significant digits, trailing zeros removed: `-1`, `0.99362`, `1.5e-7`.
pub fn significant(value: f64) -> String {
    format_significant(value, 10)
}

/// `value` to `digits` significant digits for people: fixed notation from
/// 1e-4 to 1e10, scientific outside, trailing zeros dropped (`6.58`,
/// `1.5e-12`, `2.5e12`).
pub fn format_significant(value: f64, digits: usize) -> String {
    if value == 0.0 || !value.is_finite() {
        return format!("{value}");
    }
    let exponent = value.abs().log10().floor() as i32;
    if (-4..10).contains(&exponent) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        trim_zeros(&format!("{value:.decimals$}"))
    } else {
        let text = format!("{value:.*e}", digits.saturating_sub(1));
        match text.split_once('e') {
            Some((mantissa, exp)) => format!("{}e{exp}", trim_zeros(mantissa)),
            None => text,
        }
    }
}

fn trim_zeros(text: &str) -> String {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn message_reads_after_a_flag_name() {
        let e = InputError::new(Quantity::Length, -1.0, Problem::NotPositive);
        assert_eq!(e.detail(), "must be positive, got -1 m");
        assert_eq!(e.to_string(), "length: must be positive, got -1 m");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(-1.0), "-1");
        assert_eq!(significant(0.99362), "0.99362");
        assert_eq!(significant(180.00000000000003), "180");
        assert_eq!(significant(1.5e-7), "1.5e-7");
        assert_eq!(significant(2.5e12), "2.5e12");
    }
}
