//! `pendulum listen`: a clock's rate, beat error and jitter from a sound
//! recording, as a timegrapher shows them. The listening is one library
//! call ([`pendulum_theory::listening::analysis::listen`]) over the
//! decoded file; this reads the arguments, writes the ticks and renders.

mod figure;
mod live;
mod text;

use super::common;
use crate::args::ListenArgs;
use crate::audio::{clearest_channel, info, FileSource};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output;
use crate::plot::Target;
use pendulum_theory::listening::analysis::{
    listen, sound_card_error, Calibration, ListenFailure, ListenInput, Listening, Oscillator,
};
use serde::Serialize;

/// The command's JSON: the file's keys around the library's result.
#[derive(Serialize)]
struct ListenJson<'a> {
    file: String,
    channel: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    reference: Option<ReferenceJson>,
    #[serde(flatten)]
    listening: &'a Listening,
    #[serde(skip_serializing_if = "Option::is_none")]
    ticks_file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    windows_file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    plot_file: Option<String>,
}

/// The reference's measure of the sound card, with its file.
#[derive(Serialize)]
struct ReferenceJson {
    file: String,
    channel: usize,
    #[serde(flatten)]
    calibration: Calibration,
}

/// The sound card's error measured on `path` (`--reference`).
fn reference(path: &std::path::Path) -> Result<ReferenceJson, CliError> {
    let file = path.display().to_string();
    let channel = clearest_channel(path)?;
    let mut source = FileSource {
        path,
        channel,
        info: info(path)?,
    };
    let calibration = sound_card_error(&mut source).map_err(|f| match f {
        ListenFailure::Source(e) => e,
        ListenFailure::Refused(r) => CliError::flag("--reference", format!("{file}: {}", r.reason)),
    })?;
    Ok(ReferenceJson {
        file,
        channel: channel + 1,
        calibration,
    })
}

pub fn run(args: &ListenArgs) -> Result<String, CliError> {
    let known = common::known(&args.advice)?;
    pendulum_theory::advice::check(&known).map_err(|e| common::refused(&e))?;
    let reference = args.reference.as_deref().map(reference).transpose()?;
    let ppm = match &reference {
        Some(r) => Some(r.calibration.sample_rate_error_ppm),
        None => args.sample_rate_error_ppm.map(|p| p.0),
    };
    let input = ListenInput {
        nominal: common::nominal(args.period, args.bph),
        sample_rate_error_ppm: ppm,
        lift_angle: args.lift_angle.map(|a| a.0),
        oscillator: args
            .oscillator
            .as_deref()
            .map(Oscillator::parse)
            .transpose()
            .map_err(|r| CliError::flag("--oscillator", r.reason))?,
        every: args.every.map(|t| t.0),
    };
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    if crate::file::is_stdout(&args.file) {
        let heard = live::listen(args, &input)?;
        return render(args, reference, plot.as_ref(), heard, &known);
    }
    if args.raw.is_some() {
        return Err(CliError::flag(
            "--raw",
            "is for samples on standard input: give - as the file",
        ));
    }
    let file = args.file.display().to_string();
    let channel = match args.channel {
        Some(0) => return Err(CliError::flag("--channel", "channels count from 1")),
        Some(c) => c - 1,
        None => clearest_channel(&args.file)?,
    };
    let info = info(&args.file)?;
    let mut source = FileSource {
        path: &args.file,
        channel,
        info,
    };
    let result = listen(&mut source, &input).map_err(|f| match f {
        ListenFailure::Source(e) => e,
        ListenFailure::Refused(r) => refused(&file, &r),
    })?;
    let heard = Heard {
        file,
        channel,
        channels: info.channels,
        result,
        printed: None,
    };
    render(args, reference, plot.as_ref(), heard, &known)
}

/// A refusal of the recording `file`, as an error.
fn refused(file: &str, r: &pendulum_theory::analysis::Refusal) -> CliError {
    CliError::refused(r, &[], &|_, reason| {
        CliError::other(format!("{file}: {reason}"))
    })
}

/// What was listened to, and how.
struct Heard {
    /// The file's name (`-` for standard input).
    file: String,
    /// Its channel, from 0, of `channels`.
    channel: usize,
    channels: usize,
    /// The library's result.
    result: Listening,
    /// Listening live: the windows' rows already printed.
    printed: Option<usize>,
}

/// The files asked for written, and the result rendered.
fn render(
    args: &ListenArgs,
    reference: Option<ReferenceJson>,
    plot: Option<&Target>,
    mut heard: Heard,
    known: &pendulum_theory::advice::Known,
) -> Result<String, CliError> {
    heard
        .result
        .advise(known)
        .map_err(|e| common::refused(&e))?;
    let result = &heard.result;
    let plot_file = match plot {
        Some(target) => Some(figure::draw(target, result)?),
        None => None,
    };
    let ticks_file = match &args.ticks {
        Some(path) => {
            // (`sound_level`: the band-passed sound's peak, full scale 1;
            // `amplitude`, the same, its old name, kept for one release:
            // it is not the pendulum's amplitude.)
            let mut out = CsvFile::create(path, "--ticks", "time_s,side,sound_level,amplitude")?;
            for t in &result.ticks {
                out.number(Some(t.time))
                    .integer(u64::from(t.side))
                    .number(Some(t.amplitude))
                    .number(Some(t.amplitude))
                    .end_row()?;
            }
            Some(out.commit()?)
        }
        None => None,
    };
    let windows_file = match &args.windows {
        Some(path) => {
            let mut out = CsvFile::create(
                path,
                "--windows",
                "start_s,end_s,beats,rate_s_per_day,rate_se_s_per_day,beat_error_ms,drop_ms,\
                 amplitude_deg,snr_db",
            )?;
            for w in &result.windows {
                out.number(Some(w.start_s))
                    .number(Some(w.end_s))
                    .integer(w.beats as u64)
                    .number(w.rate_s_per_day)
                    .number(w.rate_se_s_per_day)
                    .number(w.beat_error_ms)
                    .number(w.drop_ms)
                    .number(w.amplitude_deg)
                    .number(w.snr_db)
                    .end_row()?;
            }
            Some(out.commit()?)
        }
        None => None,
    };
    let json = ListenJson {
        file: heard.file,
        channel: heard.channel + 1,
        reference,
        listening: result,
        ticks_file,
        windows_file,
        plot_file,
    };
    match (args.json, heard.printed) {
        // (Live, the windows came a line each: the whole result is a line.)
        (true, Some(_)) => output::json_line(&json),
        (true, None) => output::json(&json),
        (false, printed) => Ok(text::render(&json, heard.channels, printed)),
    }
}
