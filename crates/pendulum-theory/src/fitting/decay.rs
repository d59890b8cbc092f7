//! Which damping a pendulum has, from how its amplitude falls.
//!
//! Four laws of amplitude against time, each the solution of an averaged
//! equation for the amplitude `A(t)`:
//!
//! | model | law | averaged equation | source |
//! |---|---|---|---|
//! | `viscous` | `A0 e^{-λt}`, `λ = ζω` | `dA/dt = -λA` | seed section 1-4 |
//! | `coulomb` | `A0 - μt`, `μ = 2rω/π` | `dA/dt = -μ` (2r per half swing) | book section 2-4 |
//! | `quadratic` | `A0 / (1 + κA0t)`, `κ = 4bω/(3π)` | `dA/dt = -κA²` | energy balance with `⟨|sin|³⟩ = 4/(3π)` |
//! | `viscous+coulomb` | `A0 e^{-λt} + μ expm1(-λt)/λ` | `dA/dt = -λA - μ` | the recursion `|A_{n+1}| = (|A_n| - r)/Λ - r` at half swings |
//!
//! The rates (`λ`, `μ`, `κ`) are fitted; with the pendulum's angular
//! frequency `ω` they become the physical `ζ`, friction angle `r` and
//! quadratic drag `b`. At large amplitude the frequency depends on the
//! amplitude, so `ω = 2π/T(A)` is taken at the data's median amplitude
//! (the exact period, [`crate::period`]).

use super::{fit_curve, straight_line, Fit, FitError};
use crate::pendulum::{Amplitude, Pendulum};

/// The amplitude-decay laws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecayModel {
    /// Exponential decay (viscous damping).
    Viscous,
    /// Linear decay (dry friction).
    Coulomb,
    /// Hyperbolic decay (air drag proportional to the square of the speed).
    Quadratic,
    /// Viscous damping and dry friction together.
    ViscousCoulomb,
}

/// A fitted quantity with its standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// Name, as in the JSON output (`zeta`, `friction_angle_rad`, …).
    pub name: &'static str,
    /// Value.
    pub value: f64,
    /// Standard error.
    pub standard_error: f64,
}

/// One model fitted to one decay.
#[derive(Clone, Debug, PartialEq)]
pub struct DecayFit {
    /// The model.
    pub model: DecayModel,
    /// The fit of the rates.
    pub fit: Fit,
    /// The fitted rates and, given `ω`, the physical parameters.
    pub parameters: Vec<Estimate>,
    /// `Q = ω/(2λ)`, for the models with viscous damping and a known `ω`,
    /// when the decay is measurable (`ζ` at least two standard errors
    /// above 0).
    pub q_factor: Option<f64>,
    /// When the viscous decay is not measurable (`ζ` within two standard
    /// errors of 0, or below): the two-sigma lower bound on Q,
    /// `1/(2 (ζ + 2σ_ζ))`, what the data can still say.
    pub q_factor_lower_bound: Option<f64>,
}

impl DecayModel {
    /// Every model, simplest first.
    pub const ALL: [DecayModel; 4] = [
        DecayModel::Viscous,
        DecayModel::Coulomb,
        DecayModel::Quadratic,
        DecayModel::ViscousCoulomb,
    ];

    /// The name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            DecayModel::Viscous => "viscous",
            DecayModel::Coulomb => "coulomb",
            DecayModel::Quadratic => "quadratic",
            DecayModel::ViscousCoulomb => "viscous+coulomb",
        }
    }

    /// The model called `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Names of the fitted rate parameters.
    pub fn rate_names(self) -> &'static [&'static str] {
        match self {
            DecayModel::Viscous => &["amplitude0_rad", "decay_rate_per_s"],
            DecayModel::Coulomb => &["amplitude0_rad", "amplitude_fall_rad_per_s"],
            DecayModel::Quadratic => &["amplitude0_rad", "quadratic_decay_per_rad_s"],
            DecayModel::ViscousCoulomb => &[
                "amplitude0_rad",
                "decay_rate_per_s",
                "amplitude_fall_rad_per_s",
            ],
        }
    }

    /// The amplitude at `t` for rates `p` (in the order of [`Self::rate_names`]).
    pub fn amplitude(self, t: f64, p: &[f64]) -> f64 {
        match self {
            DecayModel::Viscous => p[0] * (-p[1] * t).exp(),
            DecayModel::Coulomb => p[0] - p[1] * t,
            DecayModel::Quadratic => p[0] / (1.0 + p[1] * p[0] * t),
            DecayModel::ViscousCoulomb => {
                let (a0, lambda, mu) = (p[0], p[1], p[2]);
                // μ expm1(-λt)/λ tends to -μt as λ -> 0: no division by a
                // vanishing rate, no cancellation.
                let x = -lambda * t;
                let ratio = if x.abs() < 1e-8 {
                    -t * (1.0 + 0.5 * x)
                } else {
                    x.exp_m1() / lambda
                };
                a0 * x.exp() + mu * ratio
            }
        }
    }

    /// Starting rates from straight-line fits of ln A, A and 1/A against t.
    fn initial(self, t: &[f64], a: &[f64]) -> Vec<f64> {
        let viscous = {
            let ln: Vec<f64> = a.iter().map(|v| v.ln()).collect();
            let (c, s) = straight_line(t, &ln);
            [c.exp(), -s]
        };
        let coulomb = {
            let (c, s) = straight_line(t, a);
            [c, -s]
        };
        match self {
            DecayModel::Viscous => viscous.to_vec(),
            DecayModel::Coulomb => coulomb.to_vec(),
            DecayModel::Quadratic => {
                let inv: Vec<f64> = a.iter().map(|v| 1.0 / v).collect();
                let (c, s) = straight_line(t, &inv);
                vec![1.0 / c, s]
            }
            DecayModel::ViscousCoulomb => vec![viscous[0], 0.5 * viscous[1], 0.5 * coulomb[1]],
        }
    }
}

/// `ω = 2π/T(A)` at the median of `amplitudes` (rad): the angular frequency
/// that turns rates per second into rates per swing.
pub fn effective_angular_frequency(pendulum: &Pendulum, amplitudes: &[f64]) -> f64 {
    let mut sorted: Vec<f64> = amplitudes.iter().map(|a| a.abs()).collect();
    sorted.sort_by(f64::total_cmp);
    let median = sorted.get(sorted.len() / 2).copied().unwrap_or(0.0);
    let amplitude = Amplitude::from_radians(median.min(std::f64::consts::PI.next_down()))
        .expect("clamped into [0, π)");
    std::f64::consts::TAU / pendulum.period(amplitude)
}

/// Times (s, from the first row) of rows given as half-swing counts: each
/// half swing takes `T(A)/2` at the amplitude `A` it swings at (the mean of
/// the two rows around it), with the exact period, so that wide swings are
/// timed right.
pub fn swings_to_time(pendulum: &Pendulum, swings: &[f64], amplitudes: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(swings.len());
    let mut t = 0.0;
    for i in 0..swings.len() {
        if i > 0 {
            let mean = 0.5 * (amplitudes[i - 1] + amplitudes[i]).abs();
            let a = Amplitude::from_radians(mean.min(std::f64::consts::PI.next_down()))
                .expect("clamped into [0, π)");
            t += (swings[i] - swings[i - 1]) * 0.5 * pendulum.period(a);
        }
        out.push(t);
    }
    out
}

/// Fits `model` to amplitudes `amplitude` (rad) at times `time` (s); with
/// `omega` (rad/s) the physical parameters are added.
pub fn fit_decay(
    model: DecayModel,
    time: &[f64],
    amplitude: &[f64],
    omega: Option<f64>,
) -> Result<DecayFit, FitError> {
    let curve = |t: f64, p: &[f64]| model.amplitude(t, p);
    let fit = fit_curve(
        &curve,
        time,
        amplitude,
        None,
        &model.initial(time, amplitude),
    )?;
    let mut parameters: Vec<Estimate> = model
        .rate_names()
        .iter()
        .zip(fit.parameters.iter().zip(&fit.standard_errors))
        .map(|(&name, (&value, &standard_error))| Estimate {
            name,
            value,
            standard_error,
        })
        .collect();
    let (mut q_factor, mut q_factor_lower_bound) = (None, None);
    if let Some(w) = omega {
        let physical: Vec<Estimate> = parameters
            .iter()
            .filter_map(|e| {
                let (name, factor) = match e.name {
                    "decay_rate_per_s" => ("zeta", 1.0 / w),
                    "amplitude_fall_rad_per_s" => {
                        ("friction_angle_rad", std::f64::consts::PI / (2.0 * w))
                    }
                    "quadratic_decay_per_rad_s" => {
                        ("quadratic_drag", 3.0 * std::f64::consts::PI / (4.0 * w))
                    }
                    _ => return None,
                };
                Some(Estimate {
                    name,
                    value: e.value * factor,
                    standard_error: e.standard_error * factor,
                })
            })
            .collect();
        if let Some(z) = physical.iter().find(|e| e.name == "zeta") {
            if z.value > 2.0 * z.standard_error {
                q_factor = Some(0.5 / z.value);
            } else {
                let upper = z.value.max(0.0) + 2.0 * z.standard_error;
                q_factor_lower_bound = (upper > 0.0).then(|| 0.5 / upper);
            }
        }
        parameters.extend(physical);
    }
    Ok(DecayFit {
        model,
        fit,
        parameters,
        q_factor,
        q_factor_lower_bound,
    })
}

/// The model the data prefer: the lowest BIC among those that fitted.
pub fn preferred(fits: &[DecayFit]) -> Option<DecayModel> {
    fits.iter()
        .min_by(|a, b| a.fit.bic.total_cmp(&b.fit.bic))
        .map(|f| f.model)
}

/// The amplitude lost per half swing at `amplitude` according to a fit:
/// `-dA/dt · T/2`, for the energy budget.
pub fn half_swing_loss(fit: &DecayFit, amplitude: f64, half_period: f64) -> f64 {
    let p = &fit.fit.parameters;
    let rate = match fit.model {
        DecayModel::Viscous => p[1] * amplitude,
        DecayModel::Coulomb => p[1],
        DecayModel::Quadratic => p[1] * amplitude * amplitude,
        DecayModel::ViscousCoulomb => p[1] * amplitude + p[2],
    };
    rate * half_period
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn combined_law_reduces_to_its_parts() {
        let both = DecayModel::ViscousCoulomb;
        let t = 37.0;
        let v = both.amplitude(t, &[0.05, 1e-3, 0.0]);
        assert!((v - DecayModel::Viscous.amplitude(t, &[0.05, 1e-3])).abs() < 1e-17);
        let c = both.amplitude(t, &[0.05, 0.0, 1e-4]);
        assert!((c - DecayModel::Coulomb.amplitude(t, &[0.05, 1e-4])).abs() < 1e-17);
    }

    #[test]
    fn recovers_noiseless_parameters() {
        let t: Vec<f64> = (0..50).map(|i| f64::from(i) * 20.0).collect();
        for (model, truth) in [
            (DecayModel::Viscous, vec![0.05, 1e-3]),
            (DecayModel::Coulomb, vec![0.05, 2e-5]),
            (DecayModel::Quadratic, vec![0.05, 0.02]),
            (DecayModel::ViscousCoulomb, vec![0.05, 5e-4, 1e-5]),
        ] {
            let a: Vec<f64> = t.iter().map(|&x| model.amplitude(x, &truth)).collect();
            let fit = fit_decay(model, &t, &a, Some(3.0)).unwrap();
            for (got, want) in fit.fit.parameters.iter().zip(&truth) {
                assert!(
                    (got / want - 1.0).abs() < 1e-6,
                    "{}: {got} vs {want}",
                    model.name()
                );
            }
        }
    }
}
