//! `pendulum synth ticks`: a recording of a ticking clock with known truth.

use super::common;
use crate::args::{DropArg, SynthTicksArgs};
use crate::audio::{pcm16, wav_header};
use crate::error::CliError;
use crate::file::{AtomicFile, CsvFile};
use crate::output::num;
use crate::units::or_default;
use crate::work;
use pendulum_theory::listening::synth::{
    check_interference, typical_drop_ms, Interference, Synthesizer, TickRecording,
    DEFAULT_INTERFERENCE_DB,
};

pub fn run(args: &SynthTicksArgs) -> Result<String, CliError> {
    // Each input not given is the library's.
    let d = TickRecording::DEFAULT;
    let spec = TickRecording {
        sample_rate: args.sample_rate.map_or(d.sample_rate, |s| s.0),
        duration: args.duration.map_or(d.duration, |t| t.0),
        beats_per_hour: or_default(args.bph, d.beats_per_hour),
        rate_s_per_day: or_default(args.rate, d.rate_s_per_day),
        rate_change_s_per_day_per_hour: or_default(
            args.rate_change,
            d.rate_change_s_per_day_per_hour,
        ),
        beat_error_ms: or_default(args.beat_error, d.beat_error_ms),
        snr_db: or_default(args.snr_db, d.snr_db),
        reverb_s: args.reverb.map_or(d.reverb_s, |t| t.0),
        hum_db: or_default(args.hum_db, d.hum_db),
        missing: or_default(args.missing, d.missing),
        tock_db: or_default(args.tock_db, d.tock_db),
        drop_ms: match args.drop {
            None => d.drop_ms,
            Some(DropArg::Ms(ms)) => Some(ms),
            Some(DropArg::Clock) => Some(typical_drop_ms(
                3600.0 / or_default(args.bph, d.beats_per_hour),
            )),
        },
        arc_change_percent_per_hour: or_default(args.arc_change, d.arc_change_percent_per_hour),
        periodic_error_ms: or_default(args.periodic_error, d.periodic_error_ms),
        periodic_error_period_s: args
            .periodic_error_period
            .map_or(d.periodic_error_period_s, |t| t.0),
        seed: args.seed.unwrap_or(d.seed),
    };
    spec.check().map_err(|e| common::refused(&e))?;
    let interference: Vec<Interference> = [&args.strike, &args.chime, &args.handling]
        .into_iter()
        .flatten()
        .copied()
        .collect();
    let level_db = or_default(args.interference_db, DEFAULT_INTERFERENCE_DB);
    check_interference(&interference, spec.duration, level_db).map_err(|e| common::refused(&e))?;
    let (bph, duration, sample_rate) = (spec.beats_per_hour, spec.duration, spec.sample_rate);
    // The samples are made and written a block at a time: an hour at
    // 48 kHz is 345 MB of WAV but a few MB of memory.
    let mut recording = Synthesizer::new(&spec).interfere(&interference, level_db);
    let header = wav_header(recording.len() as u64, sample_rate).ok_or_else(|| {
        CliError::flag(
            "--duration",
            format!(
                "{} s at {} Hz passes the 4 GiB a WAV file can hold",
                num(duration, 6),
                sample_rate
            ),
        )
    })?;
    let samples = recording.len() as f64;
    work::check_space("OUT.wav", &args.output, 2.0 * samples + 44.0)?;
    if let Some(path) = &args.truth {
        work::check_space("--truth", path, 24.0 * duration * bph / 3600.0)?;
    }
    let mut progress = work::Progress::new(samples, "synthesised");
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
            format!("{} s", num(done / f64::from(sample_rate), 4))
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
        sample_rate,
        recording.ticks.len(),
        recording.missing.len()
    ))
}
