//! Periodic errors: the spectrum of a clock's rate, with the lines a
//! clock shows (the tides, the day, its wheels) measured and judged
//! against the noise around them.
//!
//! Method: the generalised Lomb–Scargle periodogram (Zechmeister &
//! Kürster 2009, A&A 496, 577, eqs. 4–20: a sinusoid and a constant
//! fitted by least squares at each frequency, so gaps and an offset mean
//! cost nothing). [`lomb_scargle`] evaluates it directly, O(N) a
//! frequency; [`gridded`] evaluates it at every frequency of a series on
//! a regular grid with gaps at once, from two zero-padded FFTs of the
//! weights and of the weighted values (the sums at ω and 2ω, as Press &
//! Rybicki 1989, ApJ 338, 277, but exact: the samples already sit on the
//! grid, so nothing is extirpolated). The two agree to 1e-9 and agree with
//! SciPy's `lombscargle(floating_mean=True)` to 1e-9 (test `clock_log.rs`,
//! reference from `tools/reference/lombscargle.py`).
//!
//! A named line's amplitude is the least-squares sinusoid at its exact
//! frequency. It is judged against the periodogram around it: the
//! powers within a factor 1.25 in frequency, away from every named line,
//! whose median over ln 2 is the mean noise power `P̄` (a periodogram of
//! noise is exponentially distributed, so the median is robust to other
//! peaks and follows a coloured noise's local level). The line's false
//! alarm probability is `exp(−A²/P̄)` and its amplitude's standard error
//! `sqrt(P̄/2)` (each quadrature's variance is half the noise power).

use realfft::RealFftPlanner;
use serde::Serialize;

/// The least-squares sinusoid at one frequency.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sinusoid {
    /// Its amplitude, in the values' unit.
    pub amplitude: f64,
    /// The normalised power: the share of the variance about the mean it
    /// explains, 0 to 1 (Zechmeister & Kürster's `p(ω)`).
    pub power: f64,
    /// Its phase: the fit is `amplitude · cos(2π f t − phase)`, rad.
    pub phase: f64,
}

/// The sums of the generalised periodogram at one ω (weights summing
/// to 1), turned into the fitted sinusoid.
#[allow(clippy::too_many_arguments)]
fn solve(y: f64, yy: f64, c: f64, s: f64, yc: f64, ys: f64, cc: f64, ss: f64, cs: f64) -> Sinusoid {
    let yy = yy - y * y;
    let yc = yc - y * c;
    let ys = ys - y * s;
    let cc = cc - c * c;
    let ss = ss - s * s;
    let cs = cs - c * s;
    let d = cc * ss - cs * cs;
    if d.is_nan() || yy.is_nan() || d <= 0.0 || yy <= 0.0 {
        return Sinusoid {
            amplitude: 0.0,
            power: 0.0,
            phase: 0.0,
        };
    }
    let a = (yc * ss - ys * cs) / d;
    let b = (ys * cc - yc * cs) / d;
    Sinusoid {
        amplitude: a.hypot(b),
        power: ((ss * yc * yc + cc * ys * ys - 2.0 * cs * yc * ys) / (yy * d)).clamp(0.0, 1.0),
        phase: b.atan2(a),
    }
}

/// The generalised Lomb–Scargle periodogram of `values` at `times` (s),
/// equal weights, at each of `frequencies_hz`: the least-squares
/// sinusoid plus constant. Non-finite values are left out. O(N) a
/// frequency.
pub fn lomb_scargle(times: &[f64], values: &[f64], frequencies_hz: &[f64]) -> Vec<Sinusoid> {
    let points: Vec<(f64, f64)> = times
        .iter()
        .zip(values)
        .filter(|(t, v)| t.is_finite() && v.is_finite())
        .map(|(&t, &v)| (t, v))
        .collect();
    let w = 1.0 / points.len().max(1) as f64;
    let t0 = points.first().map_or(0.0, |p| p.0);
    frequencies_hz
        .iter()
        .map(|&f| {
            let omega = std::f64::consts::TAU * f;
            let mut sums = [0.0; 9];
            for &(t, v) in &points {
                let (sin, cos) = (omega * (t - t0)).sin_cos();
                sums[0] += v;
                sums[1] += v * v;
                sums[2] += cos;
                sums[3] += sin;
                sums[4] += v * cos;
                sums[5] += v * sin;
                sums[6] += cos * cos;
                sums[7] += sin * sin;
                sums[8] += cos * sin;
            }
            let s = sums.map(|x| x * w);
            let mut fit = solve(s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7], s[8]);
            // The phase as of t = 0, not the first sample.
            fit.phase = (fit.phase + omega * t0).rem_euclid(std::f64::consts::TAU);
            fit
        })
        .collect()
}

/// The periodogram of a series on a regular grid of `step` s, NaN for a
/// gap, at every frequency `k / (L·step)` from the record's inverse
/// length to the Nyquist frequency, `L` the FFT length (at least twice
/// the series: the frequencies are spaced by at most half a record's
/// inverse length). Returns `(frequencies_hz, sinusoids)`; empty for
/// fewer than 3 values.
pub fn gridded(values: &[f64], step: f64) -> (Vec<f64>, Vec<Sinusoid>) {
    let n = values.len();
    let present = values.iter().filter(|v| v.is_finite()).count();
    if present < 3 || step.is_nan() || step <= 0.0 {
        return (Vec::new(), Vec::new());
    }
    let len = (2 * n).next_power_of_two();
    let w = 1.0 / present as f64;
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(len);
    let transform = |f: &dyn Fn(f64) -> f64| {
        let mut input = fft.make_input_vec();
        for (x, &v) in input.iter_mut().zip(values) {
            *x = if v.is_finite() { f(v) } else { 0.0 };
        }
        let mut output = fft.make_output_vec();
        // The lengths are the plan's own: this cannot fail.
        let _ = fft.process(&mut input, &mut output);
        output
    };
    let weights = transform(&|_| w);
    let weighted = transform(&|v| w * v);
    let (mut y, mut yy) = (0.0, 0.0);
    for v in values.iter().filter(|v| v.is_finite()) {
        y += w * v;
        yy += w * v * v;
    }
    // The transform at index k (any k below len): X_k, or conj(X_{len−k}).
    let at = |x: &[realfft::num_complex::Complex<f64>], k: usize| {
        let k = k % len;
        if k <= len / 2 {
            (x[k].re, -x[k].im)
        } else {
            (x[len - k].re, x[len - k].im)
        }
    };
    let first = len.div_ceil(n);
    let mut frequencies = Vec::with_capacity(len / 2);
    let mut fits = Vec::with_capacity(len / 2);
    for k in first..=len / 2 {
        // Σ w cos ωt = Re X_k, Σ w sin ωt = −Im X_k.
        let (c, s) = at(&weights, k);
        let (yc, ys) = at(&weighted, k);
        let (c2, s2) = at(&weights, 2 * k);
        frequencies.push(k as f64 / (len as f64 * step));
        fits.push(solve(
            y,
            yy,
            c,
            s,
            yc,
            ys,
            0.5 * (1.0 + c2),
            0.5 * (1.0 - c2),
            0.5 * s2,
        ));
    }
    (frequencies, fits)
}

/// A line a clock's rate may show.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Line {
    /// Its name: `M2`, `S2`, `K1`, `O1`, `day`, or a wheel's.
    pub name: String,
    /// Its period, s.
    pub period_s: f64,
    /// The amplitude of the rate's sinusoid at it, s/day.
    pub amplitude_s_per_day: f64,
    /// Its standard error from the noise around the line, s/day.
    pub amplitude_standard_error_s_per_day: Option<f64>,
    /// The amplitude over the noise's typical amplitude there.
    pub signal_to_noise: Option<f64>,
    /// The chance noise alone gives this much power at this frequency.
    pub false_alarm_probability: Option<f64>,
    /// Clearly there: a false alarm probability under 0.1%.
    pub seen: bool,
    /// Another named line closer in frequency than the record resolves
    /// (one over its length): the amplitude is of both together.
    pub blended_with: Option<String>,
}

/// A point of the spectrum as shown: the largest amplitude within a
/// band of frequencies (so no peak is lost to thinning).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpectrumPoint {
    /// Period, s.
    pub period_s: f64,
    /// The rate's sinusoid amplitude, s/day.
    pub amplitude_s_per_day: f64,
}

/// The spectrum of a clock's rate.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Spectrum {
    /// The grid the rate was put on, s.
    pub step_s: f64,
    /// The periodogram, at most [`SHOWN`] points from the longest period
    /// to the shortest.
    pub points: Vec<SpectrumPoint>,
    /// The named lines within its range, longest period first.
    pub lines: Vec<Line>,
}

/// Points of the spectrum kept for showing.
pub const SHOWN: usize = 2000;

/// The tidal constituents a clock may show, with the day: name and
/// period in hours (Doodson's; Cartwright & Tayler 1971).
pub const TIDAL_LINES: [(&str, f64); 5] = [
    ("O1", 25.819_341_7),
    ("day", 24.0),
    ("K1", 23.934_469_6),
    ("M2", 12.420_601_2),
    ("S2", 12.0),
];

/// The false alarm probability under which a line counts as seen.
pub const SEEN_BELOW: f64 = 1e-3;

/// The spectrum of `rate` (s/day, on a grid of `step` s, NaN for gaps)
/// with `named` lines (name, period s) measured; a line is kept when
/// its period lies between two steps and the record's length.
pub fn spectrum(rate: &[f64], step: f64, named: &[(String, f64)]) -> Spectrum {
    let (frequencies, fits) = gridded(rate, step);
    let record = rate.len() as f64 * step;
    let times: Vec<f64> = (0..rate.len()).map(|j| j as f64 * step).collect();
    let within: Vec<&(String, f64)> = named
        .iter()
        .filter(|(_, p)| *p >= 2.0 * step && *p <= record)
        .collect();
    let line_fits = lomb_scargle(
        &times,
        rate,
        &within.iter().map(|(_, p)| 1.0 / p).collect::<Vec<_>>(),
    );
    let resolution = 1.0 / record;
    let lines = within
        .iter()
        .zip(&line_fits)
        .map(|(&(name, period), fit)| {
            let f = 1.0 / period;
            // The noise around: within a factor 1.25, two resolutions
            // away from every named line.
            let mut around: Vec<f64> = frequencies
                .iter()
                .zip(&fits)
                .filter(|(&g, _)| {
                    g > f / 1.25
                        && g < f * 1.25
                        && within
                            .iter()
                            .all(|(_, p)| (g - 1.0 / p).abs() > 2.0 * resolution)
                })
                .map(|(_, s)| s.amplitude * s.amplitude)
                .collect();
            let mean_power = (around.len() >= 8).then(|| {
                let half = around.len() / 2;
                *around.select_nth_unstable_by(half, f64::total_cmp).1 / std::f64::consts::LN_2
            });
            let mean_power = mean_power.filter(|&p| p > 0.0);
            let a2 = fit.amplitude * fit.amplitude;
            let fap = mean_power.map(|p| (-a2 / p).exp());
            Line {
                name: name.clone(),
                period_s: *period,
                amplitude_s_per_day: fit.amplitude,
                amplitude_standard_error_s_per_day: mean_power.map(|p| (p / 2.0).sqrt()),
                signal_to_noise: mean_power.map(|p| fit.amplitude / p.sqrt()),
                false_alarm_probability: fap,
                seen: fap.is_some_and(|p| p < SEEN_BELOW),
                blended_with: within
                    .iter()
                    .filter(|(other, p)| other != name && (1.0 / p - f).abs() < resolution)
                    .map(|(other, _)| other.clone())
                    .next(),
            }
        })
        .collect();
    Spectrum {
        step_s: step,
        points: thin(&frequencies, &fits),
        lines,
    }
}

/// The periodogram in at most [`SHOWN`] log-spaced bands of frequency,
/// each by its largest amplitude, longest period first.
fn thin(frequencies: &[f64], fits: &[Sinusoid]) -> Vec<SpectrumPoint> {
    let (Some(&lo), Some(&hi)) = (frequencies.first(), frequencies.last()) else {
        return Vec::new();
    };
    let bands = SHOWN as f64;
    let width = (hi / lo).ln() / bands;
    let mut out: Vec<SpectrumPoint> = Vec::new();
    let mut current: Option<(usize, SpectrumPoint)> = None;
    for (&f, s) in frequencies.iter().zip(fits) {
        let band = if width > 0.0 {
            (((f / lo).ln() / width) as usize).min(SHOWN - 1)
        } else {
            0
        };
        let point = SpectrumPoint {
            period_s: 1.0 / f,
            amplitude_s_per_day: s.amplitude,
        };
        match &mut current {
            Some((b, best)) if *b == band => {
                if point.amplitude_s_per_day > best.amplitude_s_per_day {
                    *best = point;
                }
            }
            _ => {
                if let Some((_, best)) = current.take() {
                    out.push(best);
                }
                current = Some((band, point));
            }
        }
    }
    if let Some((_, best)) = current {
        out.push(best);
    }
    out
}
