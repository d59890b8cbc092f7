//! The symplectic driver: Yoshida's 6th-order composition with exact
//! damping flows ([`crate::integrate::symplectic`]) at a fixed step in
//! scaled time, events and samples on a quintic Hermite interpolant.

use super::forces::DragLaw;
use super::run::{AfterStep, Run};
use super::{Method, Model, Observer, Options, Outcome, Rates, Stopped};
use crate::integrate::symplectic::{self, damping_intervals, Hermite};
use crate::pendulum::Amplitude;

/// The symplectic method's fixed step in scaled time (`ω_n = 1`) for
/// `model` at `tolerance`: the same `rate · h` bound for every rate in the
/// motion ([`Rates`]: the oscillation, the viscous damping `2ζ`, the drag).
/// The damping flows are exact, but the splitting error between them and
/// the oscillation grows with `c h` (an overdamped ζ = 10 was 1% off before
/// this bound).
fn symplectic_step(model: &Model, amplitude: Amplitude, tolerance: f64) -> f64 {
    let fastest = Rates::new(model, amplitude).fastest();
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

/// The exact flow of `v' = -c v + a(v)` (viscous decay and one drag law,
/// [`super::forces::DragLaw::flow`]) over each of a step's damping
/// intervals; for the quadratic drag `v e / (1 + b|v| (1 - e)/c)` with `e =
/// e^{-cτ}` (a Bernoulli equation), `v / (1 + b|v| τ)` when `c = 0`.
///
/// The decay is stored as `e - 1` (from `expm1`) and applied as
/// `v + v (e - 1)`: `e` itself, a number like `1 - 1e-8`, would round to a
/// fixed nearby double and bias the damping rate by up to 1e-8 of itself at
/// every one of 10^8 steps; `e - 1` keeps the rate to an ulp.
struct DampingFlow {
    decay_minus_one: [f64; 8],
    constant: [f64; 8],
    law: Option<(&'static dyn DragLaw, f64)>,
}

impl DampingFlow {
    fn new(c: f64, law: Option<(&'static dyn DragLaw, f64)>, h: f64) -> Self {
        let taus = damping_intervals(h);
        let decay_minus_one = taus.map(|tau| (-c * tau).exp_m1());
        let constant = taus.map(|tau| law.map_or(0.0, |(l, _)| l.flow_constant(c, tau)));
        Self {
            decay_minus_one,
            constant,
            law,
        }
    }

    #[inline(always)]
    fn apply(&self, v: f64, i: usize) -> f64 {
        let decayed = v + v * self.decay_minus_one[i];
        match self.law {
            None => decayed,
            Some((law, k)) => law.flow(k, v, decayed, self.constant[i]),
        }
    }
}

pub(super) fn run_symplectic(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    // Scaled time τ = ω_n t (see `run`): ω_n = 1, viscous rate 2ζ.
    let c1 = 2.0 * model.damping.zeta();
    // One drag law at most (`check_method`).
    let law = model.drag_laws().next();
    let h = symplectic_step(model, amplitude, options.tolerance);
    let flow = DampingFlow::new(c1, law, h);
    let velocity_part = |v: f64| model.velocity_terms(c1, v);
    let force_of = |theta: f64, direction: f64| model.position_terms(theta, direction);
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
            short_flow = DampingFlow::new(c1, law, step_h);
            &short_flow
        } else {
            &flow
        };
        let direction = run.direction;
        let mut force = |theta: f64| force_of(theta, direction);
        let mut damp = |v: f64, i: usize| flow_now.apply(v, i);
        let (y1, f1) = symplectic::step(&mut force, &mut damp, y, f, step_h);
        run.evaluations += 7;
        if let Some(reason) = run.check_state(y1) {
            run.count_step(t_new);
            return run.ended(t_new, y1, reason);
        }
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
                AfterStep::Stop { time, state } => return run.ended(time, state, Stopped::Event),
            }
        } else {
            run.count_step(t_new);
        }
        n += 1;
        (t, y, f) = (t_new, y1, f1);
    }
    run.finish(t, y)
}
