//! A recording over time: its ticks cut into windows of a given length,
//! each analysed as a timegrapher analyses a short recording (rate, beat
//! error, the drop and the amplitude, the signal to noise), so that a
//! clock's rate can be followed as it warms, winds down or meets the
//! weather; and the windows' rates summed up with their standard error.

use super::analysis::Oscillator;
use super::detect::{median_of, Tick};
use crate::lift::amplitude_from_lift;
use serde::Serialize;

/// The fewest beats a window is cut to.
pub const MIN_WINDOW_BEATS: f64 = 8.0;

/// One window of a recording.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Window {
    /// Its start, s from the recording's start.
    pub start_s: f64,
    /// Its end, s.
    pub end_s: f64,
    /// Ticks kept in it.
    pub beats: usize,
    /// Its rate against the recording's nominal beat, s/day (null when
    /// fewer than four ticks, or no nominal beat).
    pub rate_s_per_day: Option<f64>,
    /// The rate's standard error, s/day.
    pub rate_se_s_per_day: Option<f64>,
    /// Its beat error, ms.
    pub beat_error_ms: Option<f64>,
    /// The median time from the unlocking to the drop, ms (null when the
    /// ticks were not timed on two sounds).
    pub drop_ms: Option<f64>,
    /// The amplitude from the lift angle, degrees (null without a lift
    /// angle or a drop).
    pub amplitude_deg: Option<f64>,
    /// The median tick's envelope peak over the floor, dB.
    pub snr_db: Option<f64>,
}

/// The windows' rates summed up.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WindowTotals {
    /// The windows' length, s.
    pub every_s: f64,
    /// Windows with a rate.
    pub windows_with_rate: usize,
    /// The mean of their rates, s/day.
    pub rate_mean_s_per_day: Option<f64>,
    /// Its standard error from the rates' scatter (the standard deviation
    /// over the square root of their number): it takes in a rate that
    /// wanders, which the whole recording's regression does not.
    pub rate_mean_se_s_per_day: Option<f64>,
    /// The windows' rates' scatter about their mean over what their own
    /// standard errors allow (the root of chi-square over its degrees of
    /// freedom): about 1 for a steady clock, far above for a rate that
    /// wanders (null for fewer than three windows).
    pub rate_scatter_over_se: Option<f64>,
}

/// What the windows need of the whole analysis.
pub struct WindowInput<'a> {
    /// The ticks kept, rescaled.
    pub ticks: &'a [Tick],
    /// Each beat's envelope peak and the floor then (beat, peak, floor).
    pub levels: &'a [(u64, f64, f64)],
    /// Each beat's time from the unlocking to the drop (beat, s).
    pub spacings: &'a [(u64, f64)],
    /// The windows' length, s.
    pub every: f64,
    /// The recording's length, s.
    pub duration: f64,
    /// The beat the rates are against, s.
    pub nominal_beat: Option<f64>,
    /// The lift angle, rad.
    pub lift_angle: Option<f64>,
    /// What swings.
    pub oscillator: Oscillator,
    /// The sound card's time scale (1 / (1 + ppm 10⁻⁶)).
    pub scale: f64,
}

/// Cuts the recording into windows of `every` s from its start (the last
/// one shorter) and analyses each: the rate and beat error of its ticks
/// (their beat numbers, as the whole recording's), the median drop and
/// from it the amplitude, and the median tick's signal to noise.
pub fn windows(input: &WindowInput) -> (Vec<Window>, WindowTotals) {
    let count = (input.duration / input.every).ceil().max(1.0) as usize;
    let mut out = Vec::with_capacity(count);
    let mut rest = input.ticks;
    for w in 0..count {
        let (start, end) = (
            w as f64 * input.every,
            ((w + 1) as f64 * input.every).min(input.duration),
        );
        let n = rest.iter().take_while(|t| t.time < end).count();
        let (here, later) = rest.split_at(n);
        rest = later;
        out.push(window(input, here, start, end));
    }
    let totals = totals(&out, input.every);
    (out, totals)
}

/// The rates of windows of `every` s summed up.
pub fn totals(out: &[Window], every: f64) -> WindowTotals {
    let rates: Vec<f64> = out.iter().filter_map(|w| w.rate_s_per_day).collect();
    let n = rates.len() as f64;
    let mean = (n > 0.0).then(|| rates.iter().sum::<f64>() / n);
    let se = mean
        .filter(|_| n >= 2.0)
        .map(|m| (rates.iter().map(|r| (r - m).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt());
    let weighed: Vec<(f64, f64)> = out
        .iter()
        .filter_map(|w| Some((w.rate_s_per_day?, w.rate_se_s_per_day.filter(|&s| s > 0.0)?)))
        .collect();
    let scatter = mean.filter(|_| weighed.len() >= 3).map(|m| {
        let chi2: f64 = weighed.iter().map(|(r, s)| ((r - m) / s).powi(2)).sum();
        (chi2 / (weighed.len() - 1) as f64).sqrt()
    });
    WindowTotals {
        every_s: every,
        windows_with_rate: rates.len(),
        rate_mean_s_per_day: mean,
        rate_mean_se_s_per_day: se,
        rate_scatter_over_se: scatter,
    }
}

/// Window `index` (from `index` to `index + 1` times `every`, s) of
/// `ticks` cleaned ([`super::detect::clean`], as the whole recording's
/// are: live, by [`super::detect::Cleaner`] as they come, its last ones
/// provisionally) and aligned, not yet rescaled: so that a window analysed
/// while the recording goes on is the one a file of it gives.
pub(crate) fn window_of(input: &WindowInput, ticks: &[Tick], index: usize) -> Window {
    let (start, end) = (
        index as f64 * input.every,
        ((index + 1) as f64 * input.every).min(input.duration),
    );
    let ticks: Vec<Tick> = ticks
        .iter()
        .map(|t| Tick {
            time: t.time * input.scale,
            ..*t
        })
        .filter(|t| t.time >= start && t.time < end)
        .collect();
    window(input, &ticks, start, end)
}

/// Live, beats past a window's end whose ticks are awaited before it is
/// cut (at most [`super::live::WINDOW_WAIT_S`]): its last ticks are
/// decided by the clean-up with these after them.
pub const CLEAN_REACH: u64 = 24;

fn window(input: &WindowInput, ticks: &[Tick], start: f64, end: f64) -> Window {
    // (A window's beat is its ticks'; with one tick, any: it is refused.)
    let analysis = super::analysis::analyse_ticks(ticks, input.every, input.nominal_beat)
        .ok()
        .filter(|_| ticks.len() >= super::analysis::MIN_TICKS);
    let beats = ticks
        .first()
        .zip(ticks.last())
        .map(|(a, b)| a.beat..=b.beat);
    let within = |k: u64| beats.as_ref().is_some_and(|r| r.contains(&k));
    let spacings: Vec<f64> = input
        .spacings
        .iter()
        .filter(|(k, _)| within(*k))
        .map(|(_, d)| d * input.scale)
        .collect();
    let drop = (!spacings.is_empty()).then(|| median_of(&spacings));
    let (peaks, floors): (Vec<f64>, Vec<f64>) = input
        .levels
        .iter()
        .filter(|(k, _, _)| within(*k))
        .map(|&(_, p, f)| (p, f))
        .unzip();
    let snr = (!peaks.is_empty())
        .then(|| super::analysis::snr(median_of(&peaks), median_of(&floors)))
        .filter(|s| s.is_finite());
    let amplitude = match (input.lift_angle, drop, &analysis) {
        (Some(lift), Some(dt), Some(a)) => amplitude_from_lift(lift, dt, 2.0 * a.mean_beat)
            .ok()
            .map(|x| input.oscillator.amplitude(&x).to_degrees()),
        _ => None,
    };
    Window {
        start_s: start,
        end_s: end,
        beats: ticks.len(),
        rate_s_per_day: analysis.as_ref().and_then(|a| a.rate_s_per_day),
        rate_se_s_per_day: analysis
            .as_ref()
            .map(|a| a.rate_se_s_per_day)
            .filter(|s| s.is_finite()),
        beat_error_ms: analysis.as_ref().map(|a| a.beat_error_ms),
        drop_ms: drop.map(|d| d * 1e3),
        amplitude_deg: amplitude
            .filter(|a| a.is_finite() && *a <= input.oscillator.largest_swing_rad().to_degrees()),
        snr_db: snr,
    }
}
