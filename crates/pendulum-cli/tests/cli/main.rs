//! The real `pendulum` binary, run as a user would run it: one test target,
//! one module per command family.

mod damped;
mod period;
mod simulate;
mod util;
