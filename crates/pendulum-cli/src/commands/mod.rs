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
mod fit_trajectory;
mod gravity;
mod length;
mod listen;
mod measured;
pub(crate) mod period;
mod regulate;
mod report;
pub(crate) mod simulate;
mod synth;
mod train;

use crate::args::{Command, FitCommand};
use crate::error::CliError;
use crate::file::{check_outputs, is_stdout};
use crate::output::Output;
use std::path::Path;

/// The files a command writes (flag and path, when asked for), and whether
/// it prints JSON or CSV for programs on standard output.
fn outputs(command: &Command) -> (Vec<(&'static str, Option<&Path>)>, bool) {
    match command {
        Command::Period(a) => (
            vec![("--plot", a.plot.as_deref())],
            a.format.json || a.format.csv,
        ),
        Command::Damped(a) => (
            vec![
                ("--trajectory", a.trajectory.as_deref()),
                ("--plot", a.plot.as_deref()),
            ],
            a.json,
        ),
        Command::Simulate(a) => (
            vec![
                ("--swings", a.swings.as_deref()),
                ("--trajectory", a.trajectory.as_deref()),
                ("--plot", a.plot.as_deref()),
                ("--phase-plot", a.phase_plot.as_deref()),
            ],
            a.json,
        ),
        Command::Fit(f) => match &f.what {
            FitCommand::Decay(a) => (
                vec![
                    ("--plot", a.plot.as_deref()),
                    ("--turning-points", a.turning_points.as_deref()),
                ],
                a.json,
            ),
            FitCommand::Trajectory(a) => (
                vec![
                    ("--residuals", a.residuals.as_deref()),
                    ("--plot", a.plot.as_deref()),
                ],
                a.json,
            ),
            FitCommand::Beats(a) => (vec![("--plot", a.plot.as_deref())], a.json),
        },
        Command::Listen(a) => (
            vec![
                ("--ticks", a.ticks.as_deref()),
                ("--plot", a.plot.as_deref()),
            ],
            a.json,
        ),
        Command::Synth(s) => match &s.what {
            crate::args::SynthCommand::Ticks(a) => (
                vec![
                    ("OUT.wav", Some(a.output.as_path())),
                    ("--truth", a.truth.as_deref()),
                ],
                false,
            ),
        },
        Command::Train(a) => (Vec::new(), a.json),
        Command::Regulate(a) => (Vec::new(), a.json),
        Command::Compensate(a) => (vec![("--write", a.write.as_deref())], a.json),
        Command::Design(a) => (Vec::new(), a.json),
        Command::Clock(a) => (
            vec![
                ("--swings", a.swings.as_deref()),
                ("--plot", a.plot.as_deref()),
            ],
            a.json,
        ),
        Command::Length(_) | Command::Amplitude(_) | Command::Gravity(_) | Command::Report(_) => {
            (Vec::new(), false)
        }
    }
}

/// The files a command reads (flag and path, when given).
fn inputs(command: &Command) -> Vec<(&'static str, Option<&Path>)> {
    fn one<'a>(flag: &'static str, path: &'a Path) -> (&'static str, Option<&'a Path>) {
        (flag, Some(path))
    }
    fn design(path: &Option<std::path::PathBuf>) -> (&'static str, Option<&Path>) {
        ("--design", path.as_deref())
    }
    match command {
        Command::Period(a) => vec![design(&a.design)],
        Command::Amplitude(a) => vec![design(&a.design)],
        Command::Damped(a) => vec![design(&a.swing.design)],
        Command::Simulate(a) => vec![design(&a.swing.design)],
        Command::Fit(f) => match &f.what {
            FitCommand::Decay(a) => vec![one("FILE", &a.file), design(&a.design)],
            FitCommand::Trajectory(a) => vec![one("FILE", &a.file), design(&a.design)],
            FitCommand::Beats(a) => vec![one("FILE", &a.file)],
        },
        Command::Listen(a) => vec![one("FILE", &a.file)],
        Command::Train(a) => vec![design(&a.design)],
        Command::Regulate(a) => vec![design(&a.design)],
        Command::Compensate(a) => vec![one("--design", &a.design)],
        Command::Design(a) => vec![one("FILE.toml", &a.file)],
        Command::Clock(a) => vec![design(&a.design), ("--drive-file", a.drive_file.as_deref())],
        Command::Report(a) => vec![design(&a.design)],
        Command::Length(_) | Command::Gravity(_) | Command::Synth(_) => Vec::new(),
    }
}

/// Runs one subcommand and returns what it prints. Its output files are
/// checked first, in one place: none a folder, no two the same, at most
/// one `-`; with data on standard output, the command's own text goes to
/// standard error, and JSON or CSV (which would mix with the data) is
/// refused.
pub fn run(command: &Command) -> Result<Output, CliError> {
    let (files, machine) = outputs(command);
    check_outputs(&files, &inputs(command))?;
    if let Command::Report(a) = command {
        crate::file::AtomicFolder::check(&a.output, "--output")?;
    }
    let data_on_stdout = files.iter().find(|(_, p)| p.is_some_and(is_stdout));
    if let (Some((flag, _)), true) = (data_on_stdout, machine) {
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
        Command::Synth(args) => match &args.what {
            crate::args::SynthCommand::Ticks(a) => synth::run(a),
        },
        Command::Fit(args) => match &args.what {
            FitCommand::Decay(a) => fit_decay::run(a),
            FitCommand::Trajectory(a) => fit_trajectory::run(a),
            FitCommand::Beats(a) => fit_beats::run(a),
        },
    };
    text.map(Output::from)
}
