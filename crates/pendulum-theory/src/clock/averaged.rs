//! The long-run method for a clock: the half-swing map of
//! [`crate::averaging`] with the escapement's exact work between the ends
//! (its closed forms, and its impulses) and its first-order time shift
//! ([`super::airy::time_shift`]).
//!
//! Measured against the symplectic method at tolerance 1e-13 over 200
//! periods of a seconds pendulum from 3° (the last turning point): Q = 100,
//! time 8.5e-7 s, amplitude 4e-4 relative (the swing has decayed 500-fold;
//! the third-order term is 1e-6 a half swing); Q = 1,000, 4.7e-8 s and
//! 4.4e-7; Q = 10,000, 1.5e-10 s and 4.3e-10. Over a week at Q = 10⁶ it
//! agrees with the symplectic method at 1e-13 to 2.9e-8 s and 3e-12
//! (`bench/RESULTS.md`). The method is for clocks (Q of thousands and
//! more), not for heavily damped swings.

use super::airy::time_shift;
use super::escapement::Escapement;
pub use crate::averaging::half_swing_action;
use crate::averaging::{HalfSwing, Work};

/// The half swing from rest at `-a1` to the next turning point, on beat
/// `beat` with drive factor `drive`, by the map of [`crate::averaging`];
/// `None` when it goes over the top or stops short of the escapement's
/// unlocking.
pub fn half_swing_map(
    escapement: Option<&dyn Escapement>,
    q: f64,
    drive: f64,
    beat: u64,
    a1: f64,
    with_time_shift: bool,
) -> Option<HalfSwing> {
    let Some(e) = escapement else {
        return crate::averaging::half_swing_map(q, a1, None);
    };
    let energy = |a2: f64| e.energy(a1, a2, beat, drive);
    let shift = |a: f64| time_shift(e, a, beat, drive);
    let work = Work {
        energy: &energy,
        time_shift: with_time_shift.then_some(&shift as &dyn Fn(f64) -> f64),
    };
    crate::averaging::half_swing_map(q, a1, Some(&work))
}
