//! Airy's thought experiment: an instantaneous impulse at a chosen angle.
//!
//! Each beat the pendulum receives the energy `e` at the moment it passes
//! `angle` before the bottom of its swing (negative: after it), in the
//! direction of motion, and nothing else. Airy (1830, "On the disturbances
//! of pendulums and balances, and on the theory of escapements", Trans.
//! Cambridge Phil. Soc. 3, 105) showed that such an impulse at the bottom
//! leaves the period alone, and one before it shortens the period.

use super::spec::Entry;
use super::Escapement;

/// Airy's instantaneous impulse in the list of escapements.
pub const ENTRY: Entry = Entry {
    name: "impulse",
    aliases: &[],
    help: "Airy's instantaneous impulse: an energy per beat given at one angle",
    build: |p| {
        p.energy_only()?;
        Ok(Box::new(Impulse {
            angle: p.spec.angle,
            energy: p.energy,
        }))
    },
};

/// An impulse of energy `energy` (over `m g l`) at `angle` rad before the
/// bottom, every beat.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impulse {
    /// Where, rad before the bottom (negative: after).
    pub angle: f64,
    /// Energy per beat, over `m g l`.
    pub energy: f64,
}

impl Escapement for Impulse {
    fn name(&self) -> &'static str {
        ENTRY.name
    }
    fn edges(&self) -> Vec<f64> {
        // Travelling towards +θ, "before the bottom" is at negative θ.
        vec![-self.angle]
    }
    fn torque(&self, _zone: usize, _theta: f64, _drive: f64) -> f64 {
        0.0
    }
    fn work(&self, _zone: usize, _from: f64, _to: f64, _drive: f64) -> f64 {
        0.0
    }
    fn kick(&self, _edge: usize, _beat: u64, drive: f64) -> f64 {
        self.energy * drive
    }
    fn symmetric(&self) -> bool {
        self.angle == 0.0
    }
    fn unlocking_amplitude(&self) -> f64 {
        self.angle.abs()
    }
}
