//! How much work a run will take, known before it starts: so that a caller
//! can refuse a run that would take hours (a 1 µm pendulum for a day, or
//! ζ = 10⁹, which makes the equation stiff for the explicit methods)
//! instead of hanging.

use super::{amplitude_floor, Method, Model, Options, Rates};
use crate::pendulum::Amplitude;
use std::f64::consts::{PI, TAU};

/// What sets the number of steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// The oscillation: the number of periods in the duration.
    Oscillation,
    /// The viscous damping: ζ well above 1 makes the equation stiff.
    Viscous,
    /// The quadratic drag, likewise.
    Drag,
}

/// The estimated cost of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkEstimate {
    /// Small-angle periods in the part of the run that is integrated (up to
    /// the duration, or until the swing decays below the method's floor,
    /// [`super::amplitude_floor`], or
    /// friction holds it).
    pub periods: f64,
    /// Integration steps (quarter periods for the closed form).
    pub steps: f64,
    /// Seconds of computing on one core of the reference machine (see
    /// `NANOSECONDS_PER_STEP`).
    pub seconds: f64,
    /// What sets the number of steps.
    pub limit: Limit,
    /// With [`Limit::Drag`]: the law (an index of
    /// [`super::forces::DRAG_LAWS`]).
    pub drag_law: usize,
}

/// Cost of one step in nanoseconds on the machine of `bench/RESULTS.md`
/// (no output files): DOP853 (12 evaluations, dense output on about one
/// step in five), Verner 9(8) (16 evaluations), the symplectic step (7
/// sines), a quarter period of the closed form.
pub const NANOSECONDS_PER_STEP: [(Method, f64); 5] = [
    (Method::Dop853, 300.0),
    (Method::Vern9, 450.0),
    (Method::Symplectic, 120.0),
    (Method::Exact, 60.0),
    (Method::Averaged, 250.0),
];

/// The steps an adaptive method takes per small-angle period at tolerance
/// `tol` (its error per step scales as `h^(order+1)`): measured at 0.5 rad
/// and 1e-10 and fitted to that power law.
fn adaptive_steps_per_period(method: Method, tol: f64) -> f64 {
    let tol = tol.clamp(1e-16, 1e-2);
    match method {
        Method::Vern9 => 17.0 * (tol / 1e-10).powf(-1.0 / 9.0),
        _ => 22.0 * (tol / 1e-10).powf(-1.0 / 8.0),
    }
}

/// The real part of the stability boundary of the explicit pairs, used to
/// estimate their steps when damping makes the equation stiff: a step may
/// not exceed about this over the fastest decay rate (DOP853's region
/// reaches -6 on the real axis; half of it allows for the controller's
/// rejections at the boundary).
const STABILITY: f64 = 3.0;

/// Estimates the work of `model` released at `amplitude` under `options`.
/// An estimate, not a bound: the steps are from power laws measured on the
/// free swing, the stiff part from the stability boundary. Measured against
/// the steps taken (1 m, 3°, tolerance 1e-10): free, Q = 300, ζ = 10 and
/// 10^4, dry friction and moderate drag within a factor of 2.2 (the
/// symplectic step count exactly); under drag-limited creep (b = 1e9) it
/// overestimates the explicit pairs' steps 13 to 19-fold, on the safe side.
pub fn work_estimate(model: &Model, amplitude: Amplitude, options: &Options) -> WorkEstimate {
    let omega = model.pendulum.natural_angular_frequency();
    let rates = Rates::new(model, amplitude);
    let a0 = amplitude.radians();
    // Scaled time integrated: the duration, or until the swing is gone.
    let mut active = options.duration * omega;
    let zeta = model.damping.zeta();
    if zeta > 0.0 && a0 > 0.0 {
        // The slowest decay rate: ζ, or ζ - sqrt(ζ² - 1) = 1/(ζ + sqrt(ζ² - 1)).
        let slow = if zeta <= 1.0 {
            zeta
        } else {
            1.0 / (zeta + (zeta * zeta - 1.0).sqrt())
        };
        active = active.min((a0 / amplitude_floor(options.method)).ln() / slow);
    }
    let r = model.friction_angle;
    if r > 0.0 {
        // Each half swing (π of scaled time) loses about 2r.
        active = active.min(PI * (a0 / (2.0 * r) + 1.0));
    }
    if a0 == 0.0 {
        active = 0.0;
    }
    let periods = active / TAU;
    let stiff_rate = rates.viscous.max(rates.drag);
    let stiff_limit = if rates.viscous >= rates.drag {
        Limit::Viscous
    } else {
        Limit::Drag
    };
    let (steps, limit) = match options.method {
        Method::Exact => (4.0 * periods, Limit::Oscillation),
        Method::Averaged => (2.0 * periods, Limit::Oscillation),
        Method::Symplectic => {
            let limit = if rates.fastest() == rates.oscillation {
                Limit::Oscillation
            } else {
                stiff_limit
            };
            let per_period = super::symplectic_steps_per_period(options.tolerance);
            (periods * rates.fastest() * per_period, limit)
        }
        Method::Dop853 | Method::Vern9 => {
            // Accuracy sets the steps, unless the stability bound is tighter.
            let accurate = periods * adaptive_steps_per_period(options.method, options.tolerance);
            let stable = active * stiff_rate / STABILITY;
            if stable > accurate {
                (stable, stiff_limit)
            } else {
                (accurate, Limit::Oscillation)
            }
        }
    };
    let per_step = NANOSECONDS_PER_STEP
        .iter()
        .find(|(m, _)| *m == options.method)
        .map_or(300.0, |(_, ns)| *ns);
    WorkEstimate {
        periods,
        steps,
        seconds: steps * per_step * 1e-9,
        limit,
        drag_law: rates.drag_law,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::damping::Damping;
    use crate::Pendulum;

    fn estimate(length: f64, zeta: f64, drag: f64, duration: f64, method: Method) -> WorkEstimate {
        let p = Pendulum::with_standard_gravity(length).unwrap();
        let model = Model::new(p, Damping::from_zeta(zeta).unwrap(), drag, 0.0).unwrap();
        let options = Options {
            duration,
            tolerance: 1e-10,
            method,
            sample_interval: None,
        };
        work_estimate(&model, Amplitude::from_degrees(3.0).unwrap(), &options)
    }

    #[test]
    fn periods_follow_the_length() {
        let e = estimate(0.99362, 0.0, 0.0, 7.0 * 86_400.0, Method::Symplectic);
        assert!((e.periods - 302_400.0).abs() < 1.0, "{}", e.periods);
        assert_eq!(e.limit, Limit::Oscillation);
        let tiny = estimate(1e-300, 0.0, 0.0, 1.0, Method::Dop853);
        assert!(tiny.periods > 1e149 && tiny.seconds.is_finite());
    }

    #[test]
    fn stiffness_is_named() {
        let e = estimate(0.99362, 1e9, 0.0, 60.0, Method::Dop853);
        assert_eq!(e.limit, Limit::Viscous);
        assert!(e.steps > 1e10);
        let d = estimate(0.99362, 0.0, 1e9, 10.0, Method::Symplectic);
        assert_eq!(d.limit, Limit::Drag);
    }

    #[test]
    fn decay_ends_the_work() {
        // Q = 300 over a year: the swing is gone after about 1e5 periods.
        let e = estimate(0.99362, 1.0 / 600.0, 0.0, 3.2e7, Method::Dop853);
        assert!(e.periods < 2e5, "{}", e.periods);
    }
}
