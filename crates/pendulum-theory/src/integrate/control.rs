//! Step-size control, in one place.
//!
//! The error norm of a step is 1 at the requested tolerance. After an
//! accepted step the next is `h · clamp(SAFETY · err^(-1/8), MIN, MAX)`
//! (an 8th-order method with its error estimated to order 7, Hairer,
//! Nørsett & Wanner I, II.4 and `dop853.f`); after a rejection the step only
//! shrinks, and it may not grow on the step right after a rejection.

/// Safety factor on the optimal step.
pub const SAFETY: f64 = 0.9;
/// The most a step may shrink at once.
pub const MIN_FACTOR: f64 = 1.0 / 3.0;
/// The most a step may grow at once.
pub const MAX_FACTOR: f64 = 6.0;
/// `-1/(q+1)` for an error estimate of order `q = 7`.
pub const ERROR_EXPONENT: f64 = -1.0 / 8.0;

/// The factor to multiply the step by, from the error norm of the last
/// attempt (`<= 1` accepted), and whether the attempt before was rejected.
pub fn step_factor(error_norm: f64, after_rejection: bool) -> f64 {
    let optimal = if error_norm == 0.0 {
        MAX_FACTOR
    } else {
        SAFETY * error_norm.powf(ERROR_EXPONENT)
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
        assert_eq!(step_factor(0.0, false), MAX_FACTOR);
        assert!(step_factor(1e10, false) == MIN_FACTOR);
        assert!(step_factor(2.0, false) < 1.0);
        assert!(step_factor(1e-6, true) <= 1.0);
        // At err = 1 the step shrinks by the safety factor.
        assert_eq!(step_factor(1.0, false), SAFETY);
    }
}
