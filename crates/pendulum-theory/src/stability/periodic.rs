//! A periodic signal in a frequency series (a room's daily cycle, a
//! wheel's turn), which the deviations read as noise that changes type
//! from one τ to the next.
//!
//! Method: the periodogram of the fractional frequency (gaps at the
//! mean, the least-squares line taken out, zero-padded to twice a power
//! of two, `realfft`), each power against the median of the powers within
//! a factor 2 in frequency about it (a periodogram of noise is
//! exponentially distributed about the local level, so the median follows
//! a coloured noise). A peak more than [`PEAK_OVER_MEDIAN`] times its
//! neighbourhood's median (a chance of exp(−60 ln 2) ≈ 1e-18 a frequency
//! for noise) whose sinusoid holds at least a tenth of the series'
//! variance is a periodic signal. Its amplitude is the least-squares
//! sinusoid at the peak (refined by a parabola through the three powers
//! about it). A sinusoidal frequency `y = A sin(2πt/P)` has the Allan
//! variance `A² sin⁴(πτ/P)/(πτ/P)²` (W. J. Riley, *Handbook of Frequency
//! Stability Analysis*, NIST SP 1065, 2008, section 9.4; checked against
//! the overlapping Allan deviation of a sampled sinusoid in the test): a
//! row where that is more than half the measured variance is the
//! signal's, not noise.

use realfft::RealFftPlanner;
use serde::Serialize;

/// How far above its neighbourhood's median a peak must stand.
pub const PEAK_OVER_MEDIAN: f64 = 60.0;

/// A periodic signal found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PeriodicSignal {
    /// Its period, s.
    pub period_s: f64,
    /// Its amplitude, fractional frequency.
    pub amplitude: f64,
    /// The same as a rate, s/day.
    pub amplitude_s_per_day: f64,
    /// The share of the series' variance it holds.
    pub share_of_variance: f64,
}

impl PeriodicSignal {
    /// Its Allan variance at `tau` (SP 1065 section 9.4).
    pub fn allan_variance(&self, tau: f64) -> f64 {
        let x = std::f64::consts::PI * tau / self.period_s;
        self.amplitude.powi(2) * x.sin().powi(4) / (x * x)
    }
}

/// The strongest periodic signal of `y` (fractional frequency, one every
/// `tau0` s, NaN a gap), if one stands out.
pub fn find_periodic(y: &[f64], tau0: f64) -> Option<PeriodicSignal> {
    let n = y.len();
    if n < 32 {
        return None;
    }
    let finite: Vec<(usize, f64)> = y
        .iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .map(|(i, &v)| (i, v))
        .collect();
    if finite.len() < 32 {
        return None;
    }
    // The least-squares line through the finite samples.
    let m = finite.len() as f64;
    let (sx, sy) = finite
        .iter()
        .fold((0.0, 0.0), |(a, b), &(i, v)| (a + i as f64, b + v));
    let (mx, my) = (sx / m, sy / m);
    let (mut sxx, mut sxy) = (0.0, 0.0);
    for &(i, v) in &finite {
        sxx += (i as f64 - mx).powi(2);
        sxy += (i as f64 - mx) * (v - my);
    }
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let detrended: Vec<f64> = y
        .iter()
        .enumerate()
        .map(|(i, &v)| {
            if v.is_finite() {
                v - my - slope * (i as f64 - mx)
            } else {
                0.0
            }
        })
        .collect();
    let variance = detrended.iter().map(|v| v * v).sum::<f64>() / m;
    if variance.is_nan() || variance <= 0.0 {
        return None;
    }
    let size = (2 * n).next_power_of_two();
    let mut buffer = detrended.clone();
    buffer.resize(size, 0.0);
    let mut planner = RealFftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(size);
    let mut spectrum = fft.make_output_vec();
    fft.process(&mut buffer, &mut spectrum).ok()?;
    let power: Vec<f64> = spectrum.iter().map(|c| c.norm_sqr()).collect();
    // Periods from 4 samples to half the series: bins k with
    // size/k between 4 and n/2 (in samples).
    let k_min = ((2 * size) / n).max(2);
    let k_max = (size / 4).min(power.len() - 2);
    if k_min >= k_max {
        return None;
    }
    let mut best: Option<(usize, f64)> = None;
    for k in k_min..=k_max {
        // A local maximum against the median of its octave about it.
        if power[k] < power[k - 1] || power[k] < power[k + 1] {
            continue;
        }
        let (lo, hi) = ((k / 2).max(1), (2 * k).min(power.len() - 1));
        let mut around: Vec<f64> = power[lo..=hi].to_vec();
        let h = around.len() / 2;
        let median = *around.select_nth_unstable_by(h, f64::total_cmp).1;
        let ratio = power[k] / median.max(f64::MIN_POSITIVE);
        if ratio > PEAK_OVER_MEDIAN && best.is_none_or(|b| ratio > b.1) {
            best = Some((k, ratio));
        }
    }
    let (k, _) = best?;
    // The peak refined by a parabola in the log powers.
    let (a, b, c) = (power[k - 1].ln(), power[k].ln(), power[k + 1].ln());
    let shift = 0.5 * (a - c) / (a - 2.0 * b + c);
    let frequency = (k as f64
        + if shift.is_finite() {
            shift.clamp(-0.5, 0.5)
        } else {
            0.0
        })
        / size as f64;
    // The least-squares sinusoid there (on the finite samples).
    let w = std::f64::consts::TAU * frequency;
    let (mut cc, mut ss, mut cs, mut yc, mut ys) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for &(i, _) in &finite {
        let (s, c) = (w * i as f64).sin_cos();
        let v = detrended[i];
        cc += c * c;
        ss += s * s;
        cs += c * s;
        yc += v * c;
        ys += v * s;
    }
    let d = cc * ss - cs * cs;
    if d.is_nan() || d <= 0.0 {
        return None;
    }
    let (p, q) = ((yc * ss - ys * cs) / d, (ys * cc - yc * cs) / d);
    let amplitude = p.hypot(q);
    let share = amplitude * amplitude / 2.0 / variance;
    (share >= 0.1).then(|| PeriodicSignal {
        period_s: tau0 / frequency,
        amplitude,
        amplitude_s_per_day: amplitude * 86_400.0,
        share_of_variance: share.min(1.0),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stability::{oadev, phase_from_frequency};
    use crate::test_noise::normals as noise;

    /// A daily cycle in a month of 10-minute rates is found to its
    /// period and amplitude; its Allan variance is the sampled sinusoid's;
    /// white noise alone gives none.
    #[test]
    fn a_daily_cycle_and_its_allan_variance() {
        let tau0 = 600.0;
        let n = 30 * 144;
        let e = noise(n, 5);
        let a = 3e-6;
        let y: Vec<f64> = (0..n)
            .map(|i| {
                a * (std::f64::consts::TAU * i as f64 * tau0 / 86_400.0 + 0.3).sin() + 5e-7 * e[i]
            })
            .collect();
        let found = find_periodic(&y, tau0).unwrap();
        assert!((found.period_s / 86_400.0 - 1.0).abs() < 2e-3, "{found:?}");
        assert!((found.amplitude / a - 1.0).abs() < 0.02, "{found:?}");
        // The formula against the sampled sinusoid's overlapping ADEV.
        let pure: Vec<f64> = (0..n)
            .map(|i| a * (std::f64::consts::TAU * i as f64 * tau0 / 86_400.0).sin())
            .collect();
        let x = phase_from_frequency(&pure, tau0);
        for m in [8usize, 36, 72, 100] {
            let tau = m as f64 * tau0;
            let measured = oadev(&x, tau0, m).unwrap();
            let formula = PeriodicSignal {
                period_s: 86_400.0,
                amplitude: a,
                amplitude_s_per_day: 0.0,
                share_of_variance: 1.0,
            }
            .allan_variance(tau)
            .sqrt();
            assert!(
                (measured / formula - 1.0).abs() < 0.05,
                "τ = {tau}: {measured} against {formula}"
            );
        }
        for seed in [1, 2, 3] {
            assert_eq!(find_periodic(&noise(n, seed), tau0), None);
        }
    }
}
