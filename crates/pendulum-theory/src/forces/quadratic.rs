//! Quadratic air drag: `-b (dθ/dτ)|dθ/dτ|`, `b` per radian (the same in
//! scaled and in real time: `b θ'|θ'| / ω_n² = b (dθ/dτ)|dθ/dτ|`), the
//! drag of a bob at high Reynolds number.

use super::DragLaw;

/// Quadratic air drag, `b` per radian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadraticDrag;

impl DragLaw for QuadraticDrag {
    fn name(&self) -> &'static str {
        "quadratic_drag"
    }

    fn describe(&self) -> &'static str {
        "b in b θ'|θ'|, per radian"
    }

    fn scaled(&self, k: f64, _omega: f64) -> f64 {
        k
    }

    #[inline(always)]
    fn acceleration(&self, b: f64, v: f64) -> f64 {
        -b * v * v.abs()
    }

    /// `(1 - e^{-c τ})/c` (`τ` without viscous decay).
    fn flow_constant(&self, c: f64, tau: f64) -> f64 {
        if c > 0.0 {
            -(-c * tau).exp_m1() / c
        } else {
            tau
        }
    }

    /// A Bernoulli equation: `v e^{-cτ} / (1 + b|v| (1 - e^{-cτ})/c)`.
    #[inline(always)]
    fn flow(&self, b: f64, v: f64, decayed: f64, gain: f64) -> f64 {
        decayed / (1.0 + b * v.abs() * gain)
    }

    /// `2 b s` at the free speed, or under strong drag twice the
    /// drag-limited creep speed `1/sqrt(b)` (where `b (dθ/dτ)² = sin θ`).
    fn rate(&self, b: f64, free_speed: f64) -> f64 {
        if b > 0.0 {
            2.0 * b * free_speed.min(2.0 / b.sqrt())
        } else {
            0.0
        }
    }

    fn power(&self) -> f64 {
        2.0
    }

    /// `4/(3π)`.
    fn sine_mean(&self) -> f64 {
        4.0 / (3.0 * std::f64::consts::PI)
    }

    fn decay_name(&self) -> &'static str {
        "quadratic"
    }

    fn decay_rate_name(&self) -> &'static str {
        "quadratic_decay_per_rad_s"
    }

    fn searched(&self) -> bool {
        true
    }
}
