//! The one Q every fit reports: the quality factor over the record, from
//! the energy the fitted motion loses per cycle at the record's own
//! amplitudes, whatever the damping law.
//!
//! `Q = 2π E / ΔE` with `ΔE` the energy lost in a cycle. Averaged over a
//! record that swings from amplitude `A₀` down to `A₁` through a phase
//! `Φ = ω Δt` (radians of the swing: `π` a half swing), the energy falls
//! by `ln(E₀/E₁)` in all, so the loss per radian of phase is
//! `1/Q = ln(E(A₀)/E(A₁)) / Φ`, with the pendulum's energy at a crest
//! `E(A) ∝ 1 − cos A = 2 sin²(A/2)` (exact at any swing; `∝ A²` at small
//! ones, where viscous damping gives back `Q = 1/(2ζ)`). The decay fit
//! takes `A₀`, `A₁` from its fitted amplitude law at the record's first
//! and last times and `ω` from the turning points (or what was given);
//! the trajectory fit from its fitted motion's first and last crests in
//! the record and the half swings between them. So the two commands
//! report the same figure for the same record: with drag or friction the
//! viscous `1/(2ζ)` alone can be several times larger (a pendulum in air,
//! `examples/tracker.txt`: 929 against 206), and is reported apart as
//! `q_viscous`.
//!
//! The standard error is that of the loss (propagated from the fit's
//! covariance, [`super::propagate`]), as the loss is what is measured: a
//! loss within two standard errors of 0 gives no Q but its two-sigma lower
//! bound `1/(loss + 2σ)`.

/// The energy of a swing of amplitude `a` (rad) at its crest, over
/// `m g l`: `1 − cos a`, computed as `2 sin²(a/2)` (no cancellation at
/// small swings).
pub fn swing_energy(a: f64) -> f64 {
    let s = (0.5 * a).sin();
    2.0 * s * s
}

/// The loss per radian of swing phase, `1/Q`, over a record whose swing
/// falls from `a_start` to `a_end` (rad) through `phase` radians of the
/// swing (`ω Δt`, or `π` times the half swings); `None` when it is not a
/// number (no phase, a zero amplitude).
pub fn loss_per_radian(phase: f64, a_start: f64, a_end: f64) -> Option<f64> {
    let ratio = swing_energy(a_start) / swing_energy(a_end);
    let loss = ratio.ln() / phase;
    (phase > 0.0 && loss.is_finite()).then_some(loss)
}

/// Q over a record, as its loss per radian and that loss's standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RecordQ {
    /// `1/Q`: the fraction of its energy the swing loses per radian of
    /// phase, averaged over the record.
    pub loss: f64,
    /// Its standard error.
    pub loss_standard_error: f64,
}

/// The number of standard errors the loss must exceed for a Q to be
/// reported (below, the two-sigma lower bound is).
pub const MEASURABLE_SIGMA: f64 = 2.0;

impl RecordQ {
    /// Whether the loss is measured: beyond [`MEASURABLE_SIGMA`] standard
    /// errors of 0.
    pub fn measurable(&self) -> bool {
        self.loss > MEASURABLE_SIGMA * self.loss_standard_error
    }

    /// `Q = 1/loss`, when measurable.
    pub fn q(&self) -> Option<f64> {
        self.measurable().then(|| 1.0 / self.loss)
    }

    /// Q's standard error, `σ_loss / loss²` (first order), when measurable.
    pub fn q_standard_error(&self) -> Option<f64> {
        self.measurable()
            .then(|| self.loss_standard_error / (self.loss * self.loss))
            .filter(|v| v.is_finite())
    }

    /// When the loss is not measurable: Q's two-sigma lower bound,
    /// `1/(max(loss, 0) + 2σ)`.
    pub fn lower_bound(&self) -> Option<f64> {
        if self.measurable() {
            return None;
        }
        let upper = self.loss.max(0.0) + MEASURABLE_SIGMA * self.loss_standard_error;
        (upper > 0.0 && upper.is_finite()).then(|| 1.0 / upper)
    }

    /// The same with the relative standard error of the `ω` the phase was
    /// measured with added in quadrature (the loss is `∝ 1/ω`).
    pub fn with_omega_error(self, relative: f64) -> Self {
        let extra = self.loss * relative;
        Self {
            loss: self.loss,
            loss_standard_error: self.loss_standard_error.hypot(extra),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viscous_decay_gives_one_over_two_zeta_at_small_swings() {
        // A(t) = A₀ e^{-ζωt}: at small swings the energy falls as A², so
        // the loss per radian is 2ζ.
        let (zeta, w, span, a0): (f64, f64, f64, f64) = (1e-3, 3.0, 100.0, 1e-4);
        let a1 = a0 * (-zeta * w * span).exp();
        let loss = loss_per_radian(w * span, a0, a1).unwrap();
        assert!((loss / (2.0 * zeta) - 1.0).abs() < 1e-8, "{loss}");
        // At a wide swing the energy 1 − cos A falls less than A² does.
        let (b0, b1) = (1.0, (-0.1f64).exp());
        let wide = loss_per_radian(1.0, b0, b1).unwrap();
        let exact = ((1.0 - b0.cos()) / (1.0 - b1.cos())).ln();
        assert!((wide - exact).abs() < 1e-14 && wide < 0.2, "{wide}");
    }

    #[test]
    fn an_unmeasured_loss_gives_a_lower_bound() {
        let q = RecordQ {
            loss: 1e-3,
            loss_standard_error: 1e-4,
        };
        assert_eq!(q.q(), Some(1000.0));
        assert!((q.q_standard_error().unwrap() - 100.0).abs() < 1e-9);
        assert_eq!(q.lower_bound(), None);
        let faint = RecordQ {
            loss: 1e-4,
            loss_standard_error: 1e-4,
        };
        assert_eq!(faint.q(), None);
        assert!((faint.lower_bound().unwrap() - 1.0 / 3e-4).abs() < 1e-6);
    }
}
