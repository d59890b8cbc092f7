//! The closed-form driver (no damping): events on quarter periods of the
//! exact motion ([`crate::exact`]), samples from the Jacobi form.

use super::run::Samples;
use super::{Action, Crossing, Model, Observer, Options, Outcome, Stopped, TurningPoint};
use super::{Method, PROGRESS_EVERY};
use crate::exact::ExactSwing;
use crate::pendulum::Amplitude;

/// Runs the undamped model on its closed form.
pub(super) fn run_exact(
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
        omega: 1.0,
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
        while let Some((t, _)) = samples.due(time) {
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
        while let Some((t, _)) = samples.due(duration) {
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
        energy_gain: None,
    }
}
