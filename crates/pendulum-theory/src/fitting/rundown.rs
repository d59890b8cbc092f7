//! The analysis of a run-down, as one call: amplitudes at times in, every
//! decay law of [`super::decay`] fitted (or the one asked for), the law
//! the data prefer, and with the pendulum and its bob the energy each law
//! says is lost. The command line's `fit decay` and Python's `fit_decay`
//! are this call.

use super::decay::{
    akaike_weights, effective_angular_frequency, fit_decay, half_swing_loss, preferred, DecayFit,
    DecayModel,
};
use super::FitError;
use crate::analysis::{
    finite, judge_work, require_finite, require_finite_sample, require_finite_samples, Refusal,
};
use crate::energy::energy_budget;
use crate::pendulum::{Amplitude, Pendulum, STANDARD_GRAVITY};
use serde::Serialize;
use std::collections::BTreeMap;

/// Computing time a row of amplitudes takes (all six laws), s: measured,
/// 2 million rows in 41 s.
pub const SECONDS_PER_ROW: f64 = 25e-6;
/// The periods a pendulum can have, s: from a 1 cm pendulum (0.2 s) to
/// Foucault's 67 m (16 s), with room.
pub const PERIOD_RANGE_S: std::ops::RangeInclusive<f64> = 1e-3..=1e4;

/// A run-down to analyse. Every field but the data is optional.
#[derive(Clone, Debug, Default)]
pub struct RunDownInput<'a> {
    /// Times, s, strictly increasing.
    pub time: &'a [f64],
    /// The amplitude at each time, rad, in (0, π).
    pub amplitude: &'a [f64],
    /// One law, or `None` for every law (`all`, the default).
    /// [`parse_model`] reads a name.
    pub model: Option<DecayModel>,
    /// The pendulum's period, s: its angular frequency turns the rates
    /// into ζ, Q, the friction angle and the drag.
    pub period: Option<f64>,
    /// The mean half period between the turning points the amplitudes
    /// came from, s (when they came from a track): used when no period is
    /// given.
    pub turning_half_period: Option<f64>,
    /// The half swing each row ends, counted from the first, when the
    /// amplitudes are a track's turning points
    /// ([`super::turning::Turns::half_swings`]): with it the half period
    /// (and its standard error) is the slope of the rows' times against
    /// it, in place of `turning_half_period`, and with `length` the
    /// turning times give g.
    pub turning_count: Option<&'a [f64]>,
    /// The pendulum's length, m: ω from the exact period at the record's
    /// median amplitude, when neither of the above is given; with `mass`,
    /// the energy each law says is lost; with `turning_count`, g.
    pub length: Option<f64>,
    /// The length's standard uncertainty, m: in g's standard error.
    pub length_standard_error: Option<f64>,
    /// Gravity, m/s² (default standard gravity).
    pub g: Option<f64>,
    /// The bob's mass, kg (needs the length).
    pub mass: Option<f64>,
    /// The amplitudes were read from a column declared in degrees (a
    /// header's unit or a flag): amplitudes that never reach a degree are
    /// then said to look like radians.
    pub declared_degrees: bool,
    /// Runs estimated beyond [`crate::analysis::FORCE_SECONDS`] anyway.
    pub force: bool,
}

/// The analysis of a run-down.
#[derive(Clone, Debug, Serialize)]
pub struct RunDown {
    /// Points fitted.
    pub points: usize,
    /// The angular frequency the rates are converted with, rad/s.
    pub omega_rad_s: Option<f64>,
    /// Where ω came from: `period`, `turning_points` or `length`.
    pub omega_source: Option<&'static str>,
    /// Every law asked for, fitted or failed, simplest first.
    pub models: Vec<LawFit>,
    /// The law the data prefer (lowest BIC with no rate at its bound).
    pub preferred: Option<&'static str>,
    /// The preferred law's Akaike weight among the laws fitted.
    pub preferred_akaike_weight: Option<f64>,
    /// The next best law (no rate at its bound) and how much higher its
    /// BIC is: under 2 the data hardly choose between them, over 10 they
    /// choose clearly (Kass & Raftery 1995).
    pub runner_up: Option<RunnerUp>,
    /// g from the turning points' times and the length (a track's
    /// amplitudes and `length`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gravity: Option<TurnGravity>,
    /// What the reader must know of these figures.
    pub warnings: Vec<RunDownWarning>,
    /// The fits themselves (residuals, for plots).
    #[serde(skip)]
    pub fits: Vec<DecayFit>,
}

/// g from the times of a track's turning points: each half swing takes
/// `T0 F(Ā)/2` at the mean amplitude `Ā` of the two turns that bound it
/// (`F` the exact period ratio, [`crate::period::period_ratio`]), so the
/// turning times are a straight line in `Σ F(Ā)` whose slope is `T0/2`
/// (least squares, its standard error from the times' scatter); `g = l
/// (2π/T0)² / (1 − ζ²)` with `ζ = 1/(2Q)` of the preferred law's Q over
/// the record (the damped period is the longer by `1/√(1 − ζ²)`).
#[derive(Clone, Debug, Serialize)]
pub struct TurnGravity {
    /// g, m/s².
    pub g_m_s2: f64,
    /// Its standard error, m/s²: the parts below in quadrature.
    pub standard_error_m_s2: f64,
    /// The parts of the standard error: the turning times' (`fit`) and
    /// the length's (`length`, null when no uncertainty was given: the
    /// standard error leaves it out).
    pub standard_error_parts: super::ErrorParts,
    /// The small-angle period the turning times give, s.
    pub small_angle_period_s: f64,
    /// Its standard error, s.
    pub small_angle_period_standard_error_s: f64,
    /// The length, m.
    pub length_m: f64,
    /// Its standard uncertainty, m, as given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_standard_error_m: Option<f64>,
}

/// What a run-down's figures carry that the reader must know.
#[derive(Clone, Debug, PartialEq)]
pub enum RunDownWarning {
    /// Amplitudes declared in degrees that never reach a degree: they look
    /// like radians, and the figures that depend on the swing's size are
    /// then wrong by 57 times.
    SwingTiny {
        /// The largest amplitude, rad.
        largest: f64,
    },
    /// The track the amplitudes came from is in pieces: the turning
    /// points of its longest run were fitted, the rest left out.
    SamplesLeftOut {
        /// The run fitted: its first and last times, s.
        kept: [f64; 2],
        /// Each run left out: first and last times, s, and samples.
        left: Vec<[f64; 3]>,
    },
}

impl crate::warning::Warn for RunDownWarning {
    fn code(&self) -> &'static str {
        match self {
            RunDownWarning::SwingTiny { .. } => "angles_look_like_radians",
            RunDownWarning::SamplesLeftOut { .. } => "samples_left_out",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            RunDownWarning::SwingTiny { .. } => Some("amplitude0_rad"),
            RunDownWarning::SamplesLeftOut { .. } => Some("points"),
        }
    }
}

impl std::fmt::Display for RunDownWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RunDownWarning::SamplesLeftOut { kept, left } => {
                f.write_str(&super::frames::left_out_message(*kept, left))
            }
            RunDownWarning::SwingTiny { largest } => write!(
                f,
                "the amplitudes, read as degrees, never reach {}°: if the column holds radians \
                 (a swing of {}°), amplitude0_rad is {} times too small, the drag \
                 (quadratic_drag_per_rad) {} times too large, and Q is right; check the column's \
                 unit",
                crate::error::format_significant(largest.to_degrees(), 3),
                crate::error::format_significant(largest.to_degrees().to_degrees(), 3),
                crate::error::format_significant(180.0 / std::f64::consts::PI, 4),
                crate::error::format_significant(180.0 / std::f64::consts::PI, 4)
            ),
        }
    }
}

crate::warning::serialize_as_warning!(RunDownWarning);

/// The law next to the preferred one.
#[derive(Clone, Debug, Serialize)]
pub struct RunnerUp {
    /// Its name.
    pub model: &'static str,
    /// Its BIC less the preferred law's.
    pub delta_bic: f64,
}

/// One law's fit, or why it failed.
#[derive(Clone, Debug, Serialize)]
pub struct LawFit {
    /// The law's name.
    pub model: &'static str,
    /// Why the law could not be fitted (then no other key).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub failed: Option<String>,
    /// The fit.
    #[serde(flatten)]
    pub fitted: Option<Fitted>,
}

/// The figures of one fitted law.
#[derive(Clone, Debug, Serialize)]
pub struct Fitted {
    /// The fitted parameters by name.
    pub parameters: BTreeMap<&'static str, f64>,
    /// Their standard errors.
    pub standard_errors: BTreeMap<&'static str, f64>,
    /// Q over the record ([`crate::fitting::quality`]): from the energy
    /// the law loses per cycle between the record's first and last
    /// amplitudes; what `fit trajectory` reports for the same record.
    pub q_factor: Option<f64>,
    /// Its standard error (the loss's, from the fit's covariance and the
    /// turning points' ω).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_factor_standard_error: Option<f64>,
    /// With no measurable loss over the record: the two-sigma lower bound
    /// on Q.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_factor_lower_bound: Option<f64>,
    /// The viscous part's Q, `1/(2ζ)`, when measurable: the pendulum's Q
    /// only when the law is viscous alone.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_viscous: Option<f64>,
    /// Its standard error, `Q σ_ζ / ζ`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_viscous_standard_error: Option<f64>,
    /// With no measurable viscous part: the two-sigma lower bound on its Q.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q_viscous_lower_bound: Option<f64>,
    /// Rates held at their bound 0 (the law is then a simpler one).
    pub at_bound: Vec<&'static str>,
    /// Root mean square of the residuals, rad.
    pub residual_rms: f64,
    /// Akaike's information criterion.
    pub aic: f64,
    /// The Bayesian information criterion.
    pub bic: f64,
    /// The law's Akaike weight among the laws fitted.
    pub akaike_weight: f64,
    /// Energy lost per period at the first amplitude, J (length and mass).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_loss_per_period_j: Option<f64>,
    /// Power lost at the first amplitude, W (length and mass).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub power_w: Option<f64>,
}

/// The model fitted when none is named: every law, compared.
pub const DEFAULT_MODEL: &str = "all";

/// The law named `name` ([`DecayModel::from_name`]), or `None` for
/// [`DEFAULT_MODEL`] (every law); refused, naming the field `model` and
/// the names, for any other.
pub fn parse_model(name: &str) -> Result<Option<DecayModel>, Refusal> {
    if name == DEFAULT_MODEL {
        return Ok(None);
    }
    DecayModel::from_name(name)
        .map(Some)
        .ok_or_else(|| Refusal::field("model", format!("'{name}' is not one of {}", model_names())))
}

/// The law names [`parse_model`] takes, `all` last, comma-separated.
pub fn model_names() -> String {
    let mut names: Vec<&str> = DecayModel::every().iter().map(|m| m.name()).collect();
    names.push(DEFAULT_MODEL);
    names.join(", ")
}

/// Checks a series of times: finite and strictly increasing.
pub(crate) fn check_times(field: &'static str, time: &[f64]) -> Result<(), Refusal> {
    require_finite_samples(field, time)?;
    match (1..time.len()).find(|&i| time[i] <= time[i - 1]) {
        Some(i) => Err(Refusal::sample(
            field,
            i,
            format!(
                "{} is not after the previous {}; sort by time",
                time[i],
                time[i - 1]
            ),
        )),
        None => Ok(()),
    }
}

/// Checks two arrays given as pairs.
pub(crate) fn check_pairs(
    first: &'static str,
    second: &'static str,
    a: &[f64],
    b: &[f64],
) -> Result<(), Refusal> {
    if a.len() == b.len() {
        Ok(())
    } else {
        Err(Refusal::field(
            second,
            format!(
                "has {} values and {first} {}: give one of each",
                b.len(),
                a.len()
            ),
        ))
    }
}

/// The pendulum of a length and g (default standard gravity).
pub(crate) fn pendulum_of(length: f64, g: Option<f64>) -> Result<Pendulum, Refusal> {
    let g = g.unwrap_or(STANDARD_GRAVITY);
    Pendulum::new(length, g).map_err(|e| match e.quantity {
        crate::Quantity::Gravity => Refusal::input("g", &e),
        _ => Refusal::input("length", &e),
    })
}

/// The run-down's inputs checked (each refusal names its field and row)
/// and the work judged: the laws to fit, the pendulum (given its
/// length) and the bob's mass.
fn validated(input: &RunDownInput<'_>) -> Result<Checked, Refusal> {
    let (time, amplitude) = (input.time, input.amplitude);
    check_pairs("time", "amplitude", time, amplitude)?;
    check_times("time", time)?;
    for (i, &a) in amplitude.iter().enumerate() {
        require_finite_sample("amplitude", i, a)?;
        if a <= 0.0 {
            return Err(Refusal::sample(
                "amplitude",
                i,
                format!("must be positive, got {a}"),
            ));
        }
        if a >= std::f64::consts::PI {
            return Err(Refusal::sample(
                "amplitude",
                i,
                format!(
                    "an amplitude of {}° is not a swing (it must be below 180°)",
                    crate::error::format_significant(a.to_degrees(), 8)
                ),
            ));
        }
    }
    let models: Vec<DecayModel> = match input.model {
        None => DecayModel::searched(),
        Some(model) => vec![model],
    };
    if let Some(p) = input.period {
        require_finite("period", p)?;
        if !PERIOD_RANGE_S.contains(&p) {
            return Err(Refusal::field(
                "period",
                format!(
                    "must lie between 1 ms and 10^4 s for a pendulum, got {} s",
                    crate::error::format_significant(p, 6)
                ),
            ));
        }
    }
    if let Some(h) = input.turning_half_period {
        if !(h > 0.0 && h.is_finite()) {
            return Err(Refusal::data(format!(
                "the turning points' half period must be positive, got {h} s"
            )));
        }
    }
    let pendulum = input.length.map(|l| pendulum_of(l, input.g)).transpose()?;
    if let Some(e) = input.length_standard_error {
        require_finite("length_standard_error", e)?;
        if e <= 0.0 {
            return Err(Refusal::field(
                "length_standard_error",
                format!("must be positive, got {e} m"),
            ));
        }
        match input.length {
            None => {
                return Err(Refusal::field(
                    "length_standard_error",
                    "is the length's uncertainty: give the length too",
                ))
            }
            Some(l) if e >= l => {
                return Err(Refusal::field(
                    "length_standard_error",
                    format!(
                        "must be smaller than the length ({} m), got {} m",
                        crate::error::format_significant(l, 6),
                        crate::error::format_significant(e, 6)
                    ),
                ))
            }
            _ => {}
        }
    }
    // It goes in g, which only a track's turning times give.
    if input.length_standard_error.is_some() && input.turning_count.is_none() {
        return Err(Refusal::field(
            "length_standard_error",
            "goes in g, which amplitudes without their turning points' count do not give",
        ));
    }
    if let Some(c) = input.turning_count {
        check_pairs("time", "turning_count", time, c)?;
        require_finite_samples("turning_count", c)?;
    }
    if input.length.is_none() {
        if let Some(g) = input.g {
            pendulum_of(1.0, Some(g))?;
        }
    }
    if let Some(m) = input.mass {
        require_finite("mass", m)?;
    }
    let mass = match (input.mass, &pendulum) {
        (Some(m), None) => {
            return Err(Refusal::field(
                "mass",
                format!(
                    "{} kg given without the length: the energy budget needs the pendulum",
                    crate::error::significant(m)
                ),
            ))
        }
        (Some(m), Some(_)) if m <= 0.0 => {
            return Err(Refusal::field(
                "mass",
                format!("must be positive, got {m} kg"),
            ))
        }
        (m, _) => m,
    };
    let rows = amplitude.len();
    judge_work(
        "time",
        format!("{rows} rows"),
        rows as f64 * SECONDS_PER_ROW,
        input.force,
    )?;
    Ok(Checked {
        models,
        pendulum,
        mass,
    })
}

/// What [`validated`] gives: the laws to fit, the pendulum (given its
/// length) and the bob's mass, kg.
struct Checked {
    models: Vec<DecayModel>,
    pendulum: Option<Pendulum>,
    mass: Option<f64>,
}

/// The turning points' half period (s) and its standard error: the slope
/// of their times against their half-swing count (three at least), else
/// the half period given with none.
fn turning_half_period(input: &RunDownInput<'_>) -> Option<(f64, f64)> {
    let time = input.time;
    match input.turning_count {
        Some(count) if count.len() >= 3 => {
            let (a, b) = super::straight_line(count, time);
            let mean = count.iter().sum::<f64>() / count.len() as f64;
            let sxx: f64 = count.iter().map(|x| (x - mean).powi(2)).sum();
            let rss: f64 = count
                .iter()
                .zip(time)
                .map(|(x, y)| (y - a - b * x).powi(2))
                .sum();
            let se = (rss / (count.len() - 2) as f64 / sxx).sqrt();
            (b > 0.0 && b.is_finite()).then_some((b, if se.is_finite() { se } else { 0.0 }))
        }
        _ => input.turning_half_period.map(|h| (h, 0.0)),
    }
}

/// Analyses a run-down (see the module notes).
///
/// # Examples
///
/// ```
/// use pendulum_theory::fitting::rundown::{analyse, RunDownInput};
///
/// // A 2 s pendulum of Q = 500 read every 10 s: A = 0.1 e^(-ζωt), ζ = 1/(2Q).
/// let (zeta, omega) = (1.0 / 1000.0, std::f64::consts::PI);
/// let time: Vec<f64> = (0..60).map(|k| 10.0 * k as f64).collect();
/// let amplitude: Vec<f64> = time.iter().map(|t| 0.1 * (-zeta * omega * t).exp()).collect();
/// let fit = analyse(&RunDownInput {
///     time: &time,
///     amplitude: &amplitude,
///     period: Some(2.0),
///     ..Default::default()
/// })?;
/// assert_eq!(fit.preferred, Some("viscous"));
/// let viscous = fit.models[0].fitted.as_ref().unwrap();
/// assert!((viscous.q_viscous.unwrap() - 500.0).abs() < 1e-6);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn analyse(input: &RunDownInput<'_>) -> Result<RunDown, Refusal> {
    let (time, amplitude) = (input.time, input.amplitude);
    let Checked {
        models,
        pendulum,
        mass,
    } = validated(input)?;
    let turning = turning_half_period(input);
    let (omega, omega_source) = match (input.period, turning, &pendulum) {
        (Some(p), _, _) => (Some(std::f64::consts::TAU / p), Some("period")),
        (None, Some((h, _)), _) => (Some(std::f64::consts::PI / h), Some("turning_points")),
        (None, None, Some(p)) => (
            Some(effective_angular_frequency(p, amplitude)),
            Some("length"),
        ),
        (None, None, None) => (None, None),
    };
    // Every law is listed: fitted, or failed with the reason.
    let mut fits = Vec::new();
    let mut failures: Vec<(DecayModel, FitError)> = Vec::new();
    // ω from the turning points carries their half period's error into
    // every Q.
    let omega_error = match (omega_source, turning) {
        (Some("turning_points"), Some((h, se))) => se / h,
        _ => 0.0,
    };
    for &model in &models {
        match fit_decay(model, time, amplitude, omega) {
            Ok(mut fit) => {
                fit.record_q = fit.record_q.map(|q| q.with_omega_error(omega_error));
                fits.push(fit)
            }
            Err(e) => failures.push((model, e)),
        }
    }
    if fits.is_empty() {
        let e = failures
            .into_iter()
            .next()
            .map_or(FitError::Singular, |(_, e)| e);
        return Err(Refusal::data(e.to_string()));
    }
    let best = preferred(&fits);
    let weights = akaike_weights(&fits);
    // Laws with no rate at its bound, by BIC: the preferred and the next.
    let mut ranked: Vec<usize> = (0..fits.len())
        .filter(|&i| fits[i].at_bound.is_empty())
        .collect();
    ranked.sort_by(|&a, &b| fits[a].fit.bic.total_cmp(&fits[b].fit.bic));
    let preferred_akaike_weight = ranked.first().map(|&i| weights[i]);
    let runner_up = match ranked[..] {
        [first, second, ..] => Some(RunnerUp {
            model: fits[second].model.name(),
            delta_bic: fits[second].fit.bic - fits[first].fit.bic,
        }),
        _ => None,
    };
    let models = models
        .iter()
        .filter_map(|&m| {
            if let Some(i) = fits.iter().position(|f| f.model == m) {
                Some(law_fit(&fits[i], weights[i], pendulum.as_ref(), mass))
            } else {
                failures.iter().find(|(f, _)| *f == m).map(|(_, e)| LawFit {
                    model: m.name(),
                    failed: Some(e.to_string()),
                    fitted: None,
                })
            }
        })
        .collect();
    let zeta = best
        .and_then(|m| fits.iter().find(|f| f.model == m))
        .and_then(|f| f.record_q)
        .map_or(0.0, |q| 0.5 * q.loss.max(0.0));
    let gravity = match (input.turning_count, input.length) {
        (Some(count), Some(l)) => {
            turn_gravity(time, amplitude, count, l, input.length_standard_error, zeta)
        }
        _ => None,
    };
    let mut warnings = Vec::new();
    let largest = amplitude.iter().copied().fold(0.0, f64::max);
    if input.declared_degrees && largest < TINY_SWING_DEG.to_radians() {
        warnings.push(RunDownWarning::SwingTiny { largest });
    }
    Ok(RunDown {
        points: time.len(),
        omega_rad_s: omega,
        omega_source,
        models,
        preferred: best.map(DecayModel::name),
        preferred_akaike_weight,
        runner_up,
        gravity,
        warnings,
        fits,
    })
}

/// A swing whose amplitudes, declared in degrees, never reach this many
/// degrees looks like one in radians: no video or clock swing is filmed
/// or logged under a degree but with an instrument that reads radians.
pub const TINY_SWING_DEG: f64 = 1.0;

/// g from the turning points' times (see [`TurnGravity`]); `None` with
/// fewer than three turns or no slope.
fn turn_gravity(
    time: &[f64],
    amplitude: &[f64],
    count: &[f64],
    length: f64,
    length_error: Option<f64>,
    zeta: f64,
) -> Option<TurnGravity> {
    let n = time.len();
    if n < 3 {
        return None;
    }
    // Σ F(Ā) over the half swings up to each turn.
    let mut sum = vec![0.0; n];
    for i in 1..n {
        let mean = 0.5 * (amplitude[i - 1] + amplitude[i]);
        let ratio = Amplitude::from_radians(mean.min(std::f64::consts::PI.next_down()))
            .map_or(1.0, crate::period::period_ratio);
        sum[i] = sum[i - 1] + (count[i] - count[i - 1]) * ratio;
    }
    let (a, half) = super::straight_line(&sum, time);
    let mean = sum.iter().sum::<f64>() / n as f64;
    let sxx: f64 = sum.iter().map(|x| (x - mean).powi(2)).sum();
    let rss: f64 = sum
        .iter()
        .zip(time)
        .map(|(x, y)| (y - a - half * x).powi(2))
        .sum();
    let half_se = (rss / (n - 2) as f64 / sxx).sqrt();
    if !(half > 0.0 && half.is_finite() && half_se.is_finite()) {
        return None;
    }
    let t0 = 2.0 * half;
    let w0 = std::f64::consts::TAU / t0;
    let g = length * w0 * w0 / (1.0 - zeta * zeta).max(f64::MIN_POSITIVE);
    let parts = super::ErrorParts::gravity(g, 2.0 * g * half_se / half, length, length_error);
    // (A length no pendulum has can overflow it: no g then.)
    if !(g.is_finite() && parts.total().is_finite()) {
        return None;
    }
    Some(TurnGravity {
        g_m_s2: g,
        standard_error_m_s2: parts.total(),
        standard_error_parts: parts,
        small_angle_period_s: t0,
        small_angle_period_standard_error_s: 2.0 * half_se,
        length_m: length,
        length_standard_error_m: length_error,
    })
}

fn law_fit(f: &DecayFit, weight: f64, pendulum: Option<&Pendulum>, mass: Option<f64>) -> LawFit {
    let parameters = f.parameters.iter().map(|e| (e.name, e.value)).collect();
    let standard_errors = f
        .parameters
        .iter()
        .map(|e| (e.name, e.standard_error))
        .collect();
    let budget = match (pendulum, mass) {
        (Some(p), Some(m)) => {
            let a0 = f.fit.parameters[0];
            let period =
                p.period(Amplitude::from_radians(a0.abs().min(3.1)).unwrap_or(Amplitude::ZERO));
            energy_budget(p, m, a0, half_swing_loss(f, a0, 0.5 * period), period).ok()
        }
        _ => None,
    };
    LawFit {
        model: f.model.name(),
        failed: None,
        fitted: Some(Fitted {
            parameters,
            standard_errors,
            q_factor: f.record_q.and_then(|q| q.q()).and_then(finite),
            q_factor_standard_error: f
                .record_q
                .and_then(|q| q.q_standard_error())
                .and_then(finite),
            q_factor_lower_bound: f.record_q.and_then(|q| q.lower_bound()).and_then(finite),
            q_viscous: f.q_viscous.and_then(finite),
            q_viscous_standard_error: f.q_viscous.and_then(|q| {
                let z = f.parameters.iter().find(|e| e.name == "zeta")?;
                finite(q * z.standard_error / z.value)
            }),
            q_viscous_lower_bound: f.q_viscous_lower_bound.and_then(finite),
            at_bound: f.at_bound.clone(),
            residual_rms: f.fit.residual_rms,
            aic: f.fit.aic,
            bic: f.fit.bic,
            akaike_weight: weight,
            energy_loss_per_period_j: budget.map(|b| b.loss_per_period),
            power_w: budget.map(|b| b.power),
        }),
    }
}
