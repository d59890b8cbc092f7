//! Fitting the theory to measurements: weighted nonlinear least squares
//! with parameter standard errors, and the decay, beat and trajectory
//! analyses built on it.
//!
//! The minimisation is the maintained `levenberg-marquardt` crate (a port of
//! MINPACK's `lmder`); this module adds what a scientist needs around it:
//! a curve model in a few lines, a Jacobian by central differences, the
//! covariance `s² (JᵀJ)⁻¹` with `s² = RSS/(n - k)` (or, with known
//! uncertainties, `(JᵀWJ)⁻¹`), and the information criteria
//! `AIC = n ln(RSS/n) + 2k`, `BIC = n ln(RSS/n) + k ln n` used to choose
//! between models.

pub mod beat_log;
pub mod beats;
pub mod crest;
pub mod decay;
pub mod frames;
pub mod gyroscope;
pub mod period_table;
pub mod periodic;
pub mod photogate;
pub mod quality;
pub mod rundown;
pub mod track;
pub mod tracked;
pub mod trajectory;
pub mod turning;

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};

/// A curve `y = f(x; p)` with named parameters.
pub trait Curve {
    /// The value at `x` for parameters `p`.
    fn value(&self, x: f64, p: &[f64]) -> f64;
}

/// Any closure `f(x, p)` is a curve.
impl<F: Fn(f64, &[f64]) -> f64> Curve for F {
    fn value(&self, x: f64, p: &[f64]) -> f64 {
        self(x, p)
    }
}

/// The result of a least-squares fit.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    /// Best-fit parameters.
    pub parameters: Vec<f64>,
    /// Their standard errors (square roots of the covariance's diagonal).
    pub standard_errors: Vec<f64>,
    /// Their covariance (scaled as the standard errors are), row by row:
    /// what a figure derived from several parameters takes its standard
    /// error from ([`propagate`]).
    pub covariance: Vec<Vec<f64>>,
    /// Residuals `y - f(x; p)` at the optimum.
    pub residuals: Vec<f64>,
    /// Root mean square of the residuals.
    pub residual_rms: f64,
    /// Akaike's information criterion (Gaussian errors).
    pub aic: f64,
    /// The Bayesian (Schwarz) information criterion.
    pub bic: f64,
}

/// What a standard error is made of, for a figure derived from a fit and
/// a measured input (g from a frequency and a length): the fit's part, and
/// the length's when its uncertainty was given (`None`: not given, and not
/// in the standard error, which is then the fit's alone). The standard
/// error is their sum in quadrature.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ErrorParts {
    /// From the fit (the frequency or period's standard error).
    pub fit: f64,
    /// From the length's uncertainty; `None` when none was given.
    pub length: Option<f64>,
}

impl ErrorParts {
    /// The parts of g's standard error, for `g ∝ l` with the fit's part
    /// `fit` and the length `length` (m) known to `length_error` (m).
    pub fn gravity(g: f64, fit: f64, length: f64, length_error: Option<f64>) -> Self {
        Self {
            fit,
            length: length_error
                .filter(|e| e.is_finite() && length > 0.0)
                .map(|e| g * e / length),
        }
    }

    /// The whole standard error, the parts in quadrature.
    pub fn total(&self) -> f64 {
        self.fit.hypot(self.length.unwrap_or(0.0))
    }
}

/// Why a fit failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FitError {
    /// Fewer points than parameters (or exactly as many: no error estimate).
    #[error(
        "{points} points cannot fit a model with {parameters} parameters; more points are needed"
    )]
    TooFewPoints {
        /// Points given.
        points: usize,
        /// Parameters of the model.
        parameters: usize,
    },
    /// The minimiser gave up.
    #[error("the fit did not converge ({0})")]
    NoConvergence(String),
    /// The parameters are not determined by the data (singular JᵀJ).
    #[error("the data do not determine all parameters of this model")]
    Singular,
}

struct Problem<'a, C: Curve> {
    curve: &'a C,
    x: &'a [f64],
    y: &'a [f64],
    weights: Option<&'a [f64]>,
    p: DVector<f64>,
}

impl<C: Curve> Problem<'_, C> {
    fn weighted_residual(&self, i: usize, p: &[f64]) -> f64 {
        let r = self.y[i] - self.curve.value(self.x[i], p);
        self.weights.map_or(r, |w| r * w[i])
    }
}

impl<C: Curve> LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_, C> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, p: &DVector<f64>) {
        self.p.copy_from(p);
    }

    fn params(&self) -> DVector<f64> {
        self.p.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        let p = self.p.as_slice();
        let r = DVector::from_fn(self.x.len(), |i, _| self.weighted_residual(i, p));
        r.iter().all(|v| v.is_finite()).then_some(r)
    }

    /// The minimiser's Jacobian: forward differences (see
    /// [`Problem::differences`]), one evaluation of the curve a parameter.
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        self.differences(false)
    }
}

impl<C: Curve> Problem<'_, C> {
    /// The Jacobian of the weighted residuals by finite differences with
    /// step `h = ε^(1/3) max(|p_j|, 1e-8)`. Central (`central`): truncation
    /// and rounding balance at about `ε^(2/3)`, 4e-11 relative: the
    /// covariance of the result. Forward otherwise: errs by about `h`
    /// relative (6e-6), which moves the minimiser's steps and not the
    /// minimum it settles at (the residuals decide that), for half the
    /// evaluations: each evaluation of a simulated curve integrates the
    /// whole record, so the nonlinear fits take about half the time
    /// (the step is the central one's, not MINPACK's `√ε |p|`: a
    /// simulated curve's integration error, 1e-12, divided by `√ε`
    /// would be 1e-4 of a derivative). The residuals at `p` itself are
    /// the curve's last evaluation (a simulated curve keeps it).
    fn differences(&self, central: bool) -> Option<DMatrix<f64>> {
        let n = self.x.len();
        let k = self.p.len();
        let mut jac = DMatrix::zeros(n, k);
        let mut p = self.p.as_slice().to_vec();
        let base: Vec<f64> = if central {
            Vec::new()
        } else {
            (0..n).map(|i| self.weighted_residual(i, &p)).collect()
        };
        for j in 0..k {
            let original = p[j];
            let step = f64::EPSILON.cbrt() * original.abs().max(1e-8);
            p[j] = original + step;
            let plus: Vec<f64> = (0..n).map(|i| self.weighted_residual(i, &p)).collect();
            if central {
                p[j] = original - step;
                for i in 0..n {
                    jac[(i, j)] = (plus[i] - self.weighted_residual(i, &p)) / (2.0 * step);
                }
            } else {
                for i in 0..n {
                    jac[(i, j)] = (plus[i] - base[i]) / step;
                }
            }
            p[j] = original;
        }
        jac.iter().all(|v| v.is_finite()).then_some(jac)
    }
}

/// Fits `curve` to the points `(x, y)` from `initial` parameters.
/// With `sigma` (the standard uncertainty of each `y`), the fit is weighted
/// by `1/σ²` and the covariance is `(JᵀWJ)⁻¹`; without, the covariance is
/// scaled by the residual variance.
pub fn fit_curve(
    curve: &impl Curve,
    x: &[f64],
    y: &[f64],
    sigma: Option<&[f64]>,
    initial: &[f64],
) -> Result<Fit, FitError> {
    fit_with(curve, x, y, sigma, initial, 200)
}

/// [`fit_curve`] unweighted, giving up after `patience` evaluations per
/// parameter (and one) where [`fit_curve`] allows 200: for costly curves
/// tried on the chance that they fit better.
pub fn fit_curve_patient(
    curve: &impl Curve,
    x: &[f64],
    y: &[f64],
    initial: &[f64],
    patience: usize,
) -> Result<Fit, FitError> {
    fit_with(curve, x, y, None, initial, patience)
}

fn fit_with(
    curve: &impl Curve,
    x: &[f64],
    y: &[f64],
    sigma: Option<&[f64]>,
    initial: &[f64],
    patience: usize,
) -> Result<Fit, FitError> {
    let (n, k) = (x.len(), initial.len());
    if n <= k {
        return Err(FitError::TooFewPoints {
            points: n,
            parameters: k,
        });
    }
    let weights: Option<Vec<f64>> = sigma.map(|s| s.iter().map(|v| 1.0 / v).collect());
    let problem = Problem {
        curve,
        x,
        y,
        weights: weights.as_deref(),
        p: DVector::from_column_slice(initial),
    };
    let (problem, report) = LevenbergMarquardt::new()
        .with_patience(patience)
        .minimize(problem);
    if !report.termination.was_successful() {
        return Err(FitError::NoConvergence(termination(&report.termination)));
    }
    let jac = problem.differences(true).ok_or(FitError::Singular)?;
    let p = problem.p.as_slice().to_vec();
    let residuals: Vec<f64> = (0..n).map(|i| y[i] - curve.value(x[i], &p)).collect();
    let rss: f64 = residuals.iter().map(|r| r * r).sum();
    let weighted_rss: f64 = (0..n)
        .map(|i| problem.weighted_residual(i, &p).powi(2))
        .sum();
    let information = jac.transpose() * &jac;
    let covariance = information.try_inverse().ok_or(FitError::Singular)?;
    let scale = if sigma.is_some() {
        1.0
    } else {
        weighted_rss / (n - k) as f64
    };
    let standard_errors = (0..k)
        .map(|j| (scale * covariance[(j, j)]).max(0.0).sqrt())
        .collect();
    let covariance = (0..k)
        .map(|r| (0..k).map(|c| scale * covariance[(r, c)]).collect())
        .collect();
    let nf = n as f64;
    let log_likelihood_term = nf * (weighted_rss / nf).max(f64::MIN_POSITIVE).ln();
    Ok(Fit {
        parameters: p,
        standard_errors,
        covariance,
        residual_rms: (rss / nf).sqrt(),
        aic: log_likelihood_term + 2.0 * k as f64,
        bic: log_likelihood_term + k as f64 * nf.ln(),
        residuals,
    })
}

/// The standard error of a figure `f(p)` of a fit's parameters, by first
/// order propagation (the delta method: `√(∇fᵀ C ∇f)`), the gradient
/// by central differences of `f` with steps of a tenth of each
/// parameter's standard error (where the figure is as good as linear,
/// whatever the parameter's size; a parameter known exactly is not
/// stepped). `None` when `f` has no finite value at a step.
///
/// Accuracy: exact for a figure linear in the parameters; for smooth
/// ones the central difference errs by `f'''h²/6`, a few parts in 10⁴ of
/// the standard error at `h = σ/10` (measured on `1/x` at 1σ = 10%).
pub fn propagate(fit: &Fit, f: impl Fn(&[f64]) -> Option<f64>) -> Option<f64> {
    let k = fit.parameters.len();
    let mut gradient = vec![0.0; k];
    let mut p = fit.parameters.clone();
    for j in 0..k {
        let h = 0.1 * fit.standard_errors[j];
        if !(h > 0.0 && h.is_finite()) {
            continue;
        }
        let original = p[j];
        p[j] = original + h;
        let plus = f(&p)?;
        p[j] = original - h;
        let minus = f(&p)?;
        p[j] = original;
        gradient[j] = (plus - minus) / (2.0 * h);
    }
    let variance: f64 = (0..k)
        .flat_map(|r| (0..k).map(move |c| (r, c)))
        .map(|(r, c)| gradient[r] * fit.covariance[r][c] * gradient[c])
        .sum();
    (variance.is_finite()).then(|| variance.max(0.0).sqrt())
}

/// Why the minimiser stopped, in words (its enum's names are not for
/// people: `User("residuals")` is a model with no value at a guess).
fn termination(reason: &levenberg_marquardt::TerminationReason) -> String {
    use levenberg_marquardt::TerminationReason as T;
    match reason {
        T::User(_) | T::Numerical(_) => "the model has no finite value at the parameters tried: \
                                         the record may not be a pendulum's swing"
            .to_string(),
        T::LostPatience => "it did not settle within its budget of evaluations".to_string(),
        T::NoImprovementPossible(_) => "no step improves it, short of its tolerance".to_string(),
        other => format!("{other:?}"),
    }
}

/// The independent noise of a series from its fourth differences, which
/// cancel any smooth pattern: `1.4826 · median|Δ⁴r| / √70` (a normal
/// deviate's robust deviation; `Δ⁴` of white noise has variance `70σ²`),
/// at least the [`rounding_noise`] of the values.
/// `None` for fewer than 20 values or none that differ.
pub fn noise_of(values: &[f64]) -> Option<f64> {
    if values.len() < 20 {
        return None;
    }
    let mut d4: Vec<f64> = values
        .windows(5)
        .map(|w| (w[0] - 4.0 * w[1] + 6.0 * w[2] - 4.0 * w[3] + w[4]).abs())
        .collect();
    d4.sort_by(f64::total_cmp);
    let noise = (1.4826 * d4[d4.len() / 2] / 70f64.sqrt()).max(rounding_noise(values));
    (noise > 0.0 && noise.is_finite()).then_some(noise)
}

/// The rounding noise of values read in steps (an encoder's counts, whole
/// pixels, a file's last digit): `q / √12` for the smallest step `q`
/// between successive values (0 when none differ). The fourth differences
/// of such values are mostly 0, and their median says nothing.
pub fn rounding_noise(values: &[f64]) -> f64 {
    let step = values
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .filter(|d| *d > 0.0)
        .fold(f64::INFINITY, f64::min);
    if step.is_finite() {
        step / 12f64.sqrt()
    } else {
        0.0
    }
}

/// The median of `values` (sorted in place; the upper one of an even
/// count; 0 for none).
pub(crate) fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Least-squares line `y = a + b x`: `(a, b)`.
pub fn straight_line(x: &[f64], y: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    (my - slope * mx, slope)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_a_line_exactly() {
        let x: Vec<f64> = (0..10).map(f64::from).collect();
        let y: Vec<f64> = x.iter().map(|v| 2.0 + 0.5 * v).collect();
        let line = |x: f64, p: &[f64]| p[0] + p[1] * x;
        let fit = fit_curve(&line, &x, &y, None, &[1.0, 1.0]).unwrap();
        assert!((fit.parameters[0] - 2.0).abs() < 1e-10);
        assert!((fit.parameters[1] - 0.5).abs() < 1e-10);
        assert!(fit.residual_rms < 1e-10);
    }

    #[test]
    fn standard_errors_of_a_line_match_the_textbook() {
        // y = a + b x with residuals ±1 alternating: se(b) = s / sqrt(Sxx).
        let x: Vec<f64> = (0..20).map(f64::from).collect();
        let y: Vec<f64> = x
            .iter()
            .enumerate()
            .map(|(i, v)| 1.0 + 2.0 * v + if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        let line = |x: f64, p: &[f64]| p[0] + p[1] * x;
        let fit = fit_curve(&line, &x, &y, None, &[0.0, 0.0]).unwrap();
        let rss: f64 = fit.residuals.iter().map(|r| r * r).sum();
        let s2 = rss / 18.0;
        let mx = 9.5;
        let sxx: f64 = x.iter().map(|v| (v - mx) * (v - mx)).sum();
        let se_b = (s2 / sxx).sqrt();
        assert!((fit.standard_errors[1] / se_b - 1.0).abs() < 1e-6);
    }

    #[test]
    fn too_few_points() {
        let line = |x: f64, p: &[f64]| p[0] + p[1] * x;
        assert!(matches!(
            fit_curve(&line, &[1.0, 2.0], &[1.0, 2.0], None, &[0.0, 0.0]),
            Err(FitError::TooFewPoints { .. })
        ));
    }
}
