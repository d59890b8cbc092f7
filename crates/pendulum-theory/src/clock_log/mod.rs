//! The analysis of a clock's log: its rate against the weather, the
//! Earth's tides and the days, with standard errors, and its stability
//! before and after the model.
//!
//! A log (offsets from a reference, rates, or half periods from a
//! photogate) is cleaned of jumps and glitches ([`jumps`]), turned into
//! one rate a bin (an hour by default, or the readings' spacing: a log
//! read once a day has a bin a day; [`series`]), and the rate model
//!
//! `rate = r̄ + drift·(t − t̄) + a_T (T_lag − T̄) + a_P (P − P̄) + a_H (H − H̄)
//!        + a_A (A − Ā) + k·tide + Σ steps + walk`
//!
//! whose terms are [`terms::TERMS`] is fitted by generalised least squares
//! under white plus random-walk frequency noise ([`model`]). `r̄` is the
//! clock's mean rate over the log at its mean weather: the constant with
//! the walk's mean over the log (its standard error carries the walk's).
//! The temperature enters through a first-order lag whose time constant
//! is found by profile likelihood with its 95% range; the terms kept,
//! and the walk, are those the Bayesian information criterion keeps
//! ([`choice`]); steps at given times (a regulation, a rewinding) are
//! always in. The tide is [`crate::tide`]'s pendulum rate, its
//! coefficient the admittance (1 when the clock sees the whole body
//! tide). The residuals are checked against the noise model
//! ([`checks`]).
//!
//! Periodic errors (`periodic`, [`spectrum`]): the spectrum of what the
//! weather, drift and steps leave of the rate, with the tidal lines, the
//! day and the going train's arbors measured and judged against the noise
//! around them; the rate folded over each arbor's turn, phased by the
//! clock's own count ([`wheels`]). From amplitudes a half swing (a
//! photogate's pulses, [`pulse`]), Q from the decay between impulses and
//! the energy's swing-to-swing scatter ([`swing`]); for half periods, the
//! bins then hold whole cycles of the impulses and the escape wheel, so a
//! cycle cut at a bin's edge does not pass for an effect of the
//! amplitude.

pub mod checks;
pub mod choice;
pub mod daily;
pub mod jumps;
pub mod model;
pub mod pulse;
pub mod series;
pub mod spectrum;
pub mod swing;
pub mod terms;
pub mod wheels;

mod analysis;
mod input;
mod periodic;
mod result;

pub use analysis::analyse;
pub use jumps::Wrap;
pub use pulse::amplitude_from_pulse;
pub use result::{
    unit_suffix, Coefficients, DesignComparison, LogColumn, LogInput, LogKind, LogResult,
    LogWarning, Partial, Predicted, ReferenceWeather, Term,
};
pub use spectrum::{Line, Spectrum, SpectrumPoint};
pub use swing::Swing;
pub use terms::{ModelTerm, Source, TERMS};
pub use wheels::{Arbor, Fold, FoldBin, TrainInput};
