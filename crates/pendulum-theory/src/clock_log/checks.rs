//! The fit checked against what it leaves and against the design.
//!
//! Under the noise model (white frequency noise and a random walk of the
//! rate) the filter's standardised innovations are uncorrelated. Their
//! long-run variance (Newey & West, Econometrica 55, 1987: the Bartlett
//! kernel over `L = ⌊4 (m/100)^{2/9}⌋` lags) says how much more the
//! residuals hold than the model says at the long periods the rate and
//! the coefficients are read from: when it exceeds 1 by more than three
//! of its own standard deviations under the model, every standard error
//! is widened by its square root and a warning says so. A wander the
//! noise model missed (a walk too small to see bin to bin, which adds up
//! over months) shows at the longest periods instead: the innovations'
//! means over eight equal blocks scatter more than their count allows (a
//! χ² test at 0.1%); the standard errors are then widened by the square
//! root of the excess. Whichever widening is larger is used.

use super::choice::{Choice, Design};
use super::model::{innovations, Fit};
use super::result::{Coefficients, DesignComparison, LogWarning, Predicted};
use super::series::Bins;
use super::terms::TERMS;
use crate::analysis::Refusal;
use crate::compound::datasheet::Air;
use crate::compound::description::Design as PendulumDesign;

/// What the checks found.
pub(crate) struct Checked {
    /// The factor on every standard error (1: none).
    pub widen: f64,
    pub warnings: Vec<LogWarning>,
}

/// The residuals checked against the noise model.
pub(crate) fn check(
    fit: &Fit,
    _walk: &[f64],
    bins: &Bins,
    _design: &Design,
    _choice: &Choice,
) -> Checked {
    let e = innovations(&fit.residuals, &bins.weight, fit.lambda);
    let m = e.len();
    let mean = e.iter().sum::<f64>() / m as f64;
    let c0 = e.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / m as f64;
    let lags = (4.0 * (m as f64 / 100.0).powf(2.0 / 9.0)).floor() as usize;
    let mut warnings = Vec::new();
    if c0 <= 0.0 || lags == 0 || m < 20 {
        return Checked {
            widen: 1.0,
            warnings,
        };
    }
    let rho = |l: usize| {
        (l..m)
            .map(|i| (e[i] - mean) * (e[i - l] - mean))
            .sum::<f64>()
            / m as f64
            / c0
    };
    let (mut sum, mut spread) = (0.0, 0.0);
    for l in 1..=lags {
        let k = 1.0 - l as f64 / (lags + 1) as f64;
        sum += k * rho(l);
        spread += k * k;
    }
    let long_run = 1.0 + 2.0 * sum;
    // Under the model each ρ has variance 1/m.
    let sd = 2.0 * (spread / m as f64).sqrt();
    let mut widen: f64 = 1.0;
    if long_run - 1.0 > 3.0 * sd {
        widen = long_run.sqrt();
    }
    // The blocks' means against their count: χ² with K − 1 degrees.
    const BLOCKS: usize = 8;
    if m >= 10 * BLOCKS {
        let q: f64 = (0..BLOCKS)
            .map(|k| {
                let (a, b) = (k * m / BLOCKS, (k + 1) * m / BLOCKS);
                let n = (b - a) as f64;
                let mk = e[a..b].iter().sum::<f64>() / n;
                n * (mk - mean).powi(2) / c0
            })
            .sum();
        let dof = (BLOCKS - 1) as f64;
        let p = statrs::distribution::ChiSquared::new(dof).map_or(1.0, |c| {
            1.0 - statrs::distribution::ContinuousCDF::cdf(&c, q)
        });
        if p < 1e-3 {
            widen = widen.max((q / dof).sqrt());
        }
    }
    if widen > 1.0 {
        warnings.push(LogWarning::ErrorsWidened {
            factor: widen,
            autocorrelation: rho(1),
        });
    }
    Checked { widen, warnings }
}

/// The design's predictions at the log's mean weather beside the
/// measured coefficients.
pub(crate) fn against_design(
    d: &PendulumDesign,
    means: &[(usize, f64)],
    coefficients: &Coefficients,
    errors: &Coefficients,
) -> Result<DesignComparison, Refusal> {
    let mean_of = |name: &str| {
        means
            .iter()
            .find(|(i, _)| TERMS[*i].name == name)
            .map(|m| m.1)
    };
    let air = Air {
        pressure_pa: mean_of("pressure").map(|p| p * 100.0),
        temperature_c: mean_of("temperature"),
        humidity: Some(mean_of("humidity").map_or(0.5, |h| h / 100.0)),
        ..Air::default()
    };
    let mut predictions = Vec::new();
    for t in TERMS.iter() {
        if let Some(predict) = t.predicted {
            let predicted = predict(d, &air)?;
            let difference_se = coefficients
                .get(t.name)
                .zip(errors.get(t.name))
                .map(|(v, s)| (v - predicted) / s);
            predictions.push(Predicted {
                term: t,
                predicted,
                difference_se,
            });
        }
    }
    Ok(DesignComparison { predictions })
}
