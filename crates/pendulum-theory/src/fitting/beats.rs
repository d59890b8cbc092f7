//! A clock's rate from beat timestamps, as a beam-break or microphone timer
//! records them: the figures a timegrapher shows, for any beat rate from one
//! beat in ten seconds to twenty a second.
//!
//! * Gaps and doubles are repaired first: against the median interval, an
//!   interval under half of it marks a doubled (spurious) beat, which is
//!   dropped, and one of `k` times it marks `k - 1` missed beats, which are
//!   filled in evenly, up to [`MAX_FILLED`] of them. A longer gap is a
//!   pause in the record, not missed beats: how many beats it held cannot be
//!   told from the times (a 28-hour pause at +4 s/day is 4.6 beats off a
//!   whole count), so it is refused with its place, to split the record.
//! * The mean beat is the slope of the least-squares line of time against
//!   beat number, as timers compute it (robust to the jitter of single beats).
//! * Beat error is half the difference between the mean "tick" and "tock"
//!   intervals (alternate beats), in ms, as timegraphers report it.
//! * Jitter is the standard deviation of the intervals about their own
//!   tick or tock mean.
//! * The Allan deviation of the rate (overlapping estimator, IEEE 1139) at
//!   averaging times of `2^k` beats up to 65,536, from the time error
//!   `x_n = t_n - n T_b`:
//!   `σ²(τ) = Σ (x_{i+2m} - 2x_{i+m} + x_i)² / (2 τ² (N - 2m))`, `τ = m T_b`.
//!
//! All of it runs on a stream ([`BeatStream`]) in fixed memory, so a log of
//! 10^7 beats needs no more than one of ten.

/// Beat rates (beats per hour) a clock is usually made for; the nominal
/// beat is taken from here when none is given.
pub const STANDARD_BEAT_RATES: [f64; 13] = [
    3600.0, 5400.0, 7200.0, 9000.0, 14_400.0, 18_000.0, 19_800.0, 21_600.0, 25_200.0, 28_800.0,
    36_000.0, 43_200.0, 72_000.0,
];

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
    /// Half the tick-tock difference, ms.
    pub beat_error_ms: f64,
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
        "beat {index} at {time} s comes {gap} s after the one before, about {beats} beats: \
         a pause in the record, not missed beats (at most 10 are filled in); \
         analyse the parts before and after it separately"
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

/// Timestamps buffered to find the typical interval before the stream starts.
const WARM_UP: usize = 1001;
/// The longest averaging time of the Allan deviation, in beats: its ring
/// buffer of `2m + 1` time errors is the only memory that grows with `m`.
pub const MAX_ALLAN_BEATS: usize = 1 << 16;

/// The beat analysis fed one timestamp at a time, in memory independent of
/// the number of beats (about 2 MB: the Allan deviation's buffers). The
/// first 1001 timestamps set the typical interval for the repairs (their
/// median); then every beat updates running sums: the regression of time
/// on beat number, the tick and tock intervals (Welford's mean and
/// variance), and, for each `m = 2^k`, the overlapping Allan sum over a
/// ring buffer of the last `2m + 1` time errors. The time error is taken
/// against the typical interval; the Allan deviation's second differences
/// cancel any linear drift, so the final mean beat is not needed for it.
#[derive(Clone, Debug, Default)]
pub struct BeatStream {
    warm_up: Vec<f64>,
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
    side_count: [usize; 2],
    // Interval statistics by parity (Welford).
    parity: [Welford; 2],
    allan: Vec<AllanSum>,
    /// The longest gap filled with missed beats; 0 for [`MAX_FILLED`].
    max_filled: usize,
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

    /// Sets the typical interval from the buffered timestamps and replays them.
    fn start(&mut self) -> Result<(), BeatError> {
        let buffered = std::mem::take(&mut self.warm_up);
        let mut intervals: Vec<f64> = buffered.windows(2).map(|w| w[1] - w[0]).collect();
        intervals.sort_by(f64::total_cmp);
        self.typical = intervals[intervals.len() / 2];
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

    /// Drops a doubled beat, fills in missed ones, then accepts `t` (the
    /// `index`-th timestamp); refuses a pause of more than [`MAX_FILLED`]
    /// missed beats.
    fn repaired(&mut self, t: f64, index: usize) -> Result<(), BeatError> {
        let gap = t - self.last;
        if gap < 0.5 * self.typical {
            self.repairs.doubled += 1;
            return Ok(());
        }
        let beats = gap / self.typical;
        let limit = if self.max_filled == 0 {
            MAX_FILLED
        } else {
            self.max_filled
        };
        if beats > limit as f64 + 1.5 {
            return Err(BeatError::Gap {
                index,
                time: t,
                gap,
                beats: beats.round(),
            });
        }
        let k = beats.round() as usize;
        if k >= 2 {
            let last = self.last;
            for j in 1..k {
                self.accept(last + gap * j as f64 / k as f64);
            }
            self.repairs.missed += k - 1;
        }
        self.accept(t);
        Ok(())
    }

    fn accept(&mut self, t: f64) {
        let n = self.count as f64;
        let x = t - self.origin;
        if self.count > 0 {
            let parity = (self.count - 1) % 2;
            self.parity[parity].push(t - self.last);
        }
        let error = x - n * self.typical;
        let side = self.count % 2;
        self.side_count[side] += 1;
        let k = self.side_count[side] as f64;
        let dn = n - self.mean_n[side];
        self.mean_n[side] += dn / k;
        self.mean_t[side] += (error - self.mean_t[side]) / k;
        self.co_nt[side] += dn * (error - self.mean_t[side]);
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
        let mean_beat =
            self.typical + (self.co_nt[0] + self.co_nt[1]) / (self.co_nn[0] + self.co_nn[1]);
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
        Ok(BeatAnalysis {
            beats: self.count,
            mean_beat,
            beats_per_hour: 3600.0 / mean_beat,
            nominal_beat,
            rate_s_per_day: nominal_beat.map(|nominal| 86_400.0 * (nominal / mean_beat - 1.0)),
            beat_error_ms: 1e3 * 0.5 * (tick.mean - tock.mean).abs(),
            jitter_ms: 1e3 * spread.sqrt(),
            repaired: self.repairs,
            allan_deviation,
        })
    }
}

/// The nearest standard beat (s) within 2% of `beat`, if any.
fn nearest_standard(beat: f64) -> Option<f64> {
    STANDARD_BEAT_RATES
        .iter()
        .map(|&r| 3600.0 / r)
        .min_by(|a, b| (a - beat).abs().total_cmp(&(b - beat).abs()))
        .filter(|&nominal| (nominal / beat - 1.0).abs() <= 0.02)
}

#[cfg(test)]
mod tests {
    use super::*;

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
