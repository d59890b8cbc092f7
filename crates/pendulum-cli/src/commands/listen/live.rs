//! `pendulum listen -`: listening live to standard input. The samples go
//! to the library's live listener ([`LiveListener`]) as they come; each
//! window of `--every` is printed as it completes (a table row, or a JSON
//! line `{"window": …}` with `--json`), after a first, provisional reading
//! within the first seconds (a line, or `{"provisional": …}`); the end of
//! the input or Ctrl-C
//! ends the listening, and the whole result is printed as for a file.

use super::text::{live_heading, live_row};
use super::Heard;
use crate::args::ListenArgs;
use crate::error::CliError;
use crate::interrupt;
use crate::output;
use crate::stream::{open, Block, Encoding, Given, Layout};
use pendulum_theory::listening::analysis::ListenInput;
use pendulum_theory::listening::live::{LiveListener, Provisional};
use pendulum_theory::listening::windows::Window;
use serde::Serialize;
use std::io::Write;
use std::sync::mpsc::RecvTimeoutError;
use std::time::Duration;

/// A window printed as a JSON line.
#[derive(Serialize)]
struct WindowLine<'a> {
    window: &'a Window,
}

/// The first reading printed as a JSON line.
#[derive(Serialize)]
struct ProvisionalLine<'a> {
    provisional: &'a Provisional,
}

/// Listens to standard input until its end or Ctrl-C.
pub(super) fn listen(args: &ListenArgs, input: &ListenInput) -> Result<Heard, CliError> {
    let given = match (&args.raw, args.sample_rate) {
        (Some(raw), Some(crate::units::SampleRate(sample_rate))) => {
            if sample_rate == 0 {
                return Err(CliError::flag(
                    "--sample-rate",
                    "must be positive, got 0 Hz",
                ));
            }
            Given::Raw(Layout {
                sample_rate,
                channels: args.channels.unwrap_or(1),
                encoding: Encoding::parse(raw)?,
            })
        }
        _ => Given::Wav,
    };
    let channel = match args.channel {
        Some(0) => return Err(CliError::flag("--channel", "channels count from 1")),
        Some(c) => c - 1,
        None => 0,
    };
    let (layout, blocks) = open(std::io::stdin(), given, channel)?;
    let refused = |r: pendulum_theory::analysis::Refusal| super::refused("-", &r);
    let mut listener = LiveListener::new(layout.sample_rate, input).map_err(refused)?;
    // (The windows go where the command's text goes: to standard error
    // when an output file is standard output.)
    let data_on_stdout = [&args.plot, &args.ticks, &args.windows]
        .iter()
        .any(|p| p.as_deref().is_some_and(crate::file::is_stdout));
    let mut printed = 0usize;
    let mut print = |first: Option<Provisional>, windows: Vec<Window>| -> Result<(), CliError> {
        let mut text = String::new();
        // (With --json and no --every the output is one document.)
        if let Some(p) = first
            .as_ref()
            .filter(|_| !args.json || args.every.is_some())
        {
            if args.json {
                text.push_str(&output::json_line(&ProvisionalLine { provisional: p })?);
            } else {
                text.push_str(&provisional_line(p));
            }
        }
        for w in &windows {
            if args.json {
                text.push_str(&output::json_line(&WindowLine { window: w })?);
            } else {
                if printed == 0 {
                    text.push_str(&live_heading(w.end_s - w.start_s));
                }
                text.push_str(&live_row(w));
            }
            printed += 1;
        }
        if !text.is_empty() {
            // (A reader gone away is not this command's failure.)
            let _ = if data_on_stdout {
                std::io::stderr().write_all(text.as_bytes())
            } else {
                let mut out = std::io::stdout().lock();
                out.write_all(text.as_bytes()).and_then(|()| out.flush())
            };
        }
        Ok(())
    };
    interrupt::stop_is_handled();
    loop {
        match blocks.recv_timeout(Duration::from_millis(200)) {
            Ok(Block::Samples(samples)) => {
                let windows = listener.push(&samples).map_err(refused)?;
                print(listener.take_provisional(), windows)?;
            }
            Ok(Block::Failed(reason)) => return Err(CliError::other(reason)),
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => break,
        }
        if interrupt::requested() {
            break;
        }
    }
    let result = listener.finish().map_err(refused)?;
    Ok(Heard {
        file: "-".to_string(),
        channel,
        channels: layout.channels,
        result,
        printed: input.every.map(|_| printed),
    })
}

/// The first reading in words, marked as provisional.
fn provisional_line(p: &Provisional) -> String {
    use crate::output::num;
    let rate = match (p.rate_s_per_day, p.rate_se_s_per_day) {
        (Some(r), Some(se)) => format!(", rate {} ± {} s/day", num(r, 3), num(se, 2)),
        (Some(r), None) => format!(", rate {} s/day", num(r, 3)),
        _ => String::new(),
    };
    format!(
        "First {} s: {} beats/hour{rate}, beat error {} ms (provisional, from {} beats; each tick is timed finer as the listening goes on)\n",
        num(p.after_s, 3),
        num(p.beats_per_hour, 7),
        num(p.beat_error_ms, 2),
        p.beats
    )
}
