//! The real `pendulum` binary, run as a user would run it: one test target,
//! one module per command family.

mod damped;
mod fit;
mod period;
mod plot;
mod simulate;
mod util;
