//! The terms of the equation of motion, each on its own: gravity, each
//! damping law, and (in [`crate::clock`]) each escapement. A model's
//! right-hand side is the sum of its terms.
//!
//! Every term gives the angular acceleration it contributes in scaled time
//! `τ = ω_n t` (over `ω_n²`), at the scaled state `y = [θ, dθ/dτ]`, with
//! `direction` (±1) the sign of the motion through the current half swing
//! (the sign dry friction takes, held fixed between turning points so that
//! the equation stays smooth there).
//!
//! The symplectic driver splits the sum in two: the terms of position
//! ([`Gravity`], [`DryFriction`]) are its kicks, the terms of velocity
//! ([`Viscous`], [`QuadraticDrag`]) its exact damping flows.

use crate::integrate::State2;

/// One term of the equation of motion.
pub trait Term {
    /// Its angular acceleration over `ω_n²` at `y` moving in `direction`.
    fn acceleration(&self, y: State2, direction: f64) -> f64;
}

/// Gravity: `-sin θ`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gravity;

impl Term for Gravity {
    #[inline(always)]
    fn acceleration(&self, y: State2, _direction: f64) -> f64 {
        -y[0].sin()
    }
}

/// Viscous damping: `-c dθ/dτ`, `c = 2ζ` (seed section 1-4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viscous(pub f64);

impl Term for Viscous {
    #[inline(always)]
    fn acceleration(&self, y: State2, _direction: f64) -> f64 {
        -self.0 * y[1]
    }
}

/// Quadratic air drag: `-b (dθ/dτ)|dθ/dτ|`, `b` per radian (the same in
/// scaled and in real time).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadraticDrag(pub f64);

impl Term for QuadraticDrag {
    #[inline(always)]
    fn acceleration(&self, y: State2, _direction: f64) -> f64 {
        -self.0 * y[1] * y[1].abs()
    }
}

/// Dry (Coulomb) friction: `-r · direction`, `r` the friction angle
/// (friction torque over the restoring torque per radian; the book's
/// section 2-4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DryFriction(pub f64);

impl Term for DryFriction {
    #[inline(always)]
    fn acceleration(&self, _y: State2, direction: f64) -> f64 {
        -self.0 * direction
    }
}
