//! `pendulum compensate`: a design's temperature coefficient, and the
//! compensating tube that cancels it.

use super::common;
use crate::args::CompensateArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::units::Dimension;
use pendulum_theory::compound::{Material, Shape};
use serde::Serialize;

#[derive(Serialize)]
struct CompensateJson {
    /// The design as given: s/day per °C (negative: losing as it warms).
    temperature_coefficient_s_per_day_per_c: f64,
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
    /// With the tube, the rod lengthened and the nut lowered by its length.
    #[serde(skip_serializing_if = "Option::is_none")]
    compensated_coefficient_s_per_day_per_c: Option<f64>,
}

pub fn run(args: &CompensateArgs) -> Result<String, CliError> {
    let design = crate::design::read(&args.design)?;
    let before = design.temperature_coefficient();
    let mut result = CompensateJson {
        temperature_coefficient_s_per_day_per_c: before,
        compensator: None,
        tube_length_m: None,
        tube_diameter_m: None,
        tube_bore_m: None,
        brass_length_m: None,
        compensated_coefficient_s_per_day_per_c: None,
    };
    if args.compensator.as_deref() == Some("gridiron") {
        let (steel, brass) = (
            Material::named("steel").expect("in the table"),
            Material::named("brass").expect("in the table"),
        );
        let (compensated, brass_length) = design.with_gridiron(&steel, &brass).ok_or_else(|| {
            CliError::flag(
                "--compensator",
                "no steel and brass gridiron of this rod's drop cancels the coefficient (the design needs a rod hanging from the pivot)",
            )
        })?;
        result.compensator = Some("gridiron".into());
        result.brass_length_m = Some(brass_length);
        result.compensated_coefficient_s_per_day_per_c =
            Some(compensated.temperature_coefficient());
    } else if let Some(name) = &args.compensator {
        let material = Material::named(name).ok_or_else(|| {
            CliError::flag(
                "--compensator",
                format!(
                    "'{name}' is not in the table ({})",
                    Material::names().join(", ")
                ),
            )
        })?;
        let bob = design
            .parts()
            .iter()
            .position(|p| p.name == args.part)
            .ok_or_else(|| {
                CliError::flag(
                    "--part",
                    format!("the design has no part named '{}'", args.part),
                )
            })?;
        let rod_diameter = design
            .rod_index()
            .and_then(|i| match design.parts()[i].shape {
                Shape::Cylinder { diameter, .. } => Some(diameter),
                _ => None,
            })
            .ok_or_else(|| CliError::flag("--design", "has no rod hanging from the pivot"))?;
        let bore = match &args.tube_bore {
            Some(t) => common::quantity("--tube-bore", t, Dimension::Length)?,
            None => rod_diameter + 1e-3,
        };
        let diameter = match &args.tube_diameter {
            Some(t) => common::quantity("--tube-diameter", t, Dimension::Length)?,
            None => bore + 3e-3,
        };
        if !(bore > 0.0 && diameter > bore) {
            return Err(CliError::flag(
                "--tube-diameter",
                "must be larger than the bore",
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
        result.compensated_coefficient_s_per_day_per_c =
            Some(compensated.temperature_coefficient());
    }
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    s.row(
        "Temperature",
        format!(
            "{} s/day per °C as designed ({} as it warms)",
            num(before, 4),
            if before < 0.0 { "losing" } else { "gaining" }
        ),
    );
    if let (Some(name), Some(l), Some(after)) = (
        &result.compensator,
        result.tube_length_m,
        result.compensated_coefficient_s_per_day_per_c,
    ) {
        s.row(
            "Compensator",
            format!(
                "a tube of {name} {} mm long ({} mm outside, {} mm bore) under the {}, the rod {} mm longer and the nut as much lower",
                num(l * 1e3, 5),
                num(result.tube_diameter_m.unwrap_or(0.0) * 1e3, 4),
                num(result.tube_bore_m.unwrap_or(0.0) * 1e3, 4),
                args.part,
                num(l * 1e3, 5)
            ),
        )
        .row("Then", format!("{} s/day per °C", num(after, 3)));
    }
    if let (Some(b), Some(after)) = (
        result.brass_length_m,
        result.compensated_coefficient_s_per_day_per_c,
    ) {
        s.row(
            "Gridiron",
            format!(
                "steel and brass rods in series, {} mm of brass against the drop's steel and as much again",
                num(b * 1e3, 5)
            ),
        )
        .row("Then", format!("{} s/day per °C", num(after, 3)));
    }
    Ok(s.render())
}
