//! The free pendulum (Shortt's, 1921): left alone for `every` beats, then
//! given one [`Impulse`], here usually at the bottom of the swing where
//! (Airy) it does not disturb the period. The slave clock's work
//! (unlocking, counting) is not on the pendulum.

use super::spec::Entry;
use super::{Escapement, Impulse};

/// Shortt's free pendulum in the list of escapements.
pub const ENTRY: Entry = Entry {
    name: "free",
    aliases: &[],
    help: "Shortt's free pendulum: an impulse once every so many beats, left alone between",
    build: |p| {
        p.energy_only()?;
        Ok(Box::new(FreePendulum {
            impulse: Impulse {
                angle: p.spec.angle,
                energy: p.energy,
            },
            every: p.spec.every,
        }))
    },
};

/// An [`Impulse`] once every `every` beats.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreePendulum {
    /// The impulse given.
    pub impulse: Impulse,
    /// Beats between impulses (Shortt's: 30 beats of a seconds pendulum).
    pub every: u64,
}

impl Escapement for FreePendulum {
    fn name(&self) -> &'static str {
        ENTRY.name
    }
    fn edges(&self) -> Vec<f64> {
        self.impulse.edges()
    }
    fn torque(&self, _zone: usize, _theta: f64, _drive: f64) -> f64 {
        0.0
    }
    fn work(&self, _zone: usize, _from: f64, _to: f64, _drive: f64) -> f64 {
        0.0
    }
    fn kick(&self, edge: usize, beat: u64, drive: f64) -> f64 {
        if beat % self.every.max(1) == 0 {
            self.impulse.kick(edge, beat, drive)
        } else {
            0.0
        }
    }
    fn cycle(&self) -> u64 {
        self.every.max(1)
    }
    fn symmetric(&self) -> bool {
        self.impulse.symmetric()
    }
    fn unlocking_amplitude(&self) -> f64 {
        self.impulse.unlocking_amplitude()
    }
}
