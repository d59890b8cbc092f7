//! The clock doctor's advice: a measured rate and beat error turned into
//! what a clockmaker does next, with its direction and its amount.
//!
//! * Regulation: the rate into the move of the bob and the turns of the
//!   rating nut, by [`crate::compound::regulate`] (the period's derivative
//!   in the length, exact for a simple pendulum, the design's own for a
//!   compound one). Given only the beat, the simple pendulum of that beat
//!   (`l = g (b/π)²` for a beat `b`, half the period), said as an
//!   assumption. The nut's direction is for the usual right-hand thread
//!   with the bob resting on the nut: seen from below, clockwise drives
//!   the nut up the rod and raises the bob.
//! * Setting in beat: the escapement's offset `δ` from the pendulum's rest
//!   that gives the measured beat error, from the model of
//!   [`crate::clock::escapement::OutOfBeat`] inverted: a harmonic swing
//!   of amplitude `A` whose beats fall at the lift's edges `δ ± h` (`h`
//!   half the lift angle) has the beat error
//!   `(asin((δ − h)/A) + asin((δ + h)/A)) / ω`, `ω = π / b`. The longer
//!   of the two intervals holds the swing to the side away from the
//!   offset, so the crutch goes towards the side the pendulum swings to in
//!   the longer gap: the side on which, swung by hand from rest, it ticks
//!   soonest. The harmonic swing is exact for a balance and within 0.3% in
//!   `δ` for a pendulum swinging up to 15° (the period's own change).
//!
//! Each piece of advice is an [`Advice`] with a stable `code`, its figures
//! with units in their names, and a sentence in the words a clockmaker
//! acts on ([`Advice::sentence`]).

use crate::analysis::{require_finite, Refusal};
use crate::compound::regulate::{regulate, Nut, Regulated};
use crate::error::format_significant;
use crate::oscillator::Oscillator;
use serde::Serialize;
use std::f64::consts::PI;

/// A pendulum's swing (either side) taken when none is measured or given,
/// rad: 2.5°, a long-case or regulator clock's usual swing (a verge's is
/// larger). The amount to set in beat scales with it and says so.
pub const ASSUMED_PENDULUM_AMPLITUDE_RAD: f64 = 2.5 * PI / 180.0;
/// A balance's swing taken when none is measured or given, rad: 270°, a
/// wristwatch lying dial up at full wind.
pub const ASSUMED_BALANCE_AMPLITUDE_RAD: f64 = 270.0 * PI / 180.0;
/// A pendulum clock's beat error worth setting, as a fraction of its beat:
/// 1% (ticks split 51/49, the least most ears hear).
pub const PENDULUM_BEAT_ERROR_FRACTION: f64 = 0.01;
/// A watch's beat error worth setting, s: 0.6 ms, the limit a
/// timegrapher's reading of a serviced movement is commonly held to.
pub const BALANCE_BEAT_ERROR_S: f64 = 0.6e-3;
/// A rate is advised on when it lies this many standard errors from zero.
pub const RATE_SIGNIFICANCE: f64 = 2.0;

/// What the user knows of the clock, beyond what was measured.
#[derive(Clone, Debug, Default)]
pub struct Known {
    /// The pendulum (a length or a design); else the simple pendulum of
    /// the beat.
    pub pendulum: Option<Regulated>,
    /// The rating nut's thread.
    pub nut: Nut,
    /// From the pendulum's pivot to the crutch's pin, m, for the move at
    /// the pin.
    pub crutch_m: Option<f64>,
    /// The swing either side, rad, as the user saw it (before any
    /// measured from the sound).
    pub amplitude_rad: Option<f64>,
}

/// What the advice is drawn from: a clock's measured rate and beat, and
/// what is known of it.
#[derive(Clone, Debug, Default)]
pub struct Clockwork {
    /// The rate, s/day (positive: gaining); none when no nominal beat is
    /// known to measure it against.
    pub rate_s_per_day: Option<f64>,
    /// Its standard error, s/day (none: taken as exact, as a simulated
    /// clock's is).
    pub rate_standard_error_s_per_day: Option<f64>,
    /// The mean beat (a pendulum's half period), s.
    pub beat_s: f64,
    /// The beat error (half the difference of the two intervals), s.
    pub beat_error_s: Option<f64>,
    /// Its standard error, s.
    pub beat_error_standard_error_s: Option<f64>,
    /// What swings (default: by the beat rate).
    pub oscillator: Option<Oscillator>,
    /// The swing either side, rad, as measured.
    pub amplitude_rad: Option<f64>,
    /// The lift angle, rad (the whole of it: the edges lie half of it
    /// either side of the escapement's centre).
    pub lift_rad: Option<f64>,
    /// What the user knows.
    pub known: Known,
}

/// Which way the bob goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BobMove {
    /// Up: the clock gains (a losing clock).
    Raise,
    /// Down: the clock loses (a gaining clock).
    Lower,
}

/// Which way the nut turns, seen from below (right-hand thread).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum NutTurn {
    /// Clockwise seen from below: the nut climbs, the bob rises.
    Clockwise,
    /// Anticlockwise seen from below: the nut and the bob go down.
    Anticlockwise,
}

/// Which way a watch's regulator index goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Index {
    /// Towards S (−): a gaining watch.
    Slow,
    /// Towards F (+): a losing watch.
    Fast,
}

/// One thing to do, with its figures.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum Advice {
    /// Bring a pendulum clock to time by its bob and nut.
    Regulate {
        /// The rate corrected, s/day.
        rate_s_per_day: f64,
        /// Which way the bob goes.
        bob: BobMove,
        /// How far, m (positive).
        bob_shift_m: f64,
        /// The (equivalent) length the move is figured for, m.
        length_m: f64,
        /// Whether that length is the simple pendulum of the beat
        /// (nothing said of the pendulum).
        length_from_beat: bool,
        /// Turns of the nut (positive), when its thread is known.
        #[serde(skip_serializing_if = "Option::is_none")]
        nut_turns: Option<f64>,
        /// Divisions of the nut, when engraved.
        #[serde(skip_serializing_if = "Option::is_none")]
        nut_divisions: Option<f64>,
        /// Which way the nut turns, seen from below.
        nut_turn: NutTurn,
    },
    /// Bring a watch to time by its regulator's index.
    RegulateIndex {
        /// The rate corrected, s/day.
        rate_s_per_day: f64,
        /// Which way the index goes.
        towards: Index,
    },
    /// The rate lies within its error of zero: leave the nut.
    OnTime {
        /// The rate, s/day.
        rate_s_per_day: f64,
        /// Its standard error, s/day.
        rate_standard_error_s_per_day: f64,
    },
    /// Set a pendulum clock in beat by its crutch.
    SetInBeat {
        /// The beat error, ms.
        beat_error_ms: f64,
        /// The two intervals as % of the pair: the longer first.
        split_percent: [f64; 2],
        /// The escapement's offset from the pendulum's rest: the angle to
        /// move the crutch, degrees.
        crutch_deg: f64,
        /// The same at the bob, m (the offset times the length).
        bob_m: f64,
        /// The same at the crutch's pin, m, when its distance below the
        /// pivot is given.
        #[serde(skip_serializing_if = "Option::is_none")]
        crutch_pin_m: Option<f64>,
        /// The swing the offset is figured for, degrees.
        amplitude_deg: f64,
        /// Whether that swing is assumed (not measured or given).
        amplitude_assumed: bool,
        /// The lift angle used, degrees (0 when not given).
        lift_deg: f64,
        /// Whether the beat error is more than this swing and lift can
        /// give (the offset is then the largest that still ticks).
        beyond_the_swing: bool,
    },
    /// Set a watch in beat: turn its collet or stud carrier.
    SetInBeatBalance {
        /// The beat error, ms.
        beat_error_ms: f64,
        /// The offset, degrees of the balance.
        balance_deg: f64,
        /// The swing the offset is figured for, degrees.
        amplitude_deg: f64,
        /// Whether that swing is assumed.
        amplitude_assumed: bool,
    },
}

impl Advice {
    /// The stable code, as in the JSON.
    pub fn code(&self) -> &'static str {
        match self {
            Advice::Regulate { .. } => "regulate",
            Advice::RegulateIndex { .. } => "regulate_index",
            Advice::OnTime { .. } => "on_time",
            Advice::SetInBeat { .. } => "set_in_beat",
            Advice::SetInBeatBalance { .. } => "set_in_beat_balance",
        }
    }

    /// What to do, in a clockmaker's words.
    pub fn sentence(&self) -> String {
        let f = format_significant;
        match *self {
            Advice::Regulate {
                rate_s_per_day,
                bob,
                bob_shift_m,
                length_m,
                length_from_beat,
                nut_turns,
                nut_divisions,
                nut_turn,
            } => {
                let (verb, why) = match bob {
                    BobMove::Raise => ("raise", "losing"),
                    BobMove::Lower => ("lower", "gaining"),
                };
                let turn = match nut_turn {
                    NutTurn::Clockwise => "clockwise",
                    NutTurn::Anticlockwise => "anticlockwise",
                };
                let nut = match nut_turns {
                    Some(t) => {
                        let divisions = nut_divisions
                            .map_or(String::new(), |d| format!(" ({} divisions)", f(d, 3)));
                        format!(
                            ": {} turn{} of the nut{divisions}, {turn} seen from below",
                            f(t, 3),
                            if (t - 1.0).abs() < 5e-3 { "" } else { "s" }
                        )
                    }
                    None => {
                        format!(" (the nut {turn} seen from below; give its thread for the turns)")
                    }
                };
                let assumed = if length_from_beat {
                    format!(
                        "; figured for the simple pendulum of this beat, {} m long: give the length \
                         or the design if yours differs",
                        f(length_m, 4)
                    )
                } else {
                    String::new()
                };
                format!(
                    "{why} {} s/day: {verb} the bob {} mm{nut}{assumed}",
                    f(rate_s_per_day.abs(), 3),
                    f(bob_shift_m * 1e3, 3)
                )
            }
            Advice::RegulateIndex {
                rate_s_per_day,
                towards,
            } => format!(
                "{} {} s/day: move the regulator's index a little towards {}, then measure again",
                if rate_s_per_day > 0.0 {
                    "gaining"
                } else {
                    "losing"
                },
                f(rate_s_per_day.abs(), 3),
                match towards {
                    Index::Slow => "S (−, slow)",
                    Index::Fast => "F (+, fast)",
                }
            ),
            Advice::OnTime {
                rate_s_per_day,
                rate_standard_error_s_per_day,
            } => format!(
                "on time within the measurement ({} ± {} s/day): leave the nut",
                f(rate_s_per_day, 3),
                f(rate_standard_error_s_per_day, 2)
            ),
            Advice::SetInBeat {
                beat_error_ms,
                split_percent,
                crutch_deg,
                bob_m,
                crutch_pin_m,
                amplitude_deg,
                amplitude_assumed,
                lift_deg,
                beyond_the_swing,
            } => {
                let pin = crutch_pin_m.map_or(String::new(), |p| {
                    format!(", {} mm at the crutch's pin", f(p * 1e3, 3))
                });
                let swing = if amplitude_assumed {
                    format!(
                        "for a swing of {}° either side, assumed: give the amplitude, the amount \
                         goes with it",
                        f(amplitude_deg, 3)
                    )
                } else {
                    format!("for its swing of {}°", f(amplitude_deg, 3))
                };
                let lift = if lift_deg > 0.0 {
                    format!(" and a lift of {}°", f(lift_deg, 3))
                } else {
                    String::new()
                };
                let beyond = if beyond_the_swing {
                    "; the ticks are more uneven than this swing allows, so start with this and \
                     listen again"
                } else {
                    ""
                };
                format!(
                    "out of beat, {}/{} ({} ms): move the crutch towards the side the pendulum \
                     swings to in the longer gap (the side it ticks soonest on, swung by hand from \
                     rest), by {}° ({} mm at the bob{pin}), {swing}{lift}{beyond}",
                    f(split_percent[0], 3),
                    f(split_percent[1], 3),
                    f(beat_error_ms, 3),
                    f(crutch_deg, 2),
                    f(bob_m * 1e3, 3),
                )
            }
            Advice::SetInBeatBalance {
                beat_error_ms,
                balance_deg,
                amplitude_deg,
                amplitude_assumed,
            } => format!(
                "out of beat by {} ms: turn the collet or the stud carrier {}° of the balance \
                 (for a swing of {}°{}), then measure again",
                f(beat_error_ms, 3),
                f(balance_deg, 2),
                f(amplitude_deg, 3),
                if amplitude_assumed { ", assumed" } else { "" }
            ),
        }
    }
}

/// The simple pendulum of a beat `beat` s (half its period), m:
/// `g (beat/π)²` at standard gravity.
pub fn length_of_beat(beat: f64) -> f64 {
    crate::STANDARD_GRAVITY * (beat / PI).powi(2)
}

/// The beat of a simple pendulum `length` m long (half its small-angle
/// period), s: `π √(l/g)` at standard gravity, [`length_of_beat`]'s
/// inverse.
pub fn beat_of_length(length: f64) -> f64 {
    PI * (length / crate::STANDARD_GRAVITY).sqrt()
}

/// The simple pendulum beating `bph` times an hour, m, for regulation
/// given the beat alone: refused above
/// [`crate::oscillator::BALANCE_ABOVE_BPH`] (a balance's beat,
/// regulated by its index) and where the pendulum would be longer than
/// [`crate::pendulum::LONGEST_CLOCK_PENDULUM_M`].
pub fn length_for_bph(bph: f64) -> Result<f64, Refusal> {
    let bph = require_finite("bph", bph)?;
    let top = crate::oscillator::BALANCE_ABOVE_BPH;
    let longest = crate::pendulum::LONGEST_CLOCK_PENDULUM_M;
    let slowest = 3600.0 / (PI * (longest / crate::STANDARD_GRAVITY).sqrt());
    if bph > top {
        return Err(Refusal::field(
            "bph",
            format!(
                "must be at most {top} for a pendulum (a faster beat is a balance's, set by its regulator's index), got {}",
                format_significant(bph, 6)
            ),
        ));
    }
    if bph < slowest {
        return Err(Refusal::field(
            "bph",
            format!(
                "must be at least {} (a pendulum of {longest} m), got {}",
                format_significant(slowest.ceil(), 4),
                format_significant(bph, 6)
            ),
        ));
    }
    Ok(length_of_beat(3600.0 / bph))
}

/// The escapement's offset from rest, rad, that gives a beat error `be`
/// s to a harmonic swing of amplitude `a` rad and angular frequency
/// `omega`, its beats at the lift's edges `δ ± h`: the root of
/// `asin((δ − h)/A) + asin((δ + h)/A) = ω be`, increasing in `δ`, by
/// bisection to 1e-15 of `A`. The second value says the beat error is
/// beyond what the swing gives (the offset is then its largest, `A − h`).
pub fn beat_offset(be: f64, a: f64, h: f64, omega: f64) -> (f64, bool) {
    let target = omega * be.abs();
    let f = |d: f64| ((d - h) / a).clamp(-1.0, 1.0).asin() + ((d + h) / a).clamp(-1.0, 1.0).asin();
    let top = (a - h).max(0.0);
    if f(top) <= target {
        return (top, true);
    }
    let (mut lo, mut hi) = (0.0, top);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-15 * a {
            break;
        }
    }
    (0.5 * (lo + hi), false)
}

/// Checks what the user said of the clock before anything is measured:
/// the crutch's distance positive, the swing above 0 and at most 180°,
/// the nut's thread and the design's part as [`regulate`] takes them.
pub fn check(known: &Known) -> Result<(), Refusal> {
    if let Some(c) = known.crutch_m {
        if !(c.is_finite() && c > 0.0) {
            return Err(Refusal::field(
                "crutch",
                format!("must be positive, got {} m", format_significant(c, 6)),
            ));
        }
    }
    if let Some(a) = known.amplitude_rad {
        if !(a.is_finite() && a > 0.0 && a <= PI) {
            return Err(Refusal::field(
                "amplitude",
                format!(
                    "must lie above 0° and at most 180°, got {}°",
                    format_significant(a.to_degrees(), 6)
                ),
            ));
        }
    }
    let pendulum = known.pendulum.clone().unwrap_or(Regulated::Length(1.0));
    let length = regulate(&pendulum, 0.0, known.nut, None)?.equivalent_length_m;
    if let (Some(c), Some(_)) = (known.crutch_m, &known.pendulum) {
        if c > length {
            return Err(Refusal::field(
                "crutch",
                format!(
                    "the crutch's pin must lie above the pendulum's end ({} m), got {} m",
                    format_significant(length, 5),
                    format_significant(c, 6)
                ),
            ));
        }
    }
    Ok(())
}

/// The advice for `clock`: how to bring it to time and, when its beat
/// error is worth it, how to set it in beat. Refused where the figures it
/// needs are not finite or the regulation cannot be figured (a rate of a
/// day a day, a nut thread out of range).
pub fn advise(clock: &Clockwork) -> Result<Vec<Advice>, Refusal> {
    let beat = require_finite("beat", clock.beat_s)?;
    if beat <= 0.0 {
        return Err(Refusal::field("beat", "must be positive"));
    }
    check(&clock.known)?;
    let oscillator = clock.oscillator.unwrap_or(Oscillator::of_beat(beat));
    let mut advice = Vec::new();
    let rate = match clock.rate_s_per_day {
        Some(r) => Some(require_finite("rate", r)?),
        None => None,
    };
    let se = clock
        .rate_standard_error_s_per_day
        .filter(|s| s.is_finite());
    if let Some(rate) = rate {
        advice.extend(regulation(clock, oscillator, beat, rate, se)?);
    }
    if let Some(be) = clock.beat_error_s.filter(|b| b.is_finite() && *b > 0.0) {
        let be_se = clock
            .beat_error_standard_error_s
            .filter(|s| s.is_finite())
            .unwrap_or(0.0);
        if worth_setting(oscillator, beat, be, be_se) {
            advice.push(set_in_beat(clock, oscillator, beat, be));
        }
    }
    Ok(advice)
}

/// Whether a beat error `be` s (standard error `be_se` s) of `oscillator`
/// beating every `beat` s is worth setting: at least
/// [`PENDULUM_BEAT_ERROR_FRACTION`] of the beat (a pendulum) or
/// [`BALANCE_BEAT_ERROR_S`] (a balance), and three standard errors from
/// none.
pub fn worth_setting(oscillator: Oscillator, beat: f64, be: f64, be_se: f64) -> bool {
    be >= beat_error_worth_setting(oscillator, beat) && be > 3.0 * be_se
}

/// The split of a beat's two intervals, %, the longer first, for a beat
/// error `be` s (half their difference) of a mean beat `beat` s:
/// `50 (1 ± be/beat)`.
pub fn split_percent(be: f64, beat: f64) -> [f64; 2] {
    let half = 50.0 * be.abs() / beat;
    [50.0 + half, 50.0 - half]
}

/// The least beat error worth setting, s: see [`worth_setting`].
pub fn beat_error_worth_setting(oscillator: Oscillator, beat: f64) -> f64 {
    match oscillator {
        Oscillator::Pendulum => PENDULUM_BEAT_ERROR_FRACTION * beat,
        Oscillator::Balance => BALANCE_BEAT_ERROR_S,
    }
}

/// How to bring `clock`, gaining `rate` s/day (standard error `se`), to
/// time: leave it (within [`RATE_SIGNIFICANCE`] standard errors of zero),
/// its index (a balance), or its bob and nut (a pendulum).
fn regulation(
    clock: &Clockwork,
    oscillator: Oscillator,
    beat: f64,
    rate: f64,
    se: Option<f64>,
) -> Result<Option<Advice>, Refusal> {
    if se.is_some_and(|s| rate.abs() <= RATE_SIGNIFICANCE * s) {
        return Ok(Some(Advice::OnTime {
            rate_s_per_day: rate,
            rate_standard_error_s_per_day: se.unwrap_or(0.0),
        }));
    }
    if rate == 0.0 {
        return Ok(None);
    }
    if oscillator == Oscillator::Balance {
        return Ok(Some(Advice::RegulateIndex {
            rate_s_per_day: rate,
            towards: if rate > 0.0 { Index::Slow } else { Index::Fast },
        }));
    }
    let pendulum = clock
        .known
        .pendulum
        .clone()
        .unwrap_or(Regulated::Length(length_of_beat(beat)));
    let r = regulate(&pendulum, rate, clock.known.nut, None)?;
    let lower = r.shift_m >= 0.0;
    Ok(Some(Advice::Regulate {
        rate_s_per_day: rate,
        bob: if lower {
            BobMove::Lower
        } else {
            BobMove::Raise
        },
        bob_shift_m: r.shift_m.abs(),
        length_m: r.equivalent_length_m,
        length_from_beat: clock.known.pendulum.is_none(),
        nut_turns: r.nut_turns.map(f64::abs),
        nut_divisions: r.nut_divisions.map(f64::abs),
        nut_turn: if lower {
            NutTurn::Anticlockwise
        } else {
            NutTurn::Clockwise
        },
    }))
}

/// The advice to set `clock` in beat, its beat error `be` s.
fn set_in_beat(clock: &Clockwork, oscillator: Oscillator, beat: f64, be: f64) -> Advice {
    let measured = clock
        .known
        .amplitude_rad
        .or(clock.amplitude_rad)
        .filter(|a| a.is_finite() && *a > 0.0);
    let a = measured.unwrap_or(match oscillator {
        Oscillator::Pendulum => ASSUMED_PENDULUM_AMPLITUDE_RAD,
        Oscillator::Balance => ASSUMED_BALANCE_AMPLITUDE_RAD,
    });
    let omega = PI / beat;
    match oscillator {
        Oscillator::Balance => {
            let (offset, _) = beat_offset(be, a, 0.0, omega);
            Advice::SetInBeatBalance {
                beat_error_ms: be * 1e3,
                balance_deg: offset.to_degrees(),
                amplitude_deg: a.to_degrees(),
                amplitude_assumed: measured.is_none(),
            }
        }
        Oscillator::Pendulum => {
            let lift = clock
                .lift_rad
                .filter(|l| l.is_finite() && *l > 0.0 && 0.5 * l < a)
                .unwrap_or(0.0);
            let (offset, beyond) = beat_offset(be, a, 0.5 * lift, omega);
            let length = match &clock.known.pendulum {
                Some(Regulated::Length(l)) => *l,
                Some(Regulated::Design(d, _)) => d.pendulum.properties().equivalent_length,
                None => length_of_beat(beat),
            };
            Advice::SetInBeat {
                beat_error_ms: be * 1e3,
                split_percent: split_percent(be, beat),
                crutch_deg: offset.to_degrees(),
                bob_m: offset * length,
                crutch_pin_m: clock.known.crutch_m.map(|c| offset * c),
                amplitude_deg: a.to_degrees(),
                amplitude_assumed: measured.is_none(),
                lift_deg: lift.to_degrees(),
                beyond_the_swing: beyond,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The offset found gives back the beat error through the forward
    /// model of `out_of_beat` (its acos form), to 1e-12 s.
    #[test]
    fn the_offset_gives_back_the_beat_error() {
        for (a_deg, h_deg, be, beat) in [
            (2.5, 0.0, 0.01, 1.0),
            (2.5, 1.0, 0.02, 1.0),
            (4.0, 1.5, 0.005, 0.5),
            (10.0, 2.0, 0.03, 0.25),
        ] {
            let (a, h) = (f64::to_radians(a_deg), f64::to_radians(h_deg));
            let omega = PI / beat;
            let (d, beyond) = beat_offset(be, a, h, omega);
            assert!(!beyond);
            let forward = (((d - h) / a).acos() + ((d + h) / a).acos() - PI).abs() / omega;
            assert!((forward - be).abs() < 1e-12, "{forward} against {be}");
        }
    }
}
