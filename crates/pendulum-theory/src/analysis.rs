//! What every analysis entry point shares: the refusal that names the
//! input it is about, and the rule on how much computing a run may take.
//!
//! An analysis (a fit of a run-down, of a track, of beat times; a
//! simulation; a clock) is one call: typed inputs in, validated here in
//! the library, a work estimate judged by [`judge_work`], the computation,
//! its own checks, and one result with named fields and typed warnings.
//! The command line and the Python module only turn their arguments into
//! the inputs and the result into text, JSON or a dict; a refusal reads
//! the same from both: the command line puts its flag (or a file and line)
//! before [`Refusal::reason`], Python its keyword (or `keyword[i]`), as
//! [`Refusal`]'s `Display` does.

use crate::error::{format_significant, InputError};
use std::fmt;

/// Runs estimated to take longer than this need forcing, s of computing.
pub const FORCE_SECONDS: f64 = 5.0;
/// Runs estimated to take longer than this are refused even when forced:
/// they would not end in a day, s of computing.
pub const IMPOSSIBLE_SECONDS: f64 = 86_400.0;

/// Which input a refusal is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// A named input (`"period"`, `"mass"`): a keyword in Python, a flag
    /// (`--period`) on the command line.
    Field(&'static str),
    /// One sample (counted from 0) of an input array (`"amplitude"`): a
    /// line of the file on the command line.
    Sample(&'static str, usize),
    /// The data as a whole (too few points, a fit that fails).
    Data,
}

/// An input an analysis refuses: where, and why.
#[derive(Clone, Debug, PartialEq)]
pub struct Refusal {
    /// The input it is about.
    pub place: Place,
    /// Why, as a sentence that reads after the input's name: `must be
    /// positive, got -2 s`.
    pub reason: String,
}

impl Refusal {
    /// A refusal of the input `field`.
    pub fn field(field: &'static str, reason: impl Into<String>) -> Self {
        Self {
            place: Place::Field(field),
            reason: reason.into(),
        }
    }

    /// A refusal of sample `index` of the array `field`.
    pub fn sample(field: &'static str, index: usize, reason: impl Into<String>) -> Self {
        Self {
            place: Place::Sample(field, index),
            reason: reason.into(),
        }
    }

    /// A refusal of the data as a whole.
    pub fn data(reason: impl Into<String>) -> Self {
        Self {
            place: Place::Data,
            reason: reason.into(),
        }
    }

    /// A refusal of `field` for the library's typed input error (its
    /// message without the quantity's name).
    pub fn input(field: &'static str, e: &InputError) -> Self {
        Self::field(field, e.detail())
    }

    /// The field it is about, if any.
    pub fn field_name(&self) -> Option<&'static str> {
        match self.place {
            Place::Field(f) | Place::Sample(f, _) => Some(f),
            Place::Data => None,
        }
    }
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.place {
            Place::Field(name) => write!(f, "{name}: {}", self.reason),
            Place::Sample(name, i) => write!(f, "{name}[{i}]: {}", self.reason),
            Place::Data => f.write_str(&self.reason),
        }
    }
}

impl std::error::Error for Refusal {}

/// A computing time for people: "40 s", "3 minutes", "2e5 years".
pub fn human_seconds(s: f64) -> String {
    const YEAR: f64 = 3.156e7;
    let n = |v: f64| format_significant(v, 2);
    if !s.is_finite() {
        "an unbounded time".to_string()
    } else if s < 120.0 {
        format!("{} s", n(s))
    } else if s < 7200.0 {
        format!("{} minutes", n(s / 60.0))
    } else if s < 172_800.0 {
        format!("{} hours", n(s / 3600.0))
    } else if s < YEAR {
        format!("{} days", n(s / 86_400.0))
    } else {
        format!("{} years", n(s / YEAR))
    }
}

/// A count for people: "4.2e7", or words for one past counting.
pub fn count(n: f64) -> String {
    if n.is_finite() {
        format_significant(n, 2)
    } else {
        "more than 10^308".to_string()
    }
}

/// Judges a run estimated at `seconds` of computing: more than
/// [`FORCE_SECONDS`] is refused unless `force`, more than
/// [`IMPOSSIBLE_SECONDS`] (or an estimate that is not a number) always.
/// The refusal names `field` (what makes the run long) and says `why`
/// ("a duration of 1e9 s is 5e8 periods").
pub fn judge_work(
    field: &'static str,
    why: impl fmt::Display,
    seconds: f64,
    force: bool,
) -> Result<(), Refusal> {
    if seconds <= FORCE_SECONDS || (force && seconds <= IMPOSSIBLE_SECONDS) {
        return Ok(());
    }
    let hint = if seconds > IMPOSSIBLE_SECONDS || seconds.is_nan() {
        "more than a day of computing; shorten the run"
    } else {
        "force it (--force; force=True in Python) if you mean it"
    };
    Err(Refusal::field(
        field,
        format!(
            "{why}: about {} of computing; {hint}",
            human_seconds(seconds)
        ),
    ))
}

/// Refuses a value of `field` that is NaN or infinite, in the words of
/// [`InputError`] (and of the command line's parser, for `nan` typed).
pub fn require_finite(field: &'static str, value: f64) -> Result<f64, Refusal> {
    if value.is_finite() {
        return Ok(value);
    }
    let got = if value.is_nan() {
        "a value that is not a number"
    } else {
        "an infinite value"
    };
    Err(Refusal::field(
        field,
        format!("must be a finite number, got {got}"),
    ))
}

/// Refuses sample `index` of the array `field` when it is NaN or
/// infinite, in the words of [`require_finite`].
pub fn require_finite_sample(
    field: &'static str,
    index: usize,
    value: f64,
) -> Result<f64, Refusal> {
    require_finite(field, value).map_err(|r| Refusal::sample(field, index, r.reason))
}

/// Refuses the first NaN or infinite sample of the array `field`.
pub fn require_finite_samples(field: &'static str, values: &[f64]) -> Result<(), Refusal> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => require_finite_sample(field, i, values[i]).map(|_| ()),
        None => Ok(()),
    }
}

/// Serialises an optional number as itself when finite and as `null`
/// otherwise (an unbounded Q), so no result ever carries NaN or inf.
pub fn finite(value: f64) -> Option<f64> {
    value.is_finite().then_some(value)
}

/// More samples of a motion than this need forcing (a file of some GB).
pub const MAX_SAMPLES: f64 = 1e8;

/// A duration, s: finite and not negative (the refusal names `duration`).
pub fn duration(seconds: f64) -> Result<f64, Refusal> {
    let d = require_finite("duration", seconds)?;
    if d < 0.0 {
        return Err(Refusal::field(
            "duration",
            format!("must not be negative, got {} s", format_significant(d, 10)),
        ));
    }
    Ok(d)
}

/// The samples of a motion over `duration` s every `interval` s
/// (`default` when none is given): the interval positive and finite, and
/// at most [`MAX_SAMPLES`] of them unless `force`. Returns the interval
/// and the number of samples (`floor(duration / interval) + 1`); refusals
/// name `sample_interval`.
pub fn sampling(
    interval: Option<f64>,
    default: f64,
    duration: f64,
    force: bool,
) -> Result<(f64, u64), Refusal> {
    let h = require_finite("sample_interval", interval.unwrap_or(default))?;
    if h <= 0.0 {
        return Err(Refusal::field(
            "sample_interval",
            format!("must be positive, got {} s", format_significant(h, 10)),
        ));
    }
    let samples = (duration / h).floor() + 1.0;
    if samples > MAX_SAMPLES && !force {
        return Err(Refusal::field(
            "sample_interval",
            format!(
                "{} samples requested; more than 10^8 needs forcing (--force; force=True in \
                 Python), or a longer interval",
                count(samples)
            ),
        ));
    }
    Ok((h, samples as u64))
}

#[cfg(test)]
mod tests {
    #[test]
    fn sampling_counts_the_samples_and_refuses_what_it_cannot_take() {
        // 10 s every 0.1 s: both ends, 101 samples (0.1 is not exact, the
        // floor of 10/0.1 is 100).
        assert_eq!(super::sampling(Some(0.1), 1.0, 10.0, false), Ok((0.1, 101)));
        assert_eq!(super::sampling(None, 0.5, 10.0, false), Ok((0.5, 21)));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let r = super::sampling(Some(bad), 1.0, 10.0, false).unwrap_err();
            assert_eq!(r.field_name(), Some("sample_interval"), "{bad}");
        }
        let many = super::sampling(Some(1e-9), 1.0, 1.0, false).unwrap_err();
        assert!(many.reason.contains("needs forcing"), "{}", many.reason);
        assert!(super::sampling(Some(1e-9), 1.0, 1.0, true).is_ok());
        assert!(super::duration(-1.0).is_err() && super::duration(f64::NAN).is_err());
        assert_eq!(super::duration(0.0), Ok(0.0));
    }

    use super::*;

    #[test]
    fn a_refusal_reads_after_its_input() {
        let r = Refusal::sample("amplitude", 3, "must be positive, got -1");
        assert_eq!(r.to_string(), "amplitude[3]: must be positive, got -1");
        assert_eq!(r.field_name(), Some("amplitude"));
        assert_eq!(Refusal::data("too few").to_string(), "too few");
    }

    #[test]
    fn work_is_judged_in_three_bands() {
        assert!(judge_work("duration", "x", 1.0, false).is_ok());
        assert!(judge_work("duration", "x", 60.0, false).is_err());
        assert!(judge_work("duration", "x", 60.0, true).is_ok());
        assert!(judge_work("duration", "x", 1e6, true).is_err());
        assert!(judge_work("duration", "x", f64::NAN, true).is_err());
    }
}
