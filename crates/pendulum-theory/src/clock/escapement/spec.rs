//! An escapement as clockmakers describe it (kind, lift angle, drive,
//! friction, ...), turned into one of the escapement types, in the
//! pendulum's units. One place for the command line and the bindings.

use super::{Escapement, OutOfBeat};

/// One escapement of the list [`ESCAPEMENTS`]: its name, what it is,
/// and how it is built from a description. Each lives in its own file
/// beside its type (`deadbeat.rs`: `Deadbeat` and its `ENTRY`).
#[derive(Debug)]
pub struct Entry {
    /// Its name on the command line, in Python and in JSON.
    pub name: &'static str,
    /// Other names it is known by (`constant_force`).
    pub aliases: &'static [&'static str],
    /// One line on what it is, for help texts.
    pub help: &'static str,
    /// The escapement from the description's parts in the pendulum's units.
    pub build: fn(&Parts<'_>) -> Result<Box<dyn Escapement>, SpecError>,
}

/// What an escapement is built from: the description, and its lift,
/// impulse torque and energy per beat in the pendulum's units (over
/// `m g l`), whichever way the drive was given.
#[derive(Clone, Copy, Debug)]
pub struct Parts<'a> {
    /// The description.
    pub spec: &'a Spec,
    /// The lift angle, rad.
    pub lift: f64,
    /// The torque over the lift, over `m g l`.
    pub torque: f64,
    /// The energy per beat, over `m g l`.
    pub energy: f64,
}

impl Parts<'_> {
    /// Refuses a torque drive: the escapement is given an energy per beat.
    pub fn energy_only(&self) -> Result<(), SpecError> {
        match self.spec.drive {
            Drive::Torque(_) => Err(SpecError {
                field: "drive",
                message: "an impulse is an energy per beat (e.g. 20uJ), not a torque".into(),
            }),
            Drive::Energy(_) => Ok(()),
        }
    }
}

/// Every escapement, by name: the command line's choices, Python's names,
/// the refusal's list and the help come from here. A new escapement is a
/// file with its type and its [`Entry`], and its line here.
pub const ESCAPEMENTS: &[Entry] = &[
    super::impulse::ENTRY,
    super::deadbeat::ENTRY,
    super::recoil::ENTRY,
    super::constant_force::ENTRY,
    super::free::ENTRY,
];

/// An escapement of [`ESCAPEMENTS`].
#[derive(Clone, Copy, Debug)]
pub struct Kind(pub &'static Entry);

impl PartialEq for Kind {
    fn eq(&self, other: &Self) -> bool {
        self.0.name == other.0.name
    }
}

impl Eq for Kind {}

impl Kind {
    /// From its name or an alias (`impulse`, `deadbeat`, `recoil`,
    /// `constant-force`, `free`, …: [`ESCAPEMENTS`]).
    pub fn from_name(name: &str) -> Option<Self> {
        ESCAPEMENTS
            .iter()
            .find(|e| e.name == name || e.aliases.contains(&name))
            .map(Kind)
    }

    /// Its name.
    pub fn name(self) -> &'static str {
        self.0.name
    }

    /// The default escapement: a regulator's deadbeat.
    pub fn deadbeat() -> Self {
        Kind(&ESCAPEMENTS[1])
    }
}

/// The names of [`ESCAPEMENTS`], "impulse, deadbeat, …".
pub fn names() -> String {
    ESCAPEMENTS
        .iter()
        .map(|e| e.name)
        .collect::<Vec<_>>()
        .join(", ")
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
        let escapement = (self.kind.0.build)(&Parts {
            spec: self,
            lift,
            torque,
            energy,
        })?;
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
