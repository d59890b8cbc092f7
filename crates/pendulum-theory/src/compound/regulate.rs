//! Regulation as one analysis: from a clock's rate to how far its bob (or
//! rating nut, with what rests on it) must move, in turns and divisions of
//! the nut, or the mass to put on a regulating tray. The command line's
//! `regulate` and Python's `regulate` are this call; the thread ranges,
//! the tray's place and its default live here.

use super::description::Design;
use super::{length_regulation, RegulationError};
use crate::analysis::{require_finite, Refusal};
use crate::error::format_significant;
use crate::warning::Warning;
use serde::Serialize;

/// The part moved when none is named and the design has no thread:
/// this, else the bob, else the heaviest part hung by its centre.
pub const DEFAULT_PART: &str = "nut";
/// Thread pitches taken, m (clock threads: 0.25 mm, M1, to a few mm).
pub const PITCH_RANGE_M: (f64, f64) = (1e-5, 0.05);
/// Threads per inch taken.
pub const TPI_RANGE: (f64, f64) = (0.5, 2540.0);
/// A regulating tray's place when none is given, as a fraction of the
/// equivalent length below the pivot.
pub const DEFAULT_TRAY_FRACTION: f64 = 1.0 / 3.0;
/// The highest a tray may sit, as a fraction of the length (at the pivot
/// a tray does nothing).
pub const MIN_TRAY_FRACTION: f64 = 0.01;

/// The pendulum regulated.
#[derive(Clone, Debug)]
pub enum Regulated {
    /// A simple pendulum of this length, m.
    Length(f64),
    /// A design, with the part moved (default [`DEFAULT_PART`]).
    Design(Design, Option<String>),
}

/// The nut's thread, when given.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Nut {
    /// Pitch, m.
    pub pitch: Option<f64>,
    /// Threads per inch (in place of the pitch).
    pub tpi: Option<f64>,
    /// Divisions engraved round it.
    pub divisions: Option<u32>,
}

/// How to bring a clock to time.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Regulation {
    /// The clock's rate, s/day (positive: gaining).
    pub rate_s_per_day: f64,
    /// The (equivalent) length, m.
    pub equivalent_length_m: f64,
    /// How far to move the bob, m: positive down (lengthening, for a
    /// gaining clock), negative up.
    pub shift_m: f64,
    /// Turns of the nut (positive lowering the bob).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_turns: Option<f64>,
    /// Divisions of the nut.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_divisions: Option<f64>,
    /// With a design: the tray's place below the pivot, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tray_position_m: Option<f64>,
    /// The mass to add on the tray, kg (negative: to take off).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tray_mass_kg: Option<f64>,
    /// What to check before moving the bob.
    pub warnings: Vec<Warning>,
}

/// The regulation of `pendulum` gaining `rate` s/day, with the nut's
/// thread `nut` (a design's own thread when its nut is the part moved and
/// none is given) and a tray at `tray` m below the pivot (designs only;
/// default a third of the length, left out of the advice when it cannot
/// do it unless asked for).
///
/// # Examples
///
/// ```
/// use pendulum_theory::compound::regulate::{regulate, Nut, Regulated};
///
/// // A seconds pendulum gaining 10 s a day, its nut threaded 0.5 mm: T ∝ √l,
/// // so the bob goes down by 2 l × 10/86400 = 0.23 mm, 0.46 of a turn.
/// let nut = Nut { pitch: Some(0.5e-3), ..Default::default() };
/// let r = regulate(&Regulated::Length(0.99362), 10.0, nut, None)?;
/// assert!((r.shift_m - 2.0 * 0.99362 * 10.0 / 86_400.0).abs() < 1e-6);
/// assert!((r.nut_turns.unwrap() - r.shift_m / 0.5e-3).abs() < 1e-9);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn regulate(
    pendulum: &Regulated,
    rate: f64,
    nut: Nut,
    tray: Option<f64>,
) -> Result<Regulation, Refusal> {
    let r = require_finite("rate", rate)?;
    if r.abs() >= 86_400.0 {
        return Err(Refusal::field(
            "rate",
            format!(
                "must be under 86400 s/day either way (a day a day), got {} s/day",
                format_significant(r, 6)
            ),
        ));
    }
    let mut pitch = match (nut.pitch, nut.tpi) {
        (Some(_), Some(_)) => {
            return Err(Refusal::field(
                "nut_tpi",
                "give the pitch or the tpi, not both",
            ))
        }
        (Some(p), None) => {
            if !(PITCH_RANGE_M.0..=PITCH_RANGE_M.1).contains(&p) {
                return Err(Refusal::field(
                    "nut_pitch",
                    // (In mm, where the pitch in mm is a number: 1e308 m
                    // is not.)
                    match p * 1e3 {
                        mm if mm.is_finite() => format!(
                            "must lie between 0.01 mm and 50 mm, got {} mm",
                            format_significant(mm, 6)
                        ),
                        _ => format!(
                            "must lie between 0.01 mm and 50 mm, got {} m",
                            format_significant(p, 6)
                        ),
                    },
                ));
            }
            Some(p)
        }
        (None, Some(tpi)) => {
            if !(TPI_RANGE.0..=TPI_RANGE.1).contains(&tpi) {
                return Err(Refusal::field(
                    "nut_tpi",
                    format!(
                        "must lie between 0.5 and 2540 threads per inch, got {}",
                        format_significant(tpi, 6)
                    ),
                ));
            }
            Some(0.0254 / tpi)
        }
        (None, None) => None,
    };
    if nut.divisions == Some(0) {
        return Err(Refusal::field("nut_divisions", "must be at least 1"));
    }
    let mut divisions = nut.divisions;
    let mut moved_instead: Option<String> = None;
    let (length, shift, tray) = match pendulum {
        Regulated::Design(read, part) => {
            let design = &read.pendulum;
            let p = design.properties();
            let index = match part.as_deref() {
                Some(part) => design
                    .parts()
                    .iter()
                    .position(|q| q.name == part)
                    .ok_or_else(|| {
                        Refusal::field("part", format!("the design has no part named '{part}'"))
                    })?,
                // None named: the threaded part, the nut, the bob, else the
                // heaviest part that rests on no other (a design need not
                // have a nut to be regulated, by a tray or by its bob).
                None => match (read.thread, default_part(design)) {
                    (Some(t), _) => t.part,
                    (None, Some((i, said))) => {
                        moved_instead = said;
                        i
                    }
                    (None, None) => return Err(Refusal::field("part", "the design has no parts")),
                },
            };
            // The design's own thread, when the part moved is its nut and
            // no other is given.
            if let Some(t) = read.thread.filter(|t| t.part == index) {
                if pitch.is_none() {
                    pitch = Some(t.pitch);
                    divisions = divisions.or(t.divisions);
                }
            }
            let shift = design.regulation(index, r).map_err(|e| match e {
                RegulationError::RestsOnAnother { .. } => Refusal::field("part", e.to_string()),
                _ => Refusal::field("rate", e.to_string()),
            })?;
            let l = p.equivalent_length;
            let at = require_finite("tray", tray.unwrap_or(DEFAULT_TRAY_FRACTION * l))?;
            if !(at >= MIN_TRAY_FRACTION * l && at < l) {
                return Err(Refusal::field(
                    "tray",
                    format!(
                        "must lie between 1% of the length below the pivot ({} mm) and the \
                         centre of oscillation ({} mm)",
                        format_significant(1e3 * MIN_TRAY_FRACTION * l, 4),
                        format_significant(1e3 * l, 6)
                    ),
                ));
            }
            let on_tray = match design.tray_mass(at, r) {
                Ok(mass) => Some((at, mass)),
                Err(e) if tray.is_some() => return Err(Refusal::field("tray", e.to_string())),
                Err(_) => None,
            };
            (l, shift, on_tray)
        }
        Regulated::Length(l) => {
            if tray.is_some() {
                return Err(Refusal::field(
                    "tray",
                    "needs a design: what a tray's mass does depends on the pendulum's parts",
                ));
            }
            let pendulum = crate::pendulum::Pendulum::with_standard_gravity(*l)
                .map_err(|e| Refusal::input("length", &e))?;
            let l = pendulum.length_m();
            let shift =
                length_regulation(l, r).map_err(|e| Refusal::field("rate", e.to_string()))?;
            (l, shift, None)
        }
    };
    let turns = pitch.map(|p| shift / p);
    let nut_divisions = turns.zip(divisions).map(|(t, d)| t * f64::from(d));
    Ok(Regulation {
        rate_s_per_day: r,
        equivalent_length_m: length,
        shift_m: shift,
        nut_turns: turns,
        nut_divisions,
        tray_position_m: tray.map(|t| t.0),
        tray_mass_kg: tray.map(|t| t.1),
        warnings: crate::pendulum::length_warning(length)
            .map(|w| Warning::new("length_implausible", w, Some("length_m")))
            .into_iter()
            .chain(moved_instead.map(|w| Warning::new("part_moved_instead", w, Some("shift_m"))))
            .collect(),
    })
}

/// The part moved when none is named: [`DEFAULT_PART`], else the bob,
/// else the heaviest part resting on no other; with the words that say
/// so when it is not the nut.
fn default_part(design: &super::CompoundPendulum) -> Option<(usize, Option<String>)> {
    let parts = design.parts();
    if let Some(i) = parts.iter().position(|q| q.name == DEFAULT_PART) {
        return Some((i, None));
    }
    let i = parts.iter().position(|q| q.name == "bob").or_else(|| {
        (0..parts.len())
            .filter(|&i| matches!(parts[i].placement, super::Placement::Centre(_)))
            .max_by(|&a, &b| parts[a].mass().total_cmp(&parts[b].mass()))
    })?;
    Some((
        i,
        Some(format!(
            "the design has no part named '{DEFAULT_PART}': the advice moves the {} (name another with --part)",
            parts[i].name
        )),
    ))
}
