//! The analysis of a tracked swing, as one call: angles at times in, the
//! closed form or the nonlinear equation fitted ([`super::trajectory`]),
//! g from a length, and what the fit cannot say as typed warnings. The
//! command line's `fit trajectory` and Python's `fit_trajectory` are this
//! call.

use super::rundown::{check_pairs, check_times};
use super::trajectory::{fit_trajectory, largest_swing, TrajectoryModel};
use crate::analysis::{judge_work, require_finite, require_finite_samples, Refusal};
use crate::error::format_significant;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt;

/// Computing time of a sample (nonlinear fit), s: measured, 2 million
/// samples of a 10° swing in 29 s.
pub const SECONDS_PER_ROW: f64 = 20e-6;
/// Lengths a measured pendulum can have, m: from a 0.1 mm hair spring to
/// a 10 km shaft.
pub const LENGTH_RANGE_M: std::ops::RangeInclusive<f64> = 1e-4..=1e4;

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
    /// `auto` (the default: nonlinear above a 5° swing), `linear` or
    /// `nonlinear`.
    pub model: Option<&'a str>,
    /// The length g is computed with, m, and where it came from.
    pub length: Option<(f64, LengthSource)>,
    /// Runs estimated beyond [`crate::analysis::FORCE_SECONDS`] anyway.
    pub force: bool,
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
}

impl fmt::Display for TrackWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TrackWarning::NonlinearRejected(note) => f.write_str(note),
            TrackWarning::NoGravityFromLinear { swing } => write!(
                f,
                "g is not reported from the linear model at a {}° swing: its finite-amplitude \
                 correction leaves a bias beyond the standard error; fit the nonlinear model",
                format_significant(swing.to_degrees(), 3)
            ),
            TrackWarning::ZetaUndetermined => f.write_str(
                "zeta not determined (its standard error exceeds it): the swing decays too \
                 little over the record to measure the damping; a longer record will",
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

impl Serialize for TrackWarning {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// The analysis of a tracked swing.
#[derive(Clone, Debug, Serialize)]
pub struct Track {
    /// Points fitted.
    pub points: usize,
    /// `linear` or `nonlinear`: the model fitted.
    pub model: &'static str,
    /// The model asked for (`auto`, `linear` or `nonlinear`).
    pub model_requested: &'static str,
    /// The fitted parameters by name (and `g_m_s2` with a length).
    pub parameters: BTreeMap<&'static str, f64>,
    /// Their standard errors.
    pub standard_errors: BTreeMap<&'static str, f64>,
    /// Root mean square of the residuals, rad.
    pub residual_rms_rad: f64,
    /// The length g is computed with, m.
    pub length_m: Option<f64>,
    /// Where it came from.
    pub length_source: Option<LengthSource>,
    /// What a person must know about these results.
    pub warnings: Vec<TrackWarning>,
    /// The parameters the data do not determine.
    #[serde(skip)]
    pub undetermined: Vec<&'static str>,
    /// The residuals, rad, one per sample.
    #[serde(skip)]
    pub residuals: Vec<f64>,
}

/// The model fitted when none is named: the nonlinear one past 5°.
pub const DEFAULT_MODEL: &str = "auto";

/// Analyses a tracked swing (see the module notes).
pub fn analyse(input: &TrackInput<'_>) -> Result<Track, Refusal> {
    let (time, theta) = (input.time, input.angle);
    check_pairs("time", "angle", time, theta)?;
    check_times("time", time)?;
    require_finite_samples("angle", theta)?;
    let requested = match input.model.unwrap_or(DEFAULT_MODEL) {
        "auto" => "auto",
        "linear" => "linear",
        "nonlinear" => "nonlinear",
        other => {
            return Err(Refusal::field(
                "model",
                format!("'{other}' is not one of auto, linear, nonlinear"),
            ))
        }
    };
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
    judge_work(
        "time",
        format!("{} rows", time.len()),
        time.len() as f64 * SECONDS_PER_ROW,
        input.force,
    )?;
    let model = match requested {
        "linear" => TrajectoryModel::Linear,
        "nonlinear" => TrajectoryModel::Nonlinear,
        _ => TrajectoryModel::auto(theta),
    };
    let fit = fit_trajectory(model, time, theta).map_err(|e| Refusal::data(e.to_string()))?;
    let names = fit.names();
    let mut parameters: BTreeMap<&'static str, f64> = names
        .iter()
        .zip(&fit.fit.parameters)
        .map(|(n, v)| (*n, *v))
        .collect();
    let mut standard_errors: BTreeMap<&'static str, f64> = names
        .iter()
        .zip(&fit.fit.standard_errors)
        .map(|(n, v)| (*n, *v))
        .collect();
    // The envelope amplitude is a magnitude; a negative one is the same
    // curve shifted by π.
    if let Some(a) = parameters.get_mut("amplitude_rad") {
        *a = a.abs();
    }
    let mut warnings: Vec<TrackWarning> = fit
        .fallback_note()
        .map(TrackWarning::NonlinearRejected)
        .into_iter()
        .collect();
    // The linear model's g carries a finite-amplitude bias larger than its
    // standard error above a few degrees (the correction takes the
    // amplitude at mid-record, but the swing decays through it).
    if let Some((l, _)) = input.length {
        if fit.model.gives_gravity(theta) {
            let (g, se) = fit.gravity(l);
            parameters.insert("g_m_s2", g);
            standard_errors.insert("g_m_s2", se);
        } else {
            warnings.push(TrackWarning::NoGravityFromLinear {
                swing: largest_swing(theta),
            });
        }
    }
    let undetermined = fit.undetermined();
    if undetermined.contains(&"zeta") {
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
    Ok(Track {
        points: time.len(),
        model: match fit.model {
            TrajectoryModel::Linear => "linear",
            TrajectoryModel::Nonlinear => "nonlinear",
        },
        model_requested: requested,
        parameters,
        standard_errors,
        residual_rms_rad: fit.fit.residual_rms,
        length_m: input.length.map(|(l, _)| l),
        length_source: input.length.map(|(_, s)| s),
        warnings,
        undetermined,
        residuals: fit.fit.residuals,
    })
}
