//! The clock doctor's findings: what a recording or a beat log shows,
//! each with its evidence (the figures, named with their units), what it
//! means, and what to do.
//!
//! The findings are drawn by each analysis from what it measured (for a
//! recording, [`crate::listening::analysis::listen`]); this module holds
//! their type, their thresholds and their words, and the two tests of the
//! beat times that are not a single figure: the swing's trend from the
//! drop's time ([`arc_trend`]) and a wheel's periodic error
//! ([`crate::fitting::periodic`]).

use crate::error::format_significant;
use serde::Serialize;

/// A swing that changes by less than this over the recording, %, is not
/// said to fall (a clock's arc breathes by a percent with the weather).
pub const ARC_FALL_PERCENT: f64 = 2.0;
/// The swing's trend must stand this many standard errors from none.
pub const ARC_SIGMA: f64 = 5.0;
/// Fewest groups of drops the trend is drawn from.
pub const ARC_GROUPS: usize = 6;
/// A periodic error smaller than this is not said, ms: it moves no rate
/// that matters, and the detector's own sub-sample errors (a sample is
/// 23 µs at 44.1 kHz) repeat at beat-to-sample aliasing periods at a few
/// µs, which clean recordings show at the false-alarm level.
pub const PERIODIC_SMALLEST_MS: f64 = 0.02;
/// A recording whose ticks stand less than this over the floor is noisy,
/// dB (the tracker's own level: ticks are still followed, less surely).
pub const NOISY_DB: f64 = 12.0;
/// A recording missing more than this share of its beats (outside what
/// was cut) is noisy, %.
pub const NOISY_MISSED_PERCENT: f64 = 10.0;
/// Clipped: runs of samples at full scale in more than this share of the
/// beats, %.
pub const CLIPPED_PERCENT: f64 = 1.0;
/// Hum is said when its amplitude reaches this fraction of the loudest
/// sound's (−10 dB).
pub const HUM_FRACTION: f64 = 0.3;

/// One thing a recording shows.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum Finding {
    /// The two gaps of the beat are unequal past what is worth setting.
    OutOfBeat {
        /// The beat error, ms.
        beat_error_ms: f64,
        /// The two gaps as % of the pair, the longer first.
        split_percent: [f64; 2],
        /// What is worth setting, ms.
        limit_ms: f64,
    },
    /// The ticks run early and late by a repeating amount: a wheel.
    PeriodicError {
        /// The period, s.
        period_s: f64,
        /// The period, beats.
        period_beats: f64,
        /// How early and late at most, ms.
        amplitude_ms: f64,
        /// The escape wheel's teeth, when the clock's usual train turns it
        /// once a period ([`usual_escape_wheel`]).
        #[serde(skip_serializing_if = "Option::is_none")]
        escape_teeth: Option<u32>,
    },
    /// The swing falls over the recording (the drop comes later after
    /// each unlocking).
    ArcFalls {
        /// The drop's time after the unlocking at the start, ms.
        drop_first_ms: f64,
        /// The same at the end, ms.
        drop_last_ms: f64,
        /// The swing's change over the recording, % (negative).
        change_percent: f64,
        /// Over, s.
        over_s: f64,
        /// When the swing, falling at this pace, would reach the lift and
        /// the clock stop, h from the end.
        stops_in_h: f64,
    },
    /// The rate wanders from window to window more than its error allows.
    RateWanders {
        /// The windows' scatter over their standard errors.
        ratio: f64,
        /// The windows' length, s.
        every_s: f64,
    },
    /// The ticks barely stand out: the figures are less sure.
    Noisy {
        /// The ticks over the floor, dB.
        snr_db: f64,
        /// The beats missed, % (outside what was cut).
        missed_percent: f64,
    },
    /// The recording is clipped: the loudest sounds hit full scale.
    Clipped {
        /// The beats with samples at full scale, %.
        clipped_percent: f64,
    },
    /// Mains hum is strong.
    Hum {
        /// Its frequency, Hz (50 or 60).
        hum_hz: f64,
        /// Its amplitude against the loudest sound's, dB.
        hum_db: f64,
    },
}

impl Finding {
    /// The stable code, as in the JSON.
    pub fn code(&self) -> &'static str {
        match self {
            Finding::OutOfBeat { .. } => "out_of_beat",
            Finding::PeriodicError { .. } => "periodic_error",
            Finding::ArcFalls { .. } => "arc_falls",
            Finding::RateWanders { .. } => "rate_wanders",
            Finding::Noisy { .. } => "noisy",
            Finding::Clipped { .. } => "clipped",
            Finding::Hum { .. } => "hum",
        }
    }

    /// What was seen, what it means and what to do, in plain words.
    pub fn sentence(&self) -> String {
        let f = format_significant;
        match *self {
            Finding::OutOfBeat {
                beat_error_ms,
                split_percent,
                limit_ms,
            } => format!(
                "out of beat: the ticks split {}/{} ({} ms, more than the {} ms worth setting); \
                 the escapement gives one swing less than the other, so the clock needs more \
                 power and stops sooner: set it in beat (below)",
                f(split_percent[0], 3),
                f(split_percent[1], 3),
                f(beat_error_ms, 2),
                f(limit_ms, 2)
            ),
            Finding::PeriodicError {
                period_s,
                period_beats,
                amplitude_ms,
                escape_teeth,
            } => {
                let wheel = match escape_teeth {
                    Some(teeth) => format!(
                        "the escape wheel, which in the usual train of a seconds clock has \
                         {teeth} teeth and turns once a minute"
                    ),
                    None => "a wheel that turns once a period".to_string(),
                };
                format!(
                    "a periodic error: the ticks come up to {} ms early and late, repeating every \
                     {} s ({} beats): {wheel}, out of round or with uneven teeth or pallets; it \
                     averages out over whole turns, so time over whole turns (--every a multiple \
                     of {} s) or the whole recording; if it grows, look at the wheel's pivots \
                     and teeth",
                    f(amplitude_ms, 2),
                    f(period_s, 3),
                    f(period_beats, 3),
                    f(period_s, 3)
                )
            }
            Finding::ArcFalls {
                drop_first_ms,
                drop_last_ms,
                change_percent,
                over_s,
                stops_in_h,
            } => format!(
                "the swing falls: {}% in {} s (the drop came {} ms after the unlocking at the \
                 start, {} ms at the end); at this pace it reaches the lift, and the clock stops, \
                 in about {} h: the weight or spring runs down, or friction grows (dry pivots, \
                 a rubbing hand or bob); wind it, then look for what takes the power",
                f(change_percent, 2),
                f(over_s, 3),
                f(drop_first_ms, 3),
                f(drop_last_ms, 3),
                f(stops_in_h, 2)
            ),
            Finding::RateWanders { ratio, every_s } => format!(
                "the rate wanders: windows of {} s scatter {} times what their errors allow; \
                 the clock is not yet steady (just set going, warming, or its power uneven) or \
                 something moved it: record again later, or trust the whole recording's rate \
                 less",
                f(every_s, 3),
                f(ratio, 2)
            ),
            Finding::Noisy {
                snr_db,
                missed_percent,
            } => format!(
                "the recording is noisy: the ticks stand {} dB over the floor and {}% of the \
                 beats were not heard; the figures are less sure: record nearer the movement \
                 (a microphone on the case or the seat board), in a quieter room",
                f(snr_db, 2),
                f(missed_percent, 2)
            ),
            Finding::Clipped { clipped_percent } => format!(
                "the recording is clipped: {}% of the beats reach full scale, which blunts \
                 their onsets; turn the recording level down",
                f(clipped_percent, 2)
            ),
            Finding::Hum { hum_hz, hum_db } => format!(
                "mains hum at {} Hz stands {} dB against the loudest sound; record on a battery, \
                 away from mains leads and transformers",
                f(hum_hz, 2),
                f(hum_db, 2)
            ),
        }
    }
}

/// The escape wheel a periodic error of `period_s` s names in a clock
/// beating every `beat_s` s, by the usual train: a seconds clock's (a
/// long-case or regulator) has 30 teeth and turns once a minute, carrying
/// the seconds hand. `None` for other beats (their trains vary) or other
/// periods (2% either way).
pub fn usual_escape_wheel(period_s: f64, beat_s: f64) -> Option<u32> {
    ((beat_s - 1.0).abs() < 0.01 && (period_s / 60.0 - 1.0).abs() < 0.02).then_some(30)
}

/// The swing's trend from the drop's time after each unlocking.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcTrend {
    /// The drop at the start and the end, s (the fitted line's).
    pub drop_first_s: f64,
    /// See `drop_first_s`.
    pub drop_last_s: f64,
    /// The swing's change from start to end, fraction.
    pub change: f64,
    /// The change over its standard error.
    pub sigma: f64,
    /// When the swing, falling on in a straight line, reaches the lift's
    /// half-angle `h` (the clock stops), s after the last drop; infinite
    /// when the swing does not fall.
    pub stops_after_s: f64,
}

/// The trend of the swing from `drops` (time s, the drop's time after
/// the unlocking s) at a beat of `beat` s: the drop crosses a lift of
/// half-angle `h` at a swing `A` in `Δ = 2 asin(h/A) b / π` (a harmonic
/// swing, `b` the beat), so `sin(π Δ / 2b) = h/A` is the lift over the
/// swing, whatever the lift. The drops are taken in [`ARC_GROUPS`] to 12
/// groups of equal time, each group's median (robust to a drop timed on
/// an echo); the least-squares line of `h/A` through the medians gives
/// the change and its standard error (from the scatter about the line).
/// `None` with fewer than [`ARC_GROUPS`] groups of 8 drops.
pub fn arc_trend(drops: &[(f64, f64)], beat: f64) -> Option<ArcTrend> {
    let groups = (drops.len() / 8).min(12);
    if groups < ARC_GROUPS || beat.is_nan() || beat <= 0.0 {
        return None;
    }
    let (start, end) = (drops.first()?.0, drops.last()?.0);
    if end.is_nan() || end <= start {
        return None;
    }
    let w = std::f64::consts::PI / (2.0 * beat);
    let mut points: Vec<(f64, f64)> = Vec::with_capacity(groups);
    for g in 0..groups {
        let (a, b) = (
            start + (end - start) * g as f64 / groups as f64,
            start + (end - start) * (g + 1) as f64 / groups as f64,
        );
        let mut here: Vec<f64> = drops
            .iter()
            .filter(|d| d.0 >= a && (d.0 < b || (g + 1 == groups && d.0 <= b)))
            .map(|d| d.1)
            .collect();
        if here.len() < 3 {
            continue;
        }
        here.sort_by(f64::total_cmp);
        let median = here[here.len() / 2];
        points.push((0.5 * (a + b), (w * median).sin()));
    }
    if points.len() < ARC_GROUPS {
        return None;
    }
    let n = points.len() as f64;
    let (mt, ms) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
    let (sxx, sxy) = points.iter().fold((0.0, 0.0), |(a, b), p| {
        (a + (p.0 - mt).powi(2), b + (p.0 - mt) * (p.1 - ms))
    });
    let slope = sxy / sxx;
    let rss: f64 = points
        .iter()
        .map(|p| (p.1 - ms - slope * (p.0 - mt)).powi(2))
        .sum();
    let slope_se = (rss / (n - 2.0) / sxx).sqrt();
    let at = |t: f64| ms + slope * (t - mt);
    let (first, last) = (at(start), at(end));
    if !(first > 0.0 && last > 0.0 && first < 1.0 && last < 1.0) {
        return None;
    }
    // The swing goes as 1 / (h/A).
    let change = first / last - 1.0;
    let sigma = if slope_se > 0.0 {
        slope.abs() / slope_se
    } else {
        f64::INFINITY
    };
    // The swing over the lift, A/h = 1/(h/A), carried on in a straight
    // line from the fitted start and end to 1 (the swing the lift's).
    let pace = (1.0 / last - 1.0 / first) / (end - start);
    let stops_after_s = if pace < 0.0 {
        (1.0 / last - 1.0) / -pace
    } else {
        f64::INFINITY
    };
    Some(ArcTrend {
        drop_first_s: first.asin() / w,
        drop_last_s: last.asin() / w,
        change,
        sigma,
        stops_after_s,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Drops of a seconds clock whose swing goes from 2.5° by `change` a
    /// second, lift 2° whole, with an alternating ±0.5 ms timing error.
    fn drops(change: f64) -> Vec<(f64, f64)> {
        let (h, beat) = (1.0_f64.to_radians(), 1.0);
        (0..300)
            .map(|k| {
                let t = k as f64;
                let a = 2.5_f64.to_radians() * (1.0 + change * t);
                let d = 2.0 * (h / a).asin() * beat / std::f64::consts::PI;
                (t, d + if k % 2 == 0 { 5e-4 } else { -5e-4 })
            })
            .collect()
    }

    #[test]
    fn a_falling_swing_is_measured_and_a_steady_one_is_not() {
        let fall = arc_trend(&drops(-1e-4), 1.0).expect("a trend");
        // 2.5° to 2.5 (1 − 0.0299)°: −2.99%.
        assert!((fall.change + 0.0299).abs() < 0.001, "{fall:?}");
        assert!(fall.sigma > ARC_SIGMA);
        // h/A = 0.4 / (1 − 1e-4 t): reaches 1 at t = 6000 s, 5701 s after
        // the last drop.
        assert!((fall.stops_after_s - 5701.0).abs() < 60.0, "{fall:?}");
        let steady = arc_trend(&drops(0.0), 1.0).expect("a trend");
        assert!(steady.change.abs() < 1e-3, "{steady:?}");
    }

    #[test]
    fn a_seconds_clock_names_its_escape_wheel() {
        assert_eq!(usual_escape_wheel(60.4, 1.0005), Some(30));
        assert_eq!(usual_escape_wheel(62.0, 1.0), None);
        assert_eq!(usual_escape_wheel(60.0, 0.5), None);
    }
}
