//! Reading a pendulum design (a TOML file of parts) into the library's
//! `CompoundPendulum`. One reader for every command that takes `--design`.
//!
//! ```toml
//! [[part]]
//! name = "rod"
//! shape = "rod"          # rod, cylinder, tube, disc, lens, sphere, ring, point
//! material = "steel"     # or { density = 700, expansion = 4.9e-6 } (kg/m³, 1/K;
//!                        # add liquid = true for a liquid, whose expansion is
//!                        # its volume's and which rests on its jar's bottom)
//! length = "1000 mm"     # a number is metres
//! diameter = "8 mm"
//! centre = "500 mm"      # below the pivot; or rests_on = "nut"
//! ```
//!
//! The rating nut may state its thread, `pitch = "0.7 mm"` or `tpi = 36`,
//! and `divisions = 20` when it is divided: the datasheet and `regulate`
//! then speak in turns and divisions.

use crate::error::CliError;
use crate::units::{parse_quantity, Dimension};
use pendulum_theory::compound::{CompoundPendulum, Material, Part, Placement, Shape};
use std::io::Read;
use std::path::Path;

/// The thread of a design's rating nut.
#[derive(Clone, Copy, Debug)]
pub struct Thread {
    /// The index of the threaded part.
    pub part: usize,
    /// Its pitch, m per turn.
    pub pitch: f64,
    /// The divisions engraved round it, if any.
    pub divisions: Option<u32>,
}

/// A design as read: the pendulum, and its nut's thread when stated.
pub struct Design {
    /// The pendulum.
    pub pendulum: CompoundPendulum,
    /// The rating nut's thread.
    pub thread: Option<Thread>,
}

/// The most bytes a design file may have.
pub const MAX_DESIGN_BYTES: u64 = 4 << 20;
/// The most parts a design may have.
pub const MAX_PARTS: usize = 1000;

/// The design in `path`, checked; every refusal names the file, the part
/// and the field.
pub fn read(path: &Path) -> Result<CompoundPendulum, CliError> {
    Ok(read_design(path)?.pendulum)
}

/// The design in `path` with its nut's thread.
pub fn read_design(path: &Path) -> Result<Design, CliError> {
    let file = path.display().to_string();
    let fail = |what: String| CliError::other(format!("{file}: {what}"));
    let mut bytes = Vec::new();
    crate::file::open_input(path)
        .and_then(|f| f.take(MAX_DESIGN_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| fail(format!("cannot read it: {e}")))?;
    if bytes.len() as u64 > MAX_DESIGN_BYTES {
        return Err(fail(format!(
            "is larger than the {} MiB a design file may have",
            MAX_DESIGN_BYTES >> 20
        )));
    }
    let text = String::from_utf8(bytes)
        .map_err(|_| fail("is not a text file (a design is TOML, in UTF-8)".to_string()))?;
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
    if parts.len() > MAX_PARTS {
        return Err(fail(format!(
            "has {} parts; a design may have at most {MAX_PARTS}",
            parts.len()
        )));
    }
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
    let mut thread: Option<Thread> = None;
    for (p, name) in parts.iter().zip(&names) {
        let bad = |field: &str, what: String| fail(format!("part '{name}': {field}: {what}"));
        let t = p
            .as_table()
            .ok_or_else(|| bad("part", "must be a table".into()))?;
        const KNOWN: [&str; 20] = [
            "pitch",
            "tpi",
            "divisions",
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
        // The nut's thread.
        let pitch = match (size("pitch", Dimension::Length)?, t.get("tpi")) {
            (Some(_), Some(_)) => return Err(bad("tpi", "give pitch or tpi, not both".into())),
            (Some(p), None) => Some(("pitch", p)),
            (None, Some(v)) => {
                let tpi = v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
                match tpi {
                    Some(n) if n > 0.0 && n.is_finite() => Some(("tpi", 0.0254 / n)),
                    _ => {
                        return Err(bad(
                            "tpi",
                            "must be a positive number of threads per inch".into(),
                        ))
                    }
                }
            }
            (None, None) => None,
        };
        let divisions = match t.get("divisions") {
            None => None,
            Some(toml::Value::Integer(d)) if (1..=10_000).contains(d) => Some(*d as u32),
            Some(_) => {
                return Err(bad(
                    "divisions",
                    "must be a whole number from 1 to 10000".into(),
                ))
            }
        };
        match (pitch, divisions) {
            (Some((field, p)), _) => {
                if !(p > 0.0 && p.is_finite()) {
                    return Err(bad(field, format!("must be positive, got {p} m")));
                }
                if thread.is_some() {
                    return Err(bad(
                        field,
                        "only one part (the rating nut) has a thread".into(),
                    ));
                }
                if t.get("rests_on").is_some() {
                    return Err(bad(field, "the threaded part is placed by its centre on the rod, not resting on another".into()));
                }
                thread = Some(Thread {
                    part: out.len(),
                    pitch: p,
                    divisions,
                });
            }
            (None, Some(_)) => {
                return Err(bad(
                    "divisions",
                    "give the thread's pitch or tpi too".into(),
                ))
            }
            (None, None) => {}
        }
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
                    liquid: match m.get("liquid") {
                        None => false,
                        Some(toml::Value::Boolean(b)) => *b,
                        Some(_) => {
                            return Err(bad("material", "liquid must be true or false".into()))
                        }
                    },
                }
            }
            None if shape == Shape::Point => Material {
                name: "point".into(),
                density: 0.0,
                expansion: 0.0,
                liquid: false,
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
    let pendulum = CompoundPendulum::new(out)
        .map_err(|e| fail(format!("part '{}': {}: {}", e.part, e.field, e.message)))?;
    Ok(Design { pendulum, thread })
}

/// A design as the TOML [`read`] takes back: sizes in millimetres to the
/// nanometre, table materials by name, others (a gridiron's equivalent
/// rod, a user's) by density and expansion.
pub fn to_toml(design: &CompoundPendulum, thread: Option<Thread>, title: &str) -> String {
    let mm = |v: f64| -> String {
        let t = format!("{:.6}", v * 1e3);
        let t = t.trim_end_matches('0').trim_end_matches('.');
        format!("\"{t} mm\"")
    };
    let mut out = String::new();
    for line in title.lines() {
        out.push_str(&format!("# {line}\n"));
    }
    let parts = design.parts();
    for (i, p) in parts.iter().enumerate() {
        out.push_str("\n[[part]]\n");
        out.push_str(&format!("name = {}\n", quoted(&p.name)));
        let mut fields: Vec<(&str, String)> = Vec::new();
        let shape = match p.shape {
            Shape::Cylinder {
                length,
                diameter,
                bore,
            } => {
                fields.push(("length", mm(length)));
                fields.push(("diameter", mm(diameter)));
                if bore > 0.0 {
                    fields.push(("bore", mm(bore)));
                }
                "cylinder"
            }
            Shape::Disc {
                diameter,
                thickness,
            }
            | Shape::Lens {
                diameter,
                thickness,
            } => {
                fields.push(("diameter", mm(diameter)));
                fields.push(("thickness", mm(thickness)));
                if matches!(p.shape, Shape::Disc { .. }) {
                    "disc"
                } else {
                    "lens"
                }
            }
            Shape::Sphere { diameter } => {
                fields.push(("diameter", mm(diameter)));
                "sphere"
            }
            Shape::Ring {
                outer,
                inner,
                thickness,
            } => {
                fields.push(("outer", mm(outer)));
                fields.push(("inner", mm(inner)));
                fields.push(("thickness", mm(thickness)));
                "ring"
            }
            Shape::Point => {
                fields.push(("mass", format!("\"{} kg\"", p.point_mass)));
                "point"
            }
        };
        out.push_str(&format!("shape = \"{shape}\"\n"));
        if p.shape != Shape::Point {
            let m = &p.material;
            let material = match Material::named(&m.name) {
                Some(t) if t == *m => quoted(&m.name),
                _ => format!(
                    "{{ name = {}, density = {:?}, expansion = {:?}{} }}",
                    quoted(&m.name),
                    m.density,
                    m.expansion,
                    if m.liquid { ", liquid = true" } else { "" }
                ),
            };
            out.push_str(&format!("material = {material}\n"));
        }
        for (key, value) in fields {
            out.push_str(&format!("{key} = {value}\n"));
        }
        match p.placement {
            Placement::Centre(c) => out.push_str(&format!("centre = {}\n", mm(c))),
            Placement::RestsOn(j) => {
                out.push_str(&format!("rests_on = {}\n", quoted(&parts[j].name)))
            }
        }
        if p.massless {
            out.push_str("massless = true\n");
        }
        if let Some(t) = thread.filter(|t| t.part == i) {
            out.push_str(&format!("pitch = {}\n", mm(t.pitch)));
            if let Some(d) = t.divisions {
                out.push_str(&format!("divisions = {d}\n"));
            }
        }
    }
    out
}

/// A TOML basic string.
fn quoted(text: &str) -> String {
    let mut s = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            c if c.is_control() => s.push_str(&format!("\\u{:04X}", c as u32)),
            c => s.push(c),
        }
    }
    s.push('"');
    s
}
