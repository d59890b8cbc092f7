//! Each tick to a fraction of a sample, by cross-correlation with its side's median sound.

use super::{median, Coarse};
use crate::listening::filter::BandPass;

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

/// A tick as the refiner gives it, before the clean-up
/// ([`super::clean`]) keeps it or not: with what the clean-up and the
/// alignment of the sides need, let go of once it is kept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refined {
    /// The tick.
    pub tick: Tick,
    /// The tracker's onset it was refined from, s (the same rule on both
    /// sides: see [`crate::listening::analysis`]'s alignment of the sides).
    pub onset: f64,
    /// The times (s) the other peaks of the correlation would give (the
    /// eight strongest), with their correlation relative to the best: one
    /// or more ringing periods either side (see [`super::clean`]).
    pub alternatives: [Option<(f64, f64)>; 8],
}

/// The tick's and the tock's median sounds are one sound (timed from one
/// onset) when their normalised correlation reaches this.
const SAME_SOUND: f64 = 0.8;
/// Ticks kept to build each side's median sound.
const TEMPLATE_TICKS: usize = 128;
/// Before and after the coarse onset in each window, s.
const PRE: f64 = 1.5e-3;
const POST: f64 = 4.5e-3;
/// The correlation search, either way, s.
const SEARCH: f64 = 2.0e-3;
/// How far past the later drop the median sounds shown run, s.
const SHOWN_AFTER_DROP: f64 = 5e-3;
/// The longest median sound shown after the onset, s.
const SHOWN_MAX: f64 = 0.05;

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
    /// Windows waiting for the templates: (beat, window start sample,
    /// samples, and the quiet window before it).
    waiting: Vec<Waiting>,
    templates: Option<[Template; 2]>,
    ticks: Vec<Refined>,
    /// Live: onsets before `coarse[0]` let go of.
    let_go: usize,
    rejected: usize,
    pre: usize,
    length: usize,
    /// The length of the median sounds shown (not matched): through the
    /// drop, when there is one.
    shown: usize,
    search: usize,
    /// Live: onsets still to come, none before this, s (see
    /// [`Refiner::push_onsets`]); `None` when all were given at the start.
    horizon: Option<f64>,
}

/// A window waiting for the templates.
struct Waiting {
    beat: u64,
    /// The tracker's onset, s.
    onset: f64,
    start: u64,
    window: Vec<f32>,
    /// The same length of sound ending [`QUIET_GAP`] before the window:
    /// what the template finds where there is no tick.
    quiet: Option<Vec<f32>>,
}

/// The gap between a quiet window and its tick's window, s.
const QUIET_GAP: f64 = 5e-3;

#[derive(Clone, Debug)]
struct Template {
    samples: Vec<f32>,
    /// The median sound over [`Refiner::shown`] samples, for pictures.
    shown: Vec<f32>,
    norm: f64,
    /// Where in the template the sound begins, samples.
    onset: f64,
    /// The median correlation of the ticks it was built from.
    typical: f64,
    /// What the template finds where there is no tick.
    null: Option<Null>,
    /// Whether the ticks it was built from stand out of the quiet (else
    /// the template is a median of noise, and nothing is taken for a tick).
    heard: bool,
}

/// The correlation and the peak of the quiet windows before the ticks
/// (noise, hum, the room's tail), against which a tick is told from noise.
#[derive(Clone, Copy, Debug)]
struct Null {
    /// Mean and standard deviation of the template's best correlation.
    correlation: (f64, f64),
    /// Mean and standard deviation of the logarithm of the peak.
    log_peak: (f64, f64),
}

/// Standard deviations (summed over correlation and peak) by which a tick
/// must stand above the quiet windows: for noise, the sum of two
/// independent standard normal scores exceeds 5 with a probability of
/// 2e-4, and only the beats where the envelope already showed a sound
/// near the tick's expected time are tested, so a beat with no tick is
/// not taken for one.
const NULL_SCORE: f64 = 5.0;
/// Standard deviations of correlation by which the median window of a side
/// must stand out of the quiet for the side to be heard at all (recordings
/// with ticks: 5 to 17; noise alone: below 1).
const HEARD_SCORE: f64 = 3.0;
/// Standard deviations of correlation alone by which a tick stands out
/// (a probability of 3.4e-6 for noise).
const NULL_CORRELATION: f64 = 4.5;

impl Null {
    fn of(correlations: &[f64], log_peaks: &[f64]) -> Option<Self> {
        let stats = |v: &[f64]| {
            let n = v.len() as f64;
            let mean = v.iter().sum::<f64>() / n;
            let sd = (v.iter().map(|c| (c - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
            (mean, sd.max(1e-6))
        };
        (correlations.len() >= 8 && log_peaks.len() >= 8).then(|| Self {
            correlation: stats(correlations),
            log_peak: stats(log_peaks),
        })
    }

    /// Whether a window with this correlation and peak is a tick: its
    /// scores summed reach [`NULL_SCORE`], or its correlation alone reaches
    /// [`NULL_CORRELATION`] (in strong noise the peak tells nothing).
    fn stands_out(&self, correlation: f64, peak: f64) -> bool {
        let by_shape = (correlation - self.correlation.0) / self.correlation.1;
        let by_peak = (peak.max(1e-30).ln() - self.log_peak.0) / self.log_peak.1;
        by_shape + by_peak >= NULL_SCORE || by_shape >= NULL_CORRELATION
    }
}

/// Where a median sound begins, samples: the first crossing of a fifth
/// of its peak magnitude, interpolated.
fn sound_onset(sound: &[f32]) -> Option<f64> {
    let peak = sound.iter().map(|v| v.abs()).fold(0.0_f32, f32::max);
    let level = 0.2 * peak;
    if level <= 0.0 {
        return None;
    }
    let i = sound.iter().position(|v| v.abs() >= level)?;
    let before = if i > 0 { sound[i - 1].abs() } else { 0.0 };
    let now = sound[i].abs();
    let f = if now > before {
        (level - before) / (now - before)
    } else {
        1.0
    };
    Some(i as f64 - 1.0 + f64::from(f.clamp(0.0, 1.0)))
}

/// The lag (samples, within `±reach`, to a fraction by a parabola) by
/// which `b` best matches `a`: `b[i + lag] ≈ a[i]`.
fn relative_lag(a: &[f32], b: &[f32], reach: usize) -> Option<f64> {
    let reach = reach as isize;
    let value = |lag: isize| -> f64 {
        a.iter()
            .enumerate()
            .filter_map(|(i, &x)| {
                let j = usize::try_from(i as isize + lag).ok()?;
                b.get(j).map(|&y| f64::from(x) * f64::from(y))
            })
            .sum()
    };
    let values: Vec<f64> = (-reach..=reach).map(value).collect();
    let (best, &peak) = values
        .iter()
        .enumerate()
        .max_by(|x, y| x.1.total_cmp(y.1))?;
    if peak <= 0.0 {
        return None;
    }
    let shift = if best > 0 && best + 1 < values.len() {
        let (p, q, r) = (values[best - 1], peak, values[best + 1]);
        let d = p - 2.0 * q + r;
        if d < 0.0 {
            (0.5 * (p - r) / d).clamp(-0.5, 0.5)
        } else {
            0.0
        }
    } else {
        0.0
    };
    Some(best as f64 - reach as f64 + shift)
}

/// The largest magnitude in `window`.
fn peak_of(window: &[f32]) -> f64 {
    f64::from(window.iter().map(|v| v.abs()).fold(0.0_f32, f32::max))
}

impl Refiner {
    /// A refiner of `coarse` onsets (from [`super::OnsetTracker`]) in audio at
    /// `sample_rate`.
    pub fn new(sample_rate: f64, coarse: &Coarse) -> Self {
        Self::with_onsets(
            sample_rate,
            coarse.timing,
            coarse.drops,
            coarse.onsets.clone(),
        )
    }

    /// A refiner for listening live: the onsets come as the tracker settles
    /// them ([`Refiner::push_onsets`]), timed on `timing` with the drops
    /// `drops` (s) that the first seconds showed.
    pub fn following(sample_rate: f64, timing: super::Timing, drops: [Option<f64>; 2]) -> Self {
        Self {
            horizon: Some(0.0),
            ..Self::with_onsets(sample_rate, timing, drops, Vec::new())
        }
    }

    /// Live: more onsets (beat number, s), later than all before; `horizon`
    /// (s): no onset still to come is earlier (the samples from it on are
    /// kept).
    pub fn push_onsets(&mut self, onsets: &[(u64, f64)], horizon: f64) {
        self.coarse.extend_from_slice(onsets);
        self.horizon = Some(horizon);
    }

    /// The ticks refined so far and not taken (none until each side's
    /// median sound is built, from its first 128 ticks).
    pub fn ticks(&self) -> &[Refined] {
        &self.ticks
    }

    /// Live: the ticks refined since the last call, in order of beat; the
    /// onsets they came from are let go of.
    pub fn take_ticks(&mut self) -> Vec<Refined> {
        if self.next > 4096 {
            self.coarse.drain(..self.next - 1);
            self.let_go += self.next - 1;
            self.next = 1;
        }
        std::mem::take(&mut self.ticks)
    }

    /// Live: onsets and ticks held (see [`super::OnsetTracker::held`]).
    #[cfg(test)]
    pub(crate) fn held(&self) -> usize {
        self.coarse.len() + self.ticks.len() + self.waiting.len()
    }

    /// Each side's median sound, once built (from its first 128 ticks).
    pub fn sounds(&self) -> Option<[MedianSound; 2]> {
        self.templates.as_ref().map(|t| {
            t.clone().map(|t| MedianSound {
                samples: t.samples,
                shown: t.shown,
                onset: t.onset,
            })
        })
    }

    /// Live: the time, s, up to which the onsets given are refined (their
    /// windows cut, each side's median sound built: [`Refiner::ticks`]
    /// holds all of theirs that stood out); 0 before.
    pub fn refined_until(&self) -> f64 {
        if self.templates.is_none() {
            return 0.0;
        }
        self.next.checked_sub(1).map_or(0.0, |i| self.coarse[i].1)
    }

    fn with_onsets(
        sample_rate: f64,
        timing: super::Timing,
        drops: [Option<f64>; 2],
        onsets: Vec<(u64, f64)>,
    ) -> Self {
        let pre = (PRE * sample_rate).round() as usize;
        // Timed on the unlocking, the window ends before the drop (so that
        // the louder drop, whose delay follows the swing, does not pull
        // the match), but takes at least 1 ms of the unlocking.
        let post = match timing {
            super::Timing::Unlocking => drops
                .iter()
                .flatten()
                .fold(POST, |p, &d| p.min(0.8 * d))
                .max(1e-3),
            super::Timing::OneSound => POST,
        };
        // The sound shown runs on past the later drop (its ringing too),
        // at most 50 ms.
        let shown = drops
            .iter()
            .flatten()
            .fold(POST, |p, &d| p.max(d + SHOWN_AFTER_DROP))
            .min(SHOWN_MAX);
        let shown = pre + (shown * sample_rate).round() as usize;
        let post = (post * sample_rate).round() as usize;
        let search = (SEARCH * sample_rate).round().max(2.0) as usize;
        Self {
            rate: sample_rate,
            filter: BandPass::new(sample_rate),
            coarse: onsets,
            next: 0,
            position: 0,
            buffer: Vec::new(),
            buffer_start: 0,
            waiting: Vec::new(),
            templates: None,
            ticks: Vec::new(),
            let_go: 0,
            rejected: 0,
            pre,
            length: pre + post,
            shown: shown.max(pre + post),
            search,
            horizon: None,
        }
    }

    /// Feeds the next samples.
    pub fn push(&mut self, samples: &[f32]) {
        for &x in samples {
            self.buffer.push(self.filter.process(f64::from(x)) as f32);
        }
        self.position += samples.len() as u64;
        // Cut every window that is complete (while the templates are
        // made, long enough for the sound shown).
        let span = (self.length + 2 * self.search) as u64;
        while self.next < self.coarse.len() {
            let (beat, onset) = self.coarse[self.next];
            let start = ((onset * self.rate).round() as i64 - (self.pre + self.search) as i64)
                .max(0) as u64;
            let cut = if self.templates.is_none() {
                (self.shown + 2 * self.search) as u64
            } else {
                span
            };
            if start + cut > self.position {
                break;
            }
            let from = (start.saturating_sub(self.buffer_start)) as usize;
            let window = self.buffer[from..from + cut as usize].to_vec();
            let quiet = (self.templates.is_none()).then(|| {
                let back = span + (QUIET_GAP * self.rate) as u64;
                let q = start.checked_sub(back)?.checked_sub(self.buffer_start)? as usize;
                Some(self.buffer[q..q + span as usize].to_vec())
            });
            self.next += 1;
            self.take(Waiting {
                beat,
                onset,
                start,
                window,
                quiet: quiet.flatten(),
            });
        }
        // Keep only what a later window can need.
        // (Live, the next onset is not known yet: none comes before the
        // horizon.)
        let keep_from = self
            .coarse
            .get(self.next)
            .map(|&(_, t)| t)
            .or(self.horizon)
            .map(|t| {
                let quiet = 2 * (self.length + 2 * self.search) + (QUIET_GAP * self.rate) as usize;
                ((t * self.rate) as i64 - (self.pre + 2 * self.search + quiet) as i64).max(0) as u64
            })
            .unwrap_or(self.position)
            .min(self.position);
        if keep_from > self.buffer_start + 4096 {
            let drop = ((keep_from - self.buffer_start) as usize).min(self.buffer.len());
            self.buffer.drain(..drop);
            self.buffer_start += drop as u64;
        }
    }

    fn take(&mut self, w: Waiting) {
        match &self.templates {
            Some(_) => {
                let span = w.window.len().min(self.length + 2 * self.search);
                self.refine(&w, &w.window[..span]);
            }
            None => {
                self.waiting.push(w);
                let sides = [0, 1].map(|s| self.waiting.iter().filter(|w| w.beat % 2 == s).count());
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
        let span = self.length + 2 * self.search;
        for side in 0..2_u64 {
            let long: Vec<&[f32]> = self
                .waiting
                .iter()
                .filter(|w| w.beat % 2 == side)
                .take(TEMPLATE_TICKS)
                .map(|w| w.window.as_slice())
                .collect();
            // Matched on the windows' first part alone; the rest is shown.
            let windows: Vec<&[f32]> = long.iter().map(|w| &w[..span.min(w.len())]).collect();
            // Start from the loudest window (its ringing is real even where
            // the noise is strong, while a median of windows misaligned by
            // more than a ringing period cancels), then align on the median
            // three times.
            let energy = |w: &[f32]| -> f64 {
                w[self.search..self.search + self.length]
                    .iter()
                    .map(|&v| f64::from(v) * f64::from(v))
                    .sum()
            };
            let mut shifts = vec![self.search; windows.len()];
            let mut template = windows
                .iter()
                .max_by(|a, b| energy(a).total_cmp(&energy(b)))
                .map(|w| w[self.search..self.search + self.length].to_vec())
                .unwrap_or_default();
            for pass in 0..3 {
                for (k, w) in windows.iter().enumerate() {
                    if let Some((lag, _)) = best_lag(w, &template, self.search) {
                        shifts[k] = lag.round().clamp(0.0, (2 * self.search) as f64) as usize;
                    }
                }
                if pass < 2 {
                    template = self.median(&windows, &shifts, self.length);
                }
            }
            // The last median over the long windows: the sound shown, whose
            // first `length` samples are the template (the same columns).
            let shown = self.median(&long, &shifts, self.shown);
            template = shown[..self.length.min(shown.len())].to_vec();
            let norm = template
                .iter()
                .map(|&v| f64::from(v) * f64::from(v))
                .sum::<f64>()
                .sqrt();
            let onset = sound_onset(&template).unwrap_or(self.pre as f64);
            let mut correlations: Vec<f64> = windows
                .iter()
                .filter_map(|w| self.matched(w, &template, norm).map(|m| m.1))
                .collect();
            let typical = median(&mut correlations);
            let quiet: Vec<&Vec<f32>> = self
                .waiting
                .iter()
                .filter(|w| w.beat % 2 == side)
                .filter_map(|w| w.quiet.as_ref())
                .collect();
            let correlations: Vec<f64> = quiet
                .iter()
                .filter_map(|q| self.matched(q, &template, norm).map(|m| m.1))
                .collect();
            let amplitudes: Vec<f64> = quiet.iter().map(|q| peak_of(q).max(1e-30).ln()).collect();
            let null = Null::of(&correlations, &amplitudes);
            // A median sound that its own windows match no better than the
            // quiet does is noise (the windows were noise crests): no tick
            // of this side is taken.
            let heard =
                null.is_none_or(|n| (typical - n.correlation.0) / n.correlation.1 >= HEARD_SCORE);
            templates.push(Template {
                samples: template,
                shown,
                norm,
                onset,
                typical,
                null,
                heard,
            });
        }
        let [mut tick, mut tock]: [Template; 2] = templates.try_into().expect("two sides");
        // One onset for both sides: the tock's median sound aligned on the
        // tick's by their cross-correlation, the onset found on their sum
        // (less noisy than either), and carried back to each; so that the
        // beat error does not depend on where a noisy template seemed to
        // begin.
        if let Some(shift) = relative_lag(&tick.samples, &tock.samples, self.search) {
            let whole = shift.round() as isize;
            let sum: Vec<f32> = (0..tick.samples.len())
                .map(|i| {
                    let j = i as isize + whole;
                    let other = usize::try_from(j)
                        .ok()
                        .and_then(|j| tock.samples.get(j))
                        .copied()
                        .unwrap_or(0.0);
                    tick.samples[i] + other
                })
                .collect();
            // (Only for one sound: a tick and a tock that sound different,
            // as a clock's two pallets often do, are each timed on their own
            // start, else the beat error takes their difference in shape.)
            let alike = likeness(&tick.samples, &tock.samples, whole) >= SAME_SOUND;
            if let (true, Some(onset)) = (alike, sound_onset(&sum)) {
                tick.onset = onset;
                tock.onset = onset + shift;
            }
        }
        self.templates = Some([tick, tock]);
        for w in std::mem::take(&mut self.waiting) {
            let span = w.window.len().min(span);
            self.refine(&w, &w.window[..span]);
        }
    }

    /// The best match of `template` (of norm `norm`) in `window`, with its
    /// normalised correlation (against the window's energy where it
    /// matched).
    fn matched(&self, window: &[f32], template: &[f32], norm: f64) -> Option<(Lags, f64)> {
        let found = lags(window, template, self.search)?;
        let energy = window
            .iter()
            .skip(found.lag.round().max(0.0) as usize)
            .take(self.length)
            .map(|&v| f64::from(v) * f64::from(v))
            .sum::<f64>()
            .sqrt();
        let correlation = if energy > 0.0 && norm > 0.0 {
            found.peak / (energy * norm)
        } else {
            0.0
        };
        Some((found, correlation))
    }

    /// The per-sample median of the windows' first `length` samples, each
    /// read from its shift.
    fn median(&self, windows: &[&[f32]], shifts: &[usize], length: usize) -> Vec<f32> {
        (0..length)
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

    fn refine(&mut self, w: &Waiting, window: &[f32]) {
        let (beat, start) = (w.beat, w.start);
        let side = (beat % 2) as usize;
        let Some(templates) = &self.templates else {
            return;
        };
        let template = &templates[side];
        let Some((found, correlation)) = self.matched(window, &template.samples, template.norm)
        else {
            self.rejected += 1;
            return;
        };
        let lag = found.lag;
        // Noise, not a tick: not standing out of the quiet before the
        // ticks by correlation and loudness together, or well below the
        // correlation the ticks have.
        let amplitude = peak_of(window);
        let noise = match &template.null {
            Some(null) => !null.stands_out(correlation, amplitude),
            None => correlation < 0.3,
        };
        if noise || !template.heard || correlation < 0.4 * template.typical {
            self.rejected += 1;
            return;
        }
        self.ticks.push(Refined {
            tick: Tick {
                beat,
                time: (start as f64 + lag + template.onset) / self.rate,
                side: side as u8,
                amplitude,
                correlation,
            },
            onset: w.onset,
            alternatives: found
                .neighbours
                .map(|n| n.map(|(l, r)| ((start as f64 + l + template.onset) / self.rate, r))),
        });
    }

    /// Ends the pass: the ticks, and how many coarse onsets were dropped as
    /// noise. Short records (fewer than 128 ticks a side) build the
    /// templates from what they have.
    pub fn finish(self) -> (Vec<Refined>, usize) {
        let refined = self.finish_with_sounds();
        (refined.0, refined.1)
    }

    /// [`Refiner::finish`], with the median tick and tock sounds (for a
    /// picture of them).
    pub fn finish_with_sounds(mut self) -> (Vec<Refined>, usize, Option<[MedianSound; 2]>) {
        if self.templates.is_none() && !self.waiting.is_empty() {
            self.build();
        }
        let sounds = self.sounds();
        (self.ticks, self.rejected, sounds)
    }
}

/// The median sound of one side (band-passed), as the ticks were matched
/// against.
#[derive(Clone, Debug, PartialEq)]
pub struct MedianSound {
    /// The samples, at the recording's rate.
    pub samples: Vec<f32>,
    /// The same median over a longer span from the same start, through
    /// the drop when there is one (for a picture; the ticks are matched on
    /// `samples`).
    pub shown: Vec<f32>,
    /// Where the tick's onset falls in them, samples.
    pub onset: f64,
}

/// The normalised correlation of two sounds, `b` read `lag` samples on.
fn likeness(a: &[f32], b: &[f32], lag: isize) -> f64 {
    let norm = |v: &[f32]| v.iter().map(|&x| f64::from(x).powi(2)).sum::<f64>().sqrt();
    let product: f64 = (0..a.len())
        .filter_map(|i| {
            let j = usize::try_from(i as isize + lag).ok()?;
            b.get(j).map(|&y| f64::from(a[i]) * f64::from(y))
        })
        .sum();
    let (na, nb) = (norm(a), norm(b));
    if na > 0.0 && nb > 0.0 {
        product / (na * nb)
    } else {
        0.0
    }
}

/// Whether the median tick and tock are one sound (their normalised
/// correlation at their best alignment, within 2 ms, reaches
/// `SAME_SOUND`): if not, each is timed from its own onset, and where
/// an onset is taken on two different sounds can differ by a few tenths
/// of a ms, which the beat error takes in.
pub fn one_sound(sounds: &[MedianSound; 2], sample_rate: f64) -> bool {
    let reach = (SEARCH * sample_rate).round().max(2.0) as usize;
    relative_lag(&sounds[0].samples, &sounds[1].samples, reach).is_some_and(|lag| {
        likeness(&sounds[0].samples, &sounds[1].samples, lag.round() as isize) >= SAME_SOUND
    })
}

/// The lag (samples, from 0 to `2 search`, to a fraction by a parabola) at
/// which `template` best matches `window`, with the correlation there.
fn best_lag(window: &[f32], template: &[f32], search: usize) -> Option<(f64, f64)> {
    lags(window, template, search).map(|l| (l.lag, l.peak))
}

/// The correlation's best peak, and the runner-up peaks either side.
struct Lags {
    /// The best lag, samples, to a fraction.
    lag: f64,
    /// The correlation there.
    peak: f64,
    /// The other local peaks, the strongest first (up to eight): lag and
    /// correlation relative to the best.
    neighbours: [Option<(f64, f64)>; 8],
}

/// The local peaks of the correlation of `template` with `window` at lags
/// 0 to `2 search` (see [`Lags`]). A tick's sound rings at a few kHz, so
/// the correlation has peaks one ringing period apart, and noise can put
/// the neighbour of the right one on top (a "cycle slip"):
/// [`super::clean`] uses the neighbours to undo that.
fn lags(window: &[f32], template: &[f32], search: usize) -> Option<Lags> {
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
    let last = values.len() - 1;
    // A peak, to a fraction of a sample by a parabola through it.
    let refine = |i: usize| -> f64 {
        if i == 0 || i == last {
            return i as f64;
        }
        let (a, b, c) = (values[i - 1], values[i], values[i + 1]);
        let d = a - 2.0 * b + c;
        if d < 0.0 {
            i as f64 + (0.5 * (a - c) / d).clamp(-0.5, 0.5)
        } else {
            i as f64
        }
    };
    let (best, &peak) = values
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    let is_peak =
        |i: usize| i > 0 && i < last && values[i] >= values[i - 1] && values[i] >= values[i + 1];
    let relative = |i: usize| (refine(i), if peak > 0.0 { values[i] / peak } else { 0.0 });
    let mut others: Vec<(f64, f64)> = (1..last)
        .filter(|&i| i != best && is_peak(i))
        .map(relative)
        .collect();
    others.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut neighbours = [None; 8];
    for (slot, o) in neighbours.iter_mut().zip(others) {
        *slot = Some(o);
    }
    Some(Lags {
        lag: refine(best),
        peak,
        neighbours,
    })
}
