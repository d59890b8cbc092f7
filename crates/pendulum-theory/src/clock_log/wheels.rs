//! The going train's wheels in a clock's rate: each arbor's period, and
//! the rate folded over it (the average rate at each part of the turn).
//!
//! Method: the period of arbor `i` is `3600 / n_i` s of the clock's own
//! time, `n_i` its turns an hour from the first arbor's through the
//! wheel and pinion ratios (Rawlings, The Science of Clocks and Watches,
//! 3rd ed., 1993, ch. 6). A wheel's errors (an eccentric wheel, a bent
//! tooth, a pinion's leaves) repeat with its turn, which is locked to the
//! clock's count of beats, not to the reference's seconds: the fold's
//! phase is the clock's time (the reference's time plus the offset, or
//! the count of beats times the nominal half period), so a clock that
//! gains does not smear the fold. Before folding, the rate's slow part is
//! taken out by a centred running mean over exactly one turn (which
//! leaves the wheel's own pattern, whose mean over a turn is zero). The
//! fold's bins are judged by a one-way analysis of variance (Fisher's F
//! of the bins' means against the scatter within them); the time error
//! the pattern makes within a turn is its running integral.

use serde::Serialize;
use statrs::distribution::{ContinuousCDF, FisherSnedecor};

/// A going train: wheels and pinions from the first arbor to the escape
/// wheel, as `pendulum train` takes them.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainInput {
    /// Teeth of each wheel; the last is the escape wheel.
    pub wheels: Vec<u32>,
    /// Leaves of each pinion the wheels drive: one fewer.
    pub pinions: Vec<u32>,
    /// Turns an hour of the first wheel's arbor (default
    /// [`crate::train::analysis::DEFAULT_ARBOR_TURNS_PER_HOUR`], the
    /// centre wheel).
    pub arbor_turns_per_hour: Option<f64>,
}

/// One arbor of the train.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Arbor {
    /// Its name: `centre wheel`, `escape wheel`, `wheel 2`, ….
    pub name: String,
    /// Its wheel's teeth.
    pub teeth: u32,
    /// Its period, s of the clock's time.
    pub period_s: f64,
}

impl TrainInput {
    /// The arbors, first to escape wheel, with their periods; `None` for
    /// a train `pendulum train` would refuse (counts that do not match,
    /// a zero).
    pub fn arbors(&self) -> Option<Vec<Arbor>> {
        self.beats_per_hour()?;
        let mut turns = self.turns();
        let last = self.wheels.len() - 1;
        let mut out = Vec::with_capacity(self.wheels.len());
        for (i, &teeth) in self.wheels.iter().enumerate() {
            if i > 0 {
                turns *= f64::from(self.wheels[i - 1]) / f64::from(self.pinions[i - 1]);
            }
            let name = if i == last {
                "escape wheel".to_string()
            } else if (turns - 1.0).abs() < 1e-9 {
                "centre wheel".to_string()
            } else if i == 0 && turns < 1.0 {
                "great wheel".to_string()
            } else {
                format!("wheel {}", i + 1)
            };
            out.push(Arbor {
                name,
                teeth,
                period_s: 3600.0 / turns,
            });
        }
        Some(out)
    }

    /// The beats an hour the train gives.
    pub fn beats_per_hour(&self) -> Option<f64> {
        crate::train::beats_per_hour(&self.wheels, &self.pinions, self.turns())
    }

    fn turns(&self) -> f64 {
        self.arbor_turns_per_hour
            .unwrap_or(crate::train::analysis::DEFAULT_ARBOR_TURNS_PER_HOUR)
    }
}

/// One part of a turn in a fold.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct FoldBin {
    /// Where in the turn the bin starts, 0 to 1.
    pub phase: f64,
    /// The mean rate there after the slow part is taken out, s/day.
    pub rate_s_per_day: f64,
    /// Its standard error, s/day.
    pub standard_error_s_per_day: f64,
    /// Turns that reached it (each turn's mean there is one
    /// observation).
    pub count: usize,
}

/// The rate folded over one arbor's turn.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Fold {
    /// The arbor.
    pub arbor: String,
    /// Its period, s.
    pub period_s: f64,
    /// Turns the log covers.
    pub turns: f64,
    /// The bins over one turn.
    pub bins: Vec<FoldBin>,
    /// The largest bin mean minus the smallest, s/day.
    pub peak_to_peak_s_per_day: f64,
    /// The clock's time error within a turn that the pattern makes,
    /// largest minus smallest, s.
    pub time_error_peak_to_peak_s: f64,
    /// Fisher's F of the bins' means against the scatter within them
    /// (`None`: no scatter within them).
    pub f_statistic: Option<f64>,
    /// The chance a flat pattern (no wheel error) gives an F this large.
    pub p_value: f64,
    /// Clearly there: `p_value` under 0.1%.
    pub seen: bool,
}

/// Folds a series regular in its index (`values` s/day, NaN for gaps,
/// one every `spacing` s of the clock's time; `position[j]`, the clock's
/// time of sample `j` in s) over `period` s in at most `max_bins` bins.
/// `None` when a turn spans fewer than 4 samples or the series fewer
/// than 3 turns.
pub fn fold(
    values: &[f64],
    position: &dyn Fn(usize) -> f64,
    spacing: f64,
    period: f64,
    max_bins: usize,
) -> Option<(Vec<FoldBin>, Option<f64>, f64, f64)> {
    let window = (period / spacing).round() as usize;
    let n = values.len();
    if window < 4 || (n as f64) < 3.0 * window as f64 {
        return None;
    }
    // The centred running mean over one turn, from cumulative sums.
    let (sum, count) = super::series::cumulative(values);
    let k = window.min(max_bins);
    // Each turn's mean in each bin is one observation: the samples within
    // a turn are correlated (a random walk of the rate leaves them so
    // even after the running mean), the turns much less.
    let (mut s1, mut s2, mut c) = (vec![0.0; k], vec![0.0; k], vec![0usize; k]);
    let (mut turn_sum, mut turn_count) = (vec![0.0; k], vec![0usize; k]);
    let mut current_turn = None;
    let mut flush = |turn_sum: &mut [f64], turn_count: &mut [usize]| {
        for b in 0..k {
            if turn_count[b] > 0 {
                let m = turn_sum[b] / turn_count[b] as f64;
                s1[b] += m;
                s2[b] += m * m;
                c[b] += 1;
            }
            turn_sum[b] = 0.0;
            turn_count[b] = 0;
        }
    };
    let half = window / 2;
    let last = n.saturating_sub(window - half);
    for (j, &v) in values.iter().enumerate().take(last).skip(half) {
        if !v.is_finite() {
            continue;
        }
        let (a, b) = (j - half, j - half + window);
        let m = count[b] - count[a];
        if m * 2 < window {
            continue;
        }
        let detrended = v - (sum[b] - sum[a]) / m as f64;
        let turns = position(j) / period;
        let turn = turns.floor();
        if current_turn != Some(turn) {
            flush(&mut turn_sum, &mut turn_count);
            current_turn = Some(turn);
        }
        let bin = ((turns.rem_euclid(1.0) * k as f64) as usize).min(k - 1);
        turn_sum[bin] += detrended;
        turn_count[bin] += 1;
    }
    flush(&mut turn_sum, &mut turn_count);
    let total: usize = c.iter().sum();
    if c.iter().any(|&m| m < 2) || total <= k {
        return None;
    }
    let grand = s1.iter().sum::<f64>() / total as f64;
    let (mut between, mut within) = (0.0, 0.0);
    let bins: Vec<FoldBin> = (0..k)
        .map(|b| {
            let m = c[b] as f64;
            let mean = s1[b] / m;
            let var = ((s2[b] - m * mean * mean) / (m - 1.0)).max(0.0);
            between += m * (mean - grand).powi(2);
            within += var * (m - 1.0);
            FoldBin {
                phase: b as f64 / k as f64,
                rate_s_per_day: mean,
                standard_error_s_per_day: (var / m).sqrt(),
                count: c[b],
            }
        })
        .collect();
    let (d1, d2) = ((k - 1) as f64, (total - k) as f64);
    // No scatter at all: nothing to judge (a constant log); no scatter
    // within the bins but some between: a pattern beyond doubt.
    if within <= 0.0 && between <= 0.0 {
        return None;
    }
    let f = (within > 0.0).then(|| (between / d1) / (within / d2));
    let p = match f {
        Some(f) => FisherSnedecor::new(d1, d2).map_or(1.0, |d| 1.0 - d.cdf(f)),
        None => 0.0,
    };
    // The time error within a turn: the running sum of the pattern (its
    // mean taken out) over each bin's share of the turn.
    let mut error = 0.0;
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for b in &bins {
        error += (b.rate_s_per_day - grand) / 86_400.0 * period / k as f64;
        lo = lo.min(error);
        hi = hi.max(error);
    }
    Some((bins, f, p, hi - lo))
}

/// Folds over each arbor (see [`fold`]), the fastest first: a pattern
/// found is taken out of the series before the slower arbors are folded,
/// or it would show again in their folds (a slower arbor's period holds
/// whole turns of the faster ones, but its bins do not).
pub fn folds(
    arbors: &[Arbor],
    mut values: Vec<f64>,
    position: &dyn Fn(usize) -> f64,
    spacing: f64,
) -> Vec<Fold> {
    let mut order: Vec<usize> = (0..arbors.len()).collect();
    order.sort_by(|&a, &b| arbors[a].period_s.total_cmp(&arbors[b].period_s));
    let mut found: Vec<(usize, Fold)> = Vec::new();
    for i in order {
        let a = &arbors[i];
        let Some((bins, f, p, error)) = fold(&values, position, spacing, a.period_s, 120) else {
            continue;
        };
        let means = bins.iter().map(|b| b.rate_s_per_day);
        let peak =
            means.clone().fold(f64::NEG_INFINITY, f64::max) - means.fold(f64::INFINITY, f64::min);
        let seen = p < super::spectrum::SEEN_BELOW;
        if seen {
            let k = bins.len();
            for (j, v) in values.iter_mut().enumerate() {
                let phase = (position(j) / a.period_s).rem_euclid(1.0);
                *v -= bins[((phase * k as f64) as usize).min(k - 1)].rate_s_per_day;
            }
        }
        found.push((
            i,
            Fold {
                arbor: a.name.clone(),
                period_s: a.period_s,
                turns: values.len() as f64 * spacing / a.period_s,
                bins,
                peak_to_peak_s_per_day: peak,
                time_error_peak_to_peak_s: error,
                f_statistic: f,
                p_value: p,
                seen,
            },
        ));
    }
    found.sort_by_key(|(i, _)| *i);
    found.into_iter().map(|(_, f)| f).collect()
}
