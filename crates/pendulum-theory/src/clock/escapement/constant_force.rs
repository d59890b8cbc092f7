//! A constant-force escapement (Grimthorpe's double three-legged gravity
//! escapement, 1854, or a remontoire): the train only lifts a weight or
//! winds a spring, which gives the pendulum the same impulse whatever the
//! train delivers. The drive reaches the pendulum only as the friction of
//! unlocking; here, as in the deadbeat, a friction torque on the locking
//! faces outside the lift (the friction coefficient times the drive
//! torque).

use super::spec::Entry;
use super::Escapement;

/// The constant-force escapement in the list of escapements.
pub const ENTRY: Entry = Entry {
    name: "constant-force",
    aliases: &["constant_force"],
    help: "a gravity escapement or remontoire: the same push whatever the train gives",
    build: |p| {
        Ok(Box::new(ConstantForce {
            lift: p.lift,
            impulse: p.torque,
            torque: p.torque,
            friction: p.spec.friction,
        }))
    },
};

/// A constant-force escapement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstantForce {
    /// The lift angle, rad.
    pub lift: f64,
    /// The impulse torque, over `m g l`: independent of the drive.
    pub impulse: f64,
    /// The drive torque at the locking faces, over `m g l`.
    pub torque: f64,
    /// The locking faces' friction coefficient.
    pub friction: f64,
}

impl Escapement for ConstantForce {
    fn name(&self) -> &'static str {
        ENTRY.name
    }
    fn edges(&self) -> Vec<f64> {
        vec![-0.5 * self.lift, 0.5 * self.lift]
    }
    fn torque(&self, zone: usize, _theta: f64, drive: f64) -> f64 {
        if zone == 1 {
            self.impulse
        } else {
            -self.friction * self.torque * drive
        }
    }
    fn work(&self, zone: usize, from: f64, to: f64, drive: f64) -> f64 {
        self.torque(zone, 0.0, drive) * (to - from)
    }
    fn symmetric(&self) -> bool {
        true
    }
    fn unlocking_amplitude(&self) -> f64 {
        0.5 * self.lift
    }
}
