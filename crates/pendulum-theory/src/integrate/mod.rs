//! Integrators and events for two-dimensional first-order systems
//! `y' = f(t, y)`, `y = [θ, θ']`, written in-house: the Rust ODE crates we
//! measured lack events or have wrong dense output.
//!
//! Following the layout of SciPy's `integrate/_ivp`, three small pieces that
//! know nothing of each other's internals:
//!
//! * [`dop853`]: one step of the Dormand-Prince 8(5,3) pair, its error
//!   estimate, and the data for its dense output ([`dop853_tableau`] holds
//!   the coefficients);
//! * [`dense`]: the 7th-order continuous extension of a step;
//! * [`events`]: sign changes filtered by direction and roots located on the
//!   dense output;
//! * [`control`]: the step-size controller, in one function.
//!
//! * [`adaptive`]: the one adaptive driver over them, with terminal
//!   events; the simulation's adaptive methods and the clock's half swing
//!   step with it.

pub mod adaptive;
pub mod control;
pub mod dense;
pub mod dop853;
pub mod dop853_tableau;
pub mod events;
pub mod symplectic;
pub mod vern9;
pub mod vern9_tableau;

/// A state `[θ, θ']` (or any pair).
pub type State2 = [f64; 2];
