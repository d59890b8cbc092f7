//! A simulation as one analysis: the inputs checked (the tolerance, the
//! duration, the method against the losses), the work judged before any
//! step ([`crate::analysis::judge_work`]), the run streamed to the
//! caller's [`Observer`], and a summary with typed warnings. The command
//! line's `simulate` and Python's `simulate` are this call.

use super::forces::{drag_law, DragLaw, DRAG_LAWS};
use super::{
    simulate, work_estimate, Method, Model, Observer, Options, Outcome, SimulationError, Stopped,
    WorkEstimate,
};
use crate::analysis::{count, finite, judge_work, require_finite, Refusal};
use crate::damping::Damping;
use crate::error::format_significant;
use crate::pendulum::{Amplitude, Pendulum, STANDARD_GRAVITY};
use crate::Quantity;
use serde::Serialize;
use std::fmt;

/// The tolerance when none is given.
pub const DEFAULT_TOLERANCE: f64 = 1e-10;
/// Tolerances taken: below 1e-15 a step asks for more than double
/// precision holds; 1 asks for nothing.
pub const TOLERANCE_RANGE: std::ops::Range<f64> = 1e-15..1.0;
/// Longer simulated durations need forcing, s (32 years).
pub const MAX_DURATION_S: f64 = 1e9;
/// A trajectory has this many samples a small-angle period when no
/// interval is given.
pub const SAMPLES_PER_PERIOD: f64 = 100.0;
/// The method when none is named.
pub const DEFAULT_METHOD: &str = "dop853";
/// The method names, in the order offered.
pub const METHODS: [&str; 5] = ["dop853", "vern9", "symplectic", "exact", "averaged"];

/// The viscous damping and the input it was given as (`zeta`, `q`,
/// `log_decrement`, `decay_time`, `damping_coefficient`), for refusals.
pub type GivenDamping = (Damping, &'static str);

/// A simulation to run.
#[derive(Clone, Debug)]
pub struct SimulationInput {
    /// Length, m.
    pub length: f64,
    /// Gravity, m/s² (default standard gravity).
    pub g: Option<f64>,
    /// Release amplitude from rest, rad.
    pub amplitude: f64,
    /// Simulated time, s.
    pub duration: f64,
    /// Viscous damping, if any.
    pub damping: Option<GivenDamping>,
    /// Quadratic drag per radian (default 0).
    pub quadratic_drag: Option<f64>,
    /// Dry friction angle, rad (default 0).
    pub friction_angle: Option<f64>,
    /// Drag laws of [`super::forces::DRAG_LAWS`] (`quadratic_drag`,
    /// `three_halves_drag`, ...; [`parse_drag_law`] reads a name) with
    /// their coefficients; each at most once, the quadratic drag here or
    /// above.
    pub drag: Vec<(&'static dyn DragLaw, f64)>,
    /// The method (default [`DEFAULT_METHOD`]; [`method_of`] reads a name).
    pub method: Option<Method>,
    /// Step tolerance (default [`DEFAULT_TOLERANCE`]).
    pub tolerance: Option<f64>,
    /// Report the state every this many seconds, if any.
    pub sample_interval: Option<f64>,
    /// Runs estimated beyond [`crate::analysis::FORCE_SECONDS`] (or longer
    /// than [`MAX_DURATION_S`]) anyway.
    pub force: bool,
    /// The elastic share of a suspension spring when the pendulum is a
    /// design hanging from one (none: a rigid pivot). The run swings the
    /// rigid pendulum of the same small-swing period and warns when its
    /// circular error differs from the spring's
    /// ([`crate::suspension::rigid_swing_warning`]).
    pub elastic_share: Option<f64>,
}

/// What a person must know about a run's numerics.
#[derive(Clone, Debug, PartialEq)]
pub enum SimulationWarning {
    /// The energy at a turning point rose by `relative` of itself at
    /// `time` s, which no damping explains.
    EnergyGain {
        /// The relative change.
        relative: f64,
        /// When, s.
        time: f64,
        /// Whether the exact method was the one run.
        exact: bool,
    },
    /// The pendulum passed over the top at `time` s.
    OverTheTop {
        /// When, s.
        time: f64,
        /// Whether the exact method was the one run.
        exact: bool,
    },
    /// The step fell to nothing at `time` s.
    StepTooSmall {
        /// When, s.
        time: f64,
    },
    /// A design on a suspension spring of elastic share `share` swung as
    /// a rigid pendulum from `amplitude` rad, whose circular error the
    /// spring would shrink (see [`crate::suspension::rigid_swing_warning`]).
    RigidOnSpring {
        /// The spring's elastic share.
        share: f64,
        /// The release amplitude, rad.
        amplitude: f64,
    },
}

impl fmt::Display for SimulationWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let hint = |exact: bool| {
            if exact {
                ""
            } else {
                " (without damping, the exact method is exact at any amplitude)"
            }
        };
        match *self {
            SimulationWarning::EnergyGain {
                relative,
                time,
                exact,
            } => write!(
                f,
                "the energy at a turning point changed by {} of itself (or of the period it \
                 implies) at {} s, which the damping does not explain: the tolerance is too \
                 loose for this motion; tighten the tolerance{}",
                format_significant(relative, 3),
                format_significant(time, 8),
                hint(exact)
            ),
            SimulationWarning::OverTheTop { time, exact } => write!(
                f,
                "the pendulum passed over the top at {} s, impossible from rest below 180°: \
                 the release is too close to 180° for this method and tolerance; the run was \
                 stopped there{}",
                format_significant(time, 8),
                hint(exact)
            ),
            SimulationWarning::StepTooSmall { time } => write!(
                f,
                "the step size fell to nothing at {} s; the run was stopped there",
                format_significant(time, 8)
            ),
            SimulationWarning::RigidOnSpring { share, amplitude } => f.write_str(
                &crate::suspension::rigid_swing_warning(share, amplitude).unwrap_or_default(),
            ),
        }
    }
}

impl crate::warning::Warn for SimulationWarning {
    fn code(&self) -> &'static str {
        match self {
            SimulationWarning::EnergyGain { .. } => "energy_gain",
            SimulationWarning::OverTheTop { .. } => "over_the_top",
            SimulationWarning::StepTooSmall { .. } => "step_too_small",
            SimulationWarning::RigidOnSpring { .. } => "rigid_on_spring",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            SimulationWarning::EnergyGain { .. } => Some("final_amplitude_rad"),
            SimulationWarning::OverTheTop { .. } | SimulationWarning::StepTooSmall { .. } => {
                Some("final_time_s")
            }
            SimulationWarning::RigidOnSpring { .. } => Some("amplitude_rad"),
        }
    }
}

crate::warning::serialize_as_warning!(SimulationWarning);

/// The summary of a run.
#[derive(Clone, Debug, Serialize)]
pub struct Simulation {
    /// The method run.
    pub method: &'static str,
    /// Half swings completed.
    pub swings: u64,
    /// When the run ended, s.
    pub final_time_s: f64,
    /// The angle then, rad.
    pub final_angle_rad: f64,
    /// The angular velocity then, rad/s.
    pub final_angular_velocity_rad_s: f64,
    /// The last turning point's amplitude, rad.
    pub final_amplitude_rad: f64,
    /// Steps taken.
    pub steps: u64,
    /// The steps estimated before the run (what forcing is judged on).
    pub estimated_steps: f64,
    /// Steps rejected by the error control.
    pub rejected_steps: u64,
    /// Evaluations of the equation of motion.
    pub function_evaluations: u64,
    /// Why the run ended.
    pub stopped: &'static str,
    /// The duration asked for, s.
    pub duration_s: f64,
    /// The step tolerance.
    pub tolerance: f64,
    /// Length, m.
    pub length_m: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// Release amplitude, rad.
    pub amplitude_rad: f64,
    /// Viscous damping ratio.
    pub zeta: f64,
    /// Q (`null` undamped).
    pub q_factor: Option<f64>,
    /// Quadratic drag per radian.
    pub quadratic_drag: f64,
    /// Every drag law's coefficient, by its name (0: not in the model).
    pub drag: std::collections::BTreeMap<&'static str, f64>,
    /// Dry friction angle, rad.
    pub friction_angle_rad: f64,
    /// Problems a person must see.
    pub warnings: Vec<SimulationWarning>,
    /// Why the run ended, typed.
    #[serde(skip)]
    pub outcome: Outcome,
}

/// A simulation checked and estimated, ready to run.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// The equation of motion.
    pub model: Model,
    /// The release.
    pub amplitude: Amplitude,
    /// The run asked for.
    pub options: Options,
    /// Its estimated cost.
    pub work: WorkEstimate,
    /// The input the damping was given as.
    pub damping_field: &'static str,
    /// A suspension spring's elastic share (0: a rigid pivot).
    pub elastic_share: f64,
}

/// The viscous damping given as the input `field` (`zeta`, `q` or
/// `log_decrement`) with `value`.
pub fn damping_of(field: &str, value: f64) -> Result<GivenDamping, Refusal> {
    let (made, name) = match field {
        "zeta" => (Damping::from_zeta(value), "zeta"),
        "q" => (Damping::from_q(value), "q"),
        "log_decrement" => (Damping::from_log_decrement(value), "log_decrement"),
        other => {
            return Err(Refusal::field(
                "damping",
                format!("'{other}' is not one of zeta, q, log_decrement"),
            ))
        }
    };
    made.map(|d| (d, name))
        .map_err(|e| Refusal::input(name, &e))
}

/// The method called `name`.
pub fn method_of(name: &str) -> Result<Method, Refusal> {
    Ok(match name {
        "dop853" => Method::Dop853,
        "vern9" => Method::Vern9,
        "symplectic" => Method::Symplectic,
        "exact" => Method::Exact,
        "averaged" => Method::Averaged,
        other => {
            return Err(Refusal::field(
                "method",
                format!("'{other}' is not one of {}", METHODS.join(", ")),
            ))
        }
    })
}

/// Checks the inputs and judges the work, before any step (see the
/// module notes).
///
/// # Examples
///
/// ```
/// use pendulum_theory::simulation::analysis::{prepare, SimulationInput};
/// use pendulum_theory::simulation::Silent;
/// use pendulum_theory::{Amplitude, Pendulum};
///
/// // A seconds pendulum released from rest at 30°, undamped, run for one
/// // exact period, 4 √(l/g) K(sin² 15°) = 2.0348 s: it is back where it began.
/// let a = Amplitude::from_degrees(30.0)?;
/// let period = Pendulum::with_standard_gravity(0.99362)?.period(a);
/// let run = prepare(&SimulationInput {
///     length: 0.99362, g: None, amplitude: a.radians(), duration: period,
///     damping: None, quadratic_drag: None, friction_angle: None, drag: vec![],
///     method: None, tolerance: None, sample_interval: None, force: false,
///     elastic_share: None,
/// })?;
/// let end = run.run(&mut Silent)?;
/// assert!((end.final_angle_rad - a.radians()).abs() < 1e-9);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn prepare(input: &SimulationInput) -> Result<Prepared, Refusal> {
    let pendulum =
        Pendulum::new(input.length, input.g.unwrap_or(STANDARD_GRAVITY)).map_err(|e| {
            match e.quantity {
                Quantity::Gravity => Refusal::input("g", &e),
                _ => Refusal::input("length", &e),
            }
        })?;
    let amplitude =
        Amplitude::from_radians(input.amplitude).map_err(|e| Refusal::input("amplitude", &e))?;
    let (damping, damping_field) = input.damping.unwrap_or((Damping::NONE, "zeta"));
    let model = Model::new(
        pendulum,
        damping,
        input.quadratic_drag.unwrap_or(0.0),
        input.friction_angle.unwrap_or(0.0),
    )
    .map_err(|e| match e.quantity {
        Quantity::QuadraticDrag => Refusal::input("quadratic_drag", &e),
        _ => Refusal::input("friction_angle", &e),
    })?;
    let model = with_drag_laws(model, input)?;
    let duration = require_finite("duration", input.duration)?;
    if duration < 0.0 {
        return Err(Refusal::field(
            "duration",
            format!(
                "must not be negative, got {} s",
                format_significant(duration, 10)
            ),
        ));
    }
    if duration > MAX_DURATION_S && !input.force {
        return Err(Refusal::field(
            "duration",
            format!(
                "{} s is over 10^9 s (32 years); force it (--force; force=True in Python) if \
                 you mean it",
                format_significant(duration, 4)
            ),
        ));
    }
    let tolerance = require_finite("tolerance", input.tolerance.unwrap_or(DEFAULT_TOLERANCE))?;
    if !TOLERANCE_RANGE.contains(&tolerance) {
        return Err(Refusal::field(
            "tolerance",
            format!(
                "must lie between 1e-15 (double precision) and 1 (e.g. 1e-10), got {}",
                format_significant(tolerance, 10)
            ),
        ));
    }
    if let Some(h) = input.sample_interval {
        if require_finite("sample_interval", h)? <= 0.0 {
            return Err(Refusal::field(
                "sample_interval",
                format!("must be positive, got {} s", format_significant(h, 10)),
            ));
        }
    }
    let method = match input.method {
        Some(m) => m,
        None => method_of(DEFAULT_METHOD)?,
    };
    let options = Options {
        duration,
        tolerance,
        method,
        sample_interval: input.sample_interval,
    };
    // The method against the losses, before the estimate.
    super::check_method(&model, &options, false).map_err(|e| refusal(e, damping_field))?;
    let work = work_estimate(&model, amplitude, &options);
    let (field, why) = match work.limit {
        super::Limit::Oscillation => (
            "duration",
            format!(
                "{} s is {} periods of this pendulum",
                format_significant(duration, 6),
                count(work.periods)
            ),
        ),
        super::Limit::Viscous => (
            damping_field,
            format!(
                "ζ = {} makes the equation stiff for an explicit method (the overdamped creep \
                 has a closed form: pendulum damped)",
                format_significant(damping.zeta(), 4)
            ),
        ),
        super::Limit::Drag => (
            DRAG_LAWS[work.drag_law].name(),
            format!(
                "a drag of {} makes the equation stiff{}",
                format_significant(model.drag[work.drag_law], 4),
                if method == Method::Symplectic {
                    " (the dop853 method often takes fewer steps in the drag-limited creep)"
                } else {
                    ""
                }
            ),
        ),
    };
    judge_work(
        field,
        format!("{why}: about {} integration steps", count(work.steps)),
        work.seconds,
        input.force,
    )?;
    let elastic_share = crate::suspension::elastic_share(input.elastic_share)?;
    Ok(Prepared {
        model,
        amplitude,
        options,
        work,
        damping_field,
        elastic_share,
    })
}

/// `model` with the drag laws of `input.drag`, each named once.
fn with_drag_laws(mut model: Model, input: &SimulationInput) -> Result<Model, Refusal> {
    let mut given = [false; DRAG_LAWS.len()];
    given[super::QUADRATIC_DRAG] = input.quadratic_drag.is_some();
    for (i, k) in checked_drag_laws(&input.drag, given)? {
        model = model
            .with_drag(i, k)
            .map_err(|reason| Refusal::field(DRAG_LAWS[i].name(), reason))?;
    }
    Ok(model)
}

/// The drag laws `drag` (coefficients in their own units) as indices of
/// [`DRAG_LAWS`] with their coefficients, each named once (`given`: the
/// laws another input gave already) and its coefficient checked; a
/// refusal names the law, the field every front end says it by
/// (`--drag NAME`). What the simulation and the clock take drag laws by.
pub(crate) fn checked_drag_laws(
    drag: &[(&'static dyn DragLaw, f64)],
    mut given: [bool; DRAG_LAWS.len()],
) -> Result<Vec<(usize, f64)>, Refusal> {
    drag.iter()
        .map(|&(law, k)| {
            let i = drag_law(law.name()).ok_or_else(|| {
                Refusal::field(
                    "drag",
                    format!("'{}' is not in the list of drag laws", law.name()),
                )
            })?;
            let field = DRAG_LAWS[i].name();
            if std::mem::replace(&mut given[i], true) {
                return Err(Refusal::field(field, "is given twice"));
            }
            let k = crate::forces::check_drag(k).map_err(|reason| Refusal::field(field, reason))?;
            Ok((i, k))
        })
        .collect()
}

/// The drag law named `name` in [`DRAG_LAWS`]; refused, naming the field
/// `drag` and the laws, for any other name.
pub fn parse_drag_law(name: &str) -> Result<&'static dyn DragLaw, Refusal> {
    match drag_law(name) {
        Some(i) => Ok(DRAG_LAWS[i]),
        None => {
            let names: Vec<&str> = DRAG_LAWS.iter().map(|l| l.name()).collect();
            Err(Refusal::field(
                "drag",
                format!("'{name}' is not one of {}", names.join(", ")),
            ))
        }
    }
}

fn refusal(e: SimulationError, damping_field: &'static str) -> Refusal {
    match e {
        SimulationError::ExactWithDamping
        | SimulationError::AveragedUnsupported
        | SimulationError::SymplecticOneDragLaw => Refusal::field("method", e.to_string()),
        SimulationError::AveragedNeedsWeakDamping { .. } => {
            Refusal::field(damping_field, e.to_string())
        }
        SimulationError::Input(ref i) => Refusal::input(
            match i.quantity {
                Quantity::Tolerance => "tolerance",
                Quantity::SampleInterval => "sample_interval",
                _ => "duration",
            },
            i,
        ),
    }
}

impl Prepared {
    /// Runs, streaming to `observer`, and sums up.
    pub fn run(&self, observer: &mut impl Observer) -> Result<Simulation, Refusal> {
        let outcome = simulate(&self.model, self.amplitude, &self.options, observer)
            .map_err(|e| refusal(e, self.damping_field))?;
        let exact = outcome.method == Method::Exact;
        let mut warnings = Vec::new();
        if let Some(gain) = outcome.energy_gain {
            warnings.push(SimulationWarning::EnergyGain {
                relative: gain.relative,
                time: gain.time,
                exact,
            });
        }
        match outcome.stopped {
            Stopped::OverTheTop => warnings.push(SimulationWarning::OverTheTop {
                time: outcome.final_time,
                exact,
            }),
            Stopped::StepTooSmall => warnings.push(SimulationWarning::StepTooSmall {
                time: outcome.final_time,
            }),
            _ => {}
        }
        let release = self.amplitude.radians();
        if crate::suspension::rigid_swing_warning(self.elastic_share, release).is_some() {
            warnings.push(SimulationWarning::RigidOnSpring {
                share: self.elastic_share,
                amplitude: release,
            });
        }
        let p = &self.model.pendulum;
        Ok(Simulation {
            method: outcome.method.name(),
            swings: outcome.swings,
            final_time_s: outcome.final_time,
            final_angle_rad: outcome.final_state.angle,
            final_angular_velocity_rad_s: outcome.final_state.angular_velocity,
            final_amplitude_rad: outcome.final_amplitude,
            steps: outcome.steps,
            estimated_steps: self.work.steps,
            rejected_steps: outcome.rejected_steps,
            function_evaluations: outcome.function_evaluations,
            stopped: outcome.stopped.name(),
            duration_s: self.options.duration,
            tolerance: self.options.tolerance,
            length_m: p.length_m(),
            g_m_s2: p.g_m_s2(),
            amplitude_rad: self.amplitude.radians(),
            zeta: self.model.damping.zeta(),
            q_factor: finite(self.model.damping.q_factor()),
            quadratic_drag: self.model.quadratic_drag(),
            drag: DRAG_LAWS
                .iter()
                .zip(self.model.drag)
                .map(|(law, k)| (law.name(), k))
                .collect(),
            friction_angle_rad: self.model.friction_angle,
            warnings,
            outcome,
        })
    }
}
