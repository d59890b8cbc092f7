//! Invariants of the damped linear pendulum's closed form: it satisfies its
//! differential equation, loses energy at the rate viscous damping says,
//! passes smoothly through critical damping, and its turning points are
//! where the velocity vanishes.

use pendulum_theory::damped::friction::DryFriction;
use pendulum_theory::damped::DampedPendulum;
use pendulum_theory::damping::Damping;
use pendulum_theory::Pendulum;
use proptest::prelude::*;

fn damped(length: f64, zeta: f64) -> DampedPendulum {
    DampedPendulum::new(
        Pendulum::with_standard_gravity(length).unwrap(),
        Damping::from_zeta(zeta).unwrap(),
    )
}

/// The 8th-order central difference for a first derivative (Fornberg 1988).
const FD8: [f64; 4] = [4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0];

fn derivative(f: impl Fn(f64) -> f64, t: f64, h: f64) -> f64 {
    FD8.iter()
        .enumerate()
        .map(|(i, c)| {
            let k = (i + 1) as f64;
            c * (f(t + k * h) - f(t - k * h))
        })
        .sum::<f64>()
        / h
}

proptest! {
    /// θ'' + 2ζω θ' + ω² θ = 0, with θ'' by finite differences of θ',
    /// relative to ω² (|θ0| + |v0|/ω): below 1e-8 (the bound).
    #[test]
    fn satisfies_the_equation(
        length in 0.1_f64..10.0,
        log_zeta in -7.0_f64..1.0,
        theta0 in -0.5_f64..0.5,
        v0 in -1.0_f64..1.0,
        periods in 0.0_f64..20.0,
    ) {
        let zeta = 10f64.powf(log_zeta);
        let p = damped(length, zeta);
        let w = p.natural_angular_frequency();
        let t = periods * std::f64::consts::TAU / w;
        // The step follows the fastest rate in the solution: ω, or the
        // fast mode ω(ζ + sqrt(ζ²-1)) of a heavily overdamped pendulum,
        // whose finite differences would otherwise carry the error.
        let fastest = w * (zeta + (zeta * zeta - 1.0).max(0.0).sqrt()).max(1.0);
        let h = 0.02 / fastest;
        let s = p.state_at(theta0, v0, t);
        let acceleration = derivative(|x| p.state_at(theta0, v0, x).angular_velocity, t, h);
        let residual = acceleration + 2.0 * zeta * w * s.angular_velocity + w * w * s.angle;
        let size = w * w * (theta0.abs() + v0.abs() / w) + f64::MIN_POSITIVE;
        prop_assert!(residual.abs() <= 1e-8 * size, "residual {:e}", residual / size);
        // And θ' is the derivative of θ.
        let velocity = derivative(|x| p.state_at(theta0, v0, x).angle, t, h);
        prop_assert!((velocity - s.angular_velocity).abs() <= 1e-9 * w * (theta0.abs() + v0.abs() / w) + 1e-300);
    }

    /// E = θ'²/2 + ω²θ²/2 never grows (dE/dt = -2ζω θ'²).
    #[test]
    fn energy_never_grows(length in 0.1_f64..10.0, log_zeta in -7.0_f64..1.0, t1 in 0.0_f64..50.0, dt in 0.0_f64..5.0) {
        let p = damped(length, 10f64.powf(log_zeta));
        let w = p.natural_angular_frequency();
        let energy = |t: f64| {
            let s = p.state_at(0.1, 0.0, t);
            0.5 * s.angular_velocity * s.angular_velocity + 0.5 * w * w * s.angle * s.angle
        };
        let (e1, e2) = (energy(t1), energy(t1 + dt));
        prop_assert!(e2 <= e1 * (1.0 + 1e-13), "{e1} -> {e2}");
    }

    /// No jump across ζ = 1: the states at 1 - 1e-12, 1 and 1 + 1e-12 agree.
    #[test]
    fn continuous_at_critical_damping(length in 0.1_f64..10.0, t in 0.0_f64..30.0, theta0 in -0.5_f64..0.5, v0 in -1.0_f64..1.0) {
        let exact = damped(length, 1.0).state_at(theta0, v0, t);
        for zeta in [1.0 - 1e-12, 1.0 + 1e-12] {
            let s = damped(length, zeta).state_at(theta0, v0, t);
            let w = damped(length, zeta).natural_angular_frequency();
            let size = theta0.abs() + v0.abs() / w;
            prop_assert!((s.angle - exact.angle).abs() <= 1e-10 * size);
            prop_assert!((s.angular_velocity - exact.angular_velocity).abs() <= 1e-10 * w * size);
        }
    }

    /// Turning points, with and without friction, are where θ' = 0 and θ
    /// equals the listed angle.
    #[test]
    fn turning_points_have_zero_velocity(length in 0.1_f64..10.0, log_zeta in -7.0_f64..-0.5, r in 0.0_f64..0.01) {
        let p = damped(length, 10f64.powf(log_zeta));
        let w = p.natural_angular_frequency();
        let f = DryFriction::new(p, r).unwrap();
        let run = f.run_down(0.1, 40);
        for pair in run.extrema.windows(2) {
            let s = f.state_in(&f.half_swing(&pair[0]), pair[1].time);
            prop_assert!((s.angle - pair[1].angle).abs() <= 1e-14);
            prop_assert!(s.angular_velocity.abs() <= 1e-13 * w);
        }
    }
}

#[test]
fn extrema_follow_the_seed() {
    // |A_N| = |A0| e^{-Nζπ/sqrt(1-ζ²)} at t = Nπ/ω_d.
    let p = damped(0.99362, 0.02);
    let wd = p.damped_angular_frequency().unwrap();
    let lambda = (0.02 * std::f64::consts::PI / (1.0_f64 - 0.0004).sqrt()).exp();
    for e in p.extrema(0.05, 10) {
        let n = e.index as f64;
        assert!((e.time - n * std::f64::consts::PI / wd).abs() < 1e-15 * (1.0 + e.time));
        assert!((e.angle.abs() - 0.05 / lambda.powf(n)).abs() < 1e-16);
    }
}
