//! The one error type of the binary: a message that names the argument and
//! the fix, printed once by `main` as `error: …` with exit status 2.

use pendulum_theory::analysis::{Place, Refusal};
use pendulum_theory::InputError;
use std::fmt;

/// Exit status for any error: bad arguments, bad input, failed writes.
pub const EXIT_ERROR: i32 = 2;

/// Says a refusal of the data (`None`) or of one sample (its array and
/// index) of the file it came from.
pub type DataError<'a> = dyn Fn(Option<(&'static str, usize)>, &str) -> CliError + 'a;

/// An error with the name of the flag it concerns, when there is one.
#[derive(Debug)]
pub struct CliError {
    message: String,
    status: u8,
}

impl CliError {
    /// An error about the value of `flag` (`--length`).
    pub fn flag(flag: &str, detail: impl fmt::Display) -> Self {
        Self {
            message: format!("{flag}: {detail}"),
            status: EXIT_ERROR as u8,
        }
    }

    /// An error not tied to one flag.
    pub fn other(message: impl Into<String>) -> Self {
        Self {
            message: message.into(),
            status: EXIT_ERROR as u8,
        }
    }

    /// The same error said of `flag` (a file reader's error, attributed
    /// to the flag that named the file).
    pub fn of_flag(self, flag: &str) -> Self {
        Self {
            message: format!("{flag}: {}", self.message),
            status: self.status,
        }
    }

    /// The same error with another exit status (130 after Ctrl-C).
    pub fn with_status(mut self, status: u8) -> Self {
        self.status = status;
        self
    }

    /// The exit status: 2, or 130 after Ctrl-C.
    pub fn status(&self) -> u8 {
        self.status
    }

    /// An analysis's refusal: a field said of its flag (`flags` maps the
    /// library's field names to flags; any other `name` is `--name`), a
    /// sample or the data as a whole by `data` (which names the file,
    /// and the line).
    pub fn refused(refusal: &Refusal, flags: &[(&str, &str)], data: &DataError<'_>) -> Self {
        match refusal.place {
            Place::Field(field) => match flags.iter().find(|(f, _)| *f == field) {
                Some((_, flag)) => Self::flag(flag, &refusal.reason),
                None => Self::flag(&format!("--{}", field.replace('_', "-")), &refusal.reason),
            },
            Place::Sample(field, i) => data(Some((field, i)), &refusal.reason),
            Place::Data => data(None, &refusal.reason),
        }
    }

    /// A library refusal, attributed to `flag`.
    pub fn input(flag: &str, error: &InputError) -> Self {
        Self::flag(flag, error.detail())
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for CliError {}

/// A file's refusal: said of the flag of the reading option it concerns
/// (`run` as `--run`), else as it is.
impl From<pendulum_data::ReadError> for CliError {
    fn from(e: pendulum_data::ReadError) -> Self {
        match e.flag() {
            Some(flag) => Self::flag(&flag, e.message),
            None => Self::other(e.message),
        }
    }
}

/// Collapses clap's multi-line error into one line: its message and tips,
/// without the usage block (`--help` shows that).
pub fn one_line_clap_error(error: &clap::Error) -> String {
    // A value its type refused (a quantity's unit, a number that is not
    // one): the tool's own line, `--flag: why`, as every other refusal.
    if error.kind() == clap::error::ErrorKind::ValueValidation {
        use clap::error::{ContextKind, ContextValue};
        let arg = match error.get(ContextKind::InvalidArg) {
            Some(ContextValue::String(a)) => a.split_whitespace().next().map(str::to_string),
            _ => None,
        };
        let value = match error.get(ContextKind::InvalidValue) {
            Some(ContextValue::String(v)) => v.clone(),
            _ => String::new(),
        };
        if let (Some(flag), Some(why)) = (arg, std::error::Error::source(error)) {
            // Our types' refusals are whole sentences; a count's (an
            // integer's) is the standard library's, which needs the value.
            let ours = why.downcast_ref::<crate::units::UnitError>().is_some()
                || why.downcast_ref::<crate::units::ValueError>().is_some();
            if ours {
                return format!("{flag}: {why}");
            }
            if let Some(e) = why.downcast_ref::<std::num::ParseIntError>() {
                use std::num::IntErrorKind::{Empty, NegOverflow, PosOverflow};
                return match e.kind() {
                    Empty => format!("{flag}: give a whole number"),
                    PosOverflow | NegOverflow => format!("{flag}: '{value}' is out of range"),
                    _ => format!("{flag}: '{value}' is not a whole number"),
                };
            }
            let why = why.to_string();
            return if why.contains(&value) {
                format!("{flag}: {why}")
            } else {
                format!("{flag}: '{value}': {why}")
            };
        }
    }
    let rendered = error.render().to_string();
    let mut parts: Vec<&str> = Vec::new();
    for line in rendered.lines() {
        let line = line.trim();
        if line.starts_with("Usage:") || line.starts_with("For more information") {
            break;
        }
        if !line.is_empty() {
            parts.push(line);
        }
    }
    let mut joined = parts.join(" ");
    // Every --length that is required may be a design instead.
    if error.kind() == clap::error::ErrorKind::MissingRequiredArgument {
        joined = joined.replace("--length <L>", "--length <L> (or --design FILE.toml)");
    }
    let text = joined.strip_prefix("error: ").unwrap_or(&joined);
    format!("{text} (see --help)")
}
