//! The energy budget of a swinging pendulum: what it stores, what it loses,
//! and the impulse an escapement must give to hold the amplitude.
//!
//! Stored energy at amplitude `A`: `m g l (1 - cos A) = 2 m g l sin²(A/2)`
//! (exact, not the small-angle `m g l A²/2`). Over a half swing the amplitude
//! falls from `A` to `A1`; the energy lost, `2 m g l (sin²(A/2) - sin²(A1/2))`,
//! is formed as `2 m g l sin((A - A1)/2) sin((A + A1)/2)`, which keeps its
//! digits when the loss is a part in 10^7 of the energy (a clock pendulum with
//! `Q = 10^4`). To hold the amplitude, an escapement must restore that energy
//! every beat; given as a short impulse at the bottom of the swing (Airy's
//! condition for no escapement error), where the angular velocity is
//! `Ω = 2 ω_n sin(A/2)`, an angular impulse `J` adds `Ω J` of energy
//! (to first order in `J`), so `J = ΔE_beat / Ω`.

use crate::error::{require_positive, InputError, Problem, Quantity};
use crate::pendulum::Pendulum;

/// The energy budget at one amplitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnergyBudget {
    /// Energy stored in the swing, J.
    pub energy: f64,
    /// Energy lost per full period (two beats) at this amplitude, J.
    pub loss_per_period: f64,
    /// Mean power dissipated, W.
    pub power: f64,
    /// Angular impulse per beat that holds the amplitude, kg m²/s.
    pub impulse_per_beat: f64,
}

/// The budget of a bob of `mass_kg` on `pendulum` swinging at `amplitude`
/// (rad) that loses `half_swing_loss` (rad) of amplitude per beat, with a
/// full period of `period` (s). The mass must be positive; at rest (zero
/// amplitude) every figure is 0 (the impulse's limit too); a budget that
/// overflows (a pendulum of 1e300 m) is refused, attributed to whichever
/// of the mass, the length and g lies furthest from 1 in its unit.
pub fn energy_budget(
    pendulum: &Pendulum,
    mass_kg: f64,
    amplitude: f64,
    half_swing_loss: f64,
    period: f64,
) -> Result<EnergyBudget, InputError> {
    let mass_kg = require_positive(Quantity::Mass, mass_kg)?;
    let a = amplitude.abs();
    let a1 = a - half_swing_loss;
    let weight_moment = mass_kg * pendulum.g_m_s2() * pendulum.length_m();
    let energy = 2.0 * weight_moment * (0.5 * a).sin().powi(2);
    let loss_per_beat =
        2.0 * weight_moment * (0.5 * half_swing_loss).sin() * (0.5 * (a + a1)).sin();
    let bottom_speed = 2.0 * pendulum.natural_angular_frequency() * (0.5 * a).sin();
    let budget = EnergyBudget {
        energy,
        loss_per_period: 2.0 * loss_per_beat,
        power: 2.0 * loss_per_beat / period,
        // At rest nothing is lost and nothing given: the limit 0, not 0/0.
        impulse_per_beat: if loss_per_beat == 0.0 {
            0.0
        } else {
            loss_per_beat / bottom_speed
        },
    };
    let values = [
        budget.energy,
        budget.loss_per_period,
        budget.power,
        budget.impulse_per_beat,
    ];
    if values.iter().any(|v| !v.is_finite()) {
        let factors = [
            (Quantity::Mass, mass_kg),
            (Quantity::Length, pendulum.length_m()),
            (Quantity::Gravity, pendulum.g_m_s2()),
        ];
        let (quantity, value) = factors
            .into_iter()
            .max_by(|a, b| a.1.log10().abs().total_cmp(&b.1.log10().abs()))
            .unwrap_or((Quantity::Length, pendulum.length_m()));
        return Err(InputError::new(
            quantity,
            value,
            Problem::ResultOverflows {
                result: "the energy budget",
            },
        ));
    }
    Ok(budget)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_angle_limits() {
        // Q = 10^4 seconds pendulum at 3°, 1 kg: E ≈ m g l A²/2, the loss per
        // period ≈ (2π/Q) E, and J ≈ (loss/2) / (ω A).
        let p = Pendulum::with_standard_gravity(0.99362).unwrap();
        let a = 3.0_f64.to_radians();
        let q = 1e4;
        let half_loss = a * (std::f64::consts::PI / (2.0 * q)); // δ/2 per beat, first order
        let b = energy_budget(&p, 1.0, a, half_loss, 2.0).unwrap();
        assert!(energy_budget(&p, 0.0, a, half_loss, 2.0).is_err());
        let e_small = 9.80665 * 0.99362 * a * a / 2.0;
        assert!((b.energy / e_small - 1.0).abs() < 1e-3);
        let expected_loss = 2.0 * std::f64::consts::PI / q * b.energy;
        assert!((b.loss_per_period / expected_loss - 1.0).abs() < 1e-3);
        let w = p.natural_angular_frequency();
        assert!((b.impulse_per_beat / (b.loss_per_period / 2.0 / (w * a)) - 1.0).abs() < 1e-3);
        assert!((b.power - b.loss_per_period / 2.0).abs() < 1e-18);
    }
}
