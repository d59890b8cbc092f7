//! The averaged driver: one step per half swing, by the closed-form map of
//! [`crate::averaging`] (the exact elliptic half period at the mean
//! energy, the viscous loss as the free half swing's action over Q,
//! reversible, so right to third order in 1/Q). Viscous damping only (the
//! map has no drag or dry-friction law); turning points only (no samples,
//! no zero crossings). The state at the end, between two turning points,
//! is the free swing's of the last amplitude.

use super::{Method, Model, Observer, Options, Outcome, Stopped, TurningPoint, PROGRESS_EVERY};
use crate::averaging::half_swing_map;
use crate::damped::State;
use crate::exact::ExactSwing;
use crate::pendulum::Amplitude;

pub(super) fn run_averaged(
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
    observer: &mut impl Observer,
) -> Outcome {
    let omega = model.pendulum.natural_angular_frequency();
    let zeta = model.damping.zeta();
    let q = if zeta > 0.0 {
        0.5 / zeta
    } else {
        f64::INFINITY
    };
    let a0 = amplitude.radians();
    observer.turning_point(&TurningPoint {
        index: 0,
        time: 0.0,
        angle: a0,
    });
    let (mut time, mut carry) = (0.0_f64, 0.0_f64);
    let (mut a, mut index, mut side) = (a0, 0_u64, 1.0_f64);
    let mut stopped = Stopped::Duration;
    while a > 0.0 {
        let Some(h) = half_swing_map(q, a, None) else {
            stopped = Stopped::OverTheTop;
            break;
        };
        // Compensated sum: a week of half swings keeps the last bit.
        let y = h.time / omega - carry;
        let t = time + y;
        if t > options.duration {
            break;
        }
        carry = (t - time) - y;
        time = t;
        a = h.amplitude;
        side = -side;
        index += 1;
        let action = observer.turning_point(&TurningPoint {
            index,
            time,
            angle: side * a,
        });
        if action != super::Action::Continue {
            stopped = Stopped::Event;
            break;
        }
        if index % PROGRESS_EVERY == 0 && !observer.progress(time) {
            stopped = Stopped::Interrupted;
            break;
        }
        if a < super::AVERAGED_AMPLITUDE_FLOOR {
            stopped = Stopped::AmplitudeBelowTolerance;
            break;
        }
    }
    let end = if stopped == Stopped::Duration {
        options.duration
    } else {
        time
    };
    let final_state = match Amplitude::from_radians(a) {
        Ok(amp) => {
            let s = ExactSwing::new(&model.pendulum, amp).state_at(end - time);
            State {
                angle: side * s.angle,
                angular_velocity: side * s.angular_velocity,
            }
        }
        Err(_) => State {
            angle: side * a,
            angular_velocity: 0.0,
        },
    };
    Outcome {
        method: Method::Averaged,
        swings: index,
        zero_crossings: 0,
        final_time: end,
        final_state,
        final_amplitude: a,
        steps: index,
        rejected_steps: 0,
        function_evaluations: 0,
        stopped,
        energy_gain: None,
    }
}
