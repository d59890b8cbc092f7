//! Ctrl-C (and SIGTERM, as `kill` and `timeout` send), in one place: the
//! first asks the running command to stop
//! at its next check (a simulation closes its files whole, a writer
//! removes its temporary file); a command still running two seconds later
//! (a fit has no check inside it), or a second signal, ends the process
//! at once, its temporaries removed.
//! An interrupted command exits with status 130, as Unix tools do.

use crate::error::CliError;
use std::sync::atomic::{AtomicBool, Ordering};

/// Exit status after Ctrl-C (128 + SIGINT).
pub const EXIT_INTERRUPTED: u8 = 130;

static REQUESTED: AtomicBool = AtomicBool::new(false);
/// Whether the running command ends itself on the first Ctrl-C, with its
/// results (live listening).
static HANDLED: AtomicBool = AtomicBool::new(false);

/// Installs the handler (once, at start).
pub fn install() {
    // Installing fails only if a handler exists already, which is harmless.
    let _ = ctrlc::set_handler(|| {
        let first = !REQUESTED.swap(true, Ordering::SeqCst);
        if first && HANDLED.load(Ordering::SeqCst) {
            return;
        }
        if first {
            // The command's own checks end it well within this; one with
            // none (a long fit) is ended here.
            std::thread::sleep(std::time::Duration::from_secs(2));
        }
        crate::file::abandon_all();
        std::process::exit(i32::from(EXIT_INTERRUPTED));
    });
}

/// Says that the running command stops on Ctrl-C by itself and prints
/// its results (a second Ctrl-C still ends it at once).
pub fn stop_is_handled() {
    HANDLED.store(true, Ordering::SeqCst);
}

/// Whether the running command said it stops on Ctrl-C by itself.
pub fn handled() -> bool {
    HANDLED.load(Ordering::Relaxed)
}

/// Whether Ctrl-C was pressed.
pub fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}

/// The error of an interrupted command: nothing written, status 130.
pub fn error() -> CliError {
    CliError::other("interrupted").with_status(EXIT_INTERRUPTED)
}
