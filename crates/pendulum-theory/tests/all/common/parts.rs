//! Parts of designs for the compound-pendulum tests.

use pendulum_theory::compound::{Material, Part, Placement, Shape};

/// A part of a built-in material.
pub fn part(name: &str, shape: Shape, material: &str, placement: Placement) -> Part {
    Part {
        name: name.into(),
        shape,
        material: Material::named(material).expect("a built-in material"),
        point_mass: 0.0,
        placement,
        massless: false,
        time_constant: 0.0,
        moisture_time_constant: 0.0,
    }
}

/// An upright cylinder.
pub fn cylinder(length: f64, diameter: f64, bore: f64) -> Shape {
    Shape::Cylinder {
        length,
        diameter,
        bore,
    }
}
