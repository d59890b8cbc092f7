//! The findings of a recording ([`crate::findings`]): drawn from what the
//! listening measured, each only where its evidence clears its threshold,
//! so that a clean recording of a clock in good order has none.

use super::analysis::Listening;
use super::quality::Measured;
use crate::advice::{beat_error_worth_setting, worth_setting};
use crate::findings::{
    arc_trend, usual_escape_wheel, Finding, ARC_FALL_PERCENT, ARC_SIGMA, CLIPPED_PERCENT,
    HUM_FRACTION, NOISY_DB, NOISY_MISSED_PERCENT, PERIODIC_SMALLEST_MS,
};
use crate::fitting::beat_log::BeatWarning;
use crate::fitting::periodic::periodic_error;

/// The findings of `heard`, whose tracker timed the drops `spacings`
/// (beat, s after the unlocking), the samples measured as `quality`.
pub(crate) fn findings(
    heard: &Listening,
    spacings: &[(u64, f64)],
    quality: Option<Measured>,
) -> Vec<Finding> {
    let b = &heard.beats;
    let beat = b.mean_beat_s;
    let mut out = Vec::new();
    let be = b.beat_error_ms.abs() * 1e-3;
    let be_se = b.beat_error_se_ms.unwrap_or(0.0) * 1e-3;
    if worth_setting(heard.oscillator, beat, be, be_se) {
        out.push(Finding::OutOfBeat {
            beat_error_ms: be * 1e3,
            split_percent: crate::advice::split_percent(be, beat),
            limit_ms: beat_error_worth_setting(heard.oscillator, beat) * 1e3,
        });
    }
    let times: Vec<(u64, f64, u8)> = heard
        .ticks
        .iter()
        .map(|t| (t.beat, t.time, t.side))
        .collect();
    let wheel = periodic_error(&times, beat).filter(|p| p.amplitude_ms >= PERIODIC_SMALLEST_MS);
    if let Some(p) = wheel {
        out.push(Finding::PeriodicError {
            period_s: p.period_s,
            period_beats: p.period_beats,
            amplitude_ms: p.amplitude_ms,
            escape_teeth: usual_escape_wheel(p.period_s, beat),
        });
    }
    // (Beat k at its time in the recording: the ticks' line through the
    // first tick, the tracker's numbers counting from it.)
    let zero = heard
        .ticks
        .first()
        .map_or(0.0, |t| t.time - t.beat as f64 * beat);
    let drops: Vec<(f64, f64)> = spacings
        .iter()
        .map(|&(k, d)| (zero + k as f64 * beat, d))
        .collect();
    if let Some(trend) = arc_trend(&drops, beat) {
        if trend.change < -ARC_FALL_PERCENT / 100.0 && trend.sigma > ARC_SIGMA {
            out.push(Finding::ArcFalls {
                drop_first_ms: trend.drop_first_s * 1e3,
                drop_last_ms: trend.drop_last_s * 1e3,
                change_percent: trend.change * 100.0,
                over_s: drops.last().map_or(0.0, |l| l.0) - drops[0].0,
                stops_in_h: trend.stops_after_s / 3600.0,
            });
        }
    }
    if let (Some(ratio), Some(totals)) = (
        b.warnings.iter().find_map(|w| match w {
            BeatWarning::RateWanders { ratio } => Some(*ratio),
            _ => None,
        }),
        &heard.window_totals,
    ) {
        out.push(Finding::RateWanders {
            ratio,
            every_s: totals.every_s,
        });
    }
    let beats = heard.ticks.len() + heard.missed;
    let missed_percent = 100.0 * heard.missed as f64 / beats.max(1) as f64;
    if heard.snr_db < NOISY_DB || missed_percent > NOISY_MISSED_PERCENT {
        out.push(Finding::Noisy {
            snr_db: heard.snr_db,
            missed_percent,
        });
    }
    if let Some(q) = &quality {
        // (A strike that clips is cut, not the recording's fault.)
        let cut = |t: f64| heard.cut_s.iter().any(|c| t >= c[0] && t <= c[1]);
        let clips = q.clip_times_s.iter().filter(|&&t| !cut(t)).count() + q.clips_untimed;
        let clipped_percent = 100.0 * clips as f64 / heard.ticks.len().max(1) as f64;
        if clipped_percent > CLIPPED_PERCENT {
            out.push(Finding::Clipped { clipped_percent });
        }
        if q.hum_fraction >= HUM_FRACTION {
            out.push(Finding::Hum {
                hum_hz: q.hum_hz,
                hum_db: 20.0 * q.hum_fraction.log10(),
            });
        }
    }
    out
}
