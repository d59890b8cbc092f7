//! The rate model's regression: generalised least squares under the noise
//! a clock's rate has, white frequency noise plus a random walk of the
//! rate, with the walk's share found by restricted maximum likelihood.
//!
//! Method: the binned rates are `y = Xβ + μ̄ + e`, `e` white with
//! variance `σ²/wᵢ` (`wᵢ` the bin's length over the median bin's: white
//! frequency noise averages down with time) and `μ̄ᵢ` the mean over bin
//! `i` of a continuous random walk `μ(t)` that moves by `ηᵢ`, variance
//! `Qᵢ = λσ²wᵢ`, over the bin, starting at zero (the constant in `X`
//! takes its start). A bin's mean is `μ̄ᵢ = μᵢ₋₁ + ξᵢ` with `Var ξ = Q/3`
//! and `Cov(ξ, η) = Q/2` (the walk's mean over the bin and its step are
//! correlated): a walk sampled at points instead would make neighbouring
//! bins' differences correlated by +¼ of the walk's part, which the fit
//! would read as less white noise than there is (a walk six times the
//! white noise a bin hides it all). The scalar Kalman filter with this
//! correlated noise (state `μᵢ₋₁`; innovation variance `F = P + Q/3 +
//! 1/w`, gain `(P + Q/2)/F`, next `P + Q − (P + Q/2)²/F`) turns `y` and
//! each column of `X` into its innovations over their standard
//! deviations, which are uncorrelated with unit variance: ordinary least
//! squares on them is the GLS estimate (A. C. Harvey, *Forecasting,
//! Structural Time Series Models and the Kalman Filter*, 1989, sections
//! 3.4 and 4.2; the restricted likelihood as D. A. Harville, JASA 72,
//! 1977). `λ` maximises the restricted likelihood, over a grid in
//! `log λ` refined by golden sections. Standard errors are
//! `σ̂² (X̃ᵀX̃)⁻¹`: on synthetic logs with white and random-walk frequency
//! noise every coefficient lies within 2 of them of its truth in 90% or
//! more of 100 seeds (test `clock_log.rs`).

use nalgebra::{DMatrix, DVector};

/// A fitted regression.
#[derive(Clone, Debug)]
pub(crate) struct Fit {
    /// The coefficients, in the order of the columns.
    pub beta: Vec<f64>,
    /// Their covariance.
    pub cov: DMatrix<f64>,
    /// The white noise's variance for a median bin, `σ̂²`.
    pub sigma2: f64,
    /// The random walk's variance a median bin, over `σ̂²`.
    pub lambda: f64,
    /// The maximised (not restricted) log-likelihood, for BIC.
    pub log_likelihood: f64,
    /// `y − Xβ̂` (the walk left in).
    pub residuals: Vec<f64>,
}

/// The filter's gains and innovation variances for `λ` and weights `w`
/// (the walk averaged over each bin: the module's method).
fn filter(w: &[f64], lambda: f64) -> (Vec<f64>, Vec<f64>) {
    let (mut gain, mut var) = (Vec::with_capacity(w.len()), Vec::with_capacity(w.len()));
    let mut p = 0.0;
    for &wi in w {
        let q = lambda * wi;
        let f = p + q / 3.0 + 1.0 / wi;
        let cross = p + q / 2.0;
        let k = cross / f;
        p = p + q - cross * cross / f;
        gain.push(k);
        var.push(f);
    }
    (gain, var)
}

/// The standardised innovations of `z`.
fn whiten(z: &[f64], gain: &[f64], var: &[f64]) -> Vec<f64> {
    let mut level = 0.0;
    z.iter()
        .zip(gain.iter().zip(var))
        .map(|(&zi, (&k, &f))| {
            let v = zi - level;
            level += k * v;
            v / f.sqrt()
        })
        .collect()
}

/// Least squares of `y` on the columns `x` under `λ`: `(β, X̃ᵀX̃, RSS,
/// Σ log F)`, or `None` when the columns are not independent.
fn solve(
    y: &[f64],
    x: &[Vec<f64>],
    w: &[f64],
    lambda: f64,
) -> Option<(DVector<f64>, DMatrix<f64>, f64, f64)> {
    let (gain, var) = filter(w, lambda);
    let n = y.len();
    let k = x.len();
    let yt = whiten(y, &gain, &var);
    let xt: Vec<Vec<f64>> = x.iter().map(|c| whiten(c, &gain, &var)).collect();
    let mut xtx = DMatrix::<f64>::zeros(k, k);
    let mut xty = DVector::<f64>::zeros(k);
    for a in 0..k {
        for b in a..k {
            let s: f64 = (0..n).map(|i| xt[a][i] * xt[b][i]).sum();
            xtx[(a, b)] = s;
            xtx[(b, a)] = s;
        }
        xty[a] = (0..n).map(|i| xt[a][i] * yt[i]).sum();
    }
    let chol = xtx.clone().cholesky()?;
    let beta = chol.solve(&xty);
    let rss: f64 = (0..n)
        .map(|i| {
            let fitted: f64 = (0..k).map(|a| xt[a][i] * beta[a]).sum();
            (yt[i] - fitted).powi(2)
        })
        .sum();
    let log_f: f64 = var.iter().map(|f| f.ln()).sum();
    Some((beta, xtx, rss, log_f))
}

/// The restricted log-likelihood at `λ` (σ² profiled out), up to a
/// constant.
fn restricted(y: &[f64], x: &[Vec<f64>], w: &[f64], lambda: f64) -> Option<f64> {
    let (_, xtx, rss, log_f) = solve(y, x, w, lambda)?;
    let dof = (y.len() - x.len()) as f64;
    let log_det = xtx
        .cholesky()?
        .l()
        .diagonal()
        .iter()
        .map(|d| 2.0 * d.ln())
        .sum::<f64>();
    Some(-0.5 * (dof * (rss / dof).ln() + log_f + log_det))
}

/// The random walk's share `λ` in a fit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Walk {
    /// Found by restricted maximum likelihood.
    Fitted,
    /// Held at this value (a search over another parameter).
    Fixed(f64),
    /// Found by restricted maximum likelihood within a decade of this
    /// value (or 0): a search over another parameter that moves it
    /// little from point to point.
    Near(f64),
}

/// Fits `y` (binned rates) on the columns `x` with bin weights `w`.
/// `None` when there are not more bins than columns or the columns are
/// dependent.
pub(crate) fn fit(y: &[f64], x: &[Vec<f64>], w: &[f64], walk: Walk) -> Option<Fit> {
    let (n, k) = (y.len(), x.len());
    if n <= k + 2 {
        return None;
    }
    let lambda = match walk {
        Walk::Fitted => best_lambda(y, x, w, None)?,
        Walk::Near(l) => best_lambda(y, x, w, Some(l))?,
        Walk::Fixed(l) => l,
    };
    let (beta, xtx, rss, log_f) = solve(y, x, w, lambda)?;
    let sigma2 = rss / (n - k) as f64;
    let cov = xtx.try_inverse()? * sigma2;
    let log_likelihood =
        -0.5 * (n as f64 * ((rss / n as f64).ln() + 1.0 + std::f64::consts::TAU.ln()) + log_f);
    let residuals = (0..n)
        .map(|i| y[i] - (0..k).map(|a| x[a][i] * beta[a]).sum::<f64>())
        .collect();
    Some(Fit {
        beta: beta.iter().copied().collect(),
        cov,
        sigma2,
        lambda,
        log_likelihood,
        residuals,
    })
}

/// The `λ` of the largest restricted likelihood: 0 or a point of a grid
/// in `log₁₀ λ` from −9 to 3 (or within a decade of `near`), refined by
/// golden sections to 0.01 in `log₁₀ λ`.
fn best_lambda(y: &[f64], x: &[Vec<f64>], w: &[f64], near: Option<f64>) -> Option<f64> {
    let at = |l: f64| restricted(y, x, w, 10f64.powf(l)).unwrap_or(f64::NEG_INFINITY);
    let zero = restricted(y, x, w, 0.0)?;
    let grid: Vec<f64> = match near.filter(|&l| l > 0.0) {
        Some(l) => (0..=4).map(|i| l.log10() - 1.0 + 0.5 * i as f64).collect(),
        None => (0..=24).map(|i| -9.0 + 0.5 * i as f64).collect(),
    };
    let values: Vec<f64> = grid.iter().map(|&l| at(l)).collect();
    let (i, &best) = values
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    if zero >= best {
        return Some(0.0);
    }
    let (mut a, mut b) = (grid[i.saturating_sub(1)], grid[(i + 1).min(grid.len() - 1)]);
    let phi = (5f64.sqrt() - 1.0) / 2.0;
    let (mut c, mut d) = (b - phi * (b - a), a + phi * (b - a));
    let (mut fc, mut fd) = (at(c), at(d));
    while b - a > 0.01 {
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - phi * (b - a);
            fc = at(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + phi * (b - a);
            fd = at(d);
        }
    }
    Some(10f64.powf(0.5 * (a + b)))
}

/// The rate averaged over the log (the constant plus the walk's weighted
/// mean over the bins) and its variance.
///
/// Method: with the walk `μ` starting at zero before the first bin, the
/// constant `β₀` is the rate there, and the log's mean rate is
/// `θ = β₀ + Σ cᵢ μ̄ᵢ` (`cᵢ` the bins' weights over their sum). The
/// filter is augmented with the running sum `S = Σ cᵢ μ̄ᵢ`: the state
/// `(μᵢ₋₁, S)` and the bin's noises `(ξᵢ, ηᵢ, eᵢ)` are updated jointly by
/// the bin's rate `μᵢ₋₁ + ξᵢ + eᵢ`, then moved on to `(μᵢ₋₁ + ηᵢ,
/// S + cᵢ(μᵢ₋₁ + ξᵢ))`. The last filtered `S` is `E[Σ cᵢ μ̄ᵢ | z]` for any
/// series `z = μ̄ + e`, a linear map `A z`, and its variance is
/// `Var(Σ cᵢ μ̄ᵢ | data, β)` (Durbin & Koopman, *Time Series Analysis by
/// State Space Methods*, 2012, section 4.3: the filtered final state is
/// the smoothed one). Then `θ̂ = β̂₀ + A(y − Xβ̂)` and, the smoothing error
/// being independent of `β̂`, `Var(θ̂ − θ) = σ² V_S + gᵀ Cov(β̂) g` with
/// `g = e₀ − A X`. Equal to the best linear unbiased prediction under the
/// full covariance to 1e-10 (test `mean_level_against_dense_gls`).
pub(crate) fn mean_level(fit: &Fit, y: &[f64], x: &[Vec<f64>], w: &[f64]) -> (f64, f64) {
    if fit.lambda <= 0.0 {
        return (fit.beta[0], fit.cov[(0, 0)]);
    }
    let total: f64 = w.iter().sum();
    let sum_of = |z: &[f64]| -> (f64, f64) {
        // The state (μ, S) and its covariance.
        let (mut mu, mut s) = (0.0, 0.0);
        let (mut p00, mut p01, mut p11) = (0.0, 0.0, 0.0);
        for (&zi, &wi) in z.iter().zip(w) {
            let c = wi / total;
            let q = fit.lambda * wi;
            // The observation's covariance with μ, S, ξ, η.
            let (h_mu, h_s, h_xi, h_eta) = (p00, p01, q / 3.0, q / 2.0);
            let f = p00 + q / 3.0 + 1.0 / wi;
            let v = zi - mu;
            // Posterior of (μ, S, ξ, η) given the innovation.
            let (m_mu, m_s, m_xi, m_eta) = (
                mu + h_mu / f * v,
                s + h_s / f * v,
                h_xi / f * v,
                h_eta / f * v,
            );
            // Posterior covariances needed for the move.
            let c_mumu = p00 - h_mu * h_mu / f;
            let c_mus = p01 - h_mu * h_s / f;
            let c_ss = p11 - h_s * h_s / f;
            let c_muxi = -h_mu * h_xi / f;
            let c_mueta = -h_mu * h_eta / f;
            let c_sxi = -h_s * h_xi / f;
            let c_seta = -h_s * h_eta / f;
            let c_xixi = q / 3.0 - h_xi * h_xi / f;
            let c_xieta = q / 2.0 - h_xi * h_eta / f;
            let c_etaeta = q - h_eta * h_eta / f;
            // Move: μ' = μ + η, S' = S + c(μ + ξ).
            mu = m_mu + m_eta;
            s = m_s + c * (m_mu + m_xi);
            let n00 = c_mumu + 2.0 * c_mueta + c_etaeta;
            let n01 = c_mus + c * (c_mumu + c_muxi) + c_seta + c * (c_mueta + c_xieta);
            let n11 = c_ss + 2.0 * c * (c_mus + c_sxi) + c * c * (c_mumu + 2.0 * c_muxi + c_xixi);
            (p00, p01, p11) = (n00, n01, n11);
        }
        (s, p11)
    };
    let (ay, vs) = sum_of(y);
    let ax: Vec<f64> = x.iter().map(|c| sum_of(c).0).collect();
    let fitted: f64 = ax.iter().zip(&fit.beta).map(|(a, b)| a * b).sum();
    let theta = fit.beta[0] + ay - fitted;
    let k = x.len();
    let g: Vec<f64> = (0..k)
        .map(|a| f64::from(u8::from(a == 0)) - ax[a])
        .collect();
    let mut var = fit.sigma2 * vs;
    for a in 0..k {
        for b in 0..k {
            var += g[a] * fit.cov[(a, b)] * g[b];
        }
    }
    (theta, var.max(0.0))
}

/// The walk smoothed (Rauch–Tung–Striebel) through `r = y − Xβ̂` for `λ`:
/// `E[μᵢ | r]` a bin (zeros when `λ = 0`).
pub(crate) fn smoothed_walk(r: &[f64], w: &[f64], lambda: f64) -> Vec<f64> {
    let n = r.len();
    if lambda <= 0.0 || n == 0 {
        return vec![0.0; n];
    }
    let (mut filtered, mut var, mut predicted) = (
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    let (mut mu, mut p) = (0.0, 0.0);
    for (&ri, &wi) in r.iter().zip(w) {
        let pred = p + lambda * wi;
        predicted.push(pred);
        let f = pred + 1.0 / wi;
        let k = pred / f;
        mu += k * (ri - mu);
        p = pred * (1.0 - k);
        filtered.push(mu);
        var.push(p);
    }
    let mut smooth = filtered.clone();
    for i in (0..n - 1).rev() {
        let c = var[i] / predicted[i + 1];
        smooth[i] = filtered[i] + c * (smooth[i + 1] - filtered[i]);
    }
    smooth
}

/// The standardised innovations of `r` (the residuals `y − Xβ̂`) under
/// the walk's share `λ`: uncorrelated with unit variance times `σ²` when
/// the noise model holds.
pub(crate) fn innovations(r: &[f64], w: &[f64], lambda: f64) -> Vec<f64> {
    let (gain, var) = filter(w, lambda);
    whiten(r, &gain, &var)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_noise::normals;

    /// The mean level and its variance against generalised least squares
    /// with the whole covariance written out: `y = Xβ + Lη + e`, the
    /// walk's `Lη` a cumulative sum. The dense estimate of `θ = β₀ + cᵀμ`
    /// is `β̂₀ + cᵀ K Lᵀ... ` computed as the best linear unbiased
    /// predictor: `θ̂ = e₀ᵀβ̂ + cᵀ Σ_μ V⁻¹ (y − Xβ̂)`, its error variance
    /// from the joint covariance of `(y, θ)`.
    #[test]
    fn mean_level_against_dense_gls() {
        let n = 40;
        let w: Vec<f64> = (0..n)
            .map(|i| 0.6 + 0.8 * ((i * 7 % 11) as f64 / 11.0))
            .collect();
        let lambda = 0.07;
        let sigma2 = 1.0;
        let e = normals(n, 17);
        let steps = normals(n, 99);
        let mut mu = 0.0;
        let t: Vec<f64> = (0..n).map(|i| i as f64 / n as f64 - 0.5).collect();
        let y: Vec<f64> = (0..n)
            .map(|i| {
                let before = mu;
                mu += (lambda * w[i]).sqrt() * steps[i];
                0.3 + 0.8 * t[i] + 0.5 * (before + mu) + e[i] / w[i].sqrt()
            })
            .collect();
        let x = vec![vec![1.0; n], t.clone()];
        let fit = fit(&y, &x, &w, Walk::Fixed(lambda)).unwrap();
        let (theta, var) = mean_level(&fit, &y, &x, &w);
        // Dense: the bins' means of the walk, Cov(μ̄ᵢ, μ̄ⱼ) = Σ_{k<i} Q_k +
        // Q_i/2 for i < j, + Q_i/3 for i = j; V = Σ_μ + diag(1/w).
        let before: Vec<f64> = w
            .iter()
            .scan(0.0, |s, wi| {
                let b = *s;
                *s += lambda * wi;
                Some(b)
            })
            .collect();
        let smu = DMatrix::from_fn(n, n, |i, j| {
            let (a, b) = (i.min(j), i.max(j));
            let q = lambda * w[a];
            sigma2 * (before[a] + if a == b { q / 3.0 } else { q / 2.0 })
        });
        let v = &smu + DMatrix::from_fn(n, n, |i, j| if i == j { sigma2 / w[i] } else { 0.0 });
        let vi = v.clone().try_inverse().unwrap();
        let xm = DMatrix::from_fn(n, 2, |i, a| x[a][i]);
        let yv = DVector::from_column_slice(&y);
        let xtvx = xm.transpose() * &vi * &xm;
        let cov_beta = xtvx.clone().try_inverse().unwrap();
        let beta = &cov_beta * xm.transpose() * &vi * &yv;
        let total: f64 = w.iter().sum();
        let c = DVector::from_iterator(n, w.iter().map(|wi| wi / total));
        // Cov(cᵀμ, y) = cᵀ Σ_μ.
        let k = c.transpose() * &smu;
        let resid = &yv - &xm * &beta;
        let dense_theta = beta[0] + (&k * &vi * &resid)[(0, 0)];
        // Error variance of the BLUP with β estimated (Henderson):
        // cᵀΣc − k V⁻¹ kᵀ + (e₀ − X ᵀ V⁻¹ kᵀ)ᵀ Cov(β̂) (…).
        let e0 = DVector::from_column_slice(&[1.0, 0.0]);
        let g = e0 - xm.transpose() * &vi * k.transpose();
        let dense_var = (c.transpose() * &smu * &c)[(0, 0)] - (&k * &vi * k.transpose())[(0, 0)]
            + (g.transpose() * &cov_beta * &g)[(0, 0)];
        assert!(
            (theta - dense_theta).abs() < 1e-10,
            "{theta} against {dense_theta}"
        );
        // The fit's σ̂² is estimated; the dense one takes σ² = 1: compare
        // on the same σ².
        let scaled = var / fit.sigma2;
        assert!(
            (scaled / dense_var - 1.0).abs() < 1e-9,
            "{scaled} against {dense_var}"
        );
        // The dense fit's coefficients are the filter's.
        assert!((beta[1] - fit.beta[1]).abs() < 1e-10);
    }
}
