//! What swings in a clock, a pendulum or a balance: it sets how the time
//! across the lift becomes an amplitude ([`crate::lift`]) and how a clock
//! is regulated and set in beat ([`crate::advice`]).

use crate::analysis::Refusal;
use serde::Serialize;

/// What swings in the clock: it sets how the time across the lift becomes
/// an amplitude.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Oscillator {
    /// A pendulum: its exact motion ([`crate::lift`]), whose crossing of
    /// the lift slows as the swing grows.
    Pendulum,
    /// A balance wheel and hairspring: harmonic at any swing, so the
    /// first-order formula `lift / (2 sin(π Δt / T))` is exact.
    Balance,
}

/// Above this beat rate (beats an hour) a clock's oscillator is taken for
/// a balance wheel unless said: 10,800 (1.5 Hz; a pendulum of that beat is
/// 11 cm long, the shortest clocks have).
pub const BALANCE_ABOVE_BPH: f64 = 10_800.0;

impl Oscillator {
    /// The oscillator of a clock beating `beat` s apart: a balance above
    /// [`BALANCE_ABOVE_BPH`].
    pub fn of_beat(beat: f64) -> Self {
        if 3600.0 / beat > BALANCE_ABOVE_BPH {
            Oscillator::Balance
        } else {
            Oscillator::Pendulum
        }
    }

    /// The oscillator named `name` (`pendulum`, `balance`), else a refusal
    /// of the field `oscillator`.
    pub fn parse(name: &str) -> Result<Self, Refusal> {
        match name {
            "pendulum" => Ok(Oscillator::Pendulum),
            "balance" => Ok(Oscillator::Balance),
            other => Err(Refusal::field(
                "oscillator",
                format!("'{other}' is not one of pendulum, balance"),
            )),
        }
    }

    /// The amplitude of this oscillator from the lift's two readings, rad:
    /// a pendulum's exact one, a balance's first-order (harmonic) one.
    pub fn amplitude(self, lifted: &crate::lift::LiftAmplitude) -> f64 {
        match self {
            Oscillator::Pendulum => lifted.amplitude,
            Oscillator::Balance => lifted.first_order,
        }
    }

    /// The largest swing either side this oscillator has in a running
    /// clock, rad: a pendulum clock's 15° (a verge's bob swings 10-15°, a
    /// long-case's 2-5°), a balance's 330° (past it the impulse pin
    /// knocks the banking). An amplitude from the sound beyond it is
    /// wrong (the drop timed as the unlocking, a lift angle not the
    /// escapement's) and is not given.
    pub fn largest_swing_rad(self) -> f64 {
        match self {
            Oscillator::Pendulum => 15f64.to_radians(),
            Oscillator::Balance => 330f64.to_radians(),
        }
    }

    /// `pendulum` or `balance`.
    pub fn name(self) -> &'static str {
        match self {
            Oscillator::Pendulum => "pendulum",
            Oscillator::Balance => "balance",
        }
    }
}
