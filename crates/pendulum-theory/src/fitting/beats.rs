//! A clock's rate from beat timestamps, as a beam-break or microphone timer
//! records them: the figures a timegrapher shows, for any beat rate from one
//! beat in ten seconds to twenty a second.
//!
//! * Gaps and doubles are repaired first: against the median interval, an
//!   interval under half of it marks a doubled (spurious) beat, which is
//!   dropped, and one of `k` times it marks `k - 1` missed beats, which are
//!   filled in evenly.
//! * The mean beat is the slope of the least-squares line of time against
//!   beat number, as timers compute it (robust to the jitter of single beats).
//! * Beat error is half the difference between the mean "tick" and "tock"
//!   intervals (alternate beats), in ms, as timegraphers report it.
//! * Jitter is the standard deviation of the intervals about their own
//!   tick or tock mean.
//! * The Allan deviation of the rate (overlapping estimator, IEEE 1139) at
//!   averaging times of `2^k` beats, from the time error `x_n = t_n - n T_b`:
//!   `σ²(τ) = Σ (x_{i+2m} - 2x_{i+m} + x_i)² / (2 τ² (N - 2m))`, `τ = m T_b`.

use super::straight_line;

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
}

/// Analyses beat timestamps `times` (s); `nominal_beat` (s) is the beat the
/// clock is meant to have, else the nearest standard rate within 2%.
pub fn analyse_beats(times: &[f64], nominal_beat: Option<f64>) -> Result<BeatAnalysis, BeatError> {
    if times.len() < 4 {
        return Err(BeatError::TooFew(times.len()));
    }
    if let Some(i) = (1..times.len()).find(|&i| times[i] <= times[i - 1]) {
        return Err(BeatError::NotIncreasing {
            index: i,
            time: times[i],
        });
    }
    let (times, repaired) = repair(times);
    let n = times.len();
    let index: Vec<f64> = (0..n).map(|i| i as f64).collect();
    let (_, mean_beat) = straight_line(&index, &times);
    let nominal_beat = nominal_beat.or_else(|| nearest_standard(mean_beat));
    let rate_s_per_day = nominal_beat.map(|nominal| 86_400.0 * (nominal / mean_beat - 1.0));
    let intervals: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    let (tick, tock) = alternate_means(&intervals);
    let spread: f64 = intervals
        .iter()
        .enumerate()
        .map(|(i, d)| (d - if i % 2 == 0 { tick } else { tock }).powi(2))
        .sum::<f64>()
        / (intervals.len().saturating_sub(2).max(1)) as f64;
    let time_error: Vec<f64> = times
        .iter()
        .enumerate()
        .map(|(i, t)| t - times[0] - i as f64 * mean_beat)
        .collect();
    Ok(BeatAnalysis {
        beats: n,
        mean_beat,
        beats_per_hour: 3600.0 / mean_beat,
        nominal_beat,
        rate_s_per_day,
        beat_error_ms: 1e3 * 0.5 * (tick - tock).abs(),
        jitter_ms: 1e3 * spread.sqrt(),
        repaired,
        allan_deviation: allan_deviation(&time_error, mean_beat),
    })
}

/// The nearest standard beat (s) within 2% of `beat`, if any.
fn nearest_standard(beat: f64) -> Option<f64> {
    let bph = 3600.0 / beat;
    STANDARD_BEAT_RATES
        .iter()
        .map(|&r| 3600.0 / r)
        .min_by(|a, b| {
            (a - 3600.0 / bph)
                .abs()
                .total_cmp(&(b - 3600.0 / bph).abs())
        })
        .filter(|&nominal| (nominal / beat - 1.0).abs() <= 0.02)
}

/// Means of the even-numbered and odd-numbered intervals.
fn alternate_means(intervals: &[f64]) -> (f64, f64) {
    let mean = |parity: usize| {
        let picked: Vec<f64> = intervals.iter().skip(parity).step_by(2).copied().collect();
        picked.iter().sum::<f64>() / picked.len().max(1) as f64
    };
    (mean(0), mean(1))
}

/// Drops doubled beats and fills in missed ones against the median interval.
fn repair(times: &[f64]) -> (Vec<f64>, Repairs) {
    let mut intervals: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    intervals.sort_by(f64::total_cmp);
    let typical = intervals[intervals.len() / 2];
    let mut out = Vec::with_capacity(times.len());
    let mut repairs = Repairs::default();
    out.push(times[0]);
    for &t in &times[1..] {
        let last = *out.last().expect("starts with one");
        let gap = t - last;
        if gap < 0.5 * typical {
            repairs.doubled += 1;
            continue;
        }
        let k = (gap / typical).round() as usize;
        if k >= 2 {
            for j in 1..k {
                out.push(last + gap * j as f64 / k as f64);
            }
            repairs.missed += k - 1;
        }
        out.push(t);
    }
    (out, repairs)
}

/// Overlapping Allan deviation of the time error `x` sampled every `beat`
/// seconds, at `m = 1, 2, 4, …` beats while `N - 2m >= 10`.
fn allan_deviation(x: &[f64], beat: f64) -> Vec<AllanPoint> {
    let n = x.len();
    let mut out = Vec::new();
    let mut m = 1;
    while n >= 2 * m + 10 {
        let terms = n - 2 * m;
        let sum: f64 = (0..terms)
            .map(|i| (x[i + 2 * m] - 2.0 * x[i + m] + x[i]).powi(2))
            .sum();
        let tau = m as f64 * beat;
        out.push(AllanPoint {
            tau,
            beats: m,
            deviation: (sum / (2.0 * tau * tau * terms as f64)).sqrt(),
        });
        m *= 2;
    }
    out
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
