//! An escapement as clockmakers describe it (kind, lift angle, drive,
//! friction, ...), turned into one of the escapement types, in the
//! pendulum's units. One place for the command line and the bindings.

use super::{ConstantForce, Deadbeat, Escapement, FreePendulum, Impulse, OutOfBeat, Recoil};

/// The escapements by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Airy's instantaneous impulse.
    Impulse,
    /// Graham's deadbeat.
    Deadbeat,
    /// The anchor (recoil).
    Recoil,
    /// Gravity escapement or remontoire.
    ConstantForce,
    /// Shortt's free pendulum.
    Free,
}

impl Kind {
    /// From its name (`impulse`, `deadbeat`, `recoil`, `constant-force`,
    /// `free`).
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "impulse" => Kind::Impulse,
            "deadbeat" => Kind::Deadbeat,
            "recoil" => Kind::Recoil,
            "constant-force" | "constant_force" => Kind::ConstantForce,
            "free" => Kind::Free,
            _ => return None,
        })
    }
}

/// What the train delivers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Drive {
    /// The torque at the pallets, N·m.
    Torque(f64),
    /// The energy per beat, J (a torque over the lift).
    Energy(f64),
}

/// An escapement's description.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spec {
    /// Which escapement.
    pub kind: Kind,
    /// The lift angle, rad.
    pub lift: f64,
    /// The drive.
    pub drive: Drive,
    /// The pallets' friction coefficient: on the dead (locking) faces of a
    /// deadbeat or constant-force escapement, on the recoil faces of an
    /// anchor.
    pub friction: f64,
    /// The torque the anchor's wheel gives back through the recoil arc,
    /// over the impulse torque.
    pub recoil: f64,
    /// Where the impulse falls before the bottom, rad (the impulse's angle;
    /// the deadbeat's lift centre).
    pub angle: f64,
    /// Free pendulum: beats between impulses.
    pub every: u64,
    /// How far the escapement sits off the pendulum's rest, rad (0: in
    /// beat; see [`OutOfBeat`]).
    pub out_of_beat: f64,
}

/// Why a description makes no escapement; `field` names the input.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct SpecError {
    /// The input at fault: `lift_angle`, `drive`, `friction`, `recoil`,
    /// `impulse_angle`, `every_beats`, `beat_error`.
    pub field: &'static str,
    /// What is wrong.
    pub message: String,
}

/// The most beats a free pendulum may go between impulses: its steady
/// state follows every beat of a cycle, so the work grows with the count;
/// Shortt's clock impulses every 30 beats, and a pendulum of Q = 10⁶
/// would lose most of its swing in far fewer than this.
pub const MAX_EVERY_BEATS: u64 = 100_000;

/// The largest swing a clock's escapement may need, rad (170°).
const TOP: f64 = 170.0 * std::f64::consts::PI / 180.0;

impl Spec {
    /// The escapement, its torques and energies over `torque_scale` (`m g
    /// l`, N·m): a torque drive is the impulse torque, an energy drive that
    /// over the lift (impulse and free pendulum take an energy only).
    pub fn build(&self, torque_scale: f64) -> Result<Box<dyn Escapement>, SpecError> {
        let fail = |field, message: String| Err(SpecError { field, message });
        let value = match self.drive {
            Drive::Torque(v) | Drive::Energy(v) => v,
        };
        if value.is_nan() || value <= 0.0 || value.is_infinite() {
            return fail("drive", format!("must be positive, got {value}"));
        }
        if !(self.lift > 0.0 && self.lift.is_finite()) {
            return fail(
                "lift_angle",
                format!("must be positive, got {} rad", self.lift),
            );
        }
        let shown = |v: f64| crate::error::format_significant(v, 6);
        for (field, v) in [("friction", self.friction), ("recoil", self.recoil)] {
            if !v.is_finite() || v < 0.0 {
                return fail(
                    field,
                    format!("must be a finite number, not negative, got {}", shown(v)),
                );
            }
        }
        if self.angle.is_nan() || self.angle.abs() >= TOP {
            return fail("impulse_angle", "must lie within 170° of the bottom".into());
        }
        if self.every == 0 || self.every > MAX_EVERY_BEATS {
            return fail(
                "every_beats",
                format!(
                    "must lie between 1 and {MAX_EVERY_BEATS} (Shortt's free pendulum is \
                     impulsed every 30 s, 30 beats), got {}",
                    self.every
                ),
            );
        }
        let lift = self.lift;
        let (torque, energy) = match self.drive {
            Drive::Torque(t) => (t / torque_scale, t * lift / torque_scale),
            Drive::Energy(e) => (e / (lift * torque_scale), e / torque_scale),
        };
        let escapement: Box<dyn Escapement> = match self.kind {
            Kind::Impulse | Kind::Free => {
                if matches!(self.drive, Drive::Torque(_)) {
                    return fail(
                        "drive",
                        "an impulse is an energy per beat (e.g. 20uJ), not a torque".into(),
                    );
                }
                let impulse = Impulse {
                    angle: self.angle,
                    energy,
                };
                if self.kind == Kind::Impulse {
                    Box::new(impulse)
                } else {
                    Box::new(FreePendulum {
                        impulse,
                        every: self.every,
                    })
                }
            }
            Kind::Deadbeat => Box::new(Deadbeat {
                lift,
                torque,
                friction: self.friction,
                offset: self.angle,
            }),
            Kind::Recoil => {
                if self.friction >= 1.0 {
                    return fail(
                        "friction",
                        format!(
                            "the recoil faces' friction must be below 1 (a face that friction \
                             locks cannot recoil), got {}",
                            shown(self.friction)
                        ),
                    );
                }
                Box::new(Recoil {
                    lift,
                    torque,
                    recoil: self.recoil,
                    friction: self.friction,
                })
            }
            Kind::ConstantForce => Box::new(ConstantForce {
                lift,
                impulse: torque,
                torque,
                friction: self.friction,
            }),
        };
        if !self.out_of_beat.is_finite() {
            return fail(
                "beat_error",
                format!("must be finite, got {}", self.out_of_beat),
            );
        }
        let in_beat_unlocking = escapement.unlocking_amplitude();
        let escapement: Box<dyn Escapement> = if self.out_of_beat == 0.0 {
            escapement
        } else {
            Box::new(OutOfBeat {
                inner: escapement,
                offset: self.out_of_beat,
            })
        };
        let unlocking = escapement.unlocking_amplitude();
        if unlocking >= TOP && in_beat_unlocking < TOP {
            return fail(
                "beat_error",
                format!(
                    "an escapement {}° out of beat unlocks only at {}° on one side, beyond the \
                     170° a pendulum can swing",
                    crate::error::format_significant(self.out_of_beat.to_degrees(), 5),
                    crate::error::format_significant(unlocking.to_degrees(), 5)
                ),
            );
        }
        if unlocking >= TOP {
            return fail(
                "lift_angle",
                format!(
                    "the escapement unlocks only at {}° either side, beyond the 170° a pendulum can swing",
                    crate::error::format_significant(unlocking.to_degrees(), 5)
                ),
            );
        }
        Ok(escapement)
    }
}
