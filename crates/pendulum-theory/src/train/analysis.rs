//! A going train as one analysis: its beat and the simple pendulum it
//! needs (and how far a design's nut must move for it), or the trains
//! that give a beat. The command line's `train` and Python's `train` and
//! `train_for` are these calls; the ranges and defaults live here.

use super::{beats_per_hour, trains_for};
use crate::analysis::{require_finite, Refusal};
use crate::compound::{CompoundPendulum, RegulationError};
use crate::error::format_significant;
use crate::pendulum::{Amplitude, STANDARD_GRAVITY};
use crate::period::length_for_period;
use serde::Serialize;

/// Beat rates taken, beats per hour: a turret clock's minute jump (60 an
/// hour) down to one an hour, up to 100 beats a second.
pub const BPH_RANGE: std::ops::RangeInclusive<f64> = 1.0..=360_000.0;
/// Turns an hour of the first wheel's arbor when not given (the centre
/// arbor).
pub const DEFAULT_ARBOR_TURNS_PER_HOUR: f64 = 1.0;
/// The largest arbor speed taken, turns an hour (a turn a second).
pub const MAX_ARBOR_TURNS_PER_HOUR: f64 = 3600.0;
/// Relative tolerance on a beat rate sought when not given.
pub const DEFAULT_TOLERANCE: f64 = 0.001;
/// The largest tolerance taken.
pub const MAX_TOLERANCE: f64 = 0.1;
/// Teeth of the escape wheel when not given (a seconds pendulum's).
pub const DEFAULT_ESCAPE_TEETH: u32 = 30;
/// Trains listed at most.
pub const MAX_TRAINS: usize = 20;

/// A train's beat and pendulum.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Train {
    /// Wheel counts (the last the escape wheel).
    pub wheels: Vec<u32>,
    /// Pinion counts.
    pub pinions: Vec<u32>,
    /// Turns an hour of the first arbor.
    pub arbor_turns_per_hour: f64,
    /// Beats per hour.
    pub beats_per_hour: f64,
    /// Period (two beats), s.
    pub period_s: f64,
    /// The simple pendulum of that period (small swings), m.
    pub length_m: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// With a design: how far its nut (or bob) must move down, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub design_shift_m: Option<f64>,
}

/// One train that gives a beat sought.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Candidate {
    /// Centre, third and escape wheel.
    pub wheels: [u32; 3],
    /// The two pinions.
    pub pinions: [u32; 2],
    /// Its beats per hour.
    pub beats_per_hour: f64,
}

/// The beat of `wheels` and `pinions` with the first arbor turning
/// `arbor_turns_per_hour` (default [`DEFAULT_ARBOR_TURNS_PER_HOUR`]), the
/// pendulum it needs under `g`, and with a `design` how far its nut (or
/// else its bob) must move down.
///
/// # Examples
///
/// ```
/// use pendulum_theory::train::analysis::train;
///
/// // A longcase's going train: centre wheel 64, third 60, escape wheel 30, on
/// // pinions of 8: the escape wheel turns once a minute, 60 beats a turn.
/// let t = train(&[64, 60, 30], &[8, 8], None, None, None)?;
/// assert_eq!(t.beats_per_hour, 3600.0); // 64/8 × 60/8 × 30 × 2
/// assert_eq!(t.period_s, 2.0);
/// assert!((t.length_m - 0.99362).abs() < 1e-5);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn train(
    wheels: &[u32],
    pinions: &[u32],
    arbor_turns_per_hour: Option<f64>,
    g: Option<f64>,
    design: Option<&CompoundPendulum>,
) -> Result<Train, Refusal> {
    if wheels.is_empty() {
        return Err(Refusal::field(
            "wheels",
            "give the wheel counts, or a beat rate",
        ));
    }
    let g = require_finite("g", g.unwrap_or(STANDARD_GRAVITY))?;
    let turns = arbor_turns_per_hour.unwrap_or(DEFAULT_ARBOR_TURNS_PER_HOUR);
    if !(turns > 0.0 && turns <= MAX_ARBOR_TURNS_PER_HOUR) {
        return Err(Refusal::field(
            "arbor_turns_per_hour",
            format!(
                "must lie between 0 and {MAX_ARBOR_TURNS_PER_HOUR} (a turn a second), got {}",
                crate::analysis::count(turns)
            ),
        ));
    }
    let bph = beats_per_hour(wheels, pinions, turns).ok_or_else(|| {
        Refusal::field(
            "pinions",
            format!(
                "give one fewer pinion than wheels (the last wheel is the escape wheel), none \
                 zero; got {} wheels and {} pinions",
                wheels.len(),
                pinions.len()
            ),
        )
    })?;
    // No clock beats faster than 100 a second (a typing error otherwise).
    if bph.is_nan() || bph > *BPH_RANGE.end() {
        // Said of the arbor's turns when they were given, else of the wheels.
        let field = if turns == DEFAULT_ARBOR_TURNS_PER_HOUR {
            "wheels"
        } else {
            "arbor_turns_per_hour"
        };
        return Err(Refusal::field(
            field,
            format!(
                "give {} beats/hour: no clock beats faster than 100 a second",
                crate::analysis::count(bph)
            ),
        ));
    }
    let period = 7200.0 / bph;
    let length = length_for_period(period, Amplitude::ZERO, g).map_err(|e| match e.quantity {
        crate::error::Quantity::Gravity => Refusal::input("g", &e),
        _ => Refusal::input("wheels", &e),
    })?;
    let design_shift_m = design.map(|d| shift(d, length, bph)).transpose()?;
    Ok(Train {
        wheels: wheels.to_vec(),
        pinions: pinions.to_vec(),
        arbor_turns_per_hour: turns,
        beats_per_hour: bph,
        period_s: period,
        length_m: length,
        g_m_s2: g,
        design_shift_m,
    })
}

/// How far `design`'s nut (else its bob) must move down for an equivalent
/// length of `length` m.
fn shift(design: &CompoundPendulum, length: f64, bph: f64) -> Result<f64, Refusal> {
    let l = design.properties().equivalent_length;
    let rate = crate::period::SECONDS_PER_DAY * ((length / l).sqrt() - 1.0);
    let parts = design.parts();
    let index = parts
        .iter()
        .position(|p| p.name == "nut")
        .or_else(|| parts.iter().position(|p| p.name == "bob"))
        .ok_or_else(|| Refusal::field("design", "has no part named 'nut' or 'bob' to move"))?;
    design.regulation(index, rate).map_err(|e| match e {
        RegulationError::RestsOnAnother { .. } => Refusal::field(
            "design",
            "its nut or bob is placed on another part; place it by its centre",
        ),
        _ => Refusal::field(
            "design",
            format!(
                "cannot be brought to {} beats an hour by its {}: {e}",
                format_significant(bph, 6),
                parts[index].name
            ),
        ),
    })
}

/// The trains (centre, third and escape wheel, two pinions) that give
/// `bph` within `tolerance` (relative; default [`DEFAULT_TOLERANCE`]) with
/// an escape wheel of `escape_teeth` (default [`DEFAULT_ESCAPE_TEETH`]),
/// closest first, at most [`MAX_TRAINS`].
pub fn train_for(
    bph: f64,
    escape_teeth: Option<u32>,
    tolerance: Option<f64>,
) -> Result<Vec<Candidate>, Refusal> {
    if !BPH_RANGE.contains(&require_finite("bph", bph)?) {
        return Err(Refusal::field(
            "bph",
            format!(
                "must lie between {} and {} beats an hour, got {}",
                BPH_RANGE.start(),
                BPH_RANGE.end(),
                crate::analysis::count(bph)
            ),
        ));
    }
    let tolerance = require_finite("tolerance", tolerance.unwrap_or(DEFAULT_TOLERANCE))?;
    if !(tolerance > 0.0 && tolerance < MAX_TOLERANCE) {
        return Err(Refusal::field(
            "tolerance",
            format!(
                "must be between 0 and {MAX_TOLERANCE}, got {}",
                format_significant(tolerance, 6)
            ),
        ));
    }
    let escape = escape_teeth.unwrap_or(DEFAULT_ESCAPE_TEETH);
    if escape == 0 {
        return Err(Refusal::field("escape_teeth", "must be positive"));
    }
    Ok(trains_for(bph, escape, tolerance, MAX_TRAINS)
        .into_iter()
        .map(|(wheels, pinions, beats_per_hour)| Candidate {
            wheels,
            pinions,
            beats_per_hour,
        })
        .collect())
}
