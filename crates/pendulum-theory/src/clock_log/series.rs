//! From a log as it comes (offsets, rates, half periods) to one rate a
//! bin, each bin knowing which stretches of the log its rate averages,
//! so that the weather is averaged over the same stretches.
//!
//! The log's stretches are its intervals: interval `j ≥ 1` runs from
//! sample `j − 1` to sample `j`; "interval" 0 is the first sample itself
//! (a rate read at one instant). A bin's rate is a weighted mean of the
//! clock's rate over its intervals, and its `Bins::parts` list the
//! weights, which sum to one.
//!
//! * Offsets: the intervals are given to the bin holding their
//!   midpoints, so every interval is in one bin and neighbouring bins
//!   share their edge sample; a bin's rate is the least-squares slope of
//!   its samples (a bin of one interval: the difference of its two
//!   offsets, as a log read once a day has). The slope is
//!   `Σ_j W_j Δx_j`, `W_j = Σ_{i ≥ j} (t_i − t̄)/S_tt`, so interval `j`'s
//!   weight is `W_j Δt_j`: the weight the clock's rate there has in the
//!   bin's.
//! * Rates and half periods: each sample is the rate over the interval
//!   before it (the first over its instant), the bin's rate their mean
//!   (weighted by the half periods, so a bin's rate is its count of beats
//!   over its time).

use super::daily::DailyCycle;

/// Bins of about equal length over a log.
#[derive(Clone, Debug, Default)]
pub(crate) struct Bins {
    /// Each bin's time: its intervals' midpoints weighted as its rate
    /// weighs them, s.
    pub centre: Vec<f64>,
    /// Each bin's rate, s/day.
    pub rate: Vec<f64>,
    /// Each bin's weight: the time its rate spans over the median bin's
    /// (white frequency noise averages down with time).
    pub weight: Vec<f64>,
    /// Each bin's span, s.
    pub span: Vec<f64>,
    /// `(interval, weight)` of every bin, bin after bin.
    pub parts: Vec<(usize, f64)>,
    /// Each bin's slice of `parts`.
    pub ranges: Vec<(usize, usize)>,
}

impl Bins {
    /// Each bin's weighted mean of `per_interval` (one value an interval,
    /// as [`interval_means`] gives), its non-finite values left out; NaN
    /// for a bin with none.
    pub fn average(&self, per_interval: &[f64]) -> Vec<f64> {
        self.ranges
            .iter()
            .map(|&(a, b)| {
                let (mut s, mut w) = (0.0, 0.0);
                for &(j, u) in &self.parts[a..b] {
                    let v = per_interval[j];
                    if v.is_finite() {
                        s += u * v;
                        w += u;
                    }
                }
                if w != 0.0 {
                    s / w
                } else {
                    f64::NAN
                }
            })
            .collect()
    }

    fn push(&mut self, parts: &[(usize, f64)], rate: f64, span: f64, times: &[f64]) {
        let start = self.parts.len();
        let centre = parts
            .iter()
            .map(|&(j, u)| {
                u * if j == 0 {
                    times[0]
                } else {
                    0.5 * (times[j - 1] + times[j])
                }
            })
            .sum::<f64>()
            / parts.iter().map(|p| p.1).sum::<f64>();
        self.parts.extend_from_slice(parts);
        self.ranges.push((start, self.parts.len()));
        self.centre.push(centre);
        self.rate.push(rate);
        self.span.push(span.max(1e-9));
    }

    /// Weights relative to the median bin's span.
    fn finish(mut self) -> Bins {
        let mut spans = self.span.clone();
        spans.sort_by(f64::total_cmp);
        let median = spans.get(spans.len() / 2).copied().unwrap_or(1.0);
        self.weight = self.span.iter().map(|s| s / median).collect();
        self
    }
}

/// The bin (counted from the first sample's time) each interval's
/// midpoint falls in; interval 0 in the first.
fn bin_of(times: &[f64], j: usize, length: f64) -> i64 {
    let mid = if j == 0 {
        times[0]
    } else {
        0.5 * (times[j - 1] + times[j])
    };
    ((mid - times[0]) / length).floor() as i64
}

/// Offsets (s) to binned rates (s/day): each bin the least-squares slope
/// of the samples at the ends of its intervals.
pub(crate) fn offsets_to_bins(times: &[f64], x: &[f64], length: f64) -> Bins {
    let mut bins = Bins::default();
    let n = times.len();
    let mut j = 1;
    let mut parts = Vec::new();
    while j < n {
        let k = bin_of(times, j, length);
        let first = j;
        while j < n && bin_of(times, j, length) == k {
            j += 1;
        }
        // Samples first − 1 ..= j − 1.
        let (a, b) = (first - 1, j);
        let count = (b - a) as f64;
        let tm = times[a..b].iter().sum::<f64>() / count;
        let xm = x[a..b].iter().sum::<f64>() / count;
        let (mut sxy, mut sxx) = (0.0, 0.0);
        for i in a..b {
            sxy += (times[i] - tm) * (x[i] - xm);
            sxx += (times[i] - tm).powi(2);
        }
        if sxx <= 0.0 {
            continue;
        }
        parts.clear();
        let mut tail = 0.0;
        for i in (a + 1..b).rev() {
            tail += (times[i] - tm) / sxx;
            parts.push((i, tail * (times[i] - times[i - 1])));
        }
        parts.reverse();
        bins.push(&parts, sxy / sxx * 86_400.0, times[b - 1] - times[a], times);
    }
    bins.finish()
}

/// Rates (s/day) to binned rates: the mean of each bin's samples, each
/// weighted by its `durations` when given (half periods: the bin's rate
/// is then its count of beats over its time, which an equal mean of each
/// beat's rate is not: a beat error `e` would add `e²` to it). A bin's
/// span is the time its samples stand for.
pub(crate) fn rates_to_bins(
    times: &[f64],
    r: &[f64],
    durations: Option<&[f64]>,
    length: f64,
) -> Bins {
    let mut bins = Bins::default();
    let n = times.len();
    // The samples' typical spacing: the time one sample stands for.
    let stride = (n / 10_000).max(1);
    let mut gaps: Vec<f64> = times
        .windows(2)
        .step_by(stride)
        .map(|w| w[1] - w[0])
        .collect();
    let spacing = if gaps.is_empty() {
        length
    } else {
        let h = gaps.len() / 2;
        *gaps.select_nth_unstable_by(h, f64::total_cmp).1
    };
    let mut parts = Vec::new();
    let mut i = 0;
    while i < n {
        let k = ((times[i] - times[0]) / length).floor();
        let a = i;
        while i < n && ((times[i] - times[0]) / length).floor() == k {
            i += 1;
        }
        let b = i;
        let total = durations.map_or((b - a) as f64, |d| d[a..b].iter().sum::<f64>());
        parts.clear();
        parts.extend((a..b).map(|s| (s, durations.map_or(1.0, |d| d[s]) / total)));
        let mean = parts.iter().map(|&(s, u)| u * r[s]).sum::<f64>();
        let count = (b - a) as f64;
        let span = match durations {
            Some(_) => total,
            None if b - a > 1 => (times[b - 1] - times[a]) * count / (count - 1.0),
            None => spacing.min(length),
        };
        bins.push(&parts, mean, span, times);
    }
    bins.finish()
}

/// Each interval's mean of `values` (read at the samples, linear between;
/// non-finite: not read, the last value held): interval 0 the first
/// value, interval `j` the mean of the values at its ends. With a daily
/// `cycle`, the cycle's exact mean and the rest's linear one.
pub(crate) fn interval_means(
    times: &[f64],
    values: &[f64],
    cycle: Option<&DailyCycle>,
) -> Vec<f64> {
    let rest = less_cycle(times, values, cycle);
    let mut out = Vec::with_capacity(rest.len());
    let mut last = rest.iter().copied().find(|v| v.is_finite());
    for (j, &v) in rest.iter().enumerate() {
        let before = last;
        if v.is_finite() {
            last = Some(v);
        }
        let linear = match (j, before, last) {
            (0, _, Some(l)) => l,
            (_, Some(a), Some(b)) => 0.5 * (a + b),
            _ => f64::NAN,
        };
        out.push(
            linear
                + cycle.map_or(0.0, |c| {
                    let (lo, hi) = if j == 0 {
                        (times[0], times[0])
                    } else {
                        (times[j - 1], times[j])
                    };
                    c.mean(lo, hi, 0.0)
                }),
        );
    }
    out
}

/// `values` less the cycle at their times.
fn less_cycle<'a>(
    times: &[f64],
    values: &'a [f64],
    cycle: Option<&DailyCycle>,
) -> std::borrow::Cow<'a, [f64]> {
    match cycle {
        Some(c) => std::borrow::Cow::Owned(
            times
                .iter()
                .zip(values)
                .map(|(&t, &v)| v - c.at(t))
                .collect(),
        ),
        None => std::borrow::Cow::Borrowed(values),
    }
}

/// Each interval's mean of `values` (as [`interval_means`]) after a
/// first-order lag `dL/dt = (v − L)/τ` starting at the first value.
///
/// Method: over an interval of length `Δ` the input runs linearly from
/// `a` to `b` (slope `s`), so `L(t) = v(t) − sτ + (L₀ − a + sτ) e^{−t/τ}`
/// exactly; its mean over the interval is `(a + b)/2 − sτ + (L₀ − a +
/// sτ)(τ/Δ)(1 − e^{−Δ/τ})`. Exact to rounding for piecewise-linear
/// input (test `lagged_means_of_a_ramp_and_a_step`); `τ = 0` gives the
/// values' own means. The exponentials are computed afresh only when the
/// spacing changes.
pub(crate) fn lagged_interval_means(
    times: &[f64],
    values: &[f64],
    tau: f64,
    cycle: Option<&DailyCycle>,
) -> Vec<f64> {
    if tau <= 0.0 {
        return interval_means(times, values, cycle);
    }
    let rest = less_cycle(times, values, cycle);
    lagged_rest(times, &rest, tau, cycle)
}

/// [`lagged_interval_means`] of `values` whose `cycle` is already taken
/// out.
fn lagged_rest(times: &[f64], values: &[f64], tau: f64, cycle: Option<&DailyCycle>) -> Vec<f64> {
    let mut out = Vec::with_capacity(values.len());
    let Some(mut level) = values.iter().copied().find(|v| v.is_finite()) else {
        return vec![f64::NAN; values.len()];
    };
    let mut held = level;
    let (mut dt, mut decay, mut mean_factor) = (f64::NAN, 0.0, 0.0);
    out.push(level);
    for j in 1..values.len() {
        let step = times[j] - times[j - 1];
        if step != dt {
            dt = step;
            let x = step / tau;
            decay = (-x).exp();
            // (1 − e^{−x})/x, without cancellation for small x.
            mean_factor = if x > 1e-12 { -(-x).exp_m1() / x } else { 1.0 };
        }
        let a = held;
        let b = if values[j].is_finite() { values[j] } else { a };
        let s_tau = (b - a) / step * tau;
        let start = level - a + s_tau;
        out.push(0.5 * (a + b) - s_tau + start * mean_factor);
        level = b - s_tau + start * decay;
        held = b;
    }
    if let Some(c) = cycle {
        out[0] += c.mean(times[0], times[0], tau);
        for j in 1..out.len() {
            out[j] += c.mean(times[j - 1], times[j], tau);
        }
    }
    out
}

/// A shorter copy of a log's weather for searching a lag: at most
/// `most` knots, each the mean time and mean value of a run of
/// consecutive samples, with the bins' parts moved onto the knots'
/// intervals (each sample's interval onto the knot interval that holds
/// its end). Lagging it costs `most` steps instead of one a sample; the
/// input it lags is the weather linear between the runs' means, which
/// differs from the samples' own only by what changes within a run.
pub(crate) struct Coarse {
    pub times: Vec<f64>,
    pub values: Vec<f64>,
    pub bins: Bins,
    /// The weather's daily cycle, taken out of `values` and added back
    /// exactly.
    pub cycle: Option<DailyCycle>,
}

impl Coarse {
    pub fn new(
        bins: &Bins,
        times: &[f64],
        values: &[f64],
        cycle: Option<DailyCycle>,
        most: usize,
    ) -> Coarse {
        let rest = less_cycle(times, values, cycle.as_ref());
        let values: &[f64] = &rest;
        let n = times.len();
        let size = n.div_ceil(most.max(2)).max(1);
        let knots = n.div_ceil(size);
        let (mut kt, mut kv) = (Vec::with_capacity(knots), Vec::with_capacity(knots));
        for run in 0..knots {
            let (a, b) = (run * size, ((run + 1) * size).min(n));
            let (mut t, mut v, mut c) = (0.0, 0.0, 0usize);
            for i in a..b {
                if values[i].is_finite() {
                    v += values[i];
                    c += 1;
                }
                t += times[i];
            }
            kt.push(t / (b - a) as f64);
            kv.push(if c > 0 { v / c as f64 } else { f64::NAN });
        }
        // Interval j (sample j − 1 to j) goes to the knot interval that
        // holds its end: the one ending at the knot of j's run when j is
        // before that knot, else the next.
        let mut coarse = Bins::default();
        let mut merged: Vec<(usize, f64)> = Vec::new();
        for &(a, b) in &bins.ranges {
            merged.clear();
            for &(j, u) in &bins.parts[a..b] {
                let run = j / size;
                let k = if times[j] <= kt[run] || run + 1 == knots {
                    run
                } else {
                    run + 1
                };
                match merged.last_mut() {
                    Some(last) if last.0 == k => last.1 += u,
                    _ => merged.push((k, u)),
                }
            }
            let start = coarse.parts.len();
            coarse.parts.extend_from_slice(&merged);
            coarse.ranges.push((start, coarse.parts.len()));
        }
        Coarse {
            times: kt,
            values: kv,
            bins: coarse,
            cycle,
        }
    }

    /// Each bin's mean of the weather lagged by `tau`.
    pub fn lagged_means(&self, tau: f64) -> Vec<f64> {
        let means = if tau > 0.0 {
            lagged_rest(&self.times, &self.values, tau, self.cycle.as_ref())
        } else {
            // The rest's means and the cycle's.
            let mut m = interval_means(&self.times, &self.values, None);
            if let Some(c) = &self.cycle {
                m[0] += c.mean(self.times[0], self.times[0], 0.0);
                for (j, v) in m.iter_mut().enumerate().skip(1) {
                    *v += c.mean(self.times[j - 1], self.times[j], 0.0);
                }
            }
            m
        };
        self.bins.average(&means)
    }
}

/// Cumulative sums and counts of `values`' finite samples, each with a
/// leading zero: the sum over `a..b` is `sum[b] - sum[a]`.
pub(crate) fn cumulative(values: &[f64]) -> (Vec<f64>, Vec<usize>) {
    let mut sum = Vec::with_capacity(values.len() + 1);
    let mut count = Vec::with_capacity(values.len() + 1);
    let (mut s, mut c) = (0.0, 0usize);
    sum.push(s);
    count.push(c);
    for v in values {
        if v.is_finite() {
            s += v;
            c += 1;
        }
        sum.push(s);
        count.push(c);
    }
    (sum, count)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ramp's lag and a step's, against their closed forms integrated
    /// by the trapezoid rule on a fine grid.
    #[test]
    fn lagged_means_of_a_ramp_and_a_step() {
        let tau = 5.0;
        // Samples 0, 2, 3, 7, 8: a ramp of slope 0.5 from 1, then held.
        let times = [0.0, 2.0, 3.0, 7.0, 8.0];
        let values = [1.0, 2.0, 2.5, 4.5, 4.5];
        let means = lagged_interval_means(&times, &values, tau, None);
        // The input linear between samples; the lag by tiny Euler steps.
        let input = |t: f64| {
            let i = times.iter().rposition(|&s| s <= t).unwrap().min(3);
            let w = (t - times[i]) / (times[i + 1] - times[i]);
            values[i] + w * (values[i + 1] - values[i])
        };
        let h = 1e-5;
        let mut level = 1.0;
        let mut t = 0.0;
        for j in 1..times.len() {
            let (mut area, steps) = (0.0, ((times[j] - times[j - 1]) / h).round() as usize);
            for _ in 0..steps {
                // Heun's step of dL/dt = (v − L)/τ.
                let k1 = (input(t) - level) / tau;
                let k2 = (input(t + h) - (level + h * k1)) / tau;
                let next = level + 0.5 * h * (k1 + k2);
                area += 0.5 * h * (level + next);
                level = next;
                t += h;
            }
            let expected = area / (times[j] - times[j - 1]);
            assert!(
                (means[j] - expected).abs() < 1e-8,
                "interval {j}: {} against {expected}",
                means[j]
            );
        }
        // No lag: the trapezoid means.
        let plain = lagged_interval_means(&times, &values, 0.0, None);
        assert_eq!(plain[1], 1.5);
        assert_eq!(plain[0], 1.0);
    }

    /// A bin of one interval is the offsets' difference; a dense bin is
    /// the slope, its parts summing to one.
    #[test]
    fn offsets_bin_by_their_intervals() {
        let times: Vec<f64> = (0..5).map(|i| i as f64 * 86_400.0).collect();
        let x: Vec<f64> = vec![0.0, 1.0, 1.5, 3.5, 4.0];
        let bins = offsets_to_bins(&times, &x, 86_400.0);
        assert_eq!(bins.rate, vec![1.0, 0.5, 2.0, 0.5]);
        assert_eq!(bins.centre[0], 43_200.0);
        let times: Vec<f64> = (0..100).map(|i| i as f64 * 36.0).collect();
        let x: Vec<f64> = times.iter().map(|t| 2e-5 * t).collect();
        let bins = offsets_to_bins(&times, &x, 3600.0);
        assert!((bins.rate[0] - 2e-5 * 86_400.0).abs() < 1e-12);
        for &(a, b) in &bins.ranges {
            let s: f64 = bins.parts[a..b].iter().map(|p| p.1).sum();
            assert!((s - 1.0).abs() < 1e-12);
        }
    }
}
