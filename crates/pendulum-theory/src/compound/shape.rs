//! The shapes of pendulum parts: volume, vertical extent, and moment of
//! inertia about the part's own centre for the swing's axis (horizontal,
//! perpendicular to the plane of swing).
//!
//! Formulas (standard rigid-body results, e.g. Goldstein, Classical
//! Mechanics, 3rd ed., 2002, §5.3; Meriam & Kraige, Engineering Mechanics:
//! Dynamics, table D/4):
//! - a cylinder standing upright (a rod, a cylindrical bob, a tube) of
//!   length `L`, outer radius `R`, bore radius `r`, turning about a
//!   transverse axis: `I = m (L²/12 + (R² + r²)/4)`;
//! - a disc in the plane of swing, radius `R`, turning about its own axis:
//!   `I = m R²/2`;
//! - a lens bob: taken as paraboloidal faces (thickness `t (1 - ρ²/R²)` at
//!   radius `ρ`, which a spherical lens whose thickness is small against
//!   its diameter follows to within (t/D)²): volume `π R² t / 2`,
//!   `I = m R²/3`;
//! - a sphere: `I = 2 m R²/5`;
//! - a ring (annulus in the plane of swing, radii `R` and `r`):
//!   `I = m (R² + r²)/2`;
//! - a point mass: `I = 0`.

use std::f64::consts::PI;

/// A part's shape, dimensions in metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// An upright cylinder (a rod, a cylindrical bob, a tube, a rating
    /// nut): length along the rod, outer diameter, bore diameter (0 for a
    /// solid one).
    Cylinder {
        /// Length along the rod, m.
        length: f64,
        /// Outer diameter, m.
        diameter: f64,
        /// Bore diameter, m.
        bore: f64,
    },
    /// A flat disc in the plane of swing.
    Disc {
        /// Diameter, m.
        diameter: f64,
        /// Thickness, m.
        thickness: f64,
    },
    /// A lens bob in the plane of swing (see the module notes).
    Lens {
        /// Diameter, m.
        diameter: f64,
        /// Thickness at the centre, m.
        thickness: f64,
    },
    /// A sphere.
    Sphere {
        /// Diameter, m.
        diameter: f64,
    },
    /// A flat ring in the plane of swing.
    Ring {
        /// Outer diameter, m.
        outer: f64,
        /// Inner diameter, m.
        inner: f64,
        /// Thickness, m.
        thickness: f64,
    },
    /// A flat suspension spring hanging from the chops (the pivot), its
    /// thickness in the plane of swing: see [`crate::suspension`].
    Spring {
        /// Free length, m.
        length: f64,
        /// Width across the plane of swing, m.
        width: f64,
        /// Thickness in the plane of swing, m.
        thickness: f64,
    },
    /// A point mass (its mass is given, not a material's).
    Point,
}

impl Shape {
    /// Its name in a description (`cylinder`, `disc`, …; a rod and a tube
    /// are cylinders).
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Cylinder { .. } => "cylinder",
            Shape::Disc { .. } => "disc",
            Shape::Lens { .. } => "lens",
            Shape::Sphere { .. } => "sphere",
            Shape::Ring { .. } => "ring",
            Shape::Spring { .. } => "spring",
            Shape::Point => "point",
        }
    }

    /// Volume, m³ (0 for a point).
    pub fn volume(&self) -> f64 {
        match *self {
            Shape::Cylinder {
                length,
                diameter,
                bore,
            } => 0.25 * PI * (diameter * diameter - bore * bore) * length,
            Shape::Disc {
                diameter,
                thickness,
            } => 0.25 * PI * diameter * diameter * thickness,
            Shape::Lens {
                diameter,
                thickness,
            } => 0.125 * PI * diameter * diameter * thickness,
            Shape::Sphere { diameter } => PI * diameter.powi(3) / 6.0,
            Shape::Ring {
                outer,
                inner,
                thickness,
            } => 0.25 * PI * (outer * outer - inner * inner) * thickness,
            Shape::Spring {
                length,
                width,
                thickness,
            } => length * width * thickness,
            Shape::Point => 0.0,
        }
    }

    /// Whether it is a suspension spring.
    pub fn is_spring(&self) -> bool {
        matches!(self, Shape::Spring { .. })
    }

    /// Vertical extent, m: from the part's top to its bottom.
    pub fn height(&self) -> f64 {
        match *self {
            Shape::Cylinder { length, .. } => length,
            Shape::Disc { diameter, .. } | Shape::Lens { diameter, .. } => diameter,
            Shape::Sphere { diameter } => diameter,
            Shape::Ring { outer, .. } => outer,
            Shape::Spring { length, .. } => length,
            Shape::Point => 0.0,
        }
    }

    /// Moment of inertia about the part's own centre per unit mass, m²
    /// (see the module notes).
    pub fn inertia_per_mass(&self) -> f64 {
        match *self {
            Shape::Cylinder {
                length,
                diameter,
                bore,
            } => length * length / 12.0 + (diameter * diameter + bore * bore) / 16.0,
            Shape::Disc { diameter, .. } => diameter * diameter / 8.0,
            Shape::Lens { diameter, .. } => diameter * diameter / 12.0,
            Shape::Sphere { diameter } => 0.1 * diameter * diameter,
            Shape::Ring { outer, inner, .. } => (outer * outer + inner * inner) / 8.0,
            Shape::Spring {
                length, thickness, ..
            } => (length * length + thickness * thickness) / 12.0,
            Shape::Point => 0.0,
        }
    }

    /// The variance of its mass's height about its centre, m²: the part
    /// of [`Shape::inertia_per_mass`] that comes from its vertical extent
    /// (an upright cylinder or a spring `L²/12`; a disc in the plane of
    /// swing `R²/4`, a ring `(R² + r²)/4`, the paraboloidal lens `R²/6`,
    /// half their inertia about their axis; a sphere `R²/5`; a point 0).
    pub fn vertical_variance(&self) -> f64 {
        match *self {
            Shape::Cylinder { length, .. } | Shape::Spring { length, .. } => length * length / 12.0,
            Shape::Disc { diameter, .. } => diameter * diameter / 16.0,
            Shape::Lens { diameter, .. } => diameter * diameter / 24.0,
            Shape::Sphere { diameter } => 0.05 * diameter * diameter,
            Shape::Ring { outer, inner, .. } => (outer * outer + inner * inner) / 16.0,
            Shape::Point => 0.0,
        }
    }

    /// The same shape with every dimension multiplied by `factor` (thermal
    /// expansion).
    pub fn scaled(&self, factor: f64) -> Self {
        match *self {
            Shape::Cylinder { .. } => self.stretched(factor, factor),
            Shape::Disc {
                diameter,
                thickness,
            } => Shape::Disc {
                diameter: diameter * factor,
                thickness: thickness * factor,
            },
            Shape::Lens {
                diameter,
                thickness,
            } => Shape::Lens {
                diameter: diameter * factor,
                thickness: thickness * factor,
            },
            Shape::Sphere { diameter } => Shape::Sphere {
                diameter: diameter * factor,
            },
            Shape::Ring {
                outer,
                inner,
                thickness,
            } => Shape::Ring {
                outer: outer * factor,
                inner: inner * factor,
                thickness: thickness * factor,
            },
            Shape::Spring {
                length,
                width,
                thickness,
            } => Shape::Spring {
                length: length * factor,
                width: width * factor,
                thickness: thickness * factor,
            },
            Shape::Point => Shape::Point,
        }
    }

    /// An upright cylinder with its length multiplied by `height` and its
    /// diameters by `width` (a liquid rising in its jar); any other shape
    /// scaled by `width` alone.
    pub fn stretched(&self, width: f64, height: f64) -> Self {
        match *self {
            Shape::Cylinder {
                length,
                diameter,
                bore,
            } => Shape::Cylinder {
                length: length * height,
                diameter: diameter * width,
                bore: bore * width,
            },
            other => other.scaled(width),
        }
    }
}
