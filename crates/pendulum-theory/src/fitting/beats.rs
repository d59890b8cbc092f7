//! A clock's rate from beat timestamps, as a beam-break or microphone timer
//! records them: the figures a timegrapher shows, for any beat rate from one
//! beat in ten seconds to twenty a second.
//!
//! * Gaps and doubles are repaired first, each side against its own
//!   interval: a record's intervals alternate (tick, tock), and out of beat
//!   (a clock, or a gate off the bob's centre) the two differ, up to one
//!   being a small part of the other. Each side's expected interval follows
//!   the record (smoothed over the last few beats, so a drifting beat error
//!   is followed); a pass is placed at the nearest of the expected next
//!   passes: at the last one (less than half the next interval after it) it
//!   is a doubled (spurious) beat and dropped, at the `k`-th it means
//!   `k - 1` missed beats, which are filled in at their expected places,
//!   up to [`MAX_FILLED`] of them. With the two sides equal this is the
//!   classic rule (half a beat, then the rounded number of beats). A pass
//!   at its own side's interval is never dropped, however short that is. A
//!   longer gap is a pause in the record, not missed beats: how many beats
//!   it held cannot be told from the times (a 28-hour pause at +4 s/day is
//!   4.6 beats off a whole count), so it is refused with its place, to split
//!   the record.
//! * The mean beat is the slope of the least-squares line of time against
//!   beat number, as timers compute it (robust to the jitter of single beats),
//!   with an intercept per side, so that a beat error neither tilts it nor,
//!   when the sides drift symmetrically apart about the turning points (a
//!   gate off centre as the swing decays), biases it.
//! * Beat error is half the difference between the mean "tick" and "tock"
//!   intervals (alternate beats), in ms, as timegraphers report it; taken
//!   also over the first and the last 16 pairs of beats, so that sides
//!   drifting apart are reported, not averaged away.
//! * Jitter is the standard deviation of the intervals about their own
//!   tick or tock mean.
//! * The Allan deviation of the rate (overlapping estimator, IEEE 1139) at
//!   averaging times of `2^k` beats up to 65,536, from the time error
//!   `x_n = t_n - n T_b`:
//!   `σ²(τ) = Σ (x_{i+2m} - 2x_{i+m} + x_i)² / (2 τ² (N - 2m))`, `τ = m T_b`.
//!
//! All of it runs on a stream ([`BeatStream`]) in fixed memory, so a log of
//! 10^7 beats needs no more than one of ten.

use super::median;

/// A beat rate clocks or watches are made for, with what keeps it and
/// where that is said.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StandardRate {
    /// Beats an hour.
    pub beats_per_hour: f64,
    /// What keeps it: for a pendulum, its length (a simple pendulum of
    /// that beat at standard gravity, by the small-angle law
    /// `L = g (T_b/π)²`) and the clocks that have one; for a balance, its
    /// frequency and the watches.
    pub kind: &'static str,
    /// Where the rate is said to be used.
    pub source: &'static str,
}

const PAGES: &str = "crownwatchblog.com/glossary/vibrations-per-hour; \
                     luxurious.whatsoever.hk/2008/04/beat-count.html; \
                     professionalwatches.com/glossary/frequency";

/// Beat rates clocks and watches are made for (issue 24's list), slowest
/// first; the nominal beat is taken from here when none is given. The
/// pendulum rates' lengths follow from the beat; the clocks named for
/// them are the usual ones of that length.
pub const STANDARD_RATES: [StandardRate; 22] = [
    StandardRate {
        beats_per_hour: 1800.0,
        kind: "2 s pendulum, 3.97 m: tower clocks (the Great Clock of Westminster)",
        source: "UK Parliament, How the Great Clock works: the pendulum beats every two seconds",
    },
    StandardRate {
        beats_per_hour: 2880.0,
        kind: "1.25 s pendulum, 1.55 m: turret clocks",
        source: "issue 24's list (the 1¼-second turret pendulum)",
    },
    StandardRate {
        beats_per_hour: 3600.0,
        kind: "seconds pendulum, 0.994 m: longcase clocks and regulators",
        source: "the seconds pendulum (seed section 1-6)",
    },
    StandardRate {
        beats_per_hour: 4800.0,
        kind: "0.75 s pendulum, 0.56 m: wall regulators",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 5400.0,
        kind: "2/3 s pendulum, 0.44 m: wall and bracket clocks",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 6000.0,
        kind: "0.6 s pendulum, 0.36 m: wall clocks",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 7200.0,
        kind: "half-seconds pendulum, 0.248 m: bracket and mantel clocks",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 8100.0,
        kind: "0.44 s pendulum, 0.196 m: mantel clocks",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 9000.0,
        kind: "0.4 s pendulum, 0.159 m: mantel and shelf clocks",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 10_800.0,
        kind: "1.5 Hz balance (or a 0.11 m pendulum): carriage and alarm clocks",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 12_000.0,
        kind: "1.67 Hz balance: clocks with a platform escapement",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 14_400.0,
        kind: "2 Hz balance: older pocket watches, alarm clocks",
        source: PAGES,
    },
    StandardRate {
        beats_per_hour: 16_200.0,
        kind: "2.25 Hz balance: older pocket watches",
        source: PAGES,
    },
    StandardRate {
        beats_per_hour: 17_280.0,
        kind: "2.4 Hz balance: pocket watches",
        source: "issue 24's list",
    },
    StandardRate {
        beats_per_hour: 18_000.0,
        kind: "2.5 Hz balance: pocket watches, early wristwatches",
        source: PAGES,
    },
    StandardRate {
        beats_per_hour: 19_800.0,
        kind: "2.75 Hz balance: wristwatches from the late 1940s",
        source: "watchtalkforums.info, Horology 101: b.p.h. & accuracy",
    },
    StandardRate {
        beats_per_hour: 21_600.0,
        kind: "3 Hz balance: wristwatches",
        source: PAGES,
    },
    StandardRate {
        beats_per_hour: 25_200.0,
        kind: "3.5 Hz balance: wristwatches (Omega's co-axial)",
        source: "watchtalkforums.info, Horology 101: b.p.h. & accuracy",
    },
    StandardRate {
        beats_per_hour: 28_800.0,
        kind: "4 Hz balance: most modern wristwatches",
        source: PAGES,
    },
    StandardRate {
        beats_per_hour: 36_000.0,
        kind: "5 Hz balance: high-beat wristwatches (Zenith El Primero, Grand Seiko)",
        source: PAGES,
    },
    StandardRate {
        beats_per_hour: 43_200.0,
        kind: "6 Hz balance: high-beat wristwatches",
        source: "professionalwatches.com/glossary/frequency",
    },
    StandardRate {
        beats_per_hour: 72_000.0,
        kind: "10 Hz balance: Breguet Type XXII",
        source: "professionalwatches.com/glossary/frequency; brooch-repair.com (Cal. 589F)",
    },
];

/// The beat rates of [`STANDARD_RATES`], beats per hour.
pub fn standard_beat_rates() -> impl Iterator<Item = f64> {
    STANDARD_RATES.iter().map(|r| r.beats_per_hour)
}

/// The standard rate nearest `beats_per_hour` within 2%, if any.
pub fn standard_rate_near(beats_per_hour: f64) -> Option<&'static StandardRate> {
    STANDARD_RATES
        .iter()
        .min_by(|a, b| {
            (a.beats_per_hour / beats_per_hour - 1.0)
                .abs()
                .total_cmp(&(b.beats_per_hour / beats_per_hour - 1.0).abs())
        })
        .filter(|r| (r.beats_per_hour / beats_per_hour - 1.0).abs() <= 0.02)
}

/// Beats dropped and filled in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Repairs {
    /// Missed beats filled in.
    pub missed: usize,
    /// Doubled beats dropped.
    pub doubled: usize,
}

/// The Allan deviation at one averaging time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AllanPoint {
    /// Averaging time, s.
    pub tau: f64,
    /// The same in beats.
    pub beats: usize,
    /// Fractional frequency deviation (multiply by 86400 for s/day).
    pub deviation: f64,
}

/// What a timegrapher would show.
#[derive(Clone, Debug, PartialEq)]
pub struct BeatAnalysis {
    /// Beats after repair.
    pub beats: usize,
    /// Mean beat, s.
    pub mean_beat: f64,
    /// `3600 / mean beat`.
    pub beats_per_hour: f64,
    /// The nominal beat the rate is measured against, s, if known.
    pub nominal_beat: Option<f64>,
    /// Gain per day against the nominal beat, s/day (positive: fast).
    pub rate_s_per_day: Option<f64>,
    /// The rate's standard error, s/day: the slope's of the least-squares
    /// line (one slope, an intercept a side) from the scatter about it
    /// (white timing noise; a clock whose rate wanders has more).
    pub rate_se_s_per_day: f64,
    /// Half the tick-tock difference, ms.
    pub beat_error_ms: f64,
    /// Its standard error, ms, from the scatter of each side's intervals.
    pub beat_error_se_ms: f64,
    /// The beat error over the record's first 16 pairs of beats (or its
    /// first half, if shorter), ms.
    pub beat_error_start_ms: f64,
    /// The same over the last 16 pairs, ms.
    pub beat_error_end_ms: f64,
    /// The change between the two in its standard errors (from the
    /// scatter at each end; 0 when too few beats to tell).
    pub beat_error_change_sigma: f64,
    /// Spread of the intervals about their tick or tock mean, ms.
    pub jitter_ms: f64,
    /// What was repaired.
    pub repaired: Repairs,
    /// Allan deviation at 1, 2, 4, … beats while at least 10 terms remain.
    pub allan_deviation: Vec<AllanPoint>,
}

/// Why beats could not be analysed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BeatError {
    /// Fewer than four beats.
    #[error("{0} beats are too few; at least 4 are needed")]
    TooFew(usize),
    /// Timestamps that do not increase.
    #[error("beat {index} at {time} s is not after the one before; sort the timestamps")]
    NotIncreasing {
        /// Index of the offending timestamp.
        index: usize,
        /// Its time, s.
        time: f64,
    },
    /// Beats too far apart or too close together for a clock (or times in
    /// the wrong unit).
    #[error(
        "the beats are {} s apart on average: no clock's beat (1 ms to an hour); are the times in seconds?",
        crate::error::format_significant(*mean_beat, 4)
    )]
    NotABeat {
        /// The mean interval, s.
        mean_beat: f64,
    },
    /// A pause in the record too long to fill with missed beats.
    #[error(
        "beat {index} at {} s comes {} s after the one before, about {} beats: \
         a pause in the record, not missed beats (at most 10 are filled in); \
         analyse the parts before and after it separately",
        crate::error::format_significant(*time, 12),
        crate::error::format_significant(*gap, 6),
        crate::error::format_significant(*beats, 4)
    )]
    Gap {
        /// Index of the timestamp after the gap.
        index: usize,
        /// Its time, s.
        time: f64,
        /// The gap, s.
        gap: f64,
        /// The gap in typical beats.
        beats: f64,
    },
}

/// The shortest mean beat a beat log may have, s: a watch at 36,000 beats
/// an hour beats every 0.1 s; a thousandth of a second leaves room.
pub const MIN_BEAT_S: f64 = 1e-3;
/// The longest mean beat, s: an hour (a turret clock's minute jump is a
/// minute; a log of anything slower is not beats).
pub const MAX_BEAT_S: f64 = 3600.0;

/// Analyses beat timestamps `times` (s); `nominal_beat` (s) is the beat the
/// clock is meant to have, else the nearest standard rate within 2%.
/// (The same as feeding them one by one to a [`BeatStream`].)
pub fn analyse_beats(times: &[f64], nominal_beat: Option<f64>) -> Result<BeatAnalysis, BeatError> {
    let mut stream = BeatStream::new();
    for &t in times {
        stream.push(t)?;
    }
    stream.finish(nominal_beat)
}

/// The most missed beats one gap may be filled with; a longer gap is
/// refused ([`BeatError::Gap`]).
pub const MAX_FILLED: usize = 10;

/// Timestamps buffered to find the typical beat before the stream starts.
const WARM_UP: usize = 1001;
/// The longest averaging time of the Allan deviation, in beats: its ring
/// buffer of `2m + 1` time errors is the only memory that grows with `m`.
pub const MAX_ALLAN_BEATS: usize = 1 << 16;

/// The beat analysis fed one timestamp at a time, in memory independent of
/// the number of beats (about 2 MB: the Allan deviation's buffers). The
/// first 1001 timestamps set the typical beat (half their median period)
/// and each side's interval at the start; then every beat updates running
/// sums: the regression of time on beat number, the tick and tock
/// intervals (Welford's mean and variance), the beat error at the ends, and,
/// for each `m = 2^k`, the overlapping Allan sum over a
/// ring buffer of the last `2m + 1` time errors. The time error is taken
/// against the typical interval; the Allan deviation's second differences
/// cancel any linear drift, so the final mean beat is not needed for it.
#[derive(Clone, Debug, Default)]
pub struct BeatStream {
    warm_up: Vec<f64>,
    /// The typical beat, s, when the source of the timestamps knows it
    /// (a recording's ticks, numbered beat by beat): else the warm-up's
    /// median.
    known_beat: Option<f64>,
    /// The beat numbers of the timestamps, when their source counted the
    /// beats (a recording's tracker): the warm-up's, then the last one's.
    numbers: Vec<u64>,
    typical: f64,
    origin: f64,
    count: usize,
    last: f64,
    raw_count: usize,
    raw_last: f64,
    repairs: Repairs,
    // Regression of the time error e = (t - origin) - n T_typical on n, by
    // running means and co-moments (Welford's update). Raw sums of n² and
    // n t at n = 10^7 would cancel; the time error is 10^4 times smaller
    // than t itself, and so are the roundings of its running mean.
    // One regression per side (ticks, tocks), pooled: a common slope with
    // an intercept per side, so that a beat error (tocks shifted against
    // ticks) does not tilt the line through an odd or short record.
    mean_n: [f64; 2],
    mean_t: [f64; 2],
    co_nt: [f64; 2],
    co_nn: [f64; 2],
    co_tt: [f64; 2],
    side_count: [usize; 2],
    // Interval statistics by parity (Welford).
    parity: [Welford; 2],
    allan: Vec<AllanSum>,
    /// The longest gap filled with missed beats; 0 for [`MAX_FILLED`].
    max_filled: usize,
    /// Each side's expected interval, followed through the record.
    sides: Sides,
    /// The interval that ended at the last beat accepted, s.
    last_interval: f64,
    /// Whether the last beat was filled in (the next interval is then not
    /// a measured one).
    last_filled: bool,
    /// The half tick-tock difference at the record's two ends.
    ends: Ends,
}

/// The smoothing of each side's expected interval: each interval moves it
/// a quarter of the way, so that it follows a beat error drifting by a few
/// percent a beat and averages the jitter of four.
const SIDE_SMOOTHING: f64 = 0.25;
/// The intervals the starting sides are judged on.
const FIRST_INTERVALS: usize = 40;

/// The interval expected to end at a pass of each side: index
/// `(n - 1) % 2` for the `n`-th pass.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Sides {
    expected: [f64; 2],
}

/// Where a pass falls among the expected next ones.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Place {
    /// Nearer the last pass than the next: a doubled beat.
    Doubled,
    /// At the `k`-th next pass: `k - 1` missed before it.
    Beats(usize),
    /// Beyond the most beats that may be filled in; about this many beats.
    Pause(f64),
}

impl Sides {
    /// The expected time from the last pass to the `k`-th next one, when
    /// the next interval is of side `side`.
    fn ahead(&self, side: usize, k: usize) -> f64 {
        (0..k).map(|j| self.expected[(side + j) % 2]).sum()
    }

    /// Where a pass `gap` after the last one falls, the next interval being
    /// of side `side`, with at most `limit` missed beats filled in: at the
    /// nearest of the expected passes (0 = the last one itself).
    fn place(&self, gap: f64, side: usize, limit: usize) -> Place {
        let mut at = 0.0;
        let mut k = 0;
        loop {
            let next = at + self.expected[(side + k) % 2];
            if gap < 0.5 * (at + next) {
                return if k == 0 {
                    Place::Doubled
                } else {
                    Place::Beats(k)
                };
            }
            if k > limit {
                let beat = 0.5 * (self.expected[0] + self.expected[1]);
                return Place::Pause(gap / beat);
            }
            at = next;
            k += 1;
        }
    }

    /// Moves side `side`'s expectation toward an interval measured.
    fn learn(&mut self, side: usize, interval: f64) {
        self.expected[side] += SIDE_SMOOTHING * (interval - self.expected[side]);
    }

    /// Repairs (missed plus doubled) the rule would make over `times`.
    fn repairs_over(mut self, times: &[f64]) -> usize {
        let (mut last, mut n, mut repairs) = (times[0], 1, 0);
        for &t in &times[1..] {
            let side = (n - 1) % 2;
            match self.place(t - last, side, MAX_FILLED) {
                Place::Doubled => repairs += 1,
                Place::Beats(k) => {
                    if k == 1 {
                        self.learn(side, t - last);
                    }
                    repairs += k - 1;
                    n += k;
                    last = t;
                }
                Place::Pause(_) => return usize::MAX,
            }
        }
        repairs
    }

    /// The sides at the record's start, from its first timestamps and its
    /// median `period` (two beats): the medians of the alternate intervals
    /// among the first [`FIRST_INTERVALS`], either way round, or half the
    /// period each, whichever the rule repairs least over them (a missed or
    /// doubled beat among them swaps the sides after it). With the `period`
    /// known (not the timestamps' median), sides that do not add up to it
    /// within 10% are not taken: with many beats missed, the alternate
    /// intervals' medians are two beats each, and would repair least.
    fn at_start(times: &[f64], period: f64, known: bool) -> Self {
        let first = &times[..times.len().min(FIRST_INTERVALS + 1)];
        let intervals: Vec<f64> = first.windows(2).map(|w| w[1] - w[0]).collect();
        let side = |k: usize| {
            let mut alternate: Vec<f64> = intervals.iter().skip(k).step_by(2).copied().collect();
            median(&mut alternate)
        };
        let (a, b) = (side(0), side(1));
        [[a, b], [b, a], [0.5 * period; 2]]
            .into_iter()
            .map(|expected| Sides { expected })
            .filter(|s| s.expected.iter().all(|&e| e > 0.0))
            .filter(|s| !known || ((s.expected[0] + s.expected[1]) / period - 1.0).abs() <= 0.1)
            .min_by_key(|s| s.repairs_over(first))
            .unwrap_or(Sides {
                expected: [0.5 * period; 2],
            })
    }
}

/// The pairs of intervals the beat error is taken over at each end of the
/// record.
const END_PAIRS: usize = 16;

/// The half tick-tock difference of the first and last [`END_PAIRS`]
/// pairs of intervals.
#[derive(Clone, Debug, Default)]
struct Ends {
    first: Vec<f64>,
    last: std::collections::VecDeque<f64>,
    pairs: usize,
}

impl Ends {
    fn push(&mut self, half_difference: f64) {
        if self.first.len() < END_PAIRS {
            self.first.push(half_difference);
        }
        if self.last.len() == END_PAIRS {
            self.last.pop_front();
        }
        self.last.push_back(half_difference);
        self.pairs += 1;
    }

    /// The mean half difference over the first and the last pairs (each at
    /// most half the record), and their difference in its standard errors
    /// (from the scatter within each end; 0 for fewer than four pairs).
    fn ends(&self) -> (f64, f64, f64) {
        let w = END_PAIRS.min(self.pairs / 2);
        if w < 2 {
            let all = self.first.iter().sum::<f64>() / self.first.len().max(1) as f64;
            return (all, all, 0.0);
        }
        let stats = |v: Vec<f64>| {
            let mean = v.iter().sum::<f64>() / w as f64;
            let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (w - 1) as f64;
            (mean, var)
        };
        let (a, va) = stats(self.first[..w].to_vec());
        let (b, vb) = stats(self.last.iter().rev().take(w).copied().collect());
        let error = ((va + vb) / w as f64).sqrt();
        let sigma = if a == b {
            0.0
        } else if error > 0.0 {
            (b - a).abs() / error
        } else {
            f64::MAX
        };
        (a, b, sigma)
    }
}

#[derive(Clone, Copy, Debug, Default)]
struct Welford {
    count: f64,
    mean: f64,
    m2: f64,
}

impl Welford {
    fn push(&mut self, x: f64) {
        self.count += 1.0;
        let d = x - self.mean;
        self.mean += d / self.count;
        self.m2 += d * (x - self.mean);
    }
}

#[derive(Clone, Debug)]
struct AllanSum {
    m: usize,
    /// Time errors by beat index modulo `2m + 1`.
    ring: Vec<f64>,
    sum: f64,
    terms: usize,
}

impl BeatStream {
    /// An empty analysis.
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty analysis that fills gaps of up to `beats` missed beats,
    /// for timestamps that come from following the clock through the gap
    /// (a recording's ticks, counted beat by beat), where the number of
    /// beats a gap held is known rather than guessed.
    pub fn filling_up_to(beats: usize) -> Self {
        Self {
            max_filled: beats,
            ..Self::default()
        }
    }

    /// The same, with the typical beat `beat` (s) known rather than taken
    /// from the first timestamps' median period: a record with many missed
    /// beats (40% of a recording's ticks lost in its noise) has a median
    /// period of three or four beats, and every gap would then be misread.
    pub fn with_beat(mut self, beat: f64) -> Self {
        self.known_beat = (beat > 0.0 && beat.is_finite()).then_some(beat);
        self
    }

    /// Adds the next timestamp, s.
    pub fn push(&mut self, t: f64) -> Result<(), BeatError> {
        if self.raw_count > 0 && t <= self.raw_last {
            return Err(BeatError::NotIncreasing {
                index: self.raw_count,
                time: t,
            });
        }
        self.raw_count += 1;
        self.raw_last = t;
        if self.typical == 0.0 {
            self.warm_up.push(t);
            if self.warm_up.len() == WARM_UP {
                self.start()?;
            }
            return Ok(());
        }
        self.repaired(t, self.raw_count - 1)
    }

    /// Adds the next timestamp, s, with its beat number (counted by the
    /// source through any gap, so that a gap's missed beats are known, not
    /// placed by the intervals: with many beats missed and a large beat
    /// error a gap can be misread by one, and every later beat then counted
    /// on the wrong side). Numbers must increase with the times.
    pub fn push_numbered(&mut self, beat: u64, t: f64) -> Result<(), BeatError> {
        if let Some(&last) = self.numbers.last() {
            if beat <= last {
                return Err(BeatError::NotIncreasing {
                    index: self.raw_count,
                    time: t,
                });
            }
        }
        if self.typical == 0.0 || self.numbers.is_empty() {
            self.numbers.push(beat);
        } else {
            self.numbers = vec![self.numbers[self.numbers.len() - 1], beat];
        }
        self.push(t)
    }

    /// The beats from the last timestamp to the `index`-th when numbered.
    fn numbered_step(&self, index: usize) -> Option<usize> {
        match self.numbers.len() {
            0 => None,
            2 if self.typical != 0.0 && index + 1 == self.raw_count => {
                Some((self.numbers[1] - self.numbers[0]) as usize)
            }
            n if index < n && index > 0 => {
                Some((self.numbers[index] - self.numbers[index - 1]) as usize)
            }
            _ => None,
        }
    }

    /// Sets the typical interval from the buffered timestamps and replays them.
    fn start(&mut self) -> Result<(), BeatError> {
        let buffered = std::mem::take(&mut self.warm_up);
        // The median period (two beats) is the same whatever the beat
        // error; the median beat is not once the sides differ much.
        let mut periods: Vec<f64> = buffered.windows(3).map(|w| w[2] - w[0]).collect();
        let period = match self.known_beat {
            Some(beat) => 2.0 * beat,
            None => median(&mut periods),
        };
        self.typical = 0.5 * period;
        self.sides = Sides::at_start(&buffered, period, self.known_beat.is_some());
        self.origin = buffered[0];
        // Every averaging time from the first beat, so that the sums are
        // exactly the overlapping estimator's.
        self.allan = (0..=MAX_ALLAN_BEATS.trailing_zeros())
            .map(|k| AllanSum {
                m: 1 << k,
                ring: vec![0.0; (2 << k) + 1],
                sum: 0.0,
                terms: 0,
            })
            .collect();
        self.accept(buffered[0]);
        for (i, &t) in buffered.iter().enumerate().skip(1) {
            self.repaired(t, i)?;
        }
        Ok(())
    }

    /// Drops a doubled beat, fills in missed ones at their sides' expected
    /// places, then accepts `t` (the `index`-th timestamp); refuses a pause
    /// of more than [`MAX_FILLED`] missed beats.
    fn repaired(&mut self, t: f64, index: usize) -> Result<(), BeatError> {
        let gap = t - self.last;
        let limit = if self.max_filled == 0 {
            MAX_FILLED
        } else {
            self.max_filled
        };
        let side = (self.count - 1) % 2;
        let place = match self.numbered_step(index) {
            Some(k) if k > limit => Place::Pause(k as f64),
            Some(k) => Place::Beats(k),
            None => self.sides.place(gap, side, limit),
        };
        match place {
            Place::Doubled => {
                self.repairs.doubled += 1;
                Ok(())
            }
            Place::Pause(beats) => Err(BeatError::Gap {
                index,
                time: t,
                gap,
                beats: beats.round(),
            }),
            Place::Beats(k) => {
                if k == 1 {
                    self.sides.learn(side, gap);
                } else {
                    // Spread over the gap as the sides expect.
                    let (last, whole) = (self.last, self.sides.ahead(side, k));
                    for j in 1..k {
                        self.fill(last + gap * self.sides.ahead(side, j) / whole);
                    }
                    self.repairs.missed += k - 1;
                }
                self.accept(t);
                Ok(())
            }
        }
    }

    /// A missed beat filled in at `t`: counted, and in the Allan
    /// deviation's series (which needs every beat), but neither in the
    /// regression nor in the intervals, which it would only tighten
    /// (its time is the sides' expectation, not a measurement).
    fn fill(&mut self, t: f64) {
        let error = (t - self.origin) - self.count as f64 * self.typical;
        self.push_allan(error);
        self.count += 1;
        self.last = t;
        self.last_filled = true;
    }

    fn accept(&mut self, t: f64) {
        let n = self.count as f64;
        let x = t - self.origin;
        let after_fill = std::mem::take(&mut self.last_filled);
        if self.count > 0 && !after_fill {
            let parity = (self.count - 1) % 2;
            let interval = t - self.last;
            self.parity[parity].push(interval);
            if parity == 1 && self.last_interval.is_finite() {
                self.ends.push(0.5 * (self.last_interval - interval));
            }
            self.last_interval = interval;
        } else if after_fill {
            // (The interval before this one was not measured either.)
            self.last_interval = f64::NAN;
        }
        let error = x - n * self.typical;
        let side = self.count % 2;
        self.side_count[side] += 1;
        let k = self.side_count[side] as f64;
        let dn = n - self.mean_n[side];
        self.mean_n[side] += dn / k;
        let dt = error - self.mean_t[side];
        self.mean_t[side] += dt / k;
        self.co_nt[side] += dn * (error - self.mean_t[side]);
        self.co_tt[side] += dt * (error - self.mean_t[side]);
        self.co_nn[side] += dn * (n - self.mean_n[side]);
        self.push_allan(error);
        self.count += 1;
        self.last = t;
    }

    fn push_allan(&mut self, error: f64) {
        let index = self.count;
        for a in &mut self.allan {
            let size = 2 * a.m + 1;
            a.ring[index % size] = error;
            // x_i, x_{i+m}, x_{i+2m} with i + 2m = index.
            if index >= 2 * a.m {
                let at = |j: usize| a.ring[j % size];
                let d = at(index) - 2.0 * at(index - a.m) + at(index - 2 * a.m);
                a.sum += d * d;
                a.terms += 1;
            }
        }
    }

    /// The analysis of all timestamps pushed.
    pub fn finish(mut self, nominal_beat: Option<f64>) -> Result<BeatAnalysis, BeatError> {
        if self.typical == 0.0 {
            if self.warm_up.len() < 4 {
                return Err(BeatError::TooFew(self.warm_up.len()));
            }
            self.start()?;
        }
        let (nt, nn) = (self.co_nt[0] + self.co_nt[1], self.co_nn[0] + self.co_nn[1]);
        let mean_beat = self.typical + nt / nn;
        // The slope's standard error from the scatter about the two lines
        // (a common slope, an intercept a side: three parameters).
        let residual = (self.co_tt[0] + self.co_tt[1] - nt * nt / nn).max(0.0);
        let freedom = (self.side_count[0] + self.side_count[1]) as f64 - 3.0;
        let slope_se = if freedom > 0.0 {
            (residual / freedom / nn).sqrt()
        } else {
            f64::INFINITY
        };
        if !(MIN_BEAT_S..=MAX_BEAT_S).contains(&mean_beat) {
            return Err(BeatError::NotABeat { mean_beat });
        }
        let nominal_beat = nominal_beat.or_else(|| nearest_standard(mean_beat));
        let [tick, tock] = self.parity;
        let spread = (tick.m2 + tock.m2) / (tick.count + tock.count - 2.0).max(1.0);
        let allan_deviation = self
            .allan
            .iter()
            .filter(|a| a.terms >= 10)
            .map(|a| {
                let tau = a.m as f64 * mean_beat;
                AllanPoint {
                    tau,
                    beats: a.m,
                    deviation: (a.sum / (2.0 * tau * tau * a.terms as f64)).sqrt(),
                }
            })
            .collect();
        let (start, end, change) = self.ends.ends();
        Ok(BeatAnalysis {
            beats: self.count,
            mean_beat,
            beats_per_hour: 3600.0 / mean_beat,
            nominal_beat,
            rate_s_per_day: nominal_beat.map(|nominal| 86_400.0 * (nominal / mean_beat - 1.0)),
            rate_se_s_per_day: 86_400.0 * slope_se / mean_beat,
            beat_error_ms: 1e3 * 0.5 * (tick.mean - tock.mean).abs(),
            beat_error_se_ms: 1e3
                * 0.5
                * (tick.m2 / (tick.count - 1.0).max(1.0) / tick.count.max(1.0)
                    + tock.m2 / (tock.count - 1.0).max(1.0) / tock.count.max(1.0))
                .sqrt(),
            beat_error_start_ms: 1e3 * start.abs(),
            beat_error_end_ms: 1e3 * end.abs(),
            beat_error_change_sigma: change,
            jitter_ms: 1e3 * spread.sqrt(),
            repaired: self.repairs,
            allan_deviation,
        })
    }
}

/// The nearest standard beat (s) within 2% of `beat`, if any.
pub(crate) fn nearest_standard(beat: f64) -> Option<f64> {
    standard_rate_near(3600.0 / beat).map(|r| 3600.0 / r.beats_per_hour)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The list holds issue 24's rates, slowest first, each more than 4%
    /// from the next (so that no beat is within 2% of two), and every
    /// pendulum's length is the small-angle law's for its beat, computed
    /// here independently: `L = g (T_b/π)²`.
    #[test]
    fn the_standard_rates_are_the_issues_and_their_lengths_the_laws() {
        let wanted = [
            1800.0, 2880.0, 3600.0, 4800.0, 5400.0, 6000.0, 7200.0, 8100.0, 9000.0, 10_800.0,
            12_000.0, 14_400.0, 16_200.0, 17_280.0, 18_000.0, 19_800.0, 21_600.0, 25_200.0,
            28_800.0, 36_000.0, 43_200.0, 72_000.0,
        ];
        let rates: Vec<f64> = standard_beat_rates().collect();
        assert_eq!(rates, wanted);
        for w in rates.windows(2) {
            assert!(w[1] / w[0] > 1.04, "{w:?}");
        }
        for r in &STANDARD_RATES {
            assert!(!r.source.is_empty() && !r.kind.is_empty());
            if let Some(m) = r.kind.split(", ").nth(1).and_then(|x| x.split(" m").next()) {
                if let Ok(length) = m.parse::<f64>() {
                    let beat = 3600.0 / r.beats_per_hour;
                    let law = 9.80665 * (beat / std::f64::consts::PI).powi(2);
                    let digits = m.split('.').nth(1).map_or(0, str::len) as i32;
                    assert!(
                        (length - law).abs() <= 0.51 * 10f64.powi(-digits),
                        "{}: {length} vs {law}",
                        r.beats_per_hour
                    );
                }
            }
            assert_eq!(
                standard_rate_near(r.beats_per_hour * 1.015).map(|x| x.beats_per_hour),
                Some(r.beats_per_hour)
            );
        }
        // 2,880 and 1,800 bph have a rate now; a beat between rates none.
        assert!(standard_rate_near(2900.0).is_some());
        assert!(standard_rate_near(4200.0).is_none());
    }

    fn clock(beats: usize, beat: f64, beat_error: f64) -> Vec<f64> {
        // Tick-tock: intervals beat + e, beat - e alternately.
        let mut t = vec![0.0];
        for i in 1..beats {
            let d = if i % 2 == 1 {
                beat + beat_error
            } else {
                beat - beat_error
            };
            t.push(t[i - 1] + d);
        }
        t
    }

    #[test]
    fn a_perfect_seconds_pendulum() {
        let a = analyse_beats(&clock(1000, 1.0, 0.0), None).unwrap();
        assert!((a.mean_beat - 1.0).abs() < 1e-12);
        assert_eq!(a.nominal_beat, Some(1.0));
        assert!(a.rate_s_per_day.unwrap().abs() < 1e-6);
        assert!(a.beat_error_ms < 1e-9 && a.jitter_ms < 1e-9);
    }

    #[test]
    fn rate_and_beat_error() {
        // 10 s/day slow: beat longer by 10/86400.
        let beat = 1.0 / (1.0 - 10.0 / 86_400.0);
        let a = analyse_beats(&clock(2001, beat, 0.002), None).unwrap();
        assert!(
            (a.rate_s_per_day.unwrap() + 10.0).abs() < 1e-6,
            "{:?}",
            a.rate_s_per_day
        );
        assert!((a.beat_error_ms - 2.0).abs() < 1e-6, "{}", a.beat_error_ms);
    }

    #[test]
    fn repairs_missed_and_doubled_beats() {
        let mut t = clock(100, 0.2, 0.0);
        t.remove(50);
        t.remove(70);
        t.insert(20, t[19] + 0.01);
        let a = analyse_beats(&t, Some(0.2)).unwrap();
        assert_eq!(
            a.repaired,
            Repairs {
                missed: 2,
                doubled: 1
            }
        );
        assert_eq!(a.beats, 100);
        assert!((a.mean_beat - 0.2).abs() < 1e-12);
    }

    #[test]
    fn allan_deviation_of_white_phase_noise_falls_like_one_over_tau() {
        // Deterministic "noise": alternating ±1 ms time error (the beat error
        // pattern) is white phase noise at the shortest scale.
        let t = clock(4096, 1.0, 0.001);
        let a = analyse_beats(&t, Some(1.0)).unwrap();
        let first = a.allan_deviation[0];
        let later = a.allan_deviation[4];
        assert_eq!(first.beats, 1);
        assert!(later.deviation < first.deviation / 10.0);
    }

    #[test]
    fn streamed_allan_deviation_equals_the_batch_formula() {
        // A wandering clock: the beat drifts and wobbles.
        let times: Vec<f64> = (0..5000)
            .map(|i| {
                let x = f64::from(i);
                x * 0.5 + 1e-4 * (x * 0.37).sin() + 3e-4 * (x * 0.011).sin()
            })
            .collect();
        let a = analyse_beats(&times, None).unwrap();
        let errors: Vec<f64> = times
            .iter()
            .enumerate()
            .map(|(i, t)| t - i as f64 * 0.5)
            .collect();
        for p in &a.allan_deviation {
            let m = p.beats;
            let terms = errors.len() - 2 * m;
            let sum: f64 = (0..terms)
                .map(|i| (errors[i + 2 * m] - 2.0 * errors[i + m] + errors[i]).powi(2))
                .sum();
            let batch = (sum / (2.0 * p.tau * p.tau * terms as f64)).sqrt();
            assert!(
                (p.deviation / batch - 1.0).abs() < 1e-9,
                "m = {m}: {} vs {batch}",
                p.deviation
            );
        }
        assert!(a.allan_deviation.len() >= 8);
    }

    #[test]
    fn a_large_beat_error_does_not_tilt_a_short_record() {
        // 71 beats (an odd count) at 21,600 bph, tocks 5 ms late, rate 0:
        // one line through both sides would lean by ~3 s/day.
        let beat = 3600.0 / 21_600.0;
        let times: Vec<f64> = (0..71)
            .map(|i| i as f64 * beat + if i % 2 == 1 { 5e-3 } else { 0.0 })
            .collect();
        let a = analyse_beats(&times, Some(beat)).unwrap();
        assert!(
            a.rate_s_per_day.unwrap().abs() < 1e-6,
            "{:?}",
            a.rate_s_per_day
        );
        assert!((a.beat_error_ms - 5.0).abs() < 1e-9);
    }

    #[test]
    fn a_pause_is_refused_not_filled() {
        // An hour at 3600 bph gaining 4 s/day, a 27.8-hour pause, an hour
        // more: filling the pause would invent about 1e5 beats and a wrong
        // rate (issue 9 measured -56 s/day for the truth +4).
        let beat = 1.0 / (1.0 + 4.0 / 86_400.0);
        let mut t: Vec<f64> = (0..3600).map(|i| i as f64 * beat).collect();
        let resume = t[3599] + 27.8 * 3600.0;
        t.extend((0..3600).map(|i| resume + i as f64 * beat));
        match analyse_beats(&t, Some(1.0)) {
            Err(BeatError::Gap { index, beats, .. }) => {
                assert_eq!(index, 3600);
                assert!(beats > 1e5, "{beats}");
            }
            other => panic!("{other:?}"),
        }
        // Ten missed beats in a row are still filled in.
        let mut short: Vec<f64> = (0..100).map(|i| i as f64).collect();
        short.retain(|&x| !(40.0..50.0).contains(&x));
        let a = analyse_beats(&short, Some(1.0)).unwrap();
        assert_eq!(a.repaired.missed, 10);
    }

    /// Passes of a decaying pendulum through a gate off its centre (at
    /// `gate` rad): `θ = A e^{-t/τ} cos ω t` crosses `gate` at
    /// `ω t = 2πk ± arccos(gate / A)`, so the intervals alternate short
    /// and long, the short one shrinking as the swing decays.
    fn off_centre_gate(
        period: f64,
        amplitude: f64,
        gate: f64,
        tau: f64,
        passes: usize,
    ) -> Vec<f64> {
        let omega = std::f64::consts::TAU / period;
        let mut times = Vec::new();
        let mut k = 0.0;
        while times.len() < passes {
            let crest = k * period;
            // The amplitude at this crest (it hardly changes in a period).
            let a = amplitude * (-crest / tau).exp();
            let half = (gate / a).acos() / omega;
            times.push(crest - half);
            times.push(crest + half);
            k += 1.0;
        }
        times.retain(|&t| t > 0.0);
        times.truncate(passes);
        times
    }

    #[test]
    fn a_gate_off_centre_keeps_every_pass() {
        // Issue 23's photogate: passes alternating 0.70/0.48 s drifting to
        // 0.97/0.20 s, a period of 1.18 s. The rule against one median
        // interval dropped the short passes and invented others.
        let period = 1.18;
        let omega = std::f64::consts::TAU / period;
        // The short interval (beyond the gate, about a crest) is
        // 2 arccos(gate / A) / ω: 0.48 s at the start, 0.20 s at the end.
        let gate = 0.2;
        let a0 = gate / (0.24 * omega).cos();
        let a_end = gate / (0.10 * omega).cos();
        let passes = 400;
        let duration = passes as f64 / 2.0 * period;
        let tau = duration / (a0 / a_end).ln();
        let times = off_centre_gate(period, a0, gate, tau, passes);
        let a = analyse_beats(&times, Some(0.5 * period)).unwrap();
        assert_eq!(a.repaired, Repairs::default(), "{a:?}");
        assert_eq!(a.beats, times.len());
        assert!(a.rate_s_per_day.unwrap().abs() < 0.5, "{a:?}");
        // The sides drift apart: from (0.70 - 0.48)/2 to (0.97 - 0.20)/2.
        // Averaged over 16 pairs at each end: 110 ms at the first beat, and
        // over the last pairs the mean of (long - short) / 2 as generated.
        assert!((a.beat_error_start_ms - 110.0).abs() < 10.0, "{a:?}");
        let last: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
        let last = &last[last.len() - 32..];
        let end = 1e3
            * last
                .chunks(2)
                .map(|p| 0.5 * (p[0] - p[1]).abs())
                .sum::<f64>()
            / 16.0;
        assert!(
            (a.beat_error_end_ms - end).abs() < 1e-6 * end,
            "{a:?} against {end}"
        );
        assert!(end > 350.0);
        assert!(a.beat_error_change_sigma > 5.0, "{a:?}");
        // A pass missed and one doubled on the short side are repaired
        // as such, at the short side's place.
        let mut broken = times.clone();
        let short_at = 301;
        broken.remove(short_at);
        broken.insert(100, broken[99] + 0.05);
        let b = analyse_beats(&broken, Some(0.5 * period)).unwrap();
        assert_eq!(
            b.repaired,
            Repairs {
                missed: 1,
                doubled: 1
            }
        );
        assert!((b.rate_s_per_day.unwrap() - a.rate_s_per_day.unwrap()).abs() < 1.0);
    }

    #[test]
    fn out_of_beat_clocks_repaired_side_by_side() {
        // Clocks 0-40% out of beat (one interval up to 2.3 times the
        // other), 0.5% jitter, every 37th beat missed and a spurious pass
        // early in every 53rd interval: each repair counted as made, the
        // rate unmoved by them.
        let mut seed = 7_u64;
        let mut uniform = move || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for case in 0..40 {
            let beat = 0.25 + 2.0 * uniform();
            let out = 0.4 * beat * (case as f64 / 39.0);
            let rate = 20.0 * (uniform() - 0.5);
            let mean = beat / (1.0 + rate / 86_400.0);
            let mut clean = vec![0.0];
            for i in 1..1200 {
                let side = if i % 2 == 1 { out } else { -out };
                let jitter = 0.005 * beat * (uniform() - 0.5);
                clean.push(clean[i - 1] + mean + side + jitter);
            }
            let truth = analyse_beats(&clean, Some(beat)).unwrap();
            let mut times = Vec::new();
            let (mut missed, mut doubled) = (0, 0);
            for i in 0..clean.len() {
                if i % 37 == 20 {
                    missed += 1;
                    continue;
                }
                times.push(clean[i]);
                if i % 53 == 30 {
                    let f = 0.05 + 0.3 * uniform();
                    times.push(clean[i] + f * (clean[i + 1] - clean[i]));
                    doubled += 1;
                }
            }
            let a = analyse_beats(&times, Some(beat)).unwrap();
            assert_eq!(a.repaired, Repairs { missed, doubled }, "case {case}");
            assert_eq!(a.beats, clean.len(), "case {case}");
            let (r, t) = (a.rate_s_per_day.unwrap(), truth.rate_s_per_day.unwrap());
            assert!((r - t).abs() < 0.5, "case {case}: {r} against {t}");
            assert!(
                (a.beat_error_ms - 1e3 * out).abs() < 0.02 * beat * 1e3,
                "case {case}: {} against {}",
                a.beat_error_ms,
                1e3 * out
            );
        }
    }

    #[test]
    fn a_steady_beat_error_has_no_trend() {
        let a = analyse_beats(&clock(2001, 1.0, 0.002), None).unwrap();
        assert!((a.beat_error_start_ms - 2.0).abs() < 1e-6, "{a:?}");
        assert!((a.beat_error_end_ms - 2.0).abs() < 1e-6, "{a:?}");
    }

    #[test]
    fn refuses_too_few_and_unsorted() {
        assert_eq!(
            analyse_beats(&[0.0, 1.0, 2.0], None),
            Err(BeatError::TooFew(3))
        );
        assert!(matches!(
            analyse_beats(&[0.0, 1.0, 0.5, 2.0, 3.0], None),
            Err(BeatError::NotIncreasing { index: 2, .. })
        ));
    }
}
