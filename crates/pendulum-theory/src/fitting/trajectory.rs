//! A pendulum's parameters from its tracked angle against time (video
//! tracking: 30 to 1000 samples a second, noisy, with an unknown zero).
//!
//! Two models, five parameters each (the nonlinear one up to seven):
//! * linear, the free vibration of seed section 1-4 about an offset:
//!   `θ(t) = θ_off + A e^{-ζω_n t} cos(ω_d t + φ)`, `ω_n = ω_d / sqrt(1 - ζ²)`;
//!   parameters `A, ω_d, ζ, φ, θ_off`;
//! * nonlinear, the full equation `θ'' + 2ζω_n θ' + ω_n² sin θ = 0`
//!   integrated inside the fit ([`crate::simulation`], DOP853 at 1e-12),
//!   released from rest at amplitude `A` at a crest: the last at or before
//!   the first sample, or the first after it when that is within a quarter
//!   period (the samples before it are then the motion's mirror image);
//!   parameters `A, ω_n, ζ, φ, θ_off`, the phase reported as the fraction
//!   of the true (finite-amplitude) period by which the release precedes
//!   the first sample (`φ` in `(-π/2, 2π)`, negative for a release after
//!   it). A bob held at the start is left out ([`held_start`]). It is started from the
//!   linear fit. Beside the viscous damping, a drag law of the list of
//!   [`crate::forces`] (quadratic air drag `b θ'|θ'|` unless another is
//!   named, [`fit_observed_with`]: the list's 3/2 power, or a law added
//!   to it) and dry friction (a friction angle `r`: the torque of a
//!   pivot's friction as an angle of the bob) are each
//!   tried, from the viscous fit, and kept when they lower the Bayesian
//!   information criterion with the coefficient determined (beyond two
//!   standard errors): a pendulum in air at a large swing, or on a knife
//!   edge, decays by neither law alone, and a viscous fit to it misplaces
//!   the first crest by tens of standard errors and g by up to fifty
//!   (measured over the generated records of `tests/all/coverage.rs`).
//!
//! Both are fitted over growing windows: the first four periods, then
//! twice as long each time, each fit started from the last, the last the
//! whole record. A long record of large swings, whose period changes by
//! up to 10% as the amplitude decays, otherwise loses the phase and lands
//! in a false minimum (issue 23: 78-94° releases over 136-375 s, now within
//! 3σ of the truth in g, `tests/all/fitting.rs`); a window too short to
//! determine every parameter is passed over.
//!
//! A gyroscope's record (angular velocity, [`Observed::AngularVelocity`])
//! is fitted by the same models' derivative: the closed form's
//! (`linear_rate`) and the integrated equation's own velocity; the
//! offset is then the gyroscope's zero, and a bob held at the start is
//! found by its rates ([`held_still`]).
//!
//! With the length, `g = l ω_0²` where `ω_0` is the small-angle natural
//! frequency: for the linear model `ω_d` is first corrected for damping
//! (`/ sqrt(1 - ζ²)`) and for the finite amplitude (times `T(A_mid)/T0`,
//! the exact period ratio at the amplitude in the middle of the record);
//! the nonlinear model has `ω_n` directly.

use super::quality::{loss_per_radian, RecordQ};
use super::{fit_curve, fit_curve_patient, propagate, Curve, Fit, FitError};
use crate::damped::State;
use crate::damping::Damping;
use crate::forces::DRAG_LAWS;
use crate::pendulum::{Amplitude, Pendulum};
use crate::period::period_ratio;
use crate::simulation::{simulate, Method, Model, Observer, Options, QUADRATIC_DRAG};
use std::cell::RefCell;

/// Which trajectory model.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrajectoryModel {
    /// Section 1-4's closed form.
    Linear,
    /// The nonlinear equation, integrated.
    Nonlinear,
}

impl TrajectoryModel {
    /// Its name, as `--model` and the JSON's `model` write it.
    pub fn name(self) -> &'static str {
        match self {
            TrajectoryModel::Linear => "linear",
            TrajectoryModel::Nonlinear => "nonlinear",
        }
    }
}

/// What a record measures of the swing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Observed {
    /// The angle, rad (a video's track, an encoder).
    #[default]
    Angle,
    /// The angular velocity `dθ/dt`, rad/s: a gyroscope that swings with
    /// the pendulum (a phone's, phyphox). Both models are then fitted by
    /// their derivative, the offset being the gyroscope's zero (its bias);
    /// the record is never integrated, so the bias cannot drift the angle.
    AngularVelocity,
}

/// The damping laws of the nonlinear model beside the viscous one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Law {
    /// A drag law of [`DRAG_LAWS`] (its index): quadratic air drag
    /// `b θ'|θ'|`, the 3/2 power, or any law added to the list.
    pub drag: Option<usize>,
    /// Dry friction at the pivot.
    pub friction: bool,
}

impl Law {
    /// Viscous damping alone.
    pub const VISCOUS: Law = Law {
        drag: None,
        friction: false,
    };

    /// The name, as the decay fit names laws (`viscous+quadratic`,
    /// `viscous+coulomb+three_halves`).
    pub fn name(self) -> &'static str {
        match (self.drag, self.friction) {
            (None, false) => "viscous",
            (None, true) => "viscous+coulomb",
            (Some(law), friction) => {
                crate::fitting::decay::drag_model_names()[law][1 + 2 * usize::from(friction)]
            }
        }
    }

    /// The JSON names of the parameters it adds: the drag law's
    /// coefficient (`quadratic_drag_per_rad`, or the law's name, the key
    /// the simulation takes it by) and the friction angle.
    fn extra_names(self) -> Vec<&'static str> {
        let mut out = Vec::new();
        if let Some(law) = self.drag {
            out.push(drag_key(law));
        }
        if self.friction {
            out.push("friction_angle_rad");
        }
        out
    }

    /// The motion of fitted parameters `p`: `[A, ω_n, ζ, φ, θ_off, k, r]`
    /// (the laws absent are 0) and the drag law `k` is of.
    fn full(self, p: &[f64]) -> Motion {
        let mut out = [0.0; 7];
        out[..5].copy_from_slice(&p[..5]);
        let mut next = 5;
        if self.drag.is_some() {
            out[5] = p[next].abs();
            next += 1;
        }
        if self.friction {
            out[6] = p[next].abs();
        }
        Motion {
            p: out,
            drag: self.drag.unwrap_or(QUADRATIC_DRAG),
        }
    }
}

/// The key of drag law `law`'s coefficient among a fit's parameters.
pub fn drag_key(law: usize) -> &'static str {
    if law == QUADRATIC_DRAG {
        "quadratic_drag_per_rad"
    } else {
        DRAG_LAWS[law].name()
    }
}

/// The drag laws the fit tries when none is named
/// ([`crate::forces::DragLaw::searched`]).
pub fn searched_drag_laws() -> Vec<usize> {
    (0..DRAG_LAWS.len())
        .filter(|&i| DRAG_LAWS[i].searched())
        .collect()
}

/// A motion of the nonlinear model: the parameters `[A, ω_n, ζ, φ, θ_off,
/// k, r]` (read by index, as an array) and the drag law of `k`.
struct Motion {
    p: [f64; 7],
    drag: usize,
}

impl std::ops::Deref for Motion {
    type Target = [f64; 7];
    fn deref(&self) -> &[f64; 7] {
        &self.p
    }
}

/// The drag coefficient `k` of `law` whose loss at the swing `a` (rad)
/// of a pendulum of natural angular frequency `wn` (rad/s) stands for
/// the viscous rate `zeta`: `(2ζ/a) (s₂/s) (ω a)^{2−p}`, `s` the law's
/// cycle average and `s₂` the quadratic one's (for quadratic drag `2ζ/a`,
/// a start the fit refines).
fn drag_for(law: usize, zeta: f64, a: f64, wn: f64) -> f64 {
    2.0 * zeta / a * law_factor(law, a, wn)
}

/// `(s₂/s) (ω a)^{2−p}` of [`drag_for`]: exactly 1 for quadratic drag
/// (whose starts are then the search's own to the last bit: its windowed
/// fits of a short record can settle on another minimum from a start one
/// ulp away, the gyroscope record `rotation-semicolon.csv` of the CLI's
/// tests).
fn law_factor(law: usize, a: f64, wn: f64) -> f64 {
    let (drag, quadratic) = (DRAG_LAWS[law], DRAG_LAWS[QUADRATIC_DRAG]);
    quadratic.sine_mean() / drag.sine_mean() * (wn * a).powf(2.0 - drag.power())
}

/// The viscous rate that stands for drag `k` of `law` at the swing `a`:
/// the inverse of [`drag_for`] but for its factor 4 (for quadratic drag
/// `k a/2`, the handing over the search was made with).
fn zeta_for(law: usize, k: f64, a: f64, wn: f64) -> f64 {
    0.5 * k * a / law_factor(law, a, wn)
}

/// The fitted trajectory.
#[derive(Clone, Debug, PartialEq)]
pub struct TrajectoryFit {
    /// The model.
    pub model: TrajectoryModel,
    /// The damping laws of the nonlinear model (viscous alone for the
    /// linear one).
    pub law: Law,
    /// The least-squares fit, parameters in the order of [`Self::names`].
    pub fit: Fit,
    /// The small-angle natural angular frequency ω_0, rad/s.
    pub natural_angular_frequency: f64,
    /// Its standard error.
    pub natural_angular_frequency_error: f64,
    /// The residual rms (rad) of a nonlinear fit that ran off (its release
    /// amplitude at the top or not determined) and came out worse than the
    /// linear one, which is then returned instead (`model` says `Linear`);
    /// `None` otherwise.
    pub nonlinear_rms_rejected: Option<f64>,
    /// Samples at the record's start where the bob is held at rest before
    /// its release (see [`held_start`]): not fitted, their residuals
    /// against the fitted release angle; the parameters' phase and time
    /// count from the first sample after them.
    pub held_samples: usize,
    /// The time from the record's first sample to the first fitted one, s.
    pub held_seconds: f64,
    /// What the record measured (the residuals and the offset are in its
    /// unit: rad, or rad/s).
    pub observed: Observed,
}

/// The swing above which the linear model's finite-amplitude correction
/// leaves a bias in g beyond its standard error, so that `auto` fits the
/// nonlinear equation and g is not reported from the linear one, rad (5°).
pub const AUTO_NONLINEAR_ABOVE: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// Half the spread of the angles: the largest swing about the middle, rad.
pub fn largest_swing(theta: &[f64]) -> f64 {
    let (lo, hi) = theta
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &t| {
            (lo.min(t), hi.max(t))
        });
    0.5 * (hi - lo)
}

impl TrajectoryModel {
    /// The model `auto` chooses for a record: nonlinear when its largest
    /// swing exceeds [`AUTO_NONLINEAR_ABOVE`].
    pub fn auto(theta: &[f64]) -> Self {
        Self::auto_at(largest_swing(theta))
    }

    /// The model `auto` chooses for a record whose largest swing is
    /// `swing` rad.
    pub fn auto_at(swing: f64) -> Self {
        if swing > AUTO_NONLINEAR_ABOVE {
            TrajectoryModel::Nonlinear
        } else {
            TrajectoryModel::Linear
        }
    }

    /// Whether g from this model fit is free of the finite-amplitude bias
    /// at the record's largest swing (always for the nonlinear model).
    pub fn gives_gravity(self, theta: &[f64]) -> bool {
        self.gives_gravity_at(largest_swing(theta))
    }

    /// [`Self::gives_gravity`] for a record whose largest swing is `swing`
    /// rad.
    pub fn gives_gravity_at(self, swing: f64) -> bool {
        self == TrajectoryModel::Nonlinear || swing <= AUTO_NONLINEAR_ABOVE
    }
}

/// The parameters the data do not determine, of `names` with `values` and
/// standard `errors`: those whose error reaches their value (a phase: half
/// a turn; an offset may be zero, so never). A NaN error determines
/// nothing.
pub fn undetermined(names: &[&'static str], values: &[f64], errors: &[f64]) -> Vec<&'static str> {
    names
        .iter()
        .zip(values.iter().zip(errors))
        .filter(|(name, (value, se))| match **name {
            "offset_rad" | "rate_offset_rad_s" => false,
            "phase_rad" => se.is_nan() || **se >= std::f64::consts::PI,
            _ => se.is_nan() || **se >= value.abs(),
        })
        .map(|(name, _)| *name)
        .collect()
}

impl TrajectoryFit {
    /// The fit's parameters the data do not determine (see
    /// [`undetermined`]), by their JSON names.
    pub fn undetermined(&self) -> Vec<&'static str> {
        undetermined(
            &self.names(),
            &self.fit.parameters,
            &self.fit.standard_errors,
        )
    }

    /// For people, when the nonlinear fit was rejected for the linear one:
    /// what happened and what to do.
    pub fn fallback_note(&self) -> Option<String> {
        self.nonlinear_rms_rejected.map(|rms| {
            if !rms.is_finite() {
                return "the nonlinear fit did not converge (its parameters are not determined \
                        from the linear fit's start): the linear fit is reported; the record does \
                        not follow a free decay from one release (heavy damping, friction?)"
                    .to_string();
            }
            format!(
                "the nonlinear fit ran off (its release amplitude went to the top or is not \
                 determined) and fits worse than the linear one (residual rms {:.3}° against \
                 {:.3}°): the linear fit is reported; the record does not follow a free decay \
                 from one release (heavy damping, friction?)",
                rms.to_degrees(),
                self.fit.residual_rms.to_degrees()
            )
        })
    }

    /// Parameter names as in JSON.
    pub fn names(&self) -> Vec<&'static str> {
        let mut names = self.base_names().to_vec();
        names.extend(self.law.extra_names());
        names
    }

    fn base_names(&self) -> [&'static str; 5] {
        let mut names = self.angle_names();
        if self.observed == Observed::AngularVelocity {
            names[4] = "rate_offset_rad_s";
        }
        names
    }

    fn angle_names(&self) -> [&'static str; 5] {
        match self.model {
            TrajectoryModel::Linear => [
                "amplitude_rad",
                "omega_d_rad_s",
                "zeta",
                "phase_rad",
                "offset_rad",
            ],
            TrajectoryModel::Nonlinear => [
                "amplitude_rad",
                "omega_n_rad_s",
                "zeta",
                "phase_rad",
                "offset_rad",
            ],
        }
    }

    /// The first crest in the record: its time from the first sample (s)
    /// with its standard error (the phase's), its amplitude about the
    /// offset (rad) with its standard error. The fitted amplitude is the envelope's at the first sample
    /// (linear) or the release's, up to a period before it (nonlinear):
    /// a record that starts just after a crest would report a swing
    /// extrapolated back a whole period (issue 23); the first crest is what
    /// the record shows. Linear: the crest of the cosine, `ω_d t + φ = kπ`,
    /// at the envelope there; nonlinear: the fitted motion integrated from
    /// the release to its first turning point at or after the first sample
    /// (DOP853 at 1e-12). The error scales with the fitted amplitude's.
    ///
    /// A crest before the first sample by less than half the first
    /// sampling `interval` (s) or twice the time's error counts as the
    /// record's: the record starts on it.
    pub fn first_crest(&self, interval: f64) -> Option<[f64; 4]> {
        // (After a held bob, the release lies within the held samples:
        // the bob held there is the record's first crest.)
        let near =
            |lead: f64, error: f64| lead <= (2.0 * error).max(0.5 * interval) + self.held_seconds;
        let p = &self.fit.parameters;
        let (a, a_error) = (p[0].abs(), self.fit.standard_errors[0]);
        let phase_error = self.fit.standard_errors[3];
        match self.model {
            TrajectoryModel::Linear => {
                let (wd, zeta, phase) = (p[1].abs(), p[2], p[3]);
                let wn = wd / (1.0 - zeta * zeta).max(f64::MIN_POSITIVE).sqrt();
                let pi = std::f64::consts::PI;
                // A crest before the first sample by less than twice the
                // time's error is the record's first (it starts on it).
                let time_error = phase_error / wd;
                // Crests at (kπ - phase)/ω_d: the first at or after the
                // first sample, or before it by less than twice the time's
                // error or half a sample (the record starts on it).
                let tolerance = (2.0 * time_error).max(0.5 * interval) + self.held_seconds;
                let k = ((phase - tolerance * wd) / pi).ceil().max(0.0);
                let t = if phase <= 0.0 {
                    -phase / wd
                } else {
                    (k * pi - phase) / wd
                };
                let decay = (-zeta * wn * t).exp();
                Some([
                    t + self.held_seconds,
                    phase_error / wd,
                    a * decay,
                    a_error * decay,
                ])
                .filter(|c| c[0].is_finite() && c[2].is_finite())
            }
            TrajectoryModel::Nonlinear => {
                let wn = p[1].abs();
                // The reported phase is a fraction of the true period; the
                // release leads the first sample by phase·ratio/ω_n.
                let ratio = release_period_ratio(a);
                let lead = p[3] * ratio / wn;
                let time_error = phase_error * ratio / wn;
                // A release before the first sample by less than twice the
                // time's error is the record's first crest (it starts on it).
                if near(lead, time_error) {
                    return Some([self.held_seconds - lead, time_error, a, a_error]);
                }
                // A crest before the first sample by less than twice the
                // time's error or half a sample is the record's first.
                let tolerance = (2.0 * time_error).max(0.5 * interval);
                let (time, angle) =
                    turning_point_after(&self.law.full(p), (lead - tolerance).max(0.0))?;
                let crest = angle.abs();
                Some([
                    self.held_seconds + time - lead,
                    time_error,
                    crest,
                    a_error * crest / a,
                ])
            }
        }
    }

    /// Q over the record ([`super::quality`]), from the energy the fitted
    /// motion loses per radian of swing over the `span` s of fitted
    /// samples (from the first fitted one), with the loss's standard error
    /// from the fit's covariance ([`super::propagate`]). Linear model: the
    /// envelope `A e^{−ζω_n t}` at the span's ends through `ω_d` times the
    /// span. Nonlinear model: the fitted motion integrated from its release
    /// (DOP853 at 1e-12), its first and last crests within the record and
    /// the half swings between them, the crests held to the same half
    /// swings while the parameters are stepped for the error (the phase
    /// then plays no part). A crest within half the sampling `interval`
    /// (s) outside the span is the record's (it starts or ends on it), as
    /// the turning points of the decay fit count it. `None` with fewer
    /// than two crests in the record, or no decay.
    pub fn record_q(&self, span: f64, interval: f64) -> Option<RecordQ> {
        let loss: Box<LossOf> = match self.model {
            TrajectoryModel::Linear => Box::new(move |p: &[f64]| {
                let (a, wd, zeta) = (p[0].abs(), p[1].abs(), p[2]);
                let wn = wd / (1.0 - zeta * zeta).max(f64::MIN_POSITIVE).sqrt();
                loss_per_radian(wd * span, a, a * (-zeta * wn * span).exp())
            }),
            TrajectoryModel::Nonlinear => {
                let p = &self.fit.parameters;
                let (a, wn) = (p[0].abs(), p[1].abs());
                // The release leads the first fitted sample by
                // phase·ratio/ω_n (the phase is a fraction of the true
                // period).
                let lead = p[3] * release_period_ratio(a) / wn.max(f64::MIN_POSITIVE);
                let crests = crests_until(&self.law.full(p), lead.max(0.0) + span + interval)?;
                // The crests the record shows, a crest it starts or ends
                // on with them.
                let tolerance = 0.5 * interval.max(0.0) + 1e-9 * span.max(1.0);
                let inside: Vec<&(u64, f64, f64)> = crests
                    .iter()
                    .filter(|(_, t, _)| *t >= lead - tolerance && *t <= lead + span + tolerance)
                    .collect();
                let (first, last) = (inside.first()?.0, inside.last()?.0);
                if last <= first {
                    return None;
                }
                let law = self.law;
                Box::new(move |q: &[f64]| {
                    let picked = crest_angles(&law.full(q), first, last)?;
                    loss_per_radian(
                        std::f64::consts::PI * (last - first) as f64,
                        picked.0,
                        picked.1,
                    )
                })
            }
        };
        let value = loss(&self.fit.parameters)?;
        Some(RecordQ {
            loss: value,
            loss_standard_error: propagate(&self.fit, |q| loss(q))?,
        })
    }

    /// `g = l ω_0²` and its standard error, for a pendulum of `length` m.
    pub fn gravity(&self, length: f64) -> (f64, f64) {
        let w = self.natural_angular_frequency;
        (
            length * w * w,
            2.0 * length * w * self.natural_angular_frequency_error,
        )
    }
}

/// `θ_off + A e^{-ζω_n t} cos(ω_d t + φ)` with `t` from the first sample.
fn linear(t: f64, p: &[f64]) -> f64 {
    let (a, wd, zeta, phase, offset) = (p[0], p[1], p[2], p[3], p[4]);
    let wn = wd / (1.0 - zeta * zeta).max(f64::MIN_POSITIVE).sqrt();
    offset + a * (-zeta * wn * t).exp() * (wd * t + phase).cos()
}

/// The derivative of [`linear`] (without its offset) plus a rate offset
/// `p[4]`: `A e^{-ζω_n t} (-ζω_n cos(ω_d t + φ) - ω_d sin(ω_d t + φ))`,
/// the angular velocity of the same motion as a gyroscope reads it.
fn linear_rate(t: f64, p: &[f64]) -> f64 {
    let (a, wd, zeta, phase, offset) = (p[0], p[1], p[2], p[3], p[4]);
    let wn = wd / (1.0 - zeta * zeta).max(f64::MIN_POSITIVE).sqrt();
    let x = wd * t + phase;
    offset + a * (-zeta * wn * t).exp() * (-zeta * wn * x.cos() - wd * x.sin())
}

/// The closed form of `observed`: [`linear`] or [`linear_rate`].
fn linear_of(observed: Observed) -> fn(f64, &[f64]) -> f64 {
    match observed {
        Observed::Angle => linear,
        Observed::AngularVelocity => linear_rate,
    }
}

/// Fits `model` to angles `theta` (rad) at times `time` (s, increasing),
/// from the release where the record starts with the bob held
/// ([`held_start`]).
pub fn fit_trajectory(
    model: TrajectoryModel,
    time: &[f64],
    theta: &[f64],
) -> Result<TrajectoryFit, FitError> {
    fit_observed(model, time, theta, Observed::Angle)
}

/// Fits `model` to `values` at times `time` (s, increasing): angles (rad)
/// or, by the model's derivative, angular velocities (rad/s), as
/// `observed` says; from the release where the record starts with the bob
/// held ([`held_start`]).
pub fn fit_observed(
    model: TrajectoryModel,
    time: &[f64],
    values: &[f64],
    observed: Observed,
) -> Result<TrajectoryFit, FitError> {
    fit_observed_with(model, time, values, observed, &searched_drag_laws())
}

/// [`fit_observed`] trying the drag laws `drag_laws` (indices of
/// [`DRAG_LAWS`]) beside the viscous damping and dry friction, where it
/// tries the [`searched_drag_laws`].
pub fn fit_observed_with(
    model: TrajectoryModel,
    time: &[f64],
    values: &[f64],
    observed: Observed,
    drag_laws: &[usize],
) -> Result<TrajectoryFit, FitError> {
    let theta = values;
    let points = time.len().min(theta.len());
    let held = match observed {
        Observed::Angle => held_start(&time[..points], &theta[..points]),
        Observed::AngularVelocity => held_still(&time[..points], &theta[..points]),
    };
    let mut fit = fit_released(
        model,
        &time[held..points],
        &theta[held..points],
        observed,
        drag_laws,
    )?;
    if held > 0 {
        // Held at the angle the fitted motion starts from (at rest: the
        // gyroscope reads its zero).
        let start = match observed {
            Observed::Angle => theta[held] - fit.fit.residuals[0],
            Observed::AngularVelocity => fit.fit.parameters[4],
        };
        let mut residuals: Vec<f64> = theta[..held].iter().map(|v| v - start).collect();
        residuals.append(&mut fit.fit.residuals);
        fit.fit.residuals = residuals;
        fit.held_samples = held;
        fit.held_seconds = time[held] - time[0];
    }
    Ok(fit)
}

/// The samples at the start of a record where the bob is held at rest
/// before its release, to be left out of the fit: a free motion leaves a
/// crest by `½ω² sin A · t²`, so it stays within three noise deviations
/// of the crest for `t₃ = sqrt(6σ / (ω² sin A))`; a record that stays
/// there longer than `2 t₃` and a sample was held; the fit starts at the
/// plateau's last sample. The noise `σ` is [`super::noise_of`] the angles
/// (a smooth motion's own fourth differences only raise it, so that less
/// is taken as held), `ω` the
/// record's crossings' and `A` its first sample from the mean. A record
/// that starts at the centre with three or more identical samples (where
/// a swinging bob is fastest) is at rest until the last of them. 0 when
/// the record starts moving.
pub fn held_start(time: &[f64], theta: &[f64]) -> usize {
    let Some((n, sigma, t)) = held_inputs(time, theta) else {
        return 0;
    };
    let guess = initial_guess(&t, theta);
    let offset = guess[4];
    // The frequency from the record's own crossings of its centre (the
    // guess's can be a harmonic, and a frequency too high takes a free
    // crest's dwell for a held bob).
    let swing = theta.iter().map(|v| (v - offset).abs()).fold(0.0, f64::max);
    let wd = crossing_frequency(&t, theta, offset, 0.1 * swing).unwrap_or(guess[1].abs());
    let mut first = theta[..3].to_vec();
    first.sort_by(f64::total_cmp);
    let crest = first[1];
    let sin_a = (crest - offset)
        .abs()
        .min(std::f64::consts::FRAC_PI_2)
        .sin();
    // Samples that do not change at the centre, where a swinging bob is
    // fastest, are a pendulum at rest before it is set going (a remote
    // lab's record, a tracker started early).
    if (crest - offset).abs() < 10.0 * sigma {
        let still = theta.iter().position(|v| *v != theta[0]).unwrap_or(n);
        return if (3..n / 2).contains(&still) {
            still - 1
        } else {
            0
        };
    }
    if !(sigma > 0.0 && wd > 0.0 && sin_a > 0.0) {
        return 0;
    }
    let t3 = (6.0 * sigma / (wd * wd * sin_a)).sqrt();
    let plateau = theta
        .iter()
        .position(|v| (v - crest).abs() > 3.0 * sigma)
        .unwrap_or(n);
    let end = t[plateau.min(n - 1)];
    if plateau >= n / 2 || end <= 2.0 * t3 + (t[1] - t[0]) {
        return 0;
    }
    // From the plateau's last sample: the release lies at or before it,
    // where the model puts it (a release after the first fitted sample
    // would be placed a whole period earlier).
    plateau - 1
}

/// What both rules for a held start need of a record: its samples (of
/// 40 or more), the noise of its values ([`super::noise_of`]) and the
/// times from its first sample.
fn held_inputs(time: &[f64], values: &[f64]) -> Option<(usize, f64, Vec<f64>)> {
    let n = time.len().min(values.len());
    if n < 40 {
        return None;
    }
    let sigma = super::noise_of(values)?;
    Some((n, sigma, time.iter().map(|x| x - time[0]).collect()))
}

/// `π (k - 1) / (t_k - t_1)` over the `k` crossings of `centre` from one
/// side of the band `centre ± band` to the other: the record's angular
/// frequency, whatever its harmonics; `None` below three crossings.
fn crossing_frequency(t: &[f64], theta: &[f64], centre: f64, band: f64) -> Option<f64> {
    let (mut side, mut first, mut last, mut count) = (0_i8, None, 0.0, 0_usize);
    for (&ti, &v) in t.iter().zip(theta) {
        let s = if v > centre + band {
            1
        } else if v < centre - band {
            -1
        } else {
            0
        };
        if s != 0 {
            if side != 0 && s != side {
                count += 1;
                first.get_or_insert(ti);
                last = ti;
            }
            side = s;
        }
    }
    let first = first?;
    (count >= 3 && last > first).then(|| std::f64::consts::PI * (count - 1) as f64 / (last - first))
}

/// [`held_start`] for a gyroscope's angular velocities: a bob held (or
/// hanging still) reads the gyroscope's zero; a free motion leaves a
/// crest's zero rate by `ω² sin A · t`, so it stays within three noise
/// deviations `σ` for `t₃ = 3σ / (ω² sin A)`, the swing `A` being the
/// largest rate over the crossings' `ω`. A record whose first samples stay
/// at their own level longer than `2 t₃` was held: the fit starts at the
/// plateau's last sample. 0 when the record starts moving.
pub fn held_still(time: &[f64], rate: &[f64]) -> usize {
    let Some((n, sigma, t)) = held_inputs(time, rate) else {
        return 0;
    };
    let offset = rate.iter().sum::<f64>() / n as f64;
    let peak = rate.iter().map(|v| (v - offset).abs()).fold(0.0, f64::max);
    let Some(wd) = crossing_frequency(&t, rate, offset, 0.1 * peak) else {
        return 0;
    };
    let mut first = rate[..3].to_vec();
    first.sort_by(f64::total_cmp);
    let level = first[1];
    // Moving at the start: a rate well away from the zero.
    if (level - offset).abs() > 0.2 * peak {
        return 0;
    }
    let sin_a = (peak / wd).min(std::f64::consts::FRAC_PI_2).sin();
    if !(sigma > 0.0 && wd > 0.0 && sin_a > 0.0) {
        return 0;
    }
    let t3 = 3.0 * sigma / (wd * wd * sin_a);
    let plateau = rate
        .iter()
        .position(|v| (v - level).abs() > 3.0 * sigma)
        .unwrap_or(n);
    let end = t[plateau.min(n - 1)];
    if plateau >= n / 2 || end <= 2.0 * t3 + (t[1] - t[0]) {
        return 0;
    }
    plateau - 1
}

/// The angle swing of a record of `observed` values: the largest swing
/// about the middle ([`largest_swing`]) of angles, or of rates divided by
/// the record's angular frequency (its crossings'), rad.
pub fn swing_of(time: &[f64], values: &[f64], observed: Observed) -> f64 {
    let swing = largest_swing(values);
    match observed {
        Observed::Angle => swing,
        Observed::AngularVelocity => {
            let n = time.len().min(values.len());
            if n < 2 {
                return 0.0;
            }
            let t: Vec<f64> = time[..n].iter().map(|x| x - time[0]).collect();
            let centre = values[..n].iter().sum::<f64>() / n as f64;
            let w = crossing_frequency(&t, &values[..n], centre, 0.1 * swing)
                .unwrap_or_else(|| initial_guess(&t, &values[..n])[1].abs());
            swing / w
        }
    }
}

/// Starting values for the closed form of `observed` from the record
/// itself ([`initial_guess`]); for rates, the guess of the rate's own
/// cosine `R cos(ω_d t + ψ)` is the angle's `A = R/ω_n`, `φ = ψ - π/2 - δ`
/// with `sin δ = ζ`.
fn guess_of(t: &[f64], values: &[f64], observed: Observed) -> Vec<f64> {
    let mut guess = initial_guess(t, values);
    if observed == Observed::AngularVelocity {
        let (wd, zeta) = (guess[1].abs().max(f64::MIN_POSITIVE), guess[2]);
        let wn = wd / (1.0 - zeta * zeta).max(f64::MIN_POSITIVE).sqrt();
        guess[0] /= wn;
        guess[3] -= std::f64::consts::FRAC_PI_2 + zeta.clamp(-1.0, 1.0).asin();
    }
    guess
}

/// Fits `model` to a record that starts at or after the release.
fn fit_released(
    model: TrajectoryModel,
    time: &[f64],
    theta: &[f64],
    observed: Observed,
    drag_laws: &[usize],
) -> Result<TrajectoryFit, FitError> {
    // Five parameters and a residual to judge them by.
    let points = time.len().min(theta.len());
    if points <= 5 {
        return Err(FitError::TooFewPoints {
            points,
            parameters: 5,
        });
    }
    let t0 = time.first().copied().unwrap_or(0.0);
    let t: Vec<f64> = time.iter().map(|x| x - t0).collect();
    let (windows, mut lin, lin_first) = staged_linear(&t, theta, observed)?;
    canonical_linear(&mut lin);
    let (w0, w0_error) = linear_natural_frequency(&lin, t.last().copied().unwrap_or(0.0));
    let linear_fit = |fit: Fit, rejected: Option<f64>| TrajectoryFit {
        model: TrajectoryModel::Linear,
        law: Law::VISCOUS,
        fit,
        natural_angular_frequency: w0,
        natural_angular_frequency_error: w0_error,
        nonlinear_rms_rejected: rejected,
        held_samples: 0,
        held_seconds: 0.0,
        observed,
    };
    if model == TrajectoryModel::Linear {
        return Ok(linear_fit(lin, None));
    }
    let mut initial = nonlinear_start(&lin_first);
    for &n in &windows[..windows.len() - 1] {
        let curve = NonlinearCurve::new(&t[..n], Law::VISCOUS, observed);
        // A window too short to determine every parameter (the damping
        // over a few periods of a high Q) leaves the start as it was for
        // the next, longer one.
        if let Ok(f) = fit_curve(&curve, &t[..n], &theta[..n], None, &initial) {
            initial = f.parameters;
        }
    }
    let curve = NonlinearCurve::new(&t, Law::VISCOUS, observed);
    let linear_rms = lin.residual_rms;
    // ζ held at its bound 0 has no slope there: a record with no damping
    // to measure, whose best ζ the noise puts below 0, ends there with no
    // covariance (or does not converge). Such a fit is made again with ζ
    // free of sign (a swing that grows a little), from where it ended.
    // (Only then: free of sign from the start, the growing windows of a
    // heavily damped wide swing can step into a growing motion and a false
    // minimum, seed 1052 of the coverage records.)
    let signed = NonlinearCurve::new(&t, Law::VISCOUS, observed).signed();
    let (fit, curve) = match fit_curve(&curve, &t, theta, None, &initial) {
        Ok(fit) if fit.parameters[2] > 0.0 => (Ok(fit), &curve),
        Ok(fit) => match fit_curve(&signed, &t, theta, None, &fit.parameters) {
            Ok(free) => (Ok(free), &signed),
            Err(_) => (Ok(fit), &curve),
        },
        Err(_) => (fit_curve(&signed, &t, theta, None, &initial), &signed),
    };
    // A nonlinear fit that fails outright (its parameters not determined
    // from this start) leaves the linear one, which says so.
    let Ok(fit) = fit else {
        return Ok(linear_fit(lin, Some(f64::NAN)));
    };
    let fit = last_release(curve, &t, theta, fit)?;
    // A nonlinear fit that ran off (its release amplitude driven to the
    // top, or not determined by the data: a release rewound through heavy
    // damping, a record that does not follow a free decay) and fits worse
    // than the linear one is not reported: the linear fit is returned, and
    // says so. (A sound nonlinear fit may still be a little worse than the
    // linear one on data that follow the linear equation exactly.)
    let (a, a_error) = (fit.parameters[0].abs(), fit.standard_errors[0]);
    let ran_off = a >= 3.0 || a_error.is_nan() || a_error >= a;
    if ran_off && (fit.residual_rms.is_nan() || fit.residual_rms > linear_rms) {
        return Ok(linear_fit(lin, Some(fit.residual_rms)));
    }
    // Drag and friction, each and both, from the viscous fit: kept when
    // the information criterion prefers them and their coefficients are
    // determined.
    // Each drag law's search; the best of them by the criterion.
    let mut best: Option<(Fit, Law)> = None;
    for &drag in drag_laws {
        let found = with_damping_laws(&t, theta, fit.clone(), observed, drag);
        if best.as_ref().is_none_or(|b| found.0.bic < b.0.bic) {
            best = Some(found);
        }
    }
    let (mut fit, law) = best.unwrap_or((fit, Law::VISCOUS));
    report_released(&mut fit);
    let (w, e) = (fit.parameters[1].abs(), fit.standard_errors[1]);
    Ok(TrajectoryFit {
        model,
        law,
        fit,
        natural_angular_frequency: w,
        natural_angular_frequency_error: e,
        nonlinear_rms_rejected: None,
        held_samples: 0,
        held_seconds: 0.0,
        observed,
    })
}

/// The linear fit over growing windows (see [`stages`]): a long record
/// of large swings, whose period changes with the amplitude, loses a fit
/// started from the whole record's phase (a false minimum, issue 23); a
/// few periods first, then twice as many, each fit started from the
/// last, follow it. (A window the linear model cannot fit, one where the
/// swing stops, say, leaves the whole record in one.) Returns the
/// windows, the fit of the whole and the fit of the first window.
fn staged_linear(
    t: &[f64],
    theta: &[f64],
    observed: Observed,
) -> Result<(Vec<usize>, Fit, Fit), FitError> {
    let linear = linear_of(observed);
    let staged = |windows: &[usize]| -> Result<(Fit, Fit), FitError> {
        let first = windows[0];
        let mut lin = fit_curve(
            &linear,
            &t[..first],
            &theta[..first],
            None,
            &guess_of(&t[..first], &theta[..first], observed),
        )?;
        let lin_first = lin.clone();
        for &n in &windows[1..] {
            lin = fit_curve(&linear, &t[..n], &theta[..n], None, &lin.parameters)?;
        }
        Ok((lin, lin_first))
    };
    let windows = stages(t, theta);
    match staged(&windows) {
        Ok((lin, first)) => Ok((windows, lin, first)),
        Err(_) if windows.len() > 1 => {
            let whole = vec![t.len()];
            let (lin, first) = staged(&whole)?;
            Ok((whole, lin, first))
        }
        Err(e) => Err(e),
    }
}

/// The natural angular frequency (rad/s) and its standard error from the
/// linear fit of a record ending at `t_end` (s): its `ω_d` undamped and
/// carried to the finite amplitude the record has at its middle.
fn linear_natural_frequency(lin: &Fit, t_end: f64) -> (f64, f64) {
    let (a, wd, zeta) = (
        lin.parameters[0].abs(),
        lin.parameters[1],
        lin.parameters[2],
    );
    let damping_factor = (1.0 - zeta * zeta).max(f64::MIN_POSITIVE).sqrt();
    let mid = 0.5 * t_end;
    let a_mid = (a * (-zeta * wd / damping_factor * mid).exp()).min(3.1);
    let ratio = Amplitude::from_radians(a_mid)
        .map(period_ratio)
        .unwrap_or(1.0);
    (
        wd / damping_factor * ratio,
        lin.standard_errors[1] / damping_factor * ratio,
    )
}

/// The release is the last crest at or before the first sample: a
/// release a whole period (or more) earlier fits the same curve with a
/// larger amplitude, so it is moved one period later, to the crest the
/// fitted motion reaches there, and fitted again from that start (three
/// times at most).
fn last_release(
    curve: &NonlinearCurve<'_>,
    t: &[f64],
    theta: &[f64],
    mut fit: Fit,
) -> Result<Fit, FitError> {
    for _ in 0..3 {
        let p = &fit.parameters;
        let ratio = release_period_ratio(p[0]);
        if p[3].abs() < std::f64::consts::TAU * ratio {
            break;
        }
        let Some((time, angle)) = crest_after_one_period(&Law::VISCOUS.full(p)) else {
            break;
        };
        let start = [angle, p[1], p[2], p[3] - p[1].abs() * time, p[4]];
        fit = fit_curve(curve, t, theta, None, &start)?;
    }
    Ok(fit)
}

/// The linear fit's curve written with `A >= 0` and `φ` in `(-π, π]` (a
/// negative amplitude is a phase shifted by π).
fn canonical_linear(lin: &mut Fit) {
    if lin.parameters[0] < 0.0 {
        lin.parameters[0] = -lin.parameters[0];
        lin.parameters[3] += std::f64::consts::PI;
        rescale(lin, 0, -1.0);
    }
    let wrapped = lin.parameters[3].rem_euclid(std::f64::consts::TAU);
    lin.parameters[3] = if wrapped > std::f64::consts::PI {
        wrapped - std::f64::consts::TAU
    } else {
        wrapped
    };
}

/// The nonlinear fit's start `[A, ω_n, ζ, φ, θ_off]` from the linear fit
/// of the first window (where the phase is sure): released from rest at
/// the crest before the first sample, which the linear fit's phase
/// places `φ/ω_d` earlier; a release more than three quarters of a
/// period before the first sample is taken as the crest just after it.
fn nonlinear_start(lin_first: &Fit) -> Vec<f64> {
    let (a1, wd1, zeta1) = {
        let p = &lin_first.parameters;
        (p[0].abs(), p[1], p[2])
    };
    let damping1 = (1.0 - zeta1 * zeta1).max(f64::MIN_POSITIVE).sqrt();
    let ratio1 = Amplitude::from_radians(a1.min(3.1))
        .map(period_ratio)
        .unwrap_or(1.0);
    let wn = wd1 / damping1 * ratio1;
    let mut phase = lin_first.parameters[3];
    if lin_first.parameters[0] < 0.0 {
        phase += std::f64::consts::PI;
    }
    // A release more than three quarters of a period before the first
    // sample is the crest just after it: released there, the few samples
    // before it are the motion's mirror image (a record that starts just
    // before a crest, or on a held bob, would otherwise be fitted from a
    // release a whole period earlier, its amplitude carried through that
    // period's decay).
    let phase = phase.rem_euclid(std::f64::consts::TAU);
    let phase = if phase > LATEST_RELEASE {
        phase - std::f64::consts::TAU
    } else {
        phase
    };
    let a_release = a1 * (zeta1 * wd1 / damping1 * phase / wd1).exp();
    vec![
        a_release,
        wn,
        zeta1.max(0.0),
        phase,
        lin_first.parameters[4],
    ]
}

/// The nonlinear fit as reported: its phase as a fraction of the true
/// (finite-amplitude) period (the release lies phase/2π of a period
/// before the first sample), its amplitude and its damping laws'
/// coefficients positive.
fn report_released(fit: &mut Fit) {
    let ratio = release_period_ratio(fit.parameters[0]);
    fit.parameters[3] /= ratio;
    fit.standard_errors[3] /= ratio;
    rescale(fit, 3, 1.0 / ratio);
    for j in (0..1).chain(5..fit.parameters.len()) {
        if fit.parameters[j] < 0.0 {
            fit.parameters[j] = -fit.parameters[j];
            rescale(fit, j, -1.0);
        }
    }
}

/// The covariance of a fit whose parameter `j` was multiplied by `factor`
/// (its sign turned, or its unit changed): row and column `j` scale by it.
fn rescale(fit: &mut Fit, j: usize, factor: f64) {
    for (r, row) in fit.covariance.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            if r == j {
                *v *= factor;
            }
            if c == j {
                *v *= factor;
            }
        }
    }
}

/// A coefficient of a damping law must exceed this many of its standard
/// errors to be kept: one that does not is at its bound, and the law is a
/// smaller one.
pub const LAW_DETERMINED_SIGMA: f64 = 2.0;

/// The patience of the damping laws' fits (the evaluations allowed, per
/// parameter and one): a law the record does not show leaves its
/// coefficient wandering, and each evaluation integrates the whole record.
pub const LAW_PATIENCE: usize = 20;

/// The viscous nonlinear `fit` refitted with quadratic drag and dry
/// friction beside the viscous damping, started from it with the decay
/// shared between the laws, over the growing windows; then each law alone,
/// started from that fit with the dropped law's decay handed to the
/// viscous rate (only the law without a coefficient within
/// [`LAW_DETERMINED_SIGMA`] standard errors of its bound 0, when just one
/// is); where the whole record does not settle with both laws (a rate at
/// its bound has no gradient), each alone from where the windows left
/// them. The best by the Bayesian information criterion among the viscous
/// fit and the laws whose added coefficients are all determined, with its
/// law. (Both laws first: from the viscous fit a single added law can
/// lose its way on a record that needs the other. Each alone too: the
/// three rates trade one for another, and both laws can settle on drag in
/// place of the viscous part. Each fit of a long record costs as much as
/// the viscous one.)
fn with_damping_laws(
    t: &[f64],
    theta: &[f64],
    fit: Fit,
    observed: Observed,
    drag: usize,
) -> (Fit, Law) {
    let both = Law {
        drag: Some(drag),
        friction: true,
    };
    let p = fit.parameters.clone();
    let (a, zeta, wn) = (p[0].abs().max(1e-6), p[2].max(1e-6), p[1].abs());
    // The viscous rate ζ shared equally among the laws: the drag matches
    // it at the swing A at `drag_for` (b = 2ζ/A, quadratic), friction
    // when r = πζA/2 (the same loss per half swing).
    let share = zeta / 3.0;
    let mut start = p.clone();
    start[2] = share;
    start.push(drag_for(drag, share, a, wn));
    start.push(0.5 * std::f64::consts::PI * share * a);
    let determined = |f: &Fit| -> Vec<bool> {
        f.parameters[5..]
            .iter()
            .zip(&f.standard_errors[5..])
            .map(|(v, se)| se.is_finite() && v.abs() > LAW_DETERMINED_SIGMA * se)
            .collect()
    };
    let fit_law = |law: Law, start: &[f64]| {
        fit_curve_patient(
            &NonlinearCurve::new(t, law, observed),
            t,
            theta,
            start,
            LAW_PATIENCE,
        )
        .ok()
        .filter(|f| f.parameters[2] >= -f.standard_errors[2])
    };
    // Both laws over the growing windows of the viscous fit, each started
    // from the last (from a viscous fit that missed a swing's stop by
    // friction, the whole record at once is too far).
    let mut windowed = start.clone();
    let fitted_both = {
        let windows = stages(t, theta);
        let mut start = start;
        for &n in &windows[..windows.len() - 1] {
            let curve = NonlinearCurve::new(&t[..n], both, observed);
            if let Ok(f) = fit_curve_patient(&curve, &t[..n], &theta[..n], &start, LAW_PATIENCE) {
                start = f.parameters;
            }
        }
        windowed.clone_from(&start);
        fit_law(both, &start)
    };
    let mut candidates: Vec<(Fit, Law)> = Vec::new();
    match fitted_both {
        Some(both_fit) => {
            let kept = determined(&both_fit);
            // The law without the coefficient at its bound; with neither
            // determined (the two laws and the viscous rate trade off over
            // a short record), each alone; with both determined, each
            // alone too: three rates can trade one for another (a record
            // of viscous damping and friction fitted with drag in place of
            // the viscous part, seed 1007 of the coverage records), and
            // the information criterion judges the smaller laws on their
            // own fits.
            let laws: &[(bool, usize)] = match (kept[0], kept[1]) {
                (true, false) => &[(true, 5)],
                (false, true) => &[(false, 6)],
                _ => &[(true, 5), (false, 6)],
            };
            for &(keeps_drag, index) in laws {
                let law = Law {
                    drag: keeps_drag.then_some(drag),
                    friction: !keeps_drag,
                };
                // The dropped law's decay handed to the viscous rate (the
                // loss per half swing at the amplitude, as above).
                let q = &both_fit.parameters;
                let amplitude = q[0].abs().max(1e-6);
                let handed = if keeps_drag {
                    2.0 * q[6].abs() / (std::f64::consts::PI * amplitude)
                } else {
                    zeta_for(drag, q[5].abs(), amplitude, q[1].abs())
                };
                let mut reduced = q[..5].to_vec();
                reduced[2] = (reduced[2] + handed).max(0.5 * zeta * 1e-3);
                reduced.push(q[index].abs().max(1e-9));
                if let Some(f) = fit_law(law, &reduced) {
                    candidates.push((f, law));
                }
            }
            if kept.iter().all(|&k| k) {
                candidates.push((both_fit, both));
            }
        }
        None => {
            for law in [
                Law {
                    drag: Some(drag),
                    friction: false,
                },
                Law {
                    drag: None,
                    friction: true,
                },
            ] {
                // From where the growing windows left both laws (the whole
                // record may not settle with both when one is at its
                // bound: its rate has no gradient there), else from the
                // viscous fit with the decay shared.
                let index = if law.drag.is_some() { 5 } else { 6 };
                let mut from_windows = windowed[..5].to_vec();
                from_windows[2] = from_windows[2].max(0.5 * zeta * 1e-3);
                from_windows.push(windowed[index].abs().max(1e-9));
                let mut one = p.clone();
                one[2] = 0.5 * zeta;
                one.push(if law.drag.is_some() {
                    drag_for(drag, 0.5 * zeta, a, wn)
                } else {
                    0.25 * std::f64::consts::PI * zeta * a
                });
                if let Some(f) = fit_law(law, &from_windows).or_else(|| fit_law(law, &one)) {
                    candidates.push((f, law));
                }
            }
        }
    }
    let mut best = (fit, Law::VISCOUS);
    for (f, law) in candidates {
        if determined(&f).iter().all(|&k| k) && f.bic < best.0.bic {
            best = (f, law);
        }
    }
    best
}

/// The sample counts of the growing windows a fit goes through: the first
/// [`FIRST_WINDOW_PERIODS`] periods (by the record's own crossings), then
/// twice as long each time, the last the whole record. A shorter record
/// starts on its first half; one of fewer than four periods is one window.
fn stages(t: &[f64], theta: &[f64]) -> Vec<usize> {
    let n = t.len();
    let guess = initial_guess(t, theta);
    let wd = guess[1].abs();
    let span = t.last().copied().unwrap_or(0.0);
    let period = std::f64::consts::TAU / wd;
    // A record of fewer than twice the first window's periods starts on
    // its first half (at least two periods): a short, heavily damped
    // record of large swings loses its phase as a long one does.
    let first = (FIRST_WINDOW_PERIODS * period).min(0.5 * span);
    if !(wd.is_finite() && wd > 0.0) || first < 2.0 * period {
        return vec![n];
    }
    let mut out = Vec::new();
    let mut end = first;
    while end < span {
        let k = t.partition_point(|&x| x <= end);
        // At least enough points to fit, and growing.
        if k > 10 && out.last().is_none_or(|&last| k > last) {
            out.push(k);
        }
        end *= 2.0;
    }
    out.push(n);
    out
}

/// The latest start of the nonlinear fit's release, as a phase before the
/// first sample (rad of the linear fit's period): beyond it the release is
/// placed at the crest after the first sample (a negative phase).
pub const LATEST_RELEASE: f64 = 1.5 * std::f64::consts::PI;

/// The first window of a staged fit, periods.
pub const FIRST_WINDOW_PERIODS: f64 = 4.0;

/// The turning points (index from the release, time after it, s, signed
/// angle, rad) of the motion of nonlinear parameters `[A, ω_n, ζ, φ, θ_off,
/// b, r]` released from rest at `A`, up to `until` s after the release
/// (DOP853 at 1e-12); the release is index 0.
fn crests_until(p: &Motion, until: f64) -> Option<Vec<(u64, f64, f64)>> {
    let model = model_of(p)?;
    let amplitude = Amplitude::from_radians(p[0].abs().min(3.1)).ok()?;
    struct All(Vec<(u64, f64, f64)>);
    impl Observer for All {
        fn turning_point(
            &mut self,
            tp: &crate::simulation::TurningPoint,
        ) -> crate::simulation::Action {
            self.0.push((tp.index, tp.time, tp.angle));
            crate::simulation::Action::Continue
        }
    }
    let options = Options {
        duration: until + 1e-9 * until.max(1.0),
        tolerance: 1e-12,
        method: Method::Dop853,
        sample_interval: None,
    };
    let mut all = All(Vec::new());
    simulate(&model, amplitude, &options, &mut all).ok()?;
    if all.0.first().is_none_or(|c| c.0 != 0) {
        all.0.insert(0, (0, 0.0, p[0].abs()));
    }
    Some(all.0)
}

/// The amplitudes (rad, unsigned) of the motion of nonlinear parameters
/// `[A, ω_n, ζ, ...]` at its turning points `first` and `last` (indices
/// from the release, 0 the release itself).
fn crest_angles(p: &Motion, first: u64, last: u64) -> Option<(f64, f64)> {
    let model = model_of(p)?;
    let amplitude = Amplitude::from_radians(p[0].abs().min(3.1)).ok()?;
    struct Two {
        first: u64,
        last: u64,
        found: (Option<f64>, Option<f64>),
    }
    impl Observer for Two {
        fn turning_point(
            &mut self,
            tp: &crate::simulation::TurningPoint,
        ) -> crate::simulation::Action {
            if tp.index == self.first {
                self.found.0 = Some(tp.angle.abs());
            }
            if tp.index == self.last {
                self.found.1 = Some(tp.angle.abs());
                return crate::simulation::Action::Stop;
            }
            crate::simulation::Action::Continue
        }
    }
    // Half a period a half swing, and room: the motion stops at the last.
    let wn = p[1].abs().max(f64::MIN_POSITIVE);
    let options = Options {
        duration: (last as f64 + 2.0) * std::f64::consts::PI / wn * release_period_ratio(p[0]),
        tolerance: 1e-12,
        method: Method::Dop853,
        sample_interval: None,
    };
    let mut two = Two {
        first,
        last,
        found: (if first == 0 { Some(p[0].abs()) } else { None }, None),
    };
    simulate(&model, amplitude, &options, &mut two).ok()?;
    match two.found {
        (Some(a), Some(b)) => Some((a, b)),
        _ => None,
    }
}

/// A figure of a fit's parameters (the loss per radian over the record).
type LossOf = dyn Fn(&[f64]) -> Option<f64>;

/// `T(A)/T0` at the release amplitude `a` (rad).
fn release_period_ratio(a: f64) -> f64 {
    Amplitude::from_radians(a.abs().min(3.1))
        .map(period_ratio)
        .unwrap_or(1.0)
}

/// The time after release (s) and angle (rad) of the crest one period after
/// the release, for nonlinear parameters `[A, ω_n, ζ, φ, θ_off, b, r]`.
fn crest_after_one_period(p: &Motion) -> Option<(f64, f64)> {
    turning_point_where(p, 0.0, |index, _| index == 2)
}

/// The first turning point (time after the release, s, and signed angle,
/// rad) at or after `after` seconds of the motion of nonlinear parameters
/// `[A, ω_n, ζ, ...]` released from rest at `A`.
fn turning_point_after(p: &Motion, after: f64) -> Option<(f64, f64)> {
    turning_point_where(p, after, |index, time| index >= 1 && time >= after)
}

/// The first turning point `pick` (its index from the release, its time)
/// takes, of the motion of nonlinear parameters `[A, ω_n, ζ, ...]`
/// released from rest at `A`, within `span` s and a period and a half
/// (DOP853 at 1e-12).
fn turning_point_where(
    p: &Motion,
    span: f64,
    pick: impl Fn(u64, f64) -> bool,
) -> Option<(f64, f64)> {
    let model = model_of(p)?;
    let pendulum = model.pendulum;
    let amplitude = Amplitude::from_radians(p[0].abs().min(3.1)).ok()?;
    struct Pick<F>(F, Option<(f64, f64)>);
    impl<F: Fn(u64, f64) -> bool> Observer for Pick<F> {
        fn turning_point(
            &mut self,
            tp: &crate::simulation::TurningPoint,
        ) -> crate::simulation::Action {
            if (self.0)(tp.index, tp.time) {
                self.1 = Some((tp.time, tp.angle));
                return crate::simulation::Action::Stop;
            }
            crate::simulation::Action::Continue
        }
    }
    let options = Options {
        duration: span + 1.5 * pendulum.period(amplitude),
        tolerance: 1e-12,
        method: Method::Dop853,
        sample_interval: None,
    };
    let mut found = Pick(pick, None);
    simulate(&model, amplitude, &options, &mut found).ok()?;
    found.1
}

/// Starting values from the record itself: the offset is the mean, the
/// frequency comes from the upward crossings of the mean, the amplitude
/// from the first period's extremes, the damping from the first and last
/// periods' amplitudes, the phase from the first sample.
fn initial_guess(t: &[f64], theta: &[f64]) -> Vec<f64> {
    let n = t.len();
    let offset = theta.iter().sum::<f64>() / n as f64;
    let crossings: Vec<f64> = (1..n)
        .filter(|&i| theta[i - 1] < offset && theta[i] >= offset)
        .map(|i| {
            let f = (offset - theta[i - 1]) / (theta[i] - theta[i - 1]);
            t[i - 1] + f * (t[i] - t[i - 1])
        })
        .collect();
    let wd = if crossings.len() >= 2 {
        std::f64::consts::TAU * (crossings.len() - 1) as f64
            / (crossings[crossings.len() - 1] - crossings[0])
    } else {
        std::f64::consts::TAU / t[n - 1].max(f64::MIN_POSITIVE)
    };
    let period = std::f64::consts::TAU / wd;
    let peak = |from: f64, to: f64| {
        t.iter()
            .zip(theta)
            .filter(|(x, _)| **x >= from && **x <= to)
            .map(|(_, y)| (y - offset).abs())
            .fold(0.0_f64, f64::max)
    };
    let span = t[n - 1];
    let (early, late) = (peak(0.0, period), peak(span - period, span));
    let a = early.max(f64::MIN_POSITIVE);
    let zeta = if late > 0.0 && early > late && span > 2.0 * period {
        ((early / late).ln() / ((span - period) * wd)).min(0.5)
    } else {
        1e-4
    };
    let c = ((theta[0] - offset) / a).clamp(-1.0, 1.0);
    let rising = n > 1 && theta[1] > theta[0];
    let phase = if rising { -c.acos() } else { c.acos() };
    vec![a, wd, zeta, phase, offset]
}

/// The most negative `ζ` the nonlinear model takes (a swing that grows
/// by e in 16 periods; the fit is of a free decay, and a record that grows
/// faster is not one): below it the model is held there.
const MOST_NEGATIVE_ZETA: f64 = -0.01;

/// The equation of motion of nonlinear parameters `[A, ω_n, ζ, φ, θ_off,
/// k, r]`, if they make one. `ζ` keeps its sign (down to
/// [`MOST_NEGATIVE_ZETA`]; the fit's curve holds it at 0 but where it
/// refits a record with no damping to measure, [`NonlinearCurve::signed`]:
/// such a record's best `ζ` lies on either side of 0 by its noise, and a
/// model held at 0 there has no slope in `ζ`, so that the fit had no
/// covariance and was refused: 8 of 18 exact undamped swings with 1e-4 rad
/// of noise fell back to the linear fit).
fn model_of(p: &Motion) -> Option<Model> {
    let wn = p[1].abs();
    let pendulum = Pendulum::with_standard_gravity(9.806_65 / (wn * wn)).ok()?;
    Model::new(
        pendulum,
        Damping::of_either_sign(p[2].max(MOST_NEGATIVE_ZETA))?,
        0.0,
        p[6].abs(),
    )
    .ok()?
    .with_drag(p.drag, p[5].abs())
    .ok()
}

/// The nonlinear model evaluated by simulation. The fit asks for the
/// points one at a time but always a whole parameter set in a row, so one
/// simulation per parameter set, kept in `cache`, serves them all.
struct NonlinearCurve<'a> {
    times: &'a [f64],
    law: Law,
    observed: Observed,
    /// Whether ζ keeps its sign (down to [`MOST_NEGATIVE_ZETA`]); else it
    /// is held at 0 below it.
    signed_zeta: bool,
    cache: RefCell<Simulated>,
}

/// A simulation's samples for one parameter set.
#[derive(Default)]
struct Simulated {
    parameters: Vec<f64>,
    states: Vec<State>,
    interval: f64,
}

/// Collects the samples of a simulation for Hermite interpolation.
struct Samples(Vec<State>);

impl Observer for Samples {
    fn sample(&mut self, _time: f64, state: &State) -> bool {
        self.0.push(*state);
        true
    }
}

impl Curve for NonlinearCurve<'_> {
    /// θ at `x` for parameters `[A, ω_n, ζ, φ, θ_off]`.
    fn value(&self, x: f64, p: &[f64]) -> f64 {
        let mut cache = self.cache.borrow_mut();
        if cache.parameters.as_slice() != p {
            let (states, interval) = self.simulate(p);
            *cache = Simulated {
                parameters: p.to_vec(),
                states,
                interval,
            };
        }
        if cache.states.len() < 2 {
            return f64::NAN;
        }
        // Before a release after the first sample, the motion's mirror
        // image: from rest at a crest it is the same either way but for
        // the damping's work over those few samples.
        let lead = p[3] / p[1].abs().max(f64::MIN_POSITIVE);
        let s = x + lead;
        match self.observed {
            Observed::Angle => hermite(&cache.states, cache.interval, s.abs()) + p[4],
            // The mirror image's velocity changes sign.
            Observed::AngularVelocity => {
                s.signum() * cubic_velocity(&cache.states, cache.interval, s.abs()) + p[4]
            }
        }
    }
}

impl<'a> NonlinearCurve<'a> {
    fn new(times: &'a [f64], law: Law, observed: Observed) -> Self {
        Self {
            times,
            law,
            observed,
            signed_zeta: false,
            cache: RefCell::new(Simulated::default()),
        }
    }

    /// The same curve with ζ free of sign.
    fn signed(self) -> Self {
        Self {
            signed_zeta: true,
            ..self
        }
    }

    fn simulate(&self, p: &[f64]) -> (Vec<State>, f64) {
        let mut full = self.law.full(p);
        if !self.signed_zeta {
            full.p[2] = full.p[2].max(0.0);
        }
        let (a, wn, phase) = (full[0], full[1].abs(), full[3]);
        let span = self.times.last().copied().unwrap_or(0.0);
        let lead = (phase / wn.max(f64::MIN_POSITIVE)).max(0.0);
        let (Some(model), Ok(amplitude)) =
            (model_of(&full), Amplitude::from_radians(a.abs().min(3.1)))
        else {
            return (Vec::new(), 1.0);
        };
        // A step of the minimiser to a frequency no record of these times
        // could show (more periods than samples) would integrate for
        // hours: it has no value, and the step is refused.
        let periods = (span * wn + phase.max(0.0)) / std::f64::consts::TAU;
        if periods.is_nan() || periods > self.times.len() as f64 + 10.0 {
            return (Vec::new(), 1.0);
        }
        // Cubic Hermite between samples errs by about (ωh)^4/384 of the
        // amplitude: 2e-9 at 200 samples a period, below any video's noise.
        let h = std::f64::consts::TAU / wn / 200.0;
        let options = Options {
            duration: span + lead + 2.0 * h,
            tolerance: 1e-12,
            method: Method::Dop853,
            sample_interval: Some(h),
        };
        let mut samples = Samples(Vec::new());
        match simulate(&model, amplitude, &options, &mut samples) {
            Ok(_) => (samples.0, h),
            Err(_) => (Vec::new(), h),
        }
    }
}

/// The angular velocity at `t` by four-point Lagrange interpolation of the
/// samples' velocities every `h` seconds from 0 (no acceleration is kept
/// to interpolate by Hermite): errs by about `(ωh)^4/40` of the peak rate,
/// 2e-8 at the 200 samples a period of [`NonlinearCurve`].
fn cubic_velocity(states: &[State], h: f64, t: f64) -> f64 {
    let n = states.len();
    if n < 4 {
        return linear_velocity(states, h, t);
    }
    let i = ((t / h).floor().max(0.0) as usize).clamp(1, n - 3) - 1;
    let x = t / h - i as f64;
    let v = |k: usize| states[i + k].angular_velocity;
    // Nodes at x = 0, 1, 2, 3.
    let l0 = -(x - 1.0) * (x - 2.0) * (x - 3.0) / 6.0;
    let l1 = x * (x - 2.0) * (x - 3.0) / 2.0;
    let l2 = -x * (x - 1.0) * (x - 3.0) / 2.0;
    let l3 = x * (x - 1.0) * (x - 2.0) / 6.0;
    l0 * v(0) + l1 * v(1) + l2 * v(2) + l3 * v(3)
}

/// Linear interpolation of the samples' velocities (fewer than four).
fn linear_velocity(states: &[State], h: f64, t: f64) -> f64 {
    match states.len() {
        0 => f64::NAN,
        1 => states[0].angular_velocity,
        n => {
            let i = ((t / h).floor().max(0.0) as usize).min(n - 2);
            let x = t / h - i as f64;
            (1.0 - x) * states[i].angular_velocity + x * states[i + 1].angular_velocity
        }
    }
}

/// Cubic Hermite interpolation of samples every `h` seconds from 0.
fn hermite(states: &[State], h: f64, t: f64) -> f64 {
    let i = ((t / h).floor().max(0.0) as usize).min(states.len().saturating_sub(2));
    let (a, b) = (states[i], states[i + 1]);
    let x = t / h - i as f64;
    let (h00, h10, h01, h11) = (
        (1.0 + 2.0 * x) * (1.0 - x) * (1.0 - x),
        x * (1.0 - x) * (1.0 - x),
        x * x * (3.0 - 2.0 * x),
        x * x * (x - 1.0),
    );
    h00 * a.angle + h10 * h * a.angular_velocity + h01 * b.angle + h11 * h * b.angular_velocity
}

#[cfg(test)]
mod tests {
    use super::undetermined;

    #[test]
    fn a_parameter_is_not_determined_when_its_error_exceeds_it() {
        let names = [
            "amplitude_rad",
            "omega_n_rad_s",
            "zeta",
            "phase_rad",
            "offset_rad",
        ];
        let values = [0.09, 3.2, 1e-5, 0.1, 0.0];
        // A NaN error determines nothing; an offset of zero is a value.
        let errors = [2e-4, f64::NAN, 2e-4, 0.5, 1e-4];
        assert_eq!(
            undetermined(&names, &values, &errors),
            vec!["omega_n_rad_s", "zeta"]
        );
        let errors = [2e-4, 1e-3, 2e-4, 4.0, 1e-4];
        assert_eq!(
            undetermined(&names, &values, &errors),
            vec!["zeta", "phase_rad"]
        );
    }
}
