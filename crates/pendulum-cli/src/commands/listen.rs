//! `pendulum listen`: a clock's rate, beat error and jitter from a sound
//! recording, as a timegrapher shows them.

use super::common;
use super::fit_beats::rate_text;
use crate::args::ListenArgs;
use crate::audio::{decode, info, louder_channel};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num, Summary};
use crate::plot::{render, thin, Figure, Panel, Series, Target};
use crate::units::{parse_number, Dimension};
use pendulum_theory::fitting::beat_log::allan_row;
use pendulum_theory::fitting::beat_log::AllanRow;
use pendulum_theory::fitting::beats::{BeatAnalysis, BeatStream};
use pendulum_theory::lift::amplitude_from_lift;
use pendulum_theory::listening::detect::{
    beat_period, clean, envelope_rate, Envelope, MedianSound, OnsetTracker, Refiner, Tick,
};

/// Seconds of the recording the beat period is found from.
const PERIOD_SPAN_S: f64 = 300.0;
use serde::Serialize;

#[derive(Serialize)]
struct ListenJson {
    file: String,
    sample_rate_hz: u32,
    channel: usize,
    duration_s: f64,
    beats: usize,
    mean_beat_s: f64,
    beats_per_hour: f64,
    nominal_beat_s: Option<f64>,
    rate_s_per_day: Option<f64>,
    beat_error_ms: f64,
    /// The split of the two intervals, % (50/50 is in beat).
    in_beat_percent: [f64; 2],
    jitter_ms: f64,
    missed: usize,
    extra: usize,
    /// Tick envelope peak over the envelope's median, dB.
    snr_db: f64,
    allan_deviation: Vec<AllanRow>,
    /// From each beat's unlocking to its drop, ms: ticks, tocks (null when
    /// no second sound stands out).
    drop_ms: [Option<f64>; 2],
    #[serde(skip_serializing_if = "Option::is_none")]
    lift_angle_deg: Option<f64>,
    /// From the exact motion; null when no drop was heard.
    #[serde(skip_serializing_if = "Option::is_none")]
    amplitude_deg: Option<Option<f64>>,
    /// From the first-order formula lift / (2 sin(π Δt / T)).
    #[serde(skip_serializing_if = "Option::is_none")]
    amplitude_first_order_deg: Option<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    ticks_file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    plot_file: Option<String>,
}

pub fn run(args: &ListenArgs) -> Result<String, CliError> {
    let file = args.file.display().to_string();
    let nominal_period = common::period_or_beat_rate(args.period.as_deref(), args.bph.as_deref())?;
    if let Some(p) = nominal_period {
        let flag = if args.period.is_some() {
            "--period"
        } else {
            "--bph"
        };
        pendulum_theory::listening::check_nominal_period(p, args.period.is_none())
            .map_err(|e| CliError::input(flag, &e))?;
    }
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let ppm = match &args.sample_rate_error_ppm {
        Some(t) => {
            let p = parse_number(t).map_err(|e| CliError::flag("--sample-rate-error-ppm", e))?;
            if p.abs() > 1e4 {
                return Err(CliError::flag(
                    "--sample-rate-error-ppm",
                    format!("must be within ±10000 ppm, got {t}"),
                ));
            }
            p
        }
        None => 0.0,
    };
    let channel = match args.channel {
        Some(0) => return Err(CliError::flag("--channel", "channels count from 1")),
        Some(c) => c - 1,
        None => louder_channel(&args.file)?,
    };
    // Pass 1: the beat, from the envelope of the first five minutes.
    let info = info(&args.file)?;
    let rate = f64::from(info.sample_rate);
    let mut env = Envelope::new(rate);
    decode(&args.file, channel, Some(PERIOD_SPAN_S), |block| {
        env.push(block)
    })?;
    let env_rate = envelope_rate(&env, rate);
    let beat = match nominal_period {
        // Near the nominal beat (a clock 3% off is 43 minutes a day off).
        Some(p) => {
            beat_period(&env.values, env_rate, 0.97 * 0.5 * p, 1.03 * 0.5 * p).unwrap_or(0.5 * p)
        }
        None => beat_period(&env.values, env_rate, 0.05, 2.0).ok_or_else(|| {
            CliError::other(format!(
                "{file}: no regular ticking found (silence, noise, or fewer than four beats); \
                 give --bph if the clock is there"
            ))
        })?,
    };
    // Pass 2: each beat's onset on the envelope, streamed (a recording
    // within the first pass is not decoded again).
    let mut tracker = OnsetTracker::new(env_rate, beat);
    let whole = (env.samples as f64) < PERIOD_SPAN_S * rate;
    let samples = if whole {
        tracker.push(&env.values);
        env.samples
    } else {
        let mut env = Envelope::new(rate);
        decode(&args.file, channel, None, |block| {
            env.push(block);
            tracker.push(&env.values);
            env.values.clear();
        })?;
        env.samples
    };
    let duration = samples as f64 / rate;
    let coarse = tracker.finish();
    let snr_db = 20.0 * (coarse.peak / coarse.floor.max(f64::MIN_POSITIVE)).log10();
    // Pass 3: each tick refined on the samples.
    let mut refiner = Refiner::new(rate, &coarse);
    decode(&args.file, channel, None, |block| refiner.push(block))?;
    // (What the refiner and the clean-up drop is counted below as missed.)
    let (ticks, _, sounds) = refiner.finish_with_sounds();
    let (ticks, _, _) = clean(ticks);
    if ticks.len() < 4 {
        let expected = (duration / beat).round();
        if expected < 4.0 {
            return Err(CliError::other(format!(
                "{file}: {} s of sound holds fewer than four beats of {} s; record at least a \
                 minute",
                num(duration, 3),
                num(beat, 4)
            )));
        }
        // Silence has no signal to noise ratio to speak of.
        let snr = if snr_db.is_finite() {
            format!(" (signal to noise {} dB)", num(snr_db, 2))
        } else {
            " (the recording is silent)".to_string()
        };
        return Err(CliError::other(format!(
            "{file}: {} of about {expected} beats stand out of the noise{snr}; \
             record nearer the clock, or in a quieter room",
            ticks.len(),
        )));
    }
    let scale = 1.0 / (1.0 + ppm * 1e-6);
    // The ticks were followed beat by beat, through any stretch the noise
    // covered: gaps up to a thousand beats are missed beats, not pauses.
    let mut stream = BeatStream::filling_up_to(1000);
    for t in &ticks {
        stream
            .push(t.time * scale)
            .map_err(|e| CliError::other(format!("{file}: {e}")))?;
    }
    let a = stream
        .finish(nominal_period.map(|p| 0.5 * p))
        .map_err(|e| CliError::other(format!("{file}: {e}")))?;
    let plot_file = match &plot {
        Some(target) => Some(draw(target, &ticks, scale, &a, sounds.as_ref(), rate)?),
        None => None,
    };
    let ticks_file = match &args.ticks {
        Some(path) => {
            let mut out = CsvFile::create(path, "--ticks", "time_s,side,amplitude")?;
            for t in &ticks {
                out.number(Some(t.time * scale))
                    .integer(u64::from(t.side))
                    .number(Some(t.amplitude))
                    .end_row()?;
            }
            Some(out.commit()?)
        }
        None => None,
    };
    let half = 50.0 * a.beat_error_ms * 1e-3 / a.mean_beat;
    // The drop: the mean of the two sides' (a clock's pallets may differ).
    let drops = coarse.drops.map(|d| d.map(|d| d * scale));
    let heard: Vec<f64> = drops.iter().flatten().copied().collect();
    let crossing = (!heard.is_empty()).then(|| heard.iter().sum::<f64>() / heard.len() as f64);
    let lift = match &args.lift_angle {
        Some(text) => {
            let lift = common::quantity("--lift-angle", text, Dimension::Angle)?;
            if !(lift > 0.0 && lift < std::f64::consts::PI) {
                return Err(CliError::flag(
                    "--lift-angle",
                    format!("must be between 0 and 180°, got {text}"),
                ));
            }
            let amplitude = match crossing {
                Some(dt) => Some(
                    amplitude_from_lift(lift, dt, 2.0 * a.mean_beat)
                        .map_err(|e| CliError::flag("--lift-angle", e.detail()))?,
                ),
                None => None,
            };
            Some((lift, amplitude))
        }
        None => None,
    };
    let result = ListenJson {
        file,
        sample_rate_hz: info.sample_rate,
        channel: channel + 1,
        duration_s: duration,
        beats: a.beats,
        mean_beat_s: a.mean_beat,
        beats_per_hour: a.beats_per_hour,
        nominal_beat_s: a.nominal_beat,
        rate_s_per_day: a.rate_s_per_day,
        beat_error_ms: a.beat_error_ms,
        in_beat_percent: [50.0 + half, 50.0 - half],
        jitter_ms: a.jitter_ms,
        // Every beat the tracker followed, less the ticks kept: missed,
        // whether no sound was there or it was dropped as noise (counted
        // once, though the analysis fills the same gaps).
        missed: (coarse.onsets.len() + coarse.missed).saturating_sub(ticks.len()),
        extra: a.repaired.doubled,
        snr_db,
        allan_deviation: a.allan_deviation.iter().map(allan_row).collect(),
        drop_ms: drops.map(|d| d.map(|d| d * 1e3)),
        lift_angle_deg: lift.map(|l| l.0.to_degrees()),
        amplitude_deg: lift.map(|l| l.1.map(|a| a.amplitude.to_degrees())),
        amplitude_first_order_deg: lift.map(|l| l.1.map(|a| a.first_order.to_degrees())),
        ticks_file,
        plot_file,
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    s.row(
        "Recording",
        format!(
            "{} s at {} Hz, channel {} of {}",
            num(result.duration_s, 6),
            result.sample_rate_hz,
            result.channel,
            info.channels
        ),
    )
    .row(
        "Beats",
        format!(
            "{} ({} missed, {} extra), {} beats/hour",
            result.beats,
            result.missed,
            result.extra,
            num(result.beats_per_hour, 7)
        ),
    )
    .row(
        "Rate",
        rate_text(result.rate_s_per_day, result.nominal_beat_s),
    )
    .row(
        "Beat error",
        format!(
            "{} ms (in beat {}/{} %)",
            num(result.beat_error_ms, 3),
            num(result.in_beat_percent[0], 3),
            num(result.in_beat_percent[1], 3)
        ),
    )
    .row("Jitter", format!("{} ms", num(result.jitter_ms, 3)))
    .row(
        "Drop",
        match result.drop_ms {
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
    if let (Some(lift), Some(amplitude)) = (result.lift_angle_deg, result.amplitude_deg) {
        s.row(
            "Amplitude",
            match (amplitude, result.amplitude_first_order_deg.flatten()) {
                (Some(exact), Some(first)) => format!(
                    "{}° from the {}° lift (first order: {}°)",
                    num(exact, 4),
                    num(lift, 4),
                    num(first, 4)
                ),
                _ => "not determined (no drop sound to time the lift by)".to_string(),
            },
        );
    }
    s.row("Signal to noise", format!("{} dB", num(result.snr_db, 3)));
    if let Some(f) = &result.ticks_file {
        s.row("Ticks file", f.clone());
    }
    if let Some(f) = &result.plot_file {
        s.row("Plot", f.clone());
    }
    Ok(s.render())
}

/// Points of the paper strip kept, at most.
const STRIP_LIMIT: usize = 8192;

/// The timegrapher's picture: the paper strip (each beat's offset from the
/// nominal beat against time, ticks and tocks apart: the rate is the
/// slope, the beat error the gap between the two traces) and the median
/// tick and tock sounds overlaid.
fn draw(
    target: &Target,
    ticks: &[Tick],
    scale: f64,
    a: &BeatAnalysis,
    sounds: Option<&[MedianSound; 2]>,
    rate: f64,
) -> Result<String, CliError> {
    let beat = a.nominal_beat.unwrap_or(a.mean_beat);
    let (first_beat, first_time) = ticks.first().map_or((0, 0.0), |t| (t.beat, t.time * scale));
    let strip = |side: u8| -> Vec<(f64, f64)> {
        let points = ticks
            .iter()
            .filter(|t| t.side == side)
            .map(|t| {
                let time = t.time * scale;
                let expected = first_time + (t.beat - first_beat) as f64 * beat;
                (time, 1e3 * (time - expected))
            })
            .collect();
        thin(points, STRIP_LIMIT)
    };
    let against = match a.nominal_beat {
        Some(_) => format!("{} beats/hour", num(3600.0 / beat, 6)),
        None => "the mean beat".to_string(),
    };
    let strip = Panel::new(
        format!("Paper strip: each beat against {against}"),
        "time (s)",
        "offset (ms)",
        vec![
            Series::dots("ticks", strip(0)),
            Series::dots("tocks", strip(1)),
        ],
    );
    let mut panels = vec![strip];
    if let Some(sounds) = sounds {
        let wave = |s: &MedianSound| -> Vec<(f64, f64)> {
            s.samples
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
    render(target, &Figure { panels })
}
