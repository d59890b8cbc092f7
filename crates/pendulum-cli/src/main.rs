//! `pendulum`: the theory of the clock pendulum from the command line.
//!
//! This file only wires: parse the arguments, run the subcommand, print its
//! output or one error line. Exit status: 0 on success, 2 on any error.

mod args;
mod commands;
mod data;
mod error;
mod file;
mod output;
mod plot;
mod units;

use clap::error::ErrorKind;
use clap::Parser;
use error::{one_line_clap_error, EXIT_ERROR};
use std::io::Write;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    match commands::run(&cli.command) {
        Ok(text) => print_stdout(&text),
        Err(e) => fail(&e.to_string()),
    }
}

/// Help and version print as clap renders them; errors become one line.
fn clap_exit(e: &clap::Error) -> ExitCode {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = e.print();
            ExitCode::SUCCESS
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = e.print();
            ExitCode::from(EXIT_ERROR as u8)
        }
        _ => fail(&one_line_clap_error(e)),
    }
}

fn fail(message: &str) -> ExitCode {
    eprintln!("error: {message}");
    ExitCode::from(EXIT_ERROR as u8)
}

/// Writes the output; a closed pipe (`pendulum … | head`) is not an error.
fn print_stdout(text: &str) -> ExitCode {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => fail(&format!("could not write to standard output: {e}")),
    }
}
