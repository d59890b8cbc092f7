//! `pendulum synth ticks`: a recording of a ticking clock with known truth.

use super::common;
use crate::args::SynthTicksArgs;
use crate::audio::{pcm16, wav_header};
use crate::error::CliError;
use crate::file::{AtomicFile, CsvFile};
use crate::output::num;
use crate::units::{parse_number, Dimension};
use crate::work;
use pendulum_theory::listening::synth::{Synthesizer, TickRecording};

/// Longer recordings are refused (a WAV file holds at most 4 GiB).
const MAX_DURATION_S: f64 = 4.0 * 3600.0;

pub fn run(args: &SynthTicksArgs) -> Result<String, CliError> {
    let number = |flag: &str, text: &str| parse_number(text).map_err(|e| CliError::flag(flag, e));
    let bph = number("--bph", &args.bph)?;
    if !(1800.0..=72_000.0).contains(&bph) {
        return Err(CliError::flag(
            "--bph",
            format!(
                "must be between 1800 and 72000 beats/hour, got {}",
                num(bph, 6)
            ),
        ));
    }
    let duration = common::quantity("--duration", &args.duration, Dimension::Time)?;
    if !(duration > 0.0 && duration <= MAX_DURATION_S) {
        return Err(CliError::flag(
            "--duration",
            format!("must be between 0 and 4 hours, got {} s", num(duration, 6)),
        ));
    }
    if !(8000..=192_000).contains(&args.sample_rate) {
        return Err(CliError::flag(
            "--sample-rate",
            format!(
                "must be between 8000 and 192000 Hz, got {}",
                args.sample_rate
            ),
        ));
    }
    let reverb = common::quantity("--reverb", &args.reverb, Dimension::Time)?;
    if !(0.0..=3.0).contains(&reverb) {
        return Err(CliError::flag("--reverb", "must be between 0 and 3 s"));
    }
    let missing = number("--missing", &args.missing)?;
    if !(0.0..=0.5).contains(&missing) {
        return Err(CliError::flag("--missing", "must be between 0 and 0.5"));
    }
    let spec = TickRecording {
        sample_rate: args.sample_rate,
        duration,
        beats_per_hour: bph,
        rate_s_per_day: number("--rate", &args.rate)?,
        beat_error_ms: number("--beat-error", &args.beat_error)?,
        snr_db: number("--snr-db", &args.snr_db)?,
        reverb_s: reverb,
        hum_db: number("--hum-db", &args.hum_db)?,
        missing,
        seed: args.seed,
    };
    if spec.rate_s_per_day.abs() > 3600.0 {
        return Err(CliError::flag("--rate", "must be within ±3600 s/day"));
    }
    if spec.beat_error_ms.abs() > 0.2 * 1800.0 / bph * 1e3 {
        return Err(CliError::flag(
            "--beat-error",
            "must be less than a fifth of the beat",
        ));
    }
    // The samples are made and written a block at a time: an hour at
    // 48 kHz is 345 MB of WAV but a few MB of memory.
    let mut recording = Synthesizer::new(&spec);
    let header = wav_header(recording.len() as u64, args.sample_rate).ok_or_else(|| {
        CliError::flag(
            "--duration",
            format!(
                "{} s at {} Hz passes the 4 GiB a WAV file can hold",
                num(duration, 6),
                args.sample_rate
            ),
        )
    })?;
    let samples = recording.len() as f64;
    work::check_space("OUT.wav", &args.output, 2.0 * samples + 44.0)?;
    if let Some(path) = &args.truth {
        work::check_space("--truth", path, 24.0 * duration * bph / 3600.0)?;
    }
    let mut progress = work::Progress::new(samples, "synthesised", false);
    let mut done = 0.0;
    let mut file = AtomicFile::create(&args.output, "OUT.wav")?;
    file.writer()
        .write_all(&header)
        .map_err(|e| file.write_error(e))?;
    let mut block = vec![0.0_f32; 1 << 16];
    let mut bytes = Vec::with_capacity(2 * block.len());
    loop {
        if crate::interrupt::requested() {
            return Err(crate::interrupt::error());
        }
        let n = recording.fill(&mut block);
        if n == 0 {
            break;
        }
        done += n as f64;
        progress.update(done, || {
            format!("{} s", num(done / f64::from(args.sample_rate), 4))
        });
        bytes.clear();
        pcm16(&block[..n], &mut bytes);
        file.writer()
            .write_all(&bytes)
            .map_err(|e| file.write_error(e))?;
    }
    let written = file.commit()?;
    if let Some(path) = &args.truth {
        let mut truth = CsvFile::create(path, "--truth", "time_s")?;
        for &t in &recording.ticks {
            truth.number(Some(t)).end_row()?;
        }
        truth.commit()?;
    }
    Ok(format!(
        "{written}: {} s at {} Hz, {} ticks ({} left out)\n",
        num(duration, 6),
        args.sample_rate,
        recording.ticks.len(),
        recording.missing.len()
    ))
}
