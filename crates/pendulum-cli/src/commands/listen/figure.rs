//! `pendulum listen --plot`: the timegrapher's picture.

use crate::error::CliError;
use crate::output::num;
use crate::plot::{render, thin, Figure, Panel, Series, Target};
use pendulum_theory::listening::analysis::Listening;
use pendulum_theory::listening::detect::MedianSound;
use pendulum_theory::listening::windows::Window;

/// Points of the paper strip kept, at most.
const STRIP_LIMIT: usize = 8192;

/// The timegrapher's picture: the paper strip (each beat's offset from the
/// nominal beat against time, ticks and tocks apart: the rate is the
/// slope, the beat error the gap between the two traces) and the median
/// tick and tock sounds overlaid.
pub(super) fn draw(target: &Target, r: &Listening) -> Result<String, CliError> {
    let ticks = &r.ticks;
    let rate = f64::from(r.sample_rate_hz);
    let beat = r.beats.nominal_beat_s.unwrap_or(r.beats.mean_beat_s);
    let (first_beat, first_time) = ticks.first().map_or((0, 0.0), |t| (t.beat, t.time));
    let strip = |side: u8| -> Vec<(f64, f64)> {
        let points = ticks
            .iter()
            .filter(|t| t.side == side)
            .map(|t| {
                // A timegrapher's sign: a beat that comes early is ahead,
                // so the strip of a gaining clock rises.
                let time = t.time;
                let expected = first_time + (t.beat - first_beat) as f64 * beat;
                (time, 1e3 * (expected - time))
            })
            .collect();
        thin(points, STRIP_LIMIT)
    };
    let against = match r.beats.nominal_beat_s {
        Some(_) => format!("{} beats/hour", num(3600.0 / beat, 6)),
        None => "the mean beat".to_string(),
    };
    let strip = Panel::new(
        format!("Paper strip: each beat against {against}"),
        crate::plot::TIME_AXIS,
        "ahead (ms), rising: gaining",
        vec![
            Series::dots("ticks", strip(0)),
            Series::dots("tocks", strip(1)),
        ],
    );
    // The two traces' separation, which the strip's scale hides when the
    // rate is large: each tock against the mean of the ticks either side.
    let by_beat: std::collections::HashMap<u64, f64> =
        ticks.iter().map(|t| (t.beat, t.time)).collect();
    let separation: Vec<(f64, f64)> = ticks
        .iter()
        .filter(|t| t.side == 1 && t.beat > 0)
        .filter_map(|t| {
            let (before, after) = (by_beat.get(&(t.beat - 1))?, by_beat.get(&(t.beat + 1))?);
            Some((t.time, 1e3 * (t.time - 0.5 * (before + after))))
        })
        .collect();
    let mut panels = vec![strip];
    if !separation.is_empty() {
        panels.push(Panel::new(
            "Tick and tock apart: each tock against the ticks either side",
            crate::plot::TIME_AXIS,
            "tock late (ms): the beat error",
            vec![Series::dots("tocks", thin(separation, STRIP_LIMIT)).colored(1)],
        ));
    }
    if let Some(sounds) = &r.sounds {
        let wave = |s: &MedianSound| -> Vec<(f64, f64)> {
            s.shown
                .iter()
                .enumerate()
                .map(|(i, &v)| (1e3 * (i as f64 - s.onset) / rate, f64::from(v)))
                .collect()
        };
        panels.push(Panel::new(
            "Median tick and tock sounds (band-passed)",
            "time from the onset (ms)",
            "sound (full scale)",
            vec![
                Series::line("tick", wave(&sounds[0])),
                Series::line("tock", wave(&sounds[1])),
            ],
        ));
    }
    // With --every: the long strip chart, each window's rate, beat error
    // and amplitude at its middle.
    if !r.windows.is_empty() {
        let over_time = |f: &dyn Fn(&Window) -> Option<f64>| -> Vec<(f64, f64)> {
            r.windows
                .iter()
                .filter_map(|w| f(w).map(|v| (0.5 * (w.start_s + w.end_s), v)))
                .collect()
        };
        let every = r.window_totals.map_or(0.0, |t| t.every_s);
        let title = |what: &str| format!("{what} in windows of {} s", num(every, 6));
        panels.push(Panel::new(
            title("Rate"),
            crate::plot::TIME_AXIS,
            "rate (s/day)",
            vec![Series::dots("rate", over_time(&|w| w.rate_s_per_day))],
        ));
        panels.push(Panel::new(
            title("Beat error"),
            crate::plot::TIME_AXIS,
            "beat error (ms)",
            vec![Series::dots("beat error", over_time(&|w| w.beat_error_ms))],
        ));
        let amplitude = over_time(&|w| w.amplitude_deg);
        if !amplitude.is_empty() {
            panels.push(Panel::new(
                title("Amplitude"),
                crate::plot::TIME_AXIS,
                "amplitude (°)",
                vec![Series::dots("amplitude", amplitude)],
            ));
        }
    }
    render(target, &Figure { panels })
}
