//! How long a command will run and how much it will write, judged before
//! it starts, in one place for every long path (a trajectory, a
//! simulation, a clock's long run, a synthetic recording, a fit of
//! millions of rows): a run estimated at more than the library's `FORCE_SECONDS` of
//! computing needs `--force`; one of more than `IMPOSSIBLE_SECONDS`
//! (it would not end in a day), or one whose output would not fit the
//! free space of the disk it goes to, is refused even with it. A progress
//! bar shows on anything that runs for more than a second.

use crate::error::CliError;
use crate::output::num;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::Path;
use std::time::{Duration, Instant};

/// Refuses, naming `flag` and saying `why` the run is long, a run of
/// `seconds` of computing beyond what `force` allows: the library's rule
/// ([`pendulum_theory::analysis::judge_work`]), said of the flag.
pub fn check_time(
    flag: &str,
    why: impl std::fmt::Display,
    seconds: f64,
    force: bool,
) -> Result<(), CliError> {
    pendulum_theory::analysis::judge_work("", why, seconds, force)
        .map_err(|r| CliError::flag(flag, r.reason))
}

/// Refuses an output of about `bytes` to `path` (named by `flag`) that
/// would not fit the free space of its disk; `--force` never lifts this.
/// Standard output is not checked.
pub fn check_space(flag: &str, path: &Path, bytes: f64) -> Result<(), CliError> {
    // Standard output, a device or a pipe: nothing to fill.
    if crate::file::is_stdout(path) || std::fs::metadata(path).is_ok_and(|m| !m.is_file()) {
        return Ok(());
    }
    let folder = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let Some(free) = free_bytes(folder) else {
        return Ok(());
    };
    if bytes > free as f64 {
        return Err(CliError::flag(
            flag,
            format!(
                "would write about {} and the disk it goes to has {} free; shorten the run \
                 or sample it less often",
                human_bytes(bytes),
                human_bytes(free as f64)
            ),
        ));
    }
    Ok(())
}

/// The bytes free to an ordinary user on the file system of `folder`.
fn free_bytes(folder: &Path) -> Option<u64> {
    use std::os::unix::ffi::OsStrExt;
    let name = std::ffi::CString::new(folder.as_os_str().as_bytes()).ok()?;
    let mut stats: libc::statvfs = unsafe { std::mem::zeroed() };
    // SAFETY: `name` is a NUL-terminated path and `stats` a valid struct
    // that statvfs fills in; nothing is kept past the call.
    let status = unsafe { libc::statvfs(name.as_ptr(), &mut stats) };
    (status == 0).then(|| {
        #[allow(clippy::useless_conversion)] // c_ulong: u32 on some targets
        u64::from(stats.f_bavail).saturating_mul(u64::from(stats.f_frsize))
    })
}

pub use pendulum_theory::analysis::human_seconds;

/// A size for people: "12 MB", "3.1 GB", "4e6 TB".
pub fn human_bytes(b: f64) -> String {
    if !b.is_finite() {
        return "an unbounded amount".to_string();
    }
    let units = [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")];
    for (size, name) in units {
        if b >= size {
            return format!("{} {name}", num(b / size, 2));
        }
    }
    format!("{} bytes", num(b, 3))
}

static QUIET: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// `--quiet`: no bar or spinner for the rest of the run.
pub fn set_quiet(quiet: bool) {
    QUIET.store(quiet, std::sync::atomic::Ordering::Relaxed);
}

/// Whether `--quiet` was given.
pub fn quiet() -> bool {
    QUIET.load(std::sync::atomic::Ordering::Relaxed)
}

/// A spinner on standard error for a step that reports no progress (a
/// fit), shown when it is estimated at more than a second (and, as every
/// bar, only when standard error is a terminal); it goes when dropped.
pub struct Spinner(Option<ProgressBar>);

impl Spinner {
    /// Starts the spinner saying `what` ("fitting 2e6 rows"), if the step
    /// is estimated at more than a second.
    pub fn start(what: String, seconds: f64) -> Self {
        if seconds <= 1.0 || quiet() {
            return Self(None);
        }
        let bar = ProgressBar::new_spinner();
        bar.set_message(format!("{what} (about {})", human_seconds(seconds)));
        bar.enable_steady_tick(Duration::from_millis(120));
        Self(Some(bar))
    }
}

impl Drop for Spinner {
    fn drop(&mut self) {
        if let Some(bar) = self.0.take() {
            bar.finish_and_clear();
        }
    }
}

/// A progress bar on standard error, shown only after a second of work
/// and only when standard error is a terminal (indicatif hides it
/// otherwise), over `total` units of work.
pub struct Progress {
    bar: Option<ProgressBar>,
    total: f64,
    label: &'static str,
    started: Instant,
}

impl Progress {
    /// A bar over `total` units (s of simulated time, rows, samples),
    /// labelled `label` ("simulated"); with `--quiet` none is shown.
    pub fn new(total: f64, label: &'static str) -> Self {
        Self {
            bar: None,
            total,
            label,
            started: Instant::now(),
        }
    }

    /// Work done so far, in the units of `total`; `shown` says it for
    /// people ("3600 s").
    pub fn update(&mut self, done: f64, shown: impl FnOnce() -> String) {
        if quiet() || self.total.is_nan() || self.total <= 0.0 {
            return;
        }
        if self.bar.is_none() && self.started.elapsed() > Duration::from_secs(1) {
            let bar = ProgressBar::new(1000);
            let template = format!(
                "{{spinner}} {} {{msg}} [{{bar:40}}] {{percent}}% (eta {{eta}})",
                self.label
            );
            if let Ok(style) = ProgressStyle::with_template(&template) {
                bar.set_style(style.progress_chars("=> "));
            }
            self.bar = Some(bar);
        }
        if let Some(bar) = &self.bar {
            bar.set_position((1000.0 * (done / self.total).clamp(0.0, 1.0)) as u64);
            bar.set_message(shown());
        }
    }

    /// Removes the bar.
    pub fn finish(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.finish();
    }
}
