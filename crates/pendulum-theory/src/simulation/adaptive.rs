//! The adaptive driver: an embedded Runge-Kutta pair (DOP853, or Verner's
//! 9(8)) stepping under the step-size controller in scaled time, with the
//! error control following the swing's size, events and samples located
//! on the pair's interpolant, and restarts where friction or the observer
//! asks.

use super::run::{AfterStep, Interpolant, Run};
use super::{Method, Model, Observer, Options, Outcome, Stopped};
use crate::integrate::control::{step_factor, Tolerance, MIN_FACTOR};
use crate::integrate::dop853::{attempt, dense_output, initial_step};
use crate::integrate::vern9;
use crate::integrate::State2;
use crate::pendulum::Amplitude;
use std::cell::Cell;

/// Runs the model with DOP853 (7th-order dense output for the events).
pub(super) fn run_dop853(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    run_adaptive::<Dop853>(Method::Dop853, model, amplitude, options, observer)
}

/// Runs the model with Verner's 9(8) pair (events by re-stepping).
pub(super) fn run_vern9(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    run_adaptive::<Vern9>(Method::Vern9, model, amplitude, options, observer)
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
    // Scaled time τ = ω_n t (see `run`): ω_n = 1, viscous rate 2ζ.
    let c1 = 2.0 * model.damping.zeta();
    let rhs =
        |y: State2, direction: f64| -> State2 { [y[1], model.acceleration(c1, y, direction)] };
    let mut run = match Run::start(model, method, amplitude, options, observer) {
        Ok(run) => run,
        Err(finished) => return finished,
    };
    let (mut t, mut y) = (0.0_f64, [amplitude.radians(), 0.0]);
    let mut tolerance = swing_tolerance(options.tolerance, y);
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
        if h_step.is_nan() || h_step <= 0.0 {
            return run.ended(t, y, Stopped::StepTooSmall);
        }
        let direction = run.direction;
        let f = |_t: f64, y: State2| rhs(y, direction);
        let step = P::attempt(&f, t, y, f0, h_step, &tolerance);
        run.evaluations += P::EVALUATIONS;
        let (y1, error) = P::end(&step);
        // A NaN error norm (an overflow inside the step) is a rejection.
        if error.is_nan() || error > 1.0 {
            run.outcome.rejected_steps += 1;
            let factor = if error.is_nan() {
                MIN_FACTOR
            } else {
                step_factor(error, true, P::ESTIMATE_ORDER)
            };
            h = h_step * factor;
            after_rejection = true;
            continue;
        }
        let f1 = f(t_new, y1);
        run.evaluations += 1;
        if let Some(reason) = run.check_state(y1) {
            run.count_step(t_new);
            return run.ended(t_new, y1, reason);
        }
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
                    tolerance = swing_tolerance(options.tolerance, y);
                    f0 = rhs(y, run.direction);
                    run.evaluations += 1;
                    after_rejection = false;
                    continue;
                }
                AfterStep::Stuck { time, angle } => return run.stuck(time, angle),
                AfterStep::Stop { time, state } => return run.ended(time, state, Stopped::Event),
            }
        } else {
            run.count_step(t_new);
        }
        (t, y, f0) = (t_new, y1, f1);
        tolerance = swing_tolerance(options.tolerance, y);
        h = h_step * step_factor(error, after_rejection, P::ESTIMATE_ORDER);
        after_rejection = false;
    }
    run.finish(t, y)
}

/// The error control of a step that starts in the scaled state `y`: the
/// relative tolerance `tol`, and an absolute tolerance `tol` times the
/// swing's size `max(|θ|, |dθ/dτ|)` (the amplitude to within a factor √2,
/// and no squares to underflow at 1e-160), so that the control follows the
/// swing as it decays instead of losing it below a fixed absolute tolerance.
fn swing_tolerance(tol: f64, y: State2) -> Tolerance {
    let size = super::run::swing_size(y);
    Tolerance {
        absolute: tol * size,
        relative: tol,
    }
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
