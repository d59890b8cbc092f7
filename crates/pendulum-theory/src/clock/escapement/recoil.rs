//! The anchor (recoil) escapement (Clement or Hooke, about 1670).
//!
//! The pallets have one face each, no dead part: the escape wheel presses
//! on a face all the time, with the train's torque. While the pendulum
//! crosses the lift the wheel drives it (the impulse). At the end of the
//! lift the tooth escapes and the next drops on the other pallet, whose
//! face meets it going the wrong way: the pendulum, swinging on, drives
//! the wheel backwards (the recoil, against the motion) to the end of its
//! swing, and the wheel then drives it back to the lift (with the
//! motion). Outside the lift the torque on the pendulum is therefore a
//! constant push towards the middle, of `recoil` times the impulse
//! torque, which stiffens the pendulum (a gain that grows with the drive).
//!
//! Friction on the faces (coefficient `μ`) makes the two directions
//! unequal. For a face at 45° to the paths of the tooth and the pallet,
//! the force a driven face receives is the driving face's times `(1 -
//! μ)/(1 + μ)` (the normal force's share along each path, less or plus
//! the friction's): the impulse the pendulum receives is already net of
//! it, the wheel's return through the recoil arc gives `recoil` times the
//! impulse torque, and the pendulum driving the wheel back must push
//! `((1 + μ)/(1 - μ))²` times as hard. Every recoil arc costs energy in
//! proportion to the drive and the arc beyond the lift, so the arc
//! hardly grows with the drive while the recoil's gain does: the anchor
//! clock gains as the drive rises and loses as it falls ("the clock loses
//! as the arc of the pendulum falls off, and vice versa", Encyclopaedia
//! Britannica, 11th ed., 1911, "Clock"; a recoil clock "go[es] gradually
//! slower" as its spring runs down, a deadbeat gains, Hasluck, Cassell's
//! Cyclopaedia of Mechanics, "Clock escapements and motive power";
//! Rawlings, The Science of Clocks and Watches, 3rd ed., ch. 5).

use super::spec::{Entry, SpecError};
use super::Escapement;

/// The anchor in the list of escapements.
pub const ENTRY: Entry = Entry {
    name: "recoil",
    aliases: &[],
    help: "the anchor (recoil): a push over the lift, the wheel driven back beyond it",
    build: |p| {
        if p.spec.friction >= 1.0 {
            return Err(SpecError {
                field: "friction",
                message: format!(
                    "the recoil faces' friction must be below 1 (a face that friction locks \
                     cannot recoil), got {}",
                    crate::error::format_significant(p.spec.friction, 6)
                ),
            });
        }
        Ok(Box::new(Recoil {
            lift: p.lift,
            torque: p.torque,
            recoil: p.spec.recoil,
            friction: p.spec.friction,
        }))
    },
};

/// An anchor (recoil) escapement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Recoil {
    /// The lift angle, rad.
    pub lift: f64,
    /// The impulse torque at the pallets (net of the faces' friction),
    /// over `m g l`.
    pub torque: f64,
    /// The torque the wheel gives back through the recoil arc, over the
    /// impulse torque (1: one straight face, the recoil continuing the
    /// impulse face's slope).
    pub recoil: f64,
    /// The pallet faces' friction coefficient, below 1.
    pub friction: f64,
}

impl Recoil {
    /// The torque pushing the wheel back, over the torque it gives back:
    /// `((1 + μ)/(1 - μ))²`.
    pub fn friction_factor(&self) -> f64 {
        ((1.0 + self.friction) / (1.0 - self.friction)).powi(2)
    }
}

impl Escapement for Recoil {
    fn name(&self) -> &'static str {
        ENTRY.name
    }
    fn edges(&self) -> Vec<f64> {
        vec![-0.5 * self.lift, 0.5 * self.lift]
    }
    fn torque(&self, zone: usize, _theta: f64, drive: f64) -> f64 {
        let t = self.torque * drive;
        match zone {
            // Coming back from -A: the wheel returns the recoil (+).
            0 => self.recoil * t,
            1 => t,
            // Going out past the lift: pushing the wheel back (-).
            _ => -self.recoil * self.friction_factor() * t,
        }
    }
    fn work(&self, zone: usize, from: f64, to: f64, drive: f64) -> f64 {
        self.torque(zone, 0.0, drive) * (to - from)
    }
    fn unlocking_amplitude(&self) -> f64 {
        0.5 * self.lift
    }
}
