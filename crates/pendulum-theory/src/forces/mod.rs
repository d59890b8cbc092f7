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
//! ([`Viscous`] and a drag law) its exact damping flows.
//!
//! The drag laws (velocity-dependent losses beyond the viscous one) are a
//! list, [`DRAG_LAWS`]: each in its own file, each a [`DragLaw`] saying
//! what the integrators need of it (its acceleration, its exact flow
//! together with the viscous decay, its rate for the step and the work
//! estimate, the range of its coefficient). A law is an input by its name
//! on every front end (`--drag NAME=VALUE`, `drag={NAME: VALUE}`) and a
//! key of the result. The decay fit reads the same list: each law's power
//! and cycle average give its averaged amplitude equation, so that a law
//! is fitted to a run-down (alone, or with viscous damping and dry
//! friction: [`crate::fitting::decay::DecayModel::Drag`]) as well as
//! simulated. Adding one is a file and a line in [`DRAG_LAWS`].

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

mod quadratic;
mod three_halves;

/// A velocity-dependent loss `a(v)` (odd in `v`, opposing the motion) in
/// scaled time `τ = ω_n t`, with what the integrators need of it.
pub trait DragLaw: Sync {
    /// Its name: the input (`quadratic_drag`) and the result's key.
    fn name(&self) -> &'static str;
    /// What its coefficient is, with its unit, for help texts.
    fn describe(&self) -> &'static str;
    /// The coefficient in scaled time of `k` given in the law's own units,
    /// for a pendulum of natural angular frequency `omega` (rad/s).
    fn scaled(&self, k: f64, omega: f64) -> f64;
    /// Its angular acceleration over `ω_n²` at the scaled angular
    /// velocity `v`, for the scaled coefficient `k`.
    fn acceleration(&self, k: f64, v: f64) -> f64;
    /// The constant of its exact flow together with viscous decay at rate
    /// `c` over a scaled time `tau`, computed once per step size: see
    /// [`DragLaw::flow`].
    fn flow_constant(&self, c: f64, tau: f64) -> f64;
    /// The exact solution at `tau` of `v' = -c v + a(v)` from `v`, given the
    /// viscous part alone `decayed = v e^{-c tau}` and
    /// [`DragLaw::flow_constant`]`(c, tau)`.
    fn flow(&self, k: f64, v: f64, decayed: f64, constant: f64) -> f64;
    /// The law's linearised rate `|da/dv|` at the fastest speed a swing
    /// whose free speed at the bottom is `free_speed` reaches under it
    /// (the stiffness the step size and the work estimate follow).
    fn rate(&self, k: f64, free_speed: f64) -> f64;

    /// Its power `p`: the loss is `k v|v|^{p−1}`. A run-down's amplitude
    /// then falls as `dA/dt = −κ A^p` (the energy balance over a cycle of
    /// `θ = A cos ωt`), `κ = k ω^{p−1} ⟨|sin|^{p+1}⟩`, which is how the
    /// decay fit reads the law (see [`DragLaw::sine_mean`]).
    fn power(&self) -> f64;
    /// `⟨|sin|^{p+1}⟩` over a cycle, `Γ(p/2 + 1)/(√π Γ(p/2 + 3/2))`
    /// (DLMF 5.12.2 with the half-period integral of `sin^{p+1}`).
    fn sine_mean(&self) -> f64;
    /// Its name among the decay fit's laws (`quadratic`), and in the
    /// laws it makes with the viscous and dry ones (`viscous+quadratic`).
    fn decay_name(&self) -> &'static str;
    /// The name, with its unit, of `κ`, the law's amplitude-decay rate in
    /// `dA/dt = −κ A^p`: a parameter of the decay fit's law.
    fn decay_rate_name(&self) -> &'static str;
    /// Whether the fits try the law when none is named: a law that the
    /// others together mimic over a record (a power between 1 and 2 is
    /// what viscous damping and quadratic drag together approximate)
    /// would split the choice between look-alikes; it is fitted when named.
    fn searched(&self) -> bool;
}

/// The drag laws, by name. A new law is a file beside this one, its `mod`
/// line above and an entry here.
pub const DRAG_LAWS: &[&dyn DragLaw] = &[&quadratic::QuadraticDrag, &three_halves::ThreeHalvesDrag];

impl std::fmt::Debug for dyn DragLaw {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The law named `name`.
pub fn drag_law(name: &str) -> Option<usize> {
    DRAG_LAWS.iter().position(|l| l.name() == name)
}

/// The coefficients of every drag law, in the laws' own units, in the
/// order of [`DRAG_LAWS`] (0 for a law not in the model).
pub type DragCoefficients = [f64; DRAG_LAWS.len()];

/// Checks a drag coefficient: finite and not negative.
pub fn check_drag(k: f64) -> Result<f64, String> {
    if !k.is_finite() {
        Err(format!(
            "must be a finite number, got {}",
            if k.is_nan() {
                "a value that is not a number"
            } else {
                "an infinite value"
            }
        ))
    } else if k < 0.0 {
        Err(format!(
            "must not be negative, got {}",
            crate::error::format_significant(k, 6)
        ))
    } else {
        Ok(k)
    }
}
