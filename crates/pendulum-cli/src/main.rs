//! The `pendulum` binary: the library's [`pendulum_cli::run`] on the
//! process's arguments.

use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(pendulum_cli::run(std::env::args_os()))
}
