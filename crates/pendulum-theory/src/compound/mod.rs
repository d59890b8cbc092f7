//! The real pendulum: a rod, a bob, a nut and whatever else hangs from the
//! pivot, each part a shape of a material at a place.
//!
//! A rigid body swinging about a horizontal axis obeys
//! `I θ'' = -m g d sin θ` (I: moment of inertia about the pivot, m: mass,
//! d: distance of the centre of mass below the pivot), which is the simple
//! pendulum's equation with the equivalent length `l = I / (m d)` (Huygens,
//! Horologium Oscillatorium, 1673; any mechanics text, e.g. Goldstein
//! §5.3). So the exact period at any amplitude is the simple pendulum's of
//! that length: `T = 4 sqrt(I / (m g d)) K(sin²(A0/2))`, and every command
//! that takes a length can take a design. `I` sums each part's own
//! inertia and `m_i d_i²` (the parallel-axis theorem).
//!
//! Temperature ([`CompoundPendulum::at_temperature`]): every dimension of a
//! part grows by its material's coefficient; a part placed by its centre
//! is carried by the rod (the first upright cylinder hanging from the
//! pivot), so its centre moves with the rod's expansion from the pivot
//! down; a part resting on another sits on that part's top and grows
//! upward from it (a bob on its rating nut).
//!
//! Air ([`CompoundPendulum::rate_in_air`]): buoyancy lessens the restoring
//! torque by the weight of the displaced air, `Σ (m_i - ρ V_i) g d_i`, and
//! the air carried along adds to the inertia, `Σ k_i ρ V_i d_i²`, with the
//! added-mass coefficients of [`shape::Shape::added_mass_coefficient`].

pub mod compensator;
pub mod material;
pub mod shape;

pub use compensator::gridiron;
pub use material::Material;
pub use shape::Shape;

/// Seconds in a day.
const DAY: f64 = 86_400.0;

/// Where a part is.
#[derive(Clone, Debug, PartialEq)]
pub enum Placement {
    /// Its centre this far below the pivot, m (at the reference
    /// temperature).
    Centre(f64),
    /// Its bottom on the top of the part with this index.
    RestsOn(usize),
}

/// One part of a pendulum.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// Its name (for messages and the datasheet).
    pub name: String,
    /// Its shape.
    pub shape: Shape,
    /// Its material (density and expansion).
    pub material: Material,
    /// Its mass, kg, for a point (else from the material).
    pub point_mass: f64,
    /// Where it is.
    pub placement: Placement,
    /// An idealised rod with no mass that still expands.
    pub massless: bool,
}

impl Part {
    /// Mass, kg.
    pub fn mass(&self) -> f64 {
        if self.massless {
            0.0
        } else if self.shape == Shape::Point {
            self.point_mass
        } else {
            self.material.density * self.shape.volume()
        }
    }
}

/// Why a design is refused: the part and the field.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("part '{part}': {field}: {message}")]
pub struct DesignError {
    /// The part's name.
    pub part: String,
    /// The field.
    pub field: &'static str,
    /// What is wrong.
    pub message: String,
}

/// A pendulum of parts, with each part's centre resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct CompoundPendulum {
    parts: Vec<Part>,
    /// Each part's centre below the pivot, m.
    centres: Vec<f64>,
}

/// The summed properties of a pendulum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Properties {
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass below the pivot, m.
    pub centre_of_mass: f64,
    /// Moment of inertia about the pivot, kg m².
    pub inertia: f64,
    /// Equivalent simple length `I / (m d)`, m.
    pub equivalent_length: f64,
}

impl Properties {
    /// The mass, kg, of the simple pendulum of the equivalent length that
    /// has this pendulum's restoring torque and energy at every angle:
    /// `M d / l` (the potential energy `M g d (1 - cos θ)` equals `m g l
    /// (1 - cos θ)`, and the kinetic `I θ'²/2` equals `m l² θ'²/2` since
    /// `I = M d l`). The energy budget of a design uses it.
    pub fn effective_mass(&self) -> f64 {
        self.mass * self.centre_of_mass / self.equivalent_length
    }
}

impl CompoundPendulum {
    /// A pendulum of `parts`, checked: every size positive and finite,
    /// every part with mass (unless `massless`), nothing above or through
    /// the pivot, a part rests only on one listed before it.
    pub fn new(parts: Vec<Part>) -> Result<Self, DesignError> {
        if parts.is_empty() {
            return Err(DesignError {
                part: "-".into(),
                field: "part",
                message: "the design has no parts".into(),
            });
        }
        for p in &parts {
            let fail = |field: &'static str, message: String| DesignError {
                part: p.name.clone(),
                field,
                message,
            };
            let dims: Vec<(&'static str, f64)> = match p.shape {
                Shape::Cylinder {
                    length,
                    diameter,
                    bore,
                } => vec![("length", length), ("diameter", diameter), ("bore", bore)],
                Shape::Disc {
                    diameter,
                    thickness,
                }
                | Shape::Lens {
                    diameter,
                    thickness,
                } => vec![("diameter", diameter), ("thickness", thickness)],
                Shape::Sphere { diameter } => vec![("diameter", diameter)],
                Shape::Ring {
                    outer,
                    inner,
                    thickness,
                } => vec![("outer", outer), ("inner", inner), ("thickness", thickness)],
                Shape::Point => vec![("mass", p.point_mass)],
            };
            for (field, v) in dims {
                let may_be_zero = field == "bore" || field == "inner";
                if !v.is_finite() || v < 0.0 || (v == 0.0 && !may_be_zero) {
                    return Err(fail(field, format!("must be positive, got {v}")));
                }
            }
            if let Shape::Cylinder { diameter, bore, .. } = p.shape {
                if bore >= diameter {
                    return Err(fail("bore", "must be less than the diameter".into()));
                }
            }
            if let Shape::Ring { outer, inner, .. } = p.shape {
                if inner >= outer {
                    return Err(fail("inner", "must be less than the outer diameter".into()));
                }
            }
            if !p.massless && p.shape != Shape::Point {
                let d = p.material.density;
                if !(d.is_finite() && d > 0.0) {
                    return Err(fail("density", format!("must be positive, got {d}")));
                }
            }
            if !p.material.expansion.is_finite() {
                return Err(fail("expansion", "must be a finite number".into()));
            }
            if p.material.liquid {
                let fits = matches!(p.shape, Shape::Cylinder { .. })
                    && matches!(p.placement, Placement::RestsOn(_));
                if !fits {
                    return Err(fail(
                        "rests_on",
                        "a liquid is an upright cylinder resting on the bottom of its jar".into(),
                    ));
                }
            }
        }
        let centres = resolve(&parts, 0.0, None)?;
        let pendulum = Self { parts, centres };
        let props = pendulum.properties();
        if props.mass.is_nan() || props.mass <= 0.0 {
            return Err(DesignError {
                part: "-".into(),
                field: "mass",
                message: "the pendulum has no mass".into(),
            });
        }
        Ok(pendulum)
    }

    /// The parts.
    pub fn parts(&self) -> &[Part] {
        &self.parts
    }

    /// Each part's centre below the pivot, m.
    pub fn centres(&self) -> &[f64] {
        &self.centres
    }

    /// Mass, centre of mass, moment of inertia about the pivot and the
    /// equivalent simple length (see the module notes).
    pub fn properties(&self) -> Properties {
        self.properties_in(0.0)
    }

    /// The same in air of density `rho` kg/m³: buoyancy and added mass.
    fn properties_in(&self, rho: f64) -> Properties {
        let (mut mass, mut moment, mut inertia) = (0.0, 0.0, 0.0);
        for (p, &d) in self.parts.iter().zip(&self.centres) {
            let m = p.mass();
            let v = p.shape.volume();
            let weighing = m - rho * v;
            mass += m;
            moment += weighing * d;
            inertia += m * (p.shape.inertia_per_mass() + d * d)
                + rho * p.shape.added_mass_coefficient() * v * d * d;
        }
        let weight_mass = self
            .parts
            .iter()
            .map(|p| p.mass() - rho * p.shape.volume())
            .sum::<f64>();
        Properties {
            mass,
            centre_of_mass: if weight_mass > 0.0 {
                moment / weight_mass
            } else {
                f64::NAN
            },
            inertia,
            equivalent_length: inertia / moment,
        }
    }

    /// The same pendulum `delta` °C warmer than its reference temperature
    /// (see the module notes).
    pub fn at_temperature(&self, delta: f64) -> Self {
        let parts: Vec<Part> = self
            .parts
            .iter()
            .map(|p| {
                // Every dimension grows; the mass does not (the density
                // falls as the volume grows). A liquid keeps its jar's
                // width and rises with its volume.
                let mut material = p.material.clone();
                if let (true, Placement::RestsOn(jar)) = (p.material.liquid, &p.placement) {
                    let width = 1.0 + self.parts[*jar].material.expansion * delta;
                    let volume = 1.0 + p.material.expansion * delta;
                    material.density /= volume;
                    return Part {
                        shape: p.shape.stretched(width, volume / (width * width)),
                        material,
                        ..p.clone()
                    };
                }
                let factor = 1.0 + p.material.expansion * delta;
                material.density /= factor.powi(3);
                Part {
                    shape: p.shape.scaled(factor),
                    material,
                    ..p.clone()
                }
            })
            .collect();
        let rod = self.rod().map(|i| self.parts[i].material.expansion);
        let centres = resolve(&parts, delta, rod).expect("a checked design stays valid");
        Self { parts, centres }
    }

    /// The index of the rod: the first upright cylinder hanging from the
    /// pivot (its top within a millimetre of it).
    pub fn rod_index(&self) -> Option<usize> {
        self.rod()
    }

    fn rod(&self) -> Option<usize> {
        self.parts.iter().zip(&self.centres).position(|(p, &c)| {
            matches!(p.shape, Shape::Cylinder { .. }) && (c - 0.5 * p.shape.height()).abs() < 1e-3
        })
    }

    /// The rate change per °C, s/day (negative: losing as it warms), to
    /// first order, by a central difference of ±0.5 °C on the exact model
    /// (its error is of order α², 1e-10 relative).
    pub fn temperature_coefficient(&self) -> f64 {
        let l = |dt: f64| self.at_temperature(dt).properties().equivalent_length;
        rate_of_length_ratio(l(0.5) / l(-0.5))
    }

    /// The rate in air of density `rho` kg/m³ against the same pendulum in
    /// a vacuum, s/day (negative: slower): the total, and buoyancy alone.
    pub fn rate_in_air(&self, rho: f64) -> AirRates {
        let vacuum = self.properties_in(0.0).equivalent_length;
        let total = rate_of_length_ratio(self.properties_in(rho).equivalent_length / vacuum);
        let (mut weighing, mut inertia) = (0.0, 0.0);
        for (p, &d) in self.parts.iter().zip(&self.centres) {
            weighing += (p.mass() - rho * p.shape.volume()) * d;
            inertia += p.mass() * (p.shape.inertia_per_mass() + d * d);
        }
        AirRates {
            total,
            buoyancy: rate_of_length_ratio(inertia / weighing / vacuum),
        }
    }

    /// The mass, kg, to add on a regulating tray `at` m below the pivot
    /// (negative: to take off) to correct a clock gaining `rate` s/day:
    /// with `μ` there the equivalent length becomes `(I + μ at²) /
    /// (m d + μ at)`, set to `l (1 + rate/86400)²` and solved for `μ`.
    pub fn tray_mass(&self, at: f64, rate: f64) -> f64 {
        let p = self.properties();
        let target = p.equivalent_length + length_change_for_rate(p.equivalent_length, rate);
        (p.inertia - target * p.mass * p.centre_of_mass) / (target * at - at * at)
    }

    /// The rate change per hPa of air pressure, s/day, at `pressure` Pa,
    /// `temperature` °C and relative humidity `humidity` (0-1): a central
    /// difference of ±1 hPa of [`CompoundPendulum::rate_in_air`] with the
    /// air's density from [`crate::air::air_density`]. NaN outside that
    /// formula's range.
    pub fn pressure_coefficient(&self, pressure: f64, temperature: f64, humidity: f64) -> f64 {
        let rate = |p: f64| {
            self.rate_in_air(crate::air::air_density(p, temperature, humidity))
                .total
        };
        0.5 * (rate(pressure + 100.0) - rate(pressure - 100.0))
    }

    /// How far to move part `index` (and what rests on it) down, m
    /// (negative: up), to change the rate by `-rate` s/day: a clock gaining
    /// `rate` s/day is brought to time. The equivalent length must become
    /// `l (1 + rate/86400)²`; the move is found by Newton's method on the
    /// exact model (derivative by central differences of ±0.1 mm).
    pub fn regulation(&self, index: usize, rate: f64) -> Option<f64> {
        let l = self.properties().equivalent_length;
        let target = l + length_change_for_rate(l, rate);
        let length_at = |shift: f64| self.length_with_shift(index, shift);
        let mut shift = 0.0;
        for _ in 0..8 {
            let h = 1e-4;
            let slope = (length_at(shift + h)? - length_at(shift - h)?) / (2.0 * h);
            if slope.is_nan() || slope == 0.0 {
                return None;
            }
            let step = (target - length_at(shift)?) / slope;
            shift += step;
            if step.abs() < 1e-12 {
                break;
            }
        }
        Some(shift)
    }
}

impl CompoundPendulum {
    /// The equivalent length, m, with part `index` (and what rests on it)
    /// moved `shift` m down; `None` when that part rests on another, or the
    /// move puts a part above the pivot.
    fn length_with_shift(&self, index: usize, shift: f64) -> Option<f64> {
        let mut parts = self.parts.clone();
        let Placement::Centre(c) = parts.get(index)?.placement else {
            return None;
        };
        parts[index].placement = Placement::Centre(c + shift);
        let centres = resolve(&parts, 0.0, None).ok()?;
        Some(Self { parts, centres }.properties().equivalent_length)
    }

    /// The rate change, s/day per metre, of moving part `index` (and what
    /// rests on it) down: `-86400/(2l) dl/dx`, the derivative by a central
    /// difference of ±0.1 mm on the exact model (the equivalent length is
    /// a ratio of quadratics in the shift, so the difference's error is
    /// about (0.1 mm / l)², 1e-8 relative). Negative: lowering the bob
    /// slows the clock. Multiply by the nut's pitch for s/day per turn.
    /// `None` when the part rests on another (move what it rests on).
    pub fn rate_per_metre(&self, index: usize) -> Option<f64> {
        let h = 1e-4;
        let l = self.properties().equivalent_length;
        let slope =
            (self.length_with_shift(index, h)? - self.length_with_shift(index, -h)?) / (2.0 * h);
        Some(-0.5 * DAY * slope / l)
    }
}

/// A clock's rate in air against a vacuum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AirRates {
    /// Buoyancy and entrained air together, s/day.
    pub total: f64,
    /// Buoyancy alone, s/day.
    pub buoyancy: f64,
}

/// The change of length, m, that corrects a clock of equivalent length
/// `length` m gaining `rate` s/day: `l ((1 + rate/86400)² - 1)` (positive:
/// lengthen), since the period goes as the square root of the length.
pub fn length_change_for_rate(length: f64, rate: f64) -> f64 {
    length * ((1.0 + rate / DAY).powi(2) - 1.0)
}

/// The rate change, s/day, of a clock whose equivalent length is
/// multiplied by `ratio`: `86400 (1/sqrt(ratio) - 1)`.
pub fn rate_of_length_ratio(ratio: f64) -> f64 {
    DAY * (1.0 / ratio.sqrt() - 1.0)
}

/// Each part's centre, `delta` °C from the reference, carried by a rod of
/// expansion `rod` (1/K) when there is one.
fn resolve(parts: &[Part], delta: f64, rod: Option<f64>) -> Result<Vec<f64>, DesignError> {
    let mut centres: Vec<Option<f64>> = vec![None; parts.len()];
    for _ in 0..=parts.len() {
        for (i, p) in parts.iter().enumerate() {
            if centres[i].is_some() {
                continue;
            }
            match p.placement {
                Placement::Centre(c) => {
                    let carried = match rod {
                        Some(alpha) => c * (1.0 + alpha * delta),
                        None => c,
                    };
                    centres[i] = Some(carried);
                }
                Placement::RestsOn(j) => {
                    if j >= parts.len() || j == i {
                        return Err(DesignError {
                            part: p.name.clone(),
                            field: "rests_on",
                            message: "names no other part".into(),
                        });
                    }
                    if let Some(cj) = centres[j] {
                        let top = cj - 0.5 * parts[j].shape.height();
                        centres[i] = Some(top - 0.5 * p.shape.height());
                    }
                }
            }
        }
    }
    let mut out = Vec::with_capacity(parts.len());
    for (p, c) in parts.iter().zip(centres) {
        let Some(c) = c else {
            return Err(DesignError {
                part: p.name.clone(),
                field: "rests_on",
                message: "the parts rest on each other in a circle".into(),
            });
        };
        if !c.is_finite() {
            return Err(DesignError {
                part: p.name.clone(),
                field: "centre",
                message: "must be a finite number".into(),
            });
        }
        // Nothing above the pivot or through it (a rod may hang from it).
        if c - 0.5 * p.shape.height() < -1e-9 {
            return Err(DesignError {
                part: p.name.clone(),
                field: "centre",
                message: format!(
                    "its top would be {:.4} m above the pivot; parts hang below it",
                    -(c - 0.5 * p.shape.height())
                ),
            });
        }
        out.push(c);
    }
    Ok(out)
}
