//! From a log as it comes (offsets, rates, half periods) to one rate per
//! bin, with the weather averaged over the same bins.

/// A jump of an offset series that is a whole beat: the reference's tick
/// compared with the clock's next tick slips by one beat.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Wrap {
    /// The log's time of the first sample after the jump, s.
    pub time_s: f64,
    /// The jump undone, s (a multiple of the beat).
    pub jump_s: f64,
}

/// Undoes whole-beat jumps of an offset series in place: a step between
/// neighbours larger than half a `beat` (given, or the smallest of the
/// large steps when every large step is within 2% of a multiple of it,
/// "large" being 50 times the median step) is taken back by its nearest
/// multiple of the beat. Returns the wraps undone.
pub(crate) fn unwrap(times: &[f64], x: &mut [f64], beat: Option<f64>) -> Vec<Wrap> {
    if x.len() < 2 {
        return Vec::new();
    }
    let step = |i: usize| x[i + 1] - x[i];
    let beat = match beat {
        Some(b) => b,
        None => {
            // The typical step from at most 100,000 of them, evenly spread.
            let stride = (x.len() / 100_000).max(1);
            let mut abs: Vec<f64> = (0..x.len() - 1)
                .step_by(stride)
                .map(|i| step(i).abs())
                .collect();
            let half = abs.len() / 2;
            let median = *abs.select_nth_unstable_by(half, f64::total_cmp).1;
            let large: Vec<f64> = (0..x.len() - 1)
                .map(|i| step(i).abs())
                .filter(|&s| s > 50.0 * median.max(1e-9) && s > 0.05)
                .collect();
            let Some(smallest) = large.iter().copied().reduce(f64::min) else {
                return Vec::new();
            };
            let whole = large.iter().all(|s| {
                let k = (s / smallest).round();
                (s / smallest - k).abs() < 0.02 * k
            });
            if !whole {
                return Vec::new();
            }
            smallest
        }
    };
    let mut wraps = Vec::new();
    let mut shift = 0.0;
    let mut previous = x[0];
    for i in 1..x.len() {
        let raw = x[i];
        let s = raw - previous;
        previous = raw;
        if s.abs() > 0.5 * beat {
            let k = (s / beat).round();
            shift -= k * beat;
            wraps.push(Wrap {
                time_s: times[i],
                jump_s: k * beat,
            });
        }
        x[i] += shift;
    }
    wraps
}

/// Bins of equal length over a log.
#[derive(Clone, Debug)]
pub(crate) struct Bins {
    /// Each bin's centre, s (the log's time).
    pub centre: Vec<f64>,
    /// Each bin's rate, s/day.
    pub rate: Vec<f64>,
    /// Each bin's weight: the time its rate spans over the median bin's.
    pub weight: Vec<f64>,
    /// The mean of each environment column over the bin.
    pub env: Vec<Vec<f64>>,
    /// Each bin's samples, as an index range.
    pub ranges: Vec<(usize, usize)>,
    /// Each sample's weight in its bin's mean of the weather: the weight
    /// its time has in the bin's rate (uniform for rates; for offsets,
    /// the least-squares slope's weight on the intervals either side of
    /// it, so that the weather is averaged as the rate is).
    pub sample_weight: Vec<f64>,
}

impl Bins {
    /// The mean of `values`' finite samples over each bin (NaN if none).
    pub fn means(&self, values: &[f64]) -> Vec<f64> {
        self.ranges
            .iter()
            .map(|&(a, b)| {
                let (mut s, mut w) = (0.0, 0.0);
                for (v, sw) in values[a..b].iter().zip(&self.sample_weight[a..b]) {
                    if v.is_finite() {
                        s += sw * v;
                        w += sw;
                    }
                }
                if w > 0.0 {
                    s / w
                } else {
                    mean_finite(&values[a..b])
                }
            })
            .collect()
    }
}

/// The mean of the finite values, NaN if none.
fn mean_finite(values: &[f64]) -> f64 {
    let (s, n) = values
        .iter()
        .filter(|v| v.is_finite())
        .fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    if n == 0 {
        f64::NAN
    } else {
        s / n as f64
    }
}

/// The samples of each bin of `length` s from the first time: `(start,
/// end)` index ranges, bins with too few samples left out.
fn ranges(times: &[f64], length: f64, least: usize) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let t0 = times[0];
    let mut start = 0;
    while start < times.len() {
        let k = ((times[start] - t0) / length).floor();
        let end_time = t0 + (k + 1.0) * length;
        let mut end = start;
        while end < times.len() && times[end] < end_time {
            end += 1;
        }
        if end - start >= least {
            out.push((start, end));
        }
        start = end;
    }
    out
}

/// Offsets (s) to binned rates: each bin's rate the least-squares slope
/// of its offsets (at least 3), which for white phase and white
/// frequency noise leaves neighbouring bins independent; weight its span.
pub(crate) fn offsets_to_bins(times: &[f64], x: &[f64], env: &[&[f64]], length: f64) -> Bins {
    let mut bins = empty(times.len());
    for (a, b) in ranges(times, length, 3) {
        let t = &times[a..b];
        let tm = t.iter().sum::<f64>() / t.len() as f64;
        let xm = x[a..b].iter().sum::<f64>() / t.len() as f64;
        let (mut sxy, mut sxx) = (0.0, 0.0);
        for i in a..b {
            sxy += (times[i] - tm) * (x[i] - xm);
            sxx += (times[i] - tm).powi(2);
        }
        if sxx <= 0.0 {
            continue;
        }
        // The slope is Σ W_j (x_j − x_{j−1}) with W_j = Σ_{i≥j} (t_i − t̄)/Sxx:
        // interval j's weight W_j Δt_j, shared by the samples at its ends.
        let mut tail = 0.0;
        for j in (a + 1..b).rev() {
            tail += (times[j] - tm) / sxx;
            let share = 0.5 * tail * (times[j] - times[j - 1]);
            bins.sample_weight[j] += share;
            bins.sample_weight[j - 1] += share;
        }
        push(
            &mut bins,
            tm,
            sxy / sxx * 86_400.0,
            t[t.len() - 1] - t[0],
            a,
            b,
        );
    }
    finish(bins, env)
}

/// Rates (s/day) to binned rates: the mean of each bin's, each sample
/// weighted by its `durations` when given (half periods: the bin's rate
/// is then its count of beats over its time, which an equal mean of each
/// beat's rate is not: a beat error `e` would add `e²` to it); weight its
/// samples' span.
pub(crate) fn rates_to_bins(
    times: &[f64],
    r: &[f64],
    durations: Option<&[f64]>,
    env: &[&[f64]],
    length: f64,
) -> Bins {
    let mut bins = empty(times.len());
    // The samples' typical spacing: the time one sample stands for.
    let stride = (times.len() / 10_000).max(1);
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
    for (a, b) in ranges(times, length, 1) {
        let n = (b - a) as f64;
        let tm = times[a..b].iter().sum::<f64>() / n;
        let total = durations.map_or(n, |d| d[a..b].iter().sum::<f64>());
        let weight = |i: usize| durations.map_or(1.0, |d| d[i]) / total;
        let mean = (a..b).map(|i| weight(i) * r[i]).sum::<f64>();
        // The time the bin's samples cover: a bin of one sample (the
        // log's last, say) stands for one spacing, not a whole bin.
        let span = match durations {
            Some(_) => total,
            None if b - a > 1 => (times[b - 1] - times[a]) * n / (n - 1.0),
            None => spacing.min(length),
        };
        for i in a..b {
            bins.sample_weight[i] = weight(i);
        }
        push(&mut bins, tm, mean, span, a, b);
    }
    finish(bins, env)
}

fn empty(samples: usize) -> Bins {
    Bins {
        sample_weight: vec![0.0; samples],
        centre: Vec::new(),
        rate: Vec::new(),
        weight: Vec::new(),
        env: Vec::new(),
        ranges: Vec::new(),
    }
}

fn push(bins: &mut Bins, t: f64, rate: f64, span: f64, a: usize, b: usize) {
    bins.centre.push(t);
    bins.rate.push(rate);
    bins.weight.push(span.max(1e-9));
    bins.ranges.push((a, b));
}

/// Weights relative to the median bin's span; the weather averaged as
/// the rates are.
fn finish(mut bins: Bins, env: &[&[f64]]) -> Bins {
    // An empty column (not in the log) gives NaN bins.
    bins.env = env
        .iter()
        .map(|values| {
            if values.is_empty() {
                vec![f64::NAN; bins.ranges.len()]
            } else {
                bins.means(values)
            }
        })
        .collect();
    let mut spans = bins.weight.clone();
    spans.sort_by(f64::total_cmp);
    if let Some(&median) = spans.get(spans.len() / 2) {
        for w in &mut bins.weight {
            *w /= median;
        }
    }
    bins
}

/// The first-order lag `dL/dt = (v − L)/τ` run sample by sample: exact
/// for a value held over the interval before its sample, starting at the
/// first value; with `τ = 0`, the values themselves.
struct Lag<'a> {
    times: &'a [f64],
    values: &'a [f64],
    tau: f64,
    level: f64,
    /// The last interval and its factor `1 − exp(−Δt/τ)`, computed afresh
    /// only when the spacing changes.
    dt: f64,
    factor: f64,
}

impl<'a> Lag<'a> {
    fn new(times: &'a [f64], values: &'a [f64], tau: f64) -> Self {
        Lag {
            times,
            values,
            tau,
            level: f64::NAN,
            dt: f64::NAN,
            factor: 0.0,
        }
    }

    /// The lagged value at sample `i` (called for `i = 0, 1, 2, …`).
    fn at(&mut self, i: usize) -> f64 {
        if i == 0 || self.tau <= 0.0 {
            self.level = self.values[i];
            return self.level;
        }
        let step = self.times[i] - self.times[i - 1];
        if step != self.dt {
            self.dt = step;
            self.factor = -(-step / self.tau).exp_m1();
        }
        if self.values[i].is_finite() {
            self.level += self.factor * (self.values[i] - self.level);
        }
        self.level
    }
}

/// Each bin's weighted mean of `values` lagged by `tau` (as [`lagged`]),
/// without keeping the lagged series.
pub(crate) fn lagged_means(bins: &Bins, times: &[f64], values: &[f64], tau: f64) -> Vec<f64> {
    let mut lag = Lag::new(times, values, tau);
    let mut next = 0;
    let mut out = Vec::with_capacity(bins.ranges.len());
    for &(start, end) in &bins.ranges {
        let (mut s, mut w) = (0.0, 0.0);
        for i in next..end {
            let level = lag.at(i);
            if i >= start && level.is_finite() {
                s += bins.sample_weight[i] * level;
                w += bins.sample_weight[i];
            }
        }
        next = end;
        out.push(if w > 0.0 { s / w } else { f64::NAN });
    }
    out
}

/// The first-order lag of `values` (at `times`) with time constant `tau`
/// s, every sample ([`Lag`]).
pub(crate) fn lagged(times: &[f64], values: &[f64], tau: f64) -> Vec<f64> {
    let mut lag = Lag::new(times, values, tau);
    (0..values.len()).map(|i| lag.at(i)).collect()
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
