//! The long-run method for a clock: the half-swing map of
//! [`crate::averaging`] with the escapement's exact work between the ends
//! (its closed forms, and its impulses) and its first-order time shift
//! ([`super::airy::time_shift`]).
//!
//! Measured against the symplectic method at tolerance 1e-13 over 200
//! periods of a seconds pendulum from 3° (the last turning point): Q = 100,
//! time 8.5e-7 s, amplitude 4e-4 relative (the swing has decayed 500-fold;
//! the third-order term is 1e-6 a half swing); Q = 1,000, 4.7e-8 s and
//! 4.4e-7; Q = 10,000, 1.5e-10 s and 4.3e-10. Over a week at Q = 10⁶ it
//! agrees with the symplectic method at 1e-13 to 2.9e-8 s and 3e-12
//! (`bench/RESULTS.md`). The method is for clocks (Q of thousands and
//! more), not for heavily damped swings.

use super::airy::time_shift;
use super::escapement::Escapement;
pub use crate::averaging::half_swing_action;
use crate::averaging::{HalfSwing, Work};
use crate::forces::DragLaw;

/// The energy (scaled, over `m g l`) a drag law of power `p` and scaled
/// coefficient 1 takes from a free half swing of amplitude `a`:
/// `∫ |v|^{p+1} dτ = ∫ v^p dθ` from `-a` to `a`, with `v =
/// 2 sqrt(sin((a−θ)/2) sin((a+θ)/2))` (the energy `v²/2 + 1 − cos θ`
/// conserved; no cancellation near the turning points).
///
/// Method: `θ = a sin φ`, then Gauss-Legendre (24 points) on four panels
/// of `[0, π/2]` (the integrand goes as `cos^{p+1} φ` at the turning
/// point). Accuracy: at `p = 1` it is the action `8 (E(k) − k'² K(k))` to
/// 1e-12 relative, and at small swings `π ⟨|sin|^{p+1}⟩ a^{p+1}`
/// (`tests::the_drag_action_is_the_action_at_power_one`).
pub fn drag_action(p: f64, a: f64) -> f64 {
    let integrand = |phi: f64| {
        let theta = a * phi.sin();
        let v = 2.0
            * ((0.5 * (a - theta)).sin() * (0.5 * (a + theta)).sin())
                .max(0.0)
                .sqrt();
        v.powf(p) * a * phi.cos()
    };
    let quarter = 0.125 * std::f64::consts::PI;
    2.0 * (0..4)
        .map(|i| {
            let from = f64::from(i) * quarter;
            super::airy::integrate(integrand, from, from + quarter)
        })
        .sum::<f64>()
}

/// The half swing from rest at `-a1` to the next turning point, on beat
/// `beat` with drive factor `drive`, by the map of [`crate::averaging`];
/// `None` when it goes over the top or stops short of the escapement's
/// unlocking.
pub fn half_swing_map(
    escapement: Option<&dyn Escapement>,
    q: f64,
    drag: &[(&'static dyn DragLaw, f64)],
    drive: f64,
    beat: u64,
    a1: f64,
    with_time_shift: bool,
) -> Option<HalfSwing> {
    if escapement.is_none() && drag.is_empty() {
        return crate::averaging::half_swing_map(q, a1, None);
    }
    // The escapement's work, less the drag laws' loss at the half swing's
    // mean energy (as the map takes the viscous loss): the loss at `a1`
    // and its slope there, three quadratures a half swing, carried to the
    // mean amplitude (a part in Q of `a1` away: the error is the square
    // of that, where the fixed-point iteration would integrate afresh
    // each time).
    let h = 1e-4;
    let loss = drag_loss(drag, a1);
    let slope =
        (drag_loss(drag, a1 * (1.0 + h)) - drag_loss(drag, a1 * (1.0 - h))) / (2.0 * h * a1);
    let energy = |a2: f64| {
        let given = escapement.map_or(0.0, |e| e.energy(a1, a2, beat, drive));
        if drag.is_empty() {
            return given;
        }
        let mean = (0.5 * (a1 * 0.5).sin().powi(2) + 0.5 * (a2 * 0.5).sin().powi(2)).sqrt();
        let a_mean = 2.0 * mean.min(1.0).asin();
        given - (loss + slope * (a_mean - a1))
    };
    let shift = |a: f64| escapement.map_or(0.0, |e| time_shift(e, a, beat, drive));
    let work = Work {
        energy: &energy,
        time_shift: with_time_shift.then_some(&shift as &dyn Fn(f64) -> f64),
    };
    crate::averaging::half_swing_map(q, a1, Some(&work))
}

/// The energy (scaled) the drag laws `drag` (scaled coefficients) take
/// from a free half swing of amplitude `a`: `Σ k ∫ v^p dθ`
/// ([`drag_action_tabled`]).
pub fn drag_loss(drag: &[(&'static dyn DragLaw, f64)], a: f64) -> f64 {
    drag.iter()
        .map(|&(law, k)| k * drag_action_tabled(law.power(), a))
        .sum()
}

/// The step of [`drag_action_tabled`]'s table in the amplitude, rad.
const TABLE_STEP: f64 = 0.01;
/// Its last amplitude, rad (past it, the quadrature itself).
const TABLE_END: f64 = 3.1;

/// `drag_action(p, a) / a^{p+1}` at `a = i TABLE_STEP` (a smooth, even
/// function of `a`, `π ⟨|sin|^{p+1}⟩` at 0), for the powers asked so far.
fn drag_table(p: f64) -> std::sync::Arc<Vec<f64>> {
    use std::sync::{Arc, Mutex, OnceLock};
    /// Each power's table, by the power's bits.
    type Tables = Vec<(u64, Arc<Vec<f64>>)>;
    static TABLES: OnceLock<Mutex<Tables>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| Mutex::new(Vec::new()));
    let mut tables = tables.lock().unwrap_or_else(|e| e.into_inner());
    if let Some((_, t)) = tables.iter().find(|(bits, _)| *bits == p.to_bits()) {
        return t.clone();
    }
    let n = (TABLE_END / TABLE_STEP).round() as usize + 2;
    let values: Vec<f64> = (0..=n)
        .map(|i| {
            // At 0 the limit, from the first point's neighbourhood.
            let a = (i as f64 * TABLE_STEP).max(1e-4);
            drag_action(p, a) / a.powf(p + 1.0)
        })
        .collect();
    let table = Arc::new(values);
    tables.push((p.to_bits(), table.clone()));
    table
}

/// [`drag_action`] by a table made once for each power (its value over
/// `a^{p+1}` every 0.01 rad up to 3.1 rad, four-point Lagrange between
/// them): the long run asks for it at every half swing, where the
/// quadrature took a hundred times the map's own work. Accuracy: within
/// 1e-9 of the quadrature (`tests::the_table_is_the_quadrature`); past
/// 3.1 rad the quadrature itself.
pub fn drag_action_tabled(p: f64, a: f64) -> f64 {
    if !(a > 0.0 && a < TABLE_END) {
        return drag_action(p, a);
    }
    let table = drag_table(p);
    let x = a / TABLE_STEP;
    let i = (x.floor() as usize).saturating_sub(1).min(table.len() - 4);
    let mut value = 0.0;
    for j in 0..4 {
        let mut weight = 1.0;
        for m in 0..4 {
            if m != j {
                weight *= (x - (i + m) as f64) / (j as f64 - m as f64);
            }
        }
        value += weight * table[i + j];
    }
    value * a.powf(p + 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At power 1 the loss is the action (an elliptic closed form); at
    /// small swings `π ⟨|sin|^{p+1}⟩ a^{p+1}` (the harmonic motion).
    #[test]
    fn the_drag_action_is_the_action_at_power_one() {
        for a in [0.01, 0.3, 1.0, 2.5] {
            let action = half_swing_action(a);
            assert!(
                (drag_action(1.0, a) / action - 1.0).abs() < 1e-12,
                "{a}: {} against {action}",
                drag_action(1.0, a)
            );
        }
        for law in crate::forces::DRAG_LAWS {
            let (p, a): (f64, f64) = (law.power(), 1e-3);
            let small = std::f64::consts::PI * law.sine_mean() * a.powf(p + 1.0);
            assert!(
                (drag_action(p, a) / small - 1.0).abs() < 1e-6,
                "{}",
                law.name()
            );
        }
    }

    /// The table against the quadrature at amplitudes between its points,
    /// near 0 and near its end.
    #[test]
    fn the_table_is_the_quadrature() {
        for law in crate::forces::DRAG_LAWS {
            let p = law.power();
            for a in [1e-3, 0.004_3, 0.017, 0.052_36, 0.3, 1.234_5, 2.5, 3.09] {
                let (table, quadrature) = (drag_action_tabled(p, a), drag_action(p, a));
                assert!(
                    (table / quadrature - 1.0).abs() < 1e-9,
                    "{} at {a}: {table} against {quadrature}",
                    law.name()
                );
            }
        }
    }
}
