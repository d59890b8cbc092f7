//! Temperature compensation as one analysis: a design's temperature
//! coefficient and the compensator that cancels it, a tube or collar under
//! the bob, a steel and brass gridiron in place of the rod, or a jar of
//! mercury in place of the bob, with the compensated design. The command
//! line's `compensate` and Python's `compensate` are this call; the
//! defaults (a glass jar of 4 mm walls, a tube 1 mm over the rod with
//! 1.5 mm walls) live here.

use super::description::Design;
use super::{CompoundPendulum, Material, Shape};
use crate::analysis::Refusal;
use crate::error::format_significant;
use serde::Serialize;

/// The part a tube goes under, or a jar replaces, when none is named.
pub const DEFAULT_PART: &str = "bob";
/// A mercury jar's material when none is given.
pub const DEFAULT_JAR_MATERIAL: &str = "glass";
/// A jar's diameter when none is given and the bob is no cylinder, m.
pub const DEFAULT_JAR_DIAMETER_M: f64 = 0.06;
/// A jar's wall (and bottom) when none is given, m.
pub const DEFAULT_JAR_WALL_M: f64 = 0.004;
/// A tube's bore over the rod's diameter when none is given, m.
pub const TUBE_CLEARANCE_M: f64 = 1e-3;
/// A tube's wall when no diameter is given, m.
pub const TUBE_WALL_M: f64 = 1.5e-3;
/// The largest tube or jar taken, m across.
pub const MAX_SIZE_M: f64 = 1.0;

/// What to size, and its sizes; every `None` the default.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CompensateInput {
    /// A tube's material (zinc, aluminium, ...; `collar` a brass collar),
    /// `gridiron` or `mercury`; none: the coefficient alone.
    pub compensator: Option<String>,
    /// The part the tube goes under or the jar replaces.
    pub part: Option<String>,
    /// The jar's material.
    pub jar_material: Option<String>,
    /// The jar's outer diameter, m (default the bob's, else 60 mm).
    pub jar_diameter: Option<f64>,
    /// The jar's wall, m.
    pub jar_wall: Option<f64>,
    /// The tube's outer diameter, m.
    pub tube_diameter: Option<f64>,
    /// The tube's bore, m.
    pub tube_bore: Option<f64>,
}

/// A design's coefficient and its compensator.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Compensation {
    /// The design as given: s/day per °C (negative: losing as it warms).
    pub temperature_coefficient_s_per_day_per_c: f64,
    /// The design as given: `I / (m d)`, m.
    pub equivalent_length_m: f64,
    /// The compensator sized.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compensator: Option<String>,
    /// A tube's length, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tube_length_m: Option<f64>,
    /// Its outer diameter, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tube_diameter_m: Option<f64>,
    /// Its bore, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tube_bore_m: Option<f64>,
    /// For a gridiron: the brass in its series, m (the steel is the drop
    /// and this).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub brass_length_m: Option<f64>,
    /// For a mercury jar: the mercury's height, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mercury_height_m: Option<f64>,
    /// The mercury's mass, kg.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mercury_mass_kg: Option<f64>,
    /// The jar's material.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub jar_material: Option<String>,
    /// The jar's diameter, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub jar_diameter_m: Option<f64>,
    /// The jar's wall, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub jar_wall_m: Option<f64>,
    /// The compensated design's coefficient, s/day per °C.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compensated_coefficient_s_per_day_per_c: Option<f64>,
    /// The compensated design's equivalent length, m (a jar in place of
    /// the bob changes it: regulate after).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compensated_equivalent_length_m: Option<f64>,
    /// The compensated design.
    #[serde(skip)]
    pub compensated: Option<CompoundPendulum>,
}

/// The index of the part `name`.
fn part_index(design: &CompoundPendulum, name: &str) -> Result<usize, Refusal> {
    design
        .parts()
        .iter()
        .position(|p| p.name == name)
        .ok_or_else(|| Refusal::field("part", format!("the design has no part named '{name}'")))
}

/// A size of a tube or jar, m: positive, at most [`MAX_SIZE_M`].
fn positive_length(field: &'static str, v: f64) -> Result<f64, Refusal> {
    if v.is_nan() || v <= 0.0 {
        return Err(Refusal::field(
            field,
            format!("must be positive, got {} m", format_significant(v, 6)),
        ));
    }
    if v > MAX_SIZE_M {
        return Err(Refusal::field(
            field,
            format!(
                "must be at most 1 m for a pendulum's tube or jar, got {} m",
                format_significant(v, 6)
            ),
        ));
    }
    Ok(v)
}

/// A material of the table, for `field`.
fn table_material(field: &'static str, name: &str) -> Result<Material, Refusal> {
    Material::named(name).ok_or_else(|| {
        Refusal::field(
            field,
            format!(
                "'{name}' is not in the table ({})",
                Material::names().join(", ")
            ),
        )
    })
}

/// The coefficient of `read`'s design and, with a compensator, its size
/// and the compensated design.
pub fn compensate(read: &Design, input: &CompensateInput) -> Result<Compensation, Refusal> {
    let design = &read.pendulum;
    let part = input.part.as_deref().unwrap_or(DEFAULT_PART);
    let before = design.temperature_coefficient();
    let mut result = Compensation {
        temperature_coefficient_s_per_day_per_c: before,
        equivalent_length_m: design.properties().equivalent_length,
        ..Compensation::default()
    };
    let kind = input.compensator.as_deref().map(str::to_ascii_lowercase);
    // A tube lifts the bob as it warms: it can only cancel a loss.
    let lifting = |what: &str| -> Option<Refusal> {
        (before > 0.0).then(|| {
            Refusal::field(
                "compensator",
                format!(
                    "the design already gains as it warms ({} s/day per °C): {what} lifting the {} would add to it; support the bob nearer its centre, or use a rod that expands more",
                    format_significant(before, 3),
                    part
                ),
            )
        })
    };
    let compensated = match kind.as_deref() {
        None => None,
        Some("gridiron") => {
            let (steel, brass) = (
                Material::named("steel")
                    .ok_or_else(|| Refusal::data("steel is not in the table"))?,
                Material::named("brass")
                    .ok_or_else(|| Refusal::data("brass is not in the table"))?,
            );
            let (compensated, brass_length) =
                design.with_gridiron(&steel, &brass).ok_or_else(|| {
                    Refusal::field(
                        "compensator",
                        "no steel and brass gridiron of this rod's drop cancels the coefficient (the design needs a rod hanging from the pivot)",
                    )
                })?;
            result.compensator = Some("gridiron".into());
            result.brass_length_m = Some(brass_length);
            Some(compensated)
        }
        Some("mercury") | Some("mercury jar") | Some("jar") => {
            let bob = part_index(design, part)?;
            let jar = table_material(
                "jar_material",
                input
                    .jar_material
                    .as_deref()
                    .unwrap_or(DEFAULT_JAR_MATERIAL),
            )?;
            if jar.liquid {
                return Err(Refusal::field("jar_material", "a jar must be a solid"));
            }
            let diameter = match input.jar_diameter {
                Some(d) => positive_length("jar_diameter", d)?,
                None => match design.parts()[bob].shape {
                    Shape::Cylinder { diameter, .. } => diameter,
                    _ => DEFAULT_JAR_DIAMETER_M,
                },
            };
            let wall = positive_length("jar_wall", input.jar_wall.unwrap_or(DEFAULT_JAR_WALL_M))?;
            let (compensated, height) = design
                .with_mercury_jar(bob, &jar, diameter, wall)
                .ok_or_else(|| {
                    Refusal::field(
                        "compensator",
                        format!(
                            "no mercury up to 0.5 m deep in a {} mm {} jar cancels this design's coefficient (the '{}' must rest on a nut or stirrup, and the jar be wider than its walls and the rod)",
                            format_significant(diameter * 1e3, 4),
                            jar.name,
                            part
                        ),
                    )
                })?;
            let mercury = compensated
                .parts()
                .iter()
                .find(|p| p.material.liquid)
                .map(|p| p.mass());
            result.compensator = Some("mercury jar".into());
            result.mercury_height_m = Some(height);
            result.mercury_mass_kg = mercury;
            result.jar_material = Some(jar.name.clone());
            result.jar_diameter_m = Some(diameter);
            result.jar_wall_m = Some(wall);
            Some(compensated)
        }
        Some(name) => {
            let material = table_material(
                "compensator",
                if name == "collar" { "brass" } else { name },
            )
            .map_err(|_| {
                Refusal::field(
                    "compensator",
                    format!(
                        "'{name}' is neither gridiron, mercury, collar nor a material of the table ({})",
                        Material::names().join(", ")
                    ),
                )
            })?;
            if material.liquid {
                return Err(Refusal::field(
                    "compensator",
                    "a liquid goes in a jar: give --compensator mercury",
                ));
            }
            let bob = part_index(design, part)?;
            if let Some(e) = lifting("a tube") {
                return Err(e);
            }
            let rod_diameter = design
                .rod_index()
                .and_then(|i| match design.parts()[i].shape {
                    Shape::Cylinder { diameter, .. } => Some(diameter),
                    _ => None,
                })
                .ok_or_else(|| Refusal::field("design", "has no rod hanging from the pivot"))?;
            let bore = positive_length(
                "tube_bore",
                input.tube_bore.unwrap_or(rod_diameter + TUBE_CLEARANCE_M),
            )?;
            let diameter = positive_length(
                "tube_diameter",
                input.tube_diameter.unwrap_or(bore + 2.0 * TUBE_WALL_M),
            )?;
            if diameter <= bore {
                // Said of the flag the user gave (the other is derived).
                let field = if input.tube_diameter.is_some() {
                    "tube_diameter"
                } else {
                    "tube_bore"
                };
                return Err(Refusal::field(
                    field,
                    format!(
                        "the tube's bore ({} mm) must be less than its diameter ({} mm)",
                        format_significant(bore * 1e3, 4),
                        format_significant(diameter * 1e3, 4)
                    ),
                ));
            }
            let (compensated, length) = design
                .with_compensating_tube(bob, material.clone(), diameter, bore)
                .ok_or_else(|| {
                    Refusal::field(
                        "compensator",
                        format!(
                            "no {} tube up to 1.5 m cancels this design's coefficient (the '{}' must rest on a nut placed on the rod, and the tube must expand more than the rod)",
                            material.name, part
                        ),
                    )
                })?;
            result.compensator = Some(material.name);
            result.tube_length_m = Some(length);
            result.tube_diameter_m = Some(diameter);
            result.tube_bore_m = Some(bore);
            Some(compensated)
        }
    };
    if let Some(c) = &compensated {
        result.compensated_coefficient_s_per_day_per_c = Some(c.temperature_coefficient());
        result.compensated_equivalent_length_m = Some(c.properties().equivalent_length);
    }
    result.compensated = compensated;
    Ok(result)
}
