//! A pendulum design described as parts, as a front end reads it (the
//! command line from a TOML file, Python from a list of dicts), checked
//! and built into a [`CompoundPendulum`]: which fields a part has, the
//! shapes and materials by name, the defaults (no bore, a gridiron of
//! steel and brass, not massless), the rating nut's thread. Sizes are
//! numbers in SI units, or text the front end's `quantity` parser reads
//! ("8 mm").
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
//! A part resting on another may be held at a point of its own:
//! `support_height = "60 mm"` above its bottom (a bob on a collar at its
//! centre), on the holder's `rests_on_end = "bottom"` (a flange at a
//! tube's lower end; default its top); `hangs_from = "tube"` hangs it by
//! its top from the top of that part (a tube inside or around another).
//!
//! A part that takes time to reach the air's temperature (a zinc tube, a
//! heavy bob, a jar of mercury) may give its thermal time constant,
//! `time_constant = "2 h"`: it follows the air as a first-order lag. A
//! wooden part takes up the air's moisture more slowly still (days through
//! a varnish): `moisture_time_constant = "3 d"`. A material of the user's
//! that takes up water gives `moisture_expansion`, its growth along its
//! length per percentage point of moisture content (wood's is in the
//! table).
//!
//! The rating nut may state its thread, `pitch = "0.7 mm"` or `tpi = 36`,
//! and `divisions = 20` when it is divided.

use super::{CompoundPendulum, End, Material, Part, Placement, Shape};
use crate::analysis::Refusal;
use serde_json::{Map, Value};

/// The thread of a design's rating nut.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Thread {
    /// The index of the threaded part.
    pub part: usize,
    /// Its pitch, m per turn.
    pub pitch: f64,
    /// The divisions engraved round it, if any.
    pub divisions: Option<u32>,
}

/// A design as read: the pendulum, and its nut's thread when stated.
#[derive(Clone, Debug)]
pub struct Design {
    /// The pendulum.
    pub pendulum: CompoundPendulum,
    /// The rating nut's thread.
    pub thread: Option<Thread>,
}

/// The fields that give a part's size, each of some shapes only.
const SHAPE_FIELDS: [&str; 11] = [
    "length",
    "diameter",
    "bore",
    "thickness",
    "width",
    "outer",
    "inner",
    "mass",
    "brass_length",
    "steel",
    "brass",
];

/// The most parts a design may have.
pub const MAX_PARTS: usize = 1000;

/// What a size given as text is: the front end's parser reads it in this
/// unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Metres.
    Length,
    /// Kilograms.
    Mass,
    /// Seconds.
    Time,
}

/// Reads a size given as text (`"8 mm"`) in SI units, or says why not.
pub type QuantityParser<'a> = &'a dyn Fn(&str, Unit) -> Result<f64, String>;

/// The design described by `value` (a table with an array `part` of part
/// tables), checked; every refusal names the part and the field. Text
/// sizes are read by `quantity`.
pub fn design(value: &Value, quantity: QuantityParser) -> Result<Design, Refusal> {
    let parts = part_tables(value)?;
    let names = part_names(parts)?;
    let mut out = Vec::new();
    let mut thread: Option<Thread> = None;
    for (p, name) in parts.iter().zip(&names) {
        let fields = PartFields::new(p, name, quantity)?;
        if let Some(stated) = fields.thread(out.len(), thread.is_some())? {
            thread = Some(stated);
        }
        out.push(fields.part(&names)?);
    }
    let pendulum = CompoundPendulum::new(out)
        .map_err(|e| Refusal::data(format!("part '{}': {}: {}", e.part, e.field, e.message)))?;
    Ok(Design { pendulum, thread })
}

/// The part tables of the design `value`: its array `part`, refused when
/// `value` is not a table, has a section other than `part` and
/// `pendulum`, or more than [`MAX_PARTS`] parts.
fn part_tables(value: &Value) -> Result<&[Value], Refusal> {
    let table = value
        .as_object()
        .ok_or_else(|| Refusal::data("a design is a table of [[part]] sections"))?;
    for key in table.keys() {
        if key != "part" && key != "pendulum" {
            return Err(Refusal::data(format!(
                "unknown section '{key}'; a design has [[part]] sections"
            )));
        }
    }
    let parts = table
        .get("part")
        .and_then(|p| p.as_array())
        .map(Vec::as_slice)
        .ok_or_else(|| Refusal::data("no [[part]] sections"))?;
    if parts.len() > MAX_PARTS {
        return Err(Refusal::data(format!(
            "has {} parts; a design may have at most {MAX_PARTS}",
            parts.len()
        )));
    }
    Ok(parts)
}

/// Each part's name, as given or `part N` (counted from 1) for a part
/// without one; a name used twice is refused.
fn part_names(parts: &[Value]) -> Result<Vec<String>, Refusal> {
    let mut names: Vec<String> = Vec::new();
    for (i, p) in parts.iter().enumerate() {
        let name = p
            .get("name")
            .and_then(|n| n.as_str())
            .map_or_else(|| format!("part {}", i + 1), str::to_string);
        if names.contains(&name) {
            return Err(Refusal::data(format!("part '{name}': name: used twice")));
        }
        names.push(name);
    }
    Ok(names)
}

/// The refusal of part `name`'s field `field`, saying `what` is wrong:
/// `part 'NAME': FIELD: WHAT`.
fn part_refusal(name: &str, field: &str, what: String) -> Refusal {
    Refusal::data(format!("part '{name}': {field}: {what}"))
}

/// One part's table as read, with its name and the reader of its sizes
/// given as text: what the steps that read a part share.
struct PartFields<'a> {
    /// The part's table of fields.
    table: &'a Map<String, Value>,
    /// Its name, as given or `part N`.
    name: &'a str,
    /// Reads a size given as text in SI units.
    quantity: QuantityParser<'a>,
}

impl<'a> PartFields<'a> {
    /// The fields of the part `p` named `name`; refused unless it is a
    /// table of known fields.
    fn new(p: &'a Value, name: &'a str, quantity: QuantityParser<'a>) -> Result<Self, Refusal> {
        let table = p
            .as_object()
            .ok_or_else(|| part_refusal(name, "part", "must be a table".into()))?;
        // Besides the sizes of the shapes ([`SHAPE_FIELDS`]).
        const KNOWN: [&str; 15] = [
            "pitch",
            "tpi",
            "divisions",
            "name",
            "shape",
            "material",
            "centre",
            "rests_on",
            "support_height",
            "rests_on_end",
            "hangs_from",
            "massless",
            "time_constant",
            "moisture_time_constant",
            "center",
        ];
        for key in table.keys() {
            if !KNOWN.contains(&key.as_str()) && !SHAPE_FIELDS.contains(&key.as_str()) {
                return Err(part_refusal(name, key, "unknown field".into()));
            }
        }
        Ok(Self {
            table,
            name,
            quantity,
        })
    }

    /// The refusal of this part's field `field`, saying `what` is wrong.
    fn bad(&self, field: &str, what: String) -> Refusal {
        part_refusal(self.name, field, what)
    }

    /// The size `field` in SI units (text read as a `dimension`), or
    /// `None` when not given; refused when it is neither a number nor a
    /// quantity the reader takes.
    fn size(&self, field: &'static str, dimension: Unit) -> Result<Option<f64>, Refusal> {
        match self.table.get(field) {
            None => Ok(None),
            Some(Value::Number(v)) => Ok(v.as_f64()),
            Some(Value::String(s)) => (self.quantity)(s, dimension)
                .map(Some)
                .map_err(|e| self.bad(field, e)),
            // A TOML `nan` or `inf` (which JSON cannot hold) arrives as
            // nothing.
            Some(Value::Null) => Err(self.bad(
                field,
                "must be a finite number, got a value that is not a number or an infinite \
                 one"
                .into(),
            )),
            Some(_) => Err(self.bad(
                field,
                "must be a number or a quantity such as \"8 mm\"".into(),
            )),
        }
    }

    /// The length `field`, m; refused when missing.
    fn need(&self, field: &'static str) -> Result<f64, Refusal> {
        self.size(field, Unit::Length)?
            .ok_or_else(|| self.bad(field, "missing".into()))
    }

    /// The pitch of the nut's thread, m per turn, with the field that gave
    /// it (`pitch`, or `tpi` in threads per inch); `None` when neither is
    /// given.
    fn pitch(&self) -> Result<Option<(&'static str, f64)>, Refusal> {
        match (self.size("pitch", Unit::Length)?, self.table.get("tpi")) {
            (Some(_), Some(_)) => Err(self.bad("tpi", "give pitch or tpi, not both".into())),
            (Some(p), None) => Ok(Some(("pitch", p))),
            (None, Some(v)) => {
                let tpi = v.as_f64();
                match tpi {
                    Some(n) if n > 0.0 && n.is_finite() => Ok(Some(("tpi", 0.0254 / n))),
                    _ => Err(self.bad(
                        "tpi",
                        "must be a positive number of threads per inch".into(),
                    )),
                }
            }
            (None, None) => Ok(None),
        }
    }

    /// The divisions engraved round the nut, 1 to 10,000; `None` when not
    /// given.
    fn divisions(&self) -> Result<Option<u32>, Refusal> {
        match self.table.get("divisions").map(Value::as_u64) {
            None => Ok(None),
            Some(Some(d)) if (1..=10_000).contains(&d) => Ok(Some(d as u32)),
            Some(_) => Err(self.bad("divisions", "must be a whole number from 1 to 10000".into())),
        }
    }

    /// The nut's thread this part states, as part `index` of the design,
    /// or `None` when it states none; refused when another part has one
    /// already (`threaded`) or this one rests on another.
    fn thread(&self, index: usize, threaded: bool) -> Result<Option<Thread>, Refusal> {
        let pitch = self.pitch()?;
        let divisions = self.divisions()?;
        match (pitch, divisions) {
            (Some((field, p)), _) => {
                if !(p > 0.0 && p.is_finite()) {
                    return Err(self.bad(field, format!("must be positive, got {p} m")));
                }
                if threaded {
                    return Err(
                        self.bad(field, "only one part (the rating nut) has a thread".into())
                    );
                }
                if self.table.get("rests_on").is_some() {
                    return Err(self.bad(field, "the threaded part is placed by its centre on the rod, not resting on another".into()));
                }
                Ok(Some(Thread {
                    part: index,
                    pitch: p,
                    divisions,
                }))
            }
            (None, Some(_)) => {
                Err(self.bad("divisions", "give the thread's pitch or tpi too".into()))
            }
            (None, None) => Ok(None),
        }
    }

    /// The part read after its thread: its shape and sizes, material,
    /// placement among the parts `names`, and its thermal and moisture
    /// time constants, s.
    fn part(&self, names: &[String]) -> Result<Part, Refusal> {
        let shape_name = self.shape_name()?;
        self.check_sizes_apply(shape_name)?;
        let shape = self.shape(shape_name)?;
        // A gridiron: its drop is `length`, its rods `diameter` thick, of
        // `steel` and `brass` (default steel and brass), `brass_length` of
        // brass in the series.
        if shape_name == "gridiron" {
            return self.gridiron(shape);
        }
        let material = self.material(shape)?;
        let point_mass = self.point_mass(shape)?;
        let placement = self.placement(shape, names)?;
        let massless = self
            .table
            .get("massless")
            .and_then(|m| m.as_bool())
            .unwrap_or(false);
        let time_constant = self.size("time_constant", Unit::Time)?.unwrap_or(0.0);
        let moisture_time_constant = self.size("moisture_time_constant", Unit::Time)?;
        if moisture_time_constant.is_some() && material.moisture_expansion.is_none() {
            return Err(self.bad(
                "moisture_time_constant",
                format!(
                    "'{}' takes up no water (wood does; a material of your own gives \
                     moisture_expansion)",
                    material.name
                ),
            ));
        }
        Ok(Part {
            name: self.name.to_string(),
            shape,
            material,
            point_mass,
            placement,
            massless,
            time_constant,
            moisture_time_constant: moisture_time_constant.unwrap_or(0.0),
        })
    }

    /// The name of the part's shape; refused when missing.
    fn shape_name(&self) -> Result<&'a str, Refusal> {
        self.table
            .get("shape")
            .and_then(|s| s.as_str())
            .ok_or_else(|| {
                self.bad(
                    "shape",
                    "missing (rod, cylinder, tube, disc, lens, sphere, ring, spring or point)"
                        .into(),
                )
            })
    }

    /// Refuses a size given that does not belong to the shape
    /// `shape_name`, naming the sizes it takes.
    fn check_sizes_apply(&self, shape_name: &str) -> Result<(), Refusal> {
        // A size that does not belong to the shape is refused, not ignored
        // (a rod's `mass`, a spring's `diameter`): it was meant for
        // something.
        let applies: &[&str] = match shape_name {
            "rod" | "cylinder" | "tube" => &["length", "diameter", "bore"],
            "gridiron" => &[
                "length",
                "diameter",
                "bore",
                "brass_length",
                "steel",
                "brass",
            ],
            "disc" | "lens" => &["diameter", "thickness"],
            "sphere" => &["diameter"],
            "ring" => &["outer", "inner", "thickness"],
            "spring" => &["length", "width", "thickness"],
            "point" => &["mass"],
            _ => &SHAPE_FIELDS,
        };
        if let Some(key) = SHAPE_FIELDS
            .iter()
            .find(|k| self.table.contains_key(**k) && !applies.contains(k))
        {
            return Err(self.bad(
                key,
                format!(
                    "does not apply to a {shape_name} (it takes {}{})",
                    applies.join(", "),
                    if *key == "mass" {
                        "; its mass comes from its material and size"
                    } else {
                        ""
                    }
                ),
            ));
        }
        Ok(())
    }

    /// The shape `shape_name` with its sizes, m (a gridiron read as the
    /// cylinder of its drop); refused when a size is missing or the shape
    /// is not one of the list.
    fn shape(&self, shape_name: &str) -> Result<Shape, Refusal> {
        let shape = match shape_name {
            "rod" | "cylinder" | "tube" | "gridiron" => Shape::Cylinder {
                length: self.need("length")?,
                diameter: self.need("diameter")?,
                bore: self.size("bore", Unit::Length)?.unwrap_or(0.0),
            },
            "disc" => Shape::Disc {
                diameter: self.need("diameter")?,
                thickness: self.need("thickness")?,
            },
            "lens" => Shape::Lens {
                diameter: self.need("diameter")?,
                thickness: self.need("thickness")?,
            },
            "sphere" => Shape::Sphere {
                diameter: self.need("diameter")?,
            },
            "ring" => Shape::Ring {
                outer: self.need("outer")?,
                inner: self.size("inner", Unit::Length)?.unwrap_or(0.0),
                thickness: self.need("thickness")?,
            },
            "spring" => Shape::Spring {
                length: self.need("length")?,
                width: self.need("width")?,
                thickness: self.need("thickness")?,
            },
            "point" => Shape::Point,
            other => {
                return Err(self.bad(
                    "shape",
                    format!(
                    "'{other}' is not one of rod, cylinder, tube, disc, lens, sphere, ring, spring, point"
                ),
                ))
            }
        };
        Ok(shape)
    }

    /// The gridiron of `shape` (the cylinder of its drop) as a part: one
    /// material standing for its steel and brass rods in series
    /// (`brass_length` of brass, m), placed by its centre below the pivot, m.
    fn gridiron(&self, shape: Shape) -> Result<Part, Refusal> {
        let metal = |key: &'static str, default: &str| -> Result<Material, Refusal> {
            let name = self
                .table
                .get(key)
                .and_then(|v| v.as_str())
                .unwrap_or(default);
            Material::named(name)
                .ok_or_else(|| self.bad(key, format!("'{name}' is not in the table")))
        };
        let (steel, brass) = (metal("steel", "steel")?, metal("brass", "brass")?);
        let Shape::Cylinder {
            length, diameter, ..
        } = shape
        else {
            unreachable!("a gridiron is read as a cylinder");
        };
        let brass_length = self.need("brass_length")?;
        let centre = self.size("centre", Unit::Length)?.ok_or_else(|| {
            self.bad(
                "centre",
                "missing (half the drop, for a gridiron hanging from the pivot)".into(),
            )
        })?;
        Ok(Part {
            name: self.name.to_string(),
            shape,
            material: super::gridiron(length, brass_length, diameter, &steel, &brass),
            point_mass: 0.0,
            placement: Placement::Centre(centre),
            massless: false,
            time_constant: self.size("time_constant", Unit::Time)?.unwrap_or(0.0),
            moisture_time_constant: 0.0,
        })
    }

    /// The part's material: one of the table by name, the user's own
    /// (`{ density = …, expansion = … }`), or for a point none (no
    /// density, no expansion).
    fn material(&self, shape: Shape) -> Result<Material, Refusal> {
        match self.table.get("material") {
            Some(Value::String(m)) => Material::named(m).ok_or_else(|| {
                self.bad(
                    "material",
                    format!(
                        "'{m}' is not in the table ({}); give {{ density = …, expansion = … }}",
                        Material::names().join(", ")
                    ),
                )
            }),
            Some(Value::Object(m)) => self.user_material(m),
            None if shape == Shape::Point => Ok(Material {
                name: "point".into(),
                density: 0.0,
                expansion: 0.0,
                liquid: false,
                modulus: None,
                modulus_coefficient: None,
                moisture_expansion: None,
            }),
            _ => Err(self.bad("material", "missing".into())),
        }
    }

    /// A material of the user's, the table `m`: its density, kg/m³ (at
    /// least [`super::MIN_DENSITY`]), and expansion, 1/K; and, when given,
    /// its name, whether it is a liquid, its modulus, Pa, with the
    /// modulus's temperature coefficient, and its moisture expansion.
    fn user_material(&self, m: &Map<String, Value>) -> Result<Material, Refusal> {
        const MATERIAL_FIELDS: [&str; 7] = [
            "name",
            "density",
            "expansion",
            "liquid",
            "modulus",
            "modulus_coefficient",
            "moisture_expansion",
        ];
        if let Some(key) = m.keys().find(|k| !MATERIAL_FIELDS.contains(&k.as_str())) {
            return Err(self.bad(
                "material",
                format!(
                    "unknown field '{key}' (a material has {})",
                    MATERIAL_FIELDS.join(", ")
                ),
            ));
        }
        let number = |key: &str| -> Result<f64, Refusal> {
            m.get(key)
                .and_then(Value::as_f64)
                .ok_or_else(|| self.bad("material", format!("needs a number '{key}'")))
        };
        let density = number("density")?;
        if density.is_finite() && density > 0.0 && density < super::MIN_DENSITY {
            return Err(self.bad(
                "material",
                format!(
                    "density must be at least {} kg/m³ (an aerogel, the lightest \
                     solid, is about 1; water 1000), got {}",
                    super::MIN_DENSITY,
                    crate::error::format_significant(density, 6)
                ),
            ));
        }
        Ok(Material {
            name: m
                .get("name")
                .and_then(|n| n.as_str())
                .unwrap_or("user-defined")
                .to_string(),
            density,
            expansion: number("expansion")?,
            liquid: match m.get("liquid") {
                None => false,
                Some(Value::Bool(b)) => *b,
                Some(_) => return Err(self.bad("material", "liquid must be true or false".into())),
            },
            modulus: m.get("modulus").map(|_| number("modulus")).transpose()?,
            modulus_coefficient: m
                .get("modulus_coefficient")
                .map(|_| number("modulus_coefficient"))
                .transpose()?,
            moisture_expansion: m
                .get("moisture_expansion")
                .map(|_| number("moisture_expansion"))
                .transpose()?,
        })
    }

    /// A point's mass, kg, or 0 for any other shape (whose mass comes from
    /// its material and size); refused when a point has none.
    fn point_mass(&self, shape: Shape) -> Result<f64, Refusal> {
        if shape == Shape::Point {
            self.size("mass", Unit::Mass)?.ok_or_else(|| {
                self.bad("mass", "missing (a point has a mass, e.g. \"2 kg\")".into())
            })
        } else {
            Ok(0.0)
        }
    }

    /// The index among `names` of the part `on` that the field `field`
    /// names; refused when it names this part itself or no part.
    fn named(&self, names: &[String], field: &str, on: &str) -> Result<usize, Refusal> {
        if on == self.name {
            return Err(self.bad(
                field,
                format!("names the part itself: give another part ('{on}' cannot hold '{on}')"),
            ));
        }
        names
            .iter()
            .position(|n| n == on)
            .ok_or_else(|| self.bad(field, format!("no part is named '{on}'")))
    }

    /// The end of the part this one rests on that holds it, from
    /// `rests_on_end` (`None` when not given).
    fn rests_on_end(&self) -> Result<Option<End>, Refusal> {
        match self.table.get("rests_on_end") {
            None => Ok(None),
            Some(Value::String(e)) if e == "top" => Ok(Some(End::Top)),
            Some(Value::String(e)) if e == "bottom" => Ok(Some(End::Bottom)),
            Some(_) => Err(self.bad(
                "rests_on_end",
                "must be \"top\" or \"bottom\" (the end of the part it rests on)".into(),
            )),
        }
    }

    /// Where the part of shape `shape` is: its centre so far below the
    /// pivot, m, resting on or held by another of the parts `names`,
    /// hanging by its top from another's top, or (a spring) from the pivot.
    fn placement(&self, shape: Shape, names: &[String]) -> Result<Placement, Refusal> {
        let t = self.table;
        let centre = match self.size("centre", Unit::Length)? {
            Some(c) => Some(c),
            None => self.size("center", Unit::Length)?,
        };
        let support_height = self.size("support_height", Unit::Length)?;
        let end = self.rests_on_end()?;
        let placement = match (centre, t.get("rests_on"), t.get("hangs_from")) {
            (Some(c), None, None) => {
                if support_height.is_some() || end.is_some() {
                    return Err(self.bad(
                        if support_height.is_some() {
                            "support_height"
                        } else {
                            "rests_on_end"
                        },
                        "goes with rests_on (the part placed by its centre hangs from the rod)"
                            .into(),
                    ));
                }
                Placement::Centre(c)
            }
            (None, Some(Value::String(on)), None) => {
                let j = self.named(names, "rests_on", on)?;
                match (support_height, end) {
                    (None, None) => Placement::RestsOn(j),
                    (h, e) => Placement::Held {
                        part: j,
                        end: e.unwrap_or(End::Top),
                        height: h.unwrap_or(0.0),
                    },
                }
            }
            (None, None, Some(Value::String(from))) => {
                if support_height.is_some() || end.is_some() {
                    return Err(self.bad(
                        "hangs_from",
                        "hangs by its top from the top of that part: give rests_on with \
                         support_height for any other point"
                            .into(),
                    ));
                }
                Placement::Held {
                    part: self.named(names, "hangs_from", from)?,
                    end: End::Top,
                    height: shape.height(),
                }
            }
            (_, Some(v), _) | (_, _, Some(v)) if !v.is_string() => {
                let field = if t.get("rests_on").is_some_and(|r| !r.is_string()) {
                    "rests_on"
                } else {
                    "hangs_from"
                };
                return Err(self.bad(field, "must be the name of another part".into()));
            }
            // A spring hangs from the pivot.
            (None, None, None) if shape.is_spring() => Placement::Centre(0.5 * shape.height()),
            (None, None, None) => {
                return Err(self.bad("centre", "missing (or rests_on = \"another part\")".into()))
            }
            _ => {
                return Err(self.bad(
                    "centre",
                    "give one of centre, rests_on and hangs_from".into(),
                ))
            }
        };
        Ok(placement)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn no_units(_: &str, _: Unit) -> Result<f64, String> {
        Err("give a number in SI units".into())
    }

    #[test]
    fn a_design_of_numbers() {
        let v = serde_json::json!({"part": [
            {"name": "rod", "shape": "rod", "material": "steel", "length": 1.0,
             "diameter": 0.008, "centre": 0.5},
            {"name": "bob", "shape": "sphere", "material": "brass", "diameter": 0.1,
             "centre": 0.95, "pitch": 0.0007, "divisions": 20}
        ]});
        let d = design(&v, &no_units).unwrap();
        assert_eq!(d.pendulum.parts().len(), 2);
        assert_eq!(d.thread.unwrap().divisions, Some(20));
        let bad = serde_json::json!({"part": [{"name": "rod", "shape": "rod",
            "material": "steel", "length": "1 m", "diameter": 0.008, "centre": 0.5}]});
        assert_eq!(
            design(&bad, &no_units).unwrap_err().to_string(),
            "part 'rod': length: give a number in SI units"
        );
    }

    /// A size that does not belong to the shape is refused by name: a
    /// rod's `mass` (its mass comes from its material), a spring's
    /// `diameter`, a sphere's `length` (a new user's finds: they were
    /// ignored).
    #[test]
    fn a_size_of_another_shape_is_refused() {
        let with = |extra: (&str, serde_json::Value)| {
            let mut rod = serde_json::json!({"name": "rod", "shape": "rod", "material": "steel",
                "length": 1.0, "diameter": 0.008, "centre": 0.5});
            rod[extra.0] = extra.1;
            let v = serde_json::json!({"part": [rod, {"name": "bob", "shape": "sphere",
                "material": "brass", "diameter": 0.1, "centre": 0.95}]});
            design(&v, &no_units).map(|_| ()).map_err(|e| e.to_string())
        };
        let e = with(("mass", serde_json::json!(2.0))).unwrap_err();
        assert!(
            e.starts_with(
                "part 'rod': mass: does not apply to a rod (it takes length, diameter, bore"
            ),
            "{e}"
        );
        assert!(with(("thickness", serde_json::json!(0.01))).is_err());
        assert!(with(("bore", serde_json::json!(0.002))).is_ok());
        let sphere = serde_json::json!({"part": [{"name": "rod", "shape": "rod",
            "material": "steel", "length": 1.0, "diameter": 0.008, "centre": 0.5},
            {"name": "bob", "shape": "sphere", "material": "brass", "diameter": 0.1,
             "length": 0.1, "centre": 0.95}]});
        let e = design(&sphere, &no_units).unwrap_err().to_string();
        assert!(
            e.starts_with("part 'bob': length: does not apply to a sphere"),
            "{e}"
        );
    }
}
