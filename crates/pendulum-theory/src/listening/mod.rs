//! Listening to a clock: the times of its ticks in a sound recording, and
//! a synthetic recording with known truth to check that against.
//!
//! * [`filter`]: the band-pass (second-order sections after the RBJ audio
//!   cookbook) that keeps the ticks and drops hum and hiss.
//! * [`detect`]: the envelope, the beat period from its autocorrelation,
//!   and each tick's onset to a fraction of a sample (coarse onsets on the
//!   envelope, then cross-correlation with the median tick and tock).
//! * [`synth`]: ticks as a few decaying resonances, the drop sound after
//!   them, room echoes, mains hum, noise and missing ticks, with the true
//!   tick times.
//!
//! The analysis of the tick times (rate, beat error, Allan deviation) is
//! [`crate::fitting::beats`], the same as for a timer's log.

pub mod detect;
pub mod filter;
pub mod synth;
