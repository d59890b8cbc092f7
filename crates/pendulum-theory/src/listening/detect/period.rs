//! The beat period from the envelope's autocorrelation.

use super::median;
use realfft::RealFftPlanner;

/// The beat period (s) of an envelope at `rate` values per second: the
/// first strong peak of its autocorrelation between `min` and `max` s.
/// `None` when no peak stands out (silence, noise, too short a record).
pub fn beat_period(envelope: &[f32], rate: f64, min: f64, max: f64) -> Option<f64> {
    let n = envelope.len().min((300.0 * rate) as usize);
    // At least four beats in the record; 2% of margin below the shortest
    // beat and 3% above the longest, so that a 50 ms beat running fast
    // and a 2 s beat running slow are found.
    if !(min > 0.0 && max > min && max.is_finite() && rate > 0.0 && rate.is_finite()) {
        return None;
    }
    let lo = ((0.98 * min * rate).floor() as usize).max(2);
    let hi = ((1.03 * max * rate).ceil() as usize).min(n / 4);
    if hi <= lo.saturating_add(2) {
        return None;
    }
    let values: Vec<f64> = envelope[..n].iter().map(|&v| f64::from(v)).collect();
    let mean = values.iter().sum::<f64>() / n as f64;
    let size = (2 * n).next_power_of_two();
    let mut planner = RealFftPlanner::<f64>::new();
    let forward = planner.plan_fft_forward(size);
    let inverse = planner.plan_fft_inverse(size);
    let mut input = forward.make_input_vec();
    for (slot, &v) in input.iter_mut().zip(&values) {
        *slot = v - mean;
    }
    let mut spectrum = forward.make_output_vec();
    forward.process(&mut input, &mut spectrum).ok()?;
    for c in &mut spectrum {
        *c = realfft::num_complex::Complex::new(c.norm_sqr(), 0.0);
    }
    let mut ac = inverse.make_output_vec();
    inverse.process(&mut spectrum, &mut ac).ok()?;
    let zero = ac[0];
    if zero <= 0.0 {
        return None;
    }
    // Unbiased (divided by the overlap), then averaged over ±1 ms (narrow:
    // a tick's own length, the most sensitive) and weighted by a triangle
    // of ±10 ms (broad: the autocorrelation of the envelope smoothed over
    // 10 ms; a beat error of a few ms splits the tick-to-tock peak in two,
    // which the broad average joins again).
    let top = (hi + (0.012 * rate) as usize + 2).min(n - 1);
    let unbiased: Vec<f64> = (0..=top)
        .map(|lag| ac[lag] / zero * n as f64 / (n - lag) as f64)
        .collect();
    let averaged = |v: &[f64], half: usize| -> Vec<f64> {
        (0..=top)
            .map(|l| {
                let (a, b) = (l.saturating_sub(half), (l + half).min(top));
                v[a..=b].iter().sum::<f64>() / (b - a + 1) as f64
            })
            .collect()
    };
    let narrow = averaged(&unbiased, ((0.001 * rate) as usize).max(1));
    let five = ((0.005 * rate) as usize).max(1);
    let broad = averaged(&averaged(&unbiased, five), five);
    let peaks = |v: &[f64], from: usize, to: usize| -> Option<usize> {
        (from.max(1)..to.min(top))
            .filter(|&l| v[l] >= v[l - 1] && v[l] >= v[l + 1])
            .max_by(|&a, &b| v[a].total_cmp(&v[b]))
    };
    // The highest local peak of the narrow average (the falling flank from
    // lag 0 is not one). It must stand out of the noise: five robust
    // standard deviations (1.4826 median absolute deviations) above the
    // median over all lags searched (most lags fall between the beats; the
    // largest of 4,000 lags of noise is 3.7 standard deviations).
    let sharp = peaks(&narrow, lo + 1, hi)?;
    let mut all: Vec<f64> = narrow[lo..=hi].to_vec();
    let centre = median(&mut all);
    let mut deviations: Vec<f64> = all.iter().map(|v| (v - centre).abs()).collect();
    let spread = 1.4826 * median(&mut deviations);
    // A fast clock fills every lag with peaks and troughs and so the
    // spread: there an autocorrelation far above what noise of this length
    // gives (ten times 1/√n) is enough.
    let strong = narrow[sharp] >= (10.0 / (n as f64).sqrt()).max(0.1);
    if (narrow[sharp] < centre + 5.0 * spread && !strong) || narrow[sharp] <= 0.0 {
        return None;
    }
    // The same peak on the broad average.
    let reach = ((0.01 * rate) as usize).max(2);
    let best = peaks(
        &broad,
        sharp.saturating_sub(reach).max(lo),
        sharp + reach + 1,
    )
    .unwrap_or(sharp);
    // The first strong peak: the shortest whole fraction of the best lag
    // where the autocorrelation peaks nearly as high is the beat (tick and
    // tock sound alike, so the best lag may be two, three or more beats).
    let mut lag = best;
    for m in (2..=best / lo.max(1)).rev() {
        let target = (best + m / 2) / m;
        let (from, to) = (
            target.saturating_sub(reach).max(lo),
            (target + reach).min(hi),
        );
        if from >= to {
            continue;
        }
        let Some(around) = (from..=to).max_by(|&a, &b| broad[a].total_cmp(&broad[b])) else {
            continue;
        };
        let is_peak = around > from && around < to;
        if is_peak && broad[around] >= 0.6 * broad[best] {
            lag = around;
            break;
        }
    }
    // To a fraction of a lag by a parabola through the peak: on the narrow
    // average at two beats (tick to tick, which no beat error splits) when
    // it is there, else on the broad one at the beat.
    let vertex = |v: &[f64], l: usize| -> f64 {
        let (a, b, c) = (v[l - 1], v[l], v[l + 1]);
        let denominator = a - 2.0 * b + c;
        let shift = if denominator < 0.0 {
            (0.5 * (a - c) / denominator).clamp(-0.5, 0.5)
        } else {
            0.0
        };
        l as f64 + shift
    };
    let two = 2 * lag;
    let fine = (two + reach < top)
        .then(|| peaks(&narrow, two - reach, two + reach + 1))
        .flatten()
        .filter(|&l| l > two - reach && l < two + reach);
    let lag = match fine {
        Some(l) => 0.5 * vertex(&narrow, l),
        None => vertex(&broad, lag),
    };
    Some(lag / rate)
}
