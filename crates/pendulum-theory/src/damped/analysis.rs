//! The damped pendulum as one analysis (seed section 1-4, with the dry
//! friction of the book's section 2-4 and the energy budget): the damping
//! in any of its forms, the friction angle against the amplitude, the
//! turning points (how many, and the work rule on them), the small-angle
//! theory's own warning, one result. The command line's `damped` and
//! Python's `damped` are this call.

use super::friction::{DryFriction, RunDown};
use super::{DampedPendulum, Regime};
use crate::analysis::{finite, require_finite, Refusal};
use crate::damping::Damping;
use crate::energy::{energy_budget, EnergyBudget};
use crate::error::{format_significant, Quantity};
use crate::pendulum::{Amplitude, Pendulum, STANDARD_GRAVITY};
use crate::warning::Warning;
use serde::Serialize;

/// Turning points listed when not given.
pub const DEFAULT_EXTREMA: u64 = 10;
/// More turning points than this need forcing.
pub const MAX_EXTREMA: u64 = 100_000;
/// More turning points than this are refused even forced (a few hundred
/// MB of text; a trajectory streams a run of any length).
pub const MAX_EXTREMA_FORCED: u64 = 10_000_000;
/// Above this amplitude, degrees, the small-angle theory is off by more
/// than 0.2% in the period: a warning names the exact period.
pub const SMALL_ANGLE_LIMIT_DEG: f64 = 10.0;

/// A trajectory (or figure) of the motion lasts this many small-angle
/// periods when no duration is given.
pub const TRAJECTORY_PERIODS: f64 = 10.0;
/// ... with this many samples a small-angle period when no interval is given.
pub const SAMPLES_PER_PERIOD: f64 = 100.0;

/// The damping's forms, by their input names.
pub const DAMPING_FIELDS: [&str; 5] = [
    "zeta",
    "q",
    "log_decrement",
    "decay_time",
    "damping_coefficient",
];

/// How a viscous damping is given: the form (one of [`DAMPING_FIELDS`])
/// and its value in that form's unit (a decay time in s, a damping
/// coefficient in N s, the others numbers).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DampingGiven {
    /// The damping ratio ζ.
    Zeta(f64),
    /// The quality factor Q.
    Q(f64),
    /// The logarithmic decrement δ.
    LogDecrement(f64),
    /// The amplitude's decay time τ, s.
    DecayTime(f64),
    /// The damping coefficient c, N s (needs the bob's mass).
    DampingCoefficient(f64),
}

impl DampingGiven {
    /// The form named `field` (one of [`DAMPING_FIELDS`]) with `value`;
    /// refused, naming the field `damping` and the forms, for any other
    /// name.
    pub fn parse(field: &str, value: f64) -> Result<Self, Refusal> {
        Ok(match field {
            "zeta" => DampingGiven::Zeta(value),
            "q" => DampingGiven::Q(value),
            "log_decrement" => DampingGiven::LogDecrement(value),
            "decay_time" => DampingGiven::DecayTime(value),
            "damping_coefficient" => DampingGiven::DampingCoefficient(value),
            other => {
                return Err(Refusal::field(
                    "damping",
                    format!("'{other}' is not one of {}", DAMPING_FIELDS.join(", ")),
                ))
            }
        })
    }

    /// The form's name: its field in refusals and on the command line.
    pub fn field(self) -> &'static str {
        match self {
            DampingGiven::Zeta(_) => "zeta",
            DampingGiven::Q(_) => "q",
            DampingGiven::LogDecrement(_) => "log_decrement",
            DampingGiven::DecayTime(_) => "decay_time",
            DampingGiven::DampingCoefficient(_) => "damping_coefficient",
        }
    }
}

/// The viscous damping `given`, for `pendulum` with a bob of `mass` kg
/// (the damping coefficient needs it), with the form's name.
pub fn damping_given(
    given: DampingGiven,
    pendulum: &Pendulum,
    mass: Option<f64>,
) -> Result<(Damping, &'static str), Refusal> {
    let name = given.field();
    let made = match given {
        DampingGiven::Zeta(v) => Damping::from_zeta(v),
        DampingGiven::Q(v) => Damping::from_q(v),
        DampingGiven::LogDecrement(v) => Damping::from_log_decrement(v),
        DampingGiven::DecayTime(v) => Damping::from_decay_time(v, pendulum),
        DampingGiven::DampingCoefficient(v) => {
            let m = mass.ok_or_else(|| {
                Refusal::field("mass", "is needed with a damping coefficient (c, N s)")
            })?;
            Damping::from_coefficient(v, m, pendulum)
        }
    };
    made.map(|d| (d, name)).map_err(|e| match e.quantity {
        Quantity::Mass => Refusal::input("mass", &e),
        _ => Refusal::input(name, &e),
    })
}

/// A damped pendulum's question.
#[derive(Clone, Debug, PartialEq)]
pub struct DampedInput {
    /// Length, m.
    pub length: f64,
    /// Gravity, m/s² (default standard gravity).
    pub g: Option<f64>,
    /// Release amplitude, rad.
    pub amplitude: f64,
    /// The damping, in one of its forms.
    pub damping: Option<DampingGiven>,
    /// Dry friction angle, rad (default 0).
    pub friction_angle: Option<f64>,
    /// Bob mass, kg, for the energy budget.
    pub mass: Option<f64>,
    /// Turning points to list after the start (default
    /// [`DEFAULT_EXTREMA`]).
    pub extrema: Option<u64>,
    /// List more than [`MAX_EXTREMA`].
    pub force: bool,
}

/// A turning point.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ExtremumRow {
    /// 0 for the release, then one per half period.
    pub index: u64,
    /// Time, s.
    pub time_s: f64,
    /// Signed angle, rad.
    pub angle_rad: f64,
}

/// Where the pendulum stops (dry friction).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StopRow {
    /// Time, s; null when it creeps there without end.
    pub time_s: Option<f64>,
    /// The angle it stays at, rad.
    pub angle_rad: f64,
}

/// The damped pendulum's answer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Damped {
    /// Length, m.
    pub length_m: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// Release amplitude, rad.
    pub amplitude_rad: f64,
    /// Damping ratio.
    pub zeta: f64,
    /// Q (null undamped).
    pub q_factor: Option<f64>,
    /// Logarithmic decrement per period (null when it does not oscillate).
    pub log_decrement: Option<f64>,
    /// ω_n, rad/s.
    pub natural_angular_frequency_rad_s: f64,
    /// ω_d, rad/s.
    pub damped_angular_frequency_rad_s: Option<f64>,
    /// The damped period, s.
    pub damped_period_s: Option<f64>,
    /// The phase φ, rad.
    pub phase_rad: Option<f64>,
    /// underdamped, critically damped, overdamped.
    pub regime: &'static str,
    /// The slowest time constant, s (the slow creep when overdamped).
    pub decay_time_s: Option<f64>,
    /// The envelope's half-life, s (when it oscillates).
    pub amplitude_half_life_s: Option<f64>,
    /// Amplitude lost per period, rad.
    pub amplitude_loss_per_period_rad: Option<f64>,
    /// The same to first order, rad.
    pub amplitude_loss_per_period_approx_rad: Option<f64>,
    /// First order less exact, rad.
    pub amplitude_loss_per_period_difference_rad: Option<f64>,
    /// Dry friction angle, rad.
    pub friction_angle_rad: f64,
    /// The turning points.
    pub extrema: Vec<ExtremumRow>,
    /// Where it stops, with dry friction.
    pub stop: Option<StopRow>,
    /// Bob mass, kg.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass_kg: Option<f64>,
    /// The damping coefficient c, N s (with a mass).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub damping_coefficient_n_s: Option<f64>,
    /// Stored energy, J.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_j: Option<f64>,
    /// Energy lost per period, J.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_loss_per_period_j: Option<f64>,
    /// Mean power, W.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub power_w: Option<f64>,
    /// Angular impulse per beat that holds the amplitude, kg m²/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impulse_per_beat_kg_m2_s: Option<f64>,
    /// The exact period at the amplitude, s (the small-angle theory's
    /// damped period ignores the amplitude).
    pub exact_period_s: f64,
    /// What a person must know about these results.
    pub warnings: Vec<Warning>,
    /// The pendulum with its damping and friction, for the motion's
    /// samples and figures.
    #[serde(skip)]
    pub friction: DryFriction,
    /// The energy budget.
    #[serde(skip)]
    pub budget: Option<EnergyBudget>,
}

/// The analysis.
///
/// # Examples
///
/// ```
/// use pendulum_theory::damped::analysis::{damped, DampedInput, DampingGiven};
///
/// // A seconds pendulum of Q = 100 released at 0.05 rad: two turning points.
/// let d = damped(&DampedInput {
///     length: 0.99362,
///     g: None,
///     amplitude: 0.05,
///     damping: Some(DampingGiven::Q(100.0)),
///     friction_angle: None,
///     mass: None,
///     extrema: Some(2),
///     force: false,
/// })?;
/// // ζ = 1/(2Q); a period on, the swing is e^-δ of itself, δ = 2πζ/√(1 - ζ²).
/// let zeta = 1.0 / 200.0_f64;
/// let delta = std::f64::consts::TAU * zeta / (1.0 - zeta * zeta).sqrt();
/// assert!((d.extrema[2].angle_rad - 0.05 * (-delta).exp()).abs() < 1e-12);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn damped(input: &DampedInput) -> Result<Damped, Refusal> {
    let g = require_finite("g", input.g.unwrap_or(STANDARD_GRAVITY))?;
    let pendulum = Pendulum::new(input.length, g).map_err(|e| match e.quantity {
        Quantity::Gravity => Refusal::input("g", &e),
        _ => Refusal::input("length", &e),
    })?;
    let amplitude =
        Amplitude::from_radians(input.amplitude).map_err(|e| Refusal::input("amplitude", &e))?;
    // A mass is checked where it is given, whether or not a budget needs it.
    if let Some(m) = input.mass {
        crate::error::require_positive(Quantity::Mass, m)
            .map_err(|e| Refusal::input("mass", &e))?;
    }
    let count = input.extrema.unwrap_or(DEFAULT_EXTREMA);
    // The turning points are held and printed: past 10^7 not even forced.
    if count > MAX_EXTREMA_FORCED || (count > MAX_EXTREMA && !input.force) {
        return Err(Refusal::field(
            "extrema",
            if count > MAX_EXTREMA_FORCED {
                format!(
                    "{count} turning points requested; at most {MAX_EXTREMA_FORCED} are listed \
                     (a trajectory file streams a run of any length)"
                )
            } else {
                format!(
                    "{count} turning points requested; more than {MAX_EXTREMA} needs forcing \
                     (--force; force=True in Python), or a trajectory file"
                )
            },
        ));
    }
    let given = input.damping.ok_or_else(|| {
        Refusal::field(
            "zeta",
            format!(
                "give the damping: zeta, or one of {}",
                DAMPING_FIELDS[1..].join(", ")
            ),
        )
    })?;
    let (damping, _) = damping_given(given, &pendulum, input.mass)?;
    let damped = DampedPendulum::new(pendulum, damping);
    let r = input.friction_angle.unwrap_or(0.0);
    let friction = DryFriction::new(damped, r).map_err(|e| Refusal::input("friction_angle", &e))?;
    let a0 = amplitude.radians();
    if r > 0.0 && r >= a0 {
        let show = |x| Quantity::FrictionAngle.format_value(x);
        return Err(Refusal::field(
            "friction_angle",
            format!(
                "must be less than the amplitude {}, got {}: friction would hold the pendulum \
                 at rest",
                show(a0),
                show(r)
            ),
        ));
    }
    let run: RunDown = friction.run_down(a0, count);
    // Without friction the closed form gives every turning point directly,
    // with no rounding carried from one to the next.
    let extrema = if r == 0.0 {
        damped.extrema(a0, count)
    } else {
        run.extrema.clone()
    };
    let budget = match (
        input.mass,
        friction.half_swing_loss(a0),
        damped.damped_period(),
    ) {
        (Some(m), Some(loss), Some(period)) => Some(
            energy_budget(&pendulum, m, a0, loss, period).map_err(|e| match e.quantity {
                Quantity::Length => Refusal::input("length", &e),
                Quantity::Gravity => Refusal::input("g", &e),
                _ => Refusal::input("mass", &e),
            })?,
        ),
        _ => None,
    };
    let exact = friction.amplitude_loss_per_period(a0);
    let approx = friction.amplitude_loss_per_period_approx(a0);
    let exact_period = pendulum.period(amplitude);
    let mut warnings = Vec::new();
    if amplitude.degrees() > SMALL_ANGLE_LIMIT_DEG {
        warnings.push(Warning::new(
            "small_angle_approximate",
            format!(
                "at {}° the small-angle theory (book section 1-4) is only approximate: the exact \
             period at this amplitude is {} s, not {}; `pendulum simulate` integrates the full \
             nonlinear damped motion",
                format_significant(amplitude.degrees(), 10),
                format_significant(exact_period, 7),
                damped
                    .damped_period()
                    .map_or("the small-angle one".to_string(), |p| format!(
                        "{} s",
                        format_significant(p, 7)
                    ))
            ),
            Some("damped_period_s"),
        ));
    }
    Ok(Damped {
        length_m: pendulum.length_m(),
        g_m_s2: pendulum.g_m_s2(),
        amplitude_rad: a0,
        zeta: damping.zeta(),
        q_factor: finite(damping.q_factor()),
        log_decrement: damping.log_decrement(),
        natural_angular_frequency_rad_s: damped.natural_angular_frequency(),
        damped_angular_frequency_rad_s: damped.damped_angular_frequency(),
        damped_period_s: damped.damped_period(),
        phase_rad: damped.phase(),
        regime: damped.regime().name(),
        decay_time_s: finite(damped.slowest_time_constant()),
        // An envelope e^{-ζω_n t} exists only when the pendulum oscillates.
        amplitude_half_life_s: damped
            .damped_period()
            .and_then(|_| finite(damping.amplitude_half_life(&pendulum))),
        amplitude_loss_per_period_rad: exact,
        amplitude_loss_per_period_approx_rad: approx,
        amplitude_loss_per_period_difference_rad: exact.zip(approx).map(|(e, a)| a - e),
        friction_angle_rad: r,
        extrema: extrema
            .iter()
            .map(|e| ExtremumRow {
                index: e.index,
                time_s: e.time,
                angle_rad: e.angle,
            })
            .collect(),
        stop: run.stop.map(|s| StopRow {
            time_s: s.time,
            angle_rad: s.angle,
        }),
        mass_kg: input.mass,
        damping_coefficient_n_s: input.mass.map(|m| damping.coefficient(m, &pendulum)),
        energy_j: budget.map(|b| b.energy),
        energy_loss_per_period_j: budget.map(|b| b.loss_per_period),
        power_w: budget.map(|b| b.power),
        impulse_per_beat_kg_m2_s: budget.map(|b| b.impulse_per_beat),
        exact_period_s: exact_period,
        warnings,
        friction,
        budget,
    })
}

impl Damped {
    /// The motion's span, s: `duration`, or [`TRAJECTORY_PERIODS`]
    /// small-angle periods; refused when negative or not finite.
    pub fn span(&self, duration: Option<f64>) -> Result<f64, Refusal> {
        let t0 = self.friction.damped.pendulum.small_angle_period();
        crate::analysis::duration(duration.unwrap_or(TRAJECTORY_PERIODS * t0))
    }

    /// The samples of the motion over `duration` s every `interval` s (by
    /// default [`SAMPLES_PER_PERIOD`] a small-angle period), checked by
    /// [`crate::analysis::sampling`]: the interval and the count.
    pub fn sampling(
        &self,
        duration: f64,
        interval: Option<f64>,
        force: bool,
    ) -> Result<(f64, u64), Refusal> {
        let t0 = self.friction.damped.pendulum.small_angle_period();
        crate::analysis::sampling(interval, t0 / SAMPLES_PER_PERIOD, duration, force)
    }

    /// Whether the pendulum oscillates.
    pub fn oscillates(&self) -> bool {
        self.friction.damped.regime() == Regime::Underdamped
    }
}
