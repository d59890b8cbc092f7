//! The periodic errors of a log: the spectrum of what the model's
//! weather, drift and steps leave of the rate (so a daily swing of the
//! room is not read as the tide), the wheels' folds, the beat error and
//! the swing's Q.

use super::spectrum::{spectrum, Spectrum, TIDAL_LINES};
use super::swing::Swing;
use super::wheels::{folds, Arbor, Fold};
use crate::analysis::Refusal;
use crate::stability::DataKind;

/// What the periodic analyses read.
pub(crate) struct Periodic<'a> {
    /// The samples' times, s.
    pub times: &'a [f64],
    /// Offsets (s) or fractional rates a sample.
    pub raw: &'a [f64],
    /// Which.
    pub kind: DataKind,
    /// For half periods: the nominal half period, s.
    pub half: Option<f64>,
    /// The samples' typical spacing, s.
    pub dt: f64,
    /// The train's arbors.
    pub arbors: &'a [Arbor],
    /// Q and the energy's scatter, found before binning.
    pub swing: Option<Swing>,
    /// The model's terms but the tide and the constant, s/day, at the
    /// bins' times (linear between, held beyond): taken from the rate
    /// before its spectrum.
    pub model: (&'a [f64], &'a [f64]),
}

/// What they found.
pub(crate) struct PeriodicFound {
    pub spectrum: Option<Spectrum>,
    pub folds: Vec<Fold>,
    pub swing: Option<Swing>,
    pub beat_error_s: Option<f64>,
}

/// `values` at `t` linear between `(times, values)`, held beyond.
fn interpolate(times: &[f64], values: &[f64], t: f64) -> f64 {
    match times.partition_point(|&c| c < t) {
        0 => values.first().copied().unwrap_or(0.0),
        k if k >= times.len() => values.last().copied().unwrap_or(0.0),
        k => {
            let w = (t - times[k - 1]) / (times[k] - times[k - 1]);
            values[k - 1] + w * (values[k] - values[k - 1])
        }
    }
}

/// The mean of the finite values at even and at odd indices (`None`
/// when either parity has none).
fn parity_means(values: impl Iterator<Item = (usize, f64)>) -> Option<[f64; 2]> {
    let (mut s, mut c) = ([0.0; 2], [0usize; 2]);
    for (j, v) in values.filter(|(_, v)| v.is_finite()) {
        s[j % 2] += v;
        c[j % 2] += 1;
    }
    (c[0] > 0 && c[1] > 0).then(|| [s[0] / c[0] as f64, s[1] / c[1] as f64])
}

/// Takes the alternation of a series a beat out: each parity's mean
/// moved to the mean of the two.
fn take_out_alternation(values: &mut [f64]) {
    let Some(m) = parity_means(values.iter().copied().enumerate()) else {
        return;
    };
    let shift = [0.5 * (m[0] - m[1]), 0.5 * (m[1] - m[0])];
    for (j, v) in values.iter_mut().enumerate() {
        *v -= shift[j % 2];
    }
}

/// The grid the spectrum and the folds read: at most this many points.
const FINE_POINTS: f64 = 1_048_576.0;

/// The rate's spectrum on a grid of the samples' spacing (coarser when
/// that would exceed [`FINE_POINTS`]), the folds over the arbors (by
/// the count of beats for half periods, by the clock's time otherwise),
/// and the swing's Q from amplitudes a half swing.
pub(crate) fn periodic(p: &Periodic) -> Result<PeriodicFound, Refusal> {
    let times = p.times;
    let span = times[times.len() - 1] - times[0];
    let step = p.dt.max(span / FINE_POINTS);
    let gridded = crate::stability::grid(times, p.raw, Some(step))?.data;
    // The rate (s/day) a grid point, and the clock's own time there.
    let (rate, position): (Vec<f64>, Vec<f64>) = match p.kind {
        DataKind::Phase => {
            let rate: Vec<f64> = gridded
                .windows(2)
                .map(|w| (w[1] - w[0]) / step * 86_400.0)
                .collect();
            let mut last = 0.0;
            let position = (0..rate.len())
                .map(|j| {
                    if gridded[j].is_finite() {
                        last = gridded[j];
                    }
                    j as f64 * step + last
                })
                .collect();
            (rate, position)
        }
        DataKind::Frequency => {
            let rate: Vec<f64> = gridded.iter().map(|f| f * 86_400.0).collect();
            let mut clock = 0.0;
            let position = rate
                .iter()
                .enumerate()
                .map(|(j, r)| {
                    let at = j as f64 * step + clock;
                    if r.is_finite() {
                        clock += r / 86_400.0 * step;
                    }
                    at
                })
                .collect();
            (rate, position)
        }
    };
    let mut named: Vec<(String, f64)> = TIDAL_LINES
        .iter()
        .map(|(name, hours)| (name.to_string(), hours * 3600.0))
        .collect();
    named.extend(p.arbors.iter().map(|a| (a.name.clone(), a.period_s)));
    // What the model's weather, drift and steps leave of the rate.
    let t0 = times[0];
    let left: Vec<f64> = rate
        .iter()
        .enumerate()
        .map(|(j, r)| r - interpolate(p.model.0, p.model.1, t0 + (j as f64 + 0.5) * step))
        .collect();
    let spectrum = Some(spectrum(&detrended(&left), step, &named)).filter(|s| !s.points.is_empty());
    // Half periods are placed on their beat's slot (a gap advances the
    // count by the beats it spans): the folds read them by the count,
    // the beat error by its parity.
    let slots: Option<Vec<usize>> = p.half.map(|half| {
        let mut index = 0usize;
        (0..times.len())
            .map(|i| {
                if i > 0 {
                    index += ((times[i] - times[i - 1]) / half).round().max(1.0) as usize;
                }
                index
            })
            .collect()
    });
    let folds = match (p.half, &slots) {
        (Some(half), Some(slots)) if !p.arbors.is_empty() => {
            let last = slots.last().copied().unwrap_or(0);
            if last > 4 * times.len() {
                Vec::new()
            } else {
                let mut by_beat = vec![f64::NAN; last + 1];
                for (&slot, f) in slots.iter().zip(p.raw) {
                    by_beat[slot] = f * 86_400.0;
                }
                // The beat error alternates every beat: a pattern of every
                // turn with an even count of beats, not a wheel's.
                take_out_alternation(&mut by_beat);
                folds(p.arbors, by_beat, &|j| j as f64 * half, half)
            }
        }
        _ => folds(p.arbors, rate.clone(), &|j| position[j], step),
    };
    // Tick and tock: alternate half periods differ by twice the beat error.
    let beat_error_s = p.half.zip(slots.as_ref()).map(|(half, slots)| {
        parity_means(slots.iter().copied().zip(p.raw.iter().copied()))
            .map_or(0.0, |m| 0.5 * half * (m[0] - m[1]).abs())
    });
    Ok(PeriodicFound {
        spectrum,
        folds,
        swing: p.swing.clone(),
        beat_error_s,
    })
}

/// The half swings a cycle of the swing takes: the least common multiple
/// of the impulse's period (from `swing`) and the escape wheel's turn
/// (`escape_beats`), when one of them is known and the cycle is under half
/// a bin (`bin_beats`).
pub(crate) fn whole_cycle(
    swing: Option<&Swing>,
    escape_beats: Option<f64>,
    bin_beats: f64,
) -> Option<usize> {
    let impulse = swing
        .filter(|s| s.q.is_some())
        .and_then(|s| s.half_swings_per_impulse)
        .map(|n| n.round() as usize)
        .filter(|&n| n >= 2);
    let escape = escape_beats.map(|b| b.round() as usize).filter(|&b| b >= 2);
    let gcd = |mut a: usize, mut b: usize| {
        while b > 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let cycle = match (impulse, escape) {
        (Some(a), Some(b)) => a / gcd(a, b) * b,
        (a, b) => a.or(b)?,
    };
    (cycle >= 2 && (cycle as f64) < bin_beats / 2.0).then_some(cycle)
}

/// The centred running mean of `values` over `window` samples (at the
/// ends the first or last `window`; NaN left out).
pub(crate) fn running_mean(values: &[f64], window: usize) -> Vec<f64> {
    let n = values.len();
    let (sum, count) = super::series::cumulative(values);
    (0..n)
        .map(|i| {
            // A whole window at the ends too, moved inward: a part of a
            // cycle would bring its pattern back.
            let a = i.saturating_sub(window / 2).min(n.saturating_sub(window));
            let b = (a + window).min(n);
            let c = count[b] - count[a];
            if c > 0 && values[i].is_finite() {
                (sum[b] - sum[a]) / c as f64
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// `values` less their least-squares line (NaN kept).
fn detrended(values: &[f64]) -> Vec<f64> {
    let (mut n, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (j, &v) in values.iter().enumerate().filter(|(_, v)| v.is_finite()) {
        let x = j as f64;
        n += 1.0;
        sx += x;
        sy += v;
        sxx += x * x;
        sxy += x * v;
    }
    let d = n * sxx - sx * sx;
    let (slope, intercept) = if d > 0.0 {
        let b = (n * sxy - sx * sy) / d;
        (b, (sy - b * sx) / n)
    } else {
        (0.0, if n > 0.0 { sy / n } else { 0.0 })
    };
    values
        .iter()
        .enumerate()
        .map(|(j, v)| v - intercept - slope * j as f64)
        .collect()
}
