//! `pendulum`: the theory of the clock pendulum from the command line.
//!
//! The command is this library's [`run`], called by the binary
//! (`src/main.rs`) and by the Python package's `pendulum` entry point
//! (`pendulum_theory`'s console script), so that one build gives both.
//!
//! [`run`] only wires: parse the arguments, run the subcommand, check
//! that what it is about to print holds no non-finite number, print it or
//! one error line. Exit status: 0 on success, 2 on any error, 130 after
//! Ctrl-C.

mod args;
mod audio;
mod commands;
mod data;
mod design;
mod error;
mod file;
mod interrupt;
mod output;
mod paths;
mod plot;
mod stream;
mod units;
mod work;

use clap::error::ErrorKind;
use clap::{CommandFactory, FromArgMatches};
use error::{one_line_clap_error, CliError, EXIT_ERROR};
use output::Output;
use std::ffi::OsString;
use std::io::Write;

/// Runs the command line `args` (the program's name first, as
/// `std::env::args_os` gives it) and returns the exit status: 0 on
/// success, 2 on any error, 130 after Ctrl-C. It prints to the process's
/// standard output and error, and installs the process's Ctrl-C handler
/// and panic hook: one run per process.
pub fn run<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let definition = args::Cli::command();
    let parsed = definition
        .clone()
        .try_get_matches_from(args)
        .and_then(|m| args::Cli::from_arg_matches(&m).map(|cli| (cli, m)));
    let (cli, matches) = match parsed {
        Ok(parsed) => parsed,
        Err(e) => return clap_exit(&e),
    };
    let declared = paths::declared(&definition, &matches);
    work::set_quiet(cli.quiet);
    interrupt::install();
    install_panic_cleanup();
    let result = commands::run(&cli.command, &declared).and_then(|out| {
        // A command that does not stop on Ctrl-C by itself is stopped here:
        // nothing of it is printed.
        if interrupt::requested() && out.status == 0 && !interrupt::handled() {
            return Err(interrupt::error());
        }
        output::check_finite_text(&out.stdout)?;
        output::check_finite_text(&out.stderr)?;
        Ok(out)
    });
    // The run's outputs are one transaction: all put in place, or none.
    match result.and_then(|out| file::commit_all().map(|()| out)) {
        Ok(out) => print(&out),
        Err(e) => {
            file::abandon_all();
            fail(&e)
        }
    }
}

/// A panic (a defect: every input error is an `Err`) still leaves no
/// temporary file behind; the default report follows.
fn install_panic_cleanup() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if !audio::quiet_panics() {
            file::abandon_all();
            default(info);
        }
    }));
}

/// Help and version print as clap renders them; errors become one line.
fn clap_exit(e: &clap::Error) -> u8 {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = e.print();
            0
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            EXIT_ERROR as u8
        }
        _ => fail(&CliError::other(one_line_clap_error(e))),
    }
}

fn fail(error: &CliError) -> u8 {
    // What the reader left out before the refusal goes on its one line:
    // it may be why (every row skipped for a blank cell).
    let notes = output::take_warnings();
    let also = if notes.is_empty() {
        String::new()
    } else {
        format!(" (and: {})", notes.join("; "))
    };
    // (Written, not `eprintln!`, which panics on a closed standard error.)
    let _ = writeln!(std::io::stderr().lock(), "error: {error}{also}");
    error.status()
}

/// Writes the output; a closed pipe (`pendulum … | head`, also with
/// `2>&1`) is not an error: the reader has what it wanted, exit 0.
fn print(out: &Output) -> u8 {
    // With --quiet the summary beside data on standard output is left
    // out, but never its warnings.
    let mut stderr: String = output::take_warnings()
        .iter()
        .map(|w| format!("warning: {w}\n"))
        .collect();
    stderr.push_str(&out.stderr);
    let stderr: String = if work::quiet() {
        stderr
            .lines()
            .filter(|l| l.to_lowercase().contains("warning"))
            .map(|l| format!("{l}\n"))
            .collect()
    } else {
        stderr
    };
    if !stderr.is_empty() {
        let _ = std::io::stderr().lock().write_all(stderr.as_bytes());
    }
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(out.stdout.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Ok(()) => out.status,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => out.status,
        Err(e) => fail(&CliError::other(format!(
            "could not write to standard output: {e}"
        ))),
    }
}
