//! Long runs of a clock: days to years of half swings.
//!
//! Each half swing is the closed-form map of [`super::averaged`] (one
//! step per beat: every turning point, a week of a seconds pendulum in a
//! fraction of a second), or, when only a row every so often is wanted,
//! many beats per step: the map's increments `g(A)` (amplitude) and `τ(A)`
//! (duration) become the flow `dA/dn = g - g g'/2`, `dt/dn = τ - τ' g/2` in
//! the beat count `n` (the map's modified equation to second order, so
//! that one unit of the flow is one half swing), advanced by the classical
//! Runge-Kutta method over up to a few thousand beats per step (at most a
//! twentieth of the amplitude's relaxation time `Q/π` periods, and never
//! past a row or a change of the drive schedule's sampling).
//!
//! The drive may change with time (a mainspring running down): the
//! `drive` function gives the factor at each moment, held over a beat. So
//! may the pendulum's own period (its temperature and the air pressure):
//! `stretch` gives the factor each half swing's duration is multiplied
//! by (1 + the relative period change, from a design's temperature and
//! barometric coefficients).
//! The clock's indicated time is its beat count times the nominal beat
//! (half the `nominal_period` it was regulated to); the time error is the
//! indicated time less the true time (positive: ahead).

use super::averaged::half_swing_map;
use super::Clock;
use crate::averaging::HalfSwing;

/// The longest escapement cycle, in beats, stepped many beats at a time
/// (its whole cycle's map as one step): one beat in beat, two out of beat.
/// A free pendulum's longer cycle steps beat by beat.
pub const MULTI_STEP_CYCLE: u64 = 2;

/// A schedule's value at `t`: linear between the points `(times[i],
/// values[i])` (times increasing), held beyond the first and the last; 1
/// for an empty schedule (the drive as given).
pub fn piecewise_linear(times: &[f64], values: &[f64], t: f64) -> f64 {
    let i = times.partition_point(|&x| x <= t);
    match (i, values.first(), values.get(i.wrapping_sub(1))) {
        (_, None, _) => 1.0,
        (0, Some(&first), _) => first,
        (_, _, Some(&last)) if i == times.len() => last,
        (_, _, Some(&v0)) => {
            let (t0, t1, v1) = (times[i - 1], times[i], values[i]);
            v0 + (v1 - v0) * (t - t0) / (t1 - t0)
        }
        _ => 1.0,
    }
}

/// The factor a clock's half swings lengthen by when its rate moves by
/// `rate` s/day (positive: gaining): `1 / (1 + rate/86400)`, the `stretch`
/// of [`run`] for a temperature or pressure coefficient.
pub fn period_factor(rate: f64) -> f64 {
    1.0 / (1.0 + rate / 86_400.0)
}

/// What a long run reports, at a turning point or every so often.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// True time, s.
    pub time: f64,
    /// Beats counted.
    pub beats: u64,
    /// Amplitude, rad.
    pub amplitude: f64,
    /// The rate at this moment, s/day (positive: gaining): `86400 (T_nominal
    /// / T - 1)` for the current half swing's period.
    pub rate: f64,
    /// Indicated less true time, s.
    pub time_error: f64,
    /// The drive factor.
    pub drive: f64,
}

/// Why a long run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// It ran its whole duration.
    Duration,
    /// The sink asked it to stop (Ctrl-C, a write error).
    Sink,
    /// The swing fell below the escapement's unlocking: the clock stopped
    /// (a drive run down, a weak drive).
    PendulumStopped,
    /// The drive carried the pendulum over the top.
    OverTheTop,
    /// The rate change (`stretch`) reached a day per day or more, or was
    /// not a number: no clock runs so.
    RateOutOfRange,
}

impl Ending {
    /// A short name for output (`"duration"`, `"pendulum_stopped"`, …).
    pub fn name(self) -> &'static str {
        match self {
            Ending::Duration => "duration",
            Ending::Sink => "interrupted",
            Ending::PendulumStopped => "pendulum_stopped",
            Ending::OverTheTop => "over_the_top",
            Ending::RateOutOfRange => "rate_out_of_range",
        }
    }
}

/// How a long run ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finish {
    /// The last row.
    pub last: Row,
    /// Half swings computed one by one.
    pub single_steps: u64,
    /// Multi-beat steps.
    pub multi_steps: u64,
    /// Whether it stopped early (the pendulum stopped, or the sink asked).
    pub stopped: bool,
    /// Why it ended.
    pub ending: Ending,
}

/// Options of a long run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LongRun {
    /// Simulated time, s.
    pub duration: f64,
    /// Amplitude at the start (a turning point), rad.
    pub amplitude: f64,
    /// The period the clock was regulated to, s.
    pub nominal_period: f64,
    /// A row this often, s; `None`: a row at every turning point.
    pub every: Option<f64>,
}

impl LongRun {
    /// A run of `duration` s started in the steady state `start` and
    /// regulated to it (its amplitude and period), a row every `every` s
    /// (`None`: every turning point).
    pub fn from_steady(start: &super::Steady, duration: f64, every: Option<f64>) -> Self {
        Self {
            duration,
            amplitude: start.amplitude,
            nominal_period: start.period,
            every,
        }
    }
}

/// Runs `clock` (one whole escapement cycle per beat pattern; free
/// pendulums step beat by beat) and hands `sink` each row; `sink` returns
/// `false` to stop.
pub fn run(
    clock: &Clock,
    drive: &dyn Fn(f64) -> f64,
    stretch: &dyn Fn(f64) -> f64,
    options: &LongRun,
    sink: &mut dyn FnMut(&Row) -> bool,
) -> Finish {
    run_with_damping(clock, drive, stretch, &|_| 1.0, options, sink)
}

/// Classical RK4 over `n` cycles of the escapement on the modified
/// equation `flow` (amplitude change and scaled duration per cycle at an
/// amplitude and a time), from amplitude `a` at time `t` (s), for a
/// pendulum of natural angular frequency `omega`: the amplitude's change,
/// the time taken (s) and the last stage's scaled cycle duration; or,
/// where a stage's half swing cannot be made, that stage's time.
fn rk4_cycles(
    flow: &dyn Fn(f64, f64) -> Option<(f64, f64)>,
    a: f64,
    t: f64,
    n: f64,
    omega: f64,
) -> Result<(f64, f64, f64), f64> {
    let k1 = flow(a, t).ok_or(t)?;
    let t2 = t + 0.5 * n * k1.1 / omega;
    let k2 = flow(a + 0.5 * n * k1.0, t2).ok_or(t2)?;
    let t3 = t + 0.5 * n * k2.1 / omega;
    let k3 = flow(a + 0.5 * n * k2.0, t3).ok_or(t3)?;
    let t4 = t + n * k3.1 / omega;
    let k4 = flow(a + n * k3.0, t4).ok_or(t4)?;
    Ok((
        n / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
        n / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1) / omega,
        k4.1,
    ))
}

/// Whether a row is due at `time` (rows every `every` s, the next at
/// `next_row`, the run ending at `duration`), moving `next_row` past
/// `time`: step by step as rows come, at once past a long beat (a clock
/// all but stopped takes years a beat: counting those rows one by one
/// never ended).
fn row_due(every: f64, next_row: &mut f64, time: f64, duration: f64) -> bool {
    if time < *next_row - 1e-9 * every && time < duration {
        return false;
    }
    let behind = (time + 1e-9 * every - *next_row) / every;
    if behind > 16.0 {
        *next_row += behind.floor() * every;
    }
    while *next_row <= time + 1e-9 * every && next_row.is_finite() {
        *next_row += every;
    }
    true
}

/// What a long run steps with: the clock, its schedules and the
/// figures every step uses.
struct Stepper<'a> {
    clock: &'a Clock,
    drive: &'a dyn Fn(f64) -> f64,
    stretch: &'a dyn Fn(f64) -> f64,
    damping: &'a dyn Fn(f64) -> f64,
    /// The pendulum's natural angular frequency, rad/s.
    omega: f64,
    /// Half the nominal period, s.
    nominal_beat: f64,
    /// The escapement's cycle, in beats.
    cycle: u64,
    /// Whether the escapement shifts the swing's time (not symmetric).
    shift: bool,
}

impl Stepper<'_> {
    /// One half swing from amplitude `a` at beat `beat` of the cycle, drive
    /// `d` and time `t` (s): the map of [`half_swing_map`] at the Q of that
    /// moment, its duration lengthened by a suspension spring's share of the
    /// circular error; `None` where the swing cannot be made.
    fn half_swing(&self, a: f64, beat: u64, d: f64, t: f64, shift: bool) -> Option<HalfSwing> {
        let q = self.clock.q * (self.damping)(t);
        half_swing_map(
            Some(self.clock.escapement.as_ref()),
            q,
            &self.clock.drag,
            d,
            beat,
            a,
            shift,
        )
        .map(|h| HalfSwing {
            time: h.time * self.clock.spring_factor(a),
            ..h
        })
    }

    /// The rate (s/day) a clock keeps whose beats take `beat_time` s.
    fn rate_of(&self, beat_time: f64) -> f64 {
        86_400.0 * (self.nominal_beat / beat_time - 1.0)
    }

    /// The beats' durations (s) over the escapement's first whole cycle
    /// from `amplitude` with drive `d` (zeros from a beat that cannot be
    /// made on): the rate at the start.
    fn first_cycle(&self, amplitude: f64, d: f64) -> Vec<f64> {
        let mut recent = vec![0.0; self.cycle as usize];
        let mut a = amplitude;
        for (beat, seconds) in recent.iter_mut().enumerate() {
            let Some(h) = self.half_swing(a, beat as u64, d, 0.0, self.shift) else {
                break;
            };
            *seconds = h.time * (self.stretch)(0.0) / self.omega;
            a = h.amplitude;
        }
        recent
    }

    /// One whole cycle of the escapement from amplitude `a`, drive `d`, at
    /// time `t`: the amplitude after it and its scaled duration.
    fn cycle_map(&self, a: f64, d: f64, t: f64, shift: bool) -> Option<HalfSwing> {
        let mut swing = HalfSwing {
            amplitude: a,
            time: 0.0,
        };
        for beat in 0..self.cycle {
            let h = self.half_swing(swing.amplitude, beat, d, t, shift)?;
            swing = HalfSwing {
                amplitude: h.amplitude,
                time: swing.time + h.time,
            };
        }
        Some(swing)
    }

    /// The modified equation's flow at amplitude `a` and time `t`: the
    /// amplitude's change and the (stretched, scaled) duration per cycle,
    /// `g - g g'/2` and `τ - τ' g/2`. The drive at each stage's time: the
    /// flow is not autonomous. The neighbours only give the derivatives
    /// of the map, for the second-order term: the escapement's time shift
    /// (Airy's integral, most of an asymmetric escapement's work) moves
    /// them by 1e-4 of that term, and is left out.
    fn flow(&self, a: f64, t: f64) -> Option<(f64, f64)> {
        let d = (self.drive)(t);
        let h = 1e-6 * a;
        let m0 = self.cycle_map(a, d, t, self.shift)?;
        let mp = self.cycle_map(a + h, d, t, false)?;
        let mm = self.cycle_map(a - h, d, t, false)?;
        let g = m0.amplitude - a;
        let dg = ((mp.amplitude - a - h) - (mm.amplitude - a + h)) / (2.0 * h);
        let dtau = (mp.time - mm.time) / (2.0 * h);
        let s = (self.stretch)(t);
        Some((g - 0.5 * g * dg, (m0.time - 0.5 * dtau * g) * s))
    }

    /// The beats the next step may take at `time` (s), a whole number of
    /// cycles: up to the next row or the end (`target`, s), a twentieth of
    /// the amplitude's relaxation (`Q/π` periods), and 4096.
    fn step_beats(&self, time: f64, target: f64, amplitude: f64) -> u64 {
        let beat_estimate = std::f64::consts::PI / self.omega;
        let room = ((target - time) / beat_estimate).floor();
        // The relaxation with every loss counted (a drag law's at this
        // swing), as the viscous Q alone would overstate it.
        let relaxation_beats =
            (self.clock.effective_q(amplitude) * (self.damping)(time) / std::f64::consts::PI * 2.0)
                .max(1.0);
        (room.min(relaxation_beats / 20.0).min(4096.0) as u64) / self.cycle * self.cycle
    }
}

/// The true time of `row` advanced by `dt` (s), as a compensated sum
/// of the half swings (`carry` holds what the sum has lost).
fn add_time(row: &mut Row, carry: &mut f64, dt: f64) {
    let y = dt - *carry;
    let t = row.time + y;
    *carry = (t - row.time) - y;
    row.time = t;
}

/// [`run`] with the pendulum's Q multiplied by `damping(t)` at each
/// moment (the gas around it changing with the pressure), held over a
/// beat like the drive.
pub fn run_with_damping(
    clock: &Clock,
    drive: &dyn Fn(f64) -> f64,
    stretch: &dyn Fn(f64) -> f64,
    damping: &dyn Fn(f64) -> f64,
    options: &LongRun,
    sink: &mut dyn FnMut(&Row) -> bool,
) -> Finish {
    let escapement = clock.escapement.as_ref();
    let stepper = Stepper {
        clock,
        drive,
        stretch,
        damping,
        omega: clock.pendulum.natural_angular_frequency(),
        nominal_beat: 0.5 * options.nominal_period,
        cycle: escapement.cycle(),
        shift: !escapement.symmetric(),
    };
    let (omega, cycle) = (stepper.omega, stepper.cycle);
    let mut row = Row {
        time: 0.0,
        beats: 0,
        amplitude: options.amplitude,
        rate: 0.0,
        time_error: 0.0,
        drive: drive(0.0),
    };
    let mut finish = Finish {
        last: row,
        single_steps: 0,
        multi_steps: 0,
        stopped: false,
        ending: Ending::Duration,
    };
    let mut carry = 0.0;
    // The rate at the start: over the escapement's first whole cycle.
    let mut recent = stepper.first_cycle(row.amplitude, row.drive);
    if recent.iter().all(|&s| s > 0.0) {
        row.rate = stepper.rate_of(recent.iter().sum::<f64>() / cycle as f64);
    }
    if !sink(&row) {
        finish.stopped = true;
        finish.ending = Ending::Sink;
        return finish;
    }
    let mut next_row = options.every.unwrap_or(0.0);
    let end = |finish: &mut Finish, ending: Ending| {
        finish.stopped = true;
        finish.ending = ending;
    };
    // A half swing the map cannot make went over the top when the swing
    // or the drive had grown, else it stopped short of the unlocking.
    let drive_at_start = drive(0.0);
    let failed = |a: f64, d: f64| {
        if a > options.amplitude || d > drive_at_start {
            Ending::OverTheTop
        } else {
            Ending::PendulumStopped
        }
    };
    while row.time < options.duration {
        let d = drive(row.time);
        let s = stretch(row.time);
        if !(s > 0.5 && s.is_finite()) {
            // A factor past 2 or below 1/2 is a rate change of a day per
            // day: no clock; the schedule is wrong.
            end(&mut finish, Ending::RateOutOfRange);
            break;
        }
        // Beats until the next row (or the end).
        let target = match options.every {
            Some(_) => next_row.min(options.duration),
            None => options.duration,
        };
        let step_beats = stepper.step_beats(row.time, target, row.amplitude);
        if options.every.is_some() && cycle <= MULTI_STEP_CYCLE && step_beats >= 16 {
            // Many beats at once: RK4 on the modified equation of the map
            // of one whole cycle of the escapement.
            let n = (step_beats / cycle) as f64;
            let (a, t) = (row.amplitude, row.time);
            let (da, dt, last_cycle) = match rk4_cycles(&|a, t| stepper.flow(a, t), a, t, n, omega)
            {
                Ok(step) => step,
                Err(at) => {
                    end(&mut finish, failed(a, drive(at)));
                    break;
                }
            };
            row.amplitude = a + da;
            add_time(&mut row, &mut carry, dt);
            row.beats += step_beats;
            row.rate = stepper.rate_of(last_cycle / omega / cycle as f64);
            finish.multi_steps += 1;
        } else {
            let beat = row.beats % cycle;
            let Some(h) = stepper.half_swing(row.amplitude, beat, d, row.time, stepper.shift)
            else {
                end(&mut finish, failed(row.amplitude, d));
                break;
            };
            let seconds = h.time * stretch(row.time) / omega;
            row.amplitude = h.amplitude;
            add_time(&mut row, &mut carry, seconds);
            row.beats += 1;
            // The rate over the last whole cycle of the escapement (its
            // beats differ when it is out of beat, or a free pendulum's
            // impulse falls on one of them).
            recent[beat as usize] = seconds;
            row.rate = stepper.rate_of(recent.iter().sum::<f64>() / cycle as f64);
            finish.single_steps += 1;
        }
        row.drive = d;
        row.time_error = row.beats as f64 * stepper.nominal_beat - row.time;
        if row.amplitude < escapement.unlocking_amplitude() {
            end(&mut finish, Ending::PendulumStopped);
            break;
        }
        let due = match options.every {
            None => true,
            Some(e) => row_due(e, &mut next_row, row.time, options.duration),
        };
        if due && !sink(&row) {
            end(&mut finish, Ending::Sink);
            break;
        }
    }
    finish.last = row;
    finish
}
