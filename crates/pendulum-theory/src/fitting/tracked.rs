//! The analysis of a tracked swing, as one call: angles at times in, the
//! closed form or the nonlinear equation fitted ([`super::trajectory`]),
//! g from a length, and what the fit cannot say as typed warnings. The
//! command line's `fit trajectory` and Python's `fit_trajectory` are this
//! call.

use super::crest::measured_crest;
use super::frames::{frame_grid, longest_run, FrameGrid};
use super::gyroscope::{principal_axis, PrincipalAxis};
pub use super::noise_of;
use super::rundown::{check_pairs, check_times};
use super::trajectory::{
    drag_key, fit_observed_with, searched_drag_laws, swing_of, Observed, TrajectoryFit,
    TrajectoryModel,
};
use super::ErrorParts;
use crate::analysis::{judge_work, require_finite, require_finite_samples, Refusal};
use crate::error::format_significant;
use crate::warning::Warn;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;

/// Computing time of a sample (nonlinear fit with its damping laws), s:
/// measured over the 200 generated records of `tests/all/coverage.rs`
/// (30 to 685,000 samples, two records at once on two cores): a median of
/// 170 µs a sample, so about 85 µs on a core of its own; 10% of the records
/// took more than 800 µs (short high-rate records of large swings, where
/// three damping laws are fitted), the worst 3.4 ms. (It was 20 µs,
/// measured on a 10° swing fitted with the viscous law alone.)
pub const SECONDS_PER_ROW: f64 = 100e-6;
/// Lengths a measured pendulum can have, m: from a 0.1 mm hair spring to
/// a 10 km shaft.
pub const LENGTH_RANGE_M: std::ops::RangeInclusive<f64> = 1e-4..=1e4;

/// A fitted g further than this from standard gravity (relative) is not a
/// pendulum's on Earth: 30%, beyond any place (9.78 to 9.83 m/s²) and any
/// fair measurement, well within what a unit mistaken makes of it.
pub const GRAVITY_TOLERANCE: f64 = 0.3;
/// A fitted g further than this from standard gravity (relative), and
/// beyond three of its standard errors, says the length is not the
/// pendulum's: 5%, beyond any place on Earth (0.5%) and a length measured
/// with a ruler.
pub const GRAVITY_CHECK: f64 = 0.05;
/// Residuals (rms) beyond this fraction of the record's largest swing mean
/// the model does not follow the record.
pub const RESIDUAL_OF_SWING: f64 = 0.25;

/// A swing whose angles, declared in degrees, never reach this many
/// degrees from the middle looks like one in radians.
pub const TINY_SWING_DEG: f64 = 1.0;

/// Standard errors apart beyond which the fitted curve's first crest is
/// said to miss the data's ([`TrackWarning::FirstCrestOff`]): 4, as the
/// measured crest's error, from a few samples, has wider tails than a
/// normal deviate's (2 of 400 fair records beyond 3σ, none beyond 4σ; see
/// [`super::crest`]).
pub const CREST_SIGMA: f64 = 4.0;
/// Samples each side of a crest it is measured from, at least.
pub const CREST_MIN_SIDE: usize = 3;

/// Of a gyroscope's rotation, the share about the swing's axis below
/// which the phone is turning about others too (twisting on its strings,
/// a conical swing): 0.9.
pub const GYROSCOPE_AXIS_SHARE: f64 = 0.9;

/// The band about the offset a zero crossing must cross, as a fraction of
/// the largest swing (so that noise at the centre counts no crossing).
pub const CROSSING_BAND: f64 = 0.1;

/// Where the length g is computed with came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LengthSource {
    /// Measured and given.
    Given,
    /// The equivalent length of a designed compound pendulum.
    Design,
    /// The radius of the arc the bob traced.
    TrackRadius,
}

/// A tracked swing to analyse.
#[derive(Clone, Debug, Default)]
pub struct TrackInput<'a> {
    /// Times, s, strictly increasing.
    pub time: &'a [f64],
    /// The angle at each time, rad.
    pub angle: &'a [f64],
    /// Or, with `angle` empty, the angular velocity at each time, rad/s: a
    /// gyroscope that swings with the pendulum (a phone's), one slice per
    /// sensor axis (one to three). The rotation about their principal axis
    /// ([`super::gyroscope::principal_axis`]) is fitted by the models'
    /// derivative, never integrated; the offset is the gyroscope's zero.
    pub angular_velocity: &'a [&'a [f64]],
    /// The model: linear or nonlinear; `None` chooses (`auto`, the
    /// default: nonlinear above a 5° swing). [`parse_model`] reads a name.
    pub model: Option<TrajectoryModel>,
    /// The drag law the nonlinear fit tries beside viscous damping and dry
    /// friction: a law of [`crate::forces::DRAG_LAWS`]
    /// ([`crate::simulation::analysis::parse_drag_law`] reads a name);
    /// `None` tries those the list searches (quadratic drag). A law named
    /// chooses the nonlinear model (and is refused beside the linear one).
    pub drag_law: Option<&'static dyn crate::forces::DragLaw>,
    /// The length g is computed with, m, and where it came from.
    pub length: Option<(f64, LengthSource)>,
    /// The length's standard uncertainty, m (measured with a tape, or a
    /// radius fitted to the track): carried into g's, which lists it as a
    /// part beside the fit's ([`Track::standard_error_parts`]).
    pub length_standard_error: Option<f64>,
    /// Runs estimated beyond [`crate::analysis::FORCE_SECONDS`] anyway.
    pub force: bool,
    /// The angles were computed from x and y positions, so no unit of
    /// theirs can be mistaken (no angle-unit hint for a g off).
    pub angle_from_positions: bool,
    /// The angles were read from a column declared in degrees (a header's
    /// unit, a flag): a swing that never reaches a degree is then said to
    /// look like radians.
    pub declared_degrees: bool,
}

/// What a person must know about a trajectory fit.
#[derive(Clone, Debug, PartialEq)]
pub enum TrackWarning {
    /// The nonlinear fit ran off and the linear one is reported (the
    /// note says why).
    NonlinearRejected(String),
    /// g is not reported from the linear model at this swing, rad.
    NoGravityFromLinear {
        /// The record's largest swing, rad.
        swing: f64,
    },
    /// The damping ratio's standard error exceeds it.
    ZetaUndetermined,
    /// Parameters of the motion's shape the data do not determine.
    ShapeUndetermined(Vec<&'static str>),
    /// g lies further than [`GRAVITY_TOLERANCE`] from standard gravity.
    GravityImplausible {
        /// The fitted g, m/s².
        g: f64,
        /// The likely cause, in words.
        likely: &'static str,
    },
    /// The fitted period is no pendulum's of [`LENGTH_RANGE_M`] (no length
    /// given to judge g by).
    PeriodImplausible {
        /// The small-angle period fitted, s.
        period: f64,
        /// The length it means at standard gravity, m.
        length: f64,
    },
    /// g is further from standard gravity than the data allow, and the
    /// angles read in the other unit would bring it close.
    AngleUnit {
        /// The fitted g, m/s².
        g: f64,
        /// g with the swing's size in the other unit, m/s².
        other: f64,
        /// `degrees` or `radians`: what the angles would then be.
        read_as: &'static str,
    },
    /// g lies further than [`GRAVITY_CHECK`] and three standard errors
    /// from standard gravity, and no unit explains it: the length.
    GravityOff {
        /// The fitted g, m/s².
        g: f64,
    },
    /// The residuals are a large part of the swing: a false minimum, or a
    /// record that is not this motion.
    PoorFit {
        /// Residual rms, rad (rad/s for angular velocities).
        rms: f64,
        /// The record's largest swing, rad (rad/s for angular velocities).
        swing: f64,
        /// Whether the record is of angular velocities.
        rate: bool,
    },
    /// The fitted curve's first crest is off the data's by more than
    /// [`CREST_SIGMA`] standard errors: the fitted motion does not follow
    /// the record's start, and its release amplitude (`amplitude_rad`) is
    /// not the record's swing.
    FirstCrestOff {
        /// The data's first crest, rad.
        measured: f64,
        /// Its standard error, rad.
        measured_error: f64,
        /// The fitted curve's, rad.
        fitted: f64,
        /// How many combined standard errors apart.
        sigmas: f64,
    },
    /// The record is in pieces: its longest run was fitted, the rest left
    /// out.
    SamplesLeftOut {
        /// The run fitted: its first and last times, s.
        kept: [f64; 2],
        /// Each run left out: first and last times, s, and samples.
        left: Vec<[f64; 3]>,
    },
    /// Angles declared in degrees whose swing never reaches a degree: they
    /// look like radians.
    AnglesLookLikeRadians {
        /// The largest swing about the middle, as read, rad.
        swing: f64,
        /// How much g (or the small-angle frequency squared) would change
        /// with the angles read as radians (relative).
        g_change: f64,
    },
    /// The fitted damping is negative beyond three standard errors: the
    /// swing grows (a driven or pushed pendulum), which a free decay does
    /// not.
    SwingGrows {
        /// The fitted ζ.
        zeta: f64,
        /// Its standard error.
        standard_error: f64,
    },
    /// A gyroscope's rotation is not about one axis: the fit follows the
    /// principal one.
    SeveralAxes {
        /// The share of the rotation's variance about the principal axis.
        share: f64,
    },
    /// The drag law named ([`TrackInput::drag_law`]) was tried and not
    /// kept: the record does not show it.
    DragLawNotKept {
        /// The law's name.
        law: &'static str,
    },
    /// The fitted curve crosses the centre a different number of times
    /// than the data do: its frequency is not the record's.
    CrossingsDiffer {
        /// Crossings in the data.
        data: usize,
        /// Crossings of the fitted curve.
        model: usize,
    },
}

impl crate::warning::Warn for TrackWarning {
    fn code(&self) -> &'static str {
        match self {
            TrackWarning::NonlinearRejected(_) => "nonlinear_rejected",
            TrackWarning::NoGravityFromLinear { .. } => "no_gravity_from_linear",
            TrackWarning::ZetaUndetermined => "zeta_undetermined",
            TrackWarning::SwingGrows { .. } => "swing_grows",
            TrackWarning::ShapeUndetermined(_) => "shape_undetermined",
            TrackWarning::GravityImplausible { .. } => "gravity_implausible",
            TrackWarning::PoorFit { .. } => "poor_fit",
            TrackWarning::PeriodImplausible { .. } => "period_implausible",
            TrackWarning::AngleUnit { .. } => "angle_unit",
            TrackWarning::GravityOff { .. } => "gravity_off",
            TrackWarning::CrossingsDiffer { .. } => "crossings_differ",
            TrackWarning::SeveralAxes { .. } => "several_axes",
            TrackWarning::FirstCrestOff { .. } => "first_crest_off",
            TrackWarning::SamplesLeftOut { .. } => "samples_left_out",
            TrackWarning::AnglesLookLikeRadians { .. } => "angles_look_like_radians",
            TrackWarning::DragLawNotKept { .. } => "drag_law_not_kept",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            TrackWarning::NonlinearRejected(_) => Some("model"),
            TrackWarning::ZetaUndetermined | TrackWarning::SwingGrows { .. } => Some("zeta"),
            TrackWarning::ShapeUndetermined(names) => names.first().copied(),
            TrackWarning::NoGravityFromLinear { .. }
            | TrackWarning::GravityImplausible { .. }
            | TrackWarning::AngleUnit { .. }
            | TrackWarning::GravityOff { .. }
            | TrackWarning::AnglesLookLikeRadians { .. } => Some("g_m_s2"),
            TrackWarning::PeriodImplausible { .. } | TrackWarning::CrossingsDiffer { .. } => {
                Some("omega_n_rad_s")
            }
            TrackWarning::PoorFit { rate: false, .. } => Some("residual_rms_rad"),
            TrackWarning::PoorFit { rate: true, .. } => Some("residual_rms_rad_s"),
            TrackWarning::FirstCrestOff { .. } => Some("amplitude_rad"),
            TrackWarning::SamplesLeftOut { .. } => Some("points"),
            TrackWarning::SeveralAxes { .. } => Some("gyroscope_axis_share"),
            TrackWarning::DragLawNotKept { .. } => Some("damping_law"),
        }
    }
}

impl fmt::Display for TrackWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TrackWarning::NonlinearRejected(note) => f.write_str(note),
            TrackWarning::DragLawNotKept { law } => write!(
                f,
                "the drag law {law} was tried and not kept: with it the fit was no better by \
                 the information criterion, its coefficient not determined, or its viscous \
                 part below 0 (the law standing in for a steeper one): the record does not \
                 show that law"
            ),
            TrackWarning::NoGravityFromLinear { swing } => write!(
                f,
                "g is not reported from the linear model at a {}° swing: its finite-amplitude \
                 correction leaves a bias beyond the standard error; fit the nonlinear model",
                format_significant(swing.to_degrees(), 3)
            ),
            TrackWarning::SwingGrows {
                zeta,
                standard_error,
            } => write!(
                f,
                "the swing grows (zeta = {} ± {}): the pendulum is driven or pushed, and the \
                 fit of a free decay does not describe it",
                format_significant(*zeta, 3),
                format_significant(*standard_error, 2)
            ),
            TrackWarning::ZetaUndetermined => f.write_str(
                "zeta not determined (its standard error exceeds it): the swing decays too \
                 little over this record to measure its damping and Q well (a longer record \
                 would tell)",
            ),
            TrackWarning::GravityImplausible { g, likely } => write!(
                f,
                "g = {} m/s² is no pendulum's on Earth (more than {}% from {} m/s²): {likely}",
                format_significant(*g, 4),
                format_significant(100.0 * GRAVITY_TOLERANCE, 2),
                crate::STANDARD_GRAVITY
            ),
            TrackWarning::PeriodImplausible { period, length } => write!(
                f,
                "a small-angle period of {} s is a pendulum of {} m at standard gravity, no \
                 pendulum one can film: {}",
                format_significant(*period, 4),
                format_significant(*length, 3),
                if *length > *LENGTH_RANGE_M.end() {
                    "the times look like milliseconds (or frame numbers) read as seconds; give \
                     the time column its unit"
                } else {
                    "the times look like seconds read as milliseconds; check the time column's \
                     unit"
                }
            ),
            TrackWarning::AngleUnit { g, other, read_as } => write!(
                f,
                "g = {} m/s² is off standard gravity by more than the data allow, and with the \
                 angles read as {read_as} it would be {} m/s²: check the angle column's unit \
                 (the swing's size sets the period's finite-amplitude correction)",
                format_significant(*g, 5),
                format_significant(*other, 5)
            ),
            TrackWarning::GravityOff { g } => write!(
                f,
                "g = {} m/s² is {}% from standard gravity, far beyond its standard error: the \
                 length is most likely not the pendulum's (measure from the pivot to the bob's \
                 centre; a bob that is not a point needs its equivalent length)",
                format_significant(*g, 5),
                format_significant(100.0 * (g / crate::STANDARD_GRAVITY - 1.0).abs(), 2)
            ),
            TrackWarning::PoorFit { rms, swing, rate } => write!(
                f,
                "the residuals (rms {}{}) are {}% of the largest swing ({}{}): the fitted curve \
                 does not follow the record (a false minimum on a long record of large swings, \
                 the wrong column, a record that is not one swinging pendulum); do not use its \
                 figures",
                format_significant(rms.to_degrees(), 3),
                degrees(*rate),
                format_significant(100.0 * rms / swing, 2),
                format_significant(swing.to_degrees(), 3),
                degrees(*rate)
            ),
            TrackWarning::FirstCrestOff {
                measured,
                measured_error,
                fitted,
                sigmas,
            } => write!(
                f,
                "the fitted curve's first crest ({}°) is {}% off the data's ({}° ± {}°, \
                 first_crest_amplitude_rad), {} standard errors: the fitted motion does not \
                 follow the record's start (a release by hand, a push; leave it out with --from), \
                 and amplitude_rad (its release amplitude) is not the record's swing",
                format_significant(fitted.to_degrees(), 4),
                format_significant(100.0 * (fitted - measured) / measured, 2),
                format_significant(measured.to_degrees(), 5),
                format_significant(measured_error.to_degrees(), 2),
                format_significant(*sigmas, 2)
            ),
            TrackWarning::SamplesLeftOut { kept, left } => {
                f.write_str(&super::frames::left_out_message(*kept, left))
            }
            TrackWarning::AnglesLookLikeRadians { swing, g_change } => write!(
                f,
                "the angles, read as degrees, never swing {}° from the middle (the largest \
                 swing {}°): if the column holds radians (a {}° swing), amplitude_rad, \
                 first_crest_amplitude_rad and offset_rad are 57.3 times too small, and g (and \
                 the small-angle omega) {} by {}% with the finite-amplitude correction; check \
                 the column's unit",
                format_significant(TINY_SWING_DEG, 2),
                format_significant(swing.to_degrees(), 3),
                format_significant(swing.to_degrees().to_degrees(), 3),
                if *g_change >= 0.0 { "rises" } else { "falls" },
                format_significant(100.0 * g_change.abs(), 2)
            ),
            TrackWarning::SeveralAxes { share } => write!(
                f,
                "only {}% of the gyroscope's rotation turns about one axis: the phone also \
                 twists on its strings or swings in a cone (a pendulum that does not swing in \
                 one plane); the fit follows the principal axis, and its damping and \
                 residuals carry the rest",
                format_significant(100.0 * share, 2)
            ),
            TrackWarning::CrossingsDiffer { data, model } => write!(
                f,
                "the fitted curve crosses the centre {model} times where the data cross it \
                 {data} times: its frequency is not the record's (a false minimum); do not use \
                 its figures"
            ),
            TrackWarning::ShapeUndetermined(names) => write!(
                f,
                "{} not determined by the data (standard error beyond the value): the record \
                 does not follow the model (no swing in it, a pendulum that friction stops, a \
                 record mostly at rest?); fit the swinging part only",
                names.join(", ")
            ),
        }
    }
}

/// The unit of an angle in degrees, or of a rate.
fn degrees(rate: bool) -> &'static str {
    if rate {
        "°/s"
    } else {
        "°"
    }
}

crate::warning::serialize_as_warning!(TrackWarning);

/// The analysis of a tracked swing.
#[derive(Clone, Debug, Serialize)]
pub struct Track {
    /// Points fitted.
    pub points: usize,
    /// `linear` or `nonlinear`: the model fitted.
    pub model: &'static str,
    /// The model asked for (`auto`, `linear` or `nonlinear`).
    pub model_requested: &'static str,
    /// The damping laws fitted: `viscous` (always for the linear model),
    /// or quadratic drag (`quadratic_drag_per_rad`) and dry friction
    /// (`friction_angle_rad`) beside it where the record shows them.
    pub damping_law: &'static str,
    /// Samples at the start where the bob was held before its release,
    /// left out of the fit (their residuals against the release angle).
    pub held_samples: usize,
    /// The fitted parameters by name (and `g_m_s2` with a length).
    pub parameters: BTreeMap<&'static str, f64>,
    /// Their standard errors.
    pub standard_errors: BTreeMap<&'static str, f64>,
    /// What was fitted: `angle`, or `angular_velocity` (a gyroscope's,
    /// by the models' derivative).
    pub observed: &'static str,
    /// A gyroscope's swing axis in its sensor axes (a unit vector), when
    /// angular velocities were given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gyroscope_axis: Option<Vec<f64>>,
    /// The share of the gyroscope's rotation (variance) about that axis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gyroscope_axis_share: Option<f64>,
    /// Root mean square of the residuals, rad (of angles).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual_rms_rad: Option<f64>,
    /// Root mean square of the residuals, rad/s (of angular velocities).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual_rms_rad_s: Option<f64>,
    /// The residuals' lag-one autocorrelation.
    pub residual_autocorrelation: f64,
    /// The factor every standard error was widened by for it,
    /// `√((1 + ρ)/(1 − ρ))` (1 for independent errors).
    pub standard_error_inflation: f64,
    /// The residual rms over the record's own sample-to-sample noise
    /// (from the residuals' fourth differences): above 1, a pattern the
    /// model leaves or tracking errors correlated from sample to sample,
    /// both already in the standard errors.
    pub residual_to_noise: Option<f64>,
    /// Q over the record ([`super::quality`]): from the energy the fitted
    /// motion loses per cycle between its first and last crests in the
    /// record, whatever its damping law; what `fit decay` reports for the
    /// same record. `None` when the loss is not measurable (then
    /// `q_factor_lower_bound`).
    pub q_factor: Option<f64>,
    /// Its standard error (the loss's, from the fit's covariance).
    pub q_factor_standard_error: Option<f64>,
    /// With no measurable loss over the record: Q's two-sigma lower bound.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_factor_lower_bound: Option<f64>,
    /// The viscous part's `Q = 1/(2ζ)`, when ζ is positive and determined:
    /// the pendulum's Q only when the damping law is `viscous`.
    pub q_viscous: Option<f64>,
    /// Its standard error, `σ_ζ / (2ζ²)` (first-order propagation).
    pub q_viscous_standard_error: Option<f64>,
    /// What the standard errors of figures derived from a measured input
    /// are made of (`g_m_s2`: the fit's part, and the length's, null when
    /// no uncertainty of the length was given).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub standard_error_parts: BTreeMap<&'static str, ErrorParts>,
    /// The length g is computed with, m.
    pub length_m: Option<f64>,
    /// Its standard uncertainty, m (given, or the fitted radius's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_standard_error_m: Option<f64>,
    /// Where it came from.
    pub length_source: Option<LengthSource>,
    /// What a person must know about these results.
    pub warnings: Vec<TrackWarning>,
    /// Their codes, in the same order (for programs).
    pub warning_codes: Vec<&'static str>,
    /// The parameters the data do not determine.
    #[serde(skip)]
    pub undetermined: Vec<&'static str>,
    /// The residuals, rad (rad/s of angular velocities), one per sample
    /// fitted.
    #[serde(skip)]
    pub residuals: Vec<f64>,
    /// The times fitted, s (rebuilt where they were written rounded): the
    /// samples from `first_row` on, one per residual.
    #[serde(skip)]
    pub time: Vec<f64>,
    /// The input's row the fitted samples start at (after a gap).
    #[serde(skip)]
    pub first_row: usize,
    /// Times written rounded, rebuilt on their frame grid
    /// ([`super::frames`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_rebuilt: Option<TimeRebuilt>,
}

/// Times written rounded and rebuilt on their frame grid: what was done.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TimeRebuilt {
    /// The frame interval found, s.
    pub frame_interval_s: f64,
    /// The quantum most times were written to, s.
    pub quantum_s: f64,
    /// The largest change from a time written to its rebuilt one, s.
    pub largest_change_s: f64,
    /// Rows whose written time repeated the row before's.
    pub repeated_times: usize,
}

impl From<&super::frames::FrameGrid> for TimeRebuilt {
    fn from(g: &super::frames::FrameGrid) -> Self {
        Self {
            frame_interval_s: g.interval,
            quantum_s: g.quantum,
            largest_change_s: g.largest_change,
            repeated_times: g.repeated,
        }
    }
}

/// A tracked record checked and cut to what is fitted: the angles, or a
/// gyroscope's rotation about its principal axis, at their times (rebuilt
/// on their frame grid where they were written rounded), the longest run
/// of them kept.
struct Record<'a> {
    /// The times given, s.
    input_time: &'a [f64],
    /// The angles given, rad (empty for a gyroscope's rates).
    input_angle: &'a [f64],
    /// A gyroscope's principal axis and the rotation about it, rad/s.
    principal: Option<PrincipalAxis>,
    /// The times rebuilt on their frame grid, where they were written
    /// rounded.
    grid: Option<FrameGrid>,
    /// The rows fitted: the record's longest run.
    kept: Range<usize>,
    /// Each run left out: first and last times, s, and samples.
    left_out: Vec<[f64; 3]>,
    /// What was measured: angles or angular velocities.
    observed: Observed,
    /// The swing, as an angle (a rate's over the record's frequency), rad.
    swing_angle: f64,
}

impl<'a> Record<'a> {
    /// The record of `input` checked (each refusal names its field): the
    /// values and their times paired, finite and increasing, the longest
    /// run kept, and a swing there that a pendulum can make.
    fn checked(input: &TrackInput<'a>) -> Result<Self, Refusal> {
        let principal = gyroscope_rotation(input)?;
        let (theta, observed, name) = match &principal {
            Some(p) => (
                p.rate.as_slice(),
                Observed::AngularVelocity,
                "angular_velocity",
            ),
            None => (input.angle, Observed::Angle, "angle"),
        };
        let rate = observed == Observed::AngularVelocity;
        check_pairs("time", name, input.time, theta)?;
        // Times written rounded (repeats among them) are rebuilt on their
        // frame grid before they are judged.
        require_finite_samples("time", input.time)?;
        let grid = frame_grid(input.time);
        let time = grid.as_ref().map_or(input.time, |g| g.time.as_slice());
        check_times("time", time)?;
        require_finite_samples(name, theta)?;
        // A record in pieces (a tracker that lost the bob, a logger paused):
        // its longest run is fitted, the rest left out and said.
        let (kept, others) = longest_run(time);
        let left_out: Vec<[f64; 3]> = others
            .iter()
            .map(|r| [time[r.start], time[r.end - 1], r.len() as f64])
            .collect();
        let (time, theta) = (&time[kept.clone()], &theta[kept.clone()]);
        refuse_still(theta, rate)?;
        // The swing, as an angle (a rate's over the record's frequency).
        let swing_angle = swing_of(time, theta, observed);
        refuse_half_turn(theta, swing_angle, rate)?;
        Ok(Record {
            input_time: input.time,
            input_angle: input.angle,
            principal,
            grid,
            kept,
            left_out,
            observed,
            swing_angle,
        })
    }

    /// The times fitted, s.
    fn time(&self) -> &[f64] {
        let time = self
            .grid
            .as_ref()
            .map_or(self.input_time, |g| g.time.as_slice());
        &time[self.kept.clone()]
    }

    /// The values fitted: angles, rad, or the angular velocities about the
    /// gyroscope's principal axis, rad/s.
    fn theta(&self) -> &[f64] {
        let theta = self
            .principal
            .as_ref()
            .map_or(self.input_angle, |p| p.rate.as_slice());
        &theta[self.kept.clone()]
    }

    /// Whether the values fitted are a gyroscope's angular velocities.
    fn rate(&self) -> bool {
        self.observed == Observed::AngularVelocity
    }

    /// The interval between the first two samples fitted, s (0 for one
    /// sample).
    fn interval(&self) -> f64 {
        let time = self.time();
        time.get(1).zip(time.first()).map_or(0.0, |(b, a)| b - a)
    }
}

/// A gyroscope's rotation about its principal axis, from the angular
/// velocities given (one to three axes, each paired with the times and
/// finite); `None` when angles are given instead. Refused when both are
/// given, or when the rates never change.
fn gyroscope_rotation(input: &TrackInput<'_>) -> Result<Option<PrincipalAxis>, Refusal> {
    let axes = input.angular_velocity;
    if !input.angle.is_empty() && !axes.is_empty() {
        return Err(Refusal::field(
            "angular_velocity",
            "give the angle or the angular velocity, not both",
        ));
    }
    if axes.len() > 3 {
        return Err(Refusal::field(
            "angular_velocity",
            format!("a gyroscope has at most three axes, got {}", axes.len()),
        ));
    }
    for axis in axes {
        check_pairs("time", "angular_velocity", input.time, axis)?;
        require_finite_samples("angular_velocity", axis)?;
    }
    if axes.is_empty() {
        return Ok(None);
    }
    Ok(Some(principal_axis(axes).ok_or_else(|| {
        Refusal::data(
            "the angular velocity never changes about any axis: there is no swing to fit; \
             is it the gyroscope of the swinging phone?",
        )
    })?))
}

/// Refuses values `theta` (angles, or angular velocities when `rate`)
/// that never change: there is no swing to fit.
fn refuse_still(theta: &[f64], rate: bool) -> Result<(), Refusal> {
    if let (Some(first), true) = (theta.first(), theta.len() > 1) {
        if theta.iter().all(|v| v == first) {
            return Err(Refusal::data(if rate {
                format!(
                    "the angular velocity never changes (every sample is {} rad/s): there is no \
                     swing to fit; is it the axis the pendulum swings about?",
                    format_significant(*first, 6)
                )
            } else {
                format!(
                    "the angle never changes (every sample is {} rad): there is no swing to fit; \
                     is it the pendulum's angle column?",
                    format_significant(*first, 6)
                )
            }));
        }
    }
    Ok(())
}

/// Refuses a swing of half a turn or more from the middle, which no
/// swinging pendulum makes: angular velocities (when `rate`) whose swing
/// as an angle is `swing_angle` rad, or angles `theta` about their median.
fn refuse_half_turn(theta: &[f64], swing_angle: f64, rate: bool) -> Result<(), Refusal> {
    if rate && swing_angle >= std::f64::consts::PI {
        return Err(Refusal::data(format!(
            "the angular velocity means a swing of {} rad ({}°) from the middle, more than the \
             half turn a swinging pendulum can: are the rates in degrees a second under a \
             radian's name?",
            format_significant(swing_angle, 4),
            format_significant(swing_angle.to_degrees(), 4)
        )));
    }
    // No swinging pendulum goes half a turn from its centre: angles that
    // do are in another unit (degrees under a radian's name) or not
    // angles at all.
    if theta.len() > 1 && !rate {
        let centre = super::median(&mut theta.to_vec());
        let swing = theta.iter().map(|v| (v - centre).abs()).fold(0.0, f64::max);
        if swing >= std::f64::consts::PI {
            return Err(Refusal::data(format!(
                "the angle goes {} rad ({}°) from its middle, more than the half turn a \
                 swinging pendulum can: are the angles in degrees under a radian's name (or not \
                 angles)?",
                format_significant(swing, 4),
                format_significant(swing.to_degrees(), 4)
            )));
        }
    }
    Ok(())
}

/// The model named `name`: `linear` or `nonlinear`, or `None` for `auto`
/// ([`DEFAULT_MODEL`]: nonlinear above a 5° swing); refused, naming the
/// field `model`, for any other name.
pub fn parse_model(name: &str) -> Result<Option<TrajectoryModel>, Refusal> {
    match name {
        "auto" => Ok(None),
        "linear" => Ok(Some(TrajectoryModel::Linear)),
        "nonlinear" => Ok(Some(TrajectoryModel::Nonlinear)),
        other => Err(Refusal::field(
            "model",
            format!("'{other}' is not one of auto, linear, nonlinear"),
        )),
    }
}

/// The drag law named `name` (one of [`crate::forces::DRAG_LAWS`]) for
/// [`TrackInput::drag_law`]; refused, naming the field `drag_law` and the
/// laws, for any other name.
pub fn parse_drag_law(name: &str) -> Result<Option<&'static dyn crate::forces::DragLaw>, Refusal> {
    crate::simulation::analysis::parse_drag_law(name)
        .map(Some)
        .map_err(|r| Refusal::field("drag_law", r.reason))
}

/// Checks the length g is computed with, m (positive, and a measured
/// one within [`LENGTH_RANGE_M`]), and its standard uncertainty, m
/// (given with the length, positive and smaller than it).
fn check_length(input: &TrackInput<'_>) -> Result<(), Refusal> {
    if let Some((l, source)) = input.length {
        require_finite("length", l)?;
        if !(l > 0.0 && l.is_finite()) {
            return Err(Refusal::field(
                "length",
                format!("must be positive, got {l} m"),
            ));
        }
        if source == LengthSource::Given && !LENGTH_RANGE_M.contains(&l) {
            return Err(Refusal::field(
                "length",
                format!(
                    "must lie between 0.1 mm and 10 km for a measured pendulum, got {} m",
                    format_significant(l, 6)
                ),
            ));
        }
    }
    if let Some(e) = input.length_standard_error {
        require_finite("length_standard_error", e)?;
        match input.length {
            None => {
                return Err(Refusal::field(
                    "length_standard_error",
                    "is the length's uncertainty: give the length too",
                ))
            }
            Some(_) if e <= 0.0 => {
                return Err(Refusal::field(
                    "length_standard_error",
                    format!("must be positive, got {e} m"),
                ))
            }
            Some((l, _)) if e >= l => {
                return Err(Refusal::field(
                    "length_standard_error",
                    format!(
                        "must be smaller than the length ({} m), got {} m",
                        format_significant(l, 6),
                        format_significant(e, 6)
                    ),
                ))
            }
            _ => {}
        }
    }
    Ok(())
}

/// Widens `fit`'s standard errors (its covariance, and the natural
/// angular frequency's error) by the AR(1) factor of its residuals after
/// the held samples ([`correlation_inflation`]): returns their lag-one
/// autocorrelation and the factor.
fn widen_for_correlation(fit: &mut TrajectoryFit) -> (f64, f64) {
    let (autocorrelation, inflation) =
        correlation_inflation(&fit.fit.residuals[fit.held_samples.min(fit.fit.residuals.len())..]);
    for se in &mut fit.fit.standard_errors {
        *se *= inflation;
    }
    for v in fit.fit.covariance.iter_mut().flatten() {
        *v *= inflation * inflation;
    }
    fit.natural_angular_frequency_error *= inflation;
    (autocorrelation, inflation)
}

/// The figures reported by name: the fitted parameters and those derived
/// from them (g, the first crest), their standard errors, and what the
/// standard errors of figures derived from a measured input are made of.
struct Figures {
    parameters: BTreeMap<&'static str, f64>,
    standard_errors: BTreeMap<&'static str, f64>,
    standard_error_parts: BTreeMap<&'static str, ErrorParts>,
}

impl Figures {
    /// The parameters of `fit` and their standard errors by name, the
    /// envelope amplitude as a magnitude.
    fn of(fit: &TrajectoryFit) -> Self {
        let names = fit.names();
        let mut parameters: BTreeMap<&'static str, f64> = names
            .iter()
            .zip(&fit.fit.parameters)
            .map(|(n, v)| (*n, *v))
            .collect();
        let standard_errors: BTreeMap<&'static str, f64> = names
            .iter()
            .zip(&fit.fit.standard_errors)
            .map(|(n, v)| (*n, *v))
            .collect();
        // The envelope amplitude is a magnitude; a negative one is the same
        // curve shifted by π.
        if let Some(a) = parameters.get_mut("amplitude_rad") {
            *a = a.abs();
        }
        Self {
            parameters,
            standard_errors,
            standard_error_parts: BTreeMap::new(),
        }
    }

    /// Sets the figure `name` to `value` with its standard error `se`.
    fn insert(&mut self, name: &'static str, value: f64, se: f64) {
        self.parameters.insert(name, value);
        self.standard_errors.insert(name, se);
    }
}

/// What a person must know about `fit` of `record`, in the order said:
/// the fit's own note, the samples left out, the angles' unit, g or the
/// period, the first crest, the gyroscope's axes, a swing that grows, the
/// parameters `undetermined`, and the fit against the record. Adds g and
/// the first crest to `figures`.
fn track_warnings(
    input: &TrackInput<'_>,
    record: &Record<'_>,
    fit: &TrajectoryFit,
    figures: &mut Figures,
    undetermined: &[&'static str],
) -> Vec<TrackWarning> {
    let time = record.time();
    let mut warnings: Vec<TrackWarning> = fit
        .fallback_note()
        .map(TrackWarning::NonlinearRejected)
        .into_iter()
        .collect();
    if !record.left_out.is_empty() {
        warnings.push(TrackWarning::SamplesLeftOut {
            kept: [time[0], time[time.len() - 1]],
            left: record.left_out.clone(),
        });
    }
    if let Some(law) = input.drag_law {
        if fit.model == TrajectoryModel::Nonlinear && fit.law.drag.is_none() {
            warnings.push(TrackWarning::DragLawNotKept { law: law.name() });
        }
    }
    warnings.extend(radians_hint(input, record));
    warnings.extend(gravity(input, record, fit, figures));
    warnings.extend(first_crest(record, fit, figures));
    // Without a length g cannot be judged; the period still can.
    if input.length.is_none() {
        warnings.extend(period_implausible(fit));
    }
    if let Some(p) = record
        .principal
        .as_ref()
        .filter(|p| p.share < GYROSCOPE_AXIS_SHARE)
    {
        warnings.push(TrackWarning::SeveralAxes { share: p.share });
    }
    warnings.extend(swing_grows(record, fit, figures));
    warnings.extend(undetermined_warnings(undetermined, &figures.parameters));
    warnings.extend(against_record(record, fit, &figures.parameters));
    warnings
}

/// Angles declared in degrees (not computed from positions) whose swing
/// never reaches [`TINY_SWING_DEG`]: a warning that they look like
/// radians, with how much g would change were they read so.
fn radians_hint(input: &TrackInput<'_>, record: &Record<'_>) -> Option<TrackWarning> {
    let swing_angle = record.swing_angle;
    (input.declared_degrees
        && !record.rate()
        && !input.angle_from_positions
        && swing_angle < TINY_SWING_DEG.to_radians())
    .then(|| {
        use crate::pendulum::Amplitude;
        use crate::period::period_ratio;
        let ratio = |a: f64| Amplitude::from_radians(a.min(3.1)).map_or(1.0, period_ratio);
        let other = swing_angle.to_degrees();
        TrackWarning::AnglesLookLikeRadians {
            swing: swing_angle,
            g_change: (ratio(other) / ratio(swing_angle)).powi(2) - 1.0,
        }
    })
}

/// g, m/s², from the length given and the fitted frequency, added to
/// `figures` with its standard error (the length's part beside the
/// fit's), and judged against standard gravity: a warning when it is no
/// pendulum's on Earth, an angle unit looks mistaken, or the length looks
/// wrong; or that the linear model gives no g at this swing. `None`
/// without a length.
fn gravity(
    input: &TrackInput<'_>,
    record: &Record<'_>,
    fit: &TrajectoryFit,
    figures: &mut Figures,
) -> Option<TrackWarning> {
    let (l, _) = input.length?;
    let (swing_angle, rate) = (record.swing_angle, record.rate());
    // The linear model's g carries a finite-amplitude bias larger than its
    // standard error above a few degrees (the correction takes the
    // amplitude at mid-record, but the swing decays through it).
    if !fit.model.gives_gravity_at(swing_angle) {
        return Some(TrackWarning::NoGravityFromLinear { swing: swing_angle });
    }
    let (g, se) = fit.gravity(l);
    // g = l ω²: the length's error adds in quadrature.
    let parts = ErrorParts::gravity(g, se, l, input.length_standard_error);
    let se = parts.total();
    figures.standard_error_parts.insert("g_m_s2", parts);
    figures.insert("g_m_s2", g, se);
    if let Some(likely) = implausible_gravity(g, input.length.map(|(_, s)| s)) {
        Some(TrackWarning::GravityImplausible { g, likely })
    } else if let Some(w) =
        // (Rates carry their unit, and one mistaken is a swing 57
        // times too large, refused above, or too small.)
        angle_unit_hint(g, se, swing_angle)
            .filter(|_| !input.angle_from_positions && !rate)
    {
        Some(w)
    } else if (g - crate::STANDARD_GRAVITY).abs()
        > (GRAVITY_CHECK * crate::STANDARD_GRAVITY).max(3.0 * se)
    {
        Some(TrackWarning::GravityOff { g })
    } else {
        None
    }
}

/// The first crest the record shows, beside the fitted amplitude (the
/// envelope's at the first sample, or the release's up to a period
/// before it): measured from the samples around it (angles; a
/// gyroscope's rate has no crest to see), the fitted curve's beside it.
/// Adds its time, s, and amplitude, rad, to `figures` (the fitted curve's
/// where none is measured); a warning when the two are more than
/// [`CREST_SIGMA`] standard errors apart.
fn first_crest(
    record: &Record<'_>,
    fit: &TrajectoryFit,
    figures: &mut Figures,
) -> Option<TrackWarning> {
    let (time, theta, rate) = (record.time(), record.theta(), record.rate());
    let held = fit.held_samples.min(time.len());
    let white = noise_of(&fit.fit.residuals[held..]).unwrap_or(0.0);
    let [crest_time, time_error, amplitude, error] = fit.first_crest(record.interval())?;
    let offset = figures.parameters.get("offset_rad").copied().unwrap_or(0.0);
    let offset_error = figures
        .standard_errors
        .get("offset_rad")
        .copied()
        .unwrap_or(0.0);
    let at = time[0] + crest_time;
    let curve: Vec<f64> = theta
        .iter()
        .zip(&fit.fit.residuals)
        .map(|(v, r)| v - r)
        .collect();
    let nearest = time[held..]
        .partition_point(|&t| t < at)
        .min(time.len() - held - 1)
        + held;
    let sign = if curve[nearest] >= offset { 1.0 } else { -1.0 };
    let quarter = 0.25 * std::f64::consts::TAU / fit.natural_angular_frequency.max(1e-300);
    let measured = (!rate)
        .then(|| {
            measured_crest(
                &time[held..],
                &theta[held..],
                &curve[held..],
                at,
                offset + sign * amplitude,
                0.5 * quarter,
                CREST_MIN_SIDE,
                white,
                sign,
            )
        })
        .flatten();
    let Some(c) = measured else {
        figures.insert("first_crest_time_s", crest_time, time_error);
        figures.insert("first_crest_amplitude_rad", amplitude, error);
        return None;
    };
    let value = sign * (c.value - offset);
    let value_se = c.value_standard_error.hypot(offset_error);
    figures.insert(
        "first_crest_time_s",
        c.time - time[0],
        c.time_standard_error,
    );
    figures.insert("first_crest_amplitude_rad", value, value_se);
    figures.insert("first_crest_fitted_amplitude_rad", amplitude, error);
    let apart = (value - amplitude).abs();
    let sigma = value_se.hypot(error);
    // (A record fitted exactly has no errors to judge by.)
    (sigma > 0.0 && (apart / sigma).is_finite() && apart > CREST_SIGMA * sigma).then_some(
        TrackWarning::FirstCrestOff {
            measured: value,
            measured_error: value_se,
            fitted: amplitude,
            sigmas: apart / sigma,
        },
    )
}

/// A warning when `fit`'s small-angle period is no pendulum's of
/// [`LENGTH_RANGE_M`] at standard gravity (the length it means, m,
/// beside it): what is judged when no length is given.
fn period_implausible(fit: &TrajectoryFit) -> Option<TrackWarning> {
    let w0 = fit.natural_angular_frequency;
    let length = crate::STANDARD_GRAVITY / (w0 * w0);
    (w0 > 0.0 && length.is_finite() && !LENGTH_RANGE_M.contains(&length)).then(|| {
        TrackWarning::PeriodImplausible {
            period: std::f64::consts::TAU / w0,
            length,
        }
    })
}

/// A swing that grows: a negative damping beyond its errors, or the
/// record's own last swings a fifth larger than its first (with a
/// negative ζ); `None` without a fitted ζ.
fn swing_grows(
    record: &Record<'_>,
    fit: &TrajectoryFit,
    figures: &Figures,
) -> Option<TrackWarning> {
    let (time, theta) = (record.time(), record.theta());
    let (Some(&zeta), Some(&se)) = (
        figures.parameters.get("zeta"),
        figures.standard_errors.get("zeta"),
    ) else {
        return None;
    };
    let turns = super::turning::turning_points(
        &time[fit.held_samples.min(time.len())..],
        &theta[fit.held_samples.min(theta.len())..],
    )
    .turns;
    let quarter = turns.len() / 4;
    let mean = |t: &[super::turning::Turn]| {
        t.iter().map(|t| t.amplitude).sum::<f64>() / t.len().max(1) as f64
    };
    let grows =
        quarter >= 2 && mean(&turns[turns.len() - quarter..]) > 1.2 * mean(&turns[..quarter]);
    (zeta < -3.0 * se || (grows && zeta < 0.0)).then_some(TrackWarning::SwingGrows {
        zeta,
        standard_error: se,
    })
}

/// The warnings of the parameters the data do not determine
/// (`undetermined`, of the fitted `parameters`): ζ where it is the whole
/// damping, and the parameters of the motion's shape.
fn undetermined_warnings(
    undetermined: &[&'static str],
    parameters: &BTreeMap<&'static str, f64>,
) -> Vec<TrackWarning> {
    let mut warnings = Vec::new();
    // An undetermined ζ is a warning where it is the whole damping (Q
    // then rests on it); beside drag or friction it is one part of a loss
    // that Q over the record measures, and its "not determined" stands
    // beside its value (a warning there fired on right answers: a 79°
    // release with Q 386 ± 2).
    let other_losses = (0..crate::forces::DRAG_LAWS.len())
        .map(drag_key)
        .chain(["friction_angle_rad"])
        .any(|k| parameters.contains_key(k));
    if undetermined.contains(&"zeta") && !other_losses {
        warnings.push(TrackWarning::ZetaUndetermined);
    }
    let shape: Vec<&'static str> = undetermined
        .iter()
        .copied()
        .filter(|n| *n != "zeta")
        .collect();
    if !shape.is_empty() {
        warnings.push(TrackWarning::ShapeUndetermined(shape));
    }
    warnings
}

/// The fit checks itself against the record: a warning when its
/// residuals are a large part ([`RESIDUAL_OF_SWING`]) of the swing about
/// the fitted offset, and one when its zero crossings are not the data's.
fn against_record(
    record: &Record<'_>,
    fit: &TrajectoryFit,
    parameters: &BTreeMap<&'static str, f64>,
) -> Vec<TrackWarning> {
    let theta = record.theta();
    let mut warnings = Vec::new();
    let offset = parameters
        .get("offset_rad")
        .or(parameters.get("rate_offset_rad_s"))
        .copied()
        .unwrap_or(0.0);
    let swing = theta.iter().map(|v| (v - offset).abs()).fold(0.0, f64::max);
    if fit.fit.residual_rms > RESIDUAL_OF_SWING * swing {
        warnings.push(TrackWarning::PoorFit {
            rms: fit.fit.residual_rms,
            swing,
            rate: record.rate(),
        });
    }
    warnings.extend(crossings_differ(theta, &fit.fit.residuals, offset, swing));
    warnings
}

/// A warning when the fitted curve (the values `theta` less their
/// `residuals`) crosses the `offset` more than two times more or fewer
/// than the data do, counted across a band of [`CROSSING_BAND`] of the
/// largest `swing`: its frequency is not the record's.
fn crossings_differ(
    theta: &[f64],
    residuals: &[f64],
    offset: f64,
    swing: f64,
) -> Option<TrackWarning> {
    // Counted over the span where both swing beyond the band: a curve
    // that decays by another law leaves the band earlier or later than
    // the data, with the same frequency.
    let band = CROSSING_BAND * swing;
    let data = crossing_indices(theta.iter().copied(), offset, band);
    let model = crossing_indices(
        theta.iter().zip(residuals).map(|(v, r)| v - r),
        offset,
        band,
    );
    // (A curve that never crosses is compared whole.)
    let end = match (data.last(), model.last()) {
        (Some(&a), Some(&b)) => a.min(b),
        _ => usize::MAX,
    };
    let data = data.iter().filter(|&&i| i <= end).count();
    let model = model.iter().filter(|&&i| i <= end).count();
    (data.abs_diff(model) > 2).then_some(TrackWarning::CrossingsDiffer { data, model })
}

/// The residual rms of `fit` over the record's own sample-to-sample noise
/// (from the residuals' fourth differences, at least the rounding's of
/// the values): `None` when it cannot be measured.
fn residual_over_noise(record: &Record<'_>, fit: &TrajectoryFit) -> Option<f64> {
    let held = fit.held_samples.min(record.time().len());
    // The residuals against the record's own sample-to-sample noise: a
    // pattern the model leaves, or tracking errors correlated from sample
    // to sample. The standard errors already carry both (the residuals'
    // variance scales them, as SciPy's curve_fit does, and their
    // correlation widens them by the AR(1) factor): said beside them, not
    // warned. (The residuals of angles read in steps are not in steps;
    // the steps' rounding is in them all the same.)
    noise_of(&fit.fit.residuals[held..])
        .map(|n| n.max(super::rounding_noise(record.theta())))
        .map(|n| fit.fit.residual_rms / n)
        .filter(|v| v.is_finite())
}

/// The viscous part's `Q = 1/(2ζ)` and its standard error `σ_ζ / (2ζ²)`,
/// when the fitted ζ is positive and not `undetermined`.
fn viscous_q(figures: &Figures, undetermined: &[&'static str]) -> (Option<f64>, Option<f64>) {
    let zeta = figures
        .parameters
        .get("zeta")
        .copied()
        .filter(|&z| z > 0.0 && !undetermined.contains(&"zeta"));
    let q_viscous = zeta.map(|z| 0.5 / z);
    let q_viscous_standard_error = zeta
        .and_then(|z| {
            figures
                .standard_errors
                .get("zeta")
                .map(|se| se / (2.0 * z * z))
        })
        .filter(|se| se.is_finite());
    (q_viscous, q_viscous_standard_error)
}

/// The model fitted when none is named: the nonlinear one past 5°.
pub const DEFAULT_MODEL: &str = "auto";

/// Analyses a tracked swing (see the module notes).
///
/// # Examples
///
/// ```
/// use pendulum_theory::fitting::tracked::{analyse, LengthSource, TrackInput};
///
/// // A 0.5 m pendulum (g = 9.81) released at 0.01 rad with ζ = 0.002, filmed
/// // at 50 frames a second: the seed's section 1-4 closed form.
/// let (w, z) = ((9.81_f64 / 0.5).sqrt(), 0.002_f64);
/// let wd = w * (1.0 - z * z).sqrt();
/// let time: Vec<f64> = (0..1000).map(|k| k as f64 / 50.0).collect();
/// let angle: Vec<f64> = time.iter()
///     .map(|&t| 0.01 * (-z * w * t).exp() * ((wd * t).cos() + z * w / wd * (wd * t).sin()))
///     .collect();
/// let length = Some((0.5, LengthSource::Given));
/// let fit = analyse(&TrackInput { time: &time, angle: &angle, length, ..Default::default() })?;
/// assert_eq!(fit.model, "linear"); // chosen below a 5° swing
/// assert!((fit.q_viscous.unwrap() - 1.0 / (2.0 * z)).abs() < 1e-6); // Q = 1/(2ζ)
/// assert!((fit.parameters["g_m_s2"] - 9.81).abs() < 1e-3);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn analyse(input: &TrackInput<'_>) -> Result<Track, Refusal> {
    let record = Record::checked(input)?;
    let requested = input.model.map_or(DEFAULT_MODEL, TrajectoryModel::name);
    check_length(input)?;
    let (time, theta, rate) = (record.time(), record.theta(), record.rate());
    judge_work(
        "time",
        format!("{} rows", time.len()),
        time.len() as f64 * SECONDS_PER_ROW,
        input.force,
    )?;
    // A drag law named is the nonlinear model's (the linear one has
    // viscous damping alone): it chooses that model, and is refused
    // beside the linear one.
    let model = match (input.model, input.drag_law) {
        (Some(TrajectoryModel::Linear), Some(law)) => {
            return Err(Refusal::field(
                "drag_law",
                format!(
                    "{} is a damping law of the nonlinear model, and the linear model has \
                     viscous damping alone: leave out one of them",
                    law.name()
                ),
            ))
        }
        (None, Some(_)) => TrajectoryModel::Nonlinear,
        (model, None) => model.unwrap_or_else(|| TrajectoryModel::auto_at(record.swing_angle)),
        (Some(model), Some(_)) => model,
    };
    let drag_laws = match input.drag_law {
        Some(law) => crate::forces::drag_law(law.name()).into_iter().collect(),
        None => searched_drag_laws(),
    };
    let mut fit = fit_observed_with(model, time, theta, record.observed, &drag_laws)
        .map_err(|e| Refusal::data(e.to_string()))?;
    // Errors correlated from sample to sample carry less information than
    // the fit assumed: every standard error is widened for it.
    let (autocorrelation, inflation) = widen_for_correlation(&mut fit);
    let mut figures = Figures::of(&fit);
    let undetermined = fit.undetermined();
    let warnings = track_warnings(input, &record, &fit, &mut figures, &undetermined);
    let residual_to_noise = residual_over_noise(&record, &fit);
    let (q_viscous, q_viscous_standard_error) = viscous_q(&figures, &undetermined);
    // Q over the record, from the fitted motion's energy loss.
    let held = fit.held_samples.min(time.len());
    let span = time.last().copied().unwrap_or(0.0) - time[held.min(time.len() - 1)];
    let q_record = fit.record_q(span, record.interval());
    let principal = record.principal.as_ref();
    Ok(Track {
        points: time.len(),
        q_factor: q_record.and_then(|q| q.q()).filter(|q| q.is_finite()),
        q_factor_standard_error: q_record.and_then(|q| q.q_standard_error()),
        q_factor_lower_bound: q_record.and_then(|q| q.lower_bound()),
        q_viscous,
        q_viscous_standard_error,
        model: fit.model.name(),
        model_requested: requested,
        damping_law: fit.law.name(),
        held_samples: fit.held_samples,
        parameters: figures.parameters,
        standard_errors: figures.standard_errors,
        observed: if rate { "angular_velocity" } else { "angle" },
        gyroscope_axis: principal.map(|p| p.direction.clone()),
        gyroscope_axis_share: principal.map(|p| p.share),
        residual_rms_rad: (!rate).then_some(fit.fit.residual_rms),
        residual_rms_rad_s: rate.then_some(fit.fit.residual_rms),
        residual_autocorrelation: autocorrelation,
        standard_error_inflation: inflation,
        residual_to_noise,
        standard_error_parts: figures.standard_error_parts,
        length_m: input.length.map(|(l, _)| l),
        length_standard_error_m: input
            .length
            .and(input.length_standard_error)
            .filter(|e| e.is_finite()),
        length_source: input.length.map(|(_, s)| s),
        warning_codes: warnings.iter().map(TrackWarning::code).collect(),
        warnings,
        undetermined,
        residuals: fit.fit.residuals,
        time: time.to_vec(),
        first_row: record.kept.start,
        time_rebuilt: record.grid.as_ref().map(TimeRebuilt::from),
    })
}

/// The likely cause of a g more than [`GRAVITY_TOLERANCE`] from standard
/// gravity, or `None` when it is within: g scales as `l/t²`, so a unit
/// mistaken shows as a power of ten (times in milliseconds read as
/// seconds: a million-fold smaller; a length in millimetres read as
/// metres: a thousand-fold larger), and a length taken from the arc's
/// radius is in the file's units (pixels, centimetres).
pub fn implausible_gravity(g: f64, source: Option<LengthSource>) -> Option<&'static str> {
    let ratio = g / crate::STANDARD_GRAVITY;
    if (ratio - 1.0).abs() <= GRAVITY_TOLERANCE {
        return None;
    }
    let near = |power: f64| (ratio.log10() - power).abs() < 0.5;
    Some(if near(-6.0) {
        "the times look like milliseconds read as seconds (g falls a million-fold); give the \
         time column its unit (time_ms)"
    } else if near(6.0) {
        "the times look like seconds read as milliseconds (g rises a million-fold); check the \
         time column's unit"
    } else if source == Some(LengthSource::TrackRadius) && ratio > 1.0 {
        "the length is the radius of the tracked arc, in the file's units: positions in pixels \
         or centimetres? give the length in metres, or the metres a unit of the file is \
         (--scale)"
    } else if near(3.0) {
        "the length looks like millimetres read as metres (g rises a thousand-fold); give it \
         with its unit (994mm)"
    } else if near(-3.0) {
        "the length looks like metres read as millimetres, or the times are off by a factor of \
         30; check the length's unit and the time column's"
    } else {
        "check the length, the time column's unit and that the column is the pendulum's angle"
    })
}

/// The largest lag-one autocorrelation of the residuals counted, so that
/// the widening stays finite (45 times).
pub const MAX_AUTOCORRELATION: f64 = 0.999;

/// The residuals' lag-one autocorrelation `ρ` (mean removed) and the
/// factor `√((1 + ρ)/(1 − ρ))` by which errors correlated from sample to
/// sample widen the standard errors of a least-squares fit that took them
/// as independent: the AR(1) variance inflation, the effective number of
/// independent points being `n(1 − ρ)/(1 + ρ)` (Bartlett 1946; von Storch
/// & Zwiers, *Statistical Analysis in Climate Research*, 1999, §17.1).
/// `ρ` is held within `[0, MAX_AUTOCORRELATION]`: independent or
/// alternating errors leave the errors as they are. Exact for the mean of
/// an AR(1) series; for the slowly varying parameters of a swing it is
/// the usual first-order correction (measured on the generated records:
/// 1 for white noise, to within 1/√n).
pub fn correlation_inflation(residuals: &[f64]) -> (f64, f64) {
    let n = residuals.len();
    if n < 3 {
        return (0.0, 1.0);
    }
    let mean = residuals.iter().sum::<f64>() / n as f64;
    let (mut c0, mut c1) = (0.0, 0.0);
    for i in 0..n {
        let d = residuals[i] - mean;
        c0 += d * d;
        if i + 1 < n {
            c1 += d * (residuals[i + 1] - mean);
        }
    }
    if c0.is_nan() || c0 <= 0.0 {
        return (0.0, 1.0);
    }
    let rho = (c1 / c0).clamp(0.0, MAX_AUTOCORRELATION);
    (c1 / c0, ((1.0 + rho) / (1.0 - rho)).sqrt())
}

/// Times `values` cross `centre`, each crossing from one side of the band
/// `centre ± band` to the other (noise within the band counts none).
pub fn crossings(values: impl Iterator<Item = f64>, centre: f64, band: f64) -> usize {
    crossing_indices(values, centre, band).len()
}

/// Where `values` cross `centre` as [`crossings`] counts them: the index
/// of the sample on the far side of each crossing.
pub fn crossing_indices(values: impl Iterator<Item = f64>, centre: f64, band: f64) -> Vec<usize> {
    let (mut side, mut out) = (0_i8, Vec::new());
    for (i, v) in values.enumerate() {
        let s = if v > centre + band {
            1
        } else if v < centre - band {
            -1
        } else {
            0
        };
        if s != 0 {
            if side != 0 && s != side {
                out.push(i);
            }
            side = s;
        }
    }
    out
}

/// A g (standard error `se`) from a record whose largest swing is `swing`
/// rad, judged for an angle unit mistaken: the swing's size sets the
/// finite-amplitude correction, `g ∝ (T(A)/T0)²` for the same observed
/// period, so angles in radians read as degrees (a swing 57 times too
/// small) lose the correction and degrees read as radians inflate it. A
/// hint when g is more than 2% and 3 standard errors from standard gravity
/// and the swing in the other unit brings it at least three times closer.
pub fn angle_unit_hint(g: f64, se: f64, swing: f64) -> Option<TrackWarning> {
    use crate::pendulum::Amplitude;
    use crate::period::period_ratio;
    let gn = crate::STANDARD_GRAVITY;
    let off = (g - gn).abs();
    if off <= (0.02 * gn).max(3.0 * se) {
        return None;
    }
    let ratio = |a: f64| Amplitude::from_radians(a).ok().map(period_ratio);
    let here = ratio(swing)?;
    [
        (swing.to_degrees(), "radians"),
        (swing.to_radians(), "degrees"),
    ]
    .into_iter()
    .filter(|(a, _)| *a < 3.0)
    .filter_map(|(a, read_as)| {
        let other = g * (ratio(a)? / here).powi(2);
        ((other - gn).abs() * 3.0 < off).then_some(TrackWarning::AngleUnit { g, other, read_as })
    })
    .next()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic AR(1) series `x_i = ρ x_{i-1} + e_i` (xorshift and
    /// Box-Muller), whose mean's standard error the independent formula
    /// understates by `√((1 + ρ)/(1 − ρ))`.
    fn ar1(rho: f64, n: usize, seed: u64) -> Vec<f64> {
        let mut e = crate::test_noise::Normals(seed);
        let mut x = 0.0;
        (0..n)
            .map(|_| {
                x = rho * x + e.next();
                x
            })
            .collect()
    }

    #[test]
    fn correlated_residuals_widen_the_errors_by_the_ar1_factor() {
        for rho in [0.0, 0.5, 0.9, 0.98] {
            let (r, f) = correlation_inflation(&ar1(rho, 200_000, 7));
            let expected = ((1.0 + rho) / (1.0 - rho)).sqrt();
            assert!((r - rho).abs() < 0.01, "ρ {rho}: {r}");
            assert!(
                (f / expected - 1.0).abs() < 0.05,
                "ρ {rho}: {f} vs {expected}"
            );
        }
        // Alternating errors are not counted as more information.
        let alternating: Vec<f64> = (0..100)
            .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        assert_eq!(correlation_inflation(&alternating).1, 1.0);
        // A smooth pattern is capped.
        let smooth: Vec<f64> = (0..10_000).map(|i| (i as f64 * 1e-4).sin()).collect();
        let f = correlation_inflation(&smooth).1;
        assert!((f - (1.999f64 / 0.001).sqrt()).abs() < 1e-9, "{f}");
    }

    /// The standard error of a mean of AR(1) data, measured over many
    /// series, is the independent one times the factor (the property the
    /// widening stands on).
    #[test]
    fn the_factor_matches_the_scatter_of_means() {
        let (rho, n, trials) = (0.8, 2000, 400);
        let means: Vec<f64> = (0..trials)
            .map(|k| ar1(rho, n, 1000 + k as u64).iter().sum::<f64>() / n as f64)
            .collect();
        let spread = (means.iter().map(|m| m * m).sum::<f64>() / trials as f64).sqrt();
        // Independent formula: σ_x / √n with σ_x² = 1/(1 − ρ²).
        let naive = (1.0 / (1.0 - rho * rho) / n as f64).sqrt();
        let ratio = spread / naive;
        let expected = ((1.0 + rho) / (1.0 - rho)).sqrt();
        // 400 trials: the spread's own error is 1/√800 = 3.5%.
        assert!(
            (ratio / expected - 1.0).abs() < 0.12,
            "{ratio} vs {expected}"
        );
    }
}
