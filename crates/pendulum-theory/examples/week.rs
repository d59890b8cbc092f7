//! The week of a Littlemore-class free pendulum: a seconds pendulum
//! (l = 0.99362 m) released at 3°, Q = 10^6, 302,400 periods, every turning
//! point collected. Prints the wall time, the step count and the final
//! amplitude. Usage: `week [TOLERANCE]` (default 1e-10).

use pendulum_theory::damping::Damping;
use pendulum_theory::simulation::{
    simulate, Action, Method, Model, Observer, Options, TurningPoint,
};
use pendulum_theory::{Amplitude, Pendulum};
use std::time::Instant;

struct Collect(Vec<TurningPoint>);
impl Observer for Collect {
    fn turning_point(&mut self, p: &TurningPoint) -> Action {
        self.0.push(*p);
        Action::Continue
    }
}

fn main() {
    let tol: f64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1e-10);
    let method = match std::env::args().nth(2).as_deref() {
        Some("symplectic") => Method::Symplectic,
        _ => Method::Dop853,
    };
    let pendulum = Pendulum::with_standard_gravity(0.99362).unwrap();
    let model = Model::new(pendulum, Damping::from_q(1e6).unwrap(), 0.0, 0.0).unwrap();
    let amplitude = Amplitude::from_degrees(3.0).unwrap();
    let duration = 302_400.0 * pendulum.period(amplitude);
    let options = Options {
        duration,
        tolerance: tol,
        method,
        sample_interval: None,
    };
    let mut collect = Collect(Vec::with_capacity(700_000));
    let start = Instant::now();
    let outcome = simulate(&model, amplitude, &options, &mut collect).unwrap();
    let elapsed = start.elapsed().as_secs_f64();
    let last = collect.0.last().unwrap();
    println!(
        "{} tol {tol:e}: {elapsed:.3} s, {} steps ({} rejected), {} evaluations, {} turning points, \
         final amplitude {:.15e} rad (last turning point {:.15e}), {:.1} ns/step",
        method.name(),
        outcome.steps,
        outcome.rejected_steps,
        outcome.function_evaluations,
        outcome.swings,
        outcome.final_amplitude,
        last.angle.abs(),
        elapsed * 1e9 / outcome.steps as f64
    );
}
