//! Frequency stability of a clock, as the time-and-frequency field
//! computes it: the Allan, modified Allan, time, Hadamard and total
//! deviations and the MTIE of
//! a series of time errors (phase data `x`, seconds, one every `τ₀`) at
//! averaging times `τ = m τ₀`, their confidence intervals and the noise
//! that dominates at each.
//!
//! Every statistic is the textbook estimator of W. J. Riley, *Handbook of
//! Frequency Stability Analysis*, NIST Special Publication 1065 (2008),
//! section 5.2, written on phase data; frequency data (fractional
//! frequency `y`, or a clock's rate) are first summed into phase
//! ([`phase_from_frequency`], SP 1065 section 5.1). On the NBS14 test
//! data (Riley's 10-point set) every value agrees with the handbook's
//! table to its printed digits, and with allantools 2024.06 to 1e-10 on
//! four seeded noises (tests `stability.rs`).
//!
//! * [`registry`]: the list of deviations the analysis reports
//!   ([`DEVIATIONS`]); one file each for [`mod@totdev`] and [`mod@mtie`].
//! * [`deviations`]: the Allan and Hadamard estimators.
//! * [`edf`]: Greenhall's equivalent degrees of freedom.
//! * [`noise`]: the lag-1 autocorrelation noise identification.
//! * [`outliers`]: jumps and glitches of a time-error series.
//! * [`periodic`]: a periodic signal that dominates some averaging times.
//! * [`stability()`]: the one call: every τ, intervals, noise, a reading.

pub mod deviations;
pub mod edf;
pub mod mtie;
pub mod noise;
pub mod outliers;
pub mod periodic;
pub mod registry;
pub mod totdev;

mod analysis;

pub use analysis::{
    grid, interval, stability, Best, DataKind, Deviations, Gridded, Measured, Outliers, Stability,
    StabilityInput, StabilityRow, StabilityWarning, Taus,
};
pub use deviations::{adev, hdev, mdev, oadev, ohdev, phase_from_frequency, tdev};
pub use mtie::{mtie, MTIE};
pub use noise::Noise;
pub use outliers::{find_accidents, remove_accidents, Accident, AccidentKind};
pub use periodic::{find_periodic, PeriodicSignal};
pub use registry::{Deviation, DeviationUnit, IntervalRule, ADEV, DEVIATIONS, HDEV, MDEV, TDEV};
pub use totdev::{totdev, TOTDEV};
