//! `pendulum compensate`: a design's temperature coefficient, and the
//! compensator that cancels it (a tube or collar, a gridiron, a mercury
//! jar), optionally written back as a design file.

use super::common;
use crate::args::CompensateArgs;
use crate::error::CliError;
use crate::file::AtomicFile;
use crate::output::{self, num, Summary};
use crate::units::Dimension;
use pendulum_theory::compound::{CompoundPendulum, Material, Shape};
use serde::Serialize;

#[derive(Serialize, Default)]
struct CompensateJson {
    /// The design as given: s/day per °C (negative: losing as it warms).
    temperature_coefficient_s_per_day_per_c: f64,
    /// The design as given: `I / (m d)`, m.
    equivalent_length_m: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    compensator: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tube_length_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tube_diameter_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tube_bore_m: Option<f64>,
    /// For a gridiron: the brass in its series, m (the steel is the drop
    /// and this).
    #[serde(skip_serializing_if = "Option::is_none")]
    brass_length_m: Option<f64>,
    /// For a mercury jar: the mercury's height, m, and mass, kg.
    #[serde(skip_serializing_if = "Option::is_none")]
    mercury_height_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    mercury_mass_kg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    jar_material: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    jar_diameter_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    jar_wall_m: Option<f64>,
    /// The compensated design's coefficient, s/day per °C.
    #[serde(skip_serializing_if = "Option::is_none")]
    compensated_coefficient_s_per_day_per_c: Option<f64>,
    /// The compensated design's equivalent length, m (a jar in place of
    /// the bob changes it: regulate after).
    #[serde(skip_serializing_if = "Option::is_none")]
    compensated_equivalent_length_m: Option<f64>,
    /// Where the compensated design was written.
    #[serde(skip_serializing_if = "Option::is_none")]
    written_to: Option<String>,
}

/// The index of the part named by `--part`.
fn part_index(design: &CompoundPendulum, name: &str) -> Result<usize, CliError> {
    design
        .parts()
        .iter()
        .position(|p| p.name == name)
        .ok_or_else(|| CliError::flag("--part", format!("the design has no part named '{name}'")))
}

/// A length flag, positive.
fn positive_length(flag: &'static str, text: &str) -> Result<f64, CliError> {
    let v = common::quantity(flag, text, Dimension::Length)?;
    if v.is_nan() || v <= 0.0 {
        return Err(CliError::flag(
            flag,
            format!("must be positive, got {text}"),
        ));
    }
    // A tube or a jar on a clock pendulum: under a metre across.
    if v > 1.0 {
        return Err(CliError::flag(
            flag,
            format!("must be at most 1 m for a pendulum's tube or jar, got {text}"),
        ));
    }
    Ok(v)
}

/// A material of the table, for `flag`.
fn table_material(flag: &'static str, name: &str) -> Result<Material, CliError> {
    Material::named(name).ok_or_else(|| {
        CliError::flag(
            flag,
            format!(
                "'{name}' is not in the table ({})",
                Material::names().join(", ")
            ),
        )
    })
}

pub fn run(args: &CompensateArgs) -> Result<String, CliError> {
    let read = crate::design::read_design(&args.design)?;
    let design = read.pendulum;
    let before = design.temperature_coefficient();
    let mut result = CompensateJson {
        temperature_coefficient_s_per_day_per_c: before,
        equivalent_length_m: design.properties().equivalent_length,
        ..CompensateJson::default()
    };
    let kind = args.compensator.as_deref().map(str::to_ascii_lowercase);
    // A tube lifts the bob as it warms: it can only cancel a loss.
    let lifting = |what: &str| -> Option<CliError> {
        (before > 0.0).then(|| {
            CliError::flag(
                "--compensator",
                format!(
                    "the design already gains as it warms ({} s/day per °C): {what} lifting the {} would add to it; support the bob nearer its centre, or use a rod that expands more",
                    num(before, 3),
                    args.part
                ),
            )
        })
    };
    let compensated = match kind.as_deref() {
        None => None,
        Some("gridiron") => {
            let (steel, brass) = (
                Material::named("steel").expect("in the table"),
                Material::named("brass").expect("in the table"),
            );
            let (compensated, brass_length) =
                design.with_gridiron(&steel, &brass).ok_or_else(|| {
                    CliError::flag(
                        "--compensator",
                        "no steel and brass gridiron of this rod's drop cancels the coefficient (the design needs a rod hanging from the pivot)",
                    )
                })?;
            result.compensator = Some("gridiron".into());
            result.brass_length_m = Some(brass_length);
            Some(compensated)
        }
        Some("mercury") | Some("mercury jar") | Some("jar") => {
            let bob = part_index(&design, &args.part)?;
            let jar = table_material(
                "--jar-material",
                args.jar_material.as_deref().unwrap_or("glass"),
            )?;
            if jar.liquid {
                return Err(CliError::flag("--jar-material", "a jar must be a solid"));
            }
            let diameter = match &args.jar_diameter {
                Some(t) => positive_length("--jar-diameter", t)?,
                None => match design.parts()[bob].shape {
                    Shape::Cylinder { diameter, .. } => diameter,
                    _ => 0.06,
                },
            };
            let wall = match &args.jar_wall {
                Some(t) => positive_length("--jar-wall", t)?,
                None => 0.004,
            };
            let (compensated, height) = design
                .with_mercury_jar(bob, &jar, diameter, wall)
                .ok_or_else(|| {
                    CliError::flag(
                        "--compensator",
                        format!(
                            "no mercury up to 0.5 m deep in a {} mm {} jar cancels this design's coefficient (the '{}' must rest on a nut or stirrup, and the jar be wider than its walls and the rod)",
                            num(diameter * 1e3, 4),
                            jar.name,
                            args.part
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
                "--compensator",
                if name == "collar" { "brass" } else { name },
            )
            .map_err(|_| {
                CliError::flag(
                    "--compensator",
                    format!(
                        "'{name}' is neither gridiron, mercury, collar nor a material of the table ({})",
                        Material::names().join(", ")
                    ),
                )
            })?;
            if material.liquid {
                return Err(CliError::flag(
                    "--compensator",
                    "a liquid goes in a jar: give --compensator mercury",
                ));
            }
            let bob = part_index(&design, &args.part)?;
            if let Some(e) = lifting("a tube") {
                return Err(e);
            }
            let rod_diameter = design
                .rod_index()
                .and_then(|i| match design.parts()[i].shape {
                    Shape::Cylinder { diameter, .. } => Some(diameter),
                    _ => None,
                })
                .ok_or_else(|| CliError::flag("--design", "has no rod hanging from the pivot"))?;
            let bore = match &args.tube_bore {
                Some(t) => positive_length("--tube-bore", t)?,
                None => rod_diameter + 1e-3,
            };
            let diameter = match &args.tube_diameter {
                Some(t) => positive_length("--tube-diameter", t)?,
                None => bore + 3e-3,
            };
            if diameter <= bore {
                // Said of the flag the user gave (the other is derived).
                let flag = if args.tube_diameter.is_some() {
                    "--tube-diameter"
                } else {
                    "--tube-bore"
                };
                return Err(CliError::flag(
                    flag,
                    format!(
                        "the tube's bore ({} mm) must be less than its diameter ({} mm)",
                        num(bore * 1e3, 4),
                        num(diameter * 1e3, 4)
                    ),
                ));
            }
            let (compensated, length) = design
                .with_compensating_tube(bob, material.clone(), diameter, bore)
                .ok_or_else(|| {
                    CliError::flag(
                        "--compensator",
                        format!(
                            "no {} tube up to 1.5 m cancels this design's coefficient (the '{}' must rest on a nut placed on the rod, and the tube must expand more than the rod)",
                            material.name, args.part
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
    match (&args.write, &compensated) {
        (Some(path), Some(c)) => {
            let title = format!(
                "{} with a {} sized by `pendulum compensate`.",
                args.design.display(),
                match (&result.compensator, result.tube_length_m) {
                    (Some(m), Some(_)) => format!("{m} tube"),
                    (Some(m), None) => m.clone(),
                    (None, _) => "compensator".into(),
                }
            );
            let text = crate::design::to_toml(c, read.thread, &title);
            let mut file = AtomicFile::create(path, "--write")?;
            file.writer()
                .write_all(text.as_bytes())
                .map_err(|e| file.write_error(e))?;
            result.written_to = Some(file.commit()?);
        }
        (Some(_), None) => {
            return Err(CliError::flag(
                "--write",
                "writes a compensated design: give --compensator",
            ))
        }
        _ => {}
    }
    if args.json {
        return output::json(&result);
    }
    render(&result, &args.part)
}

/// The summary for people.
fn render(result: &CompensateJson, part: &str) -> Result<String, CliError> {
    let before = result.temperature_coefficient_s_per_day_per_c;
    let mut s = Summary::default();
    s.row(
        "Temperature",
        format!(
            "{} s/day per °C as designed ({} as it warms)",
            num(before, 4),
            if before < 0.0 { "losing" } else { "gaining" }
        ),
    );
    if let (Some(name), Some(l)) = (&result.compensator, result.tube_length_m) {
        s.row(
            "Compensator",
            format!(
                "a {} of {name} {} mm long ({} mm outside, {} mm bore) under the {part}, the rod {} mm longer and the nut as much lower",
                if l < 0.05 { "collar" } else { "tube" },
                num(l * 1e3, 5),
                num(result.tube_diameter_m.unwrap_or(0.0) * 1e3, 4),
                num(result.tube_bore_m.unwrap_or(0.0) * 1e3, 4),
                num(l * 1e3, 5)
            ),
        );
    }
    if let Some(b) = result.brass_length_m {
        s.row(
            "Gridiron",
            format!(
                "steel and brass rods in series, {} mm of brass against the drop's steel and as much again",
                num(b * 1e3, 5)
            ),
        );
    }
    if let (Some(h), Some(jar), Some(d), Some(w)) = (
        result.mercury_height_m,
        &result.jar_material,
        result.jar_diameter_m,
        result.jar_wall_m,
    ) {
        s.row(
            "Mercury jar",
            format!(
                "{} mm of mercury ({} kg) in a {jar} jar {} mm across with {} mm walls, in place of the {part}",
                num(h * 1e3, 5),
                num(result.mercury_mass_kg.unwrap_or(f64::NAN), 4),
                num(d * 1e3, 4),
                num(w * 1e3, 3)
            ),
        );
    }
    if let (Some(after), Some(l)) = (
        result.compensated_coefficient_s_per_day_per_c,
        result.compensated_equivalent_length_m,
    ) {
        s.row("Then", format!("{} s/day per °C", num(after, 3)));
        let change = l - result.equivalent_length_m;
        if change.abs() > 1e-6 {
            s.row(
                "Length",
                format!(
                    "equivalent length {} m (was {}): regulate it to its beat",
                    num(l, 7),
                    num(result.equivalent_length_m, 7)
                ),
            );
        }
    }
    if let Some(w) = &result.written_to {
        s.row("Written", w.clone());
    }
    Ok(s.render())
}
