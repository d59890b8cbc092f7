//! Which damping a pendulum has, from how its amplitude falls.
//!
//! Seven laws of amplitude against time, each the solution of an averaged
//! equation for the amplitude `A(t)`, `dA/dt = -(μ + λA + κA²)` with some
//! of the rates zero:
//!
//! | model | rates | law | source |
//! |---|---|---|---|
//! | `viscous` | λ | `A0 e^{-λt}`, `λ = ζω` | section 1-4 |
//! | `coulomb` | μ | `A0 - μt`, `μ = 2rω/π` (2r per half swing) | book section 2-4 |
//! | `quadratic` | κ | `A0 / (1 + κA0t)`, `κ = 4bω/(3π)` | energy balance with `⟨|sin|³⟩ = 4/(3π)` |
//! | `viscous+coulomb` | λ, μ | `A0 e^{-λt} + μ expm1(-λt)/λ` | the half-swing recursion's interpolant |
//! | `viscous+quadratic` | λ, κ | `λA0 e^{-λt} / (λ + κA0(1 - e^{-λt}))` | a Bernoulli equation: the usual pendulum in air |
//! | `coulomb+quadratic` | μ, κ | `s tan(atan(2κA0/s) - st/2)/(2κ)`, `s = 2√(κμ)` | the Riccati solution below with λ = 0 |
//! | `viscous+coulomb+quadratic` (once `full`) | λ, μ, κ | the Riccati solution below | all three |
//! | `three_halves` and any other drag law of power `p` in [`DRAG_LAWS`], alone or `viscous+`, `coulomb+`, `viscous+coulomb+` | κ and λ, μ | [`power_decay_law`]: `dA/dt = -(μ + λA + κA^p)` | the law's file: `κ = k ω^{p−1} ⟨|sin|^{p+1}⟩` |
//!
//! The laws of a drag law other than the quadratic come from the list of
//! [`crate::forces`]: a law added there is fitted here with nothing more.
//! They are fitted when named, or unnamed when the law says so
//! ([`DragLaw::searched`]: the 3/2 power does not, its decay being what
//! viscous damping and quadratic drag together follow over a record).
//!
//! The full law is solved by shifting to the equilibrium `a* = -2μ/(λ + √D)`
//! (`D = λ² - 4κμ`, a root of `κa² + λa + μ`), which turns it into the
//! viscous+quadratic law for `A - a*` with rate `√D`: stable as κ or μ
//! vanish, with no division by a small rate. When `D < 0` the solution is
//! `A = (s tan(atan((2κA0 + λ)/s) - st/2) - λ)/(2κ)`, `s = √(-D)`.
//!
//! Every rate is constrained to be at least 0 (damping never feeds
//! energy): the fit is the unconstrained least squares when all rates come
//! out non-negative, else the most negative is fixed at 0 and the rest
//! refitted (an active set; the result is the bounded least squares, as
//! SciPy's `curve_fit(..., bounds=(0, inf))` finds it). A rate fixed at 0
//! is listed in [`DecayFit::at_bound`]; such a fit is the simpler law
//! already in the list, and is never preferred. The list is closed under
//! "a rate at zero": it holds every combination of the three rates (all
//! seven), so that a law with a rate at its bound always equals a smaller
//! law that is fitted and compared too (the full law with its viscous rate
//! at 0 is `coulomb+quadratic`, and so on).
//!
//! The rates become the physical `ζ`, friction angle `r` and quadratic
//! drag `b` with the pendulum's angular frequency `ω` (given, or from the
//! turning points' times, or `2π/T(A)` at the data's median amplitude with
//! the exact period, [`crate::period`]).

use super::quality::{loss_per_radian, RecordQ};
use super::{fit_curve, propagate, straight_line, Fit, FitError};
use crate::forces::{DragLaw, DRAG_LAWS};
use crate::pendulum::{Amplitude, Pendulum};
use crate::simulation::QUADRATIC_DRAG;

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
    /// Viscous damping and air drag together: the usual pendulum in air.
    ViscousQuadratic,
    /// Dry friction and air drag together (no viscous part).
    CoulombQuadratic,
    /// Viscous damping, dry friction and air drag
    /// (`viscous+coulomb+quadratic`, the trajectory fit's name for it).
    Full,
    /// A drag law of [`DRAG_LAWS`] other than the quadratic one (whose
    /// laws are the variants above, in closed form), by its index there,
    /// alone or with the viscous and dry rates: `three_halves`,
    /// `viscous+three_halves`, `coulomb+three_halves`,
    /// `viscous+coulomb+three_halves`. A law added to the list is fitted
    /// by these with nothing more.
    Drag {
        /// The law's index in [`DRAG_LAWS`].
        law: usize,
        /// With viscous damping.
        viscous: bool,
        /// With dry friction.
        coulomb: bool,
    },
}

/// The names of the laws of each drag law of [`DRAG_LAWS`] (by index):
/// itself, then with viscous damping, dry friction, both. Made once.
pub(crate) fn drag_model_names() -> &'static [[&'static str; 4]] {
    static NAMES: std::sync::OnceLock<Vec<[&'static str; 4]>> = std::sync::OnceLock::new();
    NAMES.get_or_init(|| {
        DRAG_LAWS
            .iter()
            .map(|law| {
                let n = law.decay_name();
                let leak = |s: String| -> &'static str { Box::leak(s.into_boxed_str()) };
                [
                    n,
                    leak(format!("viscous+{n}")),
                    leak(format!("coulomb+{n}")),
                    leak(format!("viscous+coulomb+{n}")),
                ]
            })
            .collect()
    })
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
    /// Q over the record ([`super::quality`]): the energy the fitted law
    /// loses per radian of swing between the record's first and last
    /// times, `ln(E(A(t₀))/E(A(tₙ))) / (ω (tₙ − t₀))`, with its standard
    /// error from the fit's covariance; `None` without `ω` or a decay.
    /// What the trajectory fit reports for the same record, whatever the
    /// law.
    pub record_q: Option<RecordQ>,
    /// The viscous part's `Q = ω/(2λ) = 1/(2ζ)`, for the laws with viscous
    /// damping and a known `ω`, when that part is measurable (`ζ` at
    /// least two standard errors above 0). With drag or friction beside
    /// it, it is not the pendulum's Q ([`Self::record_q`] is).
    pub q_viscous: Option<f64>,
    /// When the viscous part is not measurable (`ζ` within two standard
    /// errors of 0, or below): the two-sigma lower bound on its Q,
    /// `1/(2 (ζ + 2σ_ζ))`, what the data can still say.
    pub q_viscous_lower_bound: Option<f64>,
    /// The rates held at their bound 0 (physical names when `ω` is known,
    /// else the rate names): the fit is then a simpler law's.
    pub at_bound: Vec<&'static str>,
}

impl DecayModel {
    /// Every model, simplest first.
    pub const ALL: [DecayModel; 7] = [
        DecayModel::Viscous,
        DecayModel::Coulomb,
        DecayModel::Quadratic,
        DecayModel::ViscousCoulomb,
        DecayModel::ViscousQuadratic,
        DecayModel::CoulombQuadratic,
        DecayModel::Full,
    ];

    /// Every law: the seven above, then those of each other drag law of
    /// [`DRAG_LAWS`] (its four).
    pub fn every() -> Vec<DecayModel> {
        let mut out = Self::ALL.to_vec();
        out.extend(Self::drag_models(|_| true));
        out
    }

    /// The laws fitted when none is named: the seven above and those of
    /// the other drag laws that are [`DragLaw::searched`].
    pub fn searched() -> Vec<DecayModel> {
        let mut out = Self::ALL.to_vec();
        out.extend(Self::drag_models(|law| law.searched()));
        out
    }

    /// The four laws of each drag law other than the quadratic one that
    /// `keep` keeps.
    fn drag_models(keep: impl Fn(&dyn DragLaw) -> bool) -> Vec<DecayModel> {
        (0..DRAG_LAWS.len())
            .filter(|&law| law != QUADRATIC_DRAG && keep(DRAG_LAWS[law]))
            .flat_map(|law| {
                [(false, false), (true, false), (false, true), (true, true)].map(
                    |(viscous, coulomb)| DecayModel::Drag {
                        law,
                        viscous,
                        coulomb,
                    },
                )
            })
            .collect()
    }

    /// The power of the law's drag rate κ (2 for the quadratic laws and
    /// those without drag, whose κ is 0).
    pub fn power(self) -> f64 {
        match self {
            DecayModel::Drag { law, .. } => DRAG_LAWS[law].power(),
            _ => 2.0,
        }
    }

    /// The drag law of its rate κ.
    fn drag_law(self) -> &'static dyn DragLaw {
        match self {
            DecayModel::Drag { law, .. } => DRAG_LAWS[law],
            _ => DRAG_LAWS[QUADRATIC_DRAG],
        }
    }

    /// The name on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            DecayModel::Drag {
                law,
                viscous,
                coulomb,
            } => drag_model_names()[law][usize::from(viscous) + 2 * usize::from(coulomb)],
            DecayModel::Viscous => "viscous",
            DecayModel::Coulomb => "coulomb",
            DecayModel::Quadratic => "quadratic",
            DecayModel::ViscousCoulomb => "viscous+coulomb",
            DecayModel::ViscousQuadratic => "viscous+quadratic",
            DecayModel::CoulombQuadratic => "coulomb+quadratic",
            DecayModel::Full => "viscous+coulomb+quadratic",
        }
    }

    /// The model called `name` (`full` is the law of all three rates, by
    /// the name it had before the trajectory fit and this one shared
    /// their names).
    pub fn from_name(name: &str) -> Option<Self> {
        if name == "full" {
            return Some(DecayModel::Full);
        }
        Self::every().into_iter().find(|m| m.name() == name)
    }

    /// Which of the rates λ (viscous), μ (dry), κ (quadratic) the law has.
    fn rates(self) -> [bool; 3] {
        match self {
            DecayModel::Viscous => [true, false, false],
            DecayModel::Coulomb => [false, true, false],
            DecayModel::Quadratic => [false, false, true],
            DecayModel::ViscousCoulomb => [true, true, false],
            DecayModel::ViscousQuadratic => [true, false, true],
            DecayModel::CoulombQuadratic => [false, true, true],
            DecayModel::Full => [true, true, true],
            DecayModel::Drag {
                viscous, coulomb, ..
            } => [viscous, coulomb, true],
        }
    }

    /// Names of the fitted parameters: `amplitude0_rad`, then the rates.
    pub fn rate_names(self) -> Vec<&'static str> {
        let mut names = vec!["amplitude0_rad"];
        let rate_names = [
            RATE_NAMES[0],
            RATE_NAMES[1],
            self.drag_law().decay_rate_name(),
        ];
        names.extend(
            rate_names
                .iter()
                .zip(self.rates())
                .filter(|(_, used)| *used)
                .map(|(n, _)| *n),
        );
        names
    }

    /// The physical parameters' names, in the order of the rates: `zeta`,
    /// `friction_angle_rad`, and the drag law's coefficient
    /// (`quadratic_drag_per_rad`, or the law's name: the key the
    /// simulation takes it by).
    fn physical_names(self) -> [&'static str; 3] {
        let drag = match self {
            DecayModel::Drag { law, .. } => DRAG_LAWS[law].name(),
            _ => "quadratic_drag_per_rad",
        };
        ["zeta", "friction_angle_rad", drag]
    }

    /// `[A0, λ, μ, κ]` from the parameters `p` (in the order of
    /// [`Self::rate_names`]), the rates the law lacks set to 0.
    fn full_rates(self, p: &[f64]) -> [f64; 4] {
        let mut out = [p[0], 0.0, 0.0, 0.0];
        let mut next = 1;
        for (k, used) in self.rates().into_iter().enumerate() {
            if used {
                out[k + 1] = p[next];
                next += 1;
            }
        }
        out
    }

    /// The amplitude at `t` for parameters `p` (in the order of [`Self::rate_names`]).
    pub fn amplitude(self, t: f64, p: &[f64]) -> f64 {
        match self {
            DecayModel::Drag { .. } => self.amplitudes(&[t], p)[0],
            _ => {
                let [a0, lambda, mu, kappa] = self.full_rates(p);
                decay_law(t, a0, lambda, mu, kappa)
            }
        }
    }

    /// The amplitudes at each of `times` for parameters `p` (in the order
    /// of [`Self::rate_names`]): one integration through the times where
    /// the law has no closed form (see [`power_decay_law`]).
    pub fn amplitudes(self, times: &[f64], p: &[f64]) -> Vec<f64> {
        let [a0, lambda, mu, kappa] = self.full_rates(p);
        match self {
            DecayModel::Drag { law, .. } => {
                power_decay_law(times, a0, [lambda, mu, kappa], DRAG_LAWS[law].power())
            }
            _ => times
                .iter()
                .map(|&t| decay_law(t, a0, lambda, mu, kappa))
                .collect(),
        }
    }

    /// Starting parameters from straight-line fits of ln A, A and 1/A
    /// against t, each rate of a combined law starting at half its own
    /// law's value (and never below a small positive one).
    fn initial(self, t: &[f64], a: &[f64]) -> Vec<f64> {
        let ln: Vec<f64> = a.iter().map(|v| v.max(f64::MIN_POSITIVE).ln()).collect();
        let (c_ln, s_ln) = straight_line(t, &ln);
        let (c_lin, s_lin) = straight_line(t, a);
        // The drag law alone: A^{1−p} rises along a line of slope (p−1)κ.
        let p = self.power();
        let inv: Vec<f64> = a
            .iter()
            .map(|v| v.max(f64::MIN_POSITIVE).powf(1.0 - p))
            .collect();
        let (c_inv, s_inv) = straight_line(t, &inv);
        let single = [-s_ln, -s_lin, s_inv / (p - 1.0)];
        let used = self.rates();
        let combined = used.iter().filter(|u| **u).count() > 1;
        let a0 = match used {
            [false, true, false] => c_lin,
            [false, false, true] => c_inv.powf(1.0 / (1.0 - p)),
            _ => c_ln.exp(),
        };
        let mut p = vec![a0];
        for (k, u) in used.into_iter().enumerate() {
            if u {
                let v = single[k].abs().max(1e-12);
                p.push(if combined { 0.5 * v } else { single[k] });
            }
        }
        p
    }
}

/// The names of the rates λ, μ, κ.
const RATE_NAMES: [&str; 3] = [
    "decay_rate_per_s",
    "amplitude_fall_rad_per_s",
    "quadratic_decay_per_rad_s",
];

/// `(1 - e^{-λt})/λ`, which is `t` as λ -> 0, without cancellation.
fn decay_integral(lambda: f64, t: f64) -> f64 {
    let x = -lambda * t;
    if x.abs() < 1e-8 {
        t * (1.0 - 0.5 * lambda * t)
    } else {
        -x.exp_m1() / lambda
    }
}

/// The solution of `dA/dt = -(μ + λA + κA²)`, `A(0) = a0` (see the module
/// notes for the forms and their stability).
pub fn decay_law(t: f64, a0: f64, lambda: f64, mu: f64, kappa: f64) -> f64 {
    if kappa == 0.0 {
        // Viscous and dry: A0 e^{-λt} - μ (1 - e^{-λt})/λ.
        return a0 * (-lambda * t).exp() - mu * decay_integral(lambda, t);
    }
    let d = lambda * lambda - 4.0 * kappa * mu;
    if d >= 0.0 {
        let root = d.sqrt();
        let equilibrium = if mu == 0.0 {
            0.0
        } else {
            -2.0 * mu / (lambda + root)
        };
        let b0 = a0 - equilibrium;
        let b = b0 * (-root * t).exp() / (1.0 + kappa * b0 * decay_integral(root, t));
        equilibrium + b
    } else {
        let s = (-d).sqrt();
        let phase = ((2.0 * kappa * a0 + lambda) / s).atan() - 0.5 * s * t;
        (s * phase.tan() - lambda) / (2.0 * kappa)
    }
}

/// The amplitudes at `times` of `dA/dt = −(μ + λA + κA^p)`, `A(0) = a0`,
/// `rates = [λ, μ, κ]`, for a drag law of power `p > 1`.
///
/// Method: without dry friction, a Bernoulli equation: `u = A^{1−p}`
/// obeys `u' = (p−1)(λu + κ)`, so `u = u0 e^x + (p−1)κt · expm1(x)/x`,
/// `x = (p−1)λt` (the ratio by its series below 1e-8), exact. With it, the
/// classical fourth-order Runge-Kutta method through the times in order
/// from 0 (either way), in steps of at most 1/2000 of the largest `|t|`:
/// a grid set by the times alone, so that the amplitudes are a smooth
/// function of the rates (the fit's differences need that; a step chosen
/// by the rates would jump). Past `A = 0` (a swing that friction stops)
/// the equation goes on with `κ|A|^p`, as the closed forms do with `κA²`.
/// Accuracy: at `p = 2` against the closed forms of [`decay_law`], which
/// solve the same equation, within 1e-9 relative over decays of up to
/// e^{-10} (`tests::the_power_law_matches_the_closed_forms`).
pub fn power_decay_law(times: &[f64], a0: f64, rates: [f64; 3], p: f64) -> Vec<f64> {
    let [lambda, mu, kappa] = rates;
    if mu == 0.0 {
        return times
            .iter()
            .map(|&t| {
                let x = (p - 1.0) * lambda * t;
                let ratio = if x.abs() < 1e-8 {
                    1.0 + 0.5 * x
                } else {
                    x.exp_m1() / x
                };
                let u = a0.abs().powf(1.0 - p) * x.exp() + (p - 1.0) * kappa * t * ratio;
                a0.signum() * u.powf(1.0 / (1.0 - p))
            })
            .collect();
    }
    let rhs = |a: f64| -(mu + lambda * a + kappa * a.abs().powf(p));
    let longest = times.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
    let h_max = longest / 2000.0;
    let mut order: Vec<usize> = (0..times.len()).collect();
    order.sort_by(|&i, &j| times[i].total_cmp(&times[j]));
    let mut out = vec![a0; times.len()];
    // Forward from 0 through the times after it, back through those before.
    let (before, after): (Vec<usize>, Vec<usize>) = order.iter().partition(|&&i| times[i] < 0.0);
    for run in [after, before.into_iter().rev().collect()] {
        let (mut t, mut a) = (0.0, a0);
        for i in run {
            let span = times[i] - t;
            let steps = if h_max > 0.0 {
                (span.abs() / h_max).ceil().max(1.0)
            } else {
                1.0
            };
            let h = span / steps;
            for _ in 0..steps as usize {
                let k1 = rhs(a);
                let k2 = rhs(a + 0.5 * h * k1);
                let k3 = rhs(a + 0.5 * h * k2);
                let k4 = rhs(a + h * k3);
                a += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            }
            t = times[i];
            out[i] = a;
        }
    }
    out
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

/// Fits `model` to amplitudes `amplitude` (rad) at times `time` (s), every
/// rate at least 0 (see the module notes); with `omega` (rad/s) the
/// physical parameters are added.
pub fn fit_decay(
    model: DecayModel,
    time: &[f64],
    amplitude: &[f64],
    omega: Option<f64>,
) -> Result<DecayFit, FitError> {
    let names = model.rate_names();
    let k = names.len();
    let start = model.initial(time, amplitude);
    // From all rates free; if that fit fails (a combined law whose rate
    // wanders negative can overflow), from each rate held at 0 in turn,
    // keeping the best: the bounded optimum is then on that face.
    let all_free = vec![true; k];
    let (fit, full, free, bound_errors) = match active_set(model, time, amplitude, all_free, &start)
    {
        Ok(found) => found,
        // Too few points stays an error; only a combined law falls back.
        Err(first @ FitError::TooFewPoints { .. }) => return Err(first),
        Err(first) if k < 3 => return Err(first),
        Err(first) => (1..k)
            .filter_map(|j| {
                let mut free = vec![true; k];
                free[j] = false;
                let mut from = start.clone();
                from[j] = 0.0;
                active_set(model, time, amplitude, free, &from).ok()
            })
            .min_by(|a, b| rss(&a.0).total_cmp(&rss(&b.0)))
            .ok_or(first)?,
    };
    // Standard errors in the full order; a rate at its bound keeps the one
    // it had when it was fixed.
    let mut errors = bound_errors;
    for (&j, &e) in (0..k)
        .filter(|&j| free[j])
        .collect::<Vec<_>>()
        .iter()
        .zip(&fit.standard_errors)
    {
        errors[j] = e;
    }
    // The covariance in the full order: a rate at its bound keeps the
    // variance it had when it was fixed, uncorrelated (what the data can
    // say of it there: a bound on the loss it could add).
    let index: Vec<usize> = (0..k).filter(|&j| free[j]).collect();
    let mut covariance = vec![vec![0.0; k]; k];
    for (a, &r) in index.iter().enumerate() {
        for (b, &c) in index.iter().enumerate() {
            covariance[r][c] = fit.covariance[a][b];
        }
    }
    for j in (0..k).filter(|&j| !free[j]) {
        covariance[j][j] = errors[j] * errors[j];
    }
    let fit = Fit {
        parameters: full.clone(),
        standard_errors: errors,
        covariance,
        ..fit
    };
    let mut parameters: Vec<Estimate> = names
        .iter()
        .zip(fit.parameters.iter().zip(&fit.standard_errors))
        .map(|(&name, (&value, &standard_error))| Estimate {
            name,
            value,
            standard_error,
        })
        .collect();
    let physical = model.physical_names();
    let physical_name = |rate: &str| match rate {
        "decay_rate_per_s" => physical[0],
        "amplitude_fall_rad_per_s" => physical[1],
        _ => physical[2],
    };
    let at_bound: Vec<&'static str> = (1..k)
        .filter(|&j| !free[j])
        .map(|j| {
            if omega.is_some() {
                physical_name(names[j])
            } else {
                names[j]
            }
        })
        .collect();
    let (mut q_viscous, mut q_viscous_lower_bound) = (None, None);
    if let Some(w) = omega {
        let physical: Vec<Estimate> = parameters
            .iter()
            .filter_map(|e| {
                // κ = k ω^{p−1} ⟨|sin|^{p+1}⟩ (4bω/(3π) for the quadratic).
                let drag = model.drag_law();
                let factor = match e.name {
                    "decay_rate_per_s" => 1.0 / w,
                    "amplitude_fall_rad_per_s" => std::f64::consts::PI / (2.0 * w),
                    "amplitude0_rad" => return None,
                    _ => 1.0 / (w.powf(drag.power() - 1.0) * drag.sine_mean()),
                };
                Some(Estimate {
                    name: physical_name(e.name),
                    value: e.value * factor,
                    standard_error: e.standard_error * factor,
                })
            })
            .collect();
        if let Some(z) = physical.iter().find(|e| e.name == "zeta") {
            if z.value > 2.0 * z.standard_error {
                q_viscous = Some(0.5 / z.value);
            } else {
                let upper = z.value.max(0.0) + 2.0 * z.standard_error;
                q_viscous_lower_bound = (upper > 0.0).then(|| 0.5 / upper);
            }
        }
        parameters.extend(physical);
    }
    // Q over the record: the loss per radian between the record's ends.
    let record_q = match (omega, time.first(), time.last()) {
        (Some(w), Some(&t0), Some(&t1)) if t1 > t0 => {
            let loss = |p: &[f64]| {
                loss_per_radian(
                    w * (t1 - t0),
                    model.amplitude(t0, p),
                    model.amplitude(t1, p),
                )
            };
            loss(&fit.parameters).and_then(|value| {
                Some(RecordQ {
                    loss: value,
                    loss_standard_error: propagate(&fit, loss)?,
                })
            })
        }
        _ => None,
    };
    Ok(DecayFit {
        model,
        fit,
        parameters,
        record_q,
        q_viscous,
        q_viscous_lower_bound,
        at_bound,
    })
}

/// The residual sum of squares of a fit.
fn rss(fit: &Fit) -> f64 {
    fit.residuals.iter().map(|r| r * r).sum()
}

/// What the active set returns: the fit of the free parameters, all the
/// parameters (rates at their bound 0), which are free, and the standard
/// error each fixed rate had when it was fixed.
type Active = (Fit, Vec<f64>, Vec<bool>, Vec<f64>);

/// The least squares of `model` with the rates not `free` held at 0, from
/// `start`; a free rate that comes out negative is fixed at 0 (the most
/// negative first) and the rest fitted again.
fn active_set(
    model: DecayModel,
    time: &[f64],
    amplitude: &[f64],
    mut free: Vec<bool>,
    start: &[f64],
) -> Result<Active, FitError> {
    let k = free.len();
    // The standard error each rate had when it was fixed at its bound: what
    // the data can say about it there (a bound on Q, say).
    let mut bound_errors = vec![0.0; k];
    let mut start = start.to_vec();
    loop {
        let index: Vec<usize> = (0..k).filter(|&j| free[j]).collect();
        let expand = |q: &[f64]| {
            let mut p = vec![0.0; k];
            for (&j, &v) in index.iter().zip(q) {
                p[j] = v;
            }
            p
        };
        let curve = Amplitudes::new(model, time, &expand);
        let initial: Vec<f64> = index.iter().map(|&j| start[j]).collect();
        let fit = fit_curve(&curve, time, amplitude, None, &initial)?;
        let p = expand(&fit.parameters);
        // The most negative rate (index 0 is the amplitude) goes to its bound.
        let worst = (1..k)
            .filter(|&j| free[j] && p[j] < 0.0)
            .min_by(|&a, &b| p[a].total_cmp(&p[b]));
        match worst {
            Some(j) => {
                let position = index.iter().position(|&i| i == j).unwrap_or(0);
                bound_errors[j] = fit.standard_errors.get(position).copied().unwrap_or(0.0);
                free[j] = false;
                start = p.iter().map(|v| v.max(0.0)).collect();
                start[j] = 0.0;
            }
            None => return Ok((fit, p, free, bound_errors)),
        }
    }
}

/// A law's amplitudes as the fit evaluates them: the whole record at
/// once for each parameter set (one integration, where the law has no
/// closed form), kept for the points that follow.
struct Amplitudes<'a, E> {
    model: DecayModel,
    times: &'a [f64],
    expand: &'a E,
    cache: std::cell::RefCell<(Vec<f64>, Vec<f64>)>,
    next: std::cell::Cell<usize>,
}

impl<'a, E: Fn(&[f64]) -> Vec<f64>> Amplitudes<'a, E> {
    fn new(model: DecayModel, times: &'a [f64], expand: &'a E) -> Self {
        Self {
            model,
            times,
            expand,
            cache: Default::default(),
            next: Default::default(),
        }
    }
}

impl<E: Fn(&[f64]) -> Vec<f64>> super::Curve for Amplitudes<'_, E> {
    fn value(&self, t: f64, q: &[f64]) -> f64 {
        let p = (self.expand)(q);
        if !matches!(self.model, DecayModel::Drag { .. }) {
            return self.model.amplitude(t, &p);
        }
        let mut cache = self.cache.borrow_mut();
        if cache.0 != q {
            *cache = (q.to_vec(), self.model.amplitudes(self.times, &p));
        }
        // The fit asks for the points in order: the one after the last
        // asked first.
        let next = self.next.get();
        let found = if self.times.get(next) == Some(&t) {
            Some(next)
        } else {
            self.times.iter().position(|&x| x == t)
        };
        match found {
            Some(i) => {
                self.next.set(i + 1);
                cache.1[i]
            }
            None => self.model.amplitude(t, &p),
        }
    }
}

/// Akaike weights of `fits` (Burnham & Anderson, *Model selection and
/// multimodel inference*, 2nd ed., §2.9): `exp(-Δ_i/2) / Σ exp(-Δ_j/2)`,
/// `Δ_i = AIC_i - min AIC`, over the fits with no rate at its bound (those
/// are simpler laws counted already, weight 0).
pub fn akaike_weights(fits: &[DecayFit]) -> Vec<f64> {
    let best = fits
        .iter()
        .filter(|f| f.at_bound.is_empty())
        .map(|f| f.fit.aic)
        .fold(f64::INFINITY, f64::min);
    let raw: Vec<f64> = fits
        .iter()
        .map(|f| {
            if f.at_bound.is_empty() {
                (-0.5 * (f.fit.aic - best)).exp()
            } else {
                0.0
            }
        })
        .collect();
    let total: f64 = raw.iter().sum();
    raw.iter()
        .map(|w| if total > 0.0 { w / total } else { 0.0 })
        .collect()
}

/// The model the data prefer: the lowest BIC among the fits with no rate
/// at its bound.
pub fn preferred(fits: &[DecayFit]) -> Option<DecayModel> {
    fits.iter()
        .filter(|f| f.at_bound.is_empty())
        .min_by(|a, b| a.fit.bic.total_cmp(&b.fit.bic))
        .map(|f| f.model)
}

/// The amplitude lost per half swing at `amplitude` according to a fit:
/// `-dA/dt · T/2`, for the energy budget.
pub fn half_swing_loss(fit: &DecayFit, amplitude: f64, half_period: f64) -> f64 {
    let [_, lambda, mu, kappa] = fit.model.full_rates(&fit.fit.parameters);
    (mu + lambda * amplitude + kappa * amplitude.abs().powf(fit.model.power())) * half_period
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

    /// The closed forms against a fine RK4 integration of
    /// `dA/dt = -(μ + λA + κA²)` (an independent route), in every regime:
    /// D > 0, D < 0, D = 0, tiny κ and tiny μ.
    #[test]
    fn the_general_law_solves_its_equation() {
        let cases = [
            (0.05, 3e-4, 5e-6, 0.01),  // D > 0
            (0.05, 1e-5, 5e-6, 0.01),  // D < 0
            (0.05, 2e-4, 1e-6, 0.01),  // D = 0 exactly
            (0.05, 3e-4, 5e-6, 1e-13), // κ tiny
            (0.05, 3e-4, 1e-15, 0.01), // μ tiny
            (0.05, 0.0, 5e-6, 0.01),   // no viscous part
            (0.3, 6e-3, 0.0, 0.03),    // a pendulum in air
        ];
        for (a0, lambda, mu, kappa) in cases {
            let rhs = |a: f64| -(mu + lambda * a + kappa * a * a);
            let (mut a, h) = (a0, 0.01);
            for step in 1..=200_000 {
                let k1 = rhs(a);
                let k2 = rhs(a + 0.5 * h * k1);
                let k3 = rhs(a + 0.5 * h * k2);
                let k4 = rhs(a + h * k3);
                a += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
                if step % 20_000 == 0 {
                    let t = step as f64 * h;
                    let law = decay_law(t, a0, lambda, mu, kappa);
                    assert!(
                        (law - a).abs() < 1e-12 * a0,
                        "({a0}, {lambda}, {mu}, {kappa}) at {t}: {law} vs {a}"
                    );
                }
            }
        }
    }

    /// The general power law at `p = 2` against the closed forms (by
    /// Runge-Kutta with dry friction, by its Bernoulli form without), in
    /// the regimes of [`the_general_law_solves_its_equation`], over
    /// times before 0 too; and at `p = 3/2` without friction, the
    /// Bernoulli form against a fine independent Runge-Kutta run.
    #[test]
    fn the_power_law_matches_the_closed_forms() {
        let times: Vec<f64> = (-40..=400).map(|i| f64::from(i) * 5.0).collect();
        for (a0, lambda, mu, kappa) in [
            (0.05, 3e-4, 5e-6, 0.01),
            (0.05, 1e-5, 5e-6, 0.01),
            (0.05, 0.0, 5e-6, 0.01),
            (0.3, 6e-3, 0.0, 0.03),
            (0.3, 0.0, 0.0, 0.03),
            (0.05, 5e-3, 1e-7, 0.01),
        ] {
            let general = power_decay_law(&times, a0, [lambda, mu, kappa], 2.0);
            for (&t, &a) in times.iter().zip(&general) {
                let closed = decay_law(t, a0, lambda, mu, kappa);
                assert!(
                    (a - closed).abs() <= 1e-9 * closed.abs().max(1e-3 * a0),
                    "({a0}, {lambda}, {mu}, {kappa}) at {t}: {a} vs {closed}"
                );
            }
        }
        let (a0, lambda, kappa) = (0.2, 2e-3, 0.05);
        let law = power_decay_law(&[1000.0], a0, [lambda, 0.0, kappa], 1.5)[0];
        let (mut a, h) = (a0, 0.001);
        for _ in 0..1_000_000 {
            let f = |a: f64| -(lambda * a + kappa * a.powf(1.5));
            let (k1, k2) = (f(a), f(a + 0.5 * h * f(a)));
            let k3 = f(a + 0.5 * h * k2);
            let k4 = f(a + h * k3);
            a += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        assert!((law / a - 1.0).abs() < 1e-11, "{law} vs {a}");
    }

    /// Every drag law's laws are named, found by their names, and the
    /// quadratic one's are the seven in closed form.
    #[test]
    fn every_drag_law_has_its_laws() {
        let every = DecayModel::every();
        assert_eq!(every.len(), 7 + 4 * (DRAG_LAWS.len() - 1));
        for model in &every {
            assert_eq!(DecayModel::from_name(model.name()), Some(*model));
        }
        assert_eq!(
            DecayModel::from_name("viscous+three_halves").map(DecayModel::rate_names),
            Some(vec![
                "amplitude0_rad",
                "decay_rate_per_s",
                "three_halves_decay_per_sqrt_rad_s"
            ])
        );
        assert!(DecayModel::searched().len() < every.len());
    }

    #[test]
    fn recovers_noiseless_parameters() {
        let t: Vec<f64> = (0..50).map(|i| f64::from(i) * 20.0).collect();
        for (model, truth) in [
            (DecayModel::Viscous, vec![0.05, 1e-3]),
            (DecayModel::Coulomb, vec![0.05, 2e-5]),
            (DecayModel::Quadratic, vec![0.05, 0.02]),
            (DecayModel::ViscousCoulomb, vec![0.05, 5e-4, 1e-5]),
            (DecayModel::ViscousQuadratic, vec![0.05, 5e-4, 0.01]),
            (DecayModel::Full, vec![0.05, 5e-4, 3e-6, 0.01]),
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
