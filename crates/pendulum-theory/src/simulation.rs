//! The full pendulum, nonlinear and damped, simulated over days and weeks
//! of swings:
//! `θ'' + 2ζω_n θ' + b θ'|θ'| + ω_n² (sin θ + r sign θ') = 0`
//! (viscous damping ζ as in seed section 1-4, quadratic air drag `b` per
//! radian, dry friction angle `r` as in the book's section 2-4).
//!
//! The driver wires the pieces of [`crate::integrate`]: DOP853 steps under
//! the step-size controller; on each accepted step, a sign change of `θ'`
//! in the direction of motion is a turning point, located on the dense
//! output. With dry friction the sign of `θ'` is held fixed through each
//! half swing (the equation is smooth there) and the integration restarts
//! at every turning point, where the pendulum sticks if `|sin θ| <= r`.
//! `--method exact` (no damping) uses [`crate::exact`] instead.
//!
//! Time is never summed: a step ends at `t + h` computed from the step's
//! own start, and the last step lands on the duration exactly.

use crate::damped::State;
use crate::damping::Damping;
use crate::error::{require_non_negative, require_positive, InputError, Quantity};
use crate::exact::ExactSwing;
use crate::integrate::control::{step_factor, Tolerance};
use crate::integrate::dop853::{attempt, dense_output, initial_step};
use crate::integrate::events::{crossed, locate_root, Direction};
use crate::integrate::symplectic::{self, damping_intervals, Hermite};
use crate::integrate::vern9;
use crate::integrate::State2;
use crate::pendulum::{Amplitude, Pendulum};
use std::cell::Cell;

/// The physics: a pendulum and what slows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model {
    /// Length and gravity.
    pub pendulum: Pendulum,
    /// Viscous damping.
    pub damping: Damping,
    /// Quadratic drag coefficient `b`, per radian (the term `b θ'|θ'|`).
    pub quadratic_drag: f64,
    /// Dry friction angle `r`, rad.
    pub friction_angle: f64,
}

impl Model {
    /// A model; `quadratic_drag` and `friction_angle` must not be negative.
    pub fn new(
        pendulum: Pendulum,
        damping: Damping,
        quadratic_drag: f64,
        friction_angle: f64,
    ) -> Result<Self, InputError> {
        Ok(Self {
            pendulum,
            damping,
            quadratic_drag: require_non_negative(Quantity::QuadraticDrag, quadratic_drag)?,
            friction_angle: require_non_negative(Quantity::FrictionAngle, friction_angle)?,
        })
    }

    /// Whether nothing slows the pendulum.
    pub fn is_undamped(&self) -> bool {
        self.damping.zeta() == 0.0 && self.quadratic_drag == 0.0 && self.friction_angle == 0.0
    }

    /// The right-hand side with the friction sign `direction` (±1).
    #[inline(always)]
    fn acceleration(&self, w2: f64, c1: f64, y: State2, direction: f64) -> f64 {
        let v = y[1];
        -c1 * v
            - self.quadratic_drag * v * v.abs()
            - w2 * (y[0].sin() + self.friction_angle * direction)
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
}

impl Method {
    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::Dop853 => "dop853",
            Method::Exact => "exact",
            Method::Symplectic => "symplectic",
            Method::Vern9 => "vern9",
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

/// A turning point of the swing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurningPoint {
    /// 0 for the release, then one per half swing.
    pub index: u64,
    /// Time, s.
    pub time: f64,
    /// Signed angle, rad.
    pub angle: f64,
}

/// Why a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stopped {
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
    /// The name used in JSON: `"duration"`, `"friction"`, `"interrupted"`.
    pub fn name(self) -> &'static str {
        match self {
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
}

/// What an observer wants done after an event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Carry on.
    Continue,
    /// End the run at the event (a terminal event).
    Stop,
    /// Carry on from this state instead, at the event's time: the hook an
    /// escapement uses to give its impulse. The integrator restarts there.
    Restart(State),
}

/// An upward zero crossing: θ passing 0 from negative to positive, where an
/// escapement usually gives its impulse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// 1 for the first crossing, and so on.
    pub index: u64,
    /// Time, s.
    pub time: f64,
    /// θ' there, rad/s.
    pub angular_velocity: f64,
}

/// Receives what a run produces, as it produces it.
pub trait Observer {
    /// A turning point (the release is index 0, whose action is ignored).
    fn turning_point(&mut self, _point: &TurningPoint) -> Action {
        Action::Continue
    }
    /// Whether to locate upward zero crossings (off by default: it costs an
    /// interpolant every half period).
    fn wants_zero_crossings(&self) -> bool {
        false
    }
    /// An upward zero crossing.
    fn zero_crossing(&mut self, _crossing: &Crossing) -> Action {
        Action::Continue
    }
    /// A sample at a multiple of the sample interval; `false` stops the run.
    fn sample(&mut self, _time: f64, _state: &State) -> bool {
        true
    }
    /// Called every few thousand steps with the time reached; `false` stops the run.
    fn progress(&mut self, _time: f64) -> bool {
        true
    }
}

/// An observer that wants nothing.
pub struct Silent;
impl Observer for Silent {}

/// Why a run cannot start.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SimulationError {
    /// An input out of range.
    #[error(transparent)]
    Input(#[from] InputError),
    /// The closed form knows no damping.
    #[error("the exact method has no damping: drop the damping options or choose dop853")]
    ExactWithDamping,
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
/// `86400 (1 - (T0/2) / half_period)`; negative when it loses. This is the
/// circular error a half swing shows, the column `rate_s_per_day` of a
/// swings file.
pub fn half_swing_rate(pendulum: &Pendulum, half_period: f64) -> f64 {
    crate::period::SECONDS_PER_DAY * (1.0 - 0.5 * pendulum.small_angle_period() / half_period)
}

/// Steps between calls to [`Observer::progress`].
const PROGRESS_EVERY: u64 = 4096;

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
    match options.method {
        Method::Exact => {
            if !model.is_undamped() {
                return Err(SimulationError::ExactWithDamping);
            }
            Ok(run_exact(model, amplitude, options, observer))
        }
        Method::Dop853 => Ok(run_adaptive::<Dop853>(
            Method::Dop853,
            model,
            amplitude,
            options,
            observer,
        )),
        Method::Symplectic => Ok(run_symplectic(model, amplitude, options, observer)),
        Method::Vern9 => Ok(run_adaptive::<Vern9>(
            Method::Vern9,
            model,
            amplitude,
            options,
            observer,
        )),
    }
}

/// Samples due in `(from, to]` (and at 0 when `from` is negative).
struct Samples {
    interval: Option<f64>,
    next: u64,
}

impl Samples {
    fn due(&self, limit: f64) -> Option<f64> {
        let h = self.interval?;
        let t = self.next as f64 * h;
        (t <= limit).then_some(t)
    }
}

fn run_exact(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    let swing = ExactSwing::new(&model.pendulum, amplitude);
    let duration = options.duration;
    let quarter = 0.25 * swing.period();
    let mut samples = Samples {
        interval: options.sample_interval,
        next: 0,
    };
    let (mut stopped, mut turns, mut crossings) = (Stopped::Duration, 0_u64, 0_u64);
    let wants_crossings = observer.wants_zero_crossings();
    // Events fall on quarter periods: turning points on even ones, upward
    // zero crossings (released at +A0) on those of the form 4k + 3.
    let mut q = 0_u64;
    let end = loop {
        let time = q as f64 * quarter;
        if time > duration || amplitude.radians() == 0.0 && q > 0 {
            break duration;
        }
        while let Some(t) = samples.due(time) {
            if !observer.sample(t, &swing.state_at(t)) {
                stopped = Stopped::Interrupted;
            }
            samples.next += 1;
        }
        let action = if q % 2 == 0 {
            let (_, angle) = swing.turning_point(q / 2);
            turns = q / 2;
            let point = TurningPoint {
                index: turns,
                time,
                angle,
            };
            observer.turning_point(&point)
        } else if q % 4 == 3 && wants_crossings {
            crossings += 1;
            let state = swing.state_at(time);
            let crossing = Crossing {
                index: crossings,
                time,
                angular_velocity: state.angular_velocity,
            };
            observer.zero_crossing(&crossing)
        } else {
            Action::Continue
        };
        // The closed form cannot be restarted from another state: a
        // restart request ends the run at the event, like a stop.
        if q > 0 && action != Action::Continue {
            stopped = Stopped::Event;
        }
        if q % PROGRESS_EVERY == 0 && !observer.progress(time) {
            stopped = Stopped::Interrupted;
        }
        if stopped != Stopped::Duration {
            break time.min(duration);
        }
        q += 1;
    };
    if stopped == Stopped::Duration {
        while let Some(t) = samples.due(duration) {
            observer.sample(t, &swing.state_at(t));
            samples.next += 1;
        }
    }
    Outcome {
        method: Method::Exact,
        swings: turns,
        zero_crossings: crossings,
        final_time: end,
        final_state: swing.state_at(end),
        final_amplitude: amplitude.radians(),
        steps: 0,
        rejected_steps: 0,
        function_evaluations: 0,
        stopped,
    }
}

/// What the adaptive driver needs of an embedded Runge-Kutta pair: one
/// attempted step, its end and error norm, and its continuous extension.
trait EmbeddedPair {
    /// The attempted step, with whatever its interpolant needs.
    type Step;
    /// Order of the error estimate (for the step-size controller).
    const ESTIMATE_ORDER: u32;
    /// Evaluations of `f` per attempt, beyond the first stage (reused).
    const EVALUATIONS: u64;
    /// Attempts a step of length `h` from `(t, y0)` with `f0 = f(t, y0)`.
    fn attempt(
        f: &impl Fn(f64, State2) -> State2,
        t: f64,
        y0: State2,
        f0: State2,
        h: f64,
        tolerance: &Tolerance,
    ) -> Self::Step;
    /// The step's end state and error norm.
    fn end(step: &Self::Step) -> (State2, f64);
    /// Calls `handle` with the step's interpolant over `[t, t1]` (`f1 = f(t1, y1)`);
    /// returns its result and the evaluations the interpolant cost.
    #[allow(clippy::too_many_arguments)]
    fn with_interpolant<R>(
        f: &impl Fn(f64, State2) -> State2,
        step: &Self::Step,
        t: f64,
        y0: State2,
        f0: State2,
        t1: f64,
        f1: State2,
        tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> (R, u64);
}

/// DOP853 with its 7th-order dense output (3 more evaluations).
struct Dop853;

impl EmbeddedPair for Dop853 {
    type Step = crate::integrate::dop853::Step;
    const ESTIMATE_ORDER: u32 = 7;
    const EVALUATIONS: u64 = 11;

    fn attempt(
        f: &impl Fn(f64, State2) -> State2,
        t: f64,
        y0: State2,
        f0: State2,
        h: f64,
        tolerance: &Tolerance,
    ) -> Self::Step {
        attempt(&mut |t, y| f(t, y), t, y0, f0, h, tolerance)
    }

    fn end(step: &Self::Step) -> (State2, f64) {
        (step.y1, step.error)
    }

    fn with_interpolant<R>(
        f: &impl Fn(f64, State2) -> State2,
        step: &Self::Step,
        _t: f64,
        _y0: State2,
        _f0: State2,
        _t1: f64,
        f1: State2,
        _tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> (R, u64) {
        let dense = dense_output(&mut |t, y| f(t, y), step, f1);
        (handle(&dense), 3)
    }
}

/// Verner's 9(8) pair, whose "interpolant" steps again ([`ReStep`]).
struct Vern9;

impl EmbeddedPair for Vern9 {
    type Step = vern9::Step;
    const ESTIMATE_ORDER: u32 = 8;
    const EVALUATIONS: u64 = 15;

    fn attempt(
        f: &impl Fn(f64, State2) -> State2,
        t: f64,
        y0: State2,
        f0: State2,
        h: f64,
        tolerance: &Tolerance,
    ) -> Self::Step {
        vern9::attempt(f, t, y0, f0, h, tolerance)
    }

    fn end(step: &Self::Step) -> (State2, f64) {
        (step.y1, step.error)
    }

    fn with_interpolant<R>(
        f: &impl Fn(f64, State2) -> State2,
        step: &Self::Step,
        t: f64,
        y0: State2,
        f0: State2,
        t1: f64,
        _f1: State2,
        tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> (R, u64) {
        let restep = ReStep {
            f,
            t0: t,
            y0,
            f0,
            end: (t1, step.y1),
            tolerance: *tolerance,
            evaluations: Cell::new(0),
        };
        let result = handle(&restep);
        (result, restep.evaluations.get())
    }
}

/// The adaptive driver for any embedded pair: steps under the controller,
/// time as a difference of representable values, events and samples on the
/// pair's interpolant, restarts where friction or the observer asks.
fn run_adaptive<P: EmbeddedPair>(
    method: Method,
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    let w = model.pendulum.natural_angular_frequency();
    let (w2, c1) = (w * w, 2.0 * model.damping.zeta() * w);
    let tolerance = Tolerance::both(options.tolerance);
    let rhs =
        |y: State2, direction: f64| -> State2 { [y[1], model.acceleration(w2, c1, y, direction)] };
    let mut run = match Run::start(model, method, amplitude, options, observer) {
        Ok(run) => run,
        Err(finished) => return finished,
    };
    let (mut t, mut y) = (0.0_f64, [amplitude.radians(), 0.0]);
    let mut f0 = rhs(y, run.direction);
    let mut h = {
        let direction = run.direction;
        initial_step(&mut |_, y| rhs(y, direction), t, y, f0, &tolerance)
    };
    run.evaluations += 2;
    let mut after_rejection = false;
    while run.go_on && t < run.duration {
        let last = t + h >= run.duration;
        // The step is the difference of two representable times, so that
        // t + h_step is exactly t_new and no rounding builds up in t.
        let t_new = if last { run.duration } else { t + h };
        let h_step = t_new - t;
        let direction = run.direction;
        let f = |_t: f64, y: State2| rhs(y, direction);
        let step = P::attempt(&f, t, y, f0, h_step, &tolerance);
        run.evaluations += P::EVALUATIONS;
        let (y1, error) = P::end(&step);
        if error > 1.0 {
            run.outcome.rejected_steps += 1;
            h = h_step * step_factor(error, true, P::ESTIMATE_ORDER);
            after_rejection = true;
            continue;
        }
        let f1 = f(t_new, y1);
        run.evaluations += 1;
        if run.needs_interpolant(t_new, y, y1) {
            let (after, cost) =
                P::with_interpolant(&f, &step, t, y, f0, t_new, f1, &tolerance, |interpolant| {
                    run.after_step(interpolant, t, t_new, y, y1)
                });
            run.evaluations += cost;
            match after {
                AfterStep::Continue => {}
                AfterStep::Restart { time, state } => {
                    (t, y) = (time, state);
                    f0 = rhs(y, run.direction);
                    run.evaluations += 1;
                    after_rejection = false;
                    continue;
                }
                AfterStep::Stuck { time, angle } => return run.stuck(time, angle),
                AfterStep::Stop { time, state } => return run.stopped_at(time, state),
            }
        } else {
            run.count_step(t_new);
        }
        (t, y, f0) = (t_new, y1, f1);
        h = h_step * step_factor(error, after_rejection, P::ESTIMATE_ORDER);
        after_rejection = false;
    }
    run.finish(t, y)
}

/// The "interpolant" of a Verner step: a fresh step from the step's start
/// to the time wanted, exact to the method's order at any length (the pair
/// has no dense output here). Each call costs 15 evaluations, counted.
struct ReStep<'a, F: Fn(f64, State2) -> State2> {
    f: &'a F,
    t0: f64,
    y0: State2,
    f0: State2,
    end: (f64, State2),
    tolerance: Tolerance,
    evaluations: Cell<u64>,
}

impl<F: Fn(f64, State2) -> State2> Interpolant for ReStep<'_, F> {
    fn state(&self, t: f64) -> State2 {
        if t == self.t0 {
            return self.y0;
        }
        if t == self.end.0 {
            return self.end.1;
        }
        self.evaluations.set(self.evaluations.get() + 15);
        vern9::attempt(
            self.f,
            self.t0,
            self.y0,
            self.f0,
            t - self.t0,
            &self.tolerance,
        )
        .y1
    }
}

/// A step's continuous extension, as the events and samples need it.
trait Interpolant {
    /// `[θ, θ']` at `t` within the step.
    fn state(&self, t: f64) -> State2;
}

impl Interpolant for crate::integrate::dense::DenseOutput {
    fn state(&self, t: f64) -> State2 {
        self.eval(t)
    }
}

impl Interpolant for Hermite {
    fn state(&self, t: f64) -> State2 {
        [self.angle(t), self.velocity(t)]
    }
}

/// What the driver does after a step with an event or samples in it.
enum AfterStep {
    /// Carry on from the step's end.
    Continue,
    /// Restart from `state` at `time` (dry friction changed sign, or the
    /// observer changed the state).
    Restart { time: f64, state: State2 },
    /// Dry friction holds the pendulum here.
    Stuck { time: f64, angle: f64 },
    /// The observer ended the run at this event.
    Stop { time: f64, state: State2 },
}

/// The events a step can hold.
#[derive(Clone, Copy, PartialEq)]
enum EventKind {
    Turning,
    Crossing,
}

/// What every integrator's driver shares: the observer, the samples, the
/// turning points, the direction of motion (the sign dry friction takes)
/// and the counters.
struct Run<'a, O: Observer> {
    model: &'a Model,
    observer: &'a mut O,
    samples: Samples,
    duration: f64,
    outcome: Outcome,
    index: u64,
    direction: f64,
    evaluations: u64,
    go_on: bool,
    wants_crossings: bool,
}

impl<'a, O: Observer> Run<'a, O> {
    /// Reports the release; `Err` with the finished outcome if the pendulum
    /// never moves (zero amplitude, or held by friction from the start).
    fn start(
        model: &'a Model,
        method: Method,
        amplitude: Amplitude,
        options: &Options,
        observer: &'a mut O,
    ) -> Result<Self, Outcome> {
        let a0 = amplitude.radians();
        // The release is reported; there is nothing to stop or restart yet.
        observer.turning_point(&TurningPoint {
            index: 0,
            time: 0.0,
            angle: a0,
        });
        let go_on = true;
        let wants_crossings = observer.wants_zero_crossings();
        let run = Run {
            model,
            observer,
            samples: Samples {
                interval: options.sample_interval,
                next: 0,
            },
            duration: options.duration,
            outcome: Outcome {
                method,
                swings: 0,
                zero_crossings: 0,
                final_time: 0.0,
                final_state: State {
                    angle: a0,
                    angular_velocity: 0.0,
                },
                final_amplitude: a0,
                steps: 0,
                rejected_steps: 0,
                function_evaluations: 0,
                stopped: Stopped::Duration,
            },
            index: 0,
            // Released at +A0 it swings towards negative angles.
            direction: if a0 > 0.0 { -1.0 } else { 1.0 },
            evaluations: 0,
            go_on,
            wants_crossings,
        };
        if a0 == 0.0 {
            return Err(run.rest(0.0, 0.0, Stopped::Duration));
        }
        if run.sticks(a0) {
            return Err(run.stuck(0.0, a0));
        }
        Ok(run)
    }

    fn sticks(&self, angle: f64) -> bool {
        let r = self.model.friction_angle;
        r > 0.0 && angle.sin().abs() <= r
    }

    /// Whether a step from `y0` to `y1`, ending at `t_new`, holds an event
    /// or a sample, and so needs its interpolant.
    fn needs_interpolant(&self, t_new: f64, y0: State2, y1: State2) -> bool {
        y1[1] * self.direction < 0.0
            || self.crosses_upward(y0, y1)
            || self.samples.due(t_new).is_some()
    }

    fn crosses_upward(&self, y0: State2, y1: State2) -> bool {
        self.wants_crossings && crossed(y0[0], y1[0], Direction::Rising)
    }

    /// Emits the samples up to `limit` from the interpolant.
    fn emit_samples(&mut self, step: &(impl Interpolant + ?Sized), limit: f64) {
        while let Some(ts) = self.samples.due(limit) {
            let s = step.state(ts);
            let state = State {
                angle: s[0],
                angular_velocity: s[1],
            };
            self.go_on &= self.observer.sample(ts, &state);
            self.samples.next += 1;
        }
    }

    /// Handles the events and samples of the step from `(t, y0)` to
    /// `(t_new, y1)`, in time order; an event that restarts or stops the
    /// run drops the rest of the step.
    fn after_step(
        &mut self,
        step: &(impl Interpolant + ?Sized),
        t: f64,
        t_new: f64,
        y0: State2,
        y1: State2,
    ) -> AfterStep {
        self.count_step(t_new);
        let mut events: [Option<(f64, EventKind)>; 2] = [None, None];
        if y1[1] * self.direction < 0.0 {
            let time = locate_root(|x| step.state(x)[1], t, t_new, y0[1], y1[1]);
            events[0] = Some((time, EventKind::Turning));
        }
        if self.crosses_upward(y0, y1) {
            let time = locate_root(|x| step.state(x)[0], t, t_new, y0[0], y1[0]);
            events[1] = Some((time, EventKind::Crossing));
        }
        if let [Some(a), Some(b)] = events {
            if b.0 < a.0 {
                events = [Some(b), Some(a)];
            }
        }
        for (time, kind) in events.into_iter().flatten() {
            self.emit_samples(step, time);
            let state = step.state(time);
            let outcome = match kind {
                EventKind::Turning => self.turning_point(time, state[0]),
                EventKind::Crossing => self.zero_crossing(time, state),
            };
            if let Some(after) = outcome {
                return after;
            }
        }
        self.emit_samples(step, t_new);
        AfterStep::Continue
    }

    /// A turning point at `time`: report it, flip the direction, apply the
    /// observer's action and, with dry friction, stick or restart from rest.
    fn turning_point(&mut self, time: f64, angle: f64) -> Option<AfterStep> {
        self.index += 1;
        let action = self.observer.turning_point(&TurningPoint {
            index: self.index,
            time,
            angle,
        });
        self.direction = -self.direction;
        match action {
            Action::Stop => Some(AfterStep::Stop {
                time,
                state: [angle, 0.0],
            }),
            Action::Restart(s) => Some(self.restart(time, s)),
            Action::Continue if self.model.friction_angle > 0.0 => Some(if self.sticks(angle) {
                AfterStep::Stuck { time, angle }
            } else {
                AfterStep::Restart {
                    time,
                    state: [angle, 0.0],
                }
            }),
            Action::Continue => None,
        }
    }

    /// An upward zero crossing at `time`.
    fn zero_crossing(&mut self, time: f64, state: State2) -> Option<AfterStep> {
        self.outcome.zero_crossings += 1;
        let action = self.observer.zero_crossing(&Crossing {
            index: self.outcome.zero_crossings,
            time,
            angular_velocity: state[1],
        });
        match action {
            Action::Continue => None,
            Action::Stop => Some(AfterStep::Stop { time, state }),
            Action::Restart(s) => Some(self.restart(time, s)),
        }
    }

    /// A restart from the observer's `state`: the direction of motion (the
    /// sign dry friction takes) follows its velocity, or points to the
    /// centre when it is at rest.
    fn restart(&mut self, time: f64, state: State) -> AfterStep {
        self.direction = if state.angular_velocity != 0.0 {
            state.angular_velocity.signum()
        } else {
            -state.angle.signum()
        };
        AfterStep::Restart {
            time,
            state: [state.angle, state.angular_velocity],
        }
    }

    /// Counts an accepted step and now and then reports progress.
    fn count_step(&mut self, t: f64) {
        self.outcome.steps += 1;
        if self.outcome.steps % PROGRESS_EVERY == 0 {
            self.go_on &= self.observer.progress(t);
        }
    }

    /// The outcome at the end of the loop, at time `t` in state `y`.
    fn finish(mut self, t: f64, y: State2) -> Outcome {
        let state = State {
            angle: y[0],
            angular_velocity: y[1],
        };
        self.outcome.swings = self.index;
        self.outcome.final_time = t;
        self.outcome.final_amplitude = energy_amplitude(&self.model.pendulum, &state);
        self.outcome.final_state = state;
        self.outcome.function_evaluations = self.evaluations;
        if !self.go_on {
            self.outcome.stopped = Stopped::Interrupted;
        }
        self.outcome
    }

    /// Ended by the observer at an event.
    fn stopped_at(mut self, time: f64, state: State2) -> Outcome {
        let mut outcome = {
            self.go_on = true;
            self.finish(time, state)
        };
        outcome.stopped = Stopped::Event;
        outcome
    }

    /// Held by friction at `angle` from `time` on.
    fn stuck(self, time: f64, angle: f64) -> Outcome {
        self.rest(time, angle, Stopped::Friction)
    }

    /// At rest at `angle` from `time` to the end: later samples all show it.
    fn rest(mut self, time: f64, angle: f64, stopped: Stopped) -> Outcome {
        let state = State {
            angle,
            angular_velocity: 0.0,
        };
        while let Some(t) = self.samples.due(self.duration) {
            if !self.observer.sample(t, &state) {
                break;
            }
            self.samples.next += 1;
        }
        self.outcome.swings = self.index;
        self.outcome.final_time = time;
        self.outcome.final_state = state;
        self.outcome.final_amplitude = energy_amplitude(&self.model.pendulum, &state);
        self.outcome.function_evaluations = self.evaluations;
        self.outcome.stopped = stopped;
        self.outcome
    }
}

/// The symplectic method's fixed step for `model` at `tolerance`: the same
/// `rate · h` bound for every rate in the motion, the oscillation `ω_n`, the
/// viscous damping `2ζω_n` and the drag `b A0 ω_n`. The damping flows are
/// exact, but the splitting error between them and the oscillation grows
/// with `c h` (an overdamped ζ = 10 was 1% off before this bound).
fn symplectic_step(model: &Model, amplitude: Amplitude, tolerance: f64) -> f64 {
    let w = model.pendulum.natural_angular_frequency();
    let rates = [
        w,
        2.0 * model.damping.zeta() * w,
        model.quadratic_drag * amplitude.radians() * w,
    ];
    let fastest = rates.into_iter().fold(0.0, f64::max);
    let per_period = symplectic_steps_per_period(tolerance);
    std::f64::consts::TAU / (fastest * per_period)
}

/// Steps per small-angle period for the symplectic method at `tolerance`.
/// The method's error per unit time is about `(ω_n h)^6 / 5000` of the
/// amplitude (measured on the seconds pendulum at 3°: the final amplitude
/// after a week against a run with twice the steps), so
/// `ω_n h = (5000 tol)^(1/6)`, at least 12 steps a period.
pub fn symplectic_steps_per_period(tolerance: f64) -> f64 {
    let wh = (5000.0 * tolerance)
        .powf(1.0 / 6.0)
        .min(std::f64::consts::TAU / 12.0);
    (std::f64::consts::TAU / wh).ceil()
}

/// The exact flow of `v' = -c v - b v|v|` over each of a step's damping
/// intervals: `v e / (1 + b|v| (1 - e)/c)` with `e = e^{-cτ}` (a Bernoulli
/// equation), `v / (1 + b|v| τ)` when `c = 0`.
///
/// The decay is stored as `e - 1` (from `expm1`) and applied as
/// `v + v (e - 1)`: `e` itself, a number like `1 - 1e-8`, would round to a
/// fixed nearby double and bias the damping rate by up to 1e-8 of itself at
/// every one of 10^8 steps; `e - 1` keeps the rate to an ulp.
struct DampingFlow {
    decay_minus_one: [f64; 8],
    gain: [f64; 8],
    quadratic: f64,
}

impl DampingFlow {
    fn new(c: f64, quadratic: f64, h: f64) -> Self {
        let taus = damping_intervals(h);
        let decay_minus_one = taus.map(|tau| (-c * tau).exp_m1());
        let gain = taus.map(|tau| {
            if c > 0.0 {
                -(-c * tau).exp_m1() / c
            } else {
                tau
            }
        });
        Self {
            decay_minus_one,
            gain,
            quadratic,
        }
    }

    #[inline(always)]
    fn apply(&self, v: f64, i: usize) -> f64 {
        let decayed = v + v * self.decay_minus_one[i];
        if self.quadratic == 0.0 {
            decayed
        } else {
            decayed / (1.0 + self.quadratic * v.abs() * self.gain[i])
        }
    }
}

fn run_symplectic(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    let w = model.pendulum.natural_angular_frequency();
    let (w2, c1) = (w * w, 2.0 * model.damping.zeta() * w);
    let (b, r) = (model.quadratic_drag, model.friction_angle);
    let h = symplectic_step(model, amplitude, options.tolerance);
    let flow = DampingFlow::new(c1, b, h);
    let velocity_part = |v: f64| -c1 * v - b * v * v.abs();
    let force_of = |theta: f64, direction: f64| -w2 * (theta.sin() + r * direction);
    let mut run = match Run::start(model, Method::Symplectic, amplitude, options, observer) {
        Ok(run) => run,
        Err(finished) => return finished,
    };
    // Time is the restart time plus a whole number of steps, never a running sum.
    let (mut origin, mut n) = (0.0_f64, 0_u64);
    let (mut t, mut y) = (0.0_f64, [amplitude.radians(), 0.0]);
    let mut f = force_of(y[0], run.direction);
    run.evaluations += 1;
    while run.go_on && t < run.duration {
        let t_next = origin + (n + 1) as f64 * h;
        let last = t_next >= run.duration;
        let (t_new, step_h) = if last {
            (run.duration, run.duration - t)
        } else {
            (t_next, h)
        };
        let short_flow;
        let flow_now = if last {
            short_flow = DampingFlow::new(c1, b, step_h);
            &short_flow
        } else {
            &flow
        };
        let direction = run.direction;
        let mut force = |theta: f64| force_of(theta, direction);
        let mut damp = |v: f64, i: usize| flow_now.apply(v, i);
        let (y1, f1) = symplectic::step(&mut force, &mut damp, y, f, step_h);
        run.evaluations += 7;
        if run.needs_interpolant(t_new, y, y1) {
            let hermite = Hermite::new(
                t,
                step_h,
                [y[0], y[1], f + velocity_part(y[1])],
                [y1[0], y1[1], f1 + velocity_part(y1[1])],
            );
            match run.after_step(&hermite, t, t_new, y, y1) {
                AfterStep::Continue => {}
                AfterStep::Restart { time, state } => {
                    (origin, n, t, y) = (time, 0, time, state);
                    f = force_of(state[0], run.direction);
                    run.evaluations += 1;
                    continue;
                }
                AfterStep::Stuck { time, angle } => return run.stuck(time, angle),
                AfterStep::Stop { time, state } => return run.stopped_at(time, state),
            }
        } else {
            run.count_step(t_new);
        }
        n += 1;
        (t, y, f) = (t_new, y1, f1);
    }
    run.finish(t, y)
}
