//! Period tables: the periods a lab measures at several amplitudes, or at
//! several lengths, fitted with the exact theory.
//!
//! **Against amplitude.** The exact period at amplitude `A` is
//! `T(A) = T0 F(A)`, `F(A) = (2/π) K(sin²(A/2))` (section 1-6,
//! [`crate::period::period_ratio`]). The model is linear in `T0`, so the
//! fit is the closed-form weighted least squares
//! `T0 = Σ w T F / Σ w F²`, `w = 1/σ²` (or 1 without uncertainties), and
//! its standard error `(Σ w F²)^{-1/2}` with uncertainties, else scaled by
//! the residual variance. With the pendulum's length `l`, `g = 4π² l/T0²`.
//!
//! Beside it, `T0` from the seed's power series in `m = sin²(A/2)` cut
//! after two and three terms ([`crate::period::period_ratio_series`]),
//! what a lab formula would give, and the data's own test of the law: the
//! coefficient `c` of `A²` in `T/T0 = 1 + cA² + …`, fitted as
//! `T = T0 F(A) (1 + dA²)`, `c = 1/16 + d` (so that the exact law's higher
//! terms are held at theirs and `c = 1/16` at any range of amplitudes when
//! the data follow it).
//!
//! **Against length.** Each period is first brought to small amplitude,
//! `T/F(A)`, when amplitudes are given; then `T² = (4π²/g)(L + δ)`, a
//! straight line in `L` fitted by weighted least squares on `T²` (its
//! uncertainty `2Tσ`), gives `g = 4π²/slope` and the offset `δ =
//! intercept/slope`: the distance from the point the lengths were
//! measured to (the top of the bob, say) to the centre of oscillation.
//! With a spherical bob of radius `r` whose centre the lengths reach, each
//! length is the equivalent length of the physical pendulum,
//! `L + 2r²/(5L)` (the sphere's moment of inertia about its centre,
//! `2mr²/5`, moved to the pivot), before the fit.
//!
//! **Its own checks.** With uncertainties, `χ²` against its degrees of
//! freedom (Wilson & Hilferty 1931's cube-root normal approximation, good
//! to 0.01 in `z` for ν ≥ 3): residuals beyond the uncertainties widen
//! the standard errors by the Birge ratio `√(χ²/ν)` and are said;
//! residuals far inside them say the uncertainties are overstated. A `g`
//! a power of ten, a factor of 4 or of 39.37 from standard gravity is
//! named as the unit or the count it most likely comes from; a `c` more
//! than three standard errors from 1/16 is said, with the amplitudes read
//! in the other unit tried.
//!
//! Measured accuracy: on exact synthetic tables the fitted `T0` equals the
//! generating one to 2e-15 relative (the closed form's rounding); on
//! tables with noise, `T0` lies within one standard error of the truth in
//! 68% of 2,000 seeded tables (`tests` below).

use super::ErrorParts;
use crate::analysis::{judge_work, require_finite, require_finite_samples, Refusal};
use crate::pendulum::Amplitude;
use crate::period::{period_ratio, period_ratio_series};
use crate::STANDARD_GRAVITY;
use serde::Serialize;
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::fmt;

/// Computing time of a row, s (one complete elliptic integral and a few
/// sums): measured, 1 million rows in 0.09 s.
pub const SECONDS_PER_ROW: f64 = 1e-7;
/// Lengths that differ by less than this fraction are one length: the
/// table is then against amplitude.
pub const SAME_LENGTH: f64 = 0.01;
/// Amplitudes whose `F(A)` differ by less than this are one amplitude: the
/// law cannot be tested on them.
pub const SAME_AMPLITUDE: f64 = 1e-6;
/// The probability of a `χ²` at least as large below which the residuals
/// exceed the uncertainties given: 1%. (A χ² of 13.5 on 4 degrees of
/// freedom, probability 0.009, gave no word under the 0.1% test this
/// replaced, with standard errors 1.8 times too small.)
pub const CHI_SQUARE_P: f64 = 0.01;
/// The probability of a `χ²` at most as large below which the
/// uncertainties given are overstated: 0.1%.
pub const CHI_SQUARE_P_LOW: f64 = 0.001;
/// A fitted g further than this from standard gravity (relative), and
/// beyond three standard errors, says the length is not the pendulum's.
pub const GRAVITY_CHECK: f64 = 0.05;
/// Standard errors beyond which the circular-error coefficient is said to
/// differ from the theory's 1/16.
pub const LAW_SIGMA: f64 = 3.0;
/// The theory's coefficient of `A²` in `T/T0`.
pub const CIRCULAR_COEFFICIENT: f64 = 1.0 / 16.0;

/// A table of periods to fit. Lengths or amplitudes (or both) tell what
/// the periods are against.
#[derive(Clone, Debug, Default)]
pub struct PeriodTableInput<'a> {
    /// The periods, s (there and back: two swings).
    pub period: &'a [f64],
    /// Each period's standard uncertainty, s (weights `1/σ²`).
    pub period_standard_error: Option<&'a [f64]>,
    /// The amplitude each period was measured at, rad, in `[0, π)`.
    pub amplitude: Option<&'a [f64]>,
    /// The length each period was measured at, m (from the pivot to the
    /// bob's centre, or to the point the length is measured to).
    pub length: Option<&'a [f64]>,
    /// The pendulum's length when it is one for the whole table, m: gives
    /// g from `T0`.
    pub pendulum_length: Option<f64>,
    /// That length's standard uncertainty, m.
    pub pendulum_length_standard_error: Option<f64>,
    /// The radius of a spherical bob, m: lengths to its centre become the
    /// physical pendulum's equivalent length.
    pub bob_radius: Option<f64>,
    /// Runs estimated beyond [`crate::analysis::FORCE_SECONDS`] anyway.
    pub force: bool,
}

/// What the periods were fitted against.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Against {
    /// One pendulum at several amplitudes.
    Amplitude,
    /// Several lengths.
    Length,
    /// One length and one amplitude: the periods are repeats.
    Repeats,
}

/// `T0` from the seed's series cut short, beside the exact law.
#[derive(Clone, Debug, Serialize)]
pub struct SeriesFit {
    /// Terms kept (in `m = sin²(A/2)`; two terms is `1 + m/4`).
    pub terms: u32,
    /// The small-angle period it gives, s.
    pub small_angle_period_s: f64,
    /// Its difference from the exact law's, in the exact fit's standard
    /// errors.
    pub shift_standard_errors: Option<f64>,
}

/// Something the fit found wrong with its own answer.
#[derive(Clone, Debug, PartialEq)]
pub enum PeriodWarning {
    /// `χ²` of the residuals against the uncertainties given is too large
    /// (its probability below [`CHI_SQUARE_P`]): the standard errors are
    /// widened by the Birge ratio.
    ResidualsExceedUncertainties {
        /// `√(χ²/ν)`.
        birge_ratio: f64,
        /// `χ²`.
        chi_square: f64,
        /// Its degrees of freedom.
        degrees_of_freedom: usize,
        /// The probability of a `χ²` at least as large.
        probability: f64,
        /// The figures whose standard errors were widened.
        figures: Vec<&'static str>,
    },
    /// `χ²` is far below its degrees of freedom: the uncertainties given
    /// are larger than the scatter.
    UncertaintiesOverstated {
        /// `√(χ²/ν)`.
        birge_ratio: f64,
    },
    /// g far from standard gravity, with the likely cause.
    GravityImplausible {
        /// The g fitted, m/s².
        g: f64,
        /// The likely cause.
        likely: &'static str,
    },
    /// g beyond [`GRAVITY_CHECK`] and three standard errors of standard
    /// gravity.
    GravityOff {
        /// The g fitted, m/s².
        g: f64,
    },
    /// The periods grow with amplitude unlike the exact law.
    LawDiffers {
        /// The coefficient of `A²` measured.
        coefficient: f64,
        /// Its standard error.
        standard_error: f64,
        /// The amplitudes' unit that would agree with the law, if one does.
        read_as: Option<&'static str>,
    },
}

impl crate::warning::Warn for PeriodWarning {
    fn code(&self) -> &'static str {
        match self {
            PeriodWarning::ResidualsExceedUncertainties { .. } => "residuals_exceed_uncertainties",
            PeriodWarning::UncertaintiesOverstated { .. } => "uncertainties_overstated",
            PeriodWarning::GravityImplausible { .. } => "gravity_implausible",
            PeriodWarning::GravityOff { .. } => "gravity_off",
            PeriodWarning::LawDiffers { .. } => "law_differs",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            PeriodWarning::ResidualsExceedUncertainties { figures, .. } => figures.first().copied(),
            PeriodWarning::UncertaintiesOverstated { .. } => Some("chi_square"),
            PeriodWarning::GravityImplausible { .. } | PeriodWarning::GravityOff { .. } => {
                Some("g_m_s2")
            }
            PeriodWarning::LawDiffers { .. } => Some("circular_error_coefficient"),
        }
    }
}

impl fmt::Display for PeriodWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = |v: f64| crate::error::format_significant(v, 4);
        match self {
            PeriodWarning::ResidualsExceedUncertainties {
                birge_ratio,
                chi_square,
                degrees_of_freedom,
                probability,
                figures,
            } => write!(
                f,
                "the periods scatter {} times more than their uncertainties allow (χ² {} for {} \
                 degrees of freedom, a probability of {}: the uncertainties left out something, \
                 reaction time, a miscount, amplitudes that changed); the standard errors of {} \
                 are widened by that factor",
                n(*birge_ratio),
                n(*chi_square),
                degrees_of_freedom,
                crate::error::format_significant(*probability, 2),
                if figures.is_empty() {
                    "every figure".to_string()
                } else {
                    figures.join(", ")
                }
            ),
            PeriodWarning::UncertaintiesOverstated { birge_ratio } => write!(
                f,
                "the periods scatter only {} of their uncertainties: the uncertainties given \
                 are too large, and so are the standard errors computed from them",
                n(*birge_ratio)
            ),
            PeriodWarning::GravityImplausible { g, likely } => {
                write!(f, "g = {} m/s² is no pendulum's on Earth: {likely}", n(*g))
            }
            PeriodWarning::GravityOff { g } => write!(
                f,
                "g = {} m/s² is more than 5% and three standard errors from standard gravity: \
                 the length is not the pendulum's (measured to the centre of the bob?), or the \
                 periods are not",
                n(*g)
            ),
            PeriodWarning::LawDiffers {
                coefficient,
                standard_error,
                read_as,
            } => {
                write!(
                    f,
                    "the periods grow with amplitude as {} A² (± {}), where the exact law has \
                     0.0625 A²: ",
                    n(*coefficient),
                    n(*standard_error)
                )?;
                match read_as {
                    Some(unit) => write!(
                        f,
                        "the amplitudes look like {unit}; check their unit (the column's \
                         header, or the unit given for it)"
                    ),
                    None if *coefficient > CIRCULAR_COEFFICIENT => write!(
                        f,
                        "faster than any pendulum's. Are the amplitudes smaller than the swings \
                         timed (half the arc?), or does the pendulum change with the swing (a \
                         string that stretches, a support that gives)?"
                    ),
                    None => write!(
                        f,
                        "slower than the law. Are the amplitudes larger than the swings timed \
                         (a release angle, while the swing decays during the count; the whole \
                         arc from side to side)?"
                    ),
                }
            }
        }
    }
}

crate::warning::serialize_as_warning!(PeriodWarning);

/// The fit of a period table.
#[derive(Clone, Debug, Serialize)]
pub struct PeriodTable {
    /// Rows fitted.
    pub rows: usize,
    /// What the periods were fitted against.
    pub against: Against,
    /// Whether the fit was weighted by uncertainties given.
    pub weighted: bool,
    /// Fitted values by name: `small_angle_period_s` (the exact law's),
    /// `g_m_s2`, `length_offset_m`, `circular_error_coefficient`, and
    /// `small_angle_period_free_s`: `T0` with that coefficient fitted too,
    /// the data's own period at zero amplitude when they do not follow the
    /// law.
    pub parameters: BTreeMap<&'static str, f64>,
    /// Their standard errors.
    pub standard_errors: BTreeMap<&'static str, f64>,
    /// What the standard errors of figures derived from a measured input
    /// are made of (`g_m_s2` from the periods and the pendulum's length:
    /// the fit's part, and the length's, null when no uncertainty of the
    /// length was given).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub standard_error_parts: BTreeMap<&'static str, ErrorParts>,
    /// The exact law's coefficient of `A²`, 1/16, beside the measured one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub circular_error_coefficient_theory: Option<f64>,
    /// `T0` from the series cut short (against amplitude).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub series: Vec<SeriesFit>,
    /// Root mean square of the period residuals, s.
    pub residual_rms_s: f64,
    /// `χ²` of the residuals against the uncertainties given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub chi_square: Option<f64>,
    /// The probability of a `χ²` at least as large, were the
    /// uncertainties right ([`chi_square_probability`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub chi_square_probability: Option<f64>,
    /// Its degrees of freedom.
    pub degrees_of_freedom: usize,
    /// The fitted period at each row, s (for plots).
    #[serde(skip)]
    pub fitted_period: Vec<f64>,
    /// Each row's equivalent length (lengths against which `T²` is
    /// straight), m.
    #[serde(skip)]
    pub equivalent_length: Vec<f64>,
    /// What the fit found wrong with itself.
    pub warnings: Vec<PeriodWarning>,
}

/// A weighted linear least-squares fit `y ≈ Σ p_j X_j`.
struct Linear {
    p: Vec<f64>,
    cov: Vec<Vec<f64>>,
    chi_square: f64,
}

/// Weighted linear least squares by the normal equations (one or two
/// columns, well conditioned here: `F` and `F A²`, or 1 and `L`), with the
/// covariance `(XᵀWX)⁻¹` unscaled (the caller scales it).
fn linear(columns: &[Vec<f64>], y: &[f64], w: &[f64]) -> Option<Linear> {
    let k = columns.len();
    let mut a = vec![vec![0.0; k]; k];
    let mut b = vec![0.0; k];
    for i in 0..y.len() {
        for r in 0..k {
            b[r] += w[i] * columns[r][i] * y[i];
            for c in 0..k {
                a[r][c] += w[i] * columns[r][i] * columns[c][i];
            }
        }
    }
    let cov = match k {
        1 => vec![vec![1.0 / a[0][0]]],
        2 => {
            let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
            if det.abs() <= 1e-12 * (a[0][0] * a[1][1]).abs() {
                return None;
            }
            vec![
                vec![a[1][1] / det, -a[0][1] / det],
                vec![-a[1][0] / det, a[0][0] / det],
            ]
        }
        _ => return None,
    };
    let p: Vec<f64> = (0..k)
        .map(|r| (0..k).map(|c| cov[r][c] * b[c]).sum())
        .collect();
    if p.iter().chain(cov.iter().flatten()).any(|v| !v.is_finite()) {
        return None;
    }
    let chi_square = (0..y.len())
        .map(|i| {
            let r = y[i] - (0..k).map(|c| p[c] * columns[c][i]).sum::<f64>();
            w[i] * r * r
        })
        .sum();
    Some(Linear { p, cov, chi_square })
}

/// The probability that a `χ²` with `nu` degrees of freedom is at least
/// `chi_square`: `Q(ν/2, χ²/2)`, the regularised upper incomplete gamma
/// function, by its power series below `x = a + 1` and its continued
/// fraction above (modified Lentz; DLMF 8.7.1 and 8.9.2), `ln Γ(ν/2)`
/// exact for the half-integers it takes. Measured against SciPy's
/// `chi2.sf` (`tools/reference/chi_square.py`) within 1e-12 relative from
/// 1e-36 to 0.9995.
pub fn chi_square_probability(chi_square: f64, nu: usize) -> f64 {
    if nu == 0 || chi_square.is_nan() {
        return f64::NAN;
    }
    if chi_square <= 0.0 {
        return 1.0;
    }
    let (a, x) = (0.5 * nu as f64, 0.5 * chi_square);
    // ln Γ(a) for a = ν/2: (a−1)! or the half-integer product with √π.
    let ln_gamma = if nu % 2 == 0 {
        (1..nu / 2).map(|k| (k as f64).ln()).sum::<f64>()
    } else {
        0.5 * PI.ln() + (0..nu / 2).map(|k| (k as f64 + 0.5).ln()).sum::<f64>()
    };
    let front = (a * x.ln() - x - ln_gamma).exp();
    if x < a + 1.0 {
        // P(a, x) = e^{-x} x^a / Γ(a+1) Σ x^k / ((a+1)…(a+k)).
        let (mut term, mut sum, mut b) = (1.0 / a, 1.0 / a, a);
        for _ in 0..10_000 {
            b += 1.0;
            term *= x / b;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        (1.0 - sum * front).max(0.0)
    } else {
        // Q(a, x) = e^{-x} x^a / Γ(a) · 1/(x+1−a− 1(1−a)/(x+3−a− …)).
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..10_000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let step = d * c;
            h *= step;
            if (step - 1.0).abs() < 1e-16 {
                break;
            }
        }
        (front * h).clamp(0.0, 1.0)
    }
}

/// The Wilson-Hilferty normal deviate of `χ²` with `ν` degrees of
/// freedom: `((χ²/ν)^{1/3} - (1 - 2/(9ν))) / √(2/(9ν))` (Wilson &
/// Hilferty 1931; within 0.01 of the exact deviate for ν ≥ 3 in the
/// range used here).
pub fn chi_square_z(chi_square: f64, nu: usize) -> f64 {
    let nu = nu as f64;
    let v = 2.0 / (9.0 * nu);
    ((chi_square / nu).cbrt() - (1.0 - v)) / v.sqrt()
}

/// The likely cause of a g more than 30% from standard gravity: `g ∝ L/T²`,
/// so lengths in another unit show as 100, 1000 or 39.37, half periods as
/// 4, the time of ten periods as 1/100, two periods as 1/4.
pub fn gravity_cause(g: f64) -> Option<&'static str> {
    let ratio = g / STANDARD_GRAVITY;
    if (ratio - 1.0).abs() <= 0.3 {
        return None;
    }
    let near = |r: f64| (ratio / r).ln().abs() < 0.2;
    Some(if near(100.0) {
        "the lengths look like centimetres read as metres; give their unit (length_cm in a header, 99.4cm given as a length)"
    } else if near(1000.0) {
        "the lengths look like millimetres read as metres; give their unit (length_mm in a header, 994mm given as a length)"
    } else if near(39.37) {
        "the lengths look like inches read as metres; give their unit (length_in in a header, 39.1in given as a length)"
    } else if near(4.0) {
        "g is 4 times too large: the periods look like half periods (one swing across, not \
         there and back)"
    } else if near(0.25) {
        "g is 4 times too small: the periods look like two periods (or the lengths like half \
         lengths)"
    } else if near(0.01) {
        "g is 100 times too small: the periods look like the time of ten periods, not divided \
         by ten"
    } else if near(0.01 * 0.01) || near(1e-6) {
        "the lengths look like metres given in other units, or the periods in milliseconds; \
         check both units"
    } else {
        "check the lengths' and the periods' units, and that the periods are full periods"
    })
}

/// The table's inputs checked (each refusal names its field and row),
/// and the work judged; returns each row's period ratio `T(A)/T₀` at its
/// amplitude (1 where no amplitude is given).
fn validated(input: &PeriodTableInput<'_>) -> Result<Vec<f64>, Refusal> {
    let period = input.period;
    let n = period.len();
    require_finite_samples("period", period)?;
    if let Some(i) = period.iter().position(|&t| t <= 0.0) {
        return Err(Refusal::sample(
            "period",
            i,
            format!("must be positive, got {} s", period[i]),
        ));
    }
    let range = crate::fitting::rundown::PERIOD_RANGE_S;
    if let Some(i) = period.iter().position(|t| !range.contains(t)) {
        return Err(Refusal::sample(
            "period",
            i,
            format!(
                "must lie between 1 ms and 10,000 s for a pendulum, got {} s",
                crate::error::format_significant(period[i], 6)
            ),
        ));
    }
    let same_length = |name: &'static str, v: Option<&[f64]>| match v {
        Some(v) if v.len() != n => Err(Refusal::field(
            name,
            format!("has {} values and period {n}: give one of each", v.len()),
        )),
        _ => Ok(()),
    };
    same_length("period_standard_error", input.period_standard_error)?;
    same_length("amplitude", input.amplitude)?;
    same_length("length", input.length)?;
    if let Some(s) = input.period_standard_error {
        require_finite_samples("period_standard_error", s)?;
        if let Some(i) = s.iter().position(|&v| v <= 0.0) {
            return Err(Refusal::sample(
                "period_standard_error",
                i,
                format!("must be positive, got {} s", s[i]),
            ));
        }
        // An uncertainty below a picosecond or above the period itself is
        // no measurement's (and breaks the weights' arithmetic).
        if let Some(i) = (0..n).find(|&i| s[i] < 1e-12 || s[i] > period[i]) {
            return Err(Refusal::sample(
                "period_standard_error",
                i,
                format!(
                    "must lie between 1 ps and the period ({} s), got {} s",
                    crate::error::format_significant(period[i], 6),
                    crate::error::format_significant(s[i], 6)
                ),
            ));
        }
    }
    let mut ratio = vec![1.0; n];
    if let Some(a) = input.amplitude {
        require_finite_samples("amplitude", a)?;
        for (i, &v) in a.iter().enumerate() {
            let amp = Amplitude::from_radians(v)
                .map_err(|e| Refusal::sample("amplitude", i, e.detail()))?;
            ratio[i] = period_ratio(amp);
        }
    }
    if let Some(l) = input.length {
        require_finite_samples("length", l)?;
        if let Some(i) = l.iter().position(|&v| v <= 0.0) {
            return Err(Refusal::sample(
                "length",
                i,
                format!("must be positive, got {} m", l[i]),
            ));
        }
        let range = crate::fitting::tracked::LENGTH_RANGE_M;
        if let Some(i) = l.iter().position(|v| !range.contains(v)) {
            return Err(Refusal::sample(
                "length",
                i,
                format!(
                    "must lie between 0.1 mm and 10 km for a pendulum, got {} m",
                    crate::error::format_significant(l[i], 6)
                ),
            ));
        }
    }
    for (name, v) in [
        ("pendulum_length", input.pendulum_length),
        (
            "pendulum_length_standard_error",
            input.pendulum_length_standard_error,
        ),
        ("bob_radius", input.bob_radius),
    ] {
        if let Some(v) = v {
            require_finite(name, v)?;
            if v <= 0.0 {
                return Err(Refusal::field(name, format!("must be positive, got {v} m")));
            }
            if v > *crate::fitting::tracked::LENGTH_RANGE_M.end() {
                return Err(Refusal::field(
                    name,
                    format!(
                        "must be at most 10 km for a pendulum, got {} m",
                        crate::error::format_significant(v, 6)
                    ),
                ));
            }
        }
    }
    // An uncertainty of a length not given would be taken for nothing
    // (a table against lengths carries no one length's uncertainty).
    if input.pendulum_length_standard_error.is_some() && input.pendulum_length.is_none() {
        return Err(Refusal::field(
            "pendulum_length_standard_error",
            "is the uncertainty of the pendulum's one length, which is not given: give that \
             length too (the uncertainties of a table's lengths are not taken)",
        ));
    }
    if n < 2 {
        return Err(Refusal::data(format!(
            "a table needs at least two periods, got {n}"
        )));
    }
    judge_work(
        "period",
        format!("a table of {n} rows"),
        n as f64 * SECONDS_PER_ROW,
        input.force,
    )?;
    Ok(ratio)
}

/// Fits a period table (see the module notes).
///
/// # Examples
///
/// ```
/// use pendulum_theory::fitting::period_table::{analyse, Against, PeriodTableInput};
/// use std::f64::consts::TAU;
///
/// // Small-swing periods at four lengths, T = 2π √(L/g) with g = 9.81 m/s².
/// let length = [0.25, 0.5, 0.75, 1.0];
/// let period: Vec<f64> = length.iter().map(|l| TAU * (l / 9.81_f64).sqrt()).collect();
/// let fit = analyse(&PeriodTableInput {
///     period: &period,
///     length: Some(&length),
///     ..Default::default()
/// })?;
/// assert_eq!(fit.against, Against::Length);
/// assert!((fit.parameters["g_m_s2"] - 9.81).abs() < 1e-9);
/// assert!(fit.parameters["length_offset_m"].abs() < 1e-9);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn analyse(input: &PeriodTableInput<'_>) -> Result<PeriodTable, Refusal> {
    let ratio = validated(input)?;
    let n = input.period.len();
    let weights: Vec<f64> = match input.period_standard_error {
        Some(s) => s.iter().map(|s| 1.0 / (s * s)).collect(),
        None => vec![1.0; n],
    };
    let varies = |v: &[f64], tolerance: f64| {
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            });
        hi > lo * (1.0 + tolerance)
    };
    if input.bob_radius.is_some() && input.length.is_none() && input.pendulum_length.is_none() {
        return Err(Refusal::field(
            "bob_radius",
            "needs the lengths it corrects: the pendulum's length, or a column of lengths",
        ));
    }
    let lengths_vary = input.length.is_some_and(|l| varies(l, SAME_LENGTH));
    if let (true, Some(_)) = (lengths_vary, input.pendulum_length) {
        return Err(Refusal::field(
            "pendulum_length",
            "is for a table at one length; this table's lengths vary: leave it out",
        ));
    }
    // One length for the table: given, or the column's mean.
    let one_length = input.pendulum_length.or_else(|| {
        input
            .length
            .filter(|_| !lengths_vary)
            .map(|l| l.iter().sum::<f64>() / n as f64)
    });
    let equivalent = |l: f64| match input.bob_radius {
        Some(r) => l + 0.4 * r * r / l,
        None => l,
    };
    if lengths_vary {
        fit_length(input, &ratio, &weights, &equivalent)
    } else {
        fit_amplitude(
            input,
            &ratio,
            &weights,
            one_length.map(equivalent),
            varies(&ratio, SAME_AMPLITUDE),
        )
    }
}

/// Scales a covariance by the residual variance (no uncertainties given)
/// or by the Birge ratio (uncertainties given and exceeded), and says what
/// `χ²` shows.
fn judge_scatter(
    fit: &mut Linear,
    weighted: bool,
    nu: usize,
    warnings: &mut Vec<PeriodWarning>,
) -> Option<f64> {
    if nu == 0 {
        return None;
    }
    let reduced = fit.chi_square / nu as f64;
    let mut scale = |s: f64| {
        for row in fit.cov.iter_mut() {
            for v in row.iter_mut() {
                *v *= s;
            }
        }
    };
    if !weighted {
        scale(reduced);
        return None;
    }
    let p = chi_square_probability(fit.chi_square, nu);
    if p < CHI_SQUARE_P {
        warnings.push(PeriodWarning::ResidualsExceedUncertainties {
            birge_ratio: reduced.sqrt(),
            chi_square: fit.chi_square,
            degrees_of_freedom: nu,
            probability: p,
            figures: Vec::new(),
        });
        scale(reduced);
    } else if 1.0 - p < CHI_SQUARE_P_LOW {
        warnings.push(PeriodWarning::UncertaintiesOverstated {
            birge_ratio: reduced.sqrt(),
        });
    }
    Some(fit.chi_square)
}

/// g and the parts of its standard error from `T0` and a length known to
/// `length_se` (if given).
fn gravity(t0: f64, t0_se: f64, length: f64, length_se: Option<f64>) -> (f64, ErrorParts) {
    let g = 4.0 * PI * PI * length / (t0 * t0);
    (
        g,
        ErrorParts::gravity(g, 2.0 * g * t0_se / t0, length, length_se),
    )
}

/// Says what a g far from standard gravity most likely means.
fn judge_gravity(g: f64, se: f64, warnings: &mut Vec<PeriodWarning>) {
    if let Some(likely) = gravity_cause(g) {
        warnings.push(PeriodWarning::GravityImplausible { g, likely });
    } else if (g - STANDARD_GRAVITY).abs() > (GRAVITY_CHECK * STANDARD_GRAVITY).max(3.0 * se) {
        warnings.push(PeriodWarning::GravityOff { g });
    }
}

fn fit_amplitude(
    input: &PeriodTableInput<'_>,
    ratio: &[f64],
    weights: &[f64],
    length: Option<f64>,
    amplitudes_vary: bool,
) -> Result<PeriodTable, Refusal> {
    let period = input.period;
    let n = period.len();
    let weighted = input.period_standard_error.is_some();
    let mut warnings = Vec::new();
    let mut fit = linear(&[ratio.to_vec()], period, weights)
        .ok_or_else(|| Refusal::data("the periods do not determine the small-angle period"))?;
    let nu = n - 1;
    let chi_square = judge_scatter(&mut fit, weighted, nu, &mut warnings);
    let (t0, t0_se) = (fit.p[0], fit.cov[0][0].sqrt());
    let mut standard_error_parts = BTreeMap::new();
    let mut parameters = BTreeMap::new();
    let mut standard_errors = BTreeMap::new();
    parameters.insert("small_angle_period_s", t0);
    standard_errors.insert("small_angle_period_s", t0_se);
    if let Some(l) = length {
        let (g, parts) = gravity(t0, t0_se, l, input.pendulum_length_standard_error);
        let se = parts.total();
        standard_error_parts.insert("g_m_s2", parts);
        parameters.insert("g_m_s2", g);
        standard_errors.insert("g_m_s2", se);
        judge_gravity(g, se, &mut warnings);
    }
    let mut series = Vec::new();
    let mut theory = None;
    if amplitudes_vary {
        if let Some(a) = input.amplitude {
            for terms in [2, 3] {
                let f: Vec<f64> = a
                    .iter()
                    .map(|&v| {
                        Amplitude::from_radians(v)
                            .ok()
                            .and_then(|amp| period_ratio_series(amp, terms).ok())
                            .map_or(1.0, |s| s.period_ratio)
                    })
                    .collect();
                if let Some(s) = linear(&[f], period, weights) {
                    series.push(SeriesFit {
                        terms,
                        small_angle_period_s: s.p[0],
                        shift_standard_errors: (t0_se > 0.0).then(|| (s.p[0] - t0) / t0_se),
                    });
                }
            }
            // The law's own test: T = T0 F (1 + d A²).
            if n >= 3 {
                let law = |a: &[f64]| -> Option<(f64, f64, f64, f64)> {
                    let f: Vec<f64> = a
                        .iter()
                        .map(|&v| Amplitude::from_radians(v).map_or(f64::NAN, period_ratio))
                        .collect();
                    if f.iter().any(|v| !v.is_finite()) {
                        return None;
                    }
                    let fa: Vec<f64> = f.iter().zip(a).map(|(f, a)| f * a * a).collect();
                    let mut l = linear(&[f, fa], period, weights)?;
                    let mut ignore = Vec::new();
                    judge_scatter(&mut l, weighted, n - 2, &mut ignore);
                    let (t, e) = (l.p[0], l.p[1]);
                    // c - 1/16 = e/t; its variance by propagation.
                    let d = e / t;
                    let var = (l.cov[1][1] - 2.0 * d * l.cov[0][1] + d * d * l.cov[0][0]) / (t * t);
                    Some((d, var.max(0.0).sqrt(), t, l.cov[0][0].max(0.0).sqrt()))
                };
                if let Some((d, se, t_free, t_free_se)) = law(a) {
                    parameters.insert("circular_error_coefficient", CIRCULAR_COEFFICIENT + d);
                    standard_errors.insert("circular_error_coefficient", se);
                    parameters.insert("small_angle_period_free_s", t_free);
                    standard_errors.insert("small_angle_period_free_s", t_free_se);
                    theory = Some(CIRCULAR_COEFFICIENT);
                    if d.abs() > LAW_SIGMA * se {
                        let read_as = [
                            (
                                a.iter().map(|v| v.to_radians()).collect::<Vec<_>>(),
                                "degrees read as radians",
                            ),
                            (
                                a.iter().map(|v| v.to_degrees()).collect::<Vec<_>>(),
                                "radians read as degrees",
                            ),
                        ]
                        .into_iter()
                        .find_map(|(other, unit)| {
                            let (d2, se2, _, _) = law(&other)?;
                            (d2.abs() <= 2.0 * se2 || d2.abs() * 10.0 < d.abs()).then_some(unit)
                        });
                        warnings.push(PeriodWarning::LawDiffers {
                            coefficient: CIRCULAR_COEFFICIENT + d,
                            standard_error: se,
                            read_as,
                        });
                    }
                }
            }
        }
    }
    name_widened(&mut warnings, &standard_errors);
    let fitted_period: Vec<f64> = ratio.iter().map(|f| t0 * f).collect();
    let residual_rms_s = rms(period, &fitted_period);
    Ok(PeriodTable {
        rows: n,
        against: if amplitudes_vary {
            Against::Amplitude
        } else {
            Against::Repeats
        },
        weighted,
        parameters,
        standard_errors,
        circular_error_coefficient_theory: theory,
        standard_error_parts,
        series,
        residual_rms_s,
        chi_square_probability: chi_square.map(|c| chi_square_probability(c, nu)),
        chi_square,
        degrees_of_freedom: nu,
        fitted_period,
        equivalent_length: length.map_or_else(Vec::new, |l| vec![l; n]),
        warnings,
    })
}

fn fit_length(
    input: &PeriodTableInput<'_>,
    ratio: &[f64],
    weights: &[f64],
    equivalent: &dyn Fn(f64) -> f64,
) -> Result<PeriodTable, Refusal> {
    let period = input.period;
    let n = period.len();
    let lengths: Vec<f64> = input
        .length
        .unwrap_or(&[])
        .iter()
        .map(|&l| equivalent(l))
        .collect();
    let weighted = input.period_standard_error.is_some();
    // T² at small amplitude, and its weight 1/(2Tσ)².
    let small: Vec<f64> = period.iter().zip(ratio).map(|(t, f)| t / f).collect();
    let y: Vec<f64> = small.iter().map(|t| t * t).collect();
    let w: Vec<f64> = small
        .iter()
        .zip(weights)
        .zip(ratio)
        .map(|((t, w), f)| w * (f * f) / (4.0 * t * t))
        .collect();
    let w = if weighted { w } else { vec![1.0; n] };
    let with_offset = n >= 3;
    let columns = if with_offset {
        vec![vec![1.0; n], lengths.clone()]
    } else {
        vec![lengths.clone()]
    };
    let mut fit = linear(&columns, &y, &w)
        .ok_or_else(|| Refusal::data("the lengths do not determine g (all equal, or too close)"))?;
    let nu = n - columns.len();
    let mut warnings = Vec::new();
    let chi_square = judge_scatter(&mut fit, weighted, nu, &mut warnings);
    let k = columns.len() - 1;
    let slope = fit.p[k];
    if slope <= 0.0 {
        return Err(Refusal::data(
            "the periods do not grow with the length: g cannot be fitted",
        ));
    }
    let g = 4.0 * PI * PI / slope;
    let g_se = g * fit.cov[k][k].sqrt() / slope;
    let mut parameters = BTreeMap::new();
    let mut standard_errors = BTreeMap::new();
    parameters.insert("g_m_s2", g);
    standard_errors.insert("g_m_s2", g_se);
    let offset = if with_offset {
        let (a, b) = (fit.p[0], slope);
        let d = a / b;
        let var = (fit.cov[0][0] - 2.0 * d * fit.cov[0][1] + d * d * fit.cov[1][1]) / (b * b);
        parameters.insert("length_offset_m", d);
        standard_errors.insert("length_offset_m", var.max(0.0).sqrt());
        d
    } else {
        0.0
    };
    judge_gravity(g, g_se, &mut warnings);
    name_widened(&mut warnings, &standard_errors);
    let fitted_period: Vec<f64> = lengths
        .iter()
        .zip(ratio)
        .map(|(l, f)| 2.0 * PI * ((l + offset) / g).max(0.0).sqrt() * f)
        .collect();
    let residual_rms_s = rms(period, &fitted_period);
    Ok(PeriodTable {
        rows: n,
        against: Against::Length,
        weighted,
        parameters,
        standard_errors,
        circular_error_coefficient_theory: None,
        standard_error_parts: BTreeMap::new(),
        series: Vec::new(),
        residual_rms_s,
        chi_square_probability: chi_square.map(|c| chi_square_probability(c, nu)),
        chi_square,
        degrees_of_freedom: nu,
        fitted_period,
        equivalent_length: lengths,
        warnings,
    })
}

/// Names the figures whose standard errors a too large `χ²` widened.
fn name_widened(warnings: &mut [PeriodWarning], errors: &BTreeMap<&'static str, f64>) {
    for w in warnings {
        if let PeriodWarning::ResidualsExceedUncertainties { figures, .. } = w {
            *figures = errors.keys().copied().collect();
        }
    }
}

fn rms(a: &[f64], b: &[f64]) -> f64 {
    (a.iter().zip(b).map(|(a, b)| (a - b).powi(2)).sum::<f64>() / a.len().max(1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::test_noise::Normals as Normal;

    /// The exact period of a 1 m pendulum at standard gravity, computed
    /// independently by the AGM (DLMF 19.8.5), not by `period_ratio`.
    fn exact(l: f64, g: f64, a: f64) -> f64 {
        let (mut x, mut y) = (1.0_f64, (a / 2.0).cos());
        for _ in 0..40 {
            (x, y) = ((x + y) / 2.0, (x * y).sqrt());
        }
        2.0 * PI * (l / g).sqrt() / x
    }

    #[test]
    fn exact_tables_give_back_t0_and_g() {
        let a: Vec<f64> = (1..=12).map(|i| (10.0 * i as f64).to_radians()).collect();
        let t: Vec<f64> = a.iter().map(|&a| exact(0.75, 9.81, a)).collect();
        let r = analyse(&PeriodTableInput {
            period: &t,
            amplitude: Some(&a),
            pendulum_length: Some(0.75),
            ..Default::default()
        })
        .unwrap();
        let t0 = 2.0 * PI * (0.75_f64 / 9.81).sqrt();
        assert!((r.parameters["small_angle_period_s"] / t0 - 1.0).abs() < 1e-14);
        assert!((r.parameters["g_m_s2"] / 9.81 - 1.0).abs() < 1e-13);
        assert!((r.parameters["circular_error_coefficient"] - 0.0625).abs() < 1e-12);
        assert_eq!(r.against, Against::Amplitude);
        assert!(r.warnings.is_empty(), "{:?}", r.warnings);
        // The series cut short falls below F(A) at large amplitude, so
        // the T0 it gives is too long; three terms less so than two.
        let (two, three) = (&r.series[0], &r.series[1]);
        assert_eq!((two.terms, three.terms), (2, 3));
        assert!(two.small_angle_period_s > three.small_angle_period_s);
        assert!(three.small_angle_period_s > t0 * (1.0 + 1e-4));
    }

    #[test]
    fn noisy_tables_cover_t0_and_g_as_their_standard_errors_say() {
        let mut rng = Normal(0x9e37_79b9_7f4a_7c15);
        let (mut t0_in, mut g_in, mut law_in, mut trials) = (0, 0, 0, 0);
        for trial in 0..2000 {
            let weighted = trial % 2 == 0;
            let l = 0.3 + 1.5 * rng.uniform();
            let g = 9.78 + 0.05 * rng.uniform();
            let sigma = 1e-4 + 5e-3 * rng.uniform();
            let rows = 4 + (rng.uniform() * 12.0) as usize;
            let top = 10.0 + 80.0 * rng.uniform();
            let a: Vec<f64> = (0..rows)
                .map(|i| (top * (i as f64 + 1.0) / rows as f64).to_radians())
                .collect();
            let t: Vec<f64> = a
                .iter()
                .map(|&a| exact(l, g, a) + sigma * rng.next())
                .collect();
            let s = vec![sigma; rows];
            let r = analyse(&PeriodTableInput {
                period: &t,
                period_standard_error: weighted.then_some(s.as_slice()),
                amplitude: Some(&a),
                pendulum_length: Some(l),
                ..Default::default()
            })
            .unwrap();
            let t0 = 2.0 * PI * (l / g).sqrt();
            let within = |name: &str, truth: f64| {
                ((r.parameters[name] - truth) / r.standard_errors[name]).abs() <= 1.0
            };
            t0_in += within("small_angle_period_s", t0) as usize;
            g_in += within("g_m_s2", g) as usize;
            law_in += within("circular_error_coefficient", 0.0625) as usize;
            trials += 1;
        }
        // 68.3% of 2000, ± 3.3 binomial standard deviations (20.8).
        for (name, k) in [("T0", t0_in), ("g", g_in), ("c", law_in)] {
            let f = k as f64 / trials as f64;
            assert!((0.648..=0.718).contains(&f), "{name}: {k} of {trials}");
        }
    }

    #[test]
    fn a_length_table_gives_g_and_the_offset() {
        let mut rng = Normal(7);
        let (mut g_in, mut d_in) = (0, 0);
        for _ in 0..1000 {
            let l: Vec<f64> = (0..8).map(|i| 0.2 + 0.15 * i as f64).collect();
            let (g, d, sigma) = (9.803, 0.021, 2e-3);
            let t: Vec<f64> = l
                .iter()
                .map(|&l| exact(l + d, g, 0.1) + sigma * rng.next())
                .collect();
            let a = vec![0.1; 8];
            let s = vec![sigma; 8];
            let r = analyse(&PeriodTableInput {
                period: &t,
                period_standard_error: Some(&s),
                amplitude: Some(&a),
                length: Some(&l),
                ..Default::default()
            })
            .unwrap();
            assert_eq!(r.against, Against::Length);
            g_in += ((r.parameters["g_m_s2"] - g) / r.standard_errors["g_m_s2"])
                .abs()
                .le(&1.0) as usize;
            d_in += ((r.parameters["length_offset_m"] - d) / r.standard_errors["length_offset_m"])
                .abs()
                .le(&1.0) as usize;
        }
        assert!((630..=740).contains(&g_in), "g {g_in} of 1000");
        assert!((630..=740).contains(&d_in), "offset {d_in} of 1000");
    }

    #[test]
    fn a_bob_radius_makes_the_physical_pendulum() {
        // A 5 cm sphere on lengths to its centre: exact through the
        // equivalent length, with no offset.
        let r_bob = 0.05;
        let l: Vec<f64> = (0..6).map(|i| 0.15 + 0.2 * i as f64).collect();
        let t: Vec<f64> = l
            .iter()
            .map(|&l| 2.0 * PI * ((l * l + 0.4 * r_bob * r_bob) / (9.8 * l)).sqrt())
            .collect();
        let r = analyse(&PeriodTableInput {
            period: &t,
            length: Some(&l),
            bob_radius: Some(r_bob),
            ..Default::default()
        })
        .unwrap();
        assert!((r.parameters["g_m_s2"] / 9.8 - 1.0).abs() < 1e-12);
        assert!(r.parameters["length_offset_m"].abs() < 1e-12);
    }

    /// A length's uncertainty with no length is refused, not ignored (a
    /// table against lengths took it for nothing, from Python and the
    /// page, where the command line's --length-uncertainty needs --length).
    #[test]
    fn an_uncertainty_without_its_length_is_refused() {
        let l: Vec<f64> = (1..=6).map(|i| 0.2 * i as f64).collect();
        let t: Vec<f64> = l.iter().map(|&l| exact(l, 9.81, 0.05)).collect();
        let refused = analyse(&PeriodTableInput {
            period: &t,
            length: Some(&l),
            pendulum_length_standard_error: Some(0.002),
            ..Default::default()
        })
        .unwrap_err();
        assert_eq!(
            refused.place,
            crate::analysis::Place::Field("pendulum_length_standard_error")
        );
    }

    #[test]
    fn mistakes_are_named() {
        let l: Vec<f64> = (1..=6).map(|i| 0.2 * i as f64).collect();
        let t: Vec<f64> = l.iter().map(|&l| exact(l, 9.81, 0.05)).collect();
        let case = |t: &[f64], l: &[f64]| {
            analyse(&PeriodTableInput {
                period: t,
                length: Some(l),
                ..Default::default()
            })
            .unwrap()
            .warnings
            .iter()
            .map(|w| w.to_string())
            .collect::<Vec<_>>()
            .join("; ")
        };
        let cm: Vec<f64> = l.iter().map(|l| l * 100.0).collect();
        assert!(case(&t, &cm).contains("centimetres"), "{}", case(&t, &cm));
        let half: Vec<f64> = t.iter().map(|t| t / 2.0).collect();
        assert!(case(&half, &l).contains("half periods"));
        let ten: Vec<f64> = t.iter().map(|t| t * 10.0).collect();
        assert!(case(&ten, &l).contains("ten periods"));
        assert!(case(&t, &l).is_empty());
        // Amplitudes in radians read as degrees: the law differs and the
        // other unit is named.
        let a: Vec<f64> = (1..=8).map(|i| (10.0 * i as f64).to_radians()).collect();
        let t: Vec<f64> = a
            .iter()
            .map(|&a| exact(1.0, 9.81, a) * (1.0 + 1e-5))
            .collect();
        let read_wrong: Vec<f64> = a.iter().map(|a| a.to_radians()).collect();
        let s = vec![1e-4; 8];
        let r = analyse(&PeriodTableInput {
            period: &t,
            period_standard_error: Some(&s),
            amplitude: Some(&read_wrong),
            ..Default::default()
        })
        .unwrap();
        let text: Vec<String> = r.warnings.iter().map(|w| w.to_string()).collect();
        assert!(
            text.iter()
                .any(|w| w.contains("look like radians read as degrees")),
            "{text:?}"
        );
    }

    #[test]
    fn refusals_name_the_field() {
        let t = [2.0, 2.01];
        let cases: Vec<(PeriodTableInput<'_>, &str)> = vec![
            (
                PeriodTableInput {
                    period: &[2.0, -1.0],
                    ..Default::default()
                },
                "period",
            ),
            (
                PeriodTableInput {
                    period: &[2.0, f64::NAN],
                    ..Default::default()
                },
                "period",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    amplitude: Some(&[0.1]),
                    ..Default::default()
                },
                "amplitude",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    amplitude: Some(&[0.1, 4.0]),
                    ..Default::default()
                },
                "amplitude",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    length: Some(&[1.0, 0.0]),
                    ..Default::default()
                },
                "length",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    period_standard_error: Some(&[0.1, 0.0]),
                    ..Default::default()
                },
                "period_standard_error",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    pendulum_length: Some(-1.0),
                    ..Default::default()
                },
                "pendulum_length",
            ),
        ];
        for (input, field) in cases {
            let e = analyse(&input).unwrap_err();
            assert_eq!(e.field_name(), Some(field), "{e:?}");
        }
        // Numbers no pendulum has are refused, naming the row or the field.
        let huge = [2.0, 1e308];
        for (input, field) in [
            (
                PeriodTableInput {
                    period: &huge,
                    amplitude: Some(&[0.1, 0.2]),
                    ..Default::default()
                },
                "period",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    length: Some(&[1.0, 1e308]),
                    ..Default::default()
                },
                "length",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    period_standard_error: Some(&[1e-300, 0.1]),
                    ..Default::default()
                },
                "period_standard_error",
            ),
            (
                PeriodTableInput {
                    period: &t,
                    pendulum_length: Some(1e308),
                    ..Default::default()
                },
                "pendulum_length",
            ),
        ] {
            let e = analyse(&input).unwrap_err();
            assert_eq!(e.field_name(), Some(field), "{e:?}");
        }
        // A bob's radius with no length to correct.
        let e = analyse(&PeriodTableInput {
            period: &t,
            amplitude: Some(&[0.1, 0.2]),
            bob_radius: Some(0.02),
            ..Default::default()
        })
        .unwrap_err();
        assert_eq!(e.field_name(), Some("bob_radius"));
        // One row is the data's fault, not a field's.
        let e = analyse(&PeriodTableInput {
            period: &[2.0],
            ..Default::default()
        })
        .unwrap_err();
        assert_eq!(e.field_name(), None);
        assert!(e.reason.contains("at least two periods"), "{e:?}");
    }

    #[test]
    fn wilson_hilferty_matches_the_chi_square_quantiles() {
        // χ² quantiles at p = 0.999 (NIST/SEMATECH e-Handbook, table
        // 1.3.6.7.4): ν = 5: 20.515, ν = 10: 29.588, ν = 30: 59.703.
        for (nu, q) in [(5, 20.515), (10, 29.588), (30, 59.703)] {
            let z = chi_square_z(q, nu);
            assert!((z - 3.090).abs() < 0.03, "ν {nu}: z {z}");
        }
    }

    /// SciPy's `chi2.sf` (tools/reference/chi_square.py) from the tail to
    /// the bulk.
    #[test]
    fn the_chi_square_probability_is_scipys() {
        for (x, nu, p) in [
            (13.5, 4, 0.009074317061131603),
            (20.515, 5, 0.0010000024510678572),
            (3.0, 10, 0.9814240637778593),
            (100.0, 60, 0.0009168288614560842),
            (0.5, 1, 0.47950012218695337),
            (1e-3, 2, 0.9995001249791693),
            (250.0, 30, 1.5157414203687308e-36),
            (7.0, 7, 0.42887985755305486),
        ] {
            let q = chi_square_probability(x, nu);
            assert!((q / p - 1.0).abs() < 1e-12, "χ² {x} ν {nu}: {q} vs {p}");
        }
    }

    /// Issue 44: a length table whose χ² is 13.5 on 4 degrees of freedom
    /// (probability 0.009) warns, naming g, and widens its error by the
    /// Birge ratio √(13.5/4) = 1.84.
    #[test]
    fn a_chi_square_of_13_5_on_4_degrees_of_freedom_is_warned() {
        let l = [0.3, 0.5, 0.7, 0.9, 1.1, 1.3];
        let sigma = 2e-3;
        // Residuals in T of ±σ·k: χ² = Σk² after the fit's two
        // parameters; scaled to 13.5 below.
        let pattern = [1.0, -1.6, 0.4, 1.5, -1.9, 0.6];
        let t_of = |scale: f64| -> Vec<f64> {
            l.iter()
                .zip(&pattern)
                .map(|(&l, k)| 2.0 * PI * (l / 9.81_f64).sqrt() + scale * sigma * k)
                .collect()
        };
        let s = vec![sigma; 6];
        let fit = |t: &[f64]| {
            analyse(&PeriodTableInput {
                period: t,
                period_standard_error: Some(&s),
                length: Some(&l),
                ..Default::default()
            })
            .unwrap()
        };
        // The scale that makes χ² 13.5 (χ² grows nearly as its square).
        let mut scale = 1.0;
        for _ in 0..20 {
            scale *= (13.5 / fit(&t_of(scale)).chi_square.unwrap()).sqrt();
        }
        let r = fit(&t_of(scale));
        assert!(
            (r.chi_square.unwrap() - 13.5).abs() < 1e-6,
            "{:?}",
            r.chi_square
        );
        assert_eq!(r.degrees_of_freedom, 4);
        let p = r.chi_square_probability.unwrap();
        assert!((p - 0.009074317061131603).abs() < 1e-9, "{p}");
        let text: Vec<String> = r.warnings.iter().map(|w| w.to_string()).collect();
        assert!(
            text.iter()
                .any(|w| w.contains("g_m_s2") && w.contains("13.5")),
            "{text:?}"
        );
        // The same table with its χ² at 4 says nothing.
        let mut scale = 1.0;
        for _ in 0..20 {
            scale *= (4.0 / fit(&t_of(scale)).chi_square.unwrap()).sqrt();
        }
        let quiet = fit(&t_of(scale));
        assert!(quiet.warnings.is_empty(), "{:?}", quiet.warnings);
        let widened = r.standard_errors["g_m_s2"] / quiet.standard_errors["g_m_s2"];
        // Widened by √(13.5/4) = 1.84 (the unscaled errors of the two
        // tables differ by their periods' few parts in 10⁴).
        assert!(
            (widened / (13.5f64 / 4.0).sqrt() - 1.0).abs() < 1e-3,
            "{widened}"
        );
    }
}
