//! Complete elliptic integrals and Jacobi elliptic functions.
//!
//! Conventions follow DLMF chapter 19 and 22 in the *parameter* form used by
//! the seed text (section 1-6): `K(m) = ∫_0^{π/2} dθ / sqrt(1 - m sin²θ)`,
//! with `m = k²` and `k` the modulus. Every function here has two entry
//! points: one taking `m` (as SciPy's `ellipk(m)` does) and one taking a
//! [`Modulus`], which carries `k` and the complementary modulus `k'` side by
//! side. The pendulum uses the second: from an amplitude `A0`,
//! `k = sin(A0/2)` and `k' = cos(A0/2)` are each accurate to an ulp, while
//! `1 - m` formed by subtraction would lose everything near 180 degrees.
//!
//! | function | method | source |
//! |---|---|---|
//! | [`ellipk`] | AGM of 1 and `k'` | DLMF 19.8.5 |
//! | [`ellipe`] | AGM sum for `m <= 1/2`, Legendre's relation above | DLMF 19.8.6, 19.7.1 |
//! | [`ellip_e_minus_complement_k`] | same sums, cancellation-free | DLMF 19.8.6, 19.4.1 |
//! | [`jacobi`] | descending Landen / AGM transformation | DLMF 22.20(ii) |
//! | [`ellipf`] | Carlson's `R_F` by duplication | DLMF 19.25.5, 19.36.1 |
//!
//! Accuracy, measured by `tests/all/reference.rs` against mpmath at 40 digits
//! (see `tools/reference/`), is stated on each function.

mod agm;
mod complete;
mod incomplete;
mod jacobi;

pub(crate) use agm::{agm_deficit, agm_with_derivative};
pub use complete::{ellip_e_minus_complement_k, ellipe, ellipe_modulus, ellipk, ellipk_modulus};
pub use incomplete::{carlson_rf, ellipf};
pub use jacobi::{jacobi, jacobi_modulus, JacobiValues};

/// An elliptic modulus `k` held together with its complement `k' = sqrt(1 - k²)`.
///
/// Both are stored because each is needed to full relative precision in a
/// different place: `k'` drives the AGM (and so `K` near `m = 1`), `k`
/// drives the small-amplitude expansions. Constructing from an angle keeps
/// both exact to an ulp; constructing from `m` forms `1 - m`, which is exact
/// for `m >= 1/2` (Sterbenz) and harmless below.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Modulus {
    k: f64,
    k_prime: f64,
}

impl Modulus {
    /// From the parameter `m = k²`, `0 <= m <= 1`. Returns `None` outside
    /// that range and for NaN.
    pub fn from_parameter(m: f64) -> Option<Self> {
        if !(0.0..=1.0).contains(&m) {
            return None;
        }
        Some(Self {
            k: m.sqrt(),
            k_prime: (1.0 - m).sqrt(),
        })
    }

    /// From the angle `φ` with `k = sin φ`, `k' = cos φ` (DLMF 19.2.1's modular
    /// angle), `0 <= φ <= π/2`. For a pendulum of amplitude `A0`, `φ = A0/2`.
    /// Returns `None` outside that range and for NaN.
    #[inline]
    pub fn from_modular_angle(phi: f64) -> Option<Self> {
        if !(0.0..=std::f64::consts::FRAC_PI_2).contains(&phi) {
            return None;
        }
        Some(Self {
            k: phi.sin(),
            // cos(π/2 as f64) is 6.1e-17, not 0: the double closest to π/2
            // lies below it, so the pendulum at that "amplitude" still returns.
            k_prime: phi.cos(),
        })
    }

    /// The modulus `k`.
    pub fn k(&self) -> f64 {
        self.k
    }

    /// The complementary modulus `k'`.
    pub fn k_prime(&self) -> f64 {
        self.k_prime
    }

    /// The parameter `m = k²`.
    pub fn m(&self) -> f64 {
        self.k * self.k
    }

    /// The complementary parameter `m' = 1 - m = k'²`, without cancellation.
    pub fn m_complement(&self) -> f64 {
        self.k_prime * self.k_prime
    }

    /// The complementary modulus as a `Modulus` (`k` and `k'` swapped).
    pub fn complement(&self) -> Self {
        Self {
            k: self.k_prime,
            k_prime: self.k,
        }
    }
}
