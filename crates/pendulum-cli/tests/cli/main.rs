//! The real `pendulum` binary, run as a user would run it: one test target,
//! one module per command family.

mod advice;
mod audit;
mod clock;
mod damped;
mod design;
mod disk_full;
mod examples;
mod extremes;
mod figures;
mod fit;
mod fit_period;
mod formats;
mod gyroscope;
mod hardening;
mod inputs;
mod layouts;
mod listen;
mod listen_live;
mod log;
mod period;
mod plot;
mod simulate;
mod util;
