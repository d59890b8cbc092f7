//! One half swing, integrated by the one adaptive driver
//! ([`crate::integrate::adaptive`], DOP853: Hairer, Nørsett & Wanner I,
//! II.10) in scaled time `τ = ω_n t`, on
//! `θ'' = -sin θ - θ'/Q + d(θ') + a(θ)` with the drag laws' losses `d`
//! ([`crate::forces::DRAG_LAWS`]) and the escapement's torque `a` in each
//! zone. The torque changes at the zones' edges, so the integration stops
//! at each edge (a terminal event of the driver, located on the dense
//! output) and restarts there with the next zone's
//! torque and any impulse: every step integrates a smooth equation, and
//! keeps the method's order.

use super::escapement::{zone_of, Escapement, InZone};
pub use crate::averaging::HalfSwing;
use crate::forces::{DragLaw, Gravity, Term, Viscous};
use crate::integrate::adaptive::{Dop853, Driver};
use crate::integrate::control::Tolerance;
use crate::integrate::State2;

/// Most steps in one half swing before giving up (a stuck pendulum).
const MAX_STEPS: u64 = 1_000_000;
/// Steps shorter than this (scaled time) give up.
const MIN_STEP: f64 = 1e-14;

/// The losses of a half swing beside the escapement: the viscous rate
/// `1/q` and the drag laws with their coefficients, both scaled.
#[derive(Clone, Copy, Debug)]
pub struct Losses<'a> {
    /// The quality factor of the viscous damping.
    pub q: f64,
    /// The drag laws of [`crate::forces::DRAG_LAWS`] and their scaled
    /// coefficients.
    pub drag: &'a [(&'static dyn DragLaw, f64)],
}

/// Integrates the half swing that starts at rest at `-a1` (travelling
/// towards `+θ`), on beat `beat`, with the `losses` and the drive factor
/// `drive`, at tolerance `tol`. `None` if the pendulum goes over the top
/// or does not come to rest.
pub fn half_swing(
    escapement: &dyn Escapement,
    losses: Losses<'_>,
    drive: f64,
    beat: u64,
    a1: f64,
    tol: f64,
) -> Option<HalfSwing> {
    half_swing_ticked(escapement, losses, drive, beat, a1, tol).map(|(h, _)| h)
}

/// [`half_swing`], with the time (scaled, from its start) at which it
/// crosses the escapement's last edge on that beat: the drop of the next
/// tooth, the tick a microphone hears (`None` if it does not reach it).
pub fn half_swing_ticked(
    escapement: &dyn Escapement,
    losses: Losses<'_>,
    drive: f64,
    beat: u64,
    a1: f64,
    tol: f64,
) -> Option<(HalfSwing, Option<f64>)> {
    let edges = escapement.edges_on(beat);
    let q = losses.q;
    let c = if q.is_finite() { 1.0 / q } else { 0.0 };
    let tolerance = Tolerance::both(tol);
    // Gravity, viscous damping, drag and the escapement in `zone`.
    let rhs = |zone: usize| {
        let torque = InZone {
            escapement,
            zone,
            beat,
            drive,
        };
        move |_t: f64, y: State2| -> State2 {
            [
                y[1],
                Gravity.acceleration(y, 1.0)
                    + Viscous(c).acceleration(y, 1.0)
                    + losses
                        .drag
                        .iter()
                        .map(|&(law, k)| law.acceleration(k, y[1]))
                        .sum::<f64>()
                    + torque.acceleration(y, 1.0),
            ]
        }
    };
    let mut zone = zone_of(&edges, -a1);
    let mut driver = Driver::<Dop853>::start(&rhs(zone), 0.0, [-a1, 0.0], &tolerance);
    driver.min_step = MIN_STEP;
    let mut steps = 0;
    let mut tick = None;
    loop {
        let f = rhs(zone);
        let step = driver.attempt(&f, f64::INFINITY, &tolerance).ok()?;
        steps += 1;
        if steps + driver.rejected > MAX_STEPS {
            return None;
        }
        let (y, y1) = (step.y0, step.y1);
        if y[1] <= 0.0 && y1[1] <= 0.0 {
            // It does not move off its turning point.
            return None;
        }
        // Terminal events: the zone's edge crossed, and the turning point.
        let edge = edges.get(zone).copied();
        let at_edge = |y: State2| edge.map_or(-1.0, |e| y[0] - e);
        let turned = |y: State2| -y[1];
        let events: [&dyn Fn(State2) -> f64; 2] = [&at_edge, &turned];
        match driver.first_terminal(&f, &step, &tolerance, &events) {
            Some((1, time, state)) => {
                return Some((
                    HalfSwing {
                        amplitude: state[0],
                        time,
                    },
                    tick,
                ))
            }
            Some((_, time, state)) => {
                // Cross the edge: the next zone's torque, and any impulse.
                let kick = escapement.kick(zone, beat, drive);
                let v = state[1];
                let v_after = (v * v + 2.0 * kick).max(0.0).sqrt();
                let e = edges[zone];
                if zone + 1 == edges.len() {
                    tick = Some(time);
                }
                zone += 1;
                driver.restart(&rhs(zone), time, [e, v_after]);
            }
            None => {
                if y1[0] > std::f64::consts::PI {
                    return None;
                }
                driver.commit(&step);
            }
        }
    }
}
