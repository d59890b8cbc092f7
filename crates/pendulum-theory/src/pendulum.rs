//! The simple pendulum as a value: its length, the local gravity, and the
//! amplitude of a swing.

use crate::elliptic::Modulus;
use crate::error::{require_non_negative, require_positive, InputError, Problem, Quantity};
use std::f64::consts::{PI, TAU};

/// Standard gravity, 9.80665 m/s² (CGPM 1901, exact by definition).
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// Longer clock pendulums than this are not built (Big Ben's is 3.9 m, the
/// longest turret clocks' about 15 m), m: a longer one is most likely
/// sizes meant in millimetres written as bare numbers, which are metres.
pub const LONGEST_CLOCK_PENDULUM_M: f64 = 30.0;

/// A warning for a clock pendulum of (equivalent) length `length` m longer
/// than [`LONGEST_CLOCK_PENDULUM_M`], naming the likely cause.
pub fn length_warning(length: f64) -> Option<String> {
    (length > LONGEST_CLOCK_PENDULUM_M).then(|| {
        format!(
            "a pendulum {} m long is longer than any clock's: were sizes in millimetres \
             given as bare numbers (which are metres)?",
            crate::error::format_significant(length, 4)
        )
    })
}

/// A simple pendulum: a point mass on a massless rod of length `l` in a
/// uniform field `g` (seed section 1-1). Both are positive and finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pendulum {
    length: f64,
    gravity: f64,
    /// `2π sqrt(l/g)`, kept because every period evaluation needs it.
    small_angle_period: f64,
}

impl Pendulum {
    /// A pendulum of `length_m` metres under `g_m_s2` m/s²; both positive,
    /// and `g/l` within the range of double precision.
    pub fn new(length_m: f64, g_m_s2: f64) -> Result<Self, InputError> {
        let length = require_positive(Quantity::Length, length_m)?;
        let gravity = require_positive(Quantity::Gravity, g_m_s2)?;
        // g/l and l/g must both be normal doubles, or the frequency or the
        // period overflows (a length of 1e-310 m under standard gravity).
        let ratio = gravity / length;
        if !ratio.is_normal() || !(1.0 / ratio).is_normal() {
            // Blame the one that is out of the ordinary.
            let (quantity, value) = if (1e-150..1e150).contains(&length) {
                (Quantity::Gravity, gravity)
            } else {
                (Quantity::Length, length)
            };
            return Err(InputError::new(
                quantity,
                value,
                Problem::ResultOverflows {
                    result: "the frequency (sqrt(g/l))",
                },
            ));
        }
        Ok(Self {
            length,
            gravity,
            small_angle_period: TAU * (length / gravity).sqrt(),
        })
    }

    /// A pendulum of `length_m` metres under standard gravity.
    pub fn with_standard_gravity(length_m: f64) -> Result<Self, InputError> {
        Self::new(length_m, STANDARD_GRAVITY)
    }

    /// The length, m.
    pub fn length_m(&self) -> f64 {
        self.length
    }

    /// The gravitational acceleration, m/s².
    pub fn g_m_s2(&self) -> f64 {
        self.gravity
    }

    /// `ω_n = sqrt(g/l)`, rad/s (seed section 1-4).
    pub fn natural_angular_frequency(&self) -> f64 {
        (self.gravity / self.length).sqrt()
    }

    /// The small-angle period `T0 = 2π sqrt(l/g)`, s (seed section 1-1).
    pub fn small_angle_period(&self) -> f64 {
        self.small_angle_period
    }
}

/// The amplitude of a swing from rest: the largest angle from the vertical,
/// `0 <= A0 < π`. At `π` the pendulum balances inverted and never returns.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Amplitude {
    radians: f64,
}

impl Amplitude {
    /// No swing: the pendulum at rest.
    pub const ZERO: Amplitude = Amplitude { radians: 0.0 };

    /// An amplitude of `radians`.
    pub fn from_radians(radians: f64) -> Result<Self, InputError> {
        let q = Quantity::Amplitude;
        let radians = require_non_negative(q, radians)?;
        if radians >= PI {
            return Err(InputError::new(
                q,
                radians,
                Problem::AmplitudeAtLeastHalfTurn,
            ));
        }
        Ok(Self { radians })
    }

    /// An amplitude of `degrees`.
    pub fn from_degrees(degrees: f64) -> Result<Self, InputError> {
        Self::from_radians(degrees.to_radians())
    }

    /// The amplitude in radians.
    pub fn radians(&self) -> f64 {
        self.radians
    }

    /// The amplitude in degrees.
    pub fn degrees(&self) -> f64 {
        self.radians.to_degrees()
    }

    /// The elliptic modulus of the swing: `k = sin(A0/2)`, `k' = cos(A0/2)`
    /// (seed section 1-6, the substitution `sin(θ/2) = k sin φ`).
    #[inline]
    pub fn modulus(&self) -> Modulus {
        // A0/2 is exact and below π/2, so the constructor cannot refuse it.
        Modulus::from_modular_angle(0.5 * self.radians).expect("0 <= A0/2 < π/2")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_nonsense() {
        assert!(Pendulum::new(-1.0, 9.8).is_err());
        assert!(Pendulum::new(1.0, 0.0).is_err());
        assert!(Pendulum::new(f64::NAN, 9.8).is_err());
        assert!(Amplitude::from_degrees(180.0).is_err());
        assert!(Amplitude::from_radians(-0.1).is_err());
        assert!(Amplitude::from_radians(f64::INFINITY).is_err());
        assert!(Amplitude::from_radians(PI.next_down()).is_ok());
    }

    #[test]
    fn small_angle_period_of_seconds_pendulum() {
        let p = Pendulum::with_standard_gravity(STANDARD_GRAVITY / (PI * PI)).unwrap();
        assert!((p.small_angle_period() - 2.0).abs() < 4.0 * f64::EPSILON);
    }
}
