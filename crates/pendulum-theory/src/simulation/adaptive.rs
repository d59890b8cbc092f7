//! The simulation's adaptive methods: the one driver of
//! [`crate::integrate::adaptive`] (DOP853, or Verner's 9(8)) in scaled
//! time, with the error control following the swing's size, events and
//! samples located on the pair's interpolant by [`Run`], and restarts where
//! friction or the observer asks.

use super::run::{AfterStep, Run};
use super::{Method, Model, Observer, Options, Outcome, Stopped};
use crate::integrate::adaptive::{Dop853, Driver, EmbeddedPair, Vern9};
use crate::integrate::control::Tolerance;
use crate::integrate::State2;
use crate::pendulum::Amplitude;

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

/// The run with any embedded pair: the driver's accepted steps handed to
/// [`Run`] for the turning points, crossings, samples and restarts.
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
    let y0 = [amplitude.radians(), 0.0];
    let mut tolerance = swing_tolerance(options.tolerance, y0);
    let mut driver = {
        let direction = run.direction;
        Driver::<P>::start(&|_, y| rhs(y, direction), 0.0, y0, &tolerance)
    };
    let finish = |run: &mut Run<_>, driver: &Driver<P>| {
        run.evaluations = driver.evaluations;
        run.outcome.rejected_steps = driver.rejected;
    };
    while run.go_on && driver.t < run.duration {
        let direction = run.direction;
        let f = |_t: f64, y: State2| rhs(y, direction);
        let Ok(step) = driver.attempt(&f, run.duration, &tolerance) else {
            finish(&mut run, &driver);
            return run.ended(driver.t, driver.y, Stopped::StepTooSmall);
        };
        let (t, t_new, y, y1) = (step.t0, step.t1, step.y0, step.y1);
        if let Some(reason) = run.check_state(y1) {
            run.count_step(t_new);
            finish(&mut run, &driver);
            return run.ended(t_new, y1, reason);
        }
        if run.needs_interpolant(t_new, y, y1) {
            let after = driver.interpolate(&f, &step, &tolerance, |interpolant| {
                run.after_step(interpolant, t, t_new, y, y1)
            });
            match after {
                AfterStep::Continue => {}
                AfterStep::Restart { time, state } => {
                    let direction = run.direction;
                    driver.restart(&|_, y| rhs(y, direction), time, state);
                    tolerance = swing_tolerance(options.tolerance, state);
                    continue;
                }
                AfterStep::Stuck { time, angle } => {
                    finish(&mut run, &driver);
                    return run.stuck(time, angle);
                }
                AfterStep::Stop { time, state } => {
                    finish(&mut run, &driver);
                    return run.ended(time, state, Stopped::Event);
                }
            }
        } else {
            run.count_step(t_new);
        }
        driver.commit(&step);
        tolerance = swing_tolerance(options.tolerance, driver.y);
    }
    finish(&mut run, &driver);
    run.finish(driver.t, driver.y)
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
