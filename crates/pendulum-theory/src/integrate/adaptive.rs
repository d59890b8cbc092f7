//! The one adaptive driver: an embedded Runge-Kutta pair (DOP853, or
//! Verner's 9(8)) stepping under the step-size controller of
//! [`super::control`] (Hairer, Nørsett & Wanner I, II.4), time kept as a
//! difference of representable values, the pair's continuous extension
//! for events and samples, and terminal events located on it
//! ([`Driver::first_terminal`]). The simulation's adaptive methods and the
//! clock's integrated half swing both step with it; what happens at an
//! event (a turning point observed, a restart with the next escapement
//! zone's torque) is theirs.

use super::control::{step_factor, Tolerance, MIN_FACTOR};
use super::events::locate_root;
use super::{dop853, vern9, State2};
use std::cell::Cell;

/// The state `[θ, θ']` at any time within an accepted step.
pub trait Interpolant {
    /// The state at time `t` within the step.
    fn state(&self, t: f64) -> State2;
}

impl Interpolant for super::dense::DenseOutput {
    fn state(&self, t: f64) -> State2 {
        self.eval(t)
    }
}

/// What the driver needs of an embedded Runge-Kutta pair: one attempted
/// step, its end and error norm, and its continuous extension.
pub trait EmbeddedPair {
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
    /// Calls `handle` with the step's interpolant over `[t, t1]`; returns
    /// its result and the evaluations the interpolant cost.
    fn with_interpolant<R>(
        f: &impl Fn(f64, State2) -> State2,
        accepted: &Accepted<Self::Step>,
        tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> (R, u64);
}

/// DOP853 with its 7th-order dense output (3 more evaluations).
pub struct Dop853;

impl EmbeddedPair for Dop853 {
    type Step = dop853::Step;
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
        dop853::attempt(&mut |t, y| f(t, y), t, y0, f0, h, tolerance)
    }

    fn end(step: &Self::Step) -> (State2, f64) {
        (step.y1, step.error)
    }

    fn with_interpolant<R>(
        f: &impl Fn(f64, State2) -> State2,
        accepted: &Accepted<Self::Step>,
        _tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> (R, u64) {
        let dense = dop853::dense_output(&mut |t, y| f(t, y), &accepted.step, accepted.f1);
        (handle(&dense), 3)
    }
}

/// Verner's 9(8) pair, whose "interpolant" steps again (`ReStep`).
pub struct Vern9;

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
        accepted: &Accepted<Self::Step>,
        tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> (R, u64) {
        let restep = ReStep {
            f,
            t0: accepted.t0,
            y0: accepted.y0,
            f0: accepted.f0,
            end: (accepted.t1, accepted.y1),
            tolerance: *tolerance,
            evaluations: Cell::new(0),
        };
        let result = handle(&restep);
        (result, restep.evaluations.get())
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

/// An accepted step from `(t0, y0)` to `(t1, y1)`.
pub struct Accepted<S> {
    /// Its start.
    pub t0: f64,
    /// Its end (exactly the time asked for when it is the last).
    pub t1: f64,
    /// The state at its start.
    pub y0: State2,
    /// The state at its end.
    pub y1: State2,
    /// `f(t0, y0)`.
    pub f0: State2,
    /// `f(t1, y1)`.
    pub f1: State2,
    /// Its error norm (at most 1).
    pub error: f64,
    /// The pair's step, for its interpolant.
    pub step: S,
}

/// Why no step could be accepted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Failure {
    /// The step fell below the driver's smallest step, or to nothing.
    StepTooSmall,
}

/// The driver's state between steps: where it is, the next step's
/// length, and what it has cost.
pub struct Driver<P: EmbeddedPair> {
    /// The time reached.
    pub t: f64,
    /// The state reached.
    pub y: State2,
    /// `f(t, y)`.
    pub f0: State2,
    /// The next step's length.
    pub h: f64,
    /// Steps rejected so far.
    pub rejected: u64,
    /// Evaluations of `f` so far.
    pub evaluations: u64,
    /// Steps shorter than this fail ([`Failure::StepTooSmall`]).
    pub min_step: f64,
    after_rejection: bool,
    pair: std::marker::PhantomData<P>,
}

impl<P: EmbeddedPair> Driver<P> {
    /// Starts at `(t, y)` with the starting step of Hairer, Nørsett &
    /// Wanner I, II.4 (two evaluations).
    pub fn start(
        f: &impl Fn(f64, State2) -> State2,
        t: f64,
        y: State2,
        tolerance: &Tolerance,
    ) -> Self {
        let f0 = f(t, y);
        let h = dop853::initial_step(&mut |t, y| f(t, y), t, y, f0, tolerance);
        Self {
            t,
            y,
            f0,
            h,
            rejected: 0,
            evaluations: 2,
            min_step: 0.0,
            after_rejection: false,
            pair: std::marker::PhantomData,
        }
    }

    /// Attempts steps from the state reached, not past `end` (the last one
    /// ends on it exactly), until one is accepted. A step whose error norm
    /// is above 1, not a number, or whose end is not finite is rejected and
    /// the step shrinks. The accepted step is not yet taken: call
    /// [`Driver::commit`] (or [`Driver::restart`]).
    pub fn attempt(
        &mut self,
        f: &impl Fn(f64, State2) -> State2,
        end: f64,
        tolerance: &Tolerance,
    ) -> Result<Accepted<P::Step>, Failure> {
        loop {
            let t = self.t;
            // The step is the difference of two representable times, so
            // that t + h_step is exactly t1 and no rounding builds up in t.
            let t1 = if t + self.h >= end { end } else { t + self.h };
            let h = t1 - t;
            if h.is_nan() || h <= 0.0 || h < self.min_step {
                return Err(Failure::StepTooSmall);
            }
            let step = P::attempt(f, t, self.y, self.f0, h, tolerance);
            self.evaluations += P::EVALUATIONS;
            let (y1, error) = P::end(&step);
            let finite = y1[0].is_finite() && y1[1].is_finite();
            if error.is_nan() || error > 1.0 || !finite {
                self.rejected += 1;
                let factor = if error.is_nan() || !finite {
                    MIN_FACTOR
                } else {
                    step_factor(error, true, P::ESTIMATE_ORDER)
                };
                self.h = h * factor;
                self.after_rejection = true;
                continue;
            }
            let f1 = f(t1, y1);
            self.evaluations += 1;
            return Ok(Accepted {
                t0: t,
                t1,
                y0: self.y,
                y1,
                f0: self.f0,
                f1,
                error,
                step,
            });
        }
    }

    /// Calls `handle` with the accepted step's interpolant, counting what
    /// it costs.
    pub fn interpolate<R>(
        &mut self,
        f: &impl Fn(f64, State2) -> State2,
        accepted: &Accepted<P::Step>,
        tolerance: &Tolerance,
        handle: impl FnOnce(&dyn Interpolant) -> R,
    ) -> R {
        let (result, cost) = P::with_interpolant(f, accepted, tolerance, handle);
        self.evaluations += cost;
        result
    }

    /// Takes the accepted step; the next step's length follows its error.
    pub fn commit(&mut self, accepted: &Accepted<P::Step>) {
        self.t = accepted.t1;
        self.y = accepted.y1;
        self.f0 = accepted.f1;
        self.h = (accepted.t1 - accepted.t0)
            * step_factor(accepted.error, self.after_rejection, P::ESTIMATE_ORDER);
        self.after_rejection = false;
    }

    /// Restarts at `(t, y)` after an event (the right-hand side may have
    /// changed there: `f` is the new one), keeping the step length.
    pub fn restart(&mut self, f: &impl Fn(f64, State2) -> State2, t: f64, y: State2) {
        self.t = t;
        self.y = y;
        self.f0 = f(t, y);
        self.evaluations += 1;
        self.after_rejection = false;
    }

    /// The first of the terminal `events` (functions of the state; an
    /// event is hit where its function rises through zero to 0 or
    /// above) within the accepted step: its index, time and state, located
    /// on the step's interpolant by [`locate_root`]. On a tie the event
    /// listed first wins. `None` when none is hit.
    pub fn first_terminal(
        &mut self,
        f: &impl Fn(f64, State2) -> State2,
        accepted: &Accepted<P::Step>,
        tolerance: &Tolerance,
        events: &[&dyn Fn(State2) -> f64],
    ) -> Option<(usize, f64, State2)> {
        if !events.iter().any(|g| g(accepted.y1) >= 0.0) {
            return None;
        }
        let (t0, t1) = (accepted.t0, accepted.t1);
        self.interpolate(f, accepted, tolerance, |interpolant| {
            let mut first: Option<(usize, f64)> = None;
            for (i, g) in events.iter().enumerate() {
                let g1 = g(accepted.y1);
                if g1 < 0.0 {
                    continue;
                }
                let g0 = g(accepted.y0);
                let t = locate_root(|s| g(interpolant.state(s)), t0, t1, g0, g1);
                if first.is_none_or(|(_, tf)| t < tf) {
                    first = Some((i, t));
                }
            }
            first.map(|(i, t)| (i, t, interpolant.state(t)))
        })
    }
}
