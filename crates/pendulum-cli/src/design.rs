//! Reading a pendulum design (a TOML file of parts) into the library's
//! `CompoundPendulum`. One reader for every command that takes `--design`.
//!
//! ```toml
//! [[part]]
//! name = "rod"
//! shape = "rod"          # rod, cylinder, tube, disc, lens, sphere, ring, point
//! material = "steel"     # or { density = 700, expansion = 4.9e-6 } (kg/m³, 1/K)
//! length = "1000 mm"     # a number is metres
//! diameter = "8 mm"
//! centre = "500 mm"      # below the pivot; or rests_on = "nut"
//! ```

use crate::error::CliError;
use crate::units::{parse_quantity, Dimension};
use pendulum_theory::compound::{CompoundPendulum, Material, Part, Placement, Shape};
use std::path::Path;

/// The design in `path`, checked; every refusal names the file, the part
/// and the field.
pub fn read(path: &Path) -> Result<CompoundPendulum, CliError> {
    let file = path.display().to_string();
    let fail = |what: String| CliError::other(format!("{file}: {what}"));
    let text = std::fs::read_to_string(path).map_err(|e| fail(format!("cannot read it: {e}")))?;
    let table: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        let first = e.message().lines().next().unwrap_or("").to_string();
        let line = e
            .span()
            .map(|s| text[..s.start.min(text.len())].lines().count().max(1));
        match line {
            Some(l) => fail(format!("line {l}: not valid TOML: {first}")),
            None => fail(format!("not valid TOML: {first}")),
        }
    })?;
    for key in table.keys() {
        if key != "part" && key != "pendulum" {
            return Err(fail(format!(
                "unknown section '{key}'; a design has [[part]] sections"
            )));
        }
    }
    let parts = table
        .get("part")
        .and_then(|p| p.as_array())
        .ok_or_else(|| fail("no [[part]] sections".into()))?;
    let mut names: Vec<String> = Vec::new();
    for (i, p) in parts.iter().enumerate() {
        let name = p
            .get("name")
            .and_then(|n| n.as_str())
            .map_or_else(|| format!("part {}", i + 1), str::to_string);
        if names.contains(&name) {
            return Err(fail(format!("part '{name}': name: used twice")));
        }
        names.push(name);
    }
    let mut out = Vec::new();
    for (p, name) in parts.iter().zip(&names) {
        let bad = |field: &str, what: String| fail(format!("part '{name}': {field}: {what}"));
        let t = p
            .as_table()
            .ok_or_else(|| bad("part", "must be a table".into()))?;
        const KNOWN: [&str; 17] = [
            "name",
            "shape",
            "material",
            "length",
            "diameter",
            "bore",
            "thickness",
            "outer",
            "inner",
            "mass",
            "centre",
            "rests_on",
            "massless",
            "center",
            "brass_length",
            "steel",
            "brass",
        ];
        for key in t.keys() {
            if !KNOWN.contains(&key.as_str()) {
                return Err(bad(key, "unknown field".into()));
            }
        }
        let size = |field: &'static str, dimension: Dimension| -> Result<Option<f64>, CliError> {
            match t.get(field) {
                None => Ok(None),
                Some(toml::Value::Float(v)) => Ok(Some(*v)),
                Some(toml::Value::Integer(v)) => Ok(Some(*v as f64)),
                Some(toml::Value::String(s)) => parse_quantity(s, dimension)
                    .map(Some)
                    .map_err(|e| bad(field, e.to_string())),
                Some(_) => Err(bad(
                    field,
                    "must be a number or a quantity such as \"8 mm\"".into(),
                )),
            }
        };
        let need = |field: &'static str| -> Result<f64, CliError> {
            size(field, Dimension::Length)?.ok_or_else(|| bad(field, "missing".into()))
        };
        let shape_name = t.get("shape").and_then(|s| s.as_str()).ok_or_else(|| {
            bad(
                "shape",
                "missing (rod, cylinder, tube, disc, lens, sphere, ring or point)".into(),
            )
        })?;
        let shape = match shape_name {
            "rod" | "cylinder" | "tube" | "gridiron" => Shape::Cylinder {
                length: need("length")?,
                diameter: need("diameter")?,
                bore: size("bore", Dimension::Length)?.unwrap_or(0.0),
            },
            "disc" => Shape::Disc {
                diameter: need("diameter")?,
                thickness: need("thickness")?,
            },
            "lens" => Shape::Lens {
                diameter: need("diameter")?,
                thickness: need("thickness")?,
            },
            "sphere" => Shape::Sphere {
                diameter: need("diameter")?,
            },
            "ring" => Shape::Ring {
                outer: need("outer")?,
                inner: size("inner", Dimension::Length)?.unwrap_or(0.0),
                thickness: need("thickness")?,
            },
            "point" => Shape::Point,
            other => {
                return Err(bad(
                    "shape",
                    format!(
                    "'{other}' is not one of rod, cylinder, tube, disc, lens, sphere, ring, point"
                ),
                ))
            }
        };
        // A gridiron: its drop is `length`, its rods `diameter` thick, of
        // `steel` and `brass` (default steel and brass), `brass_length` of
        // brass in the series.
        if shape_name == "gridiron" {
            let metal = |key: &'static str, default: &str| -> Result<Material, CliError> {
                let name = t.get(key).and_then(|v| v.as_str()).unwrap_or(default);
                Material::named(name)
                    .ok_or_else(|| bad(key, format!("'{name}' is not in the table")))
            };
            let (steel, brass) = (metal("steel", "steel")?, metal("brass", "brass")?);
            let Shape::Cylinder {
                length, diameter, ..
            } = shape
            else {
                unreachable!("a gridiron is read as a cylinder");
            };
            let brass_length = need("brass_length")?;
            let centre = size("centre", Dimension::Length)?.ok_or_else(|| {
                bad(
                    "centre",
                    "missing (half the drop, for a gridiron hanging from the pivot)".into(),
                )
            })?;
            out.push(Part {
                name: name.clone(),
                shape,
                material: pendulum_theory::compound::gridiron(
                    length,
                    brass_length,
                    diameter,
                    &steel,
                    &brass,
                ),
                point_mass: 0.0,
                placement: Placement::Centre(centre),
                massless: false,
            });
            continue;
        }
        let material = match t.get("material") {
            Some(toml::Value::String(m)) => Material::named(m).ok_or_else(|| {
                bad(
                    "material",
                    format!(
                        "'{m}' is not in the table ({}); give {{ density = …, expansion = … }}",
                        Material::names().join(", ")
                    ),
                )
            })?,
            Some(toml::Value::Table(m)) => {
                let number = |key: &str| -> Result<f64, CliError> {
                    match m.get(key) {
                        Some(toml::Value::Float(v)) => Ok(*v),
                        Some(toml::Value::Integer(v)) => Ok(*v as f64),
                        _ => Err(bad("material", format!("needs a number '{key}'"))),
                    }
                };
                Material {
                    name: m
                        .get("name")
                        .and_then(|n| n.as_str())
                        .unwrap_or("user-defined")
                        .to_string(),
                    density: number("density")?,
                    expansion: number("expansion")?,
                }
            }
            None if shape == Shape::Point => Material {
                name: "point".into(),
                density: 0.0,
                expansion: 0.0,
            },
            _ => return Err(bad("material", "missing".into())),
        };
        let point_mass = if shape == Shape::Point {
            size("mass", Dimension::Mass)?
                .ok_or_else(|| bad("mass", "missing (a point has a mass, e.g. \"2 kg\")".into()))?
        } else {
            0.0
        };
        let centre = match size("centre", Dimension::Length)? {
            Some(c) => Some(c),
            None => size("center", Dimension::Length)?,
        };
        let placement = match (centre, t.get("rests_on")) {
            (Some(c), None) => Placement::Centre(c),
            (None, Some(toml::Value::String(on))) => Placement::RestsOn(
                names
                    .iter()
                    .position(|n| n == on)
                    .ok_or_else(|| bad("rests_on", format!("no part is named '{on}'")))?,
            ),
            (Some(_), Some(_)) => {
                return Err(bad(
                    "centre",
                    "give either centre or rests_on, not both".into(),
                ))
            }
            _ => {
                return Err(bad(
                    "centre",
                    "missing (or rests_on = \"another part\")".into(),
                ))
            }
        };
        let massless = t.get("massless").and_then(|m| m.as_bool()).unwrap_or(false);
        out.push(Part {
            name: name.clone(),
            shape,
            material,
            point_mass,
            placement,
            massless,
        });
    }
    CompoundPendulum::new(out)
        .map_err(|e| fail(format!("part '{}': {}: {}", e.part, e.field, e.message)))
}
