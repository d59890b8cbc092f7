//! A clock as one analysis: a pendulum described as a clockmaker would
//! (its length or design, its mass, Q, the escapement by name, the lift,
//! the drive), its steady state, its isochronism curve and a long run,
//! checked, computed and returned as one result. The command line's
//! `clock` and Python's `clock` and `clock_run` are this call; the
//! defaults, the ranges, the `m g l` scale of the escapement's torques and
//! the weather's effect on the rate live here and nowhere else.

use super::escapement::spec::{Drive, Kind, Spec};
use super::long_run::{period_factor, piecewise_linear, run_with_damping, Ending, LongRun, Row};
use super::plan::{check_rate_schedule, check_schedule, plan_run, RunPlan};
use super::{Clock, ClockError, HalfSwingMethod, Steady};
use crate::air::TEMPERATURE_RANGE_C;
use crate::analysis::{require_finite, require_finite_sample, Refusal};
use crate::compound::{CompoundPendulum, PartState};
use crate::error::format_significant;
use crate::pendulum::{Pendulum, STANDARD_GRAVITY};
use crate::warning::Warning;
use serde::Serialize;

/// Quality factor of the free pendulum when none is given (a good
/// regulator in air).
pub const DEFAULT_Q: f64 = 10_000.0;
/// Bob mass when neither a mass nor a design is given, kg.
pub const DEFAULT_MASS_KG: f64 = 5.0;
/// Lift angle when none is given, degrees (a regulator's deadbeat).
pub const DEFAULT_LIFT_DEG: f64 = 2.0;
/// Pallet friction coefficient when none is given (steel on brass,
/// oiled): the dead faces of a deadbeat, the recoil faces of an anchor.
pub const DEFAULT_FRICTION: f64 = 0.15;
/// The anchor's recoil torque over its impulse torque when none is given
/// (1: one straight face, the recoil continuing the impulse's slope).
pub const DEFAULT_RECOIL: f64 = 1.0;
/// Where the impulse falls before the bottom when not given, degrees.
pub const DEFAULT_IMPULSE_ANGLE_DEG: f64 = 0.0;
/// Beats between a free pendulum's impulses when none is given (Shortt's).
pub const DEFAULT_EVERY_BEATS: u64 = 30;
/// Points on an isochronism curve when none is given.
pub const DEFAULT_STEPS: usize = 7;
/// The points an isochronism curve may have.
pub const STEPS_RANGE: std::ops::RangeInclusive<usize> = 2..=1000;
/// The weather a clock is regulated in when a schedule gives no
/// temperature or no pressure at its start: °C, Pa, relative humidity.
pub const REFERENCE_WEATHER: (f64, f64, f64) = (20.0, 101_325.0, 0.5);

/// The pendulum of a clock.
#[derive(Clone, Debug)]
pub enum ClockPendulum {
    /// A simple pendulum of this length, m.
    Length(f64),
    /// A pendulum designed as parts (its equivalent length, effective mass
    /// and temperature and pressure coefficients).
    Design(CompoundPendulum),
}

/// Which drive factors an isochronism curve visits.
#[derive(Clone, Debug, PartialEq)]
pub enum DriveFactors {
    /// These factors.
    List(Vec<f64>),
    /// `steps` factors from `from` to `to` in geometric steps.
    Range {
        /// The smallest factor.
        from: f64,
        /// The largest factor.
        to: f64,
        /// How many (default [`DEFAULT_STEPS`]).
        steps: Option<usize>,
    },
}

/// A quantity that changes with time: `value[i]` at `time[i]` s, linear
/// between, held beyond.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Schedule {
    /// Times, s, increasing.
    pub time: Vec<f64>,
    /// Values.
    pub value: Vec<f64>,
}

/// The weather through a long run, at times `time` s: temperature (°C)
/// and pressure (Pa), either or both; the design's coefficients turn them
/// into a rate change against the weather at the start.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Weather {
    /// Times, s, increasing.
    pub time: Vec<f64>,
    /// Temperature, °C.
    pub temperature_c: Option<Vec<f64>>,
    /// Pressure, Pa.
    pub pressure_pa: Option<Vec<f64>>,
    /// Relative humidity, % (the air's density, and the moisture of parts
    /// that take up water: wood).
    pub humidity_percent: Option<Vec<f64>>,
    /// The vertical temperature gradient, K/m, warmer upwards: each part
    /// is at the temperature of its centre, the temperature column being
    /// read half-way down the pendulum
    /// ([`CompoundPendulum::heights_above_thermometer`]).
    pub gradient_k_per_m: Option<Vec<f64>>,
}

impl Weather {
    /// Whether any column is given.
    pub fn any(&self) -> bool {
        self.temperature_c.is_some()
            || self.pressure_pa.is_some()
            || self.humidity_percent.is_some()
            || self.gradient_k_per_m.is_some()
    }
}

/// The steepest vertical temperature gradient a weather may give, K/m
/// (a clock case's is a fraction of a kelvin per metre; a room's by a
/// radiator a few).
pub const MAX_GRADIENT_K_PER_M: f64 = 100.0;

/// A long run's request.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RunInput {
    /// Simulated time, s.
    pub duration: f64,
    /// A row this often, s (default: every turning point).
    pub every: Option<f64>,
    /// The drive factor through the run (default 1 throughout).
    pub drive_schedule: Option<Schedule>,
    /// The weather (needs a design).
    pub weather: Option<Weather>,
    /// A rate change from outside, s/day, positive gaining.
    pub rate_schedule: Option<Schedule>,
    /// The gas the weather's pressure is of (default air; nitrogen or
    /// helium for a tank whose pressure is the schedule).
    pub gas: Option<crate::gas::Gas>,
    /// Run what is estimated beyond a few seconds of computing anyway.
    pub force: bool,
}

/// How far out of beat a clock is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BeatError {
    /// The escapement's offset from the pendulum's rest, rad (the crutch's
    /// bend), positive towards the side the first half swing travels to.
    Angle(f64),
    /// The beat error its ticks show, s (half the difference of the tick
    /// and tock intervals, as `listen` measures it): the offset that gives
    /// it at the drive given (factor 1) is found, and held at every other
    /// drive.
    Time(f64),
}

/// The drag laws `drag` (coefficients in their own units), checked as
/// the simulation checks them, scaled for a pendulum of natural angular
/// frequency `omega` (rad/s).
fn scaled_drag(
    drag: &[(&'static dyn crate::forces::DragLaw, f64)],
    omega: f64,
) -> Result<Vec<(&'static dyn crate::forces::DragLaw, f64)>, Refusal> {
    use crate::forces::DRAG_LAWS;
    let checked = crate::simulation::analysis::checked_drag_laws(drag, [false; DRAG_LAWS.len()])?;
    Ok(checked
        .into_iter()
        .map(|(i, k)| (DRAG_LAWS[i], DRAG_LAWS[i].scaled(k, omega)))
        .collect())
}

/// Airy's first-order integral is warned of as far from the integrated
/// escapement error when they differ by more than this share of the larger
/// and by more than this many s/day (it is exact to first order in the
/// drive: at a regulator's drive they agree to 1%).
pub const AIRY_FAR: (f64, f64) = (0.05, 0.01);

/// A beat error of this fraction of the beat or more is warned of: an
/// uneven tick a clockmaker hears (the tick and tock intervals 51/49).
pub const AUDIBLY_OUT_OF_BEAT: f64 = 0.01;

/// A clock, described as a clockmaker would. Every `None` is the
/// library's default.
#[derive(Clone, Debug)]
pub struct ClockInput {
    /// The pendulum.
    pub pendulum: ClockPendulum,
    /// Gravity, m/s² (default standard gravity).
    pub g: Option<f64>,
    /// The bob's (effective) mass, kg (default: the design's effective
    /// mass, else [`DEFAULT_MASS_KG`]).
    pub mass: Option<f64>,
    /// Quality factor of the free pendulum (default [`DEFAULT_Q`]).
    pub q: Option<f64>,
    /// Drag laws of [`crate::forces::DRAG_LAWS`] beside the viscous
    /// damping of `q`, each with its coefficient in the law's own units
    /// (`simulate`'s `--drag`); none by default.
    pub drag: Vec<(&'static dyn crate::forces::DragLaw, f64)>,
    /// The escapement (default the deadbeat).
    pub escapement: Option<Kind>,
    /// Lift angle, rad (default [`DEFAULT_LIFT_DEG`]).
    pub lift_angle: Option<f64>,
    /// The drive: a torque at the pallets or an energy per beat.
    pub drive: Option<Drive>,
    /// Pallet friction (default [`DEFAULT_FRICTION`]).
    pub friction: Option<f64>,
    /// Recoil ratio (default [`DEFAULT_RECOIL`]).
    pub recoil: Option<f64>,
    /// Where the impulse falls before the bottom, rad (default
    /// [`DEFAULT_IMPULSE_ANGLE_DEG`]).
    pub impulse_angle: Option<f64>,
    /// Free pendulum: beats between impulses (default
    /// [`DEFAULT_EVERY_BEATS`]).
    pub every_beats: Option<u64>,
    /// How far out of beat (default in beat).
    pub beat_error: Option<BeatError>,
    /// The isochronism curve, if wanted.
    pub isochronism: Option<DriveFactors>,
    /// A long run, if wanted.
    pub run: Option<RunInput>,
}

impl ClockInput {
    /// A clock of `pendulum` with every other choice the library's
    /// default (the drive must still be given).
    pub fn new(pendulum: ClockPendulum) -> Self {
        Self {
            pendulum,
            g: None,
            mass: None,
            q: None,
            drag: Vec::new(),
            escapement: None,
            lift_angle: None,
            drive: None,
            friction: None,
            recoil: None,
            impulse_angle: None,
            every_beats: None,
            beat_error: None,
            isochronism: None,
            run: None,
        }
    }
}

/// A steady state, with the units in its keys.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SteadyState {
    /// The drive factor.
    pub drive_factor: f64,
    /// Amplitude, rad.
    pub amplitude_rad: f64,
    /// Amplitude, degrees.
    pub amplitude_deg: f64,
    /// The clock's period, s.
    pub period_s: f64,
    /// The free pendulum's exact period at that amplitude, s.
    pub free_period_s: f64,
    /// The small-angle period, s.
    pub small_angle_period_s: f64,
    /// Against a small-angle clock, s/day, positive gaining.
    pub rate_s_per_day: f64,
    /// The circular error's part of the rate, s/day (negative: it loses).
    pub circular_rate_s_per_day: f64,
    /// The circular error as `period` gives it: positive, lost.
    pub circular_error_s_per_day: f64,
    /// The escapement's part of the rate, s/day.
    pub escapement_rate_s_per_day: f64,
    /// The escapement's part by Airy's first-order integral, s/day.
    pub escapement_rate_airy_s_per_day: f64,
    /// The beat error, ms: half the difference of the tick and tock
    /// intervals (0 in beat).
    pub beat_error_ms: f64,
    /// Energy given per beat, J.
    pub energy_per_beat_j: f64,
    /// Mean power, W.
    pub power_w: f64,
}

impl From<&Steady> for SteadyState {
    fn from(s: &Steady) -> Self {
        Self {
            drive_factor: s.drive,
            amplitude_rad: s.amplitude,
            amplitude_deg: s.amplitude.to_degrees(),
            period_s: s.period,
            free_period_s: s.free_period,
            small_angle_period_s: s.small_angle_period,
            rate_s_per_day: s.rate,
            circular_rate_s_per_day: s.circular_rate,
            circular_error_s_per_day: -s.circular_rate,
            escapement_rate_s_per_day: s.escapement_rate,
            escapement_rate_airy_s_per_day: s.escapement_rate_first_order,
            beat_error_ms: 1e3 * s.beat_error,
            energy_per_beat_j: s.energy_per_beat,
            power_w: s.power,
        }
    }
}

/// One point of an isochronism curve.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct IsochronismPoint {
    /// The drive factor.
    pub drive_factor: f64,
    /// The steady state there; `None` where the pendulum stops.
    #[serde(flatten)]
    pub steady: Option<SteadyState>,
    /// Whether the pendulum stops at this drive.
    pub stops: bool,
}

/// How a long run went.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RunSummary {
    /// Time run, s (the last row's).
    pub duration_s: f64,
    /// Beats counted.
    pub beats: u64,
    /// Amplitude at the end, rad.
    pub final_amplitude_rad: f64,
    /// Rate at the end, s/day, positive gaining.
    pub final_rate_s_per_day: f64,
    /// Indicated less true time at the end, s.
    pub time_error_s: f64,
    /// Whether it stopped early.
    pub stopped: bool,
    /// Why it ended: duration, pendulum_stopped, interrupted.
    pub ending: &'static str,
    /// Half swings computed one by one.
    pub half_swings_stepped: u64,
    /// Steps of many beats.
    pub multi_beat_steps: u64,
    /// The period the clock was regulated to at the start, s.
    pub nominal_period_s: f64,
    /// What to check.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<Warning>,
}

/// A clock's analysis.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ClockResult {
    /// The escapement's name.
    pub escapement: &'static str,
    /// Quality factor.
    pub q: f64,
    /// The (equivalent) length, m.
    pub length_m: f64,
    /// The (effective) mass, kg.
    pub mass_kg: f64,
    /// Lift angle, rad.
    pub lift_angle_rad: f64,
    /// The drive as a torque, N m, when so given.
    pub drive_torque_n_m: Option<f64>,
    /// The drive as an energy per beat, J, when so given.
    pub drive_energy_j: Option<f64>,
    /// The smallest drive factor that keeps it going (0: any drive does,
    /// its impulse not depending on the drive).
    pub minimum_drive_factor: f64,
    /// How far the escapement sits off the pendulum's rest, degrees (0 in
    /// beat; given, or found from the beat error given).
    pub out_of_beat_deg: f64,
    /// What being out of beat does to the rate at the drive given, s/day:
    /// the rate less the same clock's in beat (`None` in beat).
    pub out_of_beat_rate_s_per_day: Option<f64>,
    /// The steady state at the drive given.
    pub steady: SteadyState,
    /// The isochronism curve, if asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub isochronism: Option<Vec<IsochronismPoint>>,
    /// The long run, if asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub long_run: Option<RunSummary>,
    /// What to check.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<Warning>,
    /// What to do ([`crate::advice`]): set it in beat, when it is out.
    pub advice: Vec<crate::advice::Advice>,
}

/// What a long run tells its caller as it goes.
pub trait RunSink {
    /// The run is planned (`plan`); `false` stops it before it starts (a
    /// disk too small for its rows).
    fn begin(&mut self, _plan: &RunPlan) -> bool {
        true
    }
    /// A row; `false` stops the run (Ctrl-C, a failed write).
    fn row(&mut self, row: &Row) -> bool;
    /// Whether to go on between the points of an isochronism curve.
    fn proceed(&mut self) -> bool {
        true
    }
}

/// A sink that keeps nothing.
pub struct NoRows;

impl RunSink for NoRows {
    fn row(&mut self, _row: &Row) -> bool {
        true
    }
}

/// A clock built from its description, with what the result reports of it.
pub struct Built {
    /// The clock.
    pub clock: Clock,
    /// The (effective) mass, kg.
    pub mass: f64,
    /// The lift angle, rad.
    pub lift: f64,
    /// The drive.
    pub drive: Drive,
    /// The design, when the pendulum is one.
    pub design: Option<CompoundPendulum>,
    /// How far out of beat, rad.
    pub out_of_beat: f64,
    /// The same clock in beat, when it is out of beat.
    pub in_beat: Option<Clock>,
}

/// Builds the clock: the pendulum at `g`, the mass, Q, and the escapement
/// in units of `m g l` (for a design `M g d`).
pub fn build(input: &ClockInput) -> Result<Built, Refusal> {
    let g = require_finite("g", input.g.unwrap_or(STANDARD_GRAVITY))?;
    let (length, field, design) = match &input.pendulum {
        ClockPendulum::Length(l) => (require_finite("length", *l)?, "length", None),
        ClockPendulum::Design(d) => {
            let d = d.in_gravity(g);
            (d.properties().equivalent_length, "design", Some(d))
        }
    };
    let pendulum = Pendulum::new(length, g).map_err(|e| match e.quantity {
        crate::error::Quantity::Gravity => Refusal::input("g", &e),
        _ => Refusal::input(field, &e),
    })?;
    let mass = match (input.mass, &design) {
        (Some(m), _) => {
            let m = require_finite("mass", m)?;
            if m <= 0.0 {
                return Err(Refusal::field(
                    "mass",
                    format!("must be positive, got {} kg", format_significant(m, 6)),
                ));
            }
            m
        }
        (None, Some(d)) => d.properties().effective_mass(),
        (None, None) => DEFAULT_MASS_KG,
    };
    let q = require_finite("q", input.q.unwrap_or(DEFAULT_Q))?;
    if q <= 0.5 {
        return Err(Refusal::field(
            "q",
            format!(
                "must exceed 0.5 (an underdamped pendulum), got {}",
                format_significant(q, 6)
            ),
        ));
    }
    let drive = input.drive.ok_or_else(|| {
        Refusal::field(
            "drive",
            "give the drive: a torque at the pallets (N m) or an energy per beat (J)",
        )
    })?;
    let lift = input.lift_angle.unwrap_or(DEFAULT_LIFT_DEG.to_radians());
    let spec = Spec {
        kind: input.escapement.unwrap_or_else(Kind::deadbeat),
        lift,
        drive,
        friction: input.friction.unwrap_or(DEFAULT_FRICTION),
        recoil: input.recoil.unwrap_or(DEFAULT_RECOIL),
        angle: input
            .impulse_angle
            .unwrap_or(DEFAULT_IMPULSE_ANGLE_DEG.to_radians()),
        every: input.every_beats.unwrap_or(DEFAULT_EVERY_BEATS),
        out_of_beat: 0.0,
    };
    let scale = mass * g * pendulum.length_m();
    let drag = scaled_drag(&input.drag, pendulum.natural_angular_frequency())?;
    let elastic_share = design
        .as_ref()
        .and_then(CompoundPendulum::spring_effect)
        .map_or(0.0, |e| e.elastic_share);
    let clock_of = |out_of_beat: f64| -> Result<Clock, Refusal> {
        let escapement = Spec {
            out_of_beat,
            ..spec
        }
        .build(scale)
        .map_err(|e| Refusal::field(e.field, e.message))?;
        Ok(Clock {
            pendulum,
            q,
            escapement,
            torque_scale: scale,
            elastic_share,
            drag: drag.clone(),
        })
    };
    let in_beat = clock_of(0.0)?;
    let out_of_beat = match input.beat_error {
        None => 0.0,
        Some(BeatError::Angle(a)) => require_finite("beat_error", a)?,
        Some(BeatError::Time(b)) => {
            offset_for_beat_error(&in_beat, require_finite("beat_error", b)?, &clock_of)?
        }
    };
    let (clock, in_beat) = if out_of_beat == 0.0 {
        (in_beat, None)
    } else {
        (clock_of(out_of_beat)?, Some(in_beat))
    };
    Ok(Built {
        clock,
        mass,
        lift,
        drive,
        design,
        out_of_beat,
        in_beat,
    })
}

/// The offset that gives the beat error `b` s (its sign the offset's) at
/// drive factor 1: from the free swing's small-angle relation `b = 2δ /
/// (ω sqrt(A² - h²))` at the clock's steady amplitude in beat, then the
/// secant method on the integrated steady states' beat error (to 1e-9 of
/// it).
fn offset_for_beat_error(
    in_beat: &Clock,
    b: f64,
    clock_of: &dyn Fn(f64) -> Result<Clock, Refusal>,
) -> Result<f64, Refusal> {
    if b == 0.0 {
        return Ok(0.0);
    }
    // The ticks on one side can come at most a whole beat apart from
    // those on the other: the beat error is below the beat.
    let beat = 0.5 * in_beat.pendulum.small_angle_period();
    if b.abs() >= beat {
        return Err(Refusal::field(
            "beat_error",
            format!(
                "must be less than the beat ({} s), got {} s",
                format_significant(beat, 4),
                format_significant(b.abs(), 4)
            ),
        ));
    }
    let steady = in_beat
        .steady(HalfSwingMethod::Direct, 1.0)
        .map_err(|e| refusal_of(e, "drive"))?;
    let omega = in_beat.pendulum.natural_angular_frequency();
    let a = steady.amplitude;
    let h = in_beat
        .escapement
        .edges()
        .last()
        .map_or(0.0, |e| e.abs().min(0.9 * a));
    let unreachable = || {
        Refusal::field(
            "beat_error",
            format!(
                "no offset of the escapement gives a beat error of {} ms at this drive: the pendulum stops before its ticks are that uneven",
                format_significant(1e3 * b.abs(), 4)
            ),
        )
    };
    let error_at = |delta: f64| -> Result<f64, Refusal> {
        let clock = clock_of(delta)?;
        match clock.steady(HalfSwingMethod::Direct, 1.0) {
            Ok(s) => Ok(s.beat_error - b.abs()),
            Err(ClockError::Stops { .. }) => Err(unreachable()),
            Err(e) => Err(refusal_of(e, "beat_error")),
        }
    };
    let mut d0 = 0.5 * b.abs() * omega * (a * a - h * h).sqrt();
    let mut f0 = error_at(d0)?;
    let mut d1 = d0 * (1.0 - f0 / b.abs()).clamp(0.5, 2.0);
    for _ in 0..40 {
        let f1 = error_at(d1)?;
        if f1.abs() <= 1e-9 * b.abs() || f1 == f0 {
            return Ok(d1.copysign(b));
        }
        let next = d1 - f1 * (d1 - d0) / (f1 - f0);
        (d0, f0) = (d1, f1);
        d1 = next.clamp(0.5 * d1, 2.0 * d1);
    }
    Err(unreachable())
}

/// The escapement named `name`, one of
/// [`ESCAPEMENTS`](super::escapement::spec::ESCAPEMENTS).
pub fn escapement_named(name: &str) -> Result<Kind, Refusal> {
    Kind::from_name(name).ok_or_else(|| {
        Refusal::field(
            "escapement",
            format!(
                "'{name}' is not one of {}",
                super::escapement::spec::names()
            ),
        )
    })
}

/// The drive from a torque (N m) or an energy per beat (J), at most one
/// of them given.
pub fn drive_of(torque: Option<f64>, energy: Option<f64>) -> Result<Option<Drive>, Refusal> {
    match (torque, energy) {
        (Some(_), Some(_)) => Err(Refusal::field(
            "drive",
            "give a torque or an energy per beat, not both",
        )),
        (Some(t), None) => Ok(Some(Drive::Torque(t))),
        (None, Some(e)) => Ok(Some(Drive::Energy(e))),
        (None, None) => Ok(None),
    }
}

/// A clock's failure to find a steady state, said of the input at fault
/// (`drive` is the field the drive came from).
pub fn refusal_of(e: ClockError, drive: &'static str) -> Refusal {
    match e {
        ClockError::Stops {
            minimum_factor,
            unlocking_deg,
        } if minimum_factor.is_finite() => Refusal::field(
            drive,
            format!(
                "the pendulum stops: drive below {} × the one given; it must carry the swing \
                 past {}° to unlock the escapement",
                format_significant(minimum_factor, 4),
                format_significant(unlocking_deg, 4)
            ),
        ),
        ClockError::Stops { unlocking_deg, .. } => Refusal::field(
            drive,
            format!(
                "the pendulum stops: at the start there is no drive (its factor is 0) to carry \
                 the swing past {}° and unlock the escapement",
                format_significant(unlocking_deg, 4)
            ),
        ),
        ClockError::OverTheTop => Refusal::field(drive, e.to_string()),
        ClockError::NeverRuns => Refusal::field("escapement", e.to_string()),
        ClockError::Undamped => Refusal::field("q", e.to_string()),
        ClockError::Integration(a) => Refusal::field(
            drive,
            format!(
                "at a {}° swing the pendulum cannot complete a half swing: the escapement's \
                 friction or recoil holds it, or it goes over the top; give less drive",
                format_significant(a.to_degrees(), 4)
            ),
        ),
    }
}

/// The factors of an isochronism curve, checked: positive and finite; a
/// range increasing, in geometric steps (factors span a ratio).
pub fn drive_factors(factors: &DriveFactors) -> Result<Vec<f64>, Refusal> {
    match factors {
        DriveFactors::List(list) => {
            if list.is_empty() || list.len() > *STEPS_RANGE.end() {
                return Err(Refusal::field(
                    "drive_factor",
                    format!("give 1 to {} factors", STEPS_RANGE.end()),
                ));
            }
            for (i, &v) in list.iter().enumerate() {
                if require_finite_sample("drive_factor", i, v)? <= 0.0 {
                    return Err(Refusal::sample(
                        "drive_factor",
                        i,
                        format!("must be positive, got {}", format_significant(v, 6)),
                    ));
                }
            }
            Ok(list.clone())
        }
        &DriveFactors::Range { from, to, steps } => {
            for v in [from, to] {
                if require_finite("drive_range", v)? <= 0.0 {
                    return Err(Refusal::field(
                        "drive_range",
                        format!("factors must be positive, got {}", format_significant(v, 6)),
                    ));
                }
            }
            if from >= to {
                return Err(Refusal::field(
                    "drive_range",
                    "the first factor must be the smaller",
                ));
            }
            let steps = steps.unwrap_or(DEFAULT_STEPS);
            if !STEPS_RANGE.contains(&steps) {
                return Err(Refusal::field(
                    "steps",
                    format!(
                        "must lie between {} and {}",
                        STEPS_RANGE.start(),
                        STEPS_RANGE.end()
                    ),
                ));
            }
            Ok((0..steps)
                .map(|i| from * (to / from).powf(i as f64 / (steps - 1) as f64))
                .collect())
        }
    }
}

/// Checks the weather's columns: one value per time, each within the range
/// where the gas's properties are known ([`crate::gas`]: -20 to 60 °C, 1 Pa
/// to 1.2 bar).
fn check_weather(w: &Weather) -> Result<(), Refusal> {
    let (t, p) = (TEMPERATURE_RANGE_C, crate::gas::PRESSURE_RANGE_PA);
    let columns = [
        (
            "temperature_c",
            &w.temperature_c,
            t,
            1.0,
            format!(
                "{} to {} °C, where the gas's properties are known",
                t.0, t.1
            ),
        ),
        (
            "pressure",
            &w.pressure_pa,
            p,
            100.0,
            format!("{} Pa to {} hPa", p.0, p.1 / 100.0),
        ),
        (
            "humidity",
            &w.humidity_percent,
            (0.0, 100.0),
            1.0,
            "0 to 100 %".to_string(),
        ),
        (
            "gradient",
            &w.gradient_k_per_m,
            (-MAX_GRADIENT_K_PER_M, MAX_GRADIENT_K_PER_M),
            1.0,
            format!("-{MAX_GRADIENT_K_PER_M} to {MAX_GRADIENT_K_PER_M} K/m"),
        ),
    ];
    for (name, column, range, per_unit, words) in columns {
        let Some(values) = column else { continue };
        // A value that is not a number, named by its column (the times
        // are checked by the schedule's own check, as the weather's).
        if values.len() == w.time.len() {
            if let Some(i) = values.iter().position(|v| !v.is_finite()) {
                return Err(Refusal::sample(
                    name,
                    i,
                    format!(
                        "must be a finite number, got {}",
                        if values[i].is_nan() {
                            "a value that is not a number"
                        } else {
                            "an infinite value"
                        }
                    ),
                ));
            }
        }
        check_schedule("weather", &w.time, values, f64::MIN..=f64::MAX, "a number")?;
        if let Some(i) = values.iter().position(|v| !(range.0..=range.1).contains(v)) {
            return Err(Refusal::sample(
                name,
                i,
                format!(
                    "{name} {} out of range ({words})",
                    format_significant(values[i] / per_unit, 6)
                ),
            ));
        }
    }
    Ok(())
}

/// What the weather does to a clock with a design, at each of its times
/// (and, where a part lags the air, at times between them) against its
/// first row (where the clock was regulated).
struct WeatherEffect {
    /// The times, s.
    time: Vec<f64>,
    /// The rate change, s/day: the design at each part's temperature
    /// ([`CompoundPendulum::at_part_temperatures`]: the air's, or as it
    /// lags the air) against the design at the first row's, and the gas's
    /// effect (buoyancy and carried gas, [`CompoundPendulum::in_gas`]) at
    /// the row's pressure and temperature less at the first row's.
    rates: Vec<f64>,
    /// The factor on the clock's Q: the gas's damping at the row's
    /// pressure against the first row's, with the rest of the losses (the
    /// given Q less the gas's share at the first row) held.
    q_factors: Vec<f64>,
    /// What to check.
    warnings: Vec<Warning>,
}

/// The most times a lagging design's weather is evaluated at.
const MAX_LAG_POINTS: usize = 1_000_000;

/// A first-order lag `y' = (u - y)/τ` over a step of `h` s whose input
/// goes linearly from `a` to `b`, from `y0`: exact,
/// `y = b - sτ + (y0 - a + sτ) e^{-h/τ}` with `s = (b - a)/h`.
fn lag_step(y0: f64, a: f64, b: f64, h: f64, tau: f64) -> f64 {
    if tau <= 0.0 || h <= 0.0 {
        return b;
    }
    let slope_tau = (b - a) / h * tau;
    b - slope_tau + (y0 - a + slope_tau) * (-h / tau).exp()
}

/// The times at which the parts' lags are followed: the weather's rows
/// `rows`, with steps of a quarter of the shortest of the `lags` that
/// matter between them (at most [`MAX_LAG_POINTS`] over the span), and
/// after the last row, while the air holds its state and the parts go on
/// settling towards it, to twenty of the longest or the run's end
/// `until`, whichever comes first.
fn lag_times(rows: &[f64], until: f64, lags: &[f64]) -> Vec<f64> {
    let shortest = lags
        .iter()
        .copied()
        .filter(|&t| t > 0.0)
        .fold(f64::INFINITY, f64::min);
    let longest = lags.iter().copied().fold(0.0, f64::max);
    let last = rows.last().copied().unwrap_or(0.0);
    let settled = until.min(last + 20.0 * longest).max(last);
    let span = settled - rows.first().copied().unwrap_or(0.0);
    let step = if shortest.is_finite() {
        (0.25 * shortest).max(span / MAX_LAG_POINTS as f64)
    } else {
        f64::INFINITY
    };
    let mut time = Vec::new();
    let mut ends: Vec<f64> = rows.to_vec();
    if settled > last && step.is_finite() {
        ends.push(settled);
    }
    for (k, &t) in ends.iter().enumerate() {
        time.push(t);
        if let Some(&next) = ends.get(k + 1) {
            let n = ((next - t) / step).ceil();
            if n.is_finite() && n > 1.0 {
                for j in 1..n as usize {
                    time.push(t + (next - t) * j as f64 / n);
                }
            }
        }
    }
    time
}

/// The rate the gas gives `design` at each of the weather's rows
/// against `here_rate` (the first row's, s/day), and the factor on the
/// clock's Q, `q_factor` of the gas's Q there; each row's gas checked as
/// the first row's `gas0` was (the humidity a row's air can hold at its
/// own temperature and pressure), a column a row lacks taken from
/// `first` (temperature °C, pressure Pa).
fn gas_rows(
    design: &CompoundPendulum,
    w: &Weather,
    g: f64,
    gas0: &crate::gas::GasState,
    first: (f64, f64),
    here_rate: f64,
    q_factor: &dyn Fn(f64) -> f64,
) -> Result<(Vec<f64>, Vec<f64>), Refusal> {
    let at = |c: &Option<Vec<f64>>, i: usize, c0: f64| c.as_ref().map_or(c0, |v| v[i]);
    let mut gas_rate = Vec::with_capacity(w.time.len());
    let mut gas_q = Vec::with_capacity(w.time.len());
    for i in 0..w.time.len() {
        let (t, p) = (
            at(&w.temperature_c, i, first.0),
            at(&w.pressure_pa, i, first.1),
        );
        let humidity = match &w.humidity_percent {
            Some(h) => h[i] / 100.0,
            None => gas0.at_pressure(p).humidity,
        };
        let state = crate::gas::GasState::new(gas0.gas, p, t, humidity).map_err(|e| {
            let column = match e.field_name() {
                // The humidity's own column, else the pressure that thinned
                // the air (its humidity scaled with it), else the heat.
                Some("humidity") if w.humidity_percent.is_some() => "humidity",
                Some("humidity" | "pressure") if w.pressure_pa.is_some() => "pressure",
                _ => "temperature_c",
            };
            Refusal::sample(column, i, e.reason)
        })?;
        let there = design.in_gas(&state, g);
        gas_rate.push(there.rates.total - here_rate);
        gas_q.push(q_factor(there.q));
    }
    Ok((gas_rate, gas_q))
}

/// The parts' time constants (s): thermal, whether each takes up water,
/// and of moisture; and those of them that the weather moves (thermal
/// when the temperature or its gradient is logged, of moisture when the
/// humidity or the temperature is).
struct PartLags {
    lags: Vec<f64>,
    wet: Vec<bool>,
    wet_lags: Vec<f64>,
    moving: Vec<f64>,
}

/// The [`PartLags`] of `design` under the weather `w`.
fn part_lags(design: &CompoundPendulum, w: &Weather) -> PartLags {
    let parts_of = design.parts();
    let lags: Vec<f64> = parts_of.iter().map(|p| p.time_constant).collect();
    let wet: Vec<bool> = parts_of
        .iter()
        .map(|p| p.material.moisture_expansion.is_some())
        .collect();
    let wet_lags: Vec<f64> = parts_of.iter().map(|p| p.moisture_time_constant).collect();
    let thermal_moves = w.temperature_c.is_some() || w.gradient_k_per_m.is_some();
    let water_moves = wet.iter().any(|&x| x) && (w.humidity_percent.is_some() || thermal_moves);
    let moving: Vec<f64> = lags
        .iter()
        .copied()
        .filter(|_| thermal_moves)
        .chain(
            wet_lags
                .iter()
                .zip(&wet)
                .filter(|(_, &x)| x && water_moves)
                .map(|(&t, _)| t),
        )
        .collect();
    PartLags {
        lags,
        wet,
        wet_lags,
        moving,
    }
}

/// The losses that are not the gas's, as a Q: `1/(1/q − 1/q_gas)` for the
/// clock's Q `q` and the gas's alone `q_gas`; none, with a warning, when
/// `q` is above what the gas alone allows (the pressure's change of the
/// damping is then the gas's alone).
fn pivot_q(q: f64, q_gas: f64, warnings: &mut Vec<Warning>) -> Option<f64> {
    if q < q_gas {
        return Some(1.0 / (1.0 / q - 1.0 / q_gas));
    }
    warnings.push(Warning::new(
        "q_above_gas",
        format!(
            "the Q given ({}) is above what the gas alone allows this design ({}): the \
             pressure's change of the damping is taken as the gas's alone",
            format_significant(q, 5),
            format_significant(q_gas, 5)
        ),
        Some("q"),
    ));
    None
}

/// The weather's effect on `design` in `gas` (the first row's pressure
/// and temperature taken for the composition: air of 50% humidity at
/// 1,013.25 hPa pumped to that pressure) for a clock of total Q `q` at the
/// first row. Parts with a thermal time constant follow the air's
/// temperature as a first-order lag, integrated exactly over the weather
/// (linear between its rows) on steps of at most a quarter of the
/// shortest time constant (at most [`MAX_LAG_POINTS`] of them), from the
/// first row's temperature, settled, and on after the last row (whose
/// temperature holds) for twenty of the longest time constants or to
/// `until`, the run's end, s.
fn weather_effect(
    design: &CompoundPendulum,
    w: &Weather,
    gas: crate::gas::Gas,
    q: f64,
    g: f64,
    until: f64,
) -> Result<WeatherEffect, Refusal> {
    use crate::gas::{Gas, GasState};
    let first = |c: &Option<Vec<f64>>| c.as_ref().and_then(|v| v.first().copied());
    let (t0, p0) = (
        first(&w.temperature_c).unwrap_or(REFERENCE_WEATHER.0),
        first(&w.pressure_pa).unwrap_or(REFERENCE_WEATHER.1),
    );
    if w.humidity_percent.is_some() && gas != Gas::Air {
        return Err(Refusal::field(
            "humidity",
            format!(
                "a humidity column is the air's: a tank of {} holds no water vapour (drop the column, \
                 or run in air)",
                gas.name()
            ),
        ));
    }
    let humidity = match first(&w.humidity_percent) {
        Some(h) => h / 100.0,
        None if gas == Gas::Air => REFERENCE_WEATHER.2 * (p0 / REFERENCE_WEATHER.1).min(1.0),
        None => 0.0,
    };
    let gas0 = GasState::new(gas, p0, t0, humidity)?;
    let here = design.in_gas(&gas0, g);
    let q_gas0 = here.q;
    let mut warnings = Vec::new();
    if let Some(h) = &w.humidity_percent {
        if h.iter().all(|&v| v <= 1.0) && h.iter().any(|&v| v > 0.0) {
            warnings.push(Warning::new(
                "per_cent_as_fraction",
                crate::gas::per_cent_warning("the humidity never passes 1 %"),
                Some("humidity_percent"),
            ));
        }
    }
    let pivot = pivot_q(q, q_gas0, &mut warnings);
    // The gas's rate and Q factor at each row (smooth in the row's
    // pressure, temperature and humidity: linear between rows).
    let q_factor = |gas_q: f64| match pivot {
        Some(qp) => 1.0 / (1.0 / qp + 1.0 / gas_q) / q,
        None => gas_q / q_gas0,
    };
    let (gas_rate, gas_q) = gas_rows(design, w, g, &gas0, (t0, p0), here.rates.total, &q_factor)?;
    // The parts' lags: thermal (when the temperature or its gradient
    // changes) and, for parts that take up water, of moisture (when the
    // humidity or the temperature changes).
    let PartLags {
        lags,
        wet,
        wet_lags,
        moving,
    } = part_lags(design, w);
    let time = lag_times(&w.time, until, &moving);
    let column_at = |c: &Option<Vec<f64>>, c0: f64, t: f64| match c {
        Some(v) => super::long_run::piecewise_linear(&w.time, v, t),
        None => c0,
    };
    let heights = design.heights_above_thermometer();
    // What part `i` settles towards at time `t`: its temperature, and
    // (taking up water) its moisture content.
    let g0 = first(&w.gradient_k_per_m).unwrap_or(0.0);
    let targets = |t: f64| -> Vec<(f64, f64, f64)> {
        let (air, gradient) = (
            column_at(&w.temperature_c, t0, t),
            column_at(&w.gradient_k_per_m, g0, t),
        );
        let rh = column_at(&w.humidity_percent, 100.0 * humidity, t) / 100.0;
        heights
            .iter()
            .zip(&wet)
            .map(|(h, &x)| {
                let temperature = air + gradient * h;
                let moisture = if x {
                    crate::moisture::equilibrium_moisture_content(rh, temperature)
                } else {
                    0.0
                };
                (temperature, moisture, gradient)
            })
            .collect()
    };
    // The parts start settled in the first row's weather, where the clock
    // was regulated.
    let start = targets(time.first().copied().unwrap_or(0.0));
    let mut parts = start.clone();
    let length_of = |parts: &[(f64, f64, f64)]| -> Result<f64, Refusal> {
        let states: Vec<PartState> = parts
            .iter()
            .zip(&start)
            .map(
                |(&(temperature, moisture, gradient), &(_, m0, _))| PartState {
                    temperature: temperature - t0,
                    moisture,
                    reference_moisture: m0,
                    gradient,
                },
            )
            .collect();
        // Within the span every design was checked valid for.
        Ok(design
            .at_part_states(&states)
            .map_err(|e| Refusal::field("weather", e.to_string()))?
            .properties()
            .equivalent_length)
    };
    let length0 = length_of(&start)?;
    let mut rates = Vec::with_capacity(time.len());
    let mut q_factors = Vec::with_capacity(time.len());
    let mut before = start.clone();
    for (k, &t) in time.iter().enumerate() {
        if k > 0 {
            let now = targets(t);
            let h = t - time[k - 1];
            for (i, y) in parts.iter_mut().enumerate() {
                y.0 = lag_step(y.0, before[i].0, now[i].0, h, lags[i]);
                y.1 = lag_step(y.1, before[i].1, now[i].1, h, wet_lags[i]);
                y.2 = lag_step(y.2, before[i].2, now[i].2, h, lags[i]);
            }
            before = now;
        }
        let length = length_of(&parts)?;
        rates.push(
            crate::compound::rate_of_length_ratio(length / length0)
                + super::long_run::piecewise_linear(&w.time, &gas_rate, t),
        );
        q_factors.push(super::long_run::piecewise_linear(&w.time, &gas_q, t));
    }
    Ok(WeatherEffect {
        time,
        rates,
        q_factors,
        warnings,
    })
}

/// The analysis: builds the clock, finds its steady state at the drive
/// given (integrated half swings), the isochronism curve if asked, and a
/// long run if asked (planned by [`plan_run`], started in the steady state
/// of the drive at its start by the closed-form map and regulated to it;
/// the rows go to `sink`).
///
/// # Examples
///
/// ```
/// use pendulum_theory::clock::analysis::{analyse, ClockInput, ClockPendulum, NoRows};
/// use pendulum_theory::clock::escapement::spec::Drive;
/// use pendulum_theory::{period::circular_error, Amplitude};
///
/// // A seconds pendulum given 20 µJ a beat by the defaults: a deadbeat, 5 kg, Q = 10,000.
/// let mut input = ClockInput::new(ClockPendulum::Length(0.99362));
/// input.drive = Some(Drive::Energy(20e-6));
/// let s = analyse(&input, &mut NoRows)?.steady;
/// // It settles where a beat's loss, π E/Q with E = m g l (1 - cos A), is the
/// // energy the pallets give (the rest of the 20 µJ goes in their friction).
/// let e = 5.0 * 9.80665 * 0.99362 * (1.0 - s.amplitude_rad.cos());
/// assert!((std::f64::consts::PI * e / 10_000.0 / s.energy_per_beat_j - 1.0).abs() < 1e-3);
/// let a = Amplitude::from_radians(s.amplitude_rad)?;
/// assert!((s.circular_error_s_per_day - 86_400.0 * circular_error(a)).abs() < 1e-6);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn analyse(input: &ClockInput, sink: &mut dyn RunSink) -> Result<ClockResult, Refusal> {
    let built = build(input)?;
    let clock = &built.clock;
    let steady =
        clock
            .steady(HalfSwingMethod::Direct, 1.0)
            .map_err(|e| match (&built.in_beat, e) {
                (Some(in_beat), ClockError::Stops { unlocking_deg, .. })
                    if in_beat.steady(HalfSwingMethod::Direct, 1.0).is_ok() =>
                {
                    Refusal::field(
                        "beat_error",
                        format!(
                        "the pendulum stops: {}° out of beat, it must swing {}° to one side to \
                         unlock the escapement, and this drive does not carry it there (in beat \
                         it would go)",
                        format_significant(built.out_of_beat.to_degrees().abs(), 4),
                        format_significant(unlocking_deg, 4)
                    ),
                    )
                }
                (_, e) => refusal_of(e, "drive"),
            })?;
    let mut warnings = Vec::new();
    let out_of_beat_rate = match &built.in_beat {
        Some(c) => {
            let in_beat = c
                .steady(HalfSwingMethod::Direct, 1.0)
                .map_err(|e| refusal_of(e, "drive"))?;
            Some(steady.rate - in_beat.rate)
        }
        None => None,
    };
    let beat = 0.5 * steady.period;
    if steady.beat_error >= AUDIBLY_OUT_OF_BEAT * beat {
        let split = 50.0 * steady.beat_error / beat;
        warnings.push(Warning::new(
            "out_of_beat",
            format!(
                "out of beat: the ticks come {}/{} (a beat error of {} ms); move the crutch {}° \
             ({} mm at the bob) towards the side the pendulum swings to in the longer gap, to \
             set it in beat{}",
                format_significant(50.0 + split, 3),
                format_significant(50.0 - split, 3),
                format_significant(1e3 * steady.beat_error, 3),
                format_significant(built.out_of_beat.to_degrees().abs(), 3),
                format_significant(1e3 * built.out_of_beat.abs() * clock.pendulum.length_m(), 3),
                if steady.beat_error >= crate::listening::analysis::OUT_OF_BEAT * beat {
                    " (so uneven that `listen` would take it for a beat misread)"
                } else {
                    ""
                }
            ),
            Some("out_of_beat_deg"),
        ));
    }
    let (integrated, airy) = (steady.escapement_rate, steady.escapement_rate_first_order);
    if (integrated - airy).abs() > AIRY_FAR.0 * integrated.abs().max(airy.abs())
        && (integrated - airy).abs() > AIRY_FAR.1
    {
        warnings.push(Warning::new(
            "airy_first_order_off",
            format!(
                "Airy's first-order integral gives the escapement {} s/day where the integrated \
             swing gives {}: the escapement disturbs the swing beyond first order (a drive, \
             friction or recoil large against the pendulum); the integrated figure is the \
             one to use",
                format_significant(airy, 4),
                format_significant(integrated, 4)
            ),
            Some("escapement_rate_s_per_day"),
        ));
    }
    let isochronism = match &input.isochronism {
        Some(f) => {
            let mut rows = Vec::new();
            for f in drive_factors(f)? {
                if !sink.proceed() {
                    break;
                }
                rows.push(match clock.steady(HalfSwingMethod::Direct, f) {
                    Ok(s) => IsochronismPoint {
                        drive_factor: f,
                        steady: Some(SteadyState::from(&s)),
                        stops: false,
                    },
                    Err(ClockError::Stops { .. }) => IsochronismPoint {
                        drive_factor: f,
                        steady: None,
                        stops: true,
                    },
                    Err(e) => return Err(refusal_of(e, "drive_range")),
                });
            }
            Some(rows)
        }
        None => None,
    };
    let long_run = match &input.run {
        Some(r) => Some(long(&built, r, &steady, sink)?),
        None => None,
    };
    // The advice a recording of this clock would give (its rate has no
    // nominal beat here: only the beat is advised on), checked against the
    // offset simulated in `clock::tests`.
    let advice = crate::advice::advise(&crate::advice::Clockwork {
        beat_s: 0.5 * steady.period,
        beat_error_s: Some(steady.beat_error),
        oscillator: Some(crate::oscillator::Oscillator::Pendulum),
        amplitude_rad: Some(steady.amplitude),
        lift_rad: Some(built.lift),
        known: crate::advice::Known {
            pendulum: Some(crate::compound::regulate::Regulated::Length(
                clock.pendulum.length_m(),
            )),
            ..Default::default()
        },
        ..Default::default()
    })?;
    Ok(ClockResult {
        escapement: clock.escapement.name(),
        q: clock.q,
        length_m: clock.pendulum.length_m(),
        mass_kg: built.mass,
        lift_angle_rad: built.lift,
        drive_torque_n_m: match built.drive {
            Drive::Torque(t) => Some(t),
            Drive::Energy(_) => None,
        },
        drive_energy_j: match built.drive {
            Drive::Energy(e) => Some(e),
            Drive::Torque(_) => None,
        },
        minimum_drive_factor: clock.minimum_drive(),
        out_of_beat_deg: built.out_of_beat.to_degrees(),
        out_of_beat_rate_s_per_day: out_of_beat_rate,
        steady: SteadyState::from(&steady),
        isochronism,
        long_run,
        warnings,
        advice,
    })
}

/// What a long run's rate follows besides the escapement: the rate the
/// weather gives a design (with, given a pressure, the Q it gives) or a
/// rate schedule, and the warnings of the weather's effect; refused where
/// the inputs conflict (weather and a schedule, weather without a design,
/// a gas without a pressure).
fn run_rates(built: &Built, input: &RunInput) -> Result<RunRates, Refusal> {
    let (mut warnings, mut damping) = (Vec::new(), None::<Schedule>);
    let clock = &built.clock;
    if input.gas.is_some()
        && input
            .weather
            .as_ref()
            .is_none_or(|w| w.pressure_pa.is_none())
    {
        return Err(Refusal::field(
            "gas",
            "names the gas whose pressure the weather gives: give a pressure column (a tank's \
             pressure through the run), or leave the gas out",
        ));
    }
    let input_gas = input.gas.unwrap_or(crate::gas::Gas::Air);
    let rates = match (&input.weather, &built.design, &input.rate_schedule) {
        (Some(_), _, Some(_)) => {
            return Err(Refusal::field(
                "weather",
                "give the weather or a rate schedule, not both",
            ))
        }
        (Some(w), Some(design), None) => {
            check_weather(w)?;
            let effect = weather_effect(
                design,
                w,
                input_gas,
                clock.q,
                built.clock.pendulum.g_m_s2(),
                input.duration,
            )?;
            warnings = effect.warnings;
            if w.pressure_pa.is_some() {
                damping = Some(Schedule {
                    time: effect.time.clone(),
                    value: effect.q_factors,
                });
            }
            Some(Schedule {
                time: effect.time,
                value: effect.rates,
            })
        }
        (Some(w), None, None) if w.any() => {
            return Err(Refusal::field(
                "weather",
                "temperature, pressure, humidity and gradient need a design (the pendulum's \
                 own coefficients)",
            ))
        }
        (_, _, Some(r)) => {
            check_rate_schedule(&r.time, &r.value)?;
            Some(r.clone())
        }
        _ => None,
    };
    Ok(RunRates {
        rates,
        damping,
        warnings,
    })
}

/// What [`run_rates`] finds.
struct RunRates {
    /// The rate through the run, s/day, where something moves it.
    rates: Option<Schedule>,
    /// The factor on the damping through the run (the air's pressure).
    damping: Option<Schedule>,
    /// The weather's warnings.
    warnings: Vec<Warning>,
}

/// The long run of [`analyse`].
fn long(
    built: &Built,
    input: &RunInput,
    steady: &Steady,
    sink: &mut dyn RunSink,
) -> Result<RunSummary, Refusal> {
    let clock = &built.clock;
    let plan = plan_run(
        clock,
        steady.period,
        steady.amplitude,
        input.duration,
        input.every,
        input.force,
    )?;
    let empty = Schedule::default();
    let drive = input.drive_schedule.as_ref().unwrap_or(&empty);
    check_schedule(
        "drive_schedule",
        &drive.time,
        &drive.value,
        0.0..=f64::MAX,
        "a drive factor of at least 0",
    )?;
    let RunRates {
        rates,
        damping,
        mut warnings,
    } = run_rates(built, input)?;
    let drive_at = |t: f64| piecewise_linear(&drive.time, &drive.value, t);
    let stretch = |t: f64| match &rates {
        Some(r) => period_factor(piecewise_linear(&r.time, &r.value, t)),
        None => 1.0,
    };
    // The field a failure during the run is of.
    let drive_field = if input.drive_schedule.is_some() {
        "drive_schedule"
    } else {
        "drive"
    };
    let start = clock
        .steady(HalfSwingMethod::Averaged, drive_at(0.0))
        .map_err(|e| refusal_of(e, drive_field))?;
    let nominal_period = start.period;
    if !sink.begin(&plan) {
        return Ok(summary(&empty_finish(&start), nominal_period));
    }
    let damping_at = |t: f64| match &damping {
        Some(d) => piecewise_linear(&d.time, &d.value, t),
        None => 1.0,
    };
    let finish = run_with_damping(
        clock,
        &drive_at,
        &stretch,
        &damping_at,
        &LongRun::from_steady(&start, input.duration, input.every),
        &mut |row| sink.row(row),
    );
    let when = format!(
        "{} days into the run",
        format_significant(finish.last.time / 86_400.0, 4)
    );
    // The half swing that failed lies within a row's step of the last row.
    let failed_at = (finish.last.time + input.every.unwrap_or(steady.period)).min(input.duration);
    match finish.ending {
        Ending::OverTheTop => Err(Refusal::field(
            drive_field,
            format!(
                "{when} the drive (rising to {} × the given) carries the pendulum over the top; \
                 give less drive",
                format_significant(drive_at(failed_at).max(finish.last.drive), 4)
            ),
        )),
        Ending::RateOutOfRange => Err(Refusal::field(
            if input.weather.is_some() {
                "weather"
            } else {
                "rate_schedule"
            },
            format!(
                "{when} the rate moves by a day per day or more: no clock runs so; check the \
                 units"
            ),
        )),
        Ending::Duration | Ending::Sink | Ending::PendulumStopped => {
            // A beat stretched past a row's interval (a rate change close
            // to a day lost a day, a clock all but stopped) ends the run
            // long after its duration: said with the beat's length.
            let overshoot = finish.last.time - input.duration;
            if overshoot > input.every.unwrap_or(0.0).max(2.0 * steady.period) {
                let rate = finish.last.rate;
                warnings.push(Warning::new(
                    "run_overshoots",
                    format!(
                        "the run ends {} days after the {} days asked: at a rate of {} s/day one \
                     beat lasts {} s (a clock all but stopped)",
                        format_significant(overshoot / 86_400.0, 4),
                        format_significant(input.duration / 86_400.0, 4),
                        format_significant(rate, 12),
                        format_significant(nominal_period / 2.0 * period_factor(rate), 3),
                    ),
                    Some("duration_s"),
                ));
            }
            Ok(RunSummary {
                warnings,
                ..summary(&finish, nominal_period)
            })
        }
    }
}

/// A run that never started: its first row.
fn empty_finish(start: &Steady) -> super::long_run::Finish {
    super::long_run::Finish {
        last: Row {
            time: 0.0,
            beats: 0,
            amplitude: start.amplitude,
            rate: 0.0,
            time_error: 0.0,
            drive: start.drive,
        },
        single_steps: 0,
        multi_steps: 0,
        stopped: true,
        ending: Ending::Sink,
    }
}

fn summary(finish: &super::long_run::Finish, nominal_period: f64) -> RunSummary {
    let last = finish.last;
    RunSummary {
        duration_s: last.time,
        beats: last.beats,
        final_amplitude_rad: last.amplitude,
        final_rate_s_per_day: last.rate,
        time_error_s: last.time_error,
        stopped: finish.stopped,
        ending: finish.ending.name(),
        half_swings_stepped: finish.single_steps,
        multi_beat_steps: finish.multi_steps,
        nominal_period_s: nominal_period,
        warnings: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seconds_clock() -> ClockInput {
        ClockInput {
            drive: Some(Drive::Energy(20e-6)),
            ..ClockInput::new(ClockPendulum::Length(0.99362))
        }
    }

    #[test]
    fn defaults_are_the_documented_ones() {
        let r = analyse(&seconds_clock(), &mut NoRows).unwrap();
        assert_eq!(r.q, DEFAULT_Q);
        assert_eq!(r.mass_kg, DEFAULT_MASS_KG);
        assert_eq!(r.escapement, "deadbeat");
        assert_eq!(r.lift_angle_rad, DEFAULT_LIFT_DEG.to_radians());
        // The escapement's torques are over m g l: twice the mass with
        // twice the drive swings alike.
        let mut heavy = seconds_clock();
        heavy.mass = Some(2.0 * DEFAULT_MASS_KG);
        heavy.drive = Some(Drive::Energy(40e-6));
        let h = analyse(&heavy, &mut NoRows).unwrap();
        assert!((h.steady.amplitude_rad / r.steady.amplitude_rad - 1.0).abs() < 1e-12);
    }

    #[test]
    fn the_inputs_are_refused_by_name() {
        let refused = |f: &dyn Fn(&mut ClockInput)| {
            let mut c = seconds_clock();
            f(&mut c);
            analyse(&c, &mut NoRows).unwrap_err().to_string()
        };
        assert!(refused(&|c| c.q = Some(0.5)).starts_with("q: must exceed 0.5"));
        assert!(refused(&|c| c.mass = Some(-1.0)).starts_with("mass: must be positive"));
        assert!(refused(&|c| c.drive = None).starts_with("drive: give the drive"));
        assert!(refused(&|c| c.drive = Some(Drive::Energy(1e-9))).contains("the pendulum stops"));
        assert!(refused(&|c| c.g = Some(f64::NAN)).starts_with("g: must be a finite number"));
        assert!(refused(&|c| c.isochronism = Some(DriveFactors::Range {
            from: 2.0,
            to: 1.0,
            steps: None
        }))
        .starts_with("drive_range: the first factor"));
        assert!(refused(&|c| c.run = Some(RunInput {
            duration: 86_400.0,
            weather: Some(Weather {
                time: vec![0.0],
                temperature_c: Some(vec![20.0]),
                pressure_pa: None,
                ..Weather::default()
            }),
            ..RunInput::default()
        }))
        .starts_with("weather: temperature, pressure, humidity and gradient need a design"));
    }

    #[test]
    fn a_rate_schedule_moves_the_time_error_by_its_rate() {
        // 2 s/day from outside for 4 days: 8 s more ahead than without.
        let mut c = seconds_clock();
        let run = |schedule: Option<Schedule>| RunInput {
            duration: 4.0 * 86_400.0,
            every: Some(3600.0),
            rate_schedule: schedule,
            ..RunInput::default()
        };
        c.run = Some(run(None));
        let plain = analyse(&c, &mut NoRows).unwrap().long_run.unwrap();
        c.run = Some(run(Some(Schedule {
            time: vec![0.0],
            value: vec![2.0],
        })));
        let gaining = analyse(&c, &mut NoRows).unwrap().long_run.unwrap();
        let expected = 2.0 * gaining.duration_s / 86_400.0;
        assert!((gaining.time_error_s - plain.time_error_s - expected).abs() < 1e-6);
    }

    /// A rate schedule reaching -86,400 s/day (a clock that stops) hung:
    /// its beats grew without end and the rows were counted one by one.
    /// It is refused by its sample, as is the other end; close to it the
    /// run ends, its last beat taking the clock past the duration.
    #[test]
    fn a_rate_schedule_of_a_stopped_clock_is_refused_and_near_it_ends() {
        let mut c = seconds_clock();
        let run = |to: f64| RunInput {
            duration: 2.0 * 86_400.0,
            every: Some(3600.0),
            rate_schedule: Some(Schedule {
                time: vec![0.0, 86_400.0],
                value: vec![0.0, to],
            }),
            ..RunInput::default()
        };
        for (to, says) in [
            (
                -86_400.0,
                "above -86400 s/day: a clock that loses a day a day has stopped",
            ),
            (-1e300, "has stopped"),
            (86_400.0, "below 86400 s/day"),
        ] {
            c.run = Some(run(to));
            let refused = analyse(&c, &mut NoRows).unwrap_err().to_string();
            assert!(refused.starts_with("rate_schedule[1]: "), "{refused}");
            assert!(refused.contains(says), "{refused}");
        }
        for to in [-86_399.999_999, -86_400.0 * (1.0 - f64::EPSILON)] {
            c.run = Some(run(to));
            let r = analyse(&c, &mut NoRows).unwrap().long_run.unwrap();
            assert!(
                r.duration_s > 3.0 * 86_400.0 && r.duration_s.is_finite(),
                "{r:?}"
            );
            assert!(r.time_error_s.is_finite() && r.time_error_s < 0.0, "{r:?}");
            assert!(
                r.warnings[0].code == "run_overshoots"
                    && r.warnings[0].message.contains("(a clock all but stopped)"),
                "{r:?}"
            );
        }
        // A run that ends on time says nothing of it.
        c.run = Some(run(-3600.0));
        let r = analyse(&c, &mut NoRows).unwrap().long_run.unwrap();
        assert!(r.warnings.is_empty(), "{r:?}");
        assert!(r.duration_s < 2.0 * 86_400.0 + 3600.0, "{r:?}");
    }
}
