//! A clock's long run judged before it starts: its duration, how often a
//! row is kept, how many rows and beats that makes and how long they take
//! to compute, and the schedules that drive it. The command line's
//! `clock --duration` and Python's `clock_run` both plan here, so neither
//! can start a run the other would refuse.

use super::long_run::MULTI_STEP_CYCLE;
use super::Clock;
use crate::analysis::{judge_work, require_finite, require_finite_sample, Refusal};
use crate::error::format_significant;

/// The longest run, s (about 300 years).
pub const MAX_DURATION_S: f64 = 1e10;
/// The most rows a run at every turning point may have (then a row
/// interval must be given).
pub const MAX_TURNING_POINT_ROWS: f64 = 1e8;
/// The largest rate change a schedule may give, s/day: a clock that gains
/// or loses a day per day is not running.
pub const MAX_RATE_S_PER_DAY: f64 = 86_400.0;
/// Computing time of one row of a long run, s (a week of turning points,
/// 604,800 rows, in 0.2 s, rounded up).
pub const SECONDS_PER_ROW: f64 = 0.5e-6;
/// Computing time of one step of many beats, s (1.2 µs measured, rounded
/// up).
pub const SECONDS_PER_MULTI_STEP: f64 = 1.5e-6;
/// Computing time of a half swing of an escapement that is not symmetric
/// (its time shift is Airy's integral, by quadrature), s: one by one (a
/// week of a recoil clock's turning points, 1.2 million, in 2.6 s), and
/// per beat of its cycle in a step of many beats (a year of a recoil clock
/// at a row a day in 1.7 s, 99,000 steps; out of beat, two beats a
/// cycle, 4.4 s), rounded up.
pub const SECONDS_PER_SHIFTED_ROW: f64 = 2.5e-6;
/// See [`SECONDS_PER_SHIFTED_ROW`].
pub const SECONDS_PER_SHIFTED_MULTI_STEP: f64 = 2.5e-5;
/// The factor a drag law puts on a half swing's computing time (its
/// energy over the half swing, from a table: a year of a seconds clock
/// with 3/2-power drag at a row a day in 0.46 s against 0.13 s without,
/// 3.6 times; a week of its turning points 1.6 times), rounded up.
pub const DRAG_COST_FACTOR: f64 = 4.0;

/// A long run's size, judged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunPlan {
    /// Rows the run will give.
    pub rows: f64,
    /// Beats it steps through.
    pub beats: f64,
    /// Estimated computing time, s.
    pub seconds: f64,
}

/// Plans a run of `clock`, whose steady period is `period` (s) at the
/// swing `amplitude` (rad), for `duration` s with a row every `every` s
/// (else at every turning point); refuses what cannot run, and what
/// would take too long unless `force`.
pub fn plan_run(
    clock: &Clock,
    period: f64,
    amplitude: f64,
    duration: f64,
    every: Option<f64>,
    force: bool,
) -> Result<RunPlan, Refusal> {
    let duration = require_finite("duration", duration)?;
    if duration <= 0.0 || duration > MAX_DURATION_S {
        return Err(Refusal::field(
            "duration",
            format!(
                "must lie between 0 and 300 years, got {} s",
                format_significant(duration, 6)
            ),
        ));
    }
    if let Some(e) = every {
        if require_finite("every", e)? < period {
            return Err(Refusal::field(
                "every",
                format!(
                    "must be at least a period ({} s), got {} s",
                    format_significant(period, 6),
                    format_significant(e, 6)
                ),
            ));
        }
    } else if 2.0 * duration / period > MAX_TURNING_POINT_ROWS {
        return Err(Refusal::field(
            "duration",
            "every turning point of so long a run is more than 10^8 rows: give a row interval \
             (every)",
        ));
    }
    // The rows, and the beats stepped between them (many at a time, up to
    // 4096 or a twentieth of the relaxation, when rows are sparse and the
    // escapement's cycle is one beat or two (out of beat); one by one
    // otherwise). Measured: a
    // week of every turning point in 0.2 s; ten years of a row a day at
    // Q = 10^4 (3.2e8 beats) in 1.2 s.
    let rows = duration / every.unwrap_or(0.5 * period);
    let beats = duration / (0.5 * period);
    let per_step = (clock.effective_q(amplitude) / (10.0 * std::f64::consts::PI)).min(4096.0);
    let cycle = clock.escapement.cycle();
    let (per_row, per_multi_step) = if clock.escapement.symmetric() {
        (SECONDS_PER_ROW, SECONDS_PER_MULTI_STEP)
    } else {
        (SECONDS_PER_SHIFTED_ROW, SECONDS_PER_SHIFTED_MULTI_STEP)
    };
    let drag = if clock.drag.is_empty() {
        1.0
    } else {
        DRAG_COST_FACTOR
    };
    let (per_row, per_multi_step) = (per_row * drag, per_multi_step * drag);
    let stepping = if every.is_some() && cycle <= MULTI_STEP_CYCLE && per_step >= 16.0 {
        beats / per_step * per_multi_step * cycle as f64
    } else {
        beats * per_row
    };
    let seconds = rows * SECONDS_PER_ROW + stepping;
    judge_work(
        "duration",
        format!(
            "{} beats, {} rows",
            format_significant(beats, 3),
            format_significant(rows, 3)
        ),
        seconds,
        force,
    )?;
    Ok(RunPlan {
        rows,
        beats,
        seconds,
    })
}

/// Checks a schedule `field` of `values` at `times` (s): one of each,
/// times finite and increasing, values finite and within `range`
/// (described as `what`); a refusal names the sample at fault.
pub fn check_schedule(
    field: &'static str,
    times: &[f64],
    values: &[f64],
    range: std::ops::RangeInclusive<f64>,
    what: &str,
) -> Result<(), Refusal> {
    if times.len() != values.len() {
        return Err(Refusal::field(
            field,
            format!(
                "{} times and {} values: give one of each",
                times.len(),
                values.len()
            ),
        ));
    }
    for (i, (&t, &v)) in times.iter().zip(values).enumerate() {
        // A time that is not a number: the sentence of the file reader's
        // own check, so a file and an array are refused alike.
        if !t.is_finite() {
            return Err(Refusal::sample(
                field,
                i,
                format!(
                    "must be a finite number, got {}",
                    if t.is_nan() {
                        "a value that is not a number"
                    } else {
                        "an infinite value"
                    }
                ),
            ));
        }
        if i > 0 && t <= times[i - 1] {
            return Err(Refusal::sample(
                field,
                i,
                "its time must be after the one before (sort by time)",
            ));
        }
        require_finite_sample(field, i, v)?;
        if !range.contains(&v) {
            return Err(Refusal::sample(
                field,
                i,
                format!("must be {what}, got {}", format_significant(v, 6)),
            ));
        }
    }
    Ok(())
}

/// Checks a rate schedule, s/day at times s ([`check_schedule`]'s
/// checks): every rate a change within a day per day, both ends left out.
/// At -86,400 s/day the clock has stopped (its beat lasts for ever, and a
/// run towards it never ends); at +86,400 it goes twice as fast.
pub fn check_rate_schedule(times: &[f64], values: &[f64]) -> Result<(), Refusal> {
    check_schedule(
        "rate_schedule",
        times,
        values,
        f64::MIN..=f64::MAX,
        "a number",
    )?;
    let max = MAX_RATE_S_PER_DAY;
    if let Some(i) = values.iter().position(|v| v.abs() >= max) {
        let why = if values[i] < 0.0 {
            format!("above -{max} s/day: a clock that loses a day a day has stopped")
        } else {
            format!("below {max} s/day: a clock that gains a day a day goes twice as fast")
        };
        return Err(Refusal::sample(
            "rate_schedule",
            i,
            format!(
                "must be a rate change within a day per day, {why}; got {} s/day",
                format_significant(values[i], 6)
            ),
        ));
    }
    Ok(())
}
