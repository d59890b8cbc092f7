//! `pendulum listen`'s text: what a timegrapher's screen shows.

use super::super::fit_beats::rate_text;
use super::ListenJson;
use crate::output::{num, table, Summary};
use pendulum_theory::listening::analysis::Oscillator;
use pendulum_theory::listening::detect::Timing;
use pendulum_theory::listening::windows::{Window, WindowTotals};

/// The summary of `r`, a recording of `channels` channels; listening
/// live, `printed` windows' rows were printed as they completed
/// ([`live_row`]): the table goes on with the rest, before the summary.
pub(super) fn render(r: &ListenJson, channels: usize, printed: Option<usize>) -> String {
    let mut s = Summary::default();
    s.row(
        "Recording",
        format!(
            "{} s at {} Hz, channel {} of {}",
            num(r.listening.duration_s, 6),
            r.listening.sample_rate_hz,
            r.channel,
            channels
        ),
    )
    .row(
        "Beats",
        format!(
            "{} ({} missed, {} extra), {} beats/hour",
            r.listening.beats.beats,
            r.listening.missed,
            r.listening.extra,
            num(r.listening.beats.beats_per_hour, 7)
        ),
    )
    .row(
        "Rate",
        rate_text(
            r.listening.beats.rate_s_per_day,
            r.listening.beats.nominal_beat_s,
            r.listening.beats.nominal_kind,
        ),
    )
    .row(
        "Beat error",
        format!(
            "{} ms (in beat {}/{} %)",
            num(r.listening.beats.beat_error_ms, 3),
            num(r.listening.in_beat_percent[0], 3),
            num(r.listening.in_beat_percent[1], 3)
        ),
    )
    .row(
        "Uncertainty",
        match (
            r.listening.beats.rate_se_s_per_day,
            r.listening.beats.beat_error_se_ms,
        ) {
            (Some(rate), Some(be)) => format!(
                "rate ±{} s/day, beat error ±{} ms (one standard error)",
                num(rate, 2),
                num(be, 2)
            ),
            _ => "too few beats to tell".to_string(),
        },
    )
    .row(
        "Jitter",
        format!("{} ms", num(r.listening.beats.jitter_ms, 3)),
    )
    .row(
        "Timed on",
        match r.listening.timed_on {
            Timing::Unlocking => {
                "the unlocking, the first of each beat's two sounds (the drop timed from it)"
            }
            Timing::OneSound => "each beat's one sound (no second sound stands apart from it)",
        }
        .to_string(),
    )
    .row(
        "Drop",
        match r.listening.drop_ms {
            [Some(t), Some(u)] => format!(
                "{} ms after the unlocking (ticks), {} ms (tocks)",
                num(t, 3),
                num(u, 3)
            ),
            [Some(t), None] | [None, Some(t)] => {
                format!("{} ms after the unlocking (one side only)", num(t, 3))
            }
            [None, None] => "not determined (no second sound stands out)".to_string(),
        },
    );
    if let (Some(lift), Some(amplitude)) = (r.listening.lift_angle_deg, r.listening.amplitude_deg) {
        let balance = r.listening.oscillator == Oscillator::Balance;
        // Said when the beat rate chose the oscillator, with the other.
        let chosen = if !r.listening.oscillator_from_beat {
            String::new()
        } else {
            format!(
                ", taken from the beat rate: --oscillator {} if it is not",
                if balance { "pendulum" } else { "balance" }
            )
        };
        s.row(
            "Amplitude",
            match (amplitude, r.listening.amplitude_first_order_deg.flatten()) {
                (Some(a), Some(_)) if balance => format!(
                    "{}° from the {}° lift (a balance wheel's harmonic motion{chosen})",
                    num(a, 4),
                    num(lift, 4),
                ),
                (Some(exact), Some(first)) => format!(
                    "{}° from the {}° lift (a pendulum's exact motion{chosen}; first order: {}°)",
                    num(exact, 4),
                    num(lift, 4),
                    num(first, 4)
                ),
                _ if r
                    .listening
                    .beats
                    .warning_codes
                    .contains(&"amplitude_impossible") =>
                {
                    format!(
                        "not given: the {}° lift gives more than this clock can swing (see the \
                         warning)",
                        num(lift, 4)
                    )
                }
                _ => "not determined (no drop sound to time the lift by)".to_string(),
            },
        );
    }
    s.row(
        "Signal to noise",
        format!("{} dB", num(r.listening.snr_db, 3)),
    );
    if let Some(reference) = &r.reference {
        let c = &reference.calibration;
        s.row(
            "Sound card",
            format!(
                "{} ppm{} from {} ({} ticks of a second), applied",
                num(c.sample_rate_error_ppm, 4),
                c.sample_rate_error_se_ppm
                    .map_or(String::new(), |se| format!(" ± {}", num(se, 2))),
                reference.file,
                c.beats
            ),
        );
    } else if r.listening.sample_rate_error_ppm != 0.0 {
        s.row(
            "Sound card",
            format!(
                "{} ppm, as given",
                num(r.listening.sample_rate_error_ppm, 6)
            ),
        );
    }
    if let Some(f) = &r.ticks_file {
        s.row("Ticks file", f.clone());
    }
    if let Some(f) = &r.plot_file {
        s.row("Plot", f.clone());
    }
    if let Some(f) = &r.windows_file {
        s.row("Windows file", f.clone());
    }
    let mut out = String::new();
    if let (Some(totals), Some(printed)) = (&r.listening.window_totals, printed) {
        if printed == 0 {
            out.push_str(&live_heading(totals.every_s));
        }
        for w in r.listening.windows.iter().skip(printed) {
            out.push_str(&live_row(w));
        }
        out.push_str(&mean_line(totals));
        out.push('\n');
    }
    out.push_str(&s.render());
    for w in &r.listening.beats.warnings {
        out.push_str(&format!("WARNING: {w}\n"));
    }
    if let (Some(totals), None) = (&r.listening.window_totals, printed) {
        out.push_str(&windows(r, totals));
    }
    out.push_str(&super::super::common::findings_text(&r.listening.findings));
    out.push_str(&super::super::common::advice_text(
        &r.listening.beats.advice,
    ));
    out
}

/// The columns of the windows' table.
const WINDOW_COLUMNS: [&str; 7] = [
    "start s",
    "beats",
    "rate s/day",
    "± s/day",
    "beat error ms",
    "amplitude °",
    "SNR dB",
];

/// A window's cells in the table.
fn window_cells(w: &Window) -> Vec<String> {
    let cell = |x: Option<f64>, digits: usize| x.map_or("-".to_string(), |v| num(v, digits));
    vec![
        num(w.start_s, 6),
        w.beats.to_string(),
        cell(w.rate_s_per_day, 4),
        cell(w.rate_se_s_per_day, 2),
        cell(w.beat_error_ms, 3),
        cell(w.amplitude_deg, 4),
        cell(w.snr_db, 3),
    ]
}

/// Cells right-aligned in fixed columns (the table printed row by row,
/// as the windows complete, cannot size its columns on them all).
fn fixed(cells: &[String]) -> String {
    let padded: Vec<String> = cells
        .iter()
        .zip(WINDOW_COLUMNS)
        .map(|(c, h)| {
            let w = h.chars().count().max(8);
            format!("{}{c}", " ".repeat(w.saturating_sub(c.chars().count())))
        })
        .collect();
    padded.join("  ").trim_end().to_string() + "\n"
}

/// The heading of the windows printed live.
pub(super) fn live_heading(every_s: f64) -> String {
    let header: Vec<String> = WINDOW_COLUMNS.iter().map(|h| h.to_string()).collect();
    format!("Every {} s\n{}", num(every_s, 6), fixed(&header))
}

/// A window's row, printed as it completes.
pub(super) fn live_row(w: &Window) -> String {
    fixed(&window_cells(w))
}

/// The windows' rates' mean.
fn mean_line(totals: &WindowTotals) -> String {
    match (totals.rate_mean_s_per_day, totals.rate_mean_se_s_per_day) {
        (Some(m), Some(se)) => format!(
            "Mean of {} windows' rates: {} ± {} s/day (the standard error from their scatter)\n",
            totals.windows_with_rate,
            num(m, 4),
            num(se, 2)
        ),
        (Some(m), None) => format!("One window's rate: {} s/day\n", num(m, 4)),
        _ => "No window holds enough ticks for a rate\n".to_string(),
    }
}

/// The windows of `--every` as a table, and their rates' mean.
fn windows(r: &ListenJson, totals: &WindowTotals) -> String {
    let rows: Vec<Vec<String>> = r.listening.windows.iter().map(window_cells).collect();
    let mut out = format!("\nEvery {} s\n", num(totals.every_s, 6));
    out.push_str(&table(&WINDOW_COLUMNS, &rows));
    out.push_str(&mean_line(totals));
    out
}
