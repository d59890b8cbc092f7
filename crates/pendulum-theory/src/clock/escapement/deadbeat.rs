//! Graham's deadbeat escapement (about 1715): while the pendulum crosses
//! the lift the pallet's impulse face takes a constant torque from the
//! escape wheel in the direction of motion; outside the lift the wheel
//! rests on the pallet's dead face, a circular arc about the pivot, which
//! neither pushes nor recoils but rubs: a friction torque opposing the
//! motion, the friction coefficient times the drive (Rawlings, The Science
//! of Clocks and Watches, 3rd ed., ch. 5; Woodward, My Own Right Time,
//! 1995, ch. 5).

use super::spec::Entry;
use super::Escapement;

/// Graham's deadbeat in the list of escapements.
pub const ENTRY: Entry = Entry {
    name: "deadbeat",
    aliases: &[],
    help: "Graham's deadbeat: a push over the lift, friction on the dead faces beyond it",
    build: |p| {
        Ok(Box::new(Deadbeat {
            lift: p.lift,
            torque: p.torque,
            friction: p.spec.friction,
            offset: p.spec.angle,
        }))
    },
};

/// A deadbeat escapement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deadbeat {
    /// The lift angle, rad: the impulse acts over `±lift/2` about its centre.
    pub lift: f64,
    /// The impulse torque at the pallets, over `m g l`.
    pub torque: f64,
    /// The dead faces' friction coefficient (0.1 to 0.2 for steel on
    /// polished steel or jewels, oiled).
    pub friction: f64,
    /// How far the centre of the impulse lies before the bottom, rad (0: in
    /// the middle of the swing).
    pub offset: f64,
}

impl Escapement for Deadbeat {
    fn name(&self) -> &'static str {
        ENTRY.name
    }
    fn edges(&self) -> Vec<f64> {
        vec![
            -0.5 * self.lift - self.offset,
            0.5 * self.lift - self.offset,
        ]
    }
    fn torque(&self, zone: usize, _theta: f64, drive: f64) -> f64 {
        if zone == 1 {
            self.torque * drive
        } else {
            -self.friction * self.torque * drive
        }
    }
    fn work(&self, zone: usize, from: f64, to: f64, drive: f64) -> f64 {
        self.torque(zone, 0.0, drive) * (to - from)
    }
    fn symmetric(&self) -> bool {
        self.offset == 0.0
    }
    fn unlocking_amplitude(&self) -> f64 {
        0.5 * self.lift + self.offset.abs()
    }
}
