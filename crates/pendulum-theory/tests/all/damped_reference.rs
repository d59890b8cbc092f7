//! The damped linear pendulum (seed section 1-4) and the damping
//! conversions against mpmath at 40 digits (`tools/reference/make_reference.py`
//! computes them from the roots of the characteristic equation in complex
//! arithmetic, a different route from the library's real form).
//! `cargo test --release -p pendulum-theory --test all damped_reference:: -- --nocapture` prints the
//! worst errors.

use crate::common;
use common::{check_all, ulp_error, Reference, Worst};
use pendulum_theory::damped::DampedPendulum;
use pendulum_theory::damping::Damping;
use pendulum_theory::{Pendulum, STANDARD_GRAVITY};

/// Allowed errors, one table.
mod allowed {
    /// θ and θ', in units of ε (|θ0| + |v0|/ω_n) (1 + ω_n t): an ulp of the
    /// state's size, growing with the phase ω_d t, whose last bit every
    /// evaluation of a cosine of a large argument inherits.
    pub const TRAJECTORY: f64 = 4.0;
    /// Q, logarithmic decrement, c, decay time, half-life: ulp.
    pub const CONVERSION: f64 = 4.0;
}

#[test]
fn free_vibration_in_all_regimes() {
    let mut angle = Worst::new("theta(t), all regimes");
    let mut velocity = Worst::new("theta'(t), all regimes");
    for r in Reference::load("damped.csv", 9).rows {
        let (zeta, length, theta0, v0, t) = (r[0], r[1], r[2], r[3], r[4]);
        let pendulum = Pendulum::with_standard_gravity(length).unwrap();
        let p = DampedPendulum::new(pendulum, Damping::from_zeta(zeta).unwrap());
        let w = p.natural_angular_frequency();
        let s = p.state_at(theta0, v0, t);
        let scale = f64::EPSILON * (theta0.abs() + v0.abs() / w) * (1.0 + w * t);
        angle.see(((s.angle - r[5]) - r[6]).abs() / scale, zeta);
        velocity.see(
            ((s.angular_velocity - r[7]) - r[8]).abs() / (w * scale),
            zeta,
        );
    }
    check_all(&[
        (&angle, allowed::TRAJECTORY),
        (&velocity, allowed::TRAJECTORY),
    ]);
}

#[test]
fn damping_conversions() {
    let mut q = Worst::new("Q = 1/(2 zeta)");
    let mut delta = Worst::new("log decrement");
    let mut c = Worst::new("c = 2 m zeta sqrt(g l)");
    let mut tau = Worst::new("decay time");
    let mut half = Worst::new("half-life");
    let mut round_trips = Worst::new("zeta round trips");
    for r in Reference::load("damping_conversions.csv", 13).rows {
        let (zeta, length, mass) = (r[0], r[1], r[2]);
        let p = Pendulum::new(length, STANDARD_GRAVITY).unwrap();
        let d = Damping::from_zeta(zeta).unwrap();
        q.see(ulp_error(d.q_factor(), r[3], r[4]), zeta);
        if let Some(value) = d.log_decrement() {
            delta.see(ulp_error(value, r[5], r[6]), zeta);
            let back = Damping::from_log_decrement(value).unwrap().zeta();
            round_trips.see(ulp_error(back, zeta, 0.0), zeta);
        }
        c.see(ulp_error(d.coefficient(mass, &p), r[7], r[8]), zeta);
        tau.see(ulp_error(d.decay_time(&p), r[9], r[10]), zeta);
        half.see(ulp_error(d.amplitude_half_life(&p), r[11], r[12]), zeta);
        let from_c = Damping::from_coefficient(d.coefficient(mass, &p), mass, &p).unwrap();
        round_trips.see(ulp_error(from_c.zeta(), zeta, 0.0), zeta);
        let from_tau = Damping::from_decay_time(d.decay_time(&p), &p).unwrap();
        round_trips.see(ulp_error(from_tau.zeta(), zeta, 0.0), zeta);
        let from_q = Damping::from_q(d.q_factor()).unwrap();
        round_trips.see(ulp_error(from_q.zeta(), zeta, 0.0), zeta);
    }
    check_all(&[
        (&q, allowed::CONVERSION),
        (&delta, allowed::CONVERSION),
        (&c, allowed::CONVERSION),
        (&tau, allowed::CONVERSION),
        (&half, allowed::CONVERSION),
        (&round_trips, allowed::CONVERSION),
    ]);
}
