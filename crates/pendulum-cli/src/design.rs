//! Reading a pendulum design (a TOML file of parts) into the library's
//! `CompoundPendulum`: the file and its TOML here, the parts by the
//! library's [`pendulum_theory::compound::description`]. One reader for
//! every command that takes `--design`; and writing a design back.
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
use pendulum_theory::compound::description::{design, Unit};
pub use pendulum_theory::compound::description::{Design, Thread};
use pendulum_theory::compound::{CompoundPendulum, End, Material, Placement, Shape};
use std::io::Read;
use std::path::Path;

/// The most bytes a design file may have.
pub const MAX_DESIGN_BYTES: u64 = 4 << 20;

/// The design in `path`, checked; every refusal names the file, the part
/// and the field.
pub fn read(path: &Path) -> Result<CompoundPendulum, CliError> {
    Ok(read_design(path)?.pendulum)
}

/// The design in `path` with its nut's thread: the file read as TOML
/// here, the parts checked and built by the library.
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
    let value = serde_json::to_value(&table).map_err(|e| fail(format!("not readable: {e}")))?;
    let quantity = |text: &str, unit: Unit| {
        let dimension = match unit {
            Unit::Length => Dimension::Length,
            Unit::Mass => Dimension::Mass,
            Unit::Time => Dimension::Time,
        };
        parse_quantity(text, dimension).map_err(|e| e.to_string())
    };
    design(&value, &quantity).map_err(|r| fail(r.to_string()))
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
        // Each size in mm (a point's mass in kg); a solid cylinder has no
        // bore to write.
        let fields: Vec<(&str, String)> = p
            .sizes()
            .into_iter()
            .filter(|&(key, v)| !(key == "bore" && v <= 0.0))
            .map(|(key, v)| match key {
                "mass" => (key, format!("\"{v} kg\"")),
                _ => (key, mm(v)),
            })
            .collect();
        let shape = p.shape.name();
        out.push_str(&format!("shape = \"{shape}\"\n"));
        if p.shape != Shape::Point {
            let m = &p.material;
            let material = match Material::named(&m.name) {
                Some(t) if t == *m => quoted(&m.name),
                _ => format!(
                    "{{ name = {}, density = {:?}, expansion = {:?}{}{}{}{} }}",
                    quoted(&m.name),
                    m.density,
                    m.expansion,
                    if m.liquid { ", liquid = true" } else { "" },
                    m.modulus
                        .map_or(String::new(), |e| format!(", modulus = {e:?}")),
                    m.modulus_coefficient
                        .map_or(String::new(), |b| format!(", modulus_coefficient = {b:?}")),
                    m.moisture_expansion
                        .map_or(String::new(), |w| format!(", moisture_expansion = {w:?}")),
                ),
            };
            out.push_str(&format!("material = {material}\n"));
        }
        for (key, value) in fields {
            out.push_str(&format!("{key} = {value}\n"));
        }
        match p.placement {
            // A spring hangs from the pivot: its centre follows.
            Placement::Centre(_) if p.shape.is_spring() => {}
            Placement::Centre(c) => out.push_str(&format!("centre = {}\n", mm(c))),
            Placement::RestsOn(j) => {
                out.push_str(&format!("rests_on = {}\n", quoted(&parts[j].name)))
            }
            Placement::Held { part, end, height } => {
                out.push_str(&format!("rests_on = {}\n", quoted(&parts[part].name)));
                out.push_str(&format!("support_height = {}\n", mm(height)));
                if end == End::Bottom {
                    out.push_str("rests_on_end = \"bottom\"\n");
                }
            }
        }
        if p.massless {
            out.push_str("massless = true\n");
        }
        if p.time_constant > 0.0 {
            out.push_str(&format!("time_constant = \"{} s\"\n", p.time_constant));
        }
        if p.moisture_time_constant > 0.0 {
            out.push_str(&format!(
                "moisture_time_constant = \"{} s\"\n",
                p.moisture_time_constant
            ));
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
