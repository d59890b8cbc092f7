//! The exact motion of the undamped pendulum at any amplitude (the seed's
//! section 1-6 solved for θ(t), not only for the period).
//!
//! From rest at `A0` at `t = 0`, with `k = sin(A0/2)`, `k' = cos(A0/2)`:
//! `sin(θ/2) = k sn(K - ω_n t | m) = k cd(ω_n t | m)` and
//! `θ' = -2 k k' ω_n sd(ω_n t | m)` (DLMF 22.19.ii, with 22.13 for the
//! derivatives). Since `cos(θ/2) = k' nd`, the angle is
//! `θ = 2 atan2(k cn, k')`: no `asin` of numbers near 1 at large amplitudes.
//!
//! Two evaluators:
//! * [`ExactSwing::state_at_jacobi`], from sn, cn, dn ([`crate::elliptic::jacobi`]);
//! * [`ExactSwing::state_at`], the Fourier series of `θ' = -2kk'ω_n sd`
//!   (DLMF 22.11, the series for sd) and its integral:
//!   `θ(t) = 8 Σ_{n≥0} (-1)^n q^{n+1/2} / ((2n+1)(1 + q^{2n+1})) cos((2n+1) w t)`,
//!   `w = π ω_n / (2K)`, with the nome `q` (DLMF 22.2.1). Its coefficients
//!   are computed once per amplitude and fall like `q^n` (`q = 4e-5` at 3°,
//!   0.16 at 150°), so each time costs one `sin_cos` and a few multiply-adds:
//!   the fast path for many times at one amplitude.
//!
//! Accuracy against mpmath (`tests/exact_reference.rs`): see there.

use crate::damped::State;
use crate::elliptic::{ellipk_modulus, jacobi_modulus, Modulus};
use crate::pendulum::{Amplitude, Pendulum};
use std::f64::consts::PI;

/// The exact undamped motion from rest at one amplitude.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactSwing {
    omega: f64,
    modulus: Modulus,
    amplitude: f64,
    /// `w = π ω_n / (2K)`, the angular frequency of the motion, rad/s.
    frequency: f64,
    /// Fourier amplitudes `b_n = 8 (-1)^n q^{n+1/2} / (1 + q^{2n+1})` of θ' / w;
    /// θ's are `b_n / (2n+1)`.
    coefficients: Vec<f64>,
    period: f64,
}

/// The nome `q = exp(-π K'/K)` (DLMF 19.5.5 and 22.2.1). For `m <= 1/2`
/// from the series `q = ε + 2ε⁵ + 15ε⁹ + 150ε¹³ + 1707ε¹⁷` in
/// `ε = (1 - sqrt k')/(2(1 + sqrt k'))` (A&S 17.3.21), formed without
/// cancellation, which keeps `q ≈ m/16` accurate at tiny amplitudes where
/// the exponential would carry `πK'/K` ulps of error; above, the exponential.
pub fn nome(modulus: &Modulus) -> f64 {
    let m = modulus.m();
    if m <= 0.5 {
        let (k, kp) = (modulus.k(), modulus.k_prime());
        let root = kp.sqrt();
        let eps = k * k / (2.0 * (1.0 + kp) * (1.0 + root) * (1.0 + root));
        let e4 = eps.powi(4);
        eps * (1.0 + e4 * (2.0 + e4 * (15.0 + e4 * (150.0 + e4 * 1707.0))))
    } else {
        let ratio = ellipk_modulus(&modulus.complement()) / ellipk_modulus(modulus);
        (-PI * ratio).exp()
    }
}

impl ExactSwing {
    /// The swing of `pendulum` released from rest at `amplitude`.
    pub fn new(pendulum: &Pendulum, amplitude: Amplitude) -> Self {
        let modulus = amplitude.modulus();
        let omega = pendulum.natural_angular_frequency();
        let k_integral = ellipk_modulus(&modulus);
        let q = nome(&modulus);
        let mut coefficients = Vec::new();
        let mut power = q.sqrt(); // q^{n+1/2}
        let q2 = q * q;
        let mut odd_power = q; // q^{2n+1}
        let mut sign = 1.0;
        loop {
            let b = 8.0 * power / (1.0 + odd_power);
            coefficients.push(sign * b);
            // Terms fall like q^n; stop once they no longer reach the last bit.
            if b <= 1e-18 * coefficients[0] || coefficients.len() >= 64 {
                break;
            }
            sign = -sign;
            power *= q;
            odd_power *= q2;
        }
        Self {
            omega,
            modulus,
            amplitude: amplitude.radians(),
            frequency: PI * omega / (2.0 * k_integral),
            coefficients,
            period: pendulum.period(amplitude),
        }
    }

    /// The period, s.
    pub fn period(&self) -> f64 {
        self.period
    }

    /// The amplitude, rad.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// The `n`-th turning point: time `n T/2` and angle `(-1)^n A0`.
    pub fn turning_point(&self, n: u64) -> (f64, f64) {
        let angle = if n % 2 == 0 {
            self.amplitude
        } else {
            -self.amplitude
        };
        (n as f64 * 0.5 * self.period, angle)
    }

    /// θ and θ' at `t` by the Fourier series.
    pub fn state_at(&self, t: f64) -> State {
        let x = self.frequency * t;
        let (s1, c1) = x.sin_cos();
        let (s2, c2) = (2.0 * s1 * c1, (c1 - s1) * (c1 + s1));
        let (mut s, mut c) = (s1, c1);
        let (mut angle, mut velocity) = (0.0, 0.0);
        for (n, b) in self.coefficients.iter().enumerate() {
            angle += b / (2 * n + 1) as f64 * c;
            velocity += b * s;
            (s, c) = (s * c2 + c * s2, c * c2 - s * s2);
        }
        State {
            angle,
            // 0 - x, not -x: no "-0.0" at the turning points.
            angular_velocity: 0.0 - self.frequency * velocity,
        }
    }

    /// θ and θ' at `t` from the Jacobi functions: `θ = 2 atan2(k cn, k')`,
    /// `θ' = -2 k k' ω_n sn/dn`, at `u = ω_n t`.
    pub fn state_at_jacobi(&self, t: f64) -> State {
        let v = jacobi_modulus(self.omega * t, &self.modulus);
        let (k, kp) = (self.modulus.k(), self.modulus.k_prime());
        State {
            angle: 2.0 * (k * v.cn).atan2(kp),
            angular_velocity: -2.0 * k * kp * self.omega * v.sn / v.dn,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn swing(deg: f64) -> ExactSwing {
        ExactSwing::new(
            &Pendulum::with_standard_gravity(0.99362).unwrap(),
            Amplitude::from_degrees(deg).unwrap(),
        )
    }

    #[test]
    fn starts_at_rest_at_the_amplitude() {
        for d in [0.001, 3.0, 90.0, 150.0, 179.0] {
            let s = swing(d);
            let a = s.state_at(0.0);
            let amplitude = d.to_radians();
            assert!(
                (a.angle - amplitude).abs() <= 8.0 * f64::EPSILON * amplitude,
                "{d}: {}",
                a.angle
            );
            assert_eq!(a.angular_velocity, 0.0);
            let j = s.state_at_jacobi(0.0);
            assert!(
                (j.angle - amplitude).abs() <= 4.0 * f64::EPSILON * amplitude,
                "{d}: {} vs {amplitude}",
                j.angle
            );
        }
    }

    #[test]
    fn fourier_and_jacobi_agree() {
        for d in [1.0, 30.0, 120.0, 150.0] {
            let s = swing(d);
            let amplitude = d.to_radians();
            for i in 0..50 {
                let t = s.period() * f64::from(i) / 37.0;
                let (a, b) = (s.state_at(t), s.state_at_jacobi(t));
                assert!(
                    (a.angle - b.angle).abs() < 64.0 * f64::EPSILON * amplitude,
                    "{d}° t {t}"
                );
            }
        }
    }

    #[test]
    fn nome_for_small_parameters_is_m_over_16() {
        let q = nome(&Modulus::from_parameter(1e-12).unwrap());
        assert!((q / (1e-12 / 16.0) - 1.0).abs() < 1e-11);
    }
}
