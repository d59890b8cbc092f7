//! Drag of power 3/2: `-k θ'|θ'|^{1/2}`, `k` in rad^(-1/2) s^(-1/2), a
//! phenomenological law between Stokes' linear drag (low Reynolds number)
//! and Newton's quadratic drag (high), for bobs and rods in the
//! intermediate range, where a run-down fits neither power.
//!
//! In scaled time `τ = ω_n t` the term is `(k/sqrt(ω_n)) v|v|^{1/2}`.
//! With viscous decay at rate `c` it is a Bernoulli equation: `w =
//! |v|^{-1/2}` obeys `w' = (c w + k)/2`, so that `w(τ) = |v e^{-cτ}|^{-1/2}
//! + k (e^{cτ/2} - 1)/c` exactly (`k τ/2` without viscous decay). The flow
//! is checked against a numerical integration of the equation (within
//! 1e-12; measured 1e-14), and the simulated decay of a small swing against
//! the first-order averaged law `A(τ) = (A0^{-1/2} + k B τ/(2π))^{-2}`,
//! `B = ∫_0^π sin^{5/2} = sqrt(π) Γ(7/4)/Γ(9/4)` (within 1e-4 over 200 periods;
//! measured 6.3e-6, DOP853 and the symplectic method), in
//! `tests/all/simulation.rs`.

use super::DragLaw;

/// Drag of power 3/2, `k` in rad^(-1/2) s^(-1/2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThreeHalvesDrag;

impl DragLaw for ThreeHalvesDrag {
    fn name(&self) -> &'static str {
        "three_halves_drag"
    }

    fn describe(&self) -> &'static str {
        "k in k θ'|θ'|^(1/2), rad^(-1/2) s^(-1/2)"
    }

    fn scaled(&self, k: f64, omega: f64) -> f64 {
        k / omega.sqrt()
    }

    #[inline(always)]
    fn acceleration(&self, k: f64, v: f64) -> f64 {
        -k * v * v.abs().sqrt()
    }

    /// `(e^{cτ/2} - 1)/c`, `τ/2` without viscous decay.
    fn flow_constant(&self, c: f64, tau: f64) -> f64 {
        if c > 0.0 {
            (0.5 * c * tau).exp_m1() / c
        } else {
            0.5 * tau
        }
    }

    #[inline(always)]
    fn flow(&self, k: f64, _v: f64, decayed: f64, constant: f64) -> f64 {
        if decayed == 0.0 {
            return 0.0;
        }
        let w = 1.0 / decayed.abs().sqrt() + k * constant;
        decayed.signum() / (w * w)
    }

    /// `1.5 k sqrt(s)` at the free speed, or under strong drag twice the
    /// creep speed `k^{-2/3}` (where `k v^{3/2} = sin θ`).
    fn rate(&self, k: f64, free_speed: f64) -> f64 {
        if k > 0.0 {
            1.5 * k * free_speed.min(2.0 * k.powf(-2.0 / 3.0)).sqrt()
        } else {
            0.0
        }
    }

    fn power(&self) -> f64 {
        1.5
    }

    /// `Γ(7/4)/(√π Γ(9/4))` (SciPy's `gamma`: 0.45765585810108783).
    fn sine_mean(&self) -> f64 {
        0.457_655_858_101_087_83
    }

    fn decay_name(&self) -> &'static str {
        "three_halves"
    }

    fn decay_rate_name(&self) -> &'static str {
        "three_halves_decay_per_sqrt_rad_s"
    }

    /// Not tried unless named: over a record, viscous damping and
    /// quadratic drag together follow a power between 1 and 2.
    fn searched(&self) -> bool {
        false
    }
}
