//! Temperature compensators: parts sized so that a design's first-order
//! temperature coefficient vanishes. Each builds the compensated design
//! for a trial size and finds the size by bisection on the exact model's
//! coefficient ([`CompoundPendulum::temperature_coefficient`]), so what is
//! cancelled is the coefficient of the whole pendulum (the rod, the nut,
//! the bob's own growth, the compensator's mass and inertia), not a
//! textbook ratio of lengths.
//!
//! - a tube (zinc, aluminium; a short brass collar under the bob of an
//!   Invar rod) between the nut and the bob, lifting the bob as it grows:
//!   [`CompoundPendulum::with_compensating_tube`];
//! - Harrison's gridiron of steel and brass rods: [`gridiron`],
//!   [`CompoundPendulum::with_gridiron`];
//! - Graham's jar of mercury (1721), whose level rises as the mercury
//!   expands: [`CompoundPendulum::with_mercury_jar`];
//! - a zinc tube standing on the nut inside a steel tube hanging from its
//!   top, the bob on the steel tube's lower end (the Westminster clock's
//!   compensation): [`CompoundPendulum::with_tube_in_tube`].

use super::{CompoundPendulum, Material, Part, Placement, Shape};

impl CompoundPendulum {
    /// A design of `parts` in this one's gravity, if they make one.
    fn remade(&self, parts: Vec<Part>) -> Option<Self> {
        Self::new(parts).ok().map(|p| p.in_gravity(self.gravity))
    }

    /// How part `bob` is placed and the index of the part it rests on (or
    /// hangs from): what a tube is put between.
    fn held_on(&self, bob: usize) -> Result<(Placement, usize), NoCompensation> {
        let held = self
            .parts
            .get(bob)
            .ok_or(NoCompensation::NotCarried)?
            .placement
            .clone();
        let on = held.support().ok_or(NoCompensation::NotCarried)?;
        Ok((held, on))
    }

    /// The same pendulum with a compensating tube of `material` (outer
    /// diameter `diameter`, bore `bore`, m) put under the part `bob`, which
    /// must rest on a part placed on the rod (its nut); the rod is made
    /// longer and the nut moved down by the tube's length, so that the bob
    /// stays where it was. The tube's length is chosen so that the
    /// first-order temperature coefficient vanishes: the tube grows upward
    /// from the nut as much as the rod and the bob's own expansion carry
    /// the centre of oscillation down. Found by bisection between 0.1 mm
    /// and 1.5 m on the exact model's coefficient. Returns the design and
    /// the tube's length, m; why not when no length in that range does it
    /// (a compensator that expands too little more than the rod).
    pub fn with_compensating_tube(
        &self,
        bob: usize,
        material: Material,
        diameter: f64,
        bore: f64,
    ) -> Result<(Self, f64), NoCompensation> {
        let (held, nut) = self.held_on(bob)?;
        let Placement::Centre(nut_centre) = self.parts[nut].placement else {
            return Err(NoCompensation::SupportNotOnRod);
        };
        let rod = self.rod().ok_or(NoCompensation::NoRod)?;
        let build = |length: f64| -> Option<Self> {
            let mut parts = self.parts.clone();
            if let Shape::Cylinder {
                length: l,
                diameter,
                bore,
            } = parts[rod].shape
            {
                parts[rod].shape = Shape::Cylinder {
                    length: l + length,
                    diameter,
                    bore,
                };
                parts[rod].placement = Placement::Centre(0.5 * (l + length));
            }
            parts[nut].placement = Placement::Centre(nut_centre + length);
            parts.push(Part {
                name: "compensator".into(),
                shape: Shape::Cylinder {
                    length,
                    diameter,
                    bore,
                },
                material: material.clone(),
                point_mass: 0.0,
                placement: Placement::RestsOn(nut),
                massless: false,
                time_constant: 0.0,
                moisture_time_constant: 0.0,
            });
            let tube = parts.len() - 1;
            parts[bob].placement = held.carried_by(tube);
            self.remade(parts)
        };
        sized(build, 1e-4, 1.5)
    }

    /// The same pendulum with the classical compensator of a tube inside a
    /// tube (the Westminster clock's zinc and iron): a tube of `inner`
    /// (zinc) standing on the nut the part `bob` rests on, around the rod,
    /// and a tube of `outer` (steel) of the same length hanging from its
    /// top around it, on whose lower end the bob is carried as it was on
    /// the nut. The rod grows down, the inner tube up and the outer down
    /// again, so the inner tube must expand more than the rod and the
    /// outer tube together over its length: `L (α_in - α_out) ≈ D α_rod`
    /// for a drop `D`, which for zinc and steel is about 0.6 of the rod.
    /// The bob stays where it was at the reference temperature (the outer
    /// tube ends where the nut's top is); a cylindrical bob's bore is
    /// widened to clear the outer tube. Each tube's bore clears what it
    /// surrounds by [`super::compensate::TUBE_CLEARANCE_M`], its wall
    /// `wall`. The length is found by bisection between 0.1 mm and 1.5 m
    /// (or the longest tube that stays below the pivot) on the exact
    /// model's coefficient. Returns the design and the
    /// length, m; why not when no length in that range does it.
    pub fn with_tube_in_tube(
        &self,
        bob: usize,
        inner: Material,
        outer: Material,
        rod_diameter: f64,
        wall: f64,
    ) -> Result<(Self, f64), NoCompensation> {
        let (held, nut) = self.held_on(bob)?;
        let clearance = super::compensate::TUBE_CLEARANCE_M;
        let inner_bore = rod_diameter + clearance;
        let inner_diameter = inner_bore + 2.0 * wall;
        let outer_bore = inner_diameter + clearance;
        let outer_diameter = outer_bore + 2.0 * wall;
        let build = |length: f64| -> Option<Self> {
            let mut parts = self.parts.clone();
            parts.push(Part {
                name: "inner tube".into(),
                shape: Shape::Cylinder {
                    length,
                    diameter: inner_diameter,
                    bore: inner_bore,
                },
                material: inner.clone(),
                point_mass: 0.0,
                placement: Placement::RestsOn(nut),
                massless: false,
                time_constant: 0.0,
                moisture_time_constant: 0.0,
            });
            let tube = parts.len() - 1;
            parts.push(Part {
                name: "outer tube".into(),
                shape: Shape::Cylinder {
                    length,
                    diameter: outer_diameter,
                    bore: outer_bore,
                },
                material: outer.clone(),
                point_mass: 0.0,
                placement: Placement::Held {
                    part: tube,
                    end: super::End::Top,
                    height: length,
                },
                massless: false,
                time_constant: 0.0,
                moisture_time_constant: 0.0,
            });
            let hanging = parts.len() - 1;
            // The bob's bore clears the outer tube that now runs up it.
            if let Shape::Cylinder {
                length: l,
                diameter: d,
                bore: b,
            } = parts[bob].shape
            {
                let clear = outer_diameter + clearance;
                if b < clear && clear < d {
                    parts[bob].shape = Shape::Cylinder {
                        length: l,
                        diameter: d,
                        bore: clear,
                    };
                }
            }
            parts[bob].placement = match held {
                Placement::Held { height, .. } => Placement::Held {
                    part: hanging,
                    end: super::End::Bottom,
                    height,
                },
                _ => Placement::Held {
                    part: hanging,
                    end: super::End::Bottom,
                    height: 0.0,
                },
            };
            self.remade(parts)
        };
        // The inner tube stands on the nut and must stay below the pivot
        // (warmed by the design's whole span too): the longest that does.
        let nut_top = self.centres[nut] - 0.5 * self.parts[nut].shape.height();
        let mut high = (nut_top - 1e-3).min(1.5);
        while build(high).is_none() && high > 1e-3 {
            high *= 0.98;
        }
        sized(build, 1e-4, high)
    }
}

/// A gridiron (Harrison's: steel rods hanging down, brass rods standing up,
/// in series, so that the drop `D` from the pivot to the bob's support is
/// `L_s - L_b`) as the rod it replaces: an upright cylinder of length `D`
/// and the rods' diameter, of a material whose expansion is the series'
/// net `(L_s α_s - L_b α_b) / D` and whose density carries the rods' mass:
/// each length of the series as a symmetric pair of rods but the central
/// steel rod alone, `m = A (ρ_s (2 L_s - D) + 2 ρ_b L_b)`, spread evenly
/// over the drop (the frame's crossbars are left out). Returns that
/// material.
pub fn gridiron(
    drop: f64,
    brass_length: f64,
    rod_diameter: f64,
    steel: &Material,
    brass: &Material,
) -> Material {
    let steel_length = drop + brass_length;
    let area = 0.25 * std::f64::consts::PI * rod_diameter * rod_diameter;
    let mass =
        area * (steel.density * (2.0 * steel_length - drop) + 2.0 * brass.density * brass_length);
    Material {
        name: format!(
            "gridiron ({} {:.1} mm, {} {:.1} mm)",
            steel.name,
            steel_length * 1e3,
            brass.name,
            brass_length * 1e3
        ),
        density: mass / (area * drop),
        expansion: (steel_length * steel.expansion - brass_length * brass.expansion) / drop,
        liquid: false,
        modulus: None,
        modulus_coefficient: None,
        moisture_expansion: None,
    }
}

impl CompoundPendulum {
    /// The same pendulum with its rod replaced by a gridiron of `steel` and
    /// `brass` of the same drop and rod diameter (see [`gridiron`]), the
    /// brass length chosen by bisection (0 to three drops) so that the
    /// first-order temperature coefficient vanishes. Returns the design and
    /// the brass length, m.
    pub fn with_gridiron(&self, steel: &Material, brass: &Material) -> Option<(Self, f64)> {
        let rod = self.rod()?;
        let Shape::Cylinder {
            length, diameter, ..
        } = self.parts[rod].shape
        else {
            return None;
        };
        let build = |brass_length: f64| -> Option<Self> {
            let mut parts = self.parts.clone();
            parts[rod].material = gridiron(length, brass_length, diameter, steel, brass);
            self.remade(parts)
        };
        sized(build, 0.0, 3.0 * length).ok()
    }
}

impl CompoundPendulum {
    /// The same pendulum with the part `bob` (which must rest on another
    /// part: its nut or stirrup) replaced by a jar of mercury, Graham's
    /// compensator: a bottom of `jar` material `wall` m thick and `diameter`
    /// m across resting on that support, a wall of the same material and
    /// thickness as high as the mercury, and the mercury (an upright
    /// cylinder of the jar's inner diameter) resting on the bottom. Where
    /// the bob had a bore (the rod passing through it), the bottom and the
    /// mercury keep that bore (the thin tube around the rod is left out).
    /// The mercury's height is chosen so that the first-order temperature
    /// coefficient vanishes: the mercury rises by its volume expansion
    /// less twice the jar's linear one, carrying its centre up as the rod
    /// carries the jar down. Found by bisection between 1 mm and 0.5 m.
    /// Returns the design and the height, m; `None` when no height in that
    /// range does it, or when the jar is too narrow for its walls.
    pub fn with_mercury_jar(
        &self,
        bob: usize,
        jar: &Material,
        diameter: f64,
        wall: f64,
    ) -> Option<(Self, f64)> {
        let Placement::RestsOn(support) = self.parts.get(bob)?.placement else {
            return None;
        };
        let hole = match self.parts[bob].shape {
            Shape::Cylinder { bore, .. } => bore,
            _ => 0.0,
        };
        let inner = diameter - 2.0 * wall;
        if !(wall > 0.0 && inner > hole) {
            return None;
        }
        let mercury = Material::named("mercury").expect("mercury is in the table");
        let build = |height: f64| -> Option<Self> {
            let mut parts = self.parts.clone();
            let name = parts[bob].name.clone();
            parts[bob] = Part {
                name: format!("{name} (jar bottom)"),
                shape: Shape::Cylinder {
                    length: wall,
                    diameter,
                    bore: hole,
                },
                material: jar.clone(),
                point_mass: 0.0,
                placement: Placement::RestsOn(support),
                massless: false,
                time_constant: 0.0,
                moisture_time_constant: 0.0,
            };
            let wall_part = Part {
                name: format!("{name} (jar wall)"),
                shape: Shape::Cylinder {
                    length: height,
                    diameter,
                    bore: inner,
                },
                material: jar.clone(),
                point_mass: 0.0,
                placement: Placement::RestsOn(bob),
                massless: false,
                time_constant: 0.0,
                moisture_time_constant: 0.0,
            };
            let mercury_part = Part {
                name: format!("{name} (mercury)"),
                shape: Shape::Cylinder {
                    length: height,
                    diameter: inner,
                    bore: hole,
                },
                material: mercury.clone(),
                point_mass: 0.0,
                placement: Placement::RestsOn(bob),
                massless: false,
                time_constant: 0.0,
                moisture_time_constant: 0.0,
            };
            parts.push(wall_part);
            parts.push(mercury_part);
            self.remade(parts)
        };
        sized(build, 1e-3, 0.5).ok()
    }
}

impl CompoundPendulum {
    /// The same pendulum with the part `index` (placed by its centre) and
    /// what rests on it moved `shift` m down; with `rod_follows`, the rod
    /// made as much longer (shorter for a move up), its end keeping its
    /// place under the part. `None` when the moved design is not a valid
    /// one, or (the rod staying) the part's centre leaves the rod.
    pub fn moved(&self, index: usize, shift: f64, rod_follows: bool) -> Option<Self> {
        let mut parts = self.parts.clone();
        let Placement::Centre(c) = parts.get(index)?.placement else {
            return None;
        };
        parts[index].placement = Placement::Centre(c + shift);
        if let Some(rod) = self.rod().filter(|&r| r != index) {
            if let Shape::Cylinder {
                length,
                diameter,
                bore,
            } = parts[rod].shape
            {
                if rod_follows {
                    let length = length + shift;
                    if length <= 0.0 {
                        return None;
                    }
                    parts[rod].shape = Shape::Cylinder {
                        length,
                        diameter,
                        bore,
                    };
                    parts[rod].placement = Placement::Centre(0.5 * length);
                } else if !(0.0..=length).contains(&(c + shift)) {
                    return None;
                }
            }
        }
        self.remade(parts)
    }
}

/// Why no compensator of a kind cancels a design's temperature coefficient.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NoCompensation {
    /// The part to carry does not rest on (or hang from) another part.
    NotCarried,
    /// What it rests on is not placed on the rod by its centre (a nut).
    SupportNotOnRod,
    /// The design has no rod hanging from the pivot.
    NoRod,
    /// The coefficient keeps its sign over the sizes tried: its values at
    /// the smallest and the largest, s/day per °C, and the largest size, m.
    SameSign {
        /// At the smallest size.
        smallest: f64,
        /// At the largest size.
        largest: f64,
        /// The largest size, m.
        size: f64,
    },
    /// A trial design could not be made (it would reach the pivot).
    Unbuildable,
}

/// The design `build` makes at the size [`zero_coefficient`] finds, with
/// that size.
fn sized(
    build: impl Fn(f64) -> Option<CompoundPendulum>,
    low: f64,
    high: f64,
) -> Result<(CompoundPendulum, f64), NoCompensation> {
    let size = zero_coefficient(&build, low, high)?;
    Ok((build(size).ok_or(NoCompensation::Unbuildable)?, size))
}

/// The size in `[low, high]` at which the design `build` makes has no
/// first-order temperature coefficient, by bisection (80 halvings, to the
/// last bit); why not when the coefficient keeps its sign over the range.
fn zero_coefficient(
    build: impl Fn(f64) -> Option<CompoundPendulum>,
    low: f64,
    high: f64,
) -> Result<f64, NoCompensation> {
    let coefficient = |x: f64| {
        build(x)
            .map(|p| p.temperature_coefficient())
            .ok_or(NoCompensation::Unbuildable)
    };
    let (mut low, mut high) = (low, high);
    let f_low = coefficient(low)?;
    let f_high = coefficient(high)?;
    if f_low.signum() == f_high.signum() {
        return Err(NoCompensation::SameSign {
            smallest: f_low,
            largest: f_high,
            size: high,
        });
    }
    for _ in 0..80 {
        let middle = 0.5 * (low + high);
        if coefficient(middle)?.signum() == f_low.signum() {
            low = middle;
        } else {
            high = middle;
        }
    }
    Ok(0.5 * (low + high))
}
