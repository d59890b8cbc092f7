//! Viscous damping (seed section 1-4), described in whichever form the user
//! has: the seed's coefficient `c`, the damping ratio `ζ`, the quality factor
//! `Q`, the logarithmic decrement per full period `δ`, or the amplitude
//! decay time `τ`. One canonical number, `ζ`, is stored; every form converts
//! to and from it in closed form:
//!
//! * `ζ = c / (2 m sqrt(g l))` (the seed's definition, with the force on the
//!   bob `c dθ/dt`);
//! * `Q = 1 / (2ζ)`;
//! * `δ = 2π ζ / sqrt(1 - ζ²)`, so `ζ = δ / sqrt(4π² + δ²)` (defined for
//!   `ζ < 1` only: an overdamped pendulum has no period);
//! * `τ = 1 / (ζ ω_n)`, the time for the amplitude to fall by `e`, and the
//!   half-life `τ ln 2`.
//!
//! `1 - ζ²` is formed as `(1 - ζ)(1 + ζ)`, which keeps its relative accuracy
//! as `ζ -> 1`. Round trips through every form return `ζ` within a few ulp
//! (property-tested in this module).

use crate::error::{require_non_negative, require_positive, InputError, Quantity};
use crate::pendulum::Pendulum;
use std::f64::consts::{LN_2, TAU};

/// A viscous damping, stored as its ratio `ζ >= 0` to critical damping.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Damping {
    zeta: f64,
}

impl Damping {
    /// No damping at all.
    pub const NONE: Damping = Damping { zeta: 0.0 };

    /// A damping ratio of either sign, for a fitted model only: the fit of
    /// a record with no damping to measure must be free to cross 0 (its
    /// noise puts the best `ζ` on either side; a model held at 0 below it
    /// has no slope there, and the fit no covariance). A negative `ζ` is a
    /// swing that grows, which the fit's own warnings then say.
    pub(crate) fn of_either_sign(zeta: f64) -> Option<Self> {
        zeta.is_finite().then_some(Self { zeta })
    }

    /// From the damping ratio `ζ >= 0` (`ζ = 1` is critical damping).
    pub fn from_zeta(zeta: f64) -> Result<Self, InputError> {
        Ok(Self {
            zeta: require_non_negative(Quantity::DampingRatio, zeta)?,
        })
    }

    /// From a `ζ` computed from `value` of `quantity`: an overflow (or an
    /// underflow to zero from a positive input) is said of that input.
    fn derived(quantity: Quantity, value: f64, zeta: f64) -> Result<Self, InputError> {
        if !zeta.is_finite() || zeta == 0.0 {
            return Err(InputError::new(
                quantity,
                value,
                crate::error::Problem::ResultOverflows {
                    result: "the damping ratio ζ",
                },
            ));
        }
        Self::from_zeta(zeta)
    }

    /// From the quality factor `Q > 0`: `ζ = 1/(2Q)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use pendulum_theory::damping::Damping;
    ///
    /// // A good regulator, Q = 10,000: ζ = 1/(2Q), and a logarithmic decrement
    /// // per period of 2πζ/√(1 - ζ²).
    /// let d = Damping::from_q(10_000.0)?;
    /// assert_eq!(d.zeta(), 5e-5);
    /// let delta = std::f64::consts::TAU * 5e-5 / (1.0 - 25e-10_f64).sqrt();
    /// assert!((d.log_decrement().unwrap() - delta).abs() < 1e-18);
    /// # Ok::<(), pendulum_theory::InputError>(())
    /// ```
    pub fn from_q(q_factor: f64) -> Result<Self, InputError> {
        let q = require_positive(Quantity::QualityFactor, q_factor)?;
        Self::derived(Quantity::QualityFactor, q, 0.5 / q)
    }

    /// From the logarithmic decrement per full period `δ > 0`:
    /// `ζ = δ / sqrt(4π² + δ²)`.
    pub fn from_log_decrement(delta: f64) -> Result<Self, InputError> {
        let d = require_positive(Quantity::LogDecrement, delta)?;
        Self::from_zeta(d / TAU.hypot(d))
    }

    /// From the seed's coefficient `c` (N m s, the torque per unit angular
    /// velocity divided by the length: the force on the bob is `c dθ/dt`)
    /// and the bob's mass `m` (kg): `ζ = c / (2 m sqrt(g l))`.
    pub fn from_coefficient(c: f64, mass_kg: f64, pendulum: &Pendulum) -> Result<Self, InputError> {
        let c = require_positive(Quantity::DampingCoefficient, c)?;
        let m = require_positive(Quantity::Mass, mass_kg)?;
        let zeta = c / (2.0 * m * (pendulum.g_m_s2() * pendulum.length_m()).sqrt());
        // An overflow is the mass's fault when it is the extreme one.
        let (quantity, value) = if m < 1e-6 && c <= 1e6 {
            (Quantity::Mass, m)
        } else {
            (Quantity::DampingCoefficient, c)
        };
        Self::derived(quantity, value, zeta)
    }

    /// From the amplitude decay time `τ > 0` (s): `ζ = 1/(τ ω_n)`.
    pub fn from_decay_time(tau_s: f64, pendulum: &Pendulum) -> Result<Self, InputError> {
        let tau = require_positive(Quantity::DecayTime, tau_s)?;
        Self::derived(
            Quantity::DecayTime,
            tau,
            1.0 / (tau * pendulum.natural_angular_frequency()),
        )
    }

    /// The damping ratio `ζ`.
    pub fn zeta(&self) -> f64 {
        self.zeta
    }

    /// `Q = 1/(2ζ)`; infinite without damping.
    pub fn q_factor(&self) -> f64 {
        0.5 / self.zeta
    }

    /// `sqrt(1 - ζ²)`, from `(1 - ζ)(1 + ζ)`; `None` unless underdamped.
    pub fn damped_frequency_factor(&self) -> Option<f64> {
        (self.zeta < 1.0).then(|| ((1.0 - self.zeta) * (1.0 + self.zeta)).sqrt())
    }

    /// The logarithmic decrement per full period, `2π ζ / sqrt(1 - ζ²)`;
    /// `None` when critically damped or overdamped (no period).
    pub fn log_decrement(&self) -> Option<f64> {
        self.damped_frequency_factor().map(|s| TAU * self.zeta / s)
    }

    /// The seed's coefficient `c = 2 m ζ sqrt(g l)` for a bob of `mass_kg`.
    pub fn coefficient(&self, mass_kg: f64, pendulum: &Pendulum) -> f64 {
        2.0 * mass_kg * self.zeta * (pendulum.g_m_s2() * pendulum.length_m()).sqrt()
    }

    /// The amplitude decay time `τ = 1/(ζ ω_n)`, s; infinite without damping.
    pub fn decay_time(&self, pendulum: &Pendulum) -> f64 {
        1.0 / (self.zeta * pendulum.natural_angular_frequency())
    }

    /// The time for the amplitude to halve, `τ ln 2`, s.
    pub fn amplitude_half_life(&self, pendulum: &Pendulum) -> f64 {
        LN_2 * self.decay_time(pendulum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn close(a: f64, b: f64, ulps: f64) -> bool {
        (a - b).abs() <= ulps * f64::EPSILON * a.abs().max(b.abs())
    }

    #[test]
    fn refusals() {
        assert!(Damping::from_zeta(-1e-3).is_err());
        assert!(Damping::from_zeta(f64::NAN).is_err());
        assert!(Damping::from_q(0.0).is_err());
        assert!(Damping::from_log_decrement(-0.1).is_err());
        let p = Pendulum::with_standard_gravity(1.0).unwrap();
        assert!(Damping::from_coefficient(0.1, 0.0, &p).is_err());
        assert!(Damping::from_decay_time(0.0, &p).is_err());
    }

    #[test]
    fn regimes_without_a_decrement() {
        assert_eq!(Damping::from_zeta(1.0).unwrap().log_decrement(), None);
        assert_eq!(Damping::from_zeta(3.0).unwrap().log_decrement(), None);
        assert_eq!(Damping::NONE.q_factor(), f64::INFINITY);
    }

    proptest! {
        #[test]
        fn round_trips(log_zeta in -7.0_f64..1.0, length in 0.05_f64..20.0, mass in 0.01_f64..50.0) {
            let zeta = 10f64.powf(log_zeta);
            let d = Damping::from_zeta(zeta).unwrap();
            let p = Pendulum::with_standard_gravity(length).unwrap();
            prop_assert!(close(Damping::from_q(d.q_factor()).unwrap().zeta(), zeta, 2.0));
            let c = d.coefficient(mass, &p);
            prop_assert!(close(Damping::from_coefficient(c, mass, &p).unwrap().zeta(), zeta, 6.0));
            let tau = d.decay_time(&p);
            prop_assert!(close(Damping::from_decay_time(tau, &p).unwrap().zeta(), zeta, 6.0));
            if let Some(delta) = d.log_decrement() {
                prop_assert!(close(Damping::from_log_decrement(delta).unwrap().zeta(), zeta, 6.0));
            }
        }
    }
}
