//! Ctrl-C, in one place: the first press asks the running command to stop
//! at its next check (a simulation closes its files whole, a writer
//! removes its temporary file), a second press ends the process at once.
//! An interrupted command exits with status 130, as Unix tools do.

use crate::error::CliError;
use std::sync::atomic::{AtomicBool, Ordering};

/// Exit status after Ctrl-C (128 + SIGINT).
pub const EXIT_INTERRUPTED: u8 = 130;

static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Installs the handler (once, at start).
pub fn install() {
    // Installing fails only if a handler exists already, which is harmless.
    let _ = ctrlc::set_handler(|| {
        if REQUESTED.swap(true, Ordering::SeqCst) {
            crate::file::abandon_all();
            std::process::exit(i32::from(EXIT_INTERRUPTED));
        }
    });
}

/// Whether Ctrl-C was pressed.
pub fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}

/// The error of an interrupted command: nothing written, status 130.
pub fn error() -> CliError {
    CliError::other("interrupted").with_status(EXIT_INTERRUPTED)
}
