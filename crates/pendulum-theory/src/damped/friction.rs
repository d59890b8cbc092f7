//! Dry (Coulomb) friction added to viscous damping, as the book's section 2-4
//! does for the balance wheel:
//! `θ'' + 2ζω_n θ' + ω_n² (θ + r sign θ') = 0`, with `r` the friction angle
//! (the friction torque divided by the restoring torque per radian).
//!
//! During each half swing `sign θ'` is constant, so the motion is the viscous
//! free vibration of [`crate::damped`] about the shifted centre
//! `c_n = r sign(A_n)`. From rest at `A_n` it reaches its next turning point
//! after `π/ω_d` at `A_{n+1} = c_n - (A_n - c_n)/λ`, `λ = e^{ζπ/sqrt(1-ζ²)}`,
//! so `|A_{n+1}| = (|A_n| - r)/λ - r`. Without viscous damping (`λ = 1`) the
//! amplitude falls by exactly `2r` per half swing: a straight line, not an
//! exponential. The pendulum sticks at the first turning point where
//! `|A| <= r` (the restoring torque no longer beats friction); that point
//! may lie on the same side as the one before. Critically damped and
//! overdamped pendulums creep towards `r sign(A0)` without ever turning.

use super::{DampedPendulum, Extremum, State};
use crate::error::InputError;
use std::f64::consts::PI;

/// A damped pendulum with a friction angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DryFriction {
    /// The viscously damped pendulum.
    pub damped: DampedPendulum,
    friction_angle: f64,
}

/// Where and when the pendulum sticks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stop {
    /// Time, s; `None` when it creeps there without end (overdamped).
    pub time: Option<f64>,
    /// The signed angle it stays at, rad.
    pub angle: f64,
}

/// The turning points of a run down, and where it stops.
#[derive(Clone, Debug, PartialEq)]
pub struct RunDown {
    /// Turning points from the start; the last is the stop when it stops in time.
    pub extrema: Vec<Extremum>,
    /// `None` if it had not stopped by the last turning point computed.
    pub stop: Option<Stop>,
}

/// One half swing: from rest at `start_angle` at `start_time`, about `centre`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSwing {
    /// Time of the turning point it starts from, s.
    pub start_time: f64,
    /// The angle it starts from, rad.
    pub start_angle: f64,
    /// The centre it swings about, `r sign(start_angle)`, rad.
    pub centre: f64,
}

impl DryFriction {
    /// `friction_angle` in radians, finite and not negative (0: viscous only).
    pub fn new(damped: DampedPendulum, friction_angle: f64) -> Result<Self, InputError> {
        Ok(Self {
            damped,
            friction_angle: crate::error::require_friction_angle(friction_angle)?,
        })
    }

    /// The friction angle `r`, rad.
    pub fn friction_angle(&self) -> f64 {
        self.friction_angle
    }

    /// `ζπ/sqrt(1 - ζ²)` = ln λ, the viscous decrement per half swing; `None` unless underdamped.
    fn half_decrement(&self) -> Option<f64> {
        let factor = self.damped.damping.damped_frequency_factor()?;
        Some(self.damped.damping.zeta() * PI / factor)
    }

    /// The envelope through the turning points' amplitudes, rad, at time
    /// `t` from rest at `amplitude` (ignoring sticking: it holds until the
    /// stop of [`DryFriction::run_down`]); `None` unless underdamped.
    ///
    /// Method: the recurrence `|A_{n+1}| = (|A_n| - r)/λ - r` is linear,
    /// with the fixed point `-c`, `c = r (λ + 1)/(λ - 1)`, so
    /// `|A_n| = (|A_0| + c) λ^{-n} - c`; read with the continuous
    /// `n = t ω_d / π` it is the curve `|A_0| e^{-ζω_n t} - c (1 - e^{-ζω_n t})`
    /// on which every turning point lies. Formed as
    /// `|A_0| e^{-dn} + r (λ + 1) expm1(-dn) / expm1(d)`, `d = ln λ`, so that
    /// it goes smoothly to the straight line `|A_0| - 2 r n` of pure dry
    /// friction as `ζ → 0`. Exact at the turning points to a few ulp
    /// (tested against the recurrence).
    pub fn envelope(&self, amplitude: f64, t: f64) -> Option<f64> {
        let d = self.half_decrement()?;
        let wd = self.damped.damped_angular_frequency()?;
        let n = t * wd / PI;
        let r = self.friction_angle;
        let ratio = if d == 0.0 {
            -n
        } else {
            (-d * n).exp_m1() / d.exp_m1()
        };
        Some(amplitude.abs() * (-d * n).exp() + r * (d.exp() + 1.0) * ratio)
    }

    /// The next turning point after rest at `angle`, ignoring sticking.
    pub fn next_turning_angle(&self, angle: f64) -> Option<f64> {
        let lambda_inv = (-self.half_decrement()?).exp();
        let centre = self.friction_angle.copysign(angle);
        Some(centre - (angle - centre) * lambda_inv)
    }

    /// The amplitude lost in one half swing from `amplitude`,
    /// `(A - r)(1 - 1/λ) + 2r`, formed with `expm1` so that it keeps its
    /// digits when the loss is tiny. `None` unless underdamped. Meaningful
    /// while the swing carries on past the centre (`|A| - loss > r`); a
    /// larger value says the pendulum sticks in this half swing.
    pub fn half_swing_loss(&self, amplitude: f64) -> Option<f64> {
        let a = amplitude.abs();
        let r = self.friction_angle;
        Some(-(a - r) * (-self.half_decrement()?).exp_m1() + 2.0 * r)
    }

    /// The amplitude lost over the first full period from `amplitude`
    /// (two half swings, exact); `None` unless underdamped or if the
    /// pendulum sticks within that period.
    pub fn amplitude_loss_per_period(&self, amplitude: f64) -> Option<f64> {
        let first = self.half_swing_loss(amplitude)?;
        let middle = amplitude.abs() - first;
        if middle <= self.friction_angle {
            return None;
        }
        let second = self.half_swing_loss(middle)?;
        (middle - second > self.friction_angle).then_some(first + second)
    }

    /// The first-order form: the seed's `2πζ/sqrt(1 - ζ²) A` plus `4r`.
    pub fn amplitude_loss_per_period_approx(&self, amplitude: f64) -> Option<f64> {
        Some(self.damped.amplitude_loss_per_period_approx(amplitude)? + 4.0 * self.friction_angle)
    }

    /// A sampler of the motion from rest at `amplitude`, for times that
    /// never decrease: it walks from half swing to half swing, so a run of
    /// any length needs constant memory.
    pub fn sampler(&self, amplitude: f64) -> Sampler {
        let start = Extremum {
            index: 0,
            time: 0.0,
            angle: amplitude,
        };
        let stuck = amplitude.abs() <= self.friction_angle;
        Sampler {
            friction: *self,
            swing: self.half_swing(&start),
            next: self.following(&start),
            stuck,
        }
    }

    /// The turning point after `from`, if the pendulum turns at all.
    fn following(&self, from: &Extremum) -> Option<Extremum> {
        let wd = self.damped.damped_angular_frequency()?;
        Some(Extremum {
            index: from.index + 1,
            time: (from.index + 1) as f64 * PI / wd,
            angle: self.next_turning_angle(from.angle)?,
        })
    }

    /// Turning points `0..=count` from rest at `amplitude`, stopping early
    /// where the pendulum sticks.
    pub fn run_down(&self, amplitude: f64, count: u64) -> RunDown {
        let r = self.friction_angle;
        let mut extrema = vec![Extremum {
            index: 0,
            time: 0.0,
            angle: amplitude,
        }];
        if amplitude.abs() <= r {
            let stop = Stop {
                time: Some(0.0),
                angle: amplitude,
            };
            return RunDown {
                extrema,
                stop: Some(stop),
            };
        }
        let Some(wd) = self.damped.damped_angular_frequency() else {
            let stop = (r > 0.0).then(|| Stop {
                time: None,
                angle: r.copysign(amplitude),
            });
            return RunDown { extrema, stop };
        };
        let mut angle = amplitude;
        for n in 1..=count {
            angle = self.next_turning_angle(angle).expect("underdamped");
            let time = n as f64 * PI / wd;
            extrema.push(Extremum {
                index: n,
                time,
                angle,
            });
            if angle.abs() <= r {
                let stop = Stop {
                    time: Some(time),
                    angle,
                };
                return RunDown {
                    extrema,
                    stop: Some(stop),
                };
            }
        }
        RunDown {
            extrema,
            stop: None,
        }
    }

    /// The half swing that begins at turning point `from` (which must not be a stop).
    pub fn half_swing(&self, from: &Extremum) -> HalfSwing {
        HalfSwing {
            start_time: from.time,
            start_angle: from.angle,
            centre: self.friction_angle.copysign(from.angle),
        }
    }

    /// The state at time `t` within `swing` (from its start to the next turning point).
    pub fn state_in(&self, swing: &HalfSwing, t: f64) -> State {
        let offset = swing.start_angle - swing.centre;
        let s = self.damped.state_at(offset, 0.0, t - swing.start_time);
        State {
            angle: swing.centre + s.angle,
            angular_velocity: s.angular_velocity,
        }
    }
}

/// The motion from rest, sampled at non-decreasing times (see [`DryFriction::sampler`]).
#[derive(Clone, Debug)]
pub struct Sampler {
    friction: DryFriction,
    swing: HalfSwing,
    next: Option<Extremum>,
    stuck: bool,
}

impl Sampler {
    /// The state at `t`, s; `t` must not be less than at the previous call.
    pub fn state_at(&mut self, t: f64) -> State {
        let r = self.friction.friction_angle;
        while !self.stuck {
            match self.next {
                Some(turn) if t >= turn.time => {
                    if turn.angle.abs() <= r {
                        self.stuck = true;
                        self.swing.start_angle = turn.angle;
                        break;
                    }
                    self.swing = self.friction.half_swing(&turn);
                    self.next = self.friction.following(&turn);
                }
                _ => break,
            }
        }
        if self.stuck {
            return State {
                angle: self.swing.start_angle,
                angular_velocity: 0.0,
            };
        }
        self.friction.state_in(&self.swing, t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::damping::Damping;
    use crate::pendulum::Pendulum;

    fn friction(zeta: f64, r: f64) -> DryFriction {
        let p = Pendulum::with_standard_gravity(0.99362).unwrap();
        DryFriction::new(DampedPendulum::new(p, Damping::from_zeta(zeta).unwrap()), r).unwrap()
    }

    #[test]
    fn the_envelope_passes_through_every_turning_point() {
        // Viscous and dry together, dry alone (a straight line), viscous
        // alone (the exponential).
        for (zeta, r) in [(0.01, 1e-3), (0.0, 1e-3), (0.02, 0.0), (1e-9, 2e-4)] {
            let f = friction(zeta, r);
            let run = f.run_down(0.1, 400);
            for e in &run.extrema {
                if e.angle.abs() <= r {
                    break;
                }
                let envelope = f.envelope(0.1, e.time).unwrap();
                assert!(
                    (envelope - e.angle.abs()).abs() <= 1e-14,
                    "ζ = {zeta}, r = {r}, n = {}: {envelope} against {}",
                    e.index,
                    e.angle.abs()
                );
            }
        }
        // Without viscous damping it is the line |A0| - 4 r t / T.
        let f = friction(0.0, 1e-3);
        let t = 3.3;
        let period = 2.0 * PI / f.damped.damped_angular_frequency().unwrap();
        let line = 0.1 - 4.0 * 1e-3 * t / period;
        assert!((f.envelope(0.1, t).unwrap() - line).abs() < 1e-15);
        // No envelope without oscillation.
        assert_eq!(friction(1.5, 1e-3).envelope(0.1, 1.0), None);
    }

    #[test]
    fn pure_coulomb_loses_two_r_per_half_swing() {
        let r = 1e-3;
        let run = friction(0.0, r).run_down(0.05, 100);
        for pair in run.extrema.windows(2) {
            let drop = pair[0].angle.abs() - pair[1].angle.abs();
            if pair[1].angle.abs() > r && pair[0].angle.abs() > r {
                assert!((drop - 2.0 * r).abs() < 1e-15, "{pair:?}");
            }
        }
        let stop = run.stop.unwrap();
        assert!(stop.angle.abs() <= r);
        // 0.05 / 0.002 = 25 half swings to fall within r.
        assert_eq!(run.extrema.len(), 26);
        assert_eq!(stop.time, Some(run.extrema[25].time));
    }

    #[test]
    fn stop_on_the_same_side() {
        // From 1.5r the next turning point is r - 0.5r = 0.5r... with λ = 1:
        // 2r - 1.5r = 0.5r > 0, the same side, inside the band: it sticks.
        let r = 0.01;
        let run = friction(0.0, r).run_down(0.015, 10);
        let stop = run.stop.unwrap();
        assert!(stop.angle > 0.0 && stop.angle <= r);
        assert_eq!(run.extrema.len(), 2);
    }

    #[test]
    fn overdamped_creeps_to_the_band_edge() {
        let run = friction(2.0, 0.01).run_down(0.1, 10);
        assert_eq!(run.extrema.len(), 1);
        assert_eq!(
            run.stop,
            Some(Stop {
                time: None,
                angle: 0.01
            })
        );
    }

    #[test]
    fn sampler_follows_the_run_down_and_stays_stuck() {
        let f = friction(0.0, 5e-3);
        let run = f.run_down(0.05, 100);
        let mut sampler = f.sampler(0.05);
        for e in &run.extrema {
            let s = sampler.state_at(e.time);
            assert!((s.angle - e.angle).abs() < 1e-15, "{e:?} {s:?}");
        }
        let stop = run.stop.unwrap();
        let later = sampler.state_at(stop.time.unwrap() + 100.0);
        assert_eq!((later.angle, later.angular_velocity), (stop.angle, 0.0));
    }

    #[test]
    fn no_loss_per_period_when_it_sticks_within_it() {
        let f = friction(0.2, 0.5_f64.to_radians());
        assert_eq!(f.amplitude_loss_per_period(3.0_f64.to_radians()), None);
        let light = friction(0.001, 0.01_f64.to_radians());
        let a = 3.0_f64.to_radians();
        let loss = light.amplitude_loss_per_period(a).unwrap();
        let a2 = light
            .next_turning_angle(light.next_turning_angle(a).unwrap())
            .unwrap();
        assert!((a - a2 - loss).abs() < 1e-16);
    }

    #[test]
    fn half_swing_loss_matches_the_recursion() {
        let f = friction(0.01, 2e-3);
        let next = f.next_turning_angle(0.1).unwrap();
        let loss = f.half_swing_loss(0.1).unwrap();
        assert!((0.1 - next.abs() - loss).abs() < 1e-16);
    }

    #[test]
    fn trajectory_meets_the_turning_points() {
        let f = friction(0.02, 1e-3);
        let run = f.run_down(0.05, 6);
        for pair in run.extrema.windows(2) {
            let swing = f.half_swing(&pair[0]);
            let s = f.state_in(&swing, pair[1].time);
            assert!((s.angle - pair[1].angle).abs() < 1e-15);
            assert!(s.angular_velocity.abs() < 1e-14);
        }
    }
}
