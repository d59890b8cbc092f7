//! The analysis of a beat log, as one call (or a stream of calls): one
//! time per beat in, what a timegrapher shows out ([`super::beats`]),
//! against the beat the clock is meant to keep, given or found among the
//! standard rates. The command line's `fit beats` and Python's
//! `fit_beats` are this call.

use super::beats::{AllanPoint, BeatAnalysis, BeatError, BeatStream};
use crate::analysis::{require_finite_sample, Refusal};
use crate::error::format_significant;
use crate::period::SECONDS_PER_DAY;
use crate::warning::Warn;
use serde::Serialize;

/// The ratios of nominal to measured beat taken: within the geometric
/// middle (√2) of the beat and its half or double, so that half or double
/// the beat is never read as a rate of ±43,200 s/day.
pub const NOMINAL_RATIO_RANGE: std::ops::RangeInclusive<f64> =
    std::f64::consts::FRAC_1_SQRT_2..=std::f64::consts::SQRT_2;

pub use crate::period::Nominal;

/// The Allan deviation at one averaging time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AllanRow {
    /// Averaging time, s.
    pub tau_s: f64,
    /// The same in beats.
    pub beats: usize,
    /// Fractional frequency deviation.
    pub deviation: f64,
    /// The same as a rate, s/day.
    pub deviation_s_per_day: f64,
}

/// A beat error that changes over the record by more than this part of
/// the beat (and [`DRIFT_SIGMA`] standard errors, and a fifth of the larger
/// end) is reported as sides drifting apart: 5 ms on a seconds pendulum,
/// 0.6 ms on a watch at 28,800 beats an hour.
pub const DRIFT_OF_BEAT: f64 = 0.005;
/// Standard errors a change of the beat error must exceed to be reported.
pub const DRIFT_SIGMA: f64 = 5.0;

/// The fastest beat a clock or watch has, s: 72,000 beats an hour (a
/// few chronographs beat faster; no pendulum comes near).
pub const FASTEST_BEAT_S: f64 = 0.05;
/// The slowest beat a pendulum has, s: Foucault's 67 m pendulum beats in
/// 8 s.
pub const SLOWEST_BEAT_S: f64 = 10.0;

/// A rate whose standard error exceeds this, s/day, is said to be
/// uncertain (a third of the 1 s/day a clockmaker regulates to: a figure
/// 1 s/day off is then three standard errors out).
pub const RATE_SE_WARN: f64 = 0.33;
/// A beat error whose standard error exceeds this, ms, is said to be
/// Ticks that repeat after some number of beats to within this, s (10
/// ns), repeat exactly: a loop (a clean generated recording at 30 dB
/// jitters by 0.6 µs, a real one by tens of µs).
pub const REPEATS_EXACTLY_S: f64 = 1e-8;

/// uncertain.
pub const BEAT_ERROR_SE_WARN: f64 = 0.15;

/// What a person must know about a beat analysis.
#[derive(Clone, Debug, PartialEq)]
pub enum BeatWarning {
    /// The mean beat is no clock's: faster than [`FASTEST_BEAT_S`] or
    /// slower than [`SLOWEST_BEAT_S`].
    BeatImplausible {
        /// The mean beat, s.
        beat_s: f64,
    },
    /// A gate log's intervals alternate short and long but were not paired
    /// as the two edges of each shadow.
    EdgesUnpaired {
        /// The median short interval, s.
        short: f64,
        /// The median long interval, s.
        long: f64,
    },
    /// The rate's standard error exceeds [`RATE_SE_WARN`]: too few beats,
    /// or too much scatter in their times (noise, a beat timed on two
    /// different sounds).
    RateUncertain {
        /// The standard error, s/day.
        se: f64,
    },
    /// The rates of a recording's windows scatter far more than their
    /// standard errors allow: the rate changed over the recording (a clock
    /// warming, its drive running down), and the mean describes no part.
    RateWanders {
        /// Their scatter over what their standard errors allow.
        ratio: f64,
    },
    /// A recording's tick and tock sound different: each is timed from its
    /// own onset, and the beat error takes in where each onset falls on
    /// its sound (a few tenths of a ms).
    SoundsDiffer,
    /// The ticks repeat after a number of beats to within
    /// [`REPEATS_EXACTLY_S`]: no clock's ticks do (a sound card's own
    /// quantisation alone jitters them by a tenth of a µs); the recording
    /// is a loop, or one stretch of sound copied.
    RepeatsExactly {
        /// The beats after which the ticks repeat.
        after_beats: u64,
        /// The scatter of the times between a tick and its repeat, s.
        spread_s: f64,
    },
    /// The beat error's standard error exceeds [`BEAT_ERROR_SE_WARN`].
    BeatErrorUncertain {
        /// The standard error, ms.
        se_ms: f64,
    },
    /// The amplitude from the lift is more than the oscillator swings in a
    /// running clock ([`crate::oscillator::Oscillator::largest_swing_rad`]):
    /// not given.
    AmplitudeImpossible {
        /// The amplitude the sound gave, degrees.
        amplitude_deg: f64,
        /// The largest a running clock's oscillator swings, degrees.
        largest_deg: f64,
        /// Whether the oscillator is a pendulum (else a balance).
        pendulum: bool,
    },
    /// The mean of a recording's windows' rates stands far from the whole
    /// recording's: a periodic error the windows share biases each alike.
    WindowsBiased {
        /// The windows' mean rate, s/day.
        windows_mean: f64,
        /// The whole recording's, s/day.
        whole: f64,
        /// Their difference in standard errors.
        sigma: f64,
        /// The windows' length, s.
        every_s: f64,
    },
    /// Sounds that are not ticks (a strike, a chime, handling, a voice)
    /// were cut out of the recording; the clock was followed across them.
    SoundsCut {
        /// The spans cut, s from the start: (from, to).
        spans: Vec<(f64, f64)>,
        /// The clock's beats inside them (not counted as missed).
        beats: usize,
    },
    /// The clock was not heard over a stretch of the recording (its ticks
    /// faded, it stopped, or it was drowned out), outside any span cut.
    ClockLost {
        /// Where no tick was heard, s from the start: (from, to).
        spans: Vec<(f64, f64)>,
    },
    /// The tick and tock intervals drift apart (or together) over the
    /// record: the mean beat error describes neither end.
    SidesDrift {
        /// Beat error at the start, ms.
        start_ms: f64,
        /// Beat error at the end, ms.
        end_ms: f64,
    },
}

impl crate::warning::Warn for BeatWarning {
    fn code(&self) -> &'static str {
        match self {
            BeatWarning::SidesDrift { .. } => "sides_drift",
            BeatWarning::SoundsCut { .. } => "sounds_cut",
            BeatWarning::ClockLost { .. } => "clock_lost",
            BeatWarning::AmplitudeImpossible { .. } => "amplitude_impossible",
            BeatWarning::WindowsBiased { .. } => "windows_biased",
            BeatWarning::BeatImplausible { .. } => "beat_implausible",
            BeatWarning::EdgesUnpaired { .. } => "edges_unpaired",
            BeatWarning::RateUncertain { .. } => "rate_uncertain",
            BeatWarning::SoundsDiffer => "sounds_differ",
            BeatWarning::RepeatsExactly { .. } => "repeats_exactly",
            BeatWarning::RateWanders { .. } => "rate_wanders",
            BeatWarning::BeatErrorUncertain { .. } => "beat_error_uncertain",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            BeatWarning::SidesDrift { .. } | BeatWarning::BeatErrorUncertain { .. } => {
                Some("beat_error_ms")
            }
            BeatWarning::SoundsCut { .. }
            | BeatWarning::EdgesUnpaired { .. }
            | BeatWarning::SoundsDiffer
            | BeatWarning::RepeatsExactly { .. } => None,
            BeatWarning::ClockLost { .. }
            | BeatWarning::WindowsBiased { .. }
            | BeatWarning::RateUncertain { .. }
            | BeatWarning::RateWanders { .. } => Some("rate_s_per_day"),
            BeatWarning::AmplitudeImpossible { .. } => Some("amplitude_deg"),
            BeatWarning::BeatImplausible { .. } => Some("beats_per_hour"),
        }
    }
}

/// Spans of a recording in words: "12.5-20 s, 240-262.5 s".
fn spans_text(spans: &[(f64, f64)]) -> String {
    spans
        .iter()
        .map(|&(a, b)| {
            format!(
                "{}-{} s",
                format_significant((a * 10.0).round() / 10.0, 6),
                format_significant((b * 10.0).round() / 10.0, 6)
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl std::fmt::Display for BeatWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BeatWarning::BeatImplausible { beat_s } if *beat_s < FASTEST_BEAT_S => write!(
                f,
                "a beat of {} s ({} an hour) is faster than any clock's or watch's (72,000 an \
                 hour at most): are the times a logger's samples rather than beats?",
                format_significant(*beat_s, 4),
                format_significant(3600.0 / beat_s, 6)
            ),
            BeatWarning::BeatImplausible { beat_s } => write!(
                f,
                "a beat of {} s is slower than any pendulum's (Foucault's 67 m swings in 8 s): \
                 are the times in another unit (minutes?) or of many swings?",
                format_significant(*beat_s, 4)
            ),
            BeatWarning::EdgesUnpaired { short, long } => write!(
                f,
                "the intervals alternate {} s and {} s: if the log holds both edges of each \
                 shadow (a large bob, a small swing), give the bob's diameter to pair them; \
                 else the clock is far out of beat",
                format_significant(*short, 4),
                format_significant(*long, 4)
            ),
            BeatWarning::RateUncertain { se } => write!(
                f,
                "the rate is uncertain by ±{} s/day (one standard error): too few beats or too \
                 much scatter in their times; record longer, nearer the clock, or in a quieter \
                 room",
                format_significant(*se, 2)
            ),
            BeatWarning::RateWanders { ratio } => write!(
                f,
                "the windows' rates scatter {} times what their standard errors allow: the rate \
                 changed over the recording (see the windows), and the whole recording's rate is \
                 only its mean",
                format_significant(*ratio, 2)
            ),
            BeatWarning::SoundsDiffer => write!(
                f,
                "the tick and the tock sound different (see the plot's two sounds): each is \
                 timed from its own start, and the beat error may be off by a few tenths of a \
                 ms where the two starts are taken differently"
            ),
            BeatWarning::RepeatsExactly {
                after_beats,
                spread_s,
            } => write!(
                f,
                "the ticks repeat every {after_beats} beats to within {} ns, which no clock's \
                 do: the recording is a loop, or one stretch of sound copied, and its rate is \
                 the loop's, not a clock's",
                format_significant(spread_s * 1e9, 2)
            ),
            BeatWarning::BeatErrorUncertain { se_ms } => write!(
                f,
                "the beat error is uncertain by ±{} ms (one standard error): too few beats or \
                 too much scatter in their times",
                format_significant(*se_ms, 2)
            ),
            BeatWarning::AmplitudeImpossible {
                amplitude_deg,
                largest_deg,
                pendulum,
            } => {
                write!(
                f,
                "the amplitude from the lift angle would be {}°, more than a running {} swings \
                 ({}°), so it is not given: {}",
                format_significant(*amplitude_deg, 3),
                if *pendulum { "pendulum clock" } else { "balance" },
                format_significant(*largest_deg, 3),
                if *pendulum {
                    "the lift angle is not the escapement's, or the two sounds timed are not the \
                     unlocking and the drop (in many long-case clocks the unlocking is too faint \
                     to hear)"
                } else {
                    "the lift angle is not the movement's, or the ticks were timed on another \
                     sound than the unlocking"
                }
            )
            }
            BeatWarning::SoundsCut { spans, beats } => write!(
                f,
                "sounds that are not ticks (a strike, a chime, the recorder handled, a voice) \
                 were cut out at {}: the clock was followed across, and its {beats} beats in \
                 them are not counted as missed",
                spans_text(spans)
            ),
            BeatWarning::ClockLost { spans } => write!(
                f,
                "the clock was not heard at {}: it stopped, its ticks faded, or something \
                 drowned them; the figures are from the rest of the recording",
                spans_text(spans)
            ),
            BeatWarning::WindowsBiased {
                windows_mean,
                whole,
                sigma,
                every_s,
            } => write!(
                f,
                "the windows' mean rate, {} s/day, is {} standard errors from the whole \
                 recording's {} s/day: a periodic error that repeats every {} s or a fraction of \
                 it (an escape wheel that turns once a minute) biases every window alike; trust \
                 the whole recording's rate, or cut windows that are not a multiple of the \
                 wheel's turn",
                format_significant(*windows_mean, 4),
                format_significant(*sigma, 2),
                format_significant(*whole, 4),
                format_significant(*every_s, 4)
            ),
            BeatWarning::SidesDrift { start_ms, end_ms } => write!(
                f,
                "the beat error goes from {} ms at the start to {} ms at the end: the ticks \
                 and tocks drift apart (a gate off the bob's centre as the swing changes, or a \
                 clock going out of beat); the mean beat error describes neither end",
                format_significant(*start_ms, 3),
                format_significant(*end_ms, 3)
            ),
        }
    }
}

crate::warning::serialize_as_warning!(BeatWarning);

/// Beats dropped and filled in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Repaired {
    /// Missed beats filled in.
    pub missed: usize,
    /// Doubled beats dropped.
    pub doubled: usize,
}

/// What a timegrapher shows, from a beat log.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Beats {
    /// Beats after repair.
    pub beats: usize,
    /// Mean beat, s.
    pub mean_beat_s: f64,
    /// Beats per hour at the mean beat.
    pub beats_per_hour: f64,
    /// The beat the rate is measured against, s.
    pub nominal_beat_s: Option<f64>,
    /// What keeps the nominal beat, when it is a standard rate
    /// ([`super::beats::STANDARD_RATES`]): "seconds pendulum, 0.994 m: …".
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nominal_kind: Option<&'static str>,
    /// Gain per day against it, s/day (positive: the clock gains).
    pub rate_s_per_day: Option<f64>,
    /// The rate's standard error, s/day (from the ticks' scatter about
    /// the line through them; null when too few to tell).
    pub rate_se_s_per_day: Option<f64>,
    /// Half the tick-tock difference, ms.
    pub beat_error_ms: f64,
    /// Its standard error, ms.
    pub beat_error_se_ms: Option<f64>,
    /// The same over the first 16 pairs of beats, ms.
    pub beat_error_start_ms: f64,
    /// The same over the last 16 pairs of beats, ms.
    pub beat_error_end_ms: f64,
    /// Spread of the intervals about their tick or tock mean, ms.
    pub jitter_ms: f64,
    /// What was repaired.
    pub repaired: Repaired,
    /// The overlapping Allan deviation of the rate.
    pub allan_deviation: Vec<AllanRow>,
    /// What a person must know about these figures.
    pub warnings: Vec<BeatWarning>,
    /// Their codes, in the same order (for programs).
    pub warning_codes: Vec<&'static str>,
    /// What to do: bring the clock to time, set it in beat
    /// ([`crate::advice`]), from these figures and what is known of the
    /// clock ([`Beats::advise`]).
    pub advice: Vec<crate::advice::Advice>,
}

impl Beats {
    /// Fills [`Beats::advice`] from these figures and `known`, with what
    /// swings, the measured swing (rad) and the lift angle (rad) when
    /// listening knows them. Refused when the regulation cannot be
    /// figured (a nut's thread out of range, a design's part not found).
    pub fn advise(
        &mut self,
        known: &crate::advice::Known,
        oscillator: Option<crate::oscillator::Oscillator>,
        amplitude_rad: Option<f64>,
        lift_rad: Option<f64>,
    ) -> Result<(), crate::analysis::Refusal> {
        self.advice = crate::advice::advise(&crate::advice::Clockwork {
            rate_s_per_day: self.rate_s_per_day,
            rate_standard_error_s_per_day: self.rate_se_s_per_day,
            beat_s: self.mean_beat_s,
            beat_error_s: Some(1e-3 * self.beat_error_ms),
            beat_error_standard_error_s: self.beat_error_se_ms.map(|s| 1e-3 * s),
            oscillator,
            amplitude_rad,
            lift_rad,
            known: known.clone(),
        })?;
        Ok(())
    }

    /// The result of an analysis of beat times.
    pub fn of(a: BeatAnalysis) -> Self {
        let change = (a.beat_error_end_ms - a.beat_error_start_ms).abs();
        let mut warnings: Vec<BeatWarning> = Vec::new();
        if !(FASTEST_BEAT_S..=SLOWEST_BEAT_S).contains(&a.mean_beat) {
            warnings.push(BeatWarning::BeatImplausible {
                beat_s: a.mean_beat,
            });
        }
        if a.rate_s_per_day.is_some()
            && a.rate_se_s_per_day.is_finite()
            && a.rate_se_s_per_day > RATE_SE_WARN
        {
            warnings.push(BeatWarning::RateUncertain {
                se: a.rate_se_s_per_day,
            });
        }
        if a.beat_error_se_ms.is_finite() && a.beat_error_se_ms > BEAT_ERROR_SE_WARN {
            warnings.push(BeatWarning::BeatErrorUncertain {
                se_ms: a.beat_error_se_ms,
            });
        }
        if a.beat_error_change_sigma > DRIFT_SIGMA
            && change > 1e3 * DRIFT_OF_BEAT * a.mean_beat
            && change > 0.2 * a.beat_error_start_ms.max(a.beat_error_end_ms)
        {
            warnings.push(BeatWarning::SidesDrift {
                start_ms: a.beat_error_start_ms,
                end_ms: a.beat_error_end_ms,
            });
        }
        let mut beats = Self {
            beats: a.beats,
            mean_beat_s: a.mean_beat,
            beats_per_hour: a.beats_per_hour,
            nominal_beat_s: a.nominal_beat,
            nominal_kind: a
                .nominal_beat
                .and_then(|b| super::beats::standard_rate_near(3600.0 / b))
                .filter(|r| {
                    (r.beats_per_hour * a.nominal_beat.unwrap_or(0.0) / 3600.0 - 1.0).abs() < 1e-9
                })
                .map(|r| r.kind),
            rate_s_per_day: a.rate_s_per_day,
            rate_se_s_per_day: a
                .rate_se_s_per_day
                .is_finite()
                .then_some(a.rate_se_s_per_day),
            beat_error_ms: a.beat_error_ms,
            beat_error_se_ms: a.beat_error_se_ms.is_finite().then_some(a.beat_error_se_ms),
            beat_error_start_ms: a.beat_error_start_ms,
            beat_error_end_ms: a.beat_error_end_ms,
            jitter_ms: a.jitter_ms,
            repaired: Repaired {
                missed: a.repaired.missed,
                doubled: a.repaired.doubled,
            },
            allan_deviation: a.allan_deviation.iter().map(allan_row).collect(),
            warning_codes: warnings.iter().map(BeatWarning::code).collect(),
            warnings,
            advice: Vec::new(),
        };
        // From the figures alone it cannot be refused (no thread, no
        // design): the rate and beat are finite and the beat positive.
        let _ = beats.advise(&crate::advice::Known::default(), None, None, None);
        beats
    }
}

/// One point of the Allan deviation, with its rate in s/day.
pub fn allan_row(p: &AllanPoint) -> AllanRow {
    AllanRow {
        tau_s: p.tau,
        beats: p.beats,
        deviation: p.deviation,
        deviation_s_per_day: SECONDS_PER_DAY * p.deviation,
    }
}

/// A beat log read one time at a time, in fixed memory.
pub struct BeatLog {
    stream: BeatStream,
    nominal: Option<(Nominal, f64)>,
    pushed: usize,
    previous: f64,
}

impl BeatLog {
    /// A log to be measured against `nominal` (else the nearest standard
    /// rate within 2%); the nominal value is checked now, before any time.
    pub fn new(nominal: Option<Nominal>) -> Result<Self, Refusal> {
        let nominal = nominal.map(|n| n.beat().map(|b| (n, b))).transpose()?;
        Ok(Self {
            stream: BeatStream::new(),
            nominal,
            pushed: 0,
            previous: f64::NEG_INFINITY,
        })
    }

    /// Adds the next beat's time, s.
    pub fn push(&mut self, t: f64) -> Result<(), Refusal> {
        let i = self.pushed;
        require_finite_sample("time", i, t)?;
        if t <= self.previous {
            let (now, before) = (
                format_significant(t, 12),
                format_significant(self.previous, 12),
            );
            return Err(Refusal::sample(
                "time",
                i,
                if t == self.previous {
                    format!("the time {now} repeats the one before it: a row written twice?")
                } else {
                    format!("the time {now} is not after the previous {before}; sort by time")
                },
            ));
        }
        self.previous = t;
        self.pushed += 1;
        self.stream
            .push(t)
            .map_err(|e| Refusal::sample("time", i, e.to_string()))
    }

    /// The analysis of every time pushed.
    pub fn finish(self) -> Result<Beats, Refusal> {
        let a = self
            .stream
            .finish(self.nominal.map(|(_, b)| b))
            .map_err(|e: BeatError| Refusal::data(e.to_string()))?;
        // A nominal beat far from the measured one is a typing error or
        // half or double the beat (the rate would be meaningless): refused
        // beyond the geometric middle between the beat and its double.
        if let Some((n, beat)) = self.nominal {
            check_nominal(n, beat, a.mean_beat)?;
        }
        Ok(Beats::of(a))
    }
}

/// Refuses a nominal beat (`beat` s, given as `nominal`) that is not the
/// `measured` one: beyond the geometric middle between the beat and its
/// half or double ([`NOMINAL_RATIO_RANGE`]), so that half or double the
/// beat is never read as a rate of ±43,200 s/day; the refusal says which
/// it looks like.
pub fn check_nominal(nominal: Nominal, beat: f64, measured: f64) -> Result<(), Refusal> {
    let ratio = beat / measured;
    if NOMINAL_RATIO_RANGE.contains(&ratio) {
        return Ok(());
    }
    let hint = if (ratio / 2.0 - 1.0).abs() < 0.1 {
        " (twice the measured beat: is the nominal rate half the clock's?)"
    } else if (ratio * 2.0 - 1.0).abs() < 0.1 {
        " (half the measured beat: is the nominal rate double the clock's?)"
    } else {
        ""
    };
    Err(Refusal::field(
        nominal.field(),
        format!(
            "a nominal beat of {} s is nowhere near the {} s measured{hint}",
            format_significant(beat, 6),
            format_significant(measured, 6)
        ),
    ))
}

/// Analyses beat times `time` (s) against `nominal`.
///
/// # Examples
///
/// ```
/// use pendulum_theory::fitting::beat_log::analyse;
/// use pendulum_theory::period::Nominal;
///
/// // Ten minutes of a seconds clock gaining 1 s a day (a beat of 1/(1 + 1/86400)
/// // s), every other tick 2 ms late: the intervals differ by 4 ms.
/// let beat = 1.0 / (1.0 + 1.0 / 86_400.0);
/// let time: Vec<f64> = (0..600)
///     .map(|k| k as f64 * beat + if k % 2 == 1 { 0.002 } else { 0.0 })
///     .collect();
/// let b = analyse(&time, Some(Nominal::BeatsPerHour(3600.0)))?;
/// assert!((b.rate_s_per_day.unwrap() - 1.0).abs() < 1e-6);
/// assert!((b.beat_error_ms - 2.0).abs() < 1e-6); // half the difference
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn analyse(time: &[f64], nominal: Option<Nominal>) -> Result<Beats, Refusal> {
    let mut log = BeatLog::new(nominal)?;
    for &t in time {
        log.push(t)?;
    }
    log.finish()
}
