//! A design in a gas: buoyancy, the gas carried along and the gas's
//! damping, part by part, and so the rate against a vacuum, the Q the gas
//! alone would give, and their change with pressure.
//!
//! Each part's force comes from [`crate::oscillating_flow`] at the
//! pendulum's own frequency, with each element's velocity `z θ'` at its
//! depth `z` below the pivot:
//! - a sphere, disc, lens or ring acts at its centre `d`: added inertia `k
//!   M' d²`, damping torque `k' ω M' d² θ'` (`M'` the gas it displaces;
//!   a disc, lens or ring is a plate of its mean thickness moving in its
//!   own plane);
//! - an upright cylinder is a line of cross-sections, each an infinite
//!   cylinder's (with the ideal-flow part of its added mass that of a
//!   cylinder of its proportions, [`finite_cylinder_added_mass`]): `∫ z² dz` over its length replaces `d²` (Stokes's
//!   treatment of Baily's rods, 1851 §III), less the lengths hidden inside
//!   or behind a wider part (a rod through a bob), and plus the gas in its
//!   bore, which it carries.
//!
//! Form drag: once a part's swing is not small against its size, the flow
//! separates behind it and a drag `½ ρ C_d w |u| u` per unit height of its
//! width `w` adds to Stokes's (Morison's equation; J. R. Morison et al.,
//! Petroleum Transactions AIME 189 (1950) 149). Its energy per swing is
//! `(8/3) ω² A³ ½ ρ C_d Σ w z³ dz`, so it damps more as the arc grows. The
//! coefficients are the steady-flow ones at Reynolds numbers of 1e3 to
//! 1e5 (S. F. Hoerner, Fluid-Dynamic Drag, 1965, ch. 3): a sphere 0.47, a
//! long cylinder across its axis 1.2, a cylinder whose length is about its
//! diameter 0.7 (Hoerner's finite cylinders), a disc or ring edgewise 1.2
//! on its rim (t × D), a lens edgewise 0.2 (its rim is faired). In an
//! oscillating flow the coefficient depends on the swing over the size
//! (the Keulegan-Carpenter number; Sarpkaya's measurements put it within a
//! factor of two of these for numbers 2 to 20): this is the model's
//! largest uncertainty, and the datasheet says so.
//!
//! Left out, with their size: a part's rotation about its own centre
//! (order `(size/d)²` of its damping, 1% for a 0.1 m bob a metre down);
//! the rod's ends and a short cylinder's ends (order diameter over length);
//! the flow of one part around another beyond the hidden lengths; the
//! case's walls (Stokes's confined-space correction, a few per cent of the
//! added mass in a close case). Buoyancy is exact: the displaced gas's
//! weight acts at each part's centre of volume.

use super::{rate_of_length_ratio, AirRates, CompoundPendulum, Shape};
use crate::gas::GasState;
use crate::oscillating_flow::{cylinder, plate, sphere, Flow, Medium};
use std::f64::consts::PI;

/// The potential-flow added-mass coefficient of a circular cylinder of
/// length over diameter `ratio` moving across its axis (DNV-RP-C205,
/// Environmental Conditions and Environmental Loads, 2010, table A-2, after
/// Blevins: 0.62 at 1.2, 0.78 at 2.5, 0.90 at 5, 0.96 at 9, 1 when
/// infinite), interpolated linearly in the inverse ratio; 0.62 below 1.2.
pub fn finite_cylinder_added_mass(ratio: f64) -> f64 {
    const TABLE: [(f64, f64); 5] = [
        (0.0, 1.0),
        (1.0 / 9.0, 0.96),
        (0.2, 0.90),
        (0.4, 0.78),
        (1.0 / 1.2, 0.62),
    ];
    let x = 1.0 / ratio;
    if x >= TABLE[4].0 {
        return TABLE[4].1;
    }
    TABLE.windows(2).find(|w| x <= w[1].0).map_or(1.0, |w| {
        w[0].1 + (w[1].1 - w[0].1) * (x - w[0].0) / (w[1].0 - w[0].0)
    })
}

/// A long cylinder's flow with the ideal-flow part of its added mass
/// taken for a cylinder of length over diameter `ratio`.
fn finite(flow: Flow, ratio: f64) -> Flow {
    Flow {
        added_mass: flow.added_mass - 1.0 + finite_cylinder_added_mass(ratio),
        ..flow
    }
}

/// The volume of gas a part displaces, m³: none for an idealised massless
/// rod, which stands for a real one's length only.
fn displaced_volume(p: &super::Part) -> f64 {
    if p.massless {
        0.0
    } else {
        p.shape.volume()
    }
}

/// One part in the gas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PartFlow {
    /// The added-mass coefficient `k` (the gas carried along over the gas
    /// displaced; for a cylinder, of its cross-section).
    pub added_mass_coefficient: f64,
    /// The inertia the carried gas adds about the pivot, kg m².
    pub added_inertia: f64,
    /// Its damping: torque per unit angular velocity, N m s.
    pub damping: f64,
    /// Its form drag: torque per squared angular velocity, `½ ρ C_d Σ w
    /// z³ dz`, kg m².
    pub form_drag: f64,
}

/// A design in a gas.
#[derive(Clone, Debug, PartialEq)]
pub struct InGas {
    /// Its rate against a vacuum.
    pub rates: AirRates,
    /// Each part's share.
    pub parts: Vec<PartFlow>,
    /// The damping torque per unit angular velocity, N m s.
    pub damping: f64,
    /// The form drag's torque per squared angular velocity, kg m².
    pub form_drag: f64,
    /// The inertia about the pivot with the carried gas, kg m².
    pub inertia: f64,
    /// The Q the gas's Stokes damping alone gives: `(I + ΔI) ω / c` (at
    /// a vanishing arc; see [`InGas::q_at`]).
    pub q: f64,
    /// The angular frequency the flow was computed at, rad/s.
    pub omega: f64,
}

impl CompoundPendulum {
    /// The design in `gas` under gravity `g` (see the module notes).
    pub fn in_gas(&self, gas: &GasState, g: f64) -> InGas {
        let rho = gas.density();
        let vacuum = self.properties();
        let omega = (g / vacuum.equivalent_length).sqrt();
        let medium = Medium {
            omega,
            nu: gas.kinematic_viscosity(),
            mean_free_path: gas.mean_free_path(),
            mean_speed: gas.mean_speed(),
        };
        let parts: Vec<PartFlow> = (0..self.parts.len())
            .map(|i| self.part_flow(i, rho, &medium))
            .collect();
        let added: f64 = parts.iter().map(|p| p.added_inertia).sum();
        let damping: f64 = parts.iter().map(|p| p.damping).sum();
        let form_drag: f64 = parts.iter().map(|p| p.form_drag).sum();
        let (mut weighing, mut weight, mut inertia) = (0.0, 0.0, 0.0);
        for (p, &d) in self.parts.iter().zip(&self.centres) {
            weighing += (p.mass() - rho * displaced_volume(p)) * d;
            weight += p.mass() * d;
            inertia += p.mass() * (p.shape.inertia_per_mass() + d * d);
        }
        // The gas lightens gravity's share of the restoring stiffness, not
        // a suspension spring's (share `ε`): `ω²` moves by
        // `[(1 - ε) W'/W + ε] I/(I + I_added)` for the moments of weight
        // `W` in a vacuum and `W'` in the gas.
        let share = self.spring_effect().map_or(0.0, |e| e.elastic_share);
        let stiffness = (1.0 - share) * weighing / weight + share;
        InGas {
            rates: AirRates {
                total: rate_of_length_ratio((inertia + added) / inertia / stiffness),
                buoyancy: rate_of_length_ratio(1.0 / stiffness),
            },
            parts,
            damping,
            form_drag,
            inertia: inertia + added,
            q: (inertia + added) * omega / damping,
            omega,
        }
    }

    /// The rate change per hPa of pressure, s/day, in `gas` under `g`: a
    /// central difference of ±1% of the pressure of
    /// [`CompoundPendulum::in_gas`]'s total (buoyancy and carried gas; the
    /// rate is smooth in the pressure, so the difference's error is of
    /// order 1e-4 relative).
    pub fn pressure_coefficient(&self, gas: &GasState, g: f64) -> f64 {
        let p = gas.pressure_pa;
        let rate = |f: f64| self.in_gas(&gas.at_pressure(p * f), g).rates.total;
        (rate(1.01) - rate(0.99)) / (0.02 * p) * 100.0
    }

    /// Part `i` in the gas.
    fn part_flow(&self, i: usize, rho: f64, medium: &Medium) -> PartFlow {
        let part = &self.parts[i];
        let d = self.centres[i];
        if part.massless {
            return PartFlow {
                added_mass_coefficient: 0.0,
                added_inertia: 0.0,
                damping: 0.0,
                form_drag: 0.0,
            };
        }
        // Form drag of a compact part: ½ ρ C_d (frontal area) d³.
        let form = |cd: f64, area: f64| 0.5 * rho * cd * area * d.powi(3);
        let at_centre = |flow: Flow, displaced: f64, form_drag: f64| PartFlow {
            added_mass_coefficient: flow.added_mass,
            added_inertia: flow.added_mass * displaced * d * d,
            damping: flow.damping * medium.omega * displaced * d * d,
            form_drag,
        };
        match part.shape {
            // A spring moves at most its length from the pivot (a
            // hundredth of the bob's speed): its gas is left out.
            Shape::Point | Shape::Spring { .. } => PartFlow {
                added_mass_coefficient: 0.0,
                added_inertia: 0.0,
                damping: 0.0,
                form_drag: 0.0,
            },
            Shape::Sphere { diameter } => at_centre(
                sphere(0.5 * diameter, medium),
                rho * part.shape.volume(),
                form(0.47, 0.25 * PI * diameter * diameter),
            ),
            Shape::Disc { diameter, .. }
            | Shape::Lens { diameter, .. }
            | Shape::Ring {
                outer: diameter, ..
            } => {
                // A plate of the mean thickness over its face.
                let face = match part.shape {
                    Shape::Ring { outer, inner, .. } => 0.25 * PI * (outer * outer - inner * inner),
                    _ => 0.25 * PI * diameter * diameter,
                };
                let mean = part.shape.volume() / face;
                let (cd, rim) = match part.shape {
                    Shape::Lens { thickness, .. } => (0.2, thickness),
                    Shape::Disc { thickness, .. } | Shape::Ring { thickness, .. } => {
                        (1.2, thickness)
                    }
                    _ => (0.0, 0.0),
                };
                at_centre(
                    plate(mean, diameter, medium),
                    rho * part.shape.volume(),
                    form(cd, rim * diameter),
                )
            }
            Shape::Cylinder {
                diameter,
                bore,
                length,
            } => {
                let flow = finite(cylinder(0.5 * diameter, medium), length / diameter);
                let per_length = rho * 0.25 * PI * diameter * diameter;
                let bore_air = rho * 0.25 * PI * bore * bore;
                let [second, third] = self.exposed_moments(i);
                // Hoerner's finite cylinders: 0.7 at a length of one
                // diameter or less, rising to 1.2 when long.
                let ratio = length / diameter;
                let cd = 0.7 + 0.5 * ((ratio - 1.0) / 9.0).clamp(0.0, 1.0);
                PartFlow {
                    added_mass_coefficient: flow.added_mass,
                    added_inertia: (flow.added_mass * per_length + bore_air) * second,
                    damping: flow.damping * medium.omega * per_length * second,
                    form_drag: 0.5 * rho * cd * diameter * third,
                }
            }
        }
    }

    /// `∫ z² dz` and `∫ z³ dz` over the length of cylinder `i` not hidden
    /// inside or behind a wider part, m³ and m⁴.
    fn exposed_moments(&self, i: usize) -> [f64; 2] {
        let width = |s: &Shape| match *s {
            Shape::Cylinder { diameter, .. }
            | Shape::Disc { diameter, .. }
            | Shape::Lens { diameter, .. }
            | Shape::Sphere { diameter } => diameter,
            Shape::Ring { outer, .. } => outer,
            Shape::Spring { width, .. } => width,
            Shape::Point => 0.0,
        };
        let own = width(&self.parts[i].shape);
        let half = 0.5 * self.parts[i].shape.height();
        let (top, bottom) = (self.centres[i] - half, self.centres[i] + half);
        let mut hidden: Vec<(f64, f64)> = self
            .parts
            .iter()
            .zip(&self.centres)
            .enumerate()
            .filter(|&(j, (p, _))| j != i && width(&p.shape) > own)
            .map(|(_, (p, &c))| {
                let h = 0.5 * p.shape.height();
                ((c - h).max(top), (c + h).min(bottom))
            })
            .filter(|(a, b)| b > a)
            .collect();
        hidden.sort_by(|a, b| a.0.total_cmp(&b.0));
        let moments =
            |a: f64, b: f64| [(b.powi(3) - a.powi(3)) / 3.0, (b.powi(4) - a.powi(4)) / 4.0];
        let mut total = [0.0, 0.0];
        let mut add = |a: f64, b: f64| {
            let m = moments(a, b);
            total[0] += m[0];
            total[1] += m[1];
        };
        let mut from = top;
        for (a, b) in hidden {
            if a > from {
                add(from, a);
            }
            from = from.max(b);
        }
        if bottom > from {
            add(from, bottom);
        }
        total
    }
}

impl InGas {
    /// The energy lost per cycle at semi-arc `a` rad, J: Stokes's damping
    /// and the pivot's (`pivot_damping`, N m s) `π ω a² c`, and the form
    /// drag's `(8/3) ω² a³ D` (see the module notes).
    pub fn loss_per_cycle(&self, a: f64, pivot_damping: f64) -> f64 {
        a * a * self.loss_over_arc_squared(a, pivot_damping)
    }

    /// [`InGas::loss_per_cycle`] over `a²`, J/rad²: `π ω c + (8/3) ω² a D`,
    /// finite at any arc however small (the loss itself underflows below
    /// 1e-150 rad).
    pub fn loss_over_arc_squared(&self, a: f64, pivot_damping: f64) -> f64 {
        PI * self.omega * (self.damping + pivot_damping)
            + 8.0 / 3.0 * self.omega.powi(2) * a * self.form_drag
    }

    /// The Q at semi-arc `a`: `2π E / loss`, `E = ½ I ω² a²` (with the
    /// arc divided out, so that it holds at any arc).
    pub fn q_at(&self, a: f64, pivot_damping: f64) -> f64 {
        PI * self.inertia * self.omega.powi(2) / self.loss_over_arc_squared(a, pivot_damping)
    }

    /// The semi-arc, rad, at which this design loses per cycle what
    /// `reference` loses at semi-arc `a` (a drive giving that much each
    /// cycle, the pivot's damping `pivot_damping` N m s in both): the loss
    /// grows with the arc, so bisection on the arc's ratio to `a`, with
    /// the arc divided out of both losses (the answer holds from 1e-300
    /// rad to 60°), to 1e-12 relative.
    pub fn arc_for_loss_of(&self, reference: &InGas, a: f64, pivot_damping: f64) -> f64 {
        let target = reference.loss_over_arc_squared(a, pivot_damping);
        // Loss at arc `x a` over `a²`.
        let loss = |x: f64| x * x * self.loss_over_arc_squared(x * a, pivot_damping);
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        while loss(hi) < target && hi < 1e12 {
            hi *= 2.0;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if loss(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-12 * hi {
                break;
            }
        }
        0.5 * (lo + hi) * a
    }
}
