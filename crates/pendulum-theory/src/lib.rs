//! # pendulum-theory
//!
//! The theory of the clock pendulum, computed exactly where theory allows.
//!
//! * [`elliptic`]: complete elliptic integrals `K`, `E` and the Jacobi
//!   functions sn, cn, dn, each to a few ulp (DLMF chapters 19 and 22).
//! * [`period`]: the exact period at any amplitude, `T = 4 sqrt(l/g) K(sin²(A0/2))`
//!   (seed section 1-6), the circular error a clockmaker quotes in s/day,
//!   the seed's power series, and the inverses (length for a period,
//!   amplitude from a measured period).
//! * [`damping`]: viscous damping (seed section 1-4) in every form people
//!   use: `c`, `ζ`, `Q`, logarithmic decrement, decay time.
//! * [`damped`]: the damped linear pendulum's free vibration in all three
//!   regimes, its turning points and the amplitude it loses per period.
//! * [`damped::friction`]: dry (Coulomb) friction on top of viscous damping (book
//!   section 2-4): linear decay and the stop.
//! * [`energy`]: stored energy, losses, power, and the impulse per beat an
//!   escapement must give.
//! * [`forces`]: the terms of the equation of motion (gravity, viscous
//!   damping, dry friction) and the list of drag laws, each a file saying
//!   what the integrators need of it; the simulation and the clock both
//!   sum them.
//! * [`gravity`]: WGS 84 normal gravity with the free-air correction.
//! * [`listening`]: the ticks of a sound recording, and a synthetic one.
//! * [`advice`]: a measured rate and beat error turned into the moves of
//!   the bob, the nut and the crutch, with their directions.
//! * [`stability`]: a clock's frequency stability as NIST SP 1065 computes
//!   it: Allan, modified Allan, time and Hadamard deviations.
//! * [`pendulum`]: the types that say what a number is: a [`Pendulum`]
//!   (length and g) and an [`Amplitude`].
//!
//! The crate does no I/O and depends on no command-line or plotting code:
//! the `pendulum` binary (crate `pendulum-cli`) parses, calls and renders.
//! Bad inputs come back as a typed [`InputError`] naming the quantity.
//!
//! ```
//! use pendulum_theory::{period::PeriodAnalysis, Amplitude, Pendulum};
//!
//! // A seconds pendulum swinging 2 degrees either side loses 6.58 s a day
//! // against the same pendulum at vanishing amplitude.
//! let p = Pendulum::with_standard_gravity(0.99362).unwrap();
//! let a = Amplitude::from_degrees(2.0).unwrap();
//! let analysis = PeriodAnalysis::new(p, a, 3).unwrap();
//! assert!((analysis.circular_error_s_per_day() - 6.58).abs() < 0.005);
//! ```
#![deny(missing_docs)]

pub mod advice;
pub mod air;
pub mod analysis;
pub mod averaging;
pub mod clock;
pub mod clock_log;
pub mod compound;
pub mod damped;
pub mod damping;
pub mod elliptic;
pub mod energy;
pub mod error;
pub mod exact;
pub mod findings;
pub mod fitting;
pub mod forces;
pub mod gas;
pub mod gravity;
pub mod integrate;
pub mod lift;
pub mod listening;
pub mod moisture;
pub mod oscillating_flow;
pub mod oscillator;
pub mod pendulum;
pub mod period;
pub mod report;
pub mod simulation;
pub mod stability;
pub mod suspension;
#[cfg(test)]
mod test_noise;
pub mod tide;
pub mod train;
pub mod warning;

pub use error::{InputError, Problem, Quantity};
pub use pendulum::{Amplitude, Pendulum, STANDARD_GRAVITY};
