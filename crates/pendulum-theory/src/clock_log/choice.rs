//! The rate model's terms chosen and its lag found.
//!
//! * The design: each term of [`super::terms::TERMS`] a column a bin,
//!   centred on its mean weighted by the bins' time (so the constant is
//!   the log's mean rate at its mean weather), the steps at the events,
//!   and for a lagged term its start `exp(−(t − t₀)/τ)` (the compensator's
//!   unknown state when the log begins).
//! * The lag: the profile likelihood over `τ` (0, then a grid from a
//!   quarter bin up to half the log, a factor √2 apart, the best refined
//!   by golden sections in `ln τ`), the random walk's share held; its 95%
//!   range is where the profile is within 1.92 (χ²₁/2) of its best, the
//!   crossings found by bisection. A lag at 0 is an answer only with its
//!   range ("no lag, under X"); one at the longest the log tells is
//!   flagged.
//! * The choice: backward elimination by the Bayesian information
//!   criterion from every term the log allows and the random walk, each
//!   counted as one parameter (the lag as another); the walk is kept only
//!   when the residuals need it, so a drift is not read as a wander.

use super::model::{fit, Fit, Walk};
use super::series::{Bins, Coarse};
use super::terms::{Source, TERMS};

/// The candidate regressors.
pub(crate) struct Design {
    /// Each table term's column a bin, centred (`None`: the log lacks it).
    pub columns: Vec<Option<Vec<f64>>>,
    /// Each column's weighted mean, in the variable's unit.
    pub means: Vec<Option<f64>>,
    /// The steps at the events.
    pub steps: Vec<Vec<f64>>,
    /// Each lagged term's start, when its lag is positive.
    pub transients: Vec<Option<Vec<f64>>>,
    /// Each lagged term's lag, s.
    pub lags: Vec<f64>,
    /// The bins' time-weighted mean time, s.
    pub t_ref: f64,
}

/// Which terms a model holds.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Choice {
    /// A table term each.
    pub terms: Vec<bool>,
    /// The random walk of the rate.
    pub walk: bool,
}

impl Design {
    /// The columns of a model: the constant, the kept terms, the steps,
    /// the kept lagged terms' starts.
    pub fn matrix(&self, choice: &Choice, m: usize) -> Vec<Vec<f64>> {
        let mut x = vec![vec![1.0; m]];
        for (c, &k) in self.columns.iter().zip(&choice.terms) {
            if let (Some(c), true) = (c, k) {
                x.push(c.clone());
            }
        }
        x.extend(self.steps.iter().cloned());
        for (i, t) in self.transients.iter().enumerate() {
            if let (Some(t), true) = (t, choice.terms[i]) {
                x.push(t.clone());
            }
        }
        x
    }

    /// The names of a model's columns.
    pub fn names(&self, choice: &Choice) -> Vec<String> {
        let mut names = vec!["rate".to_string()];
        for (i, t) in TERMS.iter().enumerate() {
            if choice.terms[i] && self.columns[i].is_some() {
                names.push(t.name.to_string());
            }
        }
        for k in 0..self.steps.len() {
            names.push(format!("step_{}", k + 1));
        }
        for (i, t) in self.transients.iter().enumerate() {
            if t.is_some() && choice.terms[i] {
                names.push(format!("{}_start", TERMS[i].name));
            }
        }
        names
    }

    /// The model's parameters for the criterion: its columns, σ² and
    /// each kept lag (the walk is judged apart).
    fn parameters(&self, choice: &Choice, m: usize) -> usize {
        let lags = TERMS
            .iter()
            .enumerate()
            .filter(|(i, t)| {
                t.source == Source::LaggedColumn && choice.terms[*i] && self.columns[*i].is_some()
            })
            .count();
        self.matrix(choice, m).len() + 1 + lags
    }

    /// Sets lagged term `i`'s column for lag `tau` from its binned means.
    pub fn set_lagged(&mut self, i: usize, binned: Vec<f64>, tau: f64, bins: &Bins, t0: f64) {
        let (c, mean) = centred(&binned, &bins.weight);
        self.columns[i] = Some(c);
        self.means[i] = Some(mean);
        self.lags[i] = tau;
        // The start, centred as the other columns are: the constant stays
        // the log's mean rate.
        self.transients[i] = (tau > 0.0).then(|| {
            let start: Vec<f64> = bins
                .centre
                .iter()
                .map(|&t| (-(t - t0) / tau).exp())
                .collect();
            centred(&start, &bins.weight).0
        });
    }
}

/// `v` less its mean weighted by `w` (non-finite values become 0, the
/// mean), and the mean.
pub(crate) fn centred(v: &[f64], w: &[f64]) -> (Vec<f64>, f64) {
    let (mut s, mut ws) = (0.0, 0.0);
    for (x, wi) in v.iter().zip(w) {
        if x.is_finite() {
            s += wi * x;
            ws += wi;
        }
    }
    let mu = if ws > 0.0 { s / ws } else { 0.0 };
    (
        v.iter()
            .map(|x| if x.is_finite() { x - mu } else { 0.0 })
            .collect(),
        mu,
    )
}

/// The fit of a choice (the walk's share found, or 0 without it).
pub(crate) fn fit_choice(design: &Design, choice: &Choice, bins: &Bins) -> Option<Fit> {
    let m = bins.rate.len();
    let walk = if choice.walk {
        Walk::Fitted
    } else {
        Walk::Fixed(0.0)
    };
    fit(&bins.rate, &design.matrix(choice, m), &bins.weight, walk)
}

/// What keeping the random walk costs in the criterion: the 5% point of
/// the likelihood-ratio test of a variance at its bound of 0, the
/// 50:50 mixture of χ²₀ and χ²₁ (Self & Liang, JASA 82, 1987), 2.706.
/// A walk is noise, not a term: missing a real one makes every slow
/// figure's standard error too small, so it is kept on this test's
/// evidence rather than on the stricter ln m of a term.
const WALK_COST: f64 = 2.705_543_454_095_404;

/// The Bayesian information criterion of a fit (the walk at
/// [`WALK_COST`]).
pub(crate) fn bic(f: &Fit, design: &Design, choice: &Choice, m: usize) -> f64 {
    -2.0 * f.log_likelihood
        + design.parameters(choice, m) as f64 * (m as f64).ln()
        + if choice.walk { WALK_COST } else { 0.0 }
}

/// A term judged: its ΔBIC (without it less with it) and its coefficient
/// and standard error in the model with it.
pub(crate) struct Judged {
    pub delta_bic: f64,
    pub estimate: Option<(f64, f64)>,
}

/// A choice, its fit, and what each candidate was judged (term index,
/// or `TERMS.len()` for the walk; kept or not).
pub(crate) type Chosen = (Choice, Fit, Vec<(usize, bool, Judged)>);

/// Backward elimination by BIC from `start`: each round drops the term
/// (or the walk) whose removal lowers the criterion most, until none
/// does. Returns the choice, its fit, and what each candidate was judged
/// (term index, or `TERMS.len()` for the walk).
pub(crate) fn choose(design: &Design, start: Choice, bins: &Bins) -> Option<Chosen> {
    let m = bins.rate.len();
    let mut current = start;
    let mut fitted = fit_choice(design, &current, bins)?;
    let walk_slot = TERMS.len();
    let toggles = |c: &Choice| -> Vec<usize> {
        let mut v: Vec<usize> = (0..TERMS.len())
            .filter(|&i| c.terms[i] && design.columns[i].is_some())
            .collect();
        if c.walk {
            v.push(walk_slot);
        }
        v
    };
    let without = |c: &Choice, i: usize| {
        let mut c = c.clone();
        if i == walk_slot {
            c.walk = false;
        } else {
            c.terms[i] = false;
        }
        c
    };
    let mut dropped: Vec<(usize, f64)> = Vec::new();
    loop {
        let base = bic(&fitted, design, &current, m);
        let mut best: Option<(usize, f64, Fit)> = None;
        for i in toggles(&current) {
            let trial = without(&current, i);
            if let Some(f) = fit_choice(design, &trial, bins) {
                let delta = bic(&f, design, &trial, m) - base;
                if best.as_ref().is_none_or(|b| delta < b.1) {
                    best = Some((i, delta, f));
                }
            }
        }
        match best {
            Some((i, delta, f)) if delta < 0.0 => {
                current = without(&current, i);
                dropped.push((i, delta));
                fitted = f;
            }
            _ => break,
        }
    }
    let names = design.names(&current);
    let base = bic(&fitted, design, &current, m);
    let mut judged = Vec::new();
    // Kept: against the final model without each.
    for i in toggles(&current) {
        let trial = without(&current, i);
        let delta = fit_choice(design, &trial, bins)
            .map_or(f64::INFINITY, |f| bic(&f, design, &trial, m) - base);
        let estimate = (i < walk_slot).then(|| {
            let k = names.iter().position(|n| n == TERMS[i].name).unwrap_or(0);
            (fitted.beta[k], fitted.cov[(k, k)].sqrt())
        });
        judged.push((
            i,
            true,
            Judged {
                delta_bic: delta,
                estimate,
            },
        ));
    }
    // Left out: the final model with each put back, for what the log
    // allows it to be.
    for (i, delta) in dropped {
        let mut trial = current.clone();
        if i == walk_slot {
            trial.walk = true;
        } else {
            trial.terms[i] = true;
        }
        let estimate = if i < walk_slot {
            fit_choice(design, &trial, bins).and_then(|f| {
                let k = design
                    .names(&trial)
                    .iter()
                    .position(|n| n == TERMS[i].name)?;
                Some((f.beta[k], f.cov[(k, k)].sqrt()))
            })
        } else {
            None
        };
        judged.push((
            i,
            false,
            Judged {
                delta_bic: delta,
                estimate,
            },
        ));
    }
    judged.sort_by_key(|j| j.0);
    Some((current, fitted, judged))
}

/// Where a log lies in time: its first sample, its span and its bin, s.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Extent {
    pub t0: f64,
    pub span: f64,
    pub bin: f64,
}

/// A lag found.
#[derive(Clone, Debug)]
pub(crate) struct LagFound {
    pub tau: f64,
    /// The 95% range, s.
    pub range: [f64; 2],
    /// The best is at the longest lag searched.
    pub at_limit: bool,
}

/// The half-width of the profile likelihood's 95% range: χ²₁(0.95)/2.
const PROFILE_DROP: f64 = 1.920_729_410_347_062;

/// Searches lagged term `i`'s lag on `coarse`, the other columns as
/// `design` has them and the walk's share found afresh at each lag when
/// the model holds a walk (held at 0 otherwise): a walk can take up part
/// of a lagged response, so a profile at a held share is too narrow.
pub(crate) fn search_lag(
    design: &mut Design,
    choice: &Choice,
    i: usize,
    coarse: &Coarse,
    bins: &Bins,
    extent: Extent,
) -> Option<LagFound> {
    let Extent { t0, span, bin } = extent;
    let m = bins.rate.len();
    // The walk's share at the lag the design holds, then found near it.
    let walk = if choice.walk {
        let start = fit(
            &bins.rate,
            &design.matrix(choice, m),
            &bins.weight,
            Walk::Fitted,
        )?;
        if start.lambda > 0.0 {
            Walk::Near(start.lambda)
        } else {
            Walk::Fitted
        }
    } else {
        Walk::Fixed(0.0)
    };
    let at = |tau: f64, design: &mut Design| -> f64 {
        design.set_lagged(i, coarse.lagged_means(tau), tau, bins, t0);
        fit(&bins.rate, &design.matrix(choice, m), &bins.weight, walk)
            .map_or(f64::NEG_INFINITY, |f| f.log_likelihood)
    };
    let longest = span / 2.0;
    let mut grid: Vec<f64> = vec![0.0];
    let mut tau = bin / 4.0;
    while tau < longest {
        grid.push(tau);
        tau *= std::f64::consts::SQRT_2;
    }
    let scores: Vec<f64> = grid.iter().map(|&t| at(t, design)).collect();
    let (k, &best_grid) = scores
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))?;
    if !best_grid.is_finite() {
        return None;
    }
    // Refine inside the best grid point's neighbours, in ln τ.
    let (mut best_tau, mut best) = (grid[k], best_grid);
    if k > 0 {
        let lo = if k > 1 { grid[k - 1] } else { grid[1] / 2.0 };
        let hi = grid.get(k + 1).copied().unwrap_or(grid[k] * 1.5);
        let phi = (5f64.sqrt() - 1.0) / 2.0;
        let (mut a, mut b) = (lo.ln(), hi.ln());
        let mut c = b - phi * (b - a);
        let mut d = a + phi * (b - a);
        let (mut fc, mut fd) = (at(c.exp(), design), at(d.exp(), design));
        while b - a > 1e-3 {
            if fc > fd {
                (b, d, fd) = (d, c, fc);
                c = b - phi * (b - a);
                fc = at(c.exp(), design);
            } else {
                (a, c, fc) = (c, d, fd);
                d = a + phi * (b - a);
                fd = at(d.exp(), design);
            }
        }
        for (t, f) in [(c.exp(), fc), (d.exp(), fd)] {
            if f > best {
                (best_tau, best) = (t, f);
            }
        }
    }
    let threshold = best - PROFILE_DROP;
    // The crossing between a point inside (above the threshold) and one
    // outside, by bisection (in ln τ, or in τ down to 0).
    let crossing = |inside: f64, outside: f64, design: &mut Design| -> f64 {
        let log = inside > 0.0 && outside > 0.0;
        let (mut a, mut b) = if log {
            (inside.ln(), outside.ln())
        } else {
            (inside, outside)
        };
        let best = if log { best_tau.ln() } else { best_tau };
        for _ in 0..40 {
            let mid = 0.5 * (a + b);
            let t = if log { mid.exp() } else { mid };
            if at(t, design) >= threshold {
                a = mid;
            } else {
                b = mid;
            }
            // To a hundredth of the range's half-width.
            if (b - a).abs() < 0.01 * (a - best).abs().max(1e-6) {
                break;
            }
        }
        if log {
            a.exp()
        } else {
            a
        }
    };
    // Downward: the first grid point below the best that falls outside.
    let below = grid
        .iter()
        .zip(&scores)
        .filter(|(&t, _)| t < best_tau)
        .rev()
        .find(|(_, &s)| s < threshold)
        .map(|(&t, _)| t);
    let lower = match below {
        None => 0.0,
        Some(outside) => {
            let inside = grid
                .iter()
                .copied()
                .filter(|&t| t > outside && t <= best_tau)
                .fold(best_tau, f64::min);
            crossing(inside, outside, design)
        }
    };
    let above = grid
        .iter()
        .zip(&scores)
        .filter(|(&t, _)| t > best_tau)
        .find(|(_, &s)| s < threshold)
        .map(|(&t, _)| t);
    let (upper, open) = match above {
        None => (*grid.last()?, true),
        Some(outside) => {
            let inside = grid
                .iter()
                .copied()
                .filter(|&t| t < outside && t >= best_tau)
                .fold(best_tau, f64::max);
            (crossing(inside, outside, design), false)
        }
    };
    let last = *grid.last()?;
    Some(LagFound {
        tau: best_tau,
        range: [lower.min(best_tau), upper.max(best_tau)],
        at_limit: open && best_tau >= last / std::f64::consts::SQRT_2,
    })
}
