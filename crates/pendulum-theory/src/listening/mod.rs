//! Listening to a clock: the times of its ticks in a sound recording, and
//! a synthetic recording with known truth to check that against.
//!
//! * [`filter`]: the band-pass (second-order sections after the RBJ audio
//!   cookbook) that keeps the ticks and drops hum and hiss.
//! * [`detect`]: the envelope, the beat period from its autocorrelation,
//!   and each tick's onset to a fraction of a sample (coarse onsets on the
//!   envelope, then cross-correlation with the median tick and tock).
//! * [`windows`]: the recording over time, in windows of a given length.
//! * [`live`]: listening as the sound comes, with bounded memory.
//! * [`synth`]: ticks as a few decaying resonances, the drop sound after
//!   them, room echoes, mains hum, noise and missing ticks, with the true
//!   tick times.
//!
//! The analysis of the tick times (rate, beat error, Allan deviation) is
//! [`crate::fitting::beats`], the same as for a timer's log.

use crate::error::{InputError, Problem, Quantity};

/// The beats listening finds, s: from 0.05 to 2 s apart (72,000 to 1,800
/// beats an hour), the search range of [`detect::beat_period`].
pub const BEAT_RANGE_S: (f64, f64) = (0.05, 2.0);

/// Checks a clock's nominal period `period` (s) against the beats
/// listening can find ([`BEAT_RANGE_S`], with 3% of slack for a clock far
/// off its nominal rate); the refusal is said of the beat rate when the
/// user gave one (`as_beat_rate`), else of the period.
pub fn check_nominal_period(period: f64, as_beat_rate: bool) -> Result<(), InputError> {
    let (shortest, longest) = (2.0 * BEAT_RANGE_S.0 / 1.03, 2.0 * BEAT_RANGE_S.1 * 1.03);
    if (shortest..=longest).contains(&period) {
        return Ok(());
    }
    if period.is_nan() || period <= 0.0 {
        let quantity = if as_beat_rate {
            Quantity::BeatRate
        } else {
            Quantity::Period
        };
        return Err(InputError::new(quantity, period, Problem::NotPositive));
    }
    let per_hour = |t: f64| 7200.0 / t;
    let error = match (as_beat_rate, period < shortest) {
        (true, true) => InputError::new(
            Quantity::BeatRate,
            per_hour(period),
            Problem::AboveMaximum {
                maximum: per_hour(shortest).floor(),
            },
        ),
        (true, false) => InputError::new(
            Quantity::BeatRate,
            per_hour(period),
            Problem::BelowMinimum {
                minimum: per_hour(longest).ceil(),
            },
        ),
        (false, true) => InputError::new(
            Quantity::Period,
            period,
            Problem::BelowMinimum {
                minimum: (shortest * 1e3).ceil() / 1e3,
            },
        ),
        (false, false) => InputError::new(
            Quantity::Period,
            period,
            Problem::AboveMaximum {
                maximum: (longest * 1e2).floor() / 1e2,
            },
        ),
    };
    Err(error)
}

pub mod analysis;
pub mod channels;
pub mod detect;
mod doctor;
pub mod filter;
pub mod live;
pub mod quality;
pub mod synth;
pub mod windows;
