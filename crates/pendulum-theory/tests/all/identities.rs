//! Identities and invariants that hold whatever the reference data say,
//! checked over random inputs (proptest), and the textbook values a user
//! will compare against first.

use pendulum_theory::elliptic::{ellipe_modulus, ellipk_modulus, jacobi, Modulus};
use pendulum_theory::gravity::normal_gravity;
use pendulum_theory::period::{
    amplitude_for_period, circular_error, length_for_period, period_for_beat_rate, period_ratio,
    PeriodAnalysis,
};
use pendulum_theory::{Amplitude, Pendulum, STANDARD_GRAVITY};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

proptest! {
    /// Legendre's relation, DLMF 19.7.1: E K' + E' K - K K' = π/2.
    #[test]
    fn legendre_relation(phi in 0.01_f64..1.56) {
        let q = Modulus::from_modular_angle(phi).unwrap();
        let c = q.complement();
        let (k, e) = (ellipk_modulus(&q), ellipe_modulus(&q));
        let (kc, ec) = (ellipk_modulus(&c), ellipe_modulus(&c));
        let lhs = e * kc + ec * k - k * kc;
        // The terms are as large as K K' (about 10 at the ends); allow a few
        // ulp of each.
        let scale = (k * kc).max(1.0);
        prop_assert!((lhs - FRAC_PI_2).abs() <= 8.0 * f64::EPSILON * scale, "{lhs}");
    }

    /// sn² + cn² = 1 and dn² + m sn² = 1 (DLMF 22.6.1).
    #[test]
    fn jacobi_squares(u in -50.0_f64..50.0, m in 0.0_f64..1.0) {
        let v = jacobi(u, m);
        prop_assert!((v.sn * v.sn + v.cn * v.cn - 1.0).abs() <= 4.0 * f64::EPSILON);
        prop_assert!((v.dn * v.dn + m * v.sn * v.sn - 1.0).abs() <= 4.0 * f64::EPSILON);
    }

    /// sn has period 4K and is odd (DLMF 22.4.1, 22.6.4).
    #[test]
    fn jacobi_period_and_parity(u in -3.0_f64..3.0, m in 0.0_f64..0.99) {
        let k = ellipk_modulus(&Modulus::from_parameter(m).unwrap());
        let a = jacobi(u, m);
        let b = jacobi(u + 4.0 * k, m);
        let tol = 64.0 * f64::EPSILON * (1.0 + k);
        prop_assert!((a.sn - b.sn).abs() <= tol);
        prop_assert!((a.cn - b.cn).abs() <= tol);
        prop_assert_eq!(jacobi(-u, m).sn, -a.sn);
        prop_assert_eq!(jacobi(-u, m).cn, a.cn);
    }

    /// The period grows with amplitude, and the circular error with it.
    #[test]
    fn period_grows_with_amplitude(a in 0.0_f64..3.1, b in 0.0_f64..3.1) {
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        let (lo, hi) = (Amplitude::from_radians(lo).unwrap(), Amplitude::from_radians(hi).unwrap());
        prop_assert!(period_ratio(lo) <= period_ratio(hi));
        prop_assert!(circular_error(lo) <= circular_error(hi));
    }

    /// T0/T + circular error = 1, to an ulp of 1.
    #[test]
    fn ratio_and_circular_error_agree(a in 1e-6_f64..3.1) {
        let amp = Amplitude::from_radians(a).unwrap();
        let sum = 1.0 / period_ratio(amp) + circular_error(amp);
        prop_assert!((sum - 1.0).abs() <= 4.0 * f64::EPSILON);
    }

    /// Length for a period, then the period of that length: a round trip.
    #[test]
    fn length_round_trip(t in 0.1_f64..100.0, a in 0.0_f64..3.0) {
        let amp = Amplitude::from_radians(a).unwrap();
        let l = length_for_period(t, amp, STANDARD_GRAVITY).unwrap();
        let p = Pendulum::with_standard_gravity(l).unwrap();
        prop_assert!((p.period(amp) - t).abs() <= 8.0 * f64::EPSILON * t);
    }

    /// Amplitude from a period, then the period at that amplitude.
    #[test]
    fn amplitude_round_trip(a in 1e-3_f64..3.1) {
        let p = Pendulum::with_standard_gravity(1.0).unwrap();
        let amp = Amplitude::from_radians(a).unwrap();
        let est = amplitude_for_period(&p, p.period(amp)).unwrap();
        let rel = (est.amplitude.radians() - a).abs() / a;
        prop_assert!(rel <= 8.0 * f64::EPSILON * est.condition_number.max(1.0), "{rel:e}");
    }
}

#[test]
fn known_period_ratios() {
    // Values given in the issue (20 digits, from mpmath).
    let r10 = period_ratio(Amplitude::from_degrees(10.0).unwrap());
    let r90 = period_ratio(Amplitude::from_degrees(90.0).unwrap());
    assert!((r10 - 1.001_907_188_143_216_6).abs() <= 2.0 * f64::EPSILON);
    assert!((r90 - 1.180_340_599_016_096_2).abs() <= 4.0 * f64::EPSILON);
}

#[test]
fn seconds_pendulum() {
    let t = 2.0;
    let l = length_for_period(t, Amplitude::from_radians(0.0).unwrap(), STANDARD_GRAVITY).unwrap();
    assert!((l - 0.99362).abs() < 5e-6, "{l}");
    assert!((l - STANDARD_GRAVITY / (PI * PI)).abs() <= 2.0 * f64::EPSILON);
    let p = Pendulum::with_standard_gravity(l).unwrap();
    let two_degrees = Amplitude::from_degrees(2.0).unwrap();
    let analysis = PeriodAnalysis::new(p, two_degrees, 3).unwrap();
    let rate = analysis.circular_error_s_per_day();
    assert!((rate - 6.58).abs() < 0.005, "{rate}");
    // A seconds pendulum beats 3600 times an hour.
    assert_eq!(period_for_beat_rate(3600.0).unwrap(), 2.0);
}

#[test]
fn tiny_amplitude_circular_error_keeps_its_digits() {
    // 1 - T0/T = A0²/16 - A0⁴/3072 + ..., so at 1e-6 rad it is 6.25e-14 to 1e-12 relative.
    let a = 1e-6;
    let c = circular_error(Amplitude::from_radians(a).unwrap());
    let series = a * a / 16.0 - a.powi(4) / 3072.0;
    assert!(
        (c - series).abs() <= 4.0 * f64::EPSILON * series,
        "{c:e} vs {series:e}"
    );
}

#[test]
fn gravity_at_45_degrees() {
    // Somigliana's formula with the WGS 84 constants at 45°, evaluated at
    // 40 digits with mpmath: 9.806197769373209... m/s².
    let g = normal_gravity(45.0, 0.0).unwrap();
    assert!((g - 9.806_197_769_373_21).abs() < 1e-14, "{g}");
}
