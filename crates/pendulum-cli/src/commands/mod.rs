//! One file per subcommand; each turns its arguments into library types,
//! calls the library and renders the result as a `String`.

mod amplitude;
mod common;
pub(crate) mod damped;
mod fit_beats;
mod fit_decay;
mod fit_trajectory;
mod gravity;
mod length;
pub(crate) mod period;
mod report;
pub(crate) mod simulate;

use crate::args::Command;
use crate::error::CliError;
use crate::output::Output;

/// Runs one subcommand and returns what it prints.
pub fn run(command: &Command) -> Result<Output, CliError> {
    let text = match command {
        Command::Period(args) => period::run(args),
        Command::Length(args) => length::run(args),
        Command::Amplitude(args) => amplitude::run(args),
        Command::Gravity(args) => gravity::run(args),
        Command::Simulate(args) => return simulate::run(args),
        Command::Damped(args) => return damped::run(args),
        Command::Report(args) => report::run(args),
        Command::Fit(args) => match &args.what {
            crate::args::FitCommand::Decay(a) => fit_decay::run(a),
            crate::args::FitCommand::Trajectory(a) => fit_trajectory::run(a),
            crate::args::FitCommand::Beats(a) => fit_beats::run(a),
        },
    };
    text.map(Output::from)
}
