//! The ticks of a recording, in two passes over the samples, each in fixed
//! memory but for what it keeps per tick:
//!
//! 1. [`Envelope`]: band-pass ([`super::filter::BandPass`]), a peak
//!    follower with a 1 ms release, kept at 2 kHz (the maximum of each
//!    0.5 ms). From it, [`beat_period`] (the autocorrelation of the first
//!    five minutes, by FFT, its first strong peak between 50 ms and 2 s,
//!    refined by a parabola) and [`coarse_onsets`]: each beat's onset to
//!    the envelope's 0.5 ms, found in a window around its prediction from
//!    the last beat of the same side (tick or tock: the beat error shifts
//!    one side), the first crossing of 30% of the window's rise above the
//!    noise floor (the unlocking sound, not the later drop).
//! 2. [`Refiner`]: the band-passed samples around each coarse onset; the
//!    median tick and the median tock of the first 128 of each, aligned on
//!    each other twice; each onset moved by the peak of its normalised
//!    cross-correlation with its side's median (to a fraction of a sample
//!    by a parabola through the peak); the onset of the median sound itself
//!    (the first crossing of a fifth of its peak) is the tick's time. A
//!    window whose correlation is below a third of the median correlation
//!    is noise, not a tick: it is dropped and counted as missed.
//! 3. [`drop_outliers`]: a tick 2 ms off the line its neighbours of the
//!    same side draw is a drop sound or a noise burst: dropped, counted.

use super::filter::BandPass;
use realfft::RealFftPlanner;

/// Envelope samples per second.
pub const ENVELOPE_RATE: f64 = 2000.0;

/// The envelope of a recording, fed in blocks.
#[derive(Clone, Debug)]
pub struct Envelope {
    filter: BandPass,
    decay: f64,
    level: f64,
    per_value: usize,
    count: usize,
    block_max: f64,
    /// The envelope, at [`ENVELOPE_RATE`] (the first value covers the first
    /// `per_value` samples).
    pub values: Vec<f32>,
    /// Audio samples per envelope value.
    pub samples_per_value: usize,
    /// Samples fed.
    pub samples: u64,
}

impl Envelope {
    /// An envelope for audio at `sample_rate`.
    pub fn new(sample_rate: f64) -> Self {
        let per_value = (sample_rate / ENVELOPE_RATE).round().max(1.0) as usize;
        Self {
            filter: BandPass::new(sample_rate),
            decay: (-1.0 / (1e-3 * sample_rate)).exp(),
            level: 0.0,
            per_value,
            count: 0,
            block_max: 0.0,
            values: Vec::new(),
            samples_per_value: per_value,
            samples: 0,
        }
    }

    /// Feeds samples.
    pub fn push(&mut self, samples: &[f32]) {
        for &x in samples {
            let y = self.filter.process(f64::from(x)).abs();
            self.level = y.max(self.level * self.decay);
            self.block_max = self.block_max.max(self.level);
            self.count += 1;
            if self.count == self.per_value {
                self.values.push(self.block_max as f32);
                self.count = 0;
                self.block_max = 0.0;
            }
        }
        self.samples += samples.len() as u64;
    }

    /// The time of envelope value `i` (its block's middle), in samples.
    fn rate(&self, sample_rate: f64) -> f64 {
        sample_rate / self.per_value as f64
    }
}

/// The beat period (s) of an envelope at `rate` values per second: the
/// first strong peak of its autocorrelation between `min` and `max` s.
/// `None` when no peak stands out (silence, noise, too short a record).
pub fn beat_period(envelope: &[f32], rate: f64, min: f64, max: f64) -> Option<f64> {
    let n = envelope.len().min((300.0 * rate) as usize);
    let (lo, hi) = ((min * rate).floor() as usize, (max * rate).ceil() as usize);
    if n < 2 * hi.min(n) || n < 4 || hi >= n {
        return None;
    }
    // Smoothed over 10 ms, so that a beat error of a few ms (tock shifted
    // against tick) does not split the beat's peak.
    let width = ((0.01 * rate) as usize).max(1);
    let mut smooth = vec![0.0_f64; n];
    let mut running = 0.0;
    for i in 0..n {
        running += f64::from(envelope[i]);
        if i >= width {
            running -= f64::from(envelope[i - width]);
        }
        smooth[i] = running / width as f64;
    }
    let mean = smooth.iter().sum::<f64>() / n as f64;
    let size = (2 * n).next_power_of_two();
    let mut planner = RealFftPlanner::<f64>::new();
    let forward = planner.plan_fft_forward(size);
    let inverse = planner.plan_fft_inverse(size);
    let mut input = forward.make_input_vec();
    for (slot, &v) in input.iter_mut().zip(&smooth) {
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
    // Unbiased: divide by the overlap.
    let value = |lag: usize| ac[lag] / zero * n as f64 / (n - lag) as f64;
    let best = (lo.max(1)..=hi).max_by(|&a, &b| value(a).total_cmp(&value(b)))?;
    if value(best) < 0.05 {
        return None;
    }
    // The first strong peak: a half of the best lag that is nearly as
    // strong is the beat (tick and tock sound alike).
    let mut lag = best;
    while lag / 2 >= lo.max(2) {
        let half = lag / 2;
        let reach = width.max(2);
        let around = (half.saturating_sub(reach)..=half + reach)
            .max_by(|&a, &b| value(a).total_cmp(&value(b)))
            .unwrap_or(half);
        if value(around) >= 0.6 * value(best) {
            lag = around;
        } else {
            break;
        }
    }
    let (a, b, c) = (value(lag - 1), value(lag), value(lag + 1));
    let denominator = a - 2.0 * b + c;
    let shift = if denominator < 0.0 {
        0.5 * (a - c) / denominator
    } else {
        0.0
    };
    Some((lag as f64 + shift) / rate)
}

/// Coarse onsets, s, with the beat numbers they belong to.
#[derive(Clone, Debug, PartialEq)]
pub struct Coarse {
    /// `(beat number from the first tick, onset s)`.
    pub onsets: Vec<(u64, f64)>,
    /// Beats with no tick found.
    pub missed: usize,
    /// The envelope's noise floor (its median).
    pub floor: f64,
    /// The typical tick peak of the envelope (median over ticks).
    pub peak: f64,
}

fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Each beat's onset on the envelope (see the module notes), for a beat of
/// `beat` s; `rate` is the envelope's values per second.
pub fn coarse_onsets(envelope: &[f32], rate: f64, beat: f64) -> Coarse {
    let n = envelope.len();
    let mut sample: Vec<f64> = envelope.iter().step_by(7).map(|&v| f64::from(v)).collect();
    let floor = median(&mut sample);
    let at = |t: f64| (t * rate).round().clamp(0.0, n as f64) as usize;
    // The window's rise and the first crossing of 30% of it.
    let find = |from: f64, to: f64| -> Option<(f64, f64)> {
        let (a, b) = (at(from), at(to));
        if b <= a + 1 {
            return None;
        }
        let (i_max, &max) = envelope[a..b]
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.total_cmp(y.1))?;
        let max = f64::from(max);
        let level = floor + 0.3 * (max - floor);
        // The sound's rise: within 25 ms before its peak (the drop, when it
        // is the louder, follows the unlocking by 8 to 20 ms); a noise
        // crest earlier in the window is not the tick.
        let back = (0.025 * rate) as usize;
        let from = (a + i_max).saturating_sub(back).max(a);
        // Two values in a row at the level (a sound lasts, a noise crest
        // does not: the follower halves in 0.7 ms).
        let peak_at = a + i_max;
        let i = (from..=peak_at).find(|&i| {
            f64::from(envelope[i]) >= level && (i == peak_at || f64::from(envelope[i + 1]) >= level)
        })?;
        let before = if i > 0 {
            f64::from(envelope[i - 1])
        } else {
            floor
        };
        let now = f64::from(envelope[i]);
        let fraction = if now > before {
            (level - before) / (now - before)
        } else {
            1.0
        };
        Some(((i as f64 - 1.0 + fraction.clamp(0.0, 1.0)) / rate, max))
    };
    let duration = n as f64 / rate;
    // Lock on: the loudest of the first beat and a half.
    let Some((first, first_peak)) = find(0.0, (1.5 * beat).min(duration)) else {
        return Coarse {
            onsets: Vec::new(),
            missed: 0,
            floor,
            peak: floor,
        };
    };
    // Walk back to the earliest beat of the record.
    let mut start = first;
    while start - beat > 0.005 {
        start -= beat;
    }
    let mut onsets: Vec<(u64, f64)> = Vec::new();
    let mut peaks: Vec<f64> = vec![first_peak];
    let mut typical = first_peak;
    let mut missed = 0;
    let mut k = 0_u64;
    loop {
        // Predict from the last onset of the same side, else of the other.
        let same = onsets.iter().rev().find(|(j, _)| (k - j) % 2 == 0);
        let other = onsets.last();
        let predicted = match (same, other) {
            (Some(&(j, t)), _) => t + (k - j) as f64 * beat,
            (None, Some(&(j, t))) => t + (k - j) as f64 * beat,
            (None, None) => start + k as f64 * beat,
        };
        if predicted > duration - 0.02 {
            break;
        }
        let locked = onsets.len() >= 4;
        let half = if locked {
            (0.004 + 0.02 * beat).min(0.4 * beat)
        } else {
            0.4 * beat
        };
        match find(predicted - half, predicted + half) {
            Some((t, peak)) if peak >= floor + 0.4 * (typical - floor) => {
                onsets.push((k, t));
                peaks.push(peak);
                if peaks.len() <= 64 || peaks.len() % 16 == 0 {
                    let mut p = peaks.clone();
                    typical = median(&mut p);
                }
            }
            _ => {
                if !onsets.is_empty() {
                    missed += 1;
                }
            }
        }
        k += 1;
    }
    Coarse {
        onsets,
        missed,
        floor,
        peak: typical,
    }
}

/// The refined tick of a coarse onset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tick {
    /// Beat number from the first tick.
    pub beat: u64,
    /// Onset, s.
    pub time: f64,
    /// 0 for a tick, 1 for a tock (the beat's parity).
    pub side: u8,
    /// The peak of the band-passed sound.
    pub amplitude: f64,
    /// Normalised correlation with its side's median sound.
    pub correlation: f64,
}

/// Ticks kept to build each side's median sound.
const TEMPLATE_TICKS: usize = 128;
/// Before and after the coarse onset in each window, s.
const PRE: f64 = 1.5e-3;
const POST: f64 = 4.5e-3;
/// The correlation search, either way, s.
const SEARCH: f64 = 1.0e-3;

/// The second pass: band-passed samples around each coarse onset, refined
/// by cross-correlation (see the module notes).
pub struct Refiner {
    rate: f64,
    filter: BandPass,
    coarse: Vec<(u64, f64)>,
    next: usize,
    /// Samples seen so far.
    position: u64,
    /// The most recent band-passed samples, with the index of the first.
    buffer: Vec<f32>,
    buffer_start: u64,
    /// Windows waiting for the templates: (beat, window start sample, samples).
    waiting: Vec<(u64, u64, Vec<f32>)>,
    templates: Option<[Template; 2]>,
    ticks: Vec<Tick>,
    rejected: usize,
    pre: usize,
    length: usize,
    search: usize,
}

#[derive(Clone, Debug)]
struct Template {
    samples: Vec<f32>,
    norm: f64,
    /// Where in the template the sound begins, samples.
    onset: f64,
    /// The median correlation of the ticks it was built from.
    typical: f64,
}

impl Refiner {
    /// A refiner of `coarse` onsets (from [`coarse_onsets`]) in audio at
    /// `sample_rate`.
    pub fn new(sample_rate: f64, coarse: &Coarse) -> Self {
        let pre = (PRE * sample_rate).round() as usize;
        let post = (POST * sample_rate).round() as usize;
        let search = (SEARCH * sample_rate).round().max(2.0) as usize;
        Self {
            rate: sample_rate,
            filter: BandPass::new(sample_rate),
            coarse: coarse.onsets.clone(),
            next: 0,
            position: 0,
            buffer: Vec::new(),
            buffer_start: 0,
            waiting: Vec::new(),
            templates: None,
            ticks: Vec::new(),
            rejected: 0,
            pre,
            length: pre + post,
            search,
        }
    }

    /// Feeds the next samples.
    pub fn push(&mut self, samples: &[f32]) {
        for &x in samples {
            self.buffer.push(self.filter.process(f64::from(x)) as f32);
        }
        self.position += samples.len() as u64;
        // Cut every window that is complete.
        let span = (self.length + 2 * self.search) as u64;
        while self.next < self.coarse.len() {
            let (beat, onset) = self.coarse[self.next];
            let start = ((onset * self.rate).round() as i64 - (self.pre + self.search) as i64)
                .max(0) as u64;
            if start + span > self.position {
                break;
            }
            let from = (start.saturating_sub(self.buffer_start)) as usize;
            let window = self.buffer[from..from + span as usize].to_vec();
            self.next += 1;
            self.take(beat, start, window);
        }
        // Keep only what a later window can need.
        let keep_from = self
            .coarse
            .get(self.next)
            .map(|&(_, t)| {
                ((t * self.rate) as i64 - (self.pre + 2 * self.search) as i64).max(0) as u64
            })
            .unwrap_or(self.position);
        if keep_from > self.buffer_start + 4096 {
            let drop = ((keep_from - self.buffer_start) as usize).min(self.buffer.len());
            self.buffer.drain(..drop);
            self.buffer_start += drop as u64;
        }
    }

    fn take(&mut self, beat: u64, start: u64, window: Vec<f32>) {
        match &self.templates {
            Some(_) => self.refine(beat, start, &window),
            None => {
                self.waiting.push((beat, start, window));
                let sides = [0, 1].map(|s| self.waiting.iter().filter(|w| w.0 % 2 == s).count());
                if sides.iter().all(|&c| c >= TEMPLATE_TICKS) {
                    self.build();
                }
            }
        }
    }

    /// The median sound of each side from the waiting windows, aligned on
    /// itself twice; then the waiting windows are refined.
    fn build(&mut self) {
        let mut templates = Vec::new();
        for side in 0..2_u64 {
            let windows: Vec<&Vec<f32>> = self
                .waiting
                .iter()
                .filter(|w| w.0 % 2 == side)
                .take(TEMPLATE_TICKS)
                .map(|w| &w.2)
                .collect();
            // Start aligned on the coarse onsets, then twice on the median.
            let mut shifts = vec![self.search; windows.len()];
            let mut template = self.median(&windows, &shifts);
            for _ in 0..2 {
                for (k, w) in windows.iter().enumerate() {
                    if let Some((lag, _)) = best_lag(w, &template, self.search) {
                        shifts[k] = lag.round().clamp(0.0, (2 * self.search) as f64) as usize;
                    }
                }
                template = self.median(&windows, &shifts);
            }
            let norm = template
                .iter()
                .map(|&v| f64::from(v) * f64::from(v))
                .sum::<f64>()
                .sqrt();
            let peak = template.iter().map(|v| v.abs()).fold(0.0_f32, f32::max);
            let level = 0.2 * peak;
            let onset =
                template
                    .iter()
                    .position(|v| v.abs() >= level)
                    .map_or(self.pre as f64, |i| {
                        let before = if i > 0 { template[i - 1].abs() } else { 0.0 };
                        let now = template[i].abs();
                        let f = if now > before {
                            (level - before) / (now - before)
                        } else {
                            1.0
                        };
                        i as f64 - 1.0 + f64::from(f.clamp(0.0, 1.0))
                    });
            let mut correlations: Vec<f64> = windows
                .iter()
                .filter_map(|w| {
                    let (lag, c) = best_lag(w, &template, self.search)?;
                    let energy = w
                        .iter()
                        .skip(lag.round().max(0.0) as usize)
                        .take(self.length)
                        .map(|&v| f64::from(v) * f64::from(v))
                        .sum::<f64>()
                        .sqrt();
                    (energy > 0.0 && norm > 0.0).then(|| c / (energy * norm))
                })
                .collect();
            let typical = median(&mut correlations);
            templates.push(Template {
                samples: template,
                norm,
                onset,
                typical,
            });
        }
        let [tick, tock]: [Template; 2] = templates.try_into().expect("two sides");
        self.templates = Some([tick, tock]);
        for (beat, start, window) in std::mem::take(&mut self.waiting) {
            self.refine(beat, start, &window);
        }
    }

    /// The per-sample median of the windows, each read from its shift.
    fn median(&self, windows: &[&Vec<f32>], shifts: &[usize]) -> Vec<f32> {
        (0..self.length)
            .map(|i| {
                let mut column: Vec<f64> = windows
                    .iter()
                    .zip(shifts)
                    .filter_map(|(w, &s)| w.get(s + i).map(|&v| f64::from(v)))
                    .collect();
                median(&mut column) as f32
            })
            .collect()
    }

    fn refine(&mut self, beat: u64, start: u64, window: &[f32]) {
        let side = (beat % 2) as usize;
        let Some(templates) = &self.templates else {
            return;
        };
        let template = &templates[side];
        let Some((lag, raw)) = best_lag(window, &template.samples, self.search) else {
            self.rejected += 1;
            return;
        };
        let energy = window
            .iter()
            .skip(lag.round().max(0.0) as usize)
            .take(self.length)
            .map(|&v| f64::from(v) * f64::from(v))
            .sum::<f64>()
            .sqrt();
        let correlation = if energy > 0.0 && template.norm > 0.0 {
            raw / (energy * template.norm)
        } else {
            0.0
        };
        // Noise, not a tick: well below the correlation the ticks have.
        if correlation < 0.3 || correlation < 0.4 * template.typical {
            self.rejected += 1;
            return;
        }
        let amplitude = window.iter().map(|v| v.abs()).fold(0.0_f32, f32::max);
        self.ticks.push(Tick {
            beat,
            time: (start as f64 + lag + template.onset) / self.rate,
            side: side as u8,
            amplitude: f64::from(amplitude),
            correlation,
        });
    }

    /// Ends the pass: the ticks, and how many coarse onsets were dropped as
    /// noise. Short records (fewer than 128 ticks a side) build the
    /// templates from what they have.
    pub fn finish(mut self) -> (Vec<Tick>, usize) {
        if self.templates.is_none() && !self.waiting.is_empty() {
            self.build();
        }
        (self.ticks, self.rejected)
    }
}

/// The lag (samples, from 0 to `2 search`, to a fraction by a parabola) at
/// which `template` best matches `window`, with the correlation there.
fn best_lag(window: &[f32], template: &[f32], search: usize) -> Option<(f64, f64)> {
    if window.len() < template.len() + 2 * search {
        return None;
    }
    let correlation = |lag: usize| -> f64 {
        window[lag..lag + template.len()]
            .iter()
            .zip(template)
            .map(|(&a, &b)| f64::from(a) * f64::from(b))
            .sum()
    };
    let values: Vec<f64> = (0..=2 * search).map(correlation).collect();
    let (best, &peak) = values
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    let shift = if best > 0 && best < values.len() - 1 {
        let (a, b, c) = (values[best - 1], peak, values[best + 1]);
        let d = a - 2.0 * b + c;
        if d < 0.0 {
            (0.5 * (a - c) / d).clamp(-0.5, 0.5)
        } else {
            0.0
        }
    } else {
        0.0
    };
    Some((best as f64 + shift, peak))
}

/// Drops the ticks that sit off the clockwork: a tick more than 2 ms from
/// where the ticks of its side around it (the ten before and after) put
/// it, at the beat of all of them, is a drop sound or a noise burst taken
/// for the tick. Returns the ticks kept and how many were dropped. A
/// clock's beats wander by far less than 2 ms from one to the next (the
/// jitter of a good clock is tens of µs), so no real tick is lost.
pub fn drop_outliers(ticks: Vec<Tick>) -> (Vec<Tick>, usize) {
    if ticks.len() < 8 {
        return (ticks, 0);
    }
    // The beat from all ticks: least squares of time on beat number.
    let n = ticks.len() as f64;
    let (mk, mt) = ticks.iter().fold((0.0, 0.0), |(a, b), t| {
        (a + t.beat as f64 / n, b + t.time / n)
    });
    let (sxy, sxx) = ticks.iter().fold((0.0, 0.0), |(a, b), t| {
        let dk = t.beat as f64 - mk;
        (a + dk * (t.time - mt), b + dk * dk)
    });
    let beat = if sxx > 0.0 {
        sxy / sxx
    } else {
        return (ticks, 0);
    };
    let keep: Vec<bool> = (0..ticks.len())
        .map(|i| {
            let t = &ticks[i];
            let mut predictions: Vec<f64> = ticks
                .iter()
                .enumerate()
                .filter(|(j, o)| *j != i && o.side == t.side && o.beat.abs_diff(t.beat) <= 20)
                .map(|(_, o)| o.time + (t.beat as f64 - o.beat as f64) * beat)
                .collect();
            if predictions.len() < 3 {
                return true;
            }
            (t.time - median(&mut predictions)).abs() <= 2e-3
        })
        .collect();
    let dropped = keep.iter().filter(|k| !**k).count();
    let kept = ticks
        .into_iter()
        .zip(keep)
        .filter_map(|(t, k)| k.then_some(t))
        .collect();
    (kept, dropped)
}

/// Times the envelope's values to seconds for `sample_rate`.
pub fn envelope_rate(envelope: &Envelope, sample_rate: f64) -> f64 {
    envelope.rate(sample_rate)
}
