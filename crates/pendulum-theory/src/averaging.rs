//! The method of averaging: a whole half swing per step, from one
//! turning point to the next, in closed form, under weak viscous damping
//! and any extra work done between the turning points (an escapement's,
//! given by its caller as a function of the amplitude reached).
//!
//! The energy at the turning points (scaled, `E = 2 sin²(A/2)`) goes from
//! `E₁` to `E₂ = E₁ + W(A₂) - D(Ē)/Q`, where `W` is the extra work between
//! the ends, `D(E) = ∫ v dθ = 8 (E(k) - k'² K(k))` the free half swing's
//! action at the mean energy `Ē = (E₁ + E₂)/2` (the viscous loss
//! `∫ θ'² dτ / Q`), and the half swing lasts `2 K(k̄)` plus the caller's
//! time shift at the mean amplitude. Damping and drive change sign when
//! time runs backwards, and this map, evaluated at the mean energy, undoes
//! itself under that reversal exactly as the motion does; two such maps
//! that agree to first order in the small forces then agree to second
//! order as well (the second-order term of a reversible map is fixed by
//! its first), so a half swing is right to third order in `1/Q` and the
//! drive: 1e-18 of the energy at Q = 10⁶. The implicit equation for `E₂` is
//! solved by fixed-point iteration (each contracts by the size of the
//! forces).
//!
//! The half period carries the viscous term's second-order lengthening
//! `1/sqrt(1 - ζ²)` (ζ = 1/(2Q); exact for the linear oscillator), so the
//! time is right to second order too.
//!
//! Used by the simulation's averaged method (no extra work) and by the
//! clock's ([`crate::clock::averaged`], the escapement's work); measured
//! accuracy there.

use crate::elliptic::{ellip_e_minus_complement_k, Modulus};

/// The end of a half swing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSwing {
    /// The amplitude at its end, rad.
    pub amplitude: f64,
    /// Its duration, in scaled time `τ = ω_n t`.
    pub time: f64,
}

/// The free half swing's action `∫ v dθ` at amplitude `a`, scaled:
/// `8 (E(k) - k'² K(k))`, `k = sin(a/2)` (the difference computed without
/// cancellation, [`ellip_e_minus_complement_k`]).
pub fn half_swing_action(a: f64) -> f64 {
    Modulus::from_modular_angle(0.5 * a).map_or(f64::NAN, |m| 8.0 * ellip_e_minus_complement_k(&m))
}

/// The same from the scaled energy `e = 2k²` (no angle needed).
fn action_of_energy(e: f64) -> Option<f64> {
    Modulus::from_parameter(0.5 * e).map(|m| 8.0 * ellip_e_minus_complement_k(&m))
}

/// Scaled energy at a turning point at `a`.
fn energy_of(a: f64) -> f64 {
    2.0 * (0.5 * a).sin().powi(2)
}

/// Amplitude of the turning point with scaled energy `e`; `None` at or
/// past the top.
fn amplitude_of(e: f64) -> Option<f64> {
    let s = (0.5 * e).sqrt();
    (s.is_finite() && s < 1.0).then(|| 2.0 * s.asin())
}

/// Extra work done during a half swing: the scaled energy given as a
/// function of the amplitude reached, and the time shift (scaled) as a
/// function of the mean amplitude.
pub struct Work<'a> {
    /// Energy given, scaled, against the amplitude at the end.
    pub energy: &'a dyn Fn(f64) -> f64,
    /// The half swing's time shift, scaled, at the mean amplitude; `None`
    /// for none.
    pub time_shift: Option<&'a dyn Fn(f64) -> f64>,
}

/// The half swing from rest at `-a1` to the next turning point under
/// viscous damping `1/q` (scaled; `q` infinite for none) and the extra
/// `work`, by the map of the module notes; `None` when it goes over the
/// top.
pub fn half_swing_map(q: f64, a1: f64, work: Option<&Work<'_>>) -> Option<HalfSwing> {
    let c = if q.is_finite() { 1.0 / q } else { 0.0 };
    let e1 = energy_of(a1);
    let given = |a2: f64| work.map_or(0.0, |w| (w.energy)(a2));
    // First order for a start; each iteration gains the forces' order.
    let mut e2 = e1 + given(a1) - c * action_of_energy(e1)?;
    let mut a2 = a1;
    for _ in 0..20 {
        if work.is_some() {
            a2 = amplitude_of(e2)?;
        }
        let next = e1 + given(a2) - c * action_of_energy(0.5 * (e1 + e2))?;
        let converged = (next - e2).abs() <= 4.0 * f64::EPSILON * e1;
        e2 = next;
        if converged {
            break;
        }
    }
    let a2 = amplitude_of(e2)?;
    let mean_energy = 0.5 * (e1 + e2);
    let shift = match work.and_then(|w| w.time_shift) {
        Some(shift) => shift(amplitude_of(mean_energy)?),
        None => 0.0,
    };
    if mean_energy >= 2.0 {
        return None;
    }
    Some(HalfSwing {
        amplitude: a2,
        // The viscous term's second-order lengthening, exact for the
        // linear oscillator (turning points π/ω_d apart, ω_d = sqrt(1 - ζ²)
        // with ζ = c/2).
        time: 2.0 * crate::elliptic::ellipk(0.5 * mean_energy) / (1.0 - 0.25 * c * c).sqrt()
            + shift,
    })
}
