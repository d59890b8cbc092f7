//! The analysis of a clock's log: its rate against the weather, the
//! Earth's tides and the days, with standard errors, and its stability
//! before and after the model.
//!
//! A log (offsets from a reference, rates, or half periods from a
//! photogate) is turned into one rate a bin (an hour by default:
//! [`series`]), and the rate model
//!
//! `rate = r₀ + drift·(t − t̄) + a_T (T_lag − T̄) + a_P (P − P̄) + a_H (H − H̄)
//!        + a_A (A − Ā) + k·tide + Σ steps`
//!
//! is fitted by generalised least squares under white plus random-walk
//! frequency noise ([`model`]). The temperature enters through a
//! first-order lag whose time constant is fitted (a compensator follows
//! the air late); the terms kept are those the Bayesian information
//! criterion keeps (backward elimination from all the data allow); steps
//! at given times (a regulation, a rewinding) are always in. The tide is
//! [`crate::tide`]'s pendulum rate, its coefficient the admittance (1 when
//! the clock sees the whole body tide).
//!
//! Periodic errors ([`spectrum`]): the rate's generalised Lomb–Scargle
//! periodogram with the tidal lines, the day and the going train's
//! arbors measured and judged against the noise around them; the rate
//! folded over each arbor's turn, phased by the clock's own count
//! ([`wheels`]). From amplitudes a half swing (a photogate's pulses,
//! [`pulse`]), Q from the decay between impulses and the energy's
//! swing-to-swing scatter ([`swing`]); for half periods, the bins then
//! hold whole cycles of the impulses and the escape wheel, so a cycle cut
//! at a bin's edge does not pass for an effect of the amplitude.

pub mod model;
pub mod pulse;
pub mod series;
pub mod spectrum;
pub mod swing;
pub mod wheels;

mod analysis;

pub use analysis::{
    analyse, Coefficients, DesignComparison, LogInput, LogKind, LogResult, LogWarning, Partial,
    Term,
};
pub use pulse::amplitude_from_pulse;
pub use series::Wrap;
pub use spectrum::{Line, Spectrum, SpectrumPoint};
pub use swing::Swing;
pub use wheels::{Arbor, Fold, FoldBin, TrainInput};
