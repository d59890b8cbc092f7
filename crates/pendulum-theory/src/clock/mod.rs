//! The clock: a pendulum kept swinging by an escapement.
//!
//! The escapement ([`escapement`]) pushes the pendulum over windows of its
//! swing; damping (`Q`) takes energy; their balance sets the amplitude,
//! the amplitude sets the circular error, and where in the swing the
//! escapement pushes adds an error of its own (Airy, 1830). Every half
//! swing of a symmetric escapement is the same problem, started at rest at
//! `-A` and ending at rest at `+A'`: [`direct::half_swing`] integrates it,
//! [`averaged::half_swing_map`] gives it in closed form, and the steady
//! state is the amplitude the half swing gives back ([`Clock::steady`]).
//!
//! The rate is split into the circular error (the free pendulum's exact
//! period at the steady amplitude against the small-angle period) and the
//! escapement's (the clock's period against that free period), which
//! [`airy::time_shift`] predicts to first order.

pub mod airy;
pub mod analysis;
pub mod averaged;
pub mod direct;
pub mod escapement;
pub mod long_run;
pub mod plan;

use crate::forces::DragLaw;
use crate::pendulum::Pendulum;
use escapement::Escapement;

/// Seconds in a day.
const DAY: f64 = 86_400.0;

/// Why a clock has no steady state, or its inputs none at all.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ClockError {
    /// The drive cannot carry the pendulum through the escapement's lift.
    #[error("the pendulum stops: the drive is below {minimum_factor:.4} of the one given (it must carry the swing past {unlocking_deg:.3}° to unlock the escapement)")]
    Stops {
        /// The smallest drive factor that keeps it going.
        minimum_factor: f64,
        /// The amplitude it must reach, degrees.
        unlocking_deg: f64,
    },
    /// No drive keeps it going: the escapement takes more than it gives as
    /// soon as the swing passes the lift, whatever the drive.
    #[error("no drive keeps this escapement going: it takes more energy than it gives as soon as the swing passes the lift (a recoil or its friction too large; a constant-force impulse too small for its locking friction; a drag too large)")]
    NeverRuns,
    /// The swing would go over the top.
    #[error("the drive swings the pendulum past 170°: give less drive or more damping")]
    OverTheTop,
    /// No damping: nothing limits the amplitude.
    #[error("without damping nothing limits the swing: give a finite Q")]
    Undamped,
    /// The integration failed.
    #[error("the half swing could not be integrated at amplitude {0} rad")]
    Integration(f64),
}

/// How the half swings are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HalfSwingMethod {
    /// Integrated at a tolerance ([`direct::half_swing`]).
    Direct,
    /// The closed-form map ([`averaged::half_swing_map`]).
    Averaged,
}

/// A pendulum, its damping, and its escapement.
#[derive(Debug)]
pub struct Clock {
    /// The pendulum (its equivalent length for a design).
    pub pendulum: Pendulum,
    /// The quality factor.
    pub q: f64,
    /// The escapement (torques over `torque_scale`).
    pub escapement: Box<dyn Escapement>,
    /// `m g l` (for a design `M g d`), N·m: the unit of the escapement's
    /// torques and energies.
    pub torque_scale: f64,
    /// The share of the restoring stiffness a suspension spring gives (0
    /// for a rigid pivot): its torque is linear in the angle, so it
    /// shrinks the circular error ([`Clock::spring_factor`]).
    pub elastic_share: f64,
    /// Drag laws of [`crate::forces::DRAG_LAWS`] beside the viscous
    /// damping, with their coefficients scaled ([`DragLaw::scaled`]).
    pub drag: Vec<(&'static dyn DragLaw, f64)>,
}

/// A clock's steady state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Steady {
    /// The drive factor.
    pub drive: f64,
    /// Amplitude, rad.
    pub amplitude: f64,
    /// The clock's period (two beats), s.
    pub period: f64,
    /// The free pendulum's exact period at that amplitude, s.
    pub free_period: f64,
    /// The small-angle period `2π sqrt(l/g)`, s.
    pub small_angle_period: f64,
    /// The clock's rate against a small-angle clock, s/day (positive:
    /// gaining): `86400 (T₀/T - 1)`.
    pub rate: f64,
    /// The circular error's part, s/day: `86400 (T₀/T_free - 1)`.
    pub circular_rate: f64,
    /// The escapement's part, s/day: `86400 (T_free/T - 1)`.
    pub escapement_rate: f64,
    /// The escapement's part by Airy's first-order integral, s/day.
    pub escapement_rate_first_order: f64,
    /// The beat error, s: half the difference of the intervals between
    /// ticks on alternate beats (the crossings of the escapement's last
    /// edge, the drop), from the integrated half swings of one cycle; 0 in
    /// beat.
    pub beat_error: f64,
    /// The energy the escapement gives per beat, J.
    pub energy_per_beat: f64,
    /// The mean power, W.
    pub power: f64,
}

/// Tolerance of the integrated half swings.
pub const DIRECT_TOLERANCE: f64 = 1e-13;

impl Clock {
    /// The factor a suspension spring puts on the duration of a half swing
    /// of amplitude `a` rad: its period ratio over a rigid pendulum's,
    /// [`crate::suspension::period_ratio`] at [`Clock::elastic_share`] over
    /// the same at 0 (1 without a spring). It is applied to the half swings
    /// the escapement drives, as a correction: the spring's linear torque
    /// meets the escapement's only in a product of the elastic share and
    /// the escapement's own error (a regulator's spring, share 1e-3,
    /// changes a 1 s/day escapement error by about 1e-3 s/day, which is
    /// left out).
    pub fn spring_factor(&self, a: f64) -> f64 {
        if self.elastic_share <= 0.0 {
            return 1.0;
        }
        // The rigid pendulum's ratio is the AGM's (the same to 4e-16).
        crate::Amplitude::from_radians(a).map_or(1.0, |amplitude| {
            crate::suspension::period_ratio(a, self.elastic_share)
                / crate::period::period_ratio(amplitude)
        })
    }

    /// The losses beside the escapement: the Q and the drag laws.
    pub fn losses(&self) -> direct::Losses<'_> {
        direct::Losses {
            q: self.q,
            drag: &self.drag,
        }
    }

    /// The half swing from `-a1` on beat `beat`.
    pub fn half_swing(
        &self,
        method: HalfSwingMethod,
        drive: f64,
        beat: u64,
        a1: f64,
    ) -> Option<direct::HalfSwing> {
        match method {
            HalfSwingMethod::Direct => direct::half_swing(
                self.escapement.as_ref(),
                self.losses(),
                drive,
                beat,
                a1,
                DIRECT_TOLERANCE,
            ),
            HalfSwingMethod::Averaged => averaged::half_swing_map(
                Some(self.escapement.as_ref()),
                self.q,
                &self.drag,
                drive,
                beat,
                a1,
                true,
            ),
        }
    }

    /// One cycle of the escapement's pattern from `a`: the amplitude after
    /// it and its scaled duration.
    fn cycle(&self, method: HalfSwingMethod, drive: f64, a: f64) -> Option<(f64, f64)> {
        let mut amplitude = a;
        let mut time = 0.0;
        for beat in 0..self.escapement.cycle() {
            let h = self.half_swing(method, drive, beat, amplitude)?;
            amplitude = h.amplitude;
            time += h.time;
        }
        Some((amplitude, time))
    }

    /// The energy balance over a cycle at a fixed amplitude `a`, scaled:
    /// what the escapement gives less what damping takes.
    fn balance(&self, drive: f64, a: f64) -> f64 {
        let n = self.escapement.cycle();
        let given: f64 = (0..n)
            .map(|beat| self.escapement.energy(a, a, beat, drive))
            .sum();
        given - n as f64 * self.half_swing_loss(a)
    }

    /// The energy (scaled) a free half swing of amplitude `a` loses: the
    /// viscous part `D(a)/Q` and each drag law's `k ∫ v^p dθ`.
    pub fn half_swing_loss(&self, a: f64) -> f64 {
        averaged::half_swing_action(a) / self.q + averaged::drag_loss(&self.drag, a)
    }

    /// The Q the swing has at amplitude `a` with every loss counted: the
    /// viscous `Q` with the drag laws' losses added at that swing (`Q`
    /// itself without them).
    pub fn effective_q(&self, a: f64) -> f64 {
        if self.drag.is_empty() {
            return self.q;
        }
        let action = averaged::half_swing_action(a);
        let q = action / self.half_swing_loss(a);
        if q.is_finite() && q > 0.0 {
            q
        } else {
            self.q
        }
    }

    /// The smallest drive factor that carries the swing past the
    /// escapement's unlocking amplitude (bisection on the energy balance
    /// there); infinite when none below 1e12 does (the escapement takes
    /// more than it gives there, in proportion to the drive); 0 when any
    /// drive does (an impulse that does not depend on the drive: a
    /// constant-force escapement).
    pub fn minimum_drive(&self) -> f64 {
        let a = (self.escapement.unlocking_amplitude() * (1.0 + 1e-9)).max(1e-6);
        if self.balance(1e-12, a) > 0.0 {
            return 0.0;
        }
        let (mut lo, mut hi) = (0.0, 1.0);
        while self.balance(hi, a) <= 0.0 && hi < 1e12 {
            hi *= 2.0;
        }
        if self.balance(hi, a) <= 0.0 {
            return f64::INFINITY;
        }
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if self.balance(mid, a) > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        hi
    }

    /// The steady state at drive factor `drive`: the amplitude that one
    /// cycle of half swings gives back, by bisection on the energy balance
    /// for a start, then the secant method on the half swings themselves
    /// (to 1e-13 of the amplitude).
    pub fn steady(&self, method: HalfSwingMethod, drive: f64) -> Result<Steady, ClockError> {
        if !self.q.is_finite() {
            return Err(ClockError::Undamped);
        }
        let unlock = (self.escapement.unlocking_amplitude() * (1.0 + 1e-9)).max(1e-6);
        let top = 170f64.to_radians();
        if self.balance(drive, unlock) <= 0.0 {
            if self.minimum_drive().is_infinite() {
                return Err(ClockError::NeverRuns);
            }
            return Err(ClockError::Stops {
                minimum_factor: self.minimum_drive() / drive,
                unlocking_deg: unlock.to_degrees(),
            });
        }
        if self.balance(drive, top) > 0.0 {
            return Err(ClockError::OverTheTop);
        }
        let (mut lo, mut hi) = (unlock, top);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if self.balance(drive, mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo < 1e-15 * hi {
                break;
            }
        }
        let mut a0 = 0.5 * (lo + hi);
        let f = |a: f64| -> Result<(f64, f64), ClockError> {
            self.cycle(method, drive, a)
                .map(|(b, t)| (b - a, t))
                .ok_or(ClockError::Integration(a))
        };
        let (mut f0, _) = f(a0)?;
        let mut a1 = a0 * (1.0 + 1e-7);
        for _ in 0..60 {
            let (f1, _) = f(a1)?;
            if f1 == f0 {
                break;
            }
            let next = a1 - f1 * (a1 - a0) / (f1 - f0);
            (a0, f0, a1) = (a1, f1, next.clamp(unlock, top));
            if (a1 - a0).abs() <= 1e-13 * a1 {
                break;
            }
        }
        let (_, scaled_time) = f(a1)?;
        let beat_error = self.beat_error(drive, a1)?;
        self.describe(drive, a1, scaled_time, beat_error)
    }

    /// The beat error of the steady cycle from `a`, s (see
    /// [`Steady::beat_error`]): the ticks of the integrated half swings
    /// (at tolerance [`DIRECT_TOLERANCE`]) of one cycle.
    fn beat_error(&self, drive: f64, a: f64) -> Result<f64, ClockError> {
        let n = self.escapement.cycle();
        if (0..n).all(|beat| self.escapement.offset(beat) == 0.0) || n % 2 == 1 {
            return Ok(0.0);
        }
        let mut amplitude = a;
        let mut beats = Vec::with_capacity(n as usize);
        for beat in 0..n {
            let (h, tick) = direct::half_swing_ticked(
                self.escapement.as_ref(),
                self.losses(),
                drive,
                beat,
                amplitude,
                DIRECT_TOLERANCE,
            )
            .ok_or(ClockError::Integration(amplitude))?;
            // A swing that only grazes the last edge (the clock near
            // stopping) turns there: the drop is at the turn.
            let tick = tick.unwrap_or(h.time);
            beats.push((h.time, tick));
            amplitude = h.amplitude;
        }
        // The interval from beat k's tick to beat k+1's (the cycle's first
        // beat again after the last), alternately summed.
        let difference: f64 = (0..beats.len())
            .map(|k| {
                let (time, tick) = beats[k];
                let next = beats[(k + 1) % beats.len()].1;
                let interval = time - tick + next;
                if k % 2 == 0 {
                    interval
                } else {
                    -interval
                }
            })
            .sum();
        let omega = self.pendulum.natural_angular_frequency();
        Ok((difference / n as f64).abs() / omega)
    }

    /// The steady state's figures from its amplitude and the scaled
    /// duration of one cycle.
    fn describe(
        &self,
        drive: f64,
        a: f64,
        cycle_time: f64,
        beat_error: f64,
    ) -> Result<Steady, ClockError> {
        let omega = self.pendulum.natural_angular_frequency();
        let n = self.escapement.cycle() as f64;
        let spring = self.spring_factor(a);
        let period = 2.0 * cycle_time / n / omega * spring;
        let free_half = airy::free_half_period(a);
        let free_period = 2.0 * free_half / omega * spring;
        let small = self.pendulum.small_angle_period();
        let shift: f64 = (0..self.escapement.cycle())
            .map(|beat| airy::time_shift(self.escapement.as_ref(), a, beat, drive))
            .sum::<f64>()
            / n;
        let energy_per_beat = (0..self.escapement.cycle())
            .map(|beat| self.escapement.energy(a, a, beat, drive))
            .sum::<f64>()
            / n
            * self.torque_scale;
        Ok(Steady {
            drive,
            amplitude: a,
            period,
            free_period,
            small_angle_period: small,
            rate: DAY * (small / period - 1.0),
            circular_rate: DAY * (small / free_period - 1.0),
            escapement_rate: DAY * (free_period / period - 1.0),
            escapement_rate_first_order: DAY * (free_half / (free_half + shift) - 1.0),
            beat_error,
            energy_per_beat,
            power: 2.0 * energy_per_beat / period,
        })
    }
}
