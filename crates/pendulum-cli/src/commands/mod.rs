//! One file per subcommand; each turns its arguments into library types,
//! calls the library and renders the result as a `String`.

mod amplitude;
mod clock;
mod common;
mod compensate;
pub(crate) mod damped;
mod design;
mod fit_beats;
mod fit_decay;
mod fit_period;
mod fit_trajectory;
mod gravity;
mod length;
mod listen;
mod log;
mod measured;
pub(crate) mod period;
mod regulate;
mod report;
pub(crate) mod simulate;
mod stability;
mod synth;
mod tide;
mod train;

use crate::args::{Command, FitCommand};
use crate::error::CliError;
use crate::file::{check_outputs, is_stdout};
use crate::output::Output;
use crate::paths::Declared;

/// Runs one subcommand and returns what it prints. Its files (`declared`:
/// found in the parsed arguments by their types) are checked first, in
/// one place: no output a folder, none over an input, no two the same, at
/// most one `-`; with data on standard output, the command's own text goes
/// to standard error, and JSON or CSV (which would mix with the data) is
/// refused.
pub fn run(command: &Command, declared: &Declared) -> Result<Output, CliError> {
    check_outputs(&declared.outputs, &declared.inputs)?;
    if let Command::Report(a) = command {
        crate::file::AtomicFolder::check(&a.output, "--output")?;
    }
    let data_on_stdout = declared.outputs.iter().find(|(_, p)| is_stdout(p));
    if let (Some((flag, _)), true) = (data_on_stdout, declared.machine) {
        return Err(CliError::flag(
            flag,
            "writes to standard output ('-'), where --json or --csv also prints; give it a file",
        ));
    }
    let mut out = run_command(command)?;
    if data_on_stdout.is_some() {
        out.stderr.push_str(&std::mem::take(&mut out.stdout));
    }
    Ok(out)
}

fn run_command(command: &Command) -> Result<Output, CliError> {
    let text = match command {
        Command::Period(args) => period::run(args),
        Command::Length(args) => length::run(args),
        Command::Amplitude(args) => amplitude::run(args),
        Command::Gravity(args) => gravity::run(args),
        Command::Simulate(args) => return simulate::run(args),
        Command::Damped(args) => damped::run(args),
        Command::Report(args) => report::run(args),
        Command::Listen(args) => listen::run(args),
        Command::Train(args) => train::run(args),
        Command::Regulate(args) => regulate::run(args),
        Command::Compensate(args) => compensate::run(args),
        Command::Design(args) => design::run(args),
        Command::Clock(args) => clock::run(args),
        Command::Stability(args) => stability::run(args),
        Command::Log(args) => log::run(args),
        Command::Tide(args) => tide::run(args),
        Command::Synth(args) => match &args.what {
            crate::args::SynthCommand::Ticks(a) => synth::run(a),
        },
        Command::Fit(args) => match &args.what {
            FitCommand::Decay(a) => fit_decay::run(a),
            FitCommand::Trajectory(a) => fit_trajectory::run(a),
            FitCommand::Beats(a) => fit_beats::run(a),
            FitCommand::Period(a) => fit_period::run(a),
        },
    };
    text.map(Output::from)
}
