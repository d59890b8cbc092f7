//! Step-size control, in one place.
//!
//! The error norm of a step is 1 at the requested tolerance. After an
//! accepted step the next is `h · clamp(SAFETY · err^(-1/(q+1)), MIN, MAX)`
//! for an error estimate of order `q` (7 for DOP853, 8 for Verner's 9(8);
//! Hairer, Nørsett & Wanner I, II.4 and `dop853.f`); after a rejection the
//! step only shrinks, and it may not grow on the step right after a rejection.

/// Safety factor on the optimal step.
pub const SAFETY: f64 = 0.9;
/// The most a step may shrink at once.
pub const MIN_FACTOR: f64 = 1.0 / 3.0;
/// The most a step may grow at once.
pub const MAX_FACTOR: f64 = 6.0;
/// The factor to multiply the step by, from the error norm of the last
/// attempt (`<= 1` accepted) of a method whose error estimate has order
/// `estimate_order`, and whether the attempt before was rejected.
pub fn step_factor(error_norm: f64, after_rejection: bool, estimate_order: u32) -> f64 {
    let optimal = if error_norm == 0.0 {
        MAX_FACTOR
    } else {
        SAFETY * error_norm.powf(-1.0 / f64::from(estimate_order + 1))
    };
    let factor = optimal.clamp(MIN_FACTOR, MAX_FACTOR);
    if after_rejection || error_norm > 1.0 {
        factor.min(1.0)
    } else {
        factor
    }
}

/// Absolute and relative tolerances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Absolute tolerance, in the units of each component.
    pub absolute: f64,
    /// Relative tolerance.
    pub relative: f64,
}

impl Tolerance {
    /// The same number for both.
    pub fn both(tol: f64) -> Self {
        Self {
            absolute: tol,
            relative: tol,
        }
    }

    /// The scale of component `i` over a step from `y0` to `y1`:
    /// `atol + rtol · max(|y0|, |y1|)`.
    #[inline]
    pub fn scale(&self, y0: f64, y1: f64) -> f64 {
        self.absolute + self.relative * y0.abs().max(y1.abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn factors() {
        assert_eq!(step_factor(0.0, false, 7), MAX_FACTOR);
        assert!(step_factor(1e10, false, 7) == MIN_FACTOR);
        assert!(step_factor(2.0, false, 7) < 1.0);
        assert!(step_factor(1e-6, true, 7) <= 1.0);
        // At err = 1 the step shrinks by the safety factor.
        assert_eq!(step_factor(1.0, false, 8), SAFETY);
        // 2^-8 allows twice the step of a 7th-order estimate.
        assert!((step_factor(2f64.powi(-8), false, 7) / SAFETY - 2.0).abs() < 1e-12);
    }
}
