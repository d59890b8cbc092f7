//! What every integrator's driver shares: the observer, the samples, the
//! turning points and zero crossings, the direction of motion (the sign dry
//! friction takes), the energy check and the counters.
//!
//! The drivers integrate in scaled time `τ = ω_n t` and scaled velocity
//! `dθ/dτ = θ'/ω_n`, so that both components of the state have the size of
//! the swing whatever the pendulum's length: a 1 µm pendulum and a 10 km
//! one take the same steps. [`Run`] converts every time and state it hands
//! to the observer back to seconds and rad/s.

use super::{
    Action, Crossing, EnergyGain, Model, Observer, Outcome, Stopped, TurningPoint, AMPLITUDE_FLOOR,
    PROGRESS_EVERY,
};
use crate::damped::State;
use crate::integrate::events::{crossed, locate_root, Direction};
use crate::integrate::State2;
use crate::simulation::{energy_amplitude, Method, Options};
use crate::Amplitude;

/// The size of the swing in the scaled state `y`: `max(|θ|, |dθ/dτ|)`,
/// between `A/√2` and `A` for an amplitude `A` in the linear regime.
pub(super) fn swing_size(y: State2) -> f64 {
    y[0].abs().max(y[1].abs())
}

/// `sin²(θ/2)` (the energy over `2mgl`) and the period ratio `T/T0` of
/// the swing whose turning point is at `angle`; the period ratio is 1 where
/// it is undefined (at or past 180°, which the state check reports).
fn energy_and_period(angle: f64) -> (f64, f64) {
    let half = (0.5 * angle).sin();
    let period = Amplitude::from_radians(angle.abs()).map_or(1.0, crate::period::period_ratio);
    (half * half, period)
}

/// Samples due at multiples of a physical interval, located in scaled time.
pub(super) struct Samples {
    /// Seconds between samples, if any.
    pub interval: Option<f64>,
    /// Index of the next sample.
    pub next: u64,
    /// `ω_n`: scaled time per second.
    pub omega: f64,
}

impl Samples {
    /// The next sample at or before the scaled time `limit`, as
    /// `(seconds, scaled time)`: the time in seconds is `k · interval`
    /// exactly, never a converted value.
    pub fn due(&self, limit: f64) -> Option<(f64, f64)> {
        let h = self.interval?;
        let t = self.next as f64 * h;
        let tau = t * self.omega;
        (tau <= limit).then_some((t, tau))
    }
}

pub(super) use crate::integrate::adaptive::Interpolant;

impl Interpolant for crate::integrate::symplectic::Hermite {
    fn state(&self, t: f64) -> State2 {
        [self.angle(t), self.velocity(t)]
    }
}

/// What the driver does after a step with an event or samples in it.
pub(super) enum AfterStep {
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

/// The shared state of a run, in scaled time (see the module's notes).
pub(super) struct Run<'a, O: Observer> {
    model: &'a Model,
    observer: &'a mut O,
    samples: Samples,
    /// The duration in scaled time.
    pub duration: f64,
    /// The duration in seconds, as asked.
    duration_s: f64,
    omega: f64,
    /// The outcome so far.
    pub outcome: Outcome,
    index: u64,
    /// The sign of the friction force's direction of motion, ±1.
    pub direction: f64,
    /// Evaluations of the right-hand side so far.
    pub evaluations: u64,
    /// Whether the observer wants to go on.
    pub go_on: bool,
    wants_crossings: bool,
    /// The energy check's reference: `sin²(θ/2)` and the period ratio
    /// `T/T0` at the lowest turning point so far (damped), or at the
    /// release (undamped).
    reference: (f64, f64),
    /// Whether nothing in the model takes energy: then any change counts.
    undamped: bool,
    /// Relative energy gain at a turning point above which a warning is kept.
    gain_allowance: f64,
}

impl<'a, O: Observer> Run<'a, O> {
    /// Reports the release; `Err` with the finished outcome if the pendulum
    /// never moves (zero amplitude, or held by friction from the start).
    pub fn start(
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
        let omega = model.pendulum.natural_angular_frequency();
        let wants_crossings = observer.wants_zero_crossings();
        let run = Run {
            model,
            observer,
            samples: Samples {
                interval: options.sample_interval,
                next: 0,
                omega,
            },
            duration: options.duration * omega,
            duration_s: options.duration,
            omega,
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
                energy_gain: None,
            },
            index: 0,
            // Released at +A0 it swings towards negative angles.
            direction: if a0 > 0.0 { -1.0 } else { 1.0 },
            evaluations: 0,
            go_on: true,
            wants_crossings,
            reference: energy_and_period(a0),
            undamped: model.is_undamped(),
            gain_allowance: super::energy_gain_allowance(method, options.tolerance),
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

    /// Seconds at scaled time `tau`; the duration itself exactly.
    fn seconds(&self, tau: f64) -> f64 {
        if tau == self.duration {
            self.duration_s
        } else {
            tau / self.omega
        }
    }

    /// The physical state of the scaled state `y`.
    fn physical(&self, y: State2) -> State {
        State {
            angle: y[0],
            angular_velocity: y[1] * self.omega,
        }
    }

    /// Checks the state at the end of an accepted step: the run ends if the
    /// pendulum went over the top (impossible from rest below 180° with
    /// damping that never adds energy: a numerical failure), or if the swing
    /// has decayed below [`AMPLITUDE_FLOOR`].
    pub fn check_state(&self, y: State2) -> Option<Stopped> {
        if y[0].abs() > std::f64::consts::PI {
            Some(Stopped::OverTheTop)
        } else if swing_size(y) < AMPLITUDE_FLOOR {
            Some(Stopped::AmplitudeBelowTolerance)
        } else {
            None
        }
    }

    /// Whether a step from `y0` to `y1`, ending at `t_new`, holds an event
    /// or a sample, and so needs its interpolant.
    pub fn needs_interpolant(&self, t_new: f64, y0: State2, y1: State2) -> bool {
        y1[1] * self.direction < 0.0
            || self.crosses_upward(y0, y1)
            || self.samples.due(t_new).is_some()
    }

    fn crosses_upward(&self, y0: State2, y1: State2) -> bool {
        self.wants_crossings && crossed(y0[0], y1[0], Direction::Rising)
    }

    /// Emits the samples up to `limit` from the interpolant.
    fn emit_samples(&mut self, step: &(impl Interpolant + ?Sized), limit: f64) {
        while let Some((t, tau)) = self.samples.due(limit) {
            let state = self.physical(step.state(tau));
            self.go_on &= self.observer.sample(t, &state);
            self.samples.next += 1;
        }
    }

    /// Handles the events and samples of the step from `(t, y0)` to
    /// `(t_new, y1)`, in time order; an event that restarts or stops the
    /// run drops the rest of the step.
    pub fn after_step(
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

    /// A turning point at scaled time `time`: check the energy, report it,
    /// flip the direction, apply the observer's action and, with dry
    /// friction, stick or restart from rest.
    fn turning_point(&mut self, time: f64, angle: f64) -> Option<AfterStep> {
        self.index += 1;
        self.check_energy(time, angle);
        let action = self.observer.turning_point(&TurningPoint {
            index: self.index,
            time: self.seconds(time),
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

    /// With damping that never adds energy, the energy at a turning point,
    /// `sin²(θ/2)`, and the period it implies can only fall; without
    /// damping both must stay as released. A change beyond the method's own
    /// error (see [`super::energy_gain_allowance`]), in either measure, is
    /// kept as a warning, the largest one seen. The period catches what the
    /// energy cannot near 180°, where an energy error of 1e-16 changes the
    /// period by half; the energy catches what the period cannot at small
    /// amplitudes, where the period hardly depends on it.
    fn check_energy(&mut self, time: f64, angle: f64) {
        let (energy, period) = energy_and_period(angle);
        let (e0, p0) = self.reference;
        let change = if self.undamped {
            (energy / e0 - 1.0).abs().max((period / p0 - 1.0).abs())
        } else {
            (energy / e0 - 1.0).max(period / p0 - 1.0)
        };
        if change > self.gain_allowance {
            let larger = self.outcome.energy_gain.is_none_or(|g| change > g.relative);
            if larger {
                self.outcome.energy_gain = Some(EnergyGain {
                    time: self.seconds(time),
                    relative: change,
                });
            }
        }
        if !self.undamped && energy < e0 {
            self.reference = (energy, period);
        }
    }

    /// An upward zero crossing at scaled time `time`.
    fn zero_crossing(&mut self, time: f64, state: State2) -> Option<AfterStep> {
        self.outcome.zero_crossings += 1;
        let action = self.observer.zero_crossing(&Crossing {
            index: self.outcome.zero_crossings,
            time: self.seconds(time),
            angular_velocity: state[1] * self.omega,
        });
        match action {
            Action::Continue => None,
            Action::Stop => Some(AfterStep::Stop { time, state }),
            Action::Restart(s) => Some(self.restart(time, s)),
        }
    }

    /// A restart from the observer's (physical) `state`: the direction of
    /// motion (the sign dry friction takes) follows its velocity, or points
    /// to the centre when it is at rest. An observer that adds energy resets
    /// the energy check's reference.
    fn restart(&mut self, time: f64, state: State) -> AfterStep {
        self.direction = if state.angular_velocity != 0.0 {
            state.angular_velocity.signum()
        } else {
            -state.angle.signum()
        };
        let scaled = [state.angle, state.angular_velocity / self.omega];
        self.reference = energy_and_period(energy_amplitude(&self.model.pendulum, &state));
        // An observer that adds energy makes the motion a driven one.
        self.undamped = false;
        AfterStep::Restart {
            time,
            state: scaled,
        }
    }

    /// Counts an accepted step ending at scaled time `t` and now and then
    /// reports progress.
    pub fn count_step(&mut self, t: f64) {
        self.outcome.steps += 1;
        if self.outcome.steps % PROGRESS_EVERY == 0 {
            let seconds = self.seconds(t);
            self.go_on &= self.observer.progress(seconds);
        }
    }

    /// The outcome at the end of the loop, at scaled time `t` in state `y`.
    pub fn finish(mut self, t: f64, y: State2) -> Outcome {
        let state = self.physical(y);
        self.outcome.swings = self.index;
        self.outcome.final_time = self.seconds(t);
        self.outcome.final_amplitude = energy_amplitude(&self.model.pendulum, &state);
        self.outcome.final_state = state;
        self.outcome.function_evaluations = self.evaluations;
        if !self.go_on {
            self.outcome.stopped = Stopped::Interrupted;
        }
        self.outcome
    }

    /// Ended for `reason` (an event the observer made terminal, a failed
    /// state check, a step too small) at scaled time `time` in state `state`.
    pub fn ended(mut self, time: f64, state: State2, reason: Stopped) -> Outcome {
        self.go_on = true;
        let mut outcome = self.finish(time, state);
        outcome.stopped = reason;
        outcome
    }

    /// Held by friction at `angle` from scaled time `time` on.
    pub fn stuck(self, time: f64, angle: f64) -> Outcome {
        self.rest(time, angle, Stopped::Friction)
    }

    /// At rest at `angle` from scaled time `time` to the end: later samples
    /// all show it.
    fn rest(mut self, time: f64, angle: f64, stopped: Stopped) -> Outcome {
        let state = State {
            angle,
            angular_velocity: 0.0,
        };
        while let Some((t, _)) = self.samples.due(self.duration) {
            if !self.observer.sample(t, &state) {
                break;
            }
            self.samples.next += 1;
        }
        self.outcome.swings = self.index;
        self.outcome.final_time = self.seconds(time);
        self.outcome.final_state = state;
        self.outcome.final_amplitude = energy_amplitude(&self.model.pendulum, &state);
        self.outcome.function_evaluations = self.evaluations;
        self.outcome.stopped = stopped;
        self.outcome
    }
}
