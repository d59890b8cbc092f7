//! The full pendulum, nonlinear and damped, simulated over days and weeks
//! of swings:
//! `θ'' + 2ζω_n θ' + b θ'|θ'| + ω_n² (sin θ + r sign θ') = 0`
//! (viscous damping ζ as in seed section 1-4, quadratic air drag `b` per
//! radian, dry friction angle `r` as in the book's section 2-4).
//!
//! The equation is the sum of its terms ([`forces`]: gravity and each
//! damping law, each on its own; [`crate::clock`] adds escapements to
//! them). What a run reports goes to an [`Observer`] (`observer.rs`).
//!
//! The drivers wire the pieces of [`crate::integrate`]: DOP853 (or Verner
//! 9(8)) steps under the step-size controller (`adaptive.rs`), or Yoshida's
//! symplectic composition at a fixed step (`symplectic.rs`); on each
//! accepted step, a sign change of `θ'` in the direction of motion is a
//! turning point, located on the step's interpolant (`run.rs`). The drivers
//! work in scaled time `τ = ω_n t`, so a pendulum of any length takes the
//! same steps, and the error control follows the swing's size as it decays. With dry friction the sign of `θ'` is held fixed through each
//! half swing (the equation is smooth there) and the integration restarts
//! at every turning point, where the pendulum sticks if `|sin θ| <= r`.
//! `--method exact` (no damping) uses [`crate::exact`] instead, and
//! `--method averaged` (viscous damping only) a whole half swing per step
//! in closed form (`averaged.rs`, [`crate::clock::averaged`]).
//!
//! Time is never summed: a step ends at `t + h` computed from the step's
//! own start, and the last step lands on the duration exactly.

mod adaptive;
pub mod analysis;
mod averaged;
mod closed_form;
pub use crate::forces;
mod observer;
mod run;
mod symplectic;
mod work;

pub use observer::{Action, Crossing, Observer, Silent, TurningPoint};
pub use symplectic::symplectic_steps_per_period;
pub use work::{work_estimate, Limit, WorkEstimate};

use crate::damped::State;
use crate::damping::Damping;
use crate::error::{require_non_negative, require_positive, InputError, Quantity};
use crate::integrate::State2;
use crate::pendulum::{Amplitude, Pendulum};

/// The physics: a pendulum and what slows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model {
    /// Length and gravity.
    pub pendulum: Pendulum,
    /// Viscous damping.
    pub damping: Damping,
    /// The coefficient of each drag law of [`forces::DRAG_LAWS`], in the
    /// law's own units (0: not in the model); the quadratic drag `b`, per
    /// radian (the term `b θ'|θ'|`), is the first.
    pub drag: forces::DragCoefficients,
    /// The same in scaled time.
    drag_scaled: forces::DragCoefficients,
    /// Dry friction angle `r`, rad.
    pub friction_angle: f64,
}

/// The index of the quadratic drag in [`forces::DRAG_LAWS`].
pub const QUADRATIC_DRAG: usize = 0;

impl Model {
    /// A model; `quadratic_drag` and `friction_angle` must not be negative.
    pub fn new(
        pendulum: Pendulum,
        damping: Damping,
        quadratic_drag: f64,
        friction_angle: f64,
    ) -> Result<Self, InputError> {
        let mut drag = [0.0; forces::DRAG_LAWS.len()];
        drag[QUADRATIC_DRAG] = require_non_negative(Quantity::QuadraticDrag, quadratic_drag)?;
        Ok(Self {
            pendulum,
            damping,
            drag,
            drag_scaled: drag,
            friction_angle: crate::error::require_friction_angle(friction_angle)?,
        })
    }

    /// The model with the drag law `law` (an index of
    /// [`forces::DRAG_LAWS`]) at coefficient `k` in its own units; the
    /// refusal of `k` as a reason.
    pub fn with_drag(mut self, law: usize, k: f64) -> Result<Self, String> {
        let k = forces::check_drag(k)?;
        let omega = self.pendulum.natural_angular_frequency();
        self.drag[law] = k;
        self.drag_scaled[law] = forces::DRAG_LAWS[law].scaled(k, omega);
        Ok(self)
    }

    /// The quadratic drag `b`, per radian.
    pub fn quadratic_drag(&self) -> f64 {
        self.drag[QUADRATIC_DRAG]
    }

    /// Whether any drag law acts.
    pub fn has_drag(&self) -> bool {
        self.drag.iter().any(|&k| k != 0.0)
    }

    /// The drag laws that act, with their scaled coefficients.
    pub(crate) fn drag_laws(
        &self,
    ) -> impl Iterator<Item = (&'static dyn forces::DragLaw, f64)> + '_ {
        forces::DRAG_LAWS
            .iter()
            .zip(self.drag_scaled)
            .filter(|(_, k)| *k != 0.0)
            .map(|(law, k)| (*law, k))
    }

    /// Whether nothing slows the pendulum.
    pub fn is_undamped(&self) -> bool {
        self.damping.zeta() == 0.0 && !self.has_drag() && self.friction_angle == 0.0
    }

    /// The right-hand side in scaled time `τ = ω_n t`, `d²θ/dτ²`, for the
    /// state `y = [θ, dθ/dτ]` with viscous rate `c1 = 2ζ` and the friction
    /// sign `direction` (±1).
    #[inline(always)]
    fn acceleration(&self, c1: f64, y: State2, direction: f64) -> f64 {
        self.velocity_terms(c1, y[1]) + self.position_terms(y[0], direction)
    }

    /// The terms of velocity: [`forces::Viscous`] (rate `c1 = 2ζ`) and
    /// each drag law that acts.
    #[inline(always)]
    fn velocity_terms(&self, c1: f64, v: f64) -> f64 {
        use forces::Term;
        let mut a = forces::Viscous(c1).acceleration([0.0, v], 0.0);
        for (law, k) in forces::DRAG_LAWS.iter().zip(&self.drag_scaled) {
            if *k != 0.0 {
                a += law.acceleration(*k, v);
            }
        }
        a
    }

    /// The terms of position: [`forces::Gravity`] and
    /// [`forces::DryFriction`] in `direction`.
    #[inline(always)]
    fn position_terms(&self, theta: f64, direction: f64) -> f64 {
        use forces::Term;
        let y = [theta, 0.0];
        forces::Gravity.acceleration(y, direction)
            + forces::DryFriction(self.friction_angle).acceleration(y, direction)
    }
}

/// How to integrate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Dormand-Prince 8(5,3) with 7th-order dense output.
    Dop853,
    /// The closed form (undamped only).
    Exact,
    /// Yoshida's 6th-order symplectic composition with exact damping flows,
    /// at a fixed step set by the tolerance.
    Symplectic,
    /// Verner's 9(8) pair, adaptive: for tight tolerances.
    Vern9,
    /// One step per half swing by the closed-form map (viscous damping
    /// only): for weeks to years of turning points.
    Averaged,
}

impl Method {
    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Dop853 => "dop853",
            Method::Exact => "exact",
            Method::Symplectic => "symplectic",
            Method::Vern9 => "vern9",
            Method::Averaged => "averaged",
        }
    }
}

/// What a run is asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Simulated time, s.
    pub duration: f64,
    /// Relative and absolute tolerance of each step.
    pub tolerance: f64,
    /// The method.
    pub method: Method,
    /// Report the state every this many seconds, if any.
    pub sample_interval: Option<f64>,
}

/// Why a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stopped {
    /// The swing decayed below [`AMPLITUDE_FLOOR`], where double precision
    /// no longer resolves it.
    AmplitudeBelowTolerance,
    /// The pendulum passed over the top: impossible from rest below 180°
    /// with damping that only takes energy, so a numerical failure (the
    /// release was too close to 180° for the method and tolerance).
    OverTheTop,
    /// The step size fell to nothing (an overflow the steps could not avoid).
    StepTooSmall,
    /// It reached the duration.
    Duration,
    /// Dry friction held it at a turning point.
    Friction,
    /// The observer asked it to stop (Ctrl-C, a write error).
    Interrupted,
    /// An event the observer made terminal.
    Event,
}

impl Stopped {
    /// The name used in JSON: `"duration"`, `"friction"`, `"interrupted"`,
    /// `"event"`, `"amplitude_below_tolerance"`, `"over_the_top"`,
    /// `"step_too_small"`.
    pub fn name(self) -> &'static str {
        match self {
            Stopped::AmplitudeBelowTolerance => "amplitude_below_tolerance",
            Stopped::OverTheTop => "over_the_top",
            Stopped::StepTooSmall => "step_too_small",
            Stopped::Duration => "duration",
            Stopped::Friction => "friction",
            Stopped::Interrupted => "interrupted",
            Stopped::Event => "event",
        }
    }
}

/// The result of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// The method used.
    pub method: Method,
    /// Turning points after the release.
    pub swings: u64,
    /// Upward zero crossings located (0 unless the observer wanted them).
    pub zero_crossings: u64,
    /// Time reached, s.
    pub final_time: f64,
    /// State at that time.
    pub final_state: State,
    /// The amplitude the final state's energy implies (see [`energy_amplitude`]), rad.
    pub final_amplitude: f64,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected_steps: u64,
    /// Evaluations of the right-hand side.
    pub function_evaluations: u64,
    /// Why it ended.
    pub stopped: Stopped,
    /// The largest change of energy at a turning point that the model does
    /// not explain, beyond the method's own error, if any: a gain (with
    /// damping, which only takes energy) or any change (without). A sign
    /// that the tolerance is too loose for the motion, or the release too
    /// near 180°.
    pub energy_gain: Option<EnergyGain>,
}

/// A change in the energy between turning points that the model does not
/// explain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EnergyGain {
    /// Time of the turning point, s.
    pub time: f64,
    /// The larger of the relative changes of `E = sin²(θ/2)` and of the
    /// period `T(θ)` it implies, against the lowest turning point before it
    /// (damped) or the release (undamped).
    pub relative: f64,
}

/// The smallest swing the drivers follow, rad: below it, `tolerance ×
/// swing` nears the bottom of double precision's normal range, and the run
/// stops with [`Stopped::AmplitudeBelowTolerance`].
pub const AMPLITUDE_FLOOR: f64 = 1e-280;

/// The smallest swing the averaged method follows, rad: its map works on
/// the energy `2 sin²(A/2) ≈ A²/2`, which leaves double precision's normal
/// range (2.2e-308) below an amplitude of about 2e-154, where the loss per
/// half swing no longer changes it.
pub const AVERAGED_AMPLITUDE_FLOOR: f64 = 1e-150;

/// The smallest Q the averaged method takes: its map averages the loss
/// over a half swing, right to third order in 1/Q; at Q = 10 a half swing
/// loses a quarter of its energy and the third-order term is 1e-3.
pub const AVERAGED_MIN_Q: f64 = 10.0;

/// The smallest swing `method` follows before it stops with
/// [`Stopped::AmplitudeBelowTolerance`].
pub fn amplitude_floor(method: Method) -> f64 {
    match method {
        Method::Averaged => AVERAGED_AMPLITUDE_FLOOR,
        _ => AMPLITUDE_FLOOR,
    }
}

/// The relative change of energy (or of the period it implies) at a
/// turning point that a method's own error explains at `tolerance`, beyond
/// which [`Outcome::energy_gain`] is set. Measured on undamped runs of 1000
/// periods at 0.05 to 3 rad and tolerances 1e-6 to 1e-14 (the largest
/// change against the release): DOP853 and Verner up to 1.4e4 tol (at 3
/// rad; the drift grows with the run), the symplectic method up to 170 tol
/// (bounded); damped runs (Q = 300, 10^6) at most 1.1e3 tol. The allowance
/// is 1e5 tol: a release at 179.999999° that the methods cannot follow
/// changes the period by tens of percent.
pub fn energy_gain_allowance(method: Method, tolerance: f64) -> f64 {
    match method {
        Method::Exact | Method::Averaged => 1e-12,
        Method::Dop853 | Method::Vern9 | Method::Symplectic => 1e5 * tolerance.max(1e-14),
    }
}

/// The rates of the scaled motion (per unit of `τ = ω_n t`) that set the
/// step: the oscillation (1), the viscous damping `2ζ`, and the fastest
/// drag law's linearised rate at the fastest speed the swing can reach
/// ([`forces::DragLaw::rate`]: for the quadratic drag `2b |dθ/dτ|` at the
/// free swing's `2 sin(A0/2)`, or under strong drag twice the drag-limited
/// creep speed `1/sqrt(b)`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rates {
    /// The oscillation: 1.
    pub oscillation: f64,
    /// `2ζ`.
    pub viscous: f64,
    /// The fastest drag law's rate.
    pub drag: f64,
    /// Which law that is (an index of [`forces::DRAG_LAWS`]).
    pub drag_law: usize,
}

impl Rates {
    /// The rates of `model` released at `amplitude`.
    pub fn new(model: &Model, amplitude: Amplitude) -> Self {
        let free_speed = 2.0 * (0.5 * amplitude.radians()).sin();
        let (drag_law, drag) = forces::DRAG_LAWS
            .iter()
            .zip(model.drag_scaled)
            .map(|(law, k)| law.rate(k, free_speed))
            .enumerate()
            .fold((QUADRATIC_DRAG, 0.0), |best, (i, r)| {
                if r > best.1 {
                    (i, r)
                } else {
                    best
                }
            });
        Self {
            oscillation: 1.0,
            viscous: 2.0 * model.damping.zeta(),
            drag,
            drag_law,
        }
    }

    /// The fastest of the three.
    pub fn fastest(&self) -> f64 {
        self.oscillation.max(self.viscous).max(self.drag)
    }
}

/// Why a run cannot start.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SimulationError {
    /// An input out of range.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The closed form knows no damping.
    #[error("the exact method has no damping: drop the damping options or choose dop853")]
    ExactWithDamping,
    /// The averaged method's map has viscous damping only.
    #[error("the averaged method takes viscous damping only (no drag or dry friction), and gives turning points, not samples: choose symplectic or dop853")]
    AveragedUnsupported,
    /// The symplectic method's damping flow is exact for one drag law.
    #[error("the symplectic method takes one drag law at a time (its damping flow is exact for one): choose dop853")]
    SymplecticOneDragLaw,
    /// The averaged method's map holds for weak damping only.
    #[error("the averaged method holds for Q of at least {minimum} (a half swing must lose a small part of its energy), got Q = {q:.4}: choose symplectic or dop853")]
    AveragedNeedsWeakDamping {
        /// The Q given.
        q: f64,
        /// The smallest Q taken.
        minimum: f64,
    },
}

/// The amplitude of the undamped swing with the energy of `state`:
/// `sin²(A/2) = sin²(θ/2) + (θ'/(2ω_n))²`, a sum of positive terms.
pub fn energy_amplitude(pendulum: &Pendulum, state: &State) -> f64 {
    let s = (0.5 * state.angle).sin();
    let v = state.angular_velocity / (2.0 * pendulum.natural_angular_frequency());
    2.0 * (s * s + v * v).sqrt().min(1.0).asin()
}

/// The rate a clock would keep if every beat took `half_period` seconds,
/// against the small-angle beat `T0/2` of `pendulum`, in s/day:
/// `86400 ((T0/2) / half_period - 1)`; positive when the clock gains, as
/// every `rate_s_per_day` of the tool: a swing slower than the small-angle
/// one gives a negative rate (the clock loses its circular error). The
/// column `rate_s_per_day` of a swings file.
pub fn half_swing_rate(pendulum: &Pendulum, half_period: f64) -> f64 {
    crate::period::SECONDS_PER_DAY * (0.5 * pendulum.small_angle_period() / half_period - 1.0)
}

/// Steps between calls to [`Observer::progress`].
const PROGRESS_EVERY: u64 = 4096;

/// Checks that `options.method` can run `model`: the closed form knows
/// no damping; the averaged map takes weak viscous damping only, and gives
/// neither samples nor (for an observer that wants them) zero crossings.
pub fn check_method(
    model: &Model,
    options: &Options,
    zero_crossings: bool,
) -> Result<(), SimulationError> {
    match options.method {
        Method::Exact if !model.is_undamped() => Err(SimulationError::ExactWithDamping),
        Method::Symplectic if model.drag_laws().count() > 1 => {
            Err(SimulationError::SymplecticOneDragLaw)
        }
        Method::Averaged => {
            if model.has_drag()
                || model.friction_angle > 0.0
                || options.sample_interval.is_some()
                || zero_crossings
            {
                return Err(SimulationError::AveragedUnsupported);
            }
            let zeta = model.damping.zeta();
            if zeta > 0.5 / AVERAGED_MIN_Q {
                return Err(SimulationError::AveragedNeedsWeakDamping {
                    q: 0.5 / zeta,
                    minimum: AVERAGED_MIN_Q,
                });
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Runs `model` released from rest at `amplitude` for `options.duration`.
pub fn simulate(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Result<Outcome, SimulationError> {
    require_non_negative(Quantity::Duration, options.duration)?;
    require_positive(Quantity::Tolerance, options.tolerance)?;
    if let Some(h) = options.sample_interval {
        require_positive(Quantity::SampleInterval, h)?;
    }
    check_method(model, options, observer.wants_zero_crossings())?;
    Ok(match options.method {
        Method::Exact => closed_form::run_exact(model, amplitude, options, observer),
        Method::Dop853 => adaptive::run_dop853(model, amplitude, options, observer),
        Method::Symplectic => symplectic::run_symplectic(model, amplitude, options, observer),
        Method::Vern9 => adaptive::run_vern9(model, amplitude, options, observer),
        Method::Averaged => averaged::run_averaged(model, amplitude, options, observer),
    })
}
