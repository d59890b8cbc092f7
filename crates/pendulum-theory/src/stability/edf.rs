//! Equivalent degrees of freedom of the difference variances, by
//! C. A. Greenhall and W. J. Riley, "Uncertainty of stability variances
//! based on finite differences", 35th PTTI meeting (2003), the method
//! NIST SP 1065 section 5.3 recommends and Stable32 uses.
//!
//! The variance estimate `σ̂²` of a power-law noise (`S_y(f) ∝ f^α`) is
//! treated as `σ² χ²_ν / ν`; `ν`, the EDF, follows from the
//! autocovariance of the filtered phase, which for pure power laws has
//! closed forms in the generalised functions `sw` (the paper's eq. 7).
//! The paper's "basic sum" (eq. 10) is summed exactly up to `J_max = 100`
//! lags; past it, its fitted two-term forms (its tables 1 to 3) take over.
//! Against allantools 2024.06 (which implements the same paper) on four
//! seeded noises, every EDF agrees to 1e-9 relative (test `stability.rs`).

/// Past this many lags the basic sum gives way to the paper's asymptotic
/// forms.
const J_MAX: f64 = 100.0;

/// The paper's `sw(t)`, eq. 7: the generalised autocovariance of the
/// phase's `α`-th power-law noise, up to a constant.
fn sw(t: f64, alpha: i32) -> f64 {
    let log_term = |p: i32| {
        if t == 0.0 {
            0.0
        } else {
            t.powi(p) * t.abs().ln()
        }
    };
    match alpha {
        2 => -t.abs(),
        1 => log_term(2),
        0 => t.abs().powi(3),
        -1 => log_term(4),
        -2 => t.abs().powi(5),
        -3 => log_term(6),
        _ => t.abs().powi(7),
    }
}

/// Eq. 8: `sw` through the averaging filter of `F` samples (`F = ∞` for
/// the unmodified variances at large `m`, where it becomes `sw` of the
/// next power).
fn sx(t: f64, f: f64, alpha: i32) -> f64 {
    if f.is_infinite() {
        return sw(t, alpha + 2);
    }
    f * f * (2.0 * sw(t, alpha) - sw(t - 1.0 / f, alpha) - sw(t + 1.0 / f, alpha))
}

/// Eq. 9: through the `d`-th difference, `Σ_k (−1)^k C(2d, d+k) sx(t+k)`.
fn sz(t: f64, f: f64, alpha: i32, d: u32) -> f64 {
    let weights: &[f64] = match d {
        1 => &[2.0, -1.0],
        2 => &[6.0, -4.0, 1.0],
        _ => &[20.0, -15.0, 6.0, -1.0],
    };
    weights
        .iter()
        .enumerate()
        .map(|(k, w)| {
            let k = k as f64;
            if k == 0.0 {
                w * sx(t, f, alpha)
            } else {
                w * (sx(t - k, f, alpha) + sx(t + k, f, alpha))
            }
        })
        .sum()
}

/// Eq. 10, the basic sum over lags `0..J` of `M` terms at stride `S`.
fn basic_sum(j: f64, m: f64, s: f64, f: f64, alpha: i32, d: u32) -> f64 {
    let z = |t: f64| sz(t, f, alpha, d).powi(2);
    let inner: f64 = (1..j as usize)
        .map(|k| 2.0 * (1.0 - k as f64 / m) * z(k as f64 / s))
        .sum();
    z(0.0) + (1.0 - j / m) * z(j / s) + inner
}

/// The paper's table 1 (modified variances) and table 2 (unmodified):
/// `(a₀, a₁)` of `1/EDF ≈ (a₀ − a₁/r)/r`, by `α` (rows 2 down to −4) and
/// `d` (columns 1 to 3); `None` where the variance does not converge.
fn table(modified: bool, alpha: i32, d: u32) -> Option<(f64, f64)> {
    const NO: (f64, f64) = (f64::NAN, f64::NAN);
    const MODIFIED: [[(f64, f64); 3]; 7] = [
        [
            (2.0 / 3.0, 1.0 / 3.0),
            (7.0 / 9.0, 0.5),
            (22.0 / 25.0, 2.0 / 3.0),
        ],
        [(0.840, 0.345), (0.997, 0.616), (1.141, 0.843)],
        [(1.079, 0.368), (1.033, 0.607), (1.184, 0.848)],
        [NO, (1.048, 0.534), (1.180, 0.816)],
        [NO, (1.302, 0.535), (1.175, 0.777)],
        [NO, NO, (1.194, 0.703)],
        [NO, NO, (1.489, 0.702)],
    ];
    const UNMODIFIED: [[(f64, f64); 3]; 7] = [
        [(1.5, 0.5), (35.0 / 18.0, 1.0), (231.0 / 100.0, 1.5)],
        [(78.6, 25.2), (790.0, 410.0), (9950.0, 6520.0)],
        [
            (2.0 / 3.0, 1.0 / 6.0),
            (2.0 / 3.0, 1.0 / 3.0),
            (7.0 / 9.0, 0.5),
        ],
        [NO, (0.852, 0.375), (0.997, 0.617)],
        [NO, (1.079, 0.368), (1.033, 0.607)],
        [NO, NO, (1.053, 0.553)],
        [NO, NO, (1.302, 0.535)],
    ];
    let rows = if modified { &MODIFIED } else { &UNMODIFIED };
    let row = usize::try_from(2 - alpha).ok()?;
    let cell = *rows.get(row)?.get(d.checked_sub(1)? as usize)?;
    cell.0.is_finite().then_some(cell)
}

/// The paper's table 3, `(b₀, b₁)` of the flicker-phase (`α = 1`)
/// unmodified variances' `sz(0)` ≈ `b₀ + b₁ ln m`.
fn flicker_phase_norm(d: u32) -> (f64, f64) {
    match d {
        1 => (6.0, 4.0),
        2 => (15.23, 12.0),
        _ => (47.8, 40.0),
    }
}

/// Which variance an EDF is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Estimator {
    /// The difference order: 2 for the Allan family, 3 for Hadamard.
    pub d: u32,
    /// Every start (`true`) or every `m`-th (`false`).
    pub overlapping: bool,
    /// The modified (phase-averaged) variance.
    pub modified: bool,
}

/// The overlapping Allan variance.
pub const OADEV: Estimator = Estimator {
    d: 2,
    overlapping: true,
    modified: false,
};
/// The modified Allan variance (and the time variance, its multiple).
pub const MDEV: Estimator = Estimator {
    d: 2,
    overlapping: true,
    modified: true,
};
/// The overlapping Hadamard variance.
pub const OHDEV: Estimator = Estimator {
    d: 3,
    overlapping: true,
    modified: false,
};

/// The equivalent degrees of freedom of `estimator` at averaging factor
/// `m` on `n` phase points of power-law noise `α` (2 white phase, 1
/// flicker phase, 0 white frequency, −1 flicker frequency, −2 random-walk
/// frequency, down to −4). `None` where the variance does not converge
/// (`α + 2d ≤ 1`), with no complete term, or in the one case the paper
/// leaves open (white phase, unmodified, fewer than `d + 1` strides).
pub fn greenhall(alpha: i32, estimator: Estimator, m: usize, n: usize) -> Option<f64> {
    let d = estimator.d;
    if !(1..=3).contains(&d) || !(-4..=2).contains(&alpha) || alpha + 2 * d as i32 <= 1 || m == 0 {
        return None;
    }
    let mf = m as f64;
    let f = if estimator.modified { 1.0 } else { mf };
    let s = if estimator.overlapping { mf } else { 1.0 };
    let filter = mf / f + mf * d as f64;
    let terms = 1.0 + (s * (n as f64 - filter) / mf).floor();
    if terms < 1.0 {
        return None;
    }
    let j = terms.min((d as f64 + 1.0) * s);
    let r = terms / s;
    let dd = d as f64;
    // The exact sum, normalised by sz(0) of filter `f0`.
    let exact = |j: f64, terms: f64, s: f64, f_sum: f64, norm: f64| {
        basic_sum(j, terms, s, f_sum, alpha, d) / (norm * norm * terms)
    };
    let inverse = if estimator.modified {
        if j <= J_MAX {
            exact(j, terms, s, 1.0, sz(0.0, 1.0, alpha, d))
        } else if r > dd + 1.0 {
            let (a0, a1) = table(true, alpha, d)?;
            (a0 - a1 / r) / r
        } else {
            exact(J_MAX, J_MAX, J_MAX / r, 1.0, sz(0.0, 1.0, alpha, d))
        }
    } else if alpha <= 0 {
        if j <= J_MAX {
            let f0 = if mf * (dd + 1.0) <= J_MAX {
                mf
            } else {
                f64::INFINITY
            };
            exact(j, terms, s, f0, sz(0.0, f0, alpha, d))
        } else if r > dd + 1.0 {
            let (a0, a1) = table(false, alpha, d)?;
            (a0 - a1 / r) / r
        } else {
            exact(
                J_MAX,
                J_MAX,
                J_MAX / r,
                f64::INFINITY,
                sz(0.0, f64::INFINITY, alpha, d),
            )
        }
    } else if alpha == 1 {
        let (b0, b1) = flicker_phase_norm(d);
        let norm = b0 + b1 * mf.ln();
        if j <= J_MAX {
            exact(j, terms, s, mf, sz(0.0, mf, 1, d))
        } else if r > dd + 1.0 {
            let (a0, a1) = table(false, alpha, d)?;
            (a0 - a1 / r) / (norm * norm * r)
        } else {
            let mp = J_MAX / r;
            basic_sum(J_MAX, J_MAX, mp, mp, 1, d) / (norm * norm * J_MAX)
        }
    } else {
        // White phase, unmodified: the paper's closed form.
        if r.ceil() <= dd {
            return None;
        }
        let a0 = binomial(4 * d, 2 * d) / binomial(2 * d, d).powi(2);
        (a0 - dd / 2.0 / r) / terms
    };
    let edf = 1.0 / inverse;
    (edf.is_finite() && edf > 0.0).then_some(edf)
}

/// `C(n, k)` for the small arguments used here.
fn binomial(n: u32, k: u32) -> f64 {
    (1..=k).fold(1.0, |c, i| c * (n - k + i) as f64 / i as f64)
}
