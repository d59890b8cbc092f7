//! The damped linear pendulum (seed section 1-4):
//! `θ'' + 2ζω_n θ' + ω_n² θ = 0`.
//!
//! The seed solves it by Laplace transform for `ζ < 1` from rest. Here the
//! free vibration is written once for all three regimes and any initial
//! velocity, in a form that is continuous through critical damping:
//!
//! `θ(t)  = e^{-ζω_n t} [θ0 C(t) + (v0 + ζω_n θ0) S(t)]`,
//! `θ'(t) = e^{-ζω_n t} [v0 C(t) - (ω_n² θ0 + ζω_n v0) S(t)]`,
//!
//! where, with `s = ω_n² (1 - ζ²)`,
//! `C = cos(ω_d t)`, `S = sin(ω_d t)/ω_d` when `s > 0` (underdamped, `ω_d = sqrt(s)`),
//! `C = 1`, `S = t` when `s = 0` (critical),
//! `C = cosh(μ t)`, `S = sinh(μ t)/μ` when `s < 0` (overdamped, `μ = sqrt(-s)`).
//! `S` is evaluated as `t sinc(ω_d t)` (or `t sinhc(μ t)`), so nothing
//! divides by a vanishing `ω_d` as `ζ -> 1` from either side. When
//! overdamped and `μt` is large, the products `e^{-ζω_n t} cosh(μ t)` are
//! formed as sums of decaying exponentials, which neither overflow nor
//! multiply infinity by zero. These are the Laplace-transform solutions of
//! the seed (and of any text on the damped oscillator, e.g. Thomson &
//! Dahleh, *Theory of Vibration*, ch. 2), rearranged.
//!
//! Accuracy against mpmath at 30 digits (`tests/all/damped_reference.rs`): a
//! few ulp of `|θ0| + |v0|/ω_n` over `ζ` in `[1e-7, 10]` and several
//! hundred periods.

pub mod analysis;
pub mod friction;

use crate::damping::Damping;
use crate::pendulum::Pendulum;
use std::f64::consts::PI;

/// The three kinds of free motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Regime {
    /// `ζ < 1`: it oscillates with a decaying amplitude.
    Underdamped,
    /// `ζ = 1`: the fastest return without overshoot.
    CriticallyDamped,
    /// `ζ > 1`: a slow creep back, no oscillation.
    Overdamped,
}

impl Regime {
    /// The name used in JSON: `"underdamped"`, `"critically damped"`, `"overdamped"`.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Underdamped => "underdamped",
            Regime::CriticallyDamped => "critically damped",
            Regime::Overdamped => "overdamped",
        }
    }
}

/// A pendulum with viscous damping, small angles (`sin θ ≈ θ`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DampedPendulum {
    /// Length and gravity.
    pub pendulum: Pendulum,
    /// The viscous damping.
    pub damping: Damping,
}

/// The angle and angular velocity at one time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State {
    /// Angle, rad.
    pub angle: f64,
    /// Angular velocity, rad/s.
    pub angular_velocity: f64,
}

/// A turning point of the swing (an "extreme" of the seed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extremum {
    /// 0 for the start, then one per half period (one "vibration").
    pub index: u64,
    /// Time, s.
    pub time: f64,
    /// Signed angle, rad.
    pub angle: f64,
}

impl DampedPendulum {
    /// Joins a pendulum and a damping.
    pub fn new(pendulum: Pendulum, damping: Damping) -> Self {
        Self { pendulum, damping }
    }

    /// `ω_n = sqrt(g/l)`, rad/s.
    pub fn natural_angular_frequency(&self) -> f64 {
        self.pendulum.natural_angular_frequency()
    }

    /// Which of the three regimes the damping puts the pendulum in.
    pub fn regime(&self) -> Regime {
        let zeta = self.damping.zeta();
        if zeta < 1.0 {
            Regime::Underdamped
        } else if zeta == 1.0 {
            Regime::CriticallyDamped
        } else {
            Regime::Overdamped
        }
    }

    /// `ω_d = ω_n sqrt(1 - ζ²)`, rad/s; `None` unless underdamped.
    pub fn damped_angular_frequency(&self) -> Option<f64> {
        let factor = self.damping.damped_frequency_factor()?;
        Some(self.natural_angular_frequency() * factor)
    }

    /// The time constant of the slowest part of the motion, s: the envelope's
    /// `1/(ζω_n)` when underdamped, `1/ω_n` at critical damping, and when
    /// overdamped the slow root's `1/(ω_n (ζ - sqrt(ζ² - 1)))`, computed as
    /// `(ζ + sqrt(ζ² - 1))/ω_n` (no cancellation: at ζ = 1e5 it is 2ζ/ω_n,
    /// where the pendulum creeps back, not the fast `1/(ζω_n)`). Infinite
    /// without damping.
    pub fn slowest_time_constant(&self) -> f64 {
        let zeta = self.damping.zeta();
        let w = self.natural_angular_frequency();
        if zeta <= 1.0 {
            1.0 / (zeta * w)
        } else {
            (zeta + ((zeta - 1.0) * (zeta + 1.0)).sqrt()) / w
        }
    }

    /// The damped period `T_d = 2π/ω_d`, s; `None` unless underdamped.
    pub fn damped_period(&self) -> Option<f64> {
        self.damped_angular_frequency().map(|w| 2.0 * PI / w)
    }

    /// The seed's phase `φ = atan(ζ / sqrt(1 - ζ²))`, rad, with which
    /// `θ = A0 e^{-ζω_n t} cos(ω_d t - φ) / sqrt(1 - ζ²)`; `None` unless underdamped.
    pub fn phase(&self) -> Option<f64> {
        let factor = self.damping.damped_frequency_factor()?;
        Some(self.damping.zeta().atan2(factor))
    }

    /// The free vibration at time `t` (s) from angle `theta0` (rad) and
    /// angular velocity `v0` (rad/s) at `t = 0`.
    pub fn state_at(&self, theta0: f64, v0: f64, t: f64) -> State {
        let w = self.natural_angular_frequency();
        let zw = self.damping.zeta() * w;
        let (c, s) = self.decayed_basis(t);
        State {
            angle: theta0 * c + (v0 + zw * theta0) * s,
            angular_velocity: v0 * c - (w * w * theta0 + zw * v0) * s,
        }
    }

    /// `(e^{-ζω t} C(t), e^{-ζω t} S(t))` of the module documentation.
    fn decayed_basis(&self, t: f64) -> (f64, f64) {
        let w = self.natural_angular_frequency();
        let zeta = self.damping.zeta();
        let zw = zeta * w;
        // s = ω² (1 - ζ²), formed without cancellation near ζ = 1.
        let s = w * w * ((1.0 - zeta) * (1.0 + zeta));
        if s >= 0.0 {
            let wd = s.sqrt();
            let decay = (-zw * t).exp();
            let x = wd * t;
            return (decay * x.cos(), decay * t * sinc(x));
        }
        let mu = (-s).sqrt();
        let x = mu * t;
        if x < 0.5 {
            let decay = (-zw * t).exp();
            return (decay * x.cosh(), decay * t * sinhc(x));
        }
        // e^{-ζωt} cosh(μt) = (e^{-(ζω-μ)t} + e^{-(ζω+μ)t})/2, and
        // ζω - μ = ω/(ζ + sqrt(ζ²-1)) without cancellation.
        let slow = (-(w * w / (zw + mu)) * t).exp();
        let fast = (-(zw + mu) * t).exp();
        (0.5 * (slow + fast), 0.5 * (slow - fast) / mu)
    }

    /// The turning points `0..=count` of a swing released from rest at
    /// `amplitude` (rad): at `t_n = nπ/ω_d`, angles
    /// `(-1)^n A0 exp(-nζπ/sqrt(1 - ζ²))` (seed section 1-4). Critically
    /// damped and overdamped pendulums never turn: only the start is listed.
    pub fn extrema(&self, amplitude: f64, count: u64) -> Vec<Extremum> {
        let start = Extremum {
            index: 0,
            time: 0.0,
            angle: amplitude,
        };
        let (Some(wd), Some(factor)) = (
            self.damped_angular_frequency(),
            self.damping.damped_frequency_factor(),
        ) else {
            return vec![start];
        };
        let per_vibration = self.damping.zeta() * PI / factor;
        let mut out = vec![start];
        for n in 1..=count {
            let nf = n as f64;
            let sign = if n % 2 == 0 { 1.0 } else { -1.0 };
            out.push(Extremum {
                index: n,
                time: nf * PI / wd,
                angle: sign * amplitude * (-nf * per_vibration).exp(),
            });
        }
        out
    }

    /// The envelope of the swing released from rest at `amplitude`:
    /// `A0 e^{-ζω_n t} / sqrt(1 - ζ²)` (the seed's form of the free
    /// vibration); `None` unless underdamped.
    pub fn envelope(&self, amplitude: f64, t: f64) -> Option<f64> {
        let factor = self.damping.damped_frequency_factor()?;
        Some(
            amplitude * (-self.damping.zeta() * self.natural_angular_frequency() * t).exp()
                / factor,
        )
    }

    /// The amplitude lost over one full period from `amplitude`, exactly:
    /// `A (1 - e^{-δ})`, with `δ` the logarithmic decrement. `None` unless
    /// underdamped.
    pub fn amplitude_loss_per_period(&self, amplitude: f64) -> Option<f64> {
        let delta = self.damping.log_decrement()?;
        Some(-amplitude.abs() * (-delta).exp_m1())
    }

    /// The seed's first-order form of the same loss:
    /// `2πζ/sqrt(1 - ζ²) A = (c/(2ml)) T_d A`. `None` unless underdamped.
    pub fn amplitude_loss_per_period_approx(&self, amplitude: f64) -> Option<f64> {
        Some(self.damping.log_decrement()? * amplitude.abs())
    }
}

/// `sin x / x`, with its Taylor series near 0 where the quotient would lose digits.
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        let x2 = x * x;
        1.0 - x2 / 6.0 * (1.0 - x2 / 20.0)
    } else {
        x.sin() / x
    }
}

/// `sinh x / x`, likewise.
fn sinhc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        let x2 = x * x;
        1.0 + x2 / 6.0 * (1.0 + x2 / 20.0)
    } else {
        x.sinh() / x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pendulum(zeta: f64) -> DampedPendulum {
        DampedPendulum::new(
            Pendulum::with_standard_gravity(0.99362).unwrap(),
            Damping::from_zeta(zeta).unwrap(),
        )
    }

    #[test]
    fn regimes() {
        assert_eq!(pendulum(0.5).regime(), Regime::Underdamped);
        assert_eq!(pendulum(1.0).regime(), Regime::CriticallyDamped);
        assert_eq!(pendulum(1.5).regime(), Regime::Overdamped);
        assert_eq!(pendulum(1.5).damped_period(), None);
        assert_eq!(pendulum(1.0).phase(), None);
    }

    #[test]
    fn slowest_time_constant_is_what_the_motion_shows() {
        // Overdamped from rest: θ(t)/θ0 falls by e over the slow time
        // constant once the fast mode has died (independent check: the
        // closed form's own state over one time constant late in the creep).
        for zeta in [2.0, 10.0, 1e5] {
            let d = pendulum(zeta);
            let tau = d.slowest_time_constant();
            let t1 = 20.0 / (zeta * d.natural_angular_frequency());
            let a = d.state_at(1.0, 0.0, t1).angle;
            let b = d.state_at(1.0, 0.0, t1 + tau).angle;
            assert!(
                ((a / b).ln() - 1.0).abs() < 1e-6,
                "ζ {zeta}: {}",
                (a / b).ln()
            );
        }
        let u = pendulum(0.01);
        assert_eq!(u.slowest_time_constant(), u.damping.decay_time(&u.pendulum));
    }

    #[test]
    fn seed_formula_from_rest() {
        // θ = A0 e^{-ζω t} / sqrt(1-ζ²) cos(ω_d t - φ) (seed section 1-4).
        let p = pendulum(0.05);
        let (w, wd, phi) = (
            p.natural_angular_frequency(),
            p.damped_angular_frequency().unwrap(),
            p.phase().unwrap(),
        );
        let a0 = 0.05;
        for &t in &[0.0, 0.3, 1.7, 12.0] {
            let seed =
                a0 * (-0.05 * w * t).exp() / (1.0_f64 - 0.0025).sqrt() * (wd * t - phi).cos();
            assert!((p.state_at(a0, 0.0, t).angle - seed).abs() < 1e-16);
        }
    }

    #[test]
    fn continuous_through_critical_damping() {
        let t = 0.8;
        let at = |z: f64| pendulum(z).state_at(0.1, 0.02, t);
        let below = at(1.0 - 1e-12);
        let exact = at(1.0);
        let above = at(1.0 + 1e-12);
        for s in [below, above] {
            assert!((s.angle - exact.angle).abs() < 1e-12);
            assert!((s.angular_velocity - exact.angular_velocity).abs() < 1e-12);
        }
    }

    #[test]
    fn heavy_damping_does_not_overflow() {
        let s = pendulum(10.0).state_at(0.1, 0.0, 1e4);
        assert!(s.angle.is_finite() && s.angle >= 0.0);
        assert!(s.angular_velocity.is_finite());
    }

    #[test]
    fn extrema_are_where_velocity_vanishes() {
        let p = pendulum(0.01);
        let w = p.natural_angular_frequency();
        for e in p.extrema(0.05, 20) {
            let s = p.state_at(0.05, 0.0, e.time);
            assert!((s.angle - e.angle).abs() < 1e-15, "{e:?}");
            assert!(s.angular_velocity.abs() < 1e-14 * w, "{e:?} {s:?}");
        }
        assert_eq!(pendulum(2.0).extrema(0.05, 20).len(), 1);
    }

    #[test]
    fn loss_per_period_first_order_agrees_for_light_damping() {
        let p = pendulum(1e-4);
        let exact = p.amplitude_loss_per_period(0.1).unwrap();
        let approx = p.amplitude_loss_per_period_approx(0.1).unwrap();
        assert!(exact < approx);
        assert!((approx - exact) / exact < 1e-3);
    }
}
