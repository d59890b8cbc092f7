//! The complete elliptic integrals of the first and second kind.
//!
//! Method: the arithmetic-geometric mean, DLMF 19.8.5 and 19.8.6:
//! `K = π / (2 AGM(1, k'))` and `E = K (1 - k²/2 - Σ_{n≥1} 2^(n-1) c_n²)`.
//! For `m > 1/2` the second formula would subtract nearly equal numbers
//! (both terms near 1/2 as `m -> 1`), so `E` is taken from Legendre's relation
//! (DLMF 19.7.1) applied to the complementary modulus, whose own AGM sum is
//! then small: `E = AGM(1, k) + K (k'²/2 + S')`, a sum of positive terms.
//!
//! Special values: `K(0) = E(0) = π/2`, `K(1) = +inf`, `E(1) = 1`; NaN or `m`
//! outside `[0, 1]` gives NaN.
//!
//! Accuracy (double precision, `tests/all/reference.rs`, mpmath at 40 digits):
//! `K`: at most 2 ulp over `m` in `[0, 1)` and over amplitudes
//! `(0, 179.9]` degrees; `E`: at most 3 ulp; `E - k'² K`: at most 4 ulp.

use super::agm::{agm, agm_with_sum};
use super::Modulus;
use std::f64::consts::FRAC_PI_2;

/// `K(m)`, the complete elliptic integral of the first kind (DLMF 19.2.8),
/// in the parameter convention. See [`ellipk_modulus`] for accuracy.
#[inline]
pub fn ellipk(m: f64) -> f64 {
    // Only k' is needed; skip the sqrt for k that Modulus would take.
    if !(0.0..=1.0).contains(&m) {
        return f64::NAN;
    }
    if m == 1.0 {
        return f64::INFINITY;
    }
    FRAC_PI_2 / agm((1.0 - m).sqrt())
}

/// `K` from the modulus pair `(k, k')`: `π / (2 AGM(1, k'))`, DLMF 19.8.5.
///
/// Measured error at most 2 ulp (see the module documentation).
#[inline]
pub fn ellipk_modulus(modulus: &Modulus) -> f64 {
    let k_prime = modulus.k_prime();
    if k_prime == 0.0 {
        return f64::INFINITY;
    }
    FRAC_PI_2 / agm(k_prime)
}

/// `E(m)`, the complete elliptic integral of the second kind (DLMF 19.2.8),
/// in the parameter convention. See [`ellipe_modulus`] for accuracy.
pub fn ellipe(m: f64) -> f64 {
    Modulus::from_parameter(m).map_or(f64::NAN, |q| ellipe_modulus(&q))
}

/// `E` from the modulus pair `(k, k')`: DLMF 19.8.6 for `m <= 1/2`, Legendre's
/// relation (DLMF 19.7.1) on the complement above.
///
/// Measured error at most 3 ulp (see the module documentation).
pub fn ellipe_modulus(modulus: &Modulus) -> f64 {
    let m = modulus.m();
    if modulus.k_prime() == 0.0 {
        return 1.0;
    }
    if m <= 0.5 {
        let s = agm_with_sum(modulus.k_prime());
        let k_integral = FRAC_PI_2 / s.mean;
        k_integral * ((1.0 - 0.5 * m) - s.sum)
    } else {
        let complement = agm_with_sum(modulus.k());
        let k_integral = ellipk_modulus(modulus);
        complement.mean + k_integral * (0.5 * modulus.m_complement() + complement.sum)
    }
}

/// Where [`ellip_e_minus_complement_k`] changes from the direct AGM sum to
/// Legendre's relation.
const DIFFERENCE_SWITCH: f64 = 0.8;

/// `E - k'² K`, without cancellation at any `m`.
///
/// This combination is `k k'² dK/dk` (DLMF 19.4.1) and sets the slope of the
/// pendulum's period against amplitude. For small `m` both `E` and `k'² K`
/// are near `π/2`, and their difference (about `π m / 4`) would be lost;
/// from DLMF 19.8.6 it equals `K (m/2 - S)`, dominated by `m/2`. For
/// `m > 1/2`, Legendre's relation gives `AGM(1, k) + K (S' - k'²/2)`, whose
/// second term is small.
///
/// Measured error at most 4 ulp relative to the result.
pub fn ellip_e_minus_complement_k(modulus: &Modulus) -> f64 {
    let m = modulus.m();
    if modulus.k_prime() == 0.0 {
        return 1.0;
    }
    // Both forms cancel mildly near their ends (a factor of 2 at m = 1/2 for
    // the second, at m = 0.99 for the first); they cancel equally, by a
    // factor of 1.3, near m = 0.8.
    if m <= DIFFERENCE_SWITCH {
        let s = agm_with_sum(modulus.k_prime());
        let k_integral = FRAC_PI_2 / s.mean;
        k_integral * (0.5 * m - s.sum)
    } else {
        let complement = agm_with_sum(modulus.k());
        let k_integral = ellipk_modulus(modulus);
        complement.mean + k_integral * (complement.sum - 0.5 * modulus.m_complement())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn special_values() {
        assert_eq!(ellipk(0.0), FRAC_PI_2);
        assert_eq!(ellipe(0.0), FRAC_PI_2);
        assert_eq!(ellipk(1.0), f64::INFINITY);
        assert_eq!(ellipe(1.0), 1.0);
        assert!(ellipk(f64::NAN).is_nan());
        assert!(ellipk(1.5).is_nan());
        assert!(ellipe(-0.5).is_nan());
    }

    #[test]
    fn legendre_relation_at_m_one_half() {
        // DLMF 19.7.1 with m = m' = 1/2: 2 E K - K^2 = π/2.
        let k = ellipk(0.5);
        let e = ellipe(0.5);
        assert!((2.0 * e * k - k * k - FRAC_PI_2).abs() < 4.0 * f64::EPSILON);
    }

    #[test]
    fn difference_is_small_m_series_for_tiny_m() {
        // E - k'^2 K = (π/4) m (1 + m/8 + ...) for small m.
        let q = Modulus::from_parameter(1e-12).unwrap();
        let d = ellip_e_minus_complement_k(&q);
        let series = PI / 4.0 * 1e-12 * (1.0 + 1e-12 / 8.0);
        assert!((d - series).abs() <= 2.0 * f64::EPSILON * series);
    }
}
