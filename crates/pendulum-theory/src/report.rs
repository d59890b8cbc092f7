//! A pendulum's report as one analysis: the exact period of the seed's
//! section 1-6 at the working amplitude ([`crate::period::table`]), the
//! damped pendulum of section 1-4 with its energy budget
//! ([`crate::damped::analysis`]), a design's datasheet
//! ([`crate::compound::datasheet`]) and the full nonlinear run-down until
//! the amplitude halves (the symplectic integrator of
//! [`crate::simulation`]), each with its defaults and limits here. The
//! command line's `report` and Python's `report` are this call; the
//! command line draws its page and figures from the result.

use crate::analysis::Refusal;
use crate::clock::analysis::{DEFAULT_MASS_KG, DEFAULT_Q};
use crate::compound::datasheet::{datasheet, Air, Datasheet};
use crate::compound::description::Design;
use crate::damped::analysis::DampingGiven;
use crate::damped::analysis::{damped, Damped, DampedInput};
use crate::error::format_significant;
use crate::period::table::{table, Amplitudes, PeriodInput, PeriodRow};
use crate::simulation::{
    half_swing_rate, simulate, work_estimate, Action, Method, Model, Observer, Options,
    TurningPoint,
};
use crate::warning::Warning;
use crate::Pendulum;
use serde::Serialize;

/// The length when neither a length nor a design is given, m: a seconds
/// pendulum at standard gravity.
pub const DEFAULT_LENGTH_M: f64 = 0.99362;
/// The working amplitude when none is given, degrees.
pub const DEFAULT_AMPLITUDE_DEG: f64 = 3.0;
/// The damping ratios the report takes besides 0: beyond them its
/// figures and budget leave double precision (measured: ζ = 1e200 and
/// 1e-320 overflow, 1e100 and 1e-308 do not).
pub const ZETA_RANGE: std::ops::RangeInclusive<f64> = 1e-300..=1e100;
/// The run-down stops after this many small-angle periods at the most.
pub const MAX_RUNDOWN_PERIODS: f64 = 1e5;
/// ... and after about this much computing by the simulation's work
/// estimate, s.
pub const MAX_RUNDOWN_SECONDS: f64 = 1.0;
/// The run-down's step tolerance (symplectic: the energy's error bound).
pub const RUNDOWN_TOLERANCE: f64 = 1e-8;
/// Without damping the run-down lasts this many small-angle periods.
pub const UNDAMPED_RUNDOWN_PERIODS: f64 = 100.0;

/// A report's question; every field but one of `length` and `design` may
/// be left out.
#[derive(Clone, Debug, Default)]
pub struct ReportInput {
    /// Length, m (default [`DEFAULT_LENGTH_M`] unless a design is given).
    pub length: Option<f64>,
    /// A pendulum of parts: its equivalent simple length is used, and its
    /// datasheet (in standard air, [`Air::default`]) joins the report.
    pub design: Option<Design>,
    /// Gravity, m/s² (default standard gravity).
    pub g: Option<f64>,
    /// Working amplitude, rad (default [`DEFAULT_AMPLITUDE_DEG`]).
    pub amplitude: Option<f64>,
    /// The viscous damping, in one of its forms (default Q =
    /// [`DEFAULT_Q`]).
    pub damping: Option<DampingGiven>,
    /// Bob mass for the energy budget, kg (default the design's effective
    /// mass, else [`DEFAULT_MASS_KG`]).
    pub mass: Option<f64>,
}

/// One turning point of the run-down after the release.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RundownPoint {
    /// Time, s.
    pub time_s: f64,
    /// Amplitude, rad (unsigned).
    pub amplitude_rad: f64,
    /// The rate of the half swing that ended here, s/day (positive gains).
    pub rate_s_per_day: f64,
}

/// The simulated run-down.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Rundown {
    /// The run wanted: until the amplitude halves, or
    /// [`UNDAMPED_RUNDOWN_PERIODS`] periods undamped, s.
    pub wanted_s: f64,
    /// The run made: shortened to [`MAX_RUNDOWN_PERIODS`] periods and
    /// about [`MAX_RUNDOWN_SECONDS`] of computing, s.
    pub duration_s: f64,
    /// Whether the run stopped short of what it wanted.
    pub stopped_short: bool,
    /// Where the run ended, s.
    pub final_time_s: f64,
    /// Turning points passed.
    pub turning_points: u64,
    /// The amplitude at the end, rad.
    pub final_amplitude_rad: f64,
    /// The rate of the first half swing, s/day (null without one).
    pub first_rate_s_per_day: Option<f64>,
    /// The rate of the last half swing, s/day.
    pub last_rate_s_per_day: Option<f64>,
    /// Every turning point after the release, for the figure (not in
    /// the JSON: up to 2·10⁵ of them).
    #[serde(skip)]
    pub points: Vec<RundownPoint>,
}

/// The report.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// Whether the length is a design's equivalent length.
    pub from_design: bool,
    /// The exact period at the working amplitude (section 1-6).
    pub period: PeriodRow,
    /// The damped pendulum (section 1-4) with its energy budget; no
    /// turning points listed.
    pub damped: Damped,
    /// Whether the mass is the design's effective mass `M d / l` (its
    /// swing's energy is `M g d (1 - cos A0)`) rather than a bob's.
    pub effective_mass: bool,
    /// The run-down.
    pub rundown: Rundown,
    /// The design's datasheet, with a design.
    pub datasheet: Option<Datasheet>,
    /// What to know before trusting the report: a design on a suspension
    /// spring whose run-down and figures swing the rigid pendulum of its
    /// equivalent length ([`crate::suspension::rigid_swing_warning`]).
    pub warnings: Vec<Warning>,
}

/// Collects the run-down's turning points; stops when `proceed` says so.
struct Turns<'a> {
    pendulum: Pendulum,
    previous: f64,
    points: Vec<RundownPoint>,
    proceed: &'a mut dyn FnMut() -> bool,
}

impl Observer for Turns<'_> {
    fn turning_point(&mut self, p: &TurningPoint) -> Action {
        if p.index > 0 {
            self.points.push(RundownPoint {
                time_s: p.time,
                amplitude_rad: p.angle.abs(),
                rate_s_per_day: half_swing_rate(&self.pendulum, p.time - self.previous),
            });
        }
        self.previous = p.time;
        Action::Continue
    }

    fn progress(&mut self, _time: f64) -> bool {
        (self.proceed)()
    }
}

/// The report of `input`. `proceed` is asked now and then during the
/// run-down; when it answers false the report is refused as interrupted
/// (the command line's Ctrl-C).
///
/// # Examples
///
/// ```
/// use pendulum_theory::report::{report, ReportInput};
///
/// // A seconds pendulum of Q = 1000 at the default 3°: the run-down lasts
/// // until the swing halves, ln 2 / (ζ ω_n) with ζ = 1/(2Q): 441 s.
/// let damping = Some(pendulum_theory::damped::analysis::DampingGiven::Q(1000.0));
/// let input = ReportInput { length: Some(0.99362), damping, ..Default::default() };
/// let r = report(&input, &mut || true)?;
/// let half_life = std::f64::consts::LN_2 * 2.0 * 1000.0 / (9.80665_f64 / 0.99362).sqrt();
/// assert!((r.rundown.wanted_s - half_life).abs() < 1e-9);
/// assert!((r.rundown.final_amplitude_rad / 3f64.to_radians() - 0.5).abs() < 1e-3);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn report(input: &ReportInput, proceed: &mut dyn FnMut() -> bool) -> Result<Report, Refusal> {
    let g = input.g;
    let (length, sheet, design_mass) = match (&input.design, input.length) {
        (Some(_), Some(_)) => {
            return Err(Refusal::field(
                "length",
                "give a length or a design, not both",
            ))
        }
        (Some(design), None) => {
            let sheet = datasheet(design, g, &Air::default())?;
            // The effective mass `I / l²` (Properties::effective_mass) of
            // the design in this gravity, as the sheet gives them.
            let effective =
                sheet.inertia_kg_m2 / (sheet.equivalent_length_m * sheet.equivalent_length_m);
            (sheet.equivalent_length_m, Some(sheet), Some(effective))
        }
        (None, length) => (length.unwrap_or(DEFAULT_LENGTH_M), None, None),
    };
    let length_field = if sheet.is_some() { "design" } else { "length" };
    // A design's suspension spring (the datasheet's, in this gravity): the
    // period is its own, the run-down a rigid pendulum's (with a warning
    // when that matters).
    let share = sheet
        .as_ref()
        .and_then(|s| s.spring.as_ref())
        .map_or(0.0, |s| s.elastic_share);
    let amplitude = input
        .amplitude
        .unwrap_or(DEFAULT_AMPLITUDE_DEG.to_radians());
    let period = table(&PeriodInput {
        length,
        g,
        amplitudes: Amplitudes::One(amplitude),
        series_terms: None,
        elastic_share: (share > 0.0).then_some(share),
    })
    .map_err(|r| rename(r, "length", length_field))?
    .remove(0);
    let mass = input.mass.or(design_mass).unwrap_or(DEFAULT_MASS_KG);
    let damping = input.damping.unwrap_or(DampingGiven::Q(DEFAULT_Q));
    let damped = damped(&DampedInput {
        length,
        g,
        amplitude,
        damping: Some(damping),
        friction_angle: None,
        mass: Some(mass),
        extrema: Some(0),
        force: false,
    })
    .map_err(|r| rename(r, "length", length_field))?;
    // On a suspension spring the exact period is the spring's (the damped
    // analysis is a rigid pendulum's of the same small-swing period).
    let mut damped = damped;
    if share > 0.0 {
        damped.exact_period_s = period.period_s;
    }
    let zeta = damped.zeta;
    if !(zeta == 0.0 || ZETA_RANGE.contains(&zeta)) {
        let field = damping.field();
        return Err(Refusal::field(
            field,
            format!(
                "gives ζ = {}; the report takes ζ from {:e} to {:e}, or none",
                format_significant(zeta, 4),
                ZETA_RANGE.start(),
                ZETA_RANGE.end()
            ),
        ));
    }
    let rundown = rundown(&damped, proceed)?;
    Ok(Report {
        from_design: sheet.is_some(),
        period,
        effective_mass: input.mass.is_none() && design_mass.is_some(),
        damped,
        rundown,
        datasheet: sheet,
        warnings: crate::suspension::rigid_swing_warning(share, amplitude)
            .map(|w| Warning::new("rigid_on_spring", w, Some("amplitude_rad")))
            .into_iter()
            .collect(),
    })
}

/// A refusal of `from` said of `to`.
fn rename(r: Refusal, from: &str, to: &'static str) -> Refusal {
    match r.field_name() {
        Some(f) if f == from => Refusal::field(to, r.reason),
        _ => r,
    }
}

/// The nonlinear run-down of `d` until its amplitude halves, within the
/// report's limits.
fn rundown(d: &Damped, proceed: &mut dyn FnMut() -> bool) -> Result<Rundown, Refusal> {
    let damped = d.friction.damped;
    let pendulum = damped.pendulum;
    let amplitude = crate::Amplitude::from_radians(d.amplitude_rad)
        .map_err(|e| Refusal::input("amplitude", &e))?;
    let model =
        Model::new(pendulum, damped.damping, 0.0, 0.0).map_err(|e| Refusal::data(e.to_string()))?;
    let t0 = pendulum.small_angle_period();
    // The slowest time constant: the envelope's when underdamped, the
    // creep's when overdamped.
    let half_life = std::f64::consts::LN_2 * damped.slowest_time_constant();
    let wanted = if half_life.is_finite() {
        half_life
    } else {
        UNDAMPED_RUNDOWN_PERIODS * t0
    };
    let mut options = Options {
        duration: wanted.min(MAX_RUNDOWN_PERIODS * t0),
        tolerance: RUNDOWN_TOLERANCE,
        method: Method::Symplectic,
        sample_interval: None,
    };
    let work = work_estimate(&model, amplitude, &options);
    if work.seconds > MAX_RUNDOWN_SECONDS {
        options.duration *= MAX_RUNDOWN_SECONDS / work.seconds;
    }
    let mut turns = Turns {
        pendulum,
        previous: 0.0,
        points: Vec::new(),
        proceed,
    };
    let outcome = simulate(&model, amplitude, &options, &mut turns)
        .map_err(|e| Refusal::data(e.to_string()))?;
    if !(turns.proceed)() {
        return Err(Refusal::data("interrupted"));
    }
    let points = turns.points;
    Ok(Rundown {
        wanted_s: wanted,
        duration_s: options.duration,
        stopped_short: options.duration < wanted,
        final_time_s: outcome.final_time,
        turning_points: outcome.swings,
        final_amplitude_rad: outcome.final_amplitude,
        first_rate_s_per_day: points.first().map(|p| p.rate_s_per_day),
        last_rate_s_per_day: points.last().map(|p| p.rate_s_per_day),
        points,
    })
}
