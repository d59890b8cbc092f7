//! One half swing, integrated: DOP853 (Hairer, Nørsett & Wanner I, II.10)
//! under the step-size controller, in scaled time `τ = ω_n t`, on
//! `θ'' = -sin θ - θ'/Q + a(θ)` with the escapement's torque `a` in each
//! zone. The torque changes at the zones' edges, so the integration stops
//! at each edge (located on the dense output, as the events of
//! [`crate::simulation`] are) and restarts there with the next zone's
//! torque and any impulse: every step integrates a smooth equation, and
//! keeps the method's order.

use super::escapement::{zone_of, Escapement, InZone};
use crate::forces::{Gravity, Term, Viscous};
use crate::integrate::control::{step_factor, Tolerance};
use crate::integrate::dop853;
use crate::integrate::events::locate_root;
use crate::integrate::State2;

/// The end of a half swing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSwing {
    /// The amplitude at its end, rad.
    pub amplitude: f64,
    /// Its duration, in scaled time.
    pub time: f64,
}

/// Most steps in one half swing before giving up (a stuck pendulum).
const MAX_STEPS: usize = 1_000_000;

/// Integrates the half swing that starts at rest at `-a1` (travelling
/// towards `+θ`), on beat `beat`, with viscous rate `1/q` (scaled) and the
/// drive factor `drive`, at tolerance `tol`. `None` if the pendulum goes
/// over the top or does not come to rest.
pub fn half_swing(
    escapement: &dyn Escapement,
    q: f64,
    drive: f64,
    beat: u64,
    a1: f64,
    tol: f64,
) -> Option<HalfSwing> {
    let edges = escapement.edges();
    let c = if q.is_finite() { 1.0 / q } else { 0.0 };
    let tolerance = Tolerance::both(tol);
    let mut zone = zone_of(&edges, -a1);
    let (mut t, mut y): (f64, State2) = (0.0, [-a1, 0.0]);
    let mut h = 0.0;
    let mut steps = 0;
    loop {
        let edge = edges.get(zone).copied();
        // Gravity, viscous damping and the escapement in this zone.
        let torque = InZone {
            escapement,
            zone,
            drive,
        };
        let mut f = |_t: f64, y: State2| -> State2 {
            [
                y[1],
                Gravity.acceleration(y, 1.0)
                    + Viscous(c).acceleration(y, 1.0)
                    + torque.acceleration(y, 1.0),
            ]
        };
        let mut f0 = f(t, y);
        if h == 0.0 {
            h = dop853::initial_step(&mut f, t, y, f0, &tolerance);
        }
        // One smooth segment: to the next edge or the turning point.
        let mut after_rejection = false;
        let hit = loop {
            steps += 1;
            if steps > MAX_STEPS || h < 1e-14 {
                return None;
            }
            let step = dop853::attempt(&mut f, t, y, f0, h, &tolerance);
            let factor = step_factor(step.error, after_rejection, 7);
            if step.error > 1.0 || !step.y1[0].is_finite() {
                h *= factor;
                after_rejection = true;
                continue;
            }
            after_rejection = false;
            let y1 = step.y1;
            let f1 = f(t + h, y1);
            let edge_hit = edge.is_some_and(|e| y1[0] >= e);
            if y[1] <= 0.0 && y1[1] <= 0.0 {
                // It does not move off its turning point.
                return None;
            }
            let turned = y1[1] <= 0.0;
            if edge_hit || turned {
                let dense = dop853::dense_output(&mut f, &step, f1);
                // Which comes first: the edge or the turning point.
                let t_turn =
                    turned.then(|| locate_root(|s| dense.eval(s)[1], t, t + h, y[1], y1[1]));
                let t_edge = edge
                    .filter(|_| edge_hit)
                    .map(|e| locate_root(|s| dense.eval(s)[0] - e, t, t + h, y[0] - e, y1[0] - e));
                break match (t_edge, t_turn) {
                    (Some(te), Some(tt)) if tt < te => (tt, dense.eval(tt), false),
                    (Some(te), _) => (te, dense.eval(te), true),
                    (None, Some(tt)) => (tt, dense.eval(tt), false),
                    (None, None) => unreachable!("an event was seen"),
                };
            }
            if y1[0] > std::f64::consts::PI {
                return None;
            }
            t += h;
            y = y1;
            f0 = f1;
            h *= factor;
        };
        let (t_event, y_event, at_edge) = hit;
        t = t_event;
        if !at_edge {
            return Some(HalfSwing {
                amplitude: y_event[0],
                time: t,
            });
        }
        // Cross the edge: the next zone's torque, and any impulse.
        let kick = escapement.kick(zone, beat, drive);
        let v = y_event[1];
        let v_after = (v * v + 2.0 * kick).max(0.0).sqrt();
        y = [edges[zone], v_after];
        zone += 1;
    }
}
