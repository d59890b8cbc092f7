//! The total deviation (TOTDEV): the Allan deviation of the series
//! extended by reflection at both ends, whose long-τ values scatter less
//! than ADEV's (D. A. Howe, "The total deviation approach to long-term
//! characterization of frequency stability", IEEE Trans. UFFC 47 (2000)
//! 1102; NIST SP 1065 section 5.2.11, eq. 25).

use super::registry::{Deviation, DeviationUnit};

/// The total deviation's entry in [`super::registry::DEVIATIONS`]: no
/// interval (its degrees of freedom follow SP 1065 table 11's own
/// formulas, not Greenhall's).
pub const TOTDEV: Deviation = Deviation {
    key: "totdev",
    name: "TOTDEV",
    help: "the total deviation (SP 1065 eq. 25): ADEV of the series reflected at both ends, \
           steadier at long τ",
    unit: DeviationUnit::Fractional,
    compute: totdev,
    interval: None,
};

/// The total deviation at `τ = m τ₀` from phase `x` (`N` points):
/// `Tot var(τ) = Σ_{i=2}^{N−1} (x*_{i−m} − 2x*_i + x*_{i+m})² / (2 τ² (N − 2))`
/// with `x*` the series reflected at both ends, `x*_{1−j} = 2x_1 − x_{1+j}`
/// and `x*_{N+j} = 2x_N − x_{N−j}` (SP 1065 eq. 25). A term that reads a
/// gap (NaN) is left out and the sum normalised by the terms kept.
/// `None` with fewer than three points, `m` of `N − 1` or more, or no
/// term kept. On Riley's NBS14 set it gives the handbook's 91.22945 and
/// 93.90379 at τ = 1 and 2 (SP 1065 section 12.4); against allantools
/// 2024.06 within 1e-10 relative at every octave τ of four 1,000-point
/// noises (tests `stability.rs`).
pub fn totdev(x: &[f64], tau0: f64, m: usize) -> Option<f64> {
    let tau = super::deviations::tau(tau0, m)?;
    let n = x.len();
    if n < 3 || m >= n - 1 {
        return None;
    }
    // x* at index i (0-based, may run past either end by up to N − 2).
    let at = |i: isize| -> f64 {
        let last = n as isize - 1;
        if i < 0 {
            2.0 * x[0] - x[(-i) as usize]
        } else if i > last {
            2.0 * x[n - 1] - x[(2 * last - i) as usize]
        } else {
            x[i as usize]
        }
    };
    let m = m as isize;
    let (sum, kept) = (1..n as isize - 1)
        .map(|i| at(i - m) - 2.0 * at(i) + at(i + m))
        .filter(|d| d.is_finite())
        .fold((0.0, 0usize), |(s, k), d| (s + d * d, k + 1));
    (kept > 0).then(|| (sum / (2.0 * tau * tau * kept as f64)).sqrt())
}
