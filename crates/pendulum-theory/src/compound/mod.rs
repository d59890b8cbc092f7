//! The real pendulum: a rod, a bob, a nut and whatever else hangs from the
//! pivot, each part a shape of a material at a place.
//!
//! A rigid body swinging about a horizontal axis obeys
//! `I θ'' = -m g d sin θ` (I: moment of inertia about the pivot, m: mass,
//! d: distance of the centre of mass below the pivot), which is the simple
//! pendulum's equation with the equivalent length `l = I / (m d)` (Huygens,
//! Horologium Oscillatorium, 1673; any mechanics text, e.g. Goldstein
//! §5.3). So the exact period at any amplitude is the simple pendulum's of
//! that length: `T = 4 sqrt(I / (m g d)) K(sin²(A0/2))`, and every command
//! that takes a length can take a design. `I` sums each part's own
//! inertia and `m_i d_i²` (the parallel-axis theorem).
//!
//! Temperature ([`CompoundPendulum::at_temperature`]): every dimension of a
//! part grows by its material's coefficient; a part placed by its centre
//! is carried by the rod (the first upright cylinder hanging from the
//! pivot), so its centre moves with the rod's expansion from the pivot
//! down; a part resting on another sits on that part's top and grows
//! upward from it (a bob on its rating nut); a part held at a point (a bob
//! on a collar at its centre, a tube hanging from another's top) grows
//! both ways from that point.
//!
//! Gas ([`CompoundPendulum::in_gas`], in [`gas`]): buoyancy lessens the
//! restoring torque by the weight of the displaced gas, `Σ (m_i - ρ V_i) g
//! d_i`; the gas carried along adds to the inertia and the gas damps the
//! swing, each part's by Stokes's oscillating flow
//! ([`crate::oscillating_flow`]).

pub mod compensate;
pub mod compensator;
pub mod datasheet;
pub mod description;
pub mod gas;
pub mod material;
pub mod regulate;
pub mod shape;

pub use compensator::gridiron;
pub use material::Material;
pub use shape::Shape;

/// Seconds in a day.
const DAY: f64 = 86_400.0;

/// Which end of a part holds another.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// Its top (a collar, a tube standing on a nut).
    Top,
    /// Its bottom (a flange at a tube's lower end).
    Bottom,
}

/// Where a part is.
#[derive(Clone, Debug, PartialEq)]
pub enum Placement {
    /// Its centre this far below the pivot, m (at the reference
    /// temperature).
    Centre(f64),
    /// Its bottom on the top of the part with this index.
    RestsOn(usize),
    /// Held by the end `end` of part `part` at the point `height` m above
    /// its own bottom (at the reference temperature; it grows with the
    /// part's own material): a bob on a collar at its centre (`height`
    /// half its own), a tube hanging from the top of another (`height` its
    /// whole length), a bob on a flange at a tube's lower end (`end`
    /// bottom, `height` 0).
    Held {
        /// The part that holds it.
        part: usize,
        /// Which end of that part.
        end: End,
        /// The point held, above its own bottom, m.
        height: f64,
    },
}

impl Placement {
    /// The part this one is carried by, when not placed by its centre.
    pub fn support(&self) -> Option<usize> {
        match *self {
            Placement::Centre(_) => None,
            Placement::RestsOn(j) | Placement::Held { part: j, .. } => Some(j),
        }
    }

    /// The same placement carried by part `j` instead (a compensator put
    /// between a bob and its support keeps how the bob is held).
    pub fn carried_by(&self, j: usize) -> Placement {
        match *self {
            Placement::Held { end, height, .. } => Placement::Held {
                part: j,
                end,
                height,
            },
            _ => Placement::RestsOn(j),
        }
    }
}

/// How far a part's top may reach above the pivot and still hang from
/// it, m: a dimension rounded to the micrometre, not a part through the
/// pivot.
pub const PIVOT_TOLERANCE_M: f64 = 1e-5;

/// One part of a pendulum.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// Its name (for messages and the datasheet).
    pub name: String,
    /// Its shape.
    pub shape: Shape,
    /// Its material (density and expansion).
    pub material: Material,
    /// Its mass, kg, for a point (else from the material).
    pub point_mass: f64,
    /// Where it is.
    pub placement: Placement,
    /// An idealised rod with no mass that still expands.
    pub massless: bool,
    /// Its thermal time constant, s: it follows the air's temperature as a
    /// first-order lag (0: at once).
    pub time_constant: f64,
    /// Its moisture time constant, s: a part that takes up water
    /// (`material.moisture_expansion`) follows the air's humidity as a
    /// first-order lag (0: at once).
    pub moisture_time_constant: f64,
}

impl Part {
    /// Its sizes by the description's field names, m (a point's mass,
    /// kg), in the order a description writes them.
    pub fn sizes(&self) -> Vec<(&'static str, f64)> {
        match self.shape {
            Shape::Cylinder {
                length,
                diameter,
                bore,
            } => vec![("length", length), ("diameter", diameter), ("bore", bore)],
            Shape::Disc {
                diameter,
                thickness,
            }
            | Shape::Lens {
                diameter,
                thickness,
            } => vec![("diameter", diameter), ("thickness", thickness)],
            Shape::Sphere { diameter } => vec![("diameter", diameter)],
            Shape::Ring {
                outer,
                inner,
                thickness,
            } => vec![("outer", outer), ("inner", inner), ("thickness", thickness)],
            Shape::Spring {
                length,
                width,
                thickness,
            } => vec![
                ("length", length),
                ("width", width),
                ("thickness", thickness),
            ],
            Shape::Point => vec![("mass", self.point_mass)],
        }
    }

    /// Mass, kg.
    pub fn mass(&self) -> f64 {
        if self.massless {
            0.0
        } else if self.shape == Shape::Point {
            self.point_mass
        } else {
            self.material.density * self.shape.volume()
        }
    }
}

/// A part's state away from the design's reference (see
/// [`CompoundPendulum::at_part_states`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PartState {
    /// Its temperature above the reference, K.
    pub temperature: f64,
    /// Its moisture content, % of its dry mass (a part that takes up water).
    pub moisture: f64,
    /// Its moisture content at the reference, %.
    pub reference_moisture: f64,
    /// The temperature's gradient along it, K/m, warmer upwards: its
    /// centre of mass moves with the uneven growth along it, and for the
    /// rod what it carries at a point along it moves by its expansion down
    /// to that point (a part's own length needs only its mean).
    pub gradient: f64,
}

/// Why a design is refused: the part and the field.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("part '{part}': {field}: {message}")]
pub struct DesignError {
    /// The part's name.
    pub part: String,
    /// The field.
    pub field: &'static str,
    /// What is wrong.
    pub message: String,
}

/// The largest density a material may have, kg/m³: osmium, the densest
/// element, is 22,590, but an assembly taken as one part is denser over
/// its envelope (a gridiron's rods spread over its drop reach 10^5).
pub const MAX_DENSITY: f64 = 1e6;

/// The smallest density a design file's material may have, kg/m³: the
/// lightest solids, silica aerogels, reach about 1 (a lighter part is a
/// unit slip; the library's own idealisations may go lower).
pub const MIN_DENSITY: f64 = 1.0;

/// A number from a design for a message: its digits, or words for NaN
/// and infinity (which a TOML file can hold: `nan`, `inf`).
fn shown(v: f64) -> String {
    if v.is_nan() {
        "a value that is not a number".to_string()
    } else if v.is_infinite() {
        "an infinite value".to_string()
    } else {
        crate::error::format_significant(v, 6)
    }
}

/// The largest thermal expansion a material may have, 1/K, either sign
/// (solids are 1e-6 to 3e-5; liquids' volume expansion up to about 1.5e-3).
pub const MAX_EXPANSION: f64 = 2e-3;

/// The most negative thermal expansion a material may have, 1/K: the
/// solids that shrink as they warm do so by at most about 1e-5 (zirconium
/// tungstate -9e-6, carbon fibre along its length -1e-6).
pub const MIN_EXPANSION: f64 = -5e-5;

/// The largest growth per percentage point of moisture content a material
/// may have, 1/% (wood along the grain 5e-5, across it up to 3e-3).
pub const MAX_MOISTURE_EXPANSION: f64 = 1e-2;

/// The longest thermal time constant a part may have, s (a year).
pub const MAX_TIME_CONSTANT_S: f64 = 3.156e7;

/// A design must stay valid warmed or cooled by this much from its
/// reference temperature, K (any clock's room, and every temperature a
/// command accepts, lies well within it).
pub const TEMPERATURE_SPAN_K: f64 = 150.0;

/// A pendulum of parts, with each part's centre resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct CompoundPendulum {
    parts: Vec<Part>,
    /// Each part's centre below the pivot, m.
    centres: Vec<f64>,
    /// The gravity it hangs in, m/s² (standard gravity unless given): a
    /// suspension spring's share of the restoring torque depends on it.
    gravity: f64,
}

/// The summed properties of a pendulum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Properties {
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass below the pivot, m.
    pub centre_of_mass: f64,
    /// Moment of inertia about the pivot, kg m².
    pub inertia: f64,
    /// Equivalent simple length `I / (m d)`, m.
    pub equivalent_length: f64,
}

impl Properties {
    /// The mass, kg, of the simple pendulum of the equivalent length that
    /// has this pendulum's energy at every amplitude: `I / l²`, so that
    /// the kinetic energy `I θ'²/2` equals `m l² θ'²/2` and the restoring
    /// stiffness `I ω²` equals `m g l`. For a rigid pendulum (`I = M d l`)
    /// it is `M d / l`, and the potential energies `M g d (1 - cos θ)` and
    /// `m g l (1 - cos θ)` agree at every angle; on a suspension spring
    /// the spring's share of the stiffness is in it too. The energy budget
    /// of a design uses it.
    pub fn effective_mass(&self) -> f64 {
        self.inertia / (self.equivalent_length * self.equivalent_length)
    }
}

/// The index of the suspension spring among `parts`: the first part of
/// that shape (a design has at most one).
fn spring_index(parts: &[Part]) -> Option<usize> {
    parts.iter().position(|p| p.shape.is_spring())
}

/// The largest share of a modulus's change per kelvin a material may
/// give (steels -2.5e-4/K, fused silica +1.5e-4/K, bronzes about -4e-4/K).
const MAX_MODULUS_COEFFICIENT: f64 = 1e-2;

/// Checks suspension spring `p` among `parts`: the only one, hanging from
/// the pivot (its centre half its length down), of a material with a
/// modulus and its temperature coefficient.
fn check_spring(p: &Part, parts: &[Part]) -> Result<(), (&'static str, String)> {
    let Shape::Spring { length, .. } = p.shape else {
        return Ok(());
    };
    if !spring_index(parts).is_some_and(|i| std::ptr::eq(&parts[i], p)) {
        return Err((
            "shape",
            "a design hangs from one suspension spring (give springs side by side as one, of \
             their summed width)"
                .into(),
        ));
    }
    if parts.len() == 1 {
        return Err((
            "shape",
            "a spring carries the pendulum: give the parts clamped below it".into(),
        ));
    }
    match p.placement {
        Placement::Centre(c) if (c - 0.5 * length).abs() <= 1e-9 * length => {}
        Placement::RestsOn(_) => {
            return Err((
                "rests_on",
                "a suspension spring hangs from the pivot: leave rests_on out".into(),
            ))
        }
        Placement::Held { .. } => {
            return Err((
                "hangs_from",
                "a suspension spring hangs from the pivot: leave hangs_from (and rests_on) out"
                    .into(),
            ))
        }
        _ => {
            return Err((
                "centre",
                format!(
                    "a suspension spring hangs from the pivot: its centre is half its length \
                     down ({} m; leave centre out)",
                    shown(0.5 * length)
                ),
            ))
        }
    }
    // What is placed by its centre hangs below the spring, the rod clamped
    // at its bottom (within 1 µm: sizes in mm; a millimetre for the rod).
    let tops: Vec<(&str, f64)> = parts
        .iter()
        .filter(|q| !q.shape.is_spring())
        .filter_map(|q| match q.placement {
            Placement::Centre(c) => Some((q.name.as_str(), c - 0.5 * q.shape.height())),
            _ => None,
        })
        .collect();
    if let Some((name, top)) = tops.iter().find(|(_, top)| *top < length - 1e-6) {
        return Err((
            "length",
            format!(
                "part '{name}' reaches up into the spring (its top {} mm below the pivot, the \
                 spring's bottom {} mm): parts are clamped below the spring",
                shown(top * 1e3),
                shown(length * 1e3)
            ),
        ));
    }
    if let Some(nearest) = tops.iter().map(|t| t.1).reduce(f64::min) {
        if nearest > length + 1e-3 {
            return Err((
                "length",
                format!(
                    "nothing is clamped to the spring's bottom ({} mm below the pivot): the \
                     highest part placed on the rod starts at {} mm; the rod's top belongs \
                     there",
                    shown(length * 1e3),
                    shown(nearest * 1e3)
                ),
            ));
        }
    }
    let m = &p.material;
    match m.modulus {
        Some(e) if e.is_finite() && e > 0.0 && e <= 1.2e12 => {}
        Some(e) => {
            return Err((
                "modulus",
                format!(
                    "must be more than 0 and at most 1.2e12 Pa (diamond's), got {}",
                    shown(e)
                ),
            ))
        }
        None => {
            return Err((
                "material",
                format!(
                    "a spring needs its material's Young's modulus: '{}' has none in the table \
                     (steel, fused silica have it with its temperature coefficient); give the \
                     material as {{ density = …, expansion = …, modulus = …, \
                     modulus_coefficient = … }}",
                    m.name
                ),
            ))
        }
    }
    match m.modulus_coefficient {
        Some(b) if b.abs() <= MAX_MODULUS_COEFFICIENT => Ok(()),
        Some(b) => Err((
            "modulus_coefficient",
            format!(
                "must lie within ±{MAX_MODULUS_COEFFICIENT:e} per K (steel's is -2.5e-4), got {}",
                shown(b)
            ),
        )),
        None if m.name == "user-defined" => Err((
            "modulus_coefficient",
            "missing: the material given needs the temperature coefficient of its modulus \
             too, modulus_coefficient = … ((1/E) dE/dT, 1/K; steel's is -2.5e-4)"
                .to_string(),
        )),
        None => Err((
            "modulus_coefficient",
            format!(
                "the temperature coefficient of {}'s modulus is not in the table: give the \
                 material as {{ density = …, expansion = …, modulus = …, \
                 modulus_coefficient = … }} ((1/E) dE/dT, 1/K)",
                m.name
            ),
        )),
    }
}

/// Checks part `p`'s sizes: each positive and finite (a bore or a ring's
/// inner diameter may be 0), a bore less than its diameter, a ring's
/// inner diameter less than its outer.
fn check_sizes(p: &Part) -> Result<(), (&'static str, String)> {
    for (field, v) in p.sizes() {
        let may_be_zero = field == "bore" || field == "inner";
        if !v.is_finite() || v < 0.0 || (v == 0.0 && !may_be_zero) {
            return Err((
                field,
                format!("must be a positive number, got {}", shown(v)),
            ));
        }
    }
    if let Shape::Cylinder { diameter, bore, .. } = p.shape {
        if bore >= diameter {
            return Err(("bore", "must be less than the diameter".into()));
        }
    }
    if let Shape::Ring { outer, inner, .. } = p.shape {
        if inner >= outer {
            return Err(("inner", "must be less than the outer diameter".into()));
        }
    }
    Ok(())
}

/// Checks the density of part `p`'s material, kg/m³: more than 0 and at
/// most [`MAX_DENSITY`] (a massless part and a point have none to check).
fn check_density(p: &Part) -> Result<(), (&'static str, String)> {
    if !p.massless && p.shape != Shape::Point {
        let d = p.material.density;
        if !(d > 0.0 && d <= MAX_DENSITY) {
            return Err((
                "density",
                format!(
                    "must be more than 0 and at most {MAX_DENSITY:e} kg/m³ (osmium, the \
                     densest metal, is 22,590; an assembly taken as one part may be \
                     denser over its envelope), got {}",
                    shown(d)
                ),
            ));
        }
    }
    Ok(())
}

/// Checks that part `p` does not rest on or hang from a suspension spring
/// among `parts`: parts are clamped below it.
fn check_not_on_spring(p: &Part, parts: &[Part]) -> Result<(), (&'static str, String)> {
    if let Some(j) = p.placement.support() {
        if parts.get(j).is_some_and(|q| q.shape.is_spring()) {
            return Err((
                if matches!(p.placement, Placement::RestsOn(_)) {
                    "rests_on"
                } else {
                    "hangs_from"
                },
                "nothing rests on or hangs from a suspension spring: parts are clamped \
                 below it (placed by their centre)"
                    .into(),
            ));
        }
    }
    Ok(())
}

/// Checks how part `p` follows the air: its material's expansion, 1/K,
/// its thermal and moisture time constants, s (0 to a year), and its
/// material's growth per percentage point of moisture, 1/%.
fn check_response(p: &Part) -> Result<(), (&'static str, String)> {
    let alpha = p.material.expansion;
    if !(MIN_EXPANSION..=MAX_EXPANSION).contains(&alpha) {
        return Err((
            "expansion",
            format!(
                "must be between {MIN_EXPANSION:e} and {MAX_EXPANSION:e} per K \
                 (steel 1.2e-5, mercury's volume 1.8e-4; zirconium tungstate, which \
                 shrinks as it warms, -9e-6), got {}",
                shown(alpha)
            ),
        ));
    }
    if !(p.time_constant.is_finite() && (0.0..=MAX_TIME_CONSTANT_S).contains(&p.time_constant)) {
        return Err((
            "time_constant",
            format!(
                "must lie between 0 and {MAX_TIME_CONSTANT_S:e} s (a year), got {}",
                shown(p.time_constant)
            ),
        ));
    }
    if !(p.moisture_time_constant.is_finite()
        && (0.0..=MAX_TIME_CONSTANT_S).contains(&p.moisture_time_constant))
    {
        return Err((
            "moisture_time_constant",
            format!(
                "must lie between 0 and {MAX_TIME_CONSTANT_S:e} s (a year), got {}",
                shown(p.moisture_time_constant)
            ),
        ));
    }
    if let Some(m) = p.material.moisture_expansion {
        if !(0.0..=MAX_MOISTURE_EXPANSION).contains(&m) {
            return Err((
                "moisture_expansion",
                format!(
                    "must lie between 0 and {MAX_MOISTURE_EXPANSION:e} per % of \
                     moisture content (wood along the grain 5e-5), got {}",
                    shown(m)
                ),
            ));
        }
    }
    Ok(())
}

/// Checks how part `p` is held: at a point within its own height, m, and
/// a liquid as an upright cylinder resting on its jar's bottom.
fn check_held(p: &Part) -> Result<(), (&'static str, String)> {
    if let Placement::Held { height, .. } = p.placement {
        if !(0.0..=p.shape.height()).contains(&height) {
            return Err((
                "support_height",
                format!(
                    "must lie between 0 and the part's own height ({} m), got {}",
                    shown(p.shape.height()),
                    shown(height)
                ),
            ));
        }
    }
    if p.material.liquid {
        let fits = matches!(p.shape, Shape::Cylinder { .. })
            && matches!(p.placement, Placement::RestsOn(_));
        if !fits {
            return Err((
                "rests_on",
                "a liquid is an upright cylinder resting on the bottom of its jar".into(),
            ));
        }
    }
    Ok(())
}

/// Checks part `p` among `parts` on its own (sizes, density, a spring,
/// what carries it, expansion and time constants, how it is held); the
/// error names the part and the field.
fn check_part(p: &Part, parts: &[Part]) -> Result<(), DesignError> {
    let fail = |(field, message): (&'static str, String)| DesignError {
        part: p.name.clone(),
        field,
        message,
    };
    check_sizes(p).map_err(fail)?;
    check_density(p).map_err(fail)?;
    if p.shape.is_spring() {
        check_spring(p, parts).map_err(fail)?;
    }
    check_not_on_spring(p, parts).map_err(fail)?;
    check_response(p).map_err(fail)?;
    check_held(p).map_err(fail)
}

impl CompoundPendulum {
    /// A pendulum of `parts`, checked: every size positive and finite,
    /// every part with mass (unless `massless`), nothing above or through
    /// the pivot, a part rests only on one listed before it.
    pub fn new(parts: Vec<Part>) -> Result<Self, DesignError> {
        if parts.is_empty() {
            return Err(DesignError {
                part: "-".into(),
                field: "part",
                message: "the design has no parts".into(),
            });
        }
        for p in &parts {
            check_part(p, &parts)?;
        }
        let centres = resolve(&parts, None)?;
        let pendulum = Self {
            parts,
            centres,
            gravity: crate::pendulum::STANDARD_GRAVITY,
        };
        pendulum.check_temperature_span()?;
        pendulum.check_swings()?;
        Ok(pendulum)
    }

    /// Checks that the design stays valid warmed or cooled by
    /// [`TEMPERATURE_SPAN_K`] from its reference; the error is the one
    /// met where it first fails.
    fn check_temperature_span(&self) -> Result<(), DesignError> {
        // Every size is linear in the temperature, so a design valid at both
        // ends of the span is valid everywhere in it: the commands that warm
        // or cool it (datasheets, coefficients, long runs with weather) can
        // then never meet an invalid design.
        for span in [-TEMPERATURE_SPAN_K, TEMPERATURE_SPAN_K] {
            if self.at_temperature(span).is_err() {
                // Say where it first fails (bisection to 1e-6 of the span).
                let (mut ok, mut bad) = (0.0, span);
                for _ in 0..28 {
                    let mid = 0.5 * (ok + bad);
                    if self.at_temperature(mid).is_ok() {
                        ok = mid;
                    } else {
                        bad = mid;
                    }
                }
                return Err(self.at_temperature(bad).err().unwrap_or(DesignError {
                    part: "-".into(),
                    field: "part",
                    message: format!("the design is not valid {span} °C from its reference"),
                }));
            }
        }
        Ok(())
    }

    /// Checks that the design swings: it has mass, what a suspension
    /// spring carries hangs below it, and its centre of mass is below the
    /// pivot.
    fn check_swings(&self) -> Result<(), DesignError> {
        let props = self.properties();
        if props.mass.is_nan() || props.mass <= 0.0 {
            return Err(DesignError {
                part: "-".into(),
                field: "mass",
                message: "the pendulum has no mass (every part is massless)".into(),
            });
        }
        if let Some(i) = spring_index(&self.parts) {
            if self.spring_effect().is_none() {
                return Err(DesignError {
                    part: self.parts[i].name.clone(),
                    field: "length",
                    message: "the parts it carries must hang below the spring: their centre of \
                              mass is above its bottom"
                        .into(),
                });
            }
        }
        if !(props.equivalent_length.is_finite() && props.centre_of_mass > 0.0) {
            return Err(DesignError {
                part: "-".into(),
                field: "centre",
                message: "the centre of mass is at the pivot: the pendulum would not swing".into(),
            });
        }
        Ok(())
    }

    /// The parts.
    pub fn parts(&self) -> &[Part] {
        &self.parts
    }

    /// The same design in gravity `g`, m/s² (a positive finite value;
    /// anything else leaves it as it was, for the caller's own check of g
    /// to refuse). Only a suspension spring feels it: the spring's
    /// stiffness does not scale with g as gravity's does, so its share,
    /// its gain and the equivalent length change with it.
    pub fn in_gravity(&self, g: f64) -> Self {
        let mut out = self.clone();
        if g.is_finite() && g > 0.0 {
            out.gravity = g;
        }
        out
    }

    /// The gravity it hangs in, m/s².
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// Each part's centre below the pivot, m.
    pub fn centres(&self) -> &[f64] {
        &self.centres
    }

    /// Mass, centre of mass, moment of inertia about the pivot and the
    /// equivalent simple length (see the module notes). A design hanging
    /// from a suspension spring has the length of the simple pendulum of
    /// its frequency on the spring ([`CompoundPendulum::spring_effect`]):
    /// the rigid `I / (M d)` times `(ω_rigid / ω)²`.
    pub fn properties(&self) -> Properties {
        let rigid = self.rigid_properties();
        match self.spring_effect() {
            Some(e) => Properties {
                equivalent_length: rigid.equivalent_length * (e.rigid_omega / e.omega).powi(2),
                ..rigid
            },
            None => rigid,
        }
    }

    /// The suspension spring's effect ([`crate::suspension::effect`]) on
    /// the rest of the design, taken as a rigid body hanging from its
    /// bottom, in the design's gravity ([`CompoundPendulum::in_gravity`]:
    /// the tension is the weight, and the spring's stiffness against
    /// gravity's sets its share); `None` without a spring.
    pub fn spring_effect(&self) -> Option<crate::suspension::SpringEffect> {
        let i = spring_index(&self.parts)?;
        let Shape::Spring {
            length,
            width,
            thickness,
        } = self.parts[i].shape
        else {
            return None;
        };
        let (mut mass, mut moment, mut inertia) = (0.0, 0.0, 0.0);
        for (j, (p, &d)) in self.parts.iter().zip(&self.centres).enumerate() {
            if j != i {
                let m = p.mass();
                mass += m;
                moment += m * d;
                inertia += m * (p.shape.inertia_per_mass() + d * d);
            }
        }
        let com = moment / mass;
        let body = crate::suspension::Body {
            mass,
            centre: com - length,
            inertia: inertia - mass * com * com,
        };
        let strip = crate::suspension::Strip {
            length,
            width,
            thickness,
            modulus: self.parts[i].material.modulus?,
        };
        crate::suspension::effect(&strip, &body, self.gravity).ok()
    }

    /// The same design with its spring's modulus unchanged by temperature
    /// (to separate the spring's part of the temperature coefficient).
    pub fn without_spring_thermoelasticity(&self) -> Self {
        let mut out = self.clone();
        for p in &mut out.parts {
            if p.shape.is_spring() {
                p.material.modulus_coefficient = Some(0.0);
            }
        }
        out
    }

    /// [`CompoundPendulum::properties`] of the design as a rigid body about
    /// the pivot.
    fn rigid_properties(&self) -> Properties {
        let (mut mass, mut moment, mut inertia) = (0.0, 0.0, 0.0);
        for (p, &d) in self.parts.iter().zip(&self.centres) {
            let m = p.mass();
            mass += m;
            moment += m * d;
            inertia += m * (p.shape.inertia_per_mass() + d * d);
        }
        Properties {
            mass,
            centre_of_mass: if mass > 0.0 { moment / mass } else { f64::NAN },
            inertia,
            equivalent_length: inertia / moment,
        }
    }

    /// The same pendulum `delta` °C warmer than its reference temperature
    /// (see the module notes). Within ±[`TEMPERATURE_SPAN_K`] of the
    /// reference this never fails (checked when the design was made);
    /// beyond it, a design whose parts would then reach above the pivot is
    /// refused, saying at which temperature.
    pub fn at_temperature(&self, delta: f64) -> Result<Self, DesignError> {
        self.at_part_temperatures(&vec![delta; self.parts.len()])
    }

    /// The same pendulum with part `i` `deltas[i]` °C warmer than the
    /// reference (a part that lags the air; see
    /// [`CompoundPendulum::at_temperature`]): each part grows by its own,
    /// and what the rod carries moves with the rod's. A slice of the wrong
    /// length is taken as the first value for every part.
    pub fn at_part_temperatures(&self, deltas: &[f64]) -> Result<Self, DesignError> {
        let delta_of = |i: usize| {
            deltas
                .get(i)
                .copied()
                .filter(|_| deltas.len() == self.parts.len())
                .unwrap_or(deltas.first().copied().unwrap_or(0.0))
        };
        let states: Vec<PartState> = (0..self.parts.len())
            .map(|i| PartState {
                temperature: delta_of(i),
                ..PartState::default()
            })
            .collect();
        self.at_part_states(&states)
    }

    /// The same pendulum with each part in its own state: `states[i]`
    /// (missing entries are the reference). Every dimension of a part grows
    /// with its temperature, the mass staying; a part that takes up water
    /// (`material.moisture_expansion`) grows along its length with the
    /// moisture it gains (a rod with its grain along it: the growth across
    /// the grain, 20 to 40 times more, is not modelled, and the datasheet
    /// says so for any other wooden shape) and gains the water's mass. What
    /// the rod carries moves with the rod.
    pub fn at_part_states(&self, states: &[PartState]) -> Result<Self, DesignError> {
        let state = |i: usize| states.get(i).copied().unwrap_or_default();
        // Each part's growth along its length.
        let along = |i: usize| {
            let (p, s) = (&self.parts[i], state(i));
            let water =
                p.material.moisture_expansion.unwrap_or(0.0) * (s.moisture - s.reference_moisture);
            (1.0 + p.material.expansion * s.temperature) * (1.0 + water)
        };
        let parts: Vec<Part> = self
            .parts
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let s = state(i);
                // A liquid keeps its jar's width and rises with its volume;
                // the jar's wall beside it is at its temperature (not the
                // bottom's, lower down in a gradient).
                let mut material = p.material.clone();
                if let (true, Placement::RestsOn(jar)) = (p.material.liquid, &p.placement) {
                    let width = 1.0 + self.parts[*jar].material.expansion * s.temperature;
                    let volume = 1.0 + p.material.expansion * s.temperature;
                    material.density /= volume;
                    return Part {
                        shape: p.shape.stretched(width, volume / (width * width)),
                        material,
                        ..p.clone()
                    };
                }
                let factor = 1.0 + p.material.expansion * s.temperature;
                let length = along(i);
                let water = if p.material.moisture_expansion.is_some() {
                    (100.0 + s.moisture) / (100.0 + s.reference_moisture)
                } else {
                    1.0
                };
                let shape = match p.shape {
                    Shape::Cylinder { .. } => p.shape.stretched(factor, length),
                    _ => p.shape.scaled(factor),
                };
                // The mass stays (and gains any water): the density follows
                // the volume, by the factors themselves (the volumes'
                // ratio would add rounding a nested solve feels).
                let volume = match p.shape {
                    Shape::Cylinder { .. } => factor * factor * length,
                    _ => factor.powi(3),
                };
                material.density = material.density * water / volume;
                if let (Some(e), Some(beta)) = (material.modulus, material.modulus_coefficient) {
                    material.modulus = Some(e * (1.0 + beta * s.temperature));
                }
                let placement = match p.placement {
                    Placement::Held { part, end, height } => Placement::Held {
                        part,
                        end,
                        height: height * length,
                    },
                    ref other => other.clone(),
                };
                Part {
                    shape,
                    material,
                    placement,
                    ..p.clone()
                }
            })
            .collect();
        let rod = self.rod();
        let delta = rod.map_or(state(0).temperature, |i| state(i).temperature);
        let factors: Vec<f64> = (0..self.parts.len()).map(along).collect();
        // Down a rod of length `L` warmer upwards by `G`, a point `x` below
        // its top moves by `α G x (L/2 - x/2)` besides its mean growth.
        let bend = rod.map_or((0.0, 0.0), |r| {
            (
                self.parts[r].material.expansion * state(r).gradient,
                self.parts[r].shape.height(),
            )
        });
        let mut centres =
            resolve(&parts, Some((rod, &factors, bend))).map_err(|e| DesignError {
                message: format!(
                    "{} when {} by {:.3} °C (a design must hold from -{TEMPERATURE_SPAN_K} to \
                 +{TEMPERATURE_SPAN_K} °C about its reference)",
                    e.message,
                    if delta > 0.0 { "warmed" } else { "cooled" },
                    delta.abs()
                ),
                ..e
            })?;
        // In a gradient a part grows more at its warmer end: the
        // displacement `α ∫ T dz` from the point it is held at is quadratic
        // along it, so besides its growth at its mean temperature its
        // centre of mass moves by `α G (o² - v)/2` (down), `o` the offset
        // of the held point from its centre and `v` its mass's variance of
        // height, and its ends by `α G (o² - h²/4)/2`, which moves what
        // rests on them or is held by them (nothing for a part held at an
        // end; the rod's own points are its bend above). Its inertia about
        // its centre changes only at second order.
        let shifts: Vec<(f64, f64)> = (0..self.parts.len())
            .map(|i| {
                let g = state(i).gradient;
                if g == 0.0 {
                    return (0.0, 0.0);
                }
                let (offset, variance, alpha) = self.gradient_lever(i, rod);
                let half = 0.5 * self.parts[i].shape.height();
                (
                    0.5 * alpha * g * (offset * offset - variance),
                    0.5 * alpha * g * (offset * offset - half * half),
                )
            })
            .collect();
        if shifts.iter().any(|&(c, e)| c != 0.0 || e != 0.0) {
            for (i, c) in centres.iter_mut().enumerate() {
                *c += shifts[i].0;
                // Down the chain of supports (resolved: no circles).
                let mut held_by = self.parts[i].placement.support();
                for _ in 0..self.parts.len() {
                    let Some(j) = held_by else { break };
                    *c += shifts[j].1;
                    held_by = self.parts[j].placement.support();
                }
            }
        }
        Ok(Self {
            parts,
            centres,
            gravity: self.gravity,
        })
    }

    /// For part `i` in a gradient (see [`CompoundPendulum::at_part_states`]):
    /// the offset of the point it is held at from its centre, m (its top
    /// for the rod and a suspension spring, which hang from above; its
    /// bottom for a part resting on another; the point given for a part
    /// held; its centre for a part placed by its centre, which the rod
    /// carries there), its mass's variance of height about its centre, m²
    /// ([`Shape::vertical_variance`]), and its growth in height per K (a
    /// liquid's volume's less its jar's width's).
    fn gradient_lever(&self, i: usize, rod: Option<usize>) -> (f64, f64, f64) {
        let p = &self.parts[i];
        let half = 0.5 * p.shape.height();
        let offset = match p.placement {
            _ if p.shape.is_spring() || rod == Some(i) => half,
            Placement::Centre(_) => 0.0,
            Placement::RestsOn(_) => half,
            Placement::Held { height, .. } => half - height,
        };
        let alpha = match (p.material.liquid, &p.placement) {
            (true, Placement::RestsOn(jar)) => {
                p.material.expansion - 2.0 * self.parts[*jar].material.expansion
            }
            _ => p.material.expansion,
        };
        (offset, p.shape.vertical_variance(), alpha)
    }

    /// The index of the rod: the first upright cylinder hanging from the
    /// pivot (its top within a millimetre of it, or of the bottom of the
    /// suspension spring the design hangs from).
    pub fn rod_index(&self) -> Option<usize> {
        self.rod()
    }

    fn rod(&self) -> Option<usize> {
        // Its top at the pivot, or at a suspension spring's bottom.
        let top = spring_index(&self.parts).map_or(0.0, |i| self.parts[i].shape.height());
        self.parts.iter().zip(&self.centres).position(|(p, &c)| {
            matches!(p.shape, Shape::Cylinder { .. })
                && (c - 0.5 * p.shape.height() - top).abs() < 1e-3
        })
    }

    /// The rate change per °C, s/day (negative: losing as it warms), to
    /// first order, by a central difference of ±0.5 °C on the exact model
    /// (its error is of order α², 1e-10 relative).
    pub fn temperature_coefficient(&self) -> f64 {
        // ±0.5 °C lies inside the span checked when the design was made.
        let l = |dt: f64| {
            self.at_temperature(dt)
                .map_or(f64::NAN, |p| p.properties().equivalent_length)
        };
        rate_of_length_ratio(l(0.5) / l(-0.5))
    }

    /// Each part's centre above the thermometer, m: the height at which a
    /// vertical temperature gradient is read. The thermometer is taken
    /// half-way down the pendulum (between the pivot and the bottom of its
    /// lowest part); for a compensated pendulum, whose rate does not move
    /// with the temperature there, where it hangs does not change what a
    /// gradient does.
    pub fn heights_above_thermometer(&self) -> Vec<f64> {
        let bottom = self
            .parts
            .iter()
            .zip(&self.centres)
            .map(|(p, &c)| c + 0.5 * p.shape.height())
            .fold(0.0, f64::max);
        self.centres.iter().map(|&c| 0.5 * bottom - c).collect()
    }

    /// The rate change per K/m of vertical temperature gradient (warmer
    /// upwards) at a constant temperature at the thermometer
    /// ([`CompoundPendulum::heights_above_thermometer`]), s/day: each part
    /// grows by the temperature along it (its length as at the temperature
    /// of its centre, its centre of mass moved towards its colder end when
    /// it hangs, its warmer end when it stands; see
    /// [`CompoundPendulum::at_part_states`]) and what the rod carries is
    /// moved by the rod's expansion down to it, by a central difference of
    /// ±0.5 K/m on the exact model (error of order α², 1e-10 relative).
    pub fn gradient_coefficient(&self) -> f64 {
        let heights = self.heights_above_thermometer();
        let l = |g: f64| {
            let states: Vec<PartState> = heights
                .iter()
                .map(|h| PartState {
                    temperature: g * h,
                    gradient: g,
                    ..PartState::default()
                })
                .collect();
            self.at_part_states(&states)
                .map_or(f64::NAN, |p| p.properties().equivalent_length)
        };
        rate_of_length_ratio(l(0.5) / l(-0.5))
    }

    /// The rate change per percentage point of relative humidity, s/day,
    /// when every part that takes up water has settled at wood's
    /// equilibrium moisture content ([`crate::moisture`]) in air of
    /// `humidity` (0 to 1) at `temperature_c`: by a central difference of
    /// ±1 point. `None` when no part takes up water.
    pub fn humidity_coefficient(&self, humidity: f64, temperature_c: f64) -> Option<f64> {
        if self
            .parts
            .iter()
            .all(|p| p.material.moisture_expansion.is_none())
        {
            return None;
        }
        let emc = |h: f64| crate::moisture::equilibrium_moisture_content(h, temperature_c);
        let h = humidity.clamp(0.02, 0.97);
        let reference = emc(h);
        let l = |dh: f64| {
            let states: Vec<PartState> = self
                .parts
                .iter()
                .map(|_| PartState {
                    moisture: emc(h + dh),
                    reference_moisture: reference,
                    ..PartState::default()
                })
                .collect();
            self.at_part_states(&states)
                .map_or(f64::NAN, |p| p.properties().equivalent_length)
        };
        Some(0.5 * rate_of_length_ratio(l(0.01) / l(-0.01)))
    }

    /// The mass, kg, to add on a regulating tray `at` m below the pivot
    /// (negative: to take off) to correct a clock gaining `rate` s/day:
    /// with `μ` there the equivalent length becomes `(I + μ at²) /
    /// (m d + μ at)`, set to `l (1 + rate/86400)²` and solved for `μ`.
    ///
    /// A mass whose size exceeds the pendulum's own is refused: no tray
    /// carries it, and none can give up more than it holds.
    pub fn tray_mass(&self, at: f64, rate: f64) -> Result<f64, RegulationError> {
        let p = self.properties();
        let target = p.equivalent_length + length_change_for_rate(p.equivalent_length, rate);
        let mass = (p.inertia - target * p.mass * p.centre_of_mass) / (target * at - at * at);
        if !(-p.mass..=p.mass).contains(&mass) {
            return Err(RegulationError::TrayTooHeavy {
                at,
                mass,
                pendulum_mass: p.mass,
            });
        }
        Ok(mass)
    }

    /// How far to move part `index` (and what rests on it) down, m
    /// (negative: up), to change the rate by `-rate` s/day: a clock gaining
    /// `rate` s/day is brought to time. The equivalent length must become
    /// `l (1 + rate/86400)²`; the move is found by Newton's method on the
    /// exact model (derivative by central differences of ±0.1 mm).
    ///
    /// The move is checked as a clockmaker would: the moved design must be
    /// a valid one (nothing at or above the pivot), and a part on the rod
    /// must stay on it (its centre between the pivot and the rod's end).
    pub fn regulation(&self, index: usize, rate: f64) -> Result<f64, RegulationError> {
        let name = self
            .parts
            .get(index)
            .map_or("?", |p| p.name.as_str())
            .to_string();
        if !matches!(
            self.parts.get(index).map(|p| &p.placement),
            Some(Placement::Centre(_))
        ) {
            return Err(RegulationError::RestsOnAnother { part: name });
        }
        if rate.is_nan() || rate.abs() >= DAY {
            return Err(RegulationError::Unreachable {
                part: name,
                why: "a rate change of a day a day or more".into(),
            });
        }
        let l = self.properties().equivalent_length;
        let target = l + length_change_for_rate(l, rate);
        let length_at = |shift: f64| self.length_with_shift(index, shift);
        let unreachable = |why: &str| RegulationError::Unreachable {
            part: name.clone(),
            why: why.to_string(),
        };
        let mut shift = 0.0;
        for _ in 0..50 {
            let h = 1e-4;
            let (Some(up), Some(down), Some(here)) =
                (length_at(shift + h), length_at(shift - h), length_at(shift))
            else {
                return Err(unreachable("the move would put a part above the pivot"));
            };
            let slope = (up - down) / (2.0 * h);
            if !slope.is_finite() || slope == 0.0 {
                return Err(unreachable("moving it does not change the length"));
            }
            let step = (target - here) / slope;
            shift += step;
            if !shift.is_finite() || shift.abs() > 1e3 * l {
                return Err(unreachable("no move of it reaches that length"));
            }
            if step.abs() < 1e-12 {
                break;
            }
        }
        if length_at(shift).is_none_or(|got| (got - target).abs() > 1e-9 * l) {
            return Err(unreachable("no move of it reaches that length"));
        }
        // The moved design, checked as a design; and a part on the rod
        // stays on it.
        let mut parts = self.parts.clone();
        if let Placement::Centre(c) = parts[index].placement {
            parts[index].placement = Placement::Centre(c + shift);
            if let Some(rod) = self.rod().filter(|&r| r != index) {
                let end = self.centres[rod] + 0.5 * self.parts[rod].shape.height();
                if c + shift > end || c + shift < 0.0 {
                    return Err(RegulationError::OffTheRod {
                        part: name,
                        shift,
                        rod_end: end,
                        centre: c,
                    });
                }
            }
        }
        CompoundPendulum::new(parts).map_err(|e| RegulationError::Invalid {
            part: name,
            shift,
            error: e,
        })?;
        Ok(shift)
    }
}

/// Why no regulation of a design gives a rate.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RegulationError {
    /// The part rests on another: move that one.
    #[error("'{part}' rests on another part; name the part it rests on")]
    RestsOnAnother {
        /// The part named.
        part: String,
    },
    /// No move of the part reaches the length.
    #[error("no move of '{part}' corrects that rate: {why}")]
    Unreachable {
        /// The part named.
        part: String,
        /// Why.
        why: String,
    },
    /// The move takes the part off the end of the rod (or above the pivot).
    #[error(
        "correcting that rate would move '{part}' {} mm {}, its centre to {} mm below the pivot, \
         off the rod (which ends {} mm below it)",
        crate::error::significant(1e3 * shift.abs()),
        if *shift >= 0.0 { "down" } else { "up" },
        crate::error::significant(1e3 * (centre + shift)),
        crate::error::significant(1e3 * rod_end)
    )]
    OffTheRod {
        /// The part.
        part: String,
        /// The move, m (positive: down).
        shift: f64,
        /// The rod's lower end below the pivot, m.
        rod_end: f64,
        /// The part's centre before the move, m.
        centre: f64,
    },
    /// The moved design is not a valid design.
    #[error("correcting that rate would move '{part}' {} mm: {error}", crate::error::significant(1e3 * shift))]
    Invalid {
        /// The part.
        part: String,
        /// The move, m.
        shift: f64,
        /// What is wrong with the moved design.
        error: DesignError,
    },
    /// A tray mass heavier than the pendulum (or taking off more than it
    /// weighs).
    #[error(
        "correcting that rate on a tray {} mm below the pivot takes {} kg, more than the \
         pendulum's {} kg: move the bob instead",
        crate::error::significant(1e3 * at),
        crate::error::significant(*mass),
        crate::error::significant(*pendulum_mass)
    )]
    TrayTooHeavy {
        /// The tray's place below the pivot, m.
        at: f64,
        /// The mass it would take, kg (negative: taken off).
        mass: f64,
        /// The pendulum's mass, kg.
        pendulum_mass: f64,
    },
}

impl CompoundPendulum {
    /// The equivalent length, m, with part `index` (and what rests on it)
    /// moved `shift` m down; `None` when that part rests on another, or the
    /// move puts a part above the pivot.
    fn length_with_shift(&self, index: usize, shift: f64) -> Option<f64> {
        let mut parts = self.parts.clone();
        let Placement::Centre(c) = parts.get(index)?.placement else {
            return None;
        };
        parts[index].placement = Placement::Centre(c + shift);
        let centres = resolve(&parts, None).ok()?;
        Some(
            Self {
                parts,
                centres,
                gravity: self.gravity,
            }
            .properties()
            .equivalent_length,
        )
    }

    /// The rate change, s/day per metre, of moving part `index` (and what
    /// rests on it) down: `-86400/(2l) dl/dx`, the derivative by a central
    /// difference of ±0.1 mm on the exact model (the equivalent length is
    /// a ratio of quadratics in the shift, so the difference's error is
    /// about (0.1 mm / l)², 1e-8 relative). Negative: lowering the bob
    /// slows the clock. Multiply by the nut's pitch for s/day per turn.
    /// `None` when the part rests on another (move what it rests on).
    pub fn rate_per_metre(&self, index: usize) -> Option<f64> {
        let h = 1e-4;
        let l = self.properties().equivalent_length;
        let slope =
            (self.length_with_shift(index, h)? - self.length_with_shift(index, -h)?) / (2.0 * h);
        Some(-0.5 * DAY * slope / l)
    }
}

/// A clock's rate in air against a vacuum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AirRates {
    /// Buoyancy and entrained air together, s/day.
    pub total: f64,
    /// Buoyancy alone, s/day.
    pub buoyancy: f64,
}

/// The move of a simple pendulum's bob, m (positive: down), that corrects
/// a clock gaining `rate` s/day: [`length_change_for_rate`], refused when
/// it would change the length by more than half (that is a new pendulum,
/// not a regulation: rates beyond about ±19,000 s/day).
pub fn length_regulation(length: f64, rate: f64) -> Result<f64, RegulationError> {
    let change = length_change_for_rate(length, rate);
    if !(-0.5 * length..=0.5 * length).contains(&change) {
        return Err(RegulationError::Unreachable {
            part: "bob".into(),
            why: format!(
                "the length would change by {}%: that is a new pendulum, not a regulation",
                crate::error::significant((100.0 * change / length).round())
            ),
        });
    }
    Ok(change)
}

/// The change of length, m, that corrects a clock of equivalent length
/// `length` m gaining `rate` s/day: `l ((1 + rate/86400)² - 1)` (positive:
/// lengthen), since the period goes as the square root of the length.
pub fn length_change_for_rate(length: f64, rate: f64) -> f64 {
    length * ((1.0 + rate / DAY).powi(2) - 1.0)
}

/// The rate change, s/day, of a clock whose equivalent length is
/// multiplied by `ratio`: `86400 (1/sqrt(ratio) - 1)`.
pub fn rate_of_length_ratio(ratio: f64) -> f64 {
    DAY * (1.0 / ratio.sqrt() - 1.0)
}

/// Each part's centre, `delta` °C from the reference, carried by a rod of
/// expansion `rod` (1/K) when there is one.
/// How the parts have grown from the design: the rod's index, each part's
/// growth along its length, and the rod's expansion times its temperature
/// gradient with its reference length.
type Grown<'a> = (Option<usize>, &'a [f64], (f64, f64));

/// `grown`: how the parts have grown (none: the parts as designed).
fn resolve(parts: &[Part], grown: Option<Grown<'_>>) -> Result<Vec<f64>, DesignError> {
    // Each part's centre follows its chain of supports down to a part
    // placed by its centre; every part is resolved once (linear in the
    // number of parts), and a chain that comes back on itself is a circle.
    let mut centres: Vec<Option<f64>> = vec![None; parts.len()];
    // A suspension spring hangs from the pivot and grows with its own
    // material; what is placed by its centre hangs from the spring's
    // bottom and grows below it with the rod.
    let growth = |i: usize| grown.map_or(1.0, |(_, f, _)| f.get(i).copied().unwrap_or(1.0));
    let rod = grown.and_then(|(rod, _, _)| rod).map_or(1.0, growth);
    let (bend, rod_length) = grown.map_or((0.0, 0.0), |(_, _, b)| b);
    let spring = spring_index(parts).map(|i| {
        let length = parts[i].shape.height();
        (i, length, length / growth(i))
    });
    let mut chain: Vec<usize> = Vec::new();
    let mut on_chain = vec![false; parts.len()];
    for start in 0..parts.len() {
        let mut i = start;
        let mut base = loop {
            if let Some(c) = centres[i] {
                break Some(c);
            }
            let p = &parts[i];
            match p.placement {
                Placement::Centre(c) => {
                    // The rod itself keeps its ends (its centre is their
                    // middle); what it carries moves with the point it is at.
                    let rod_index = grown.and_then(|(rod, _, _)| rod);
                    let grown = |c: f64| {
                        let x = c.clamp(0.0, rod_length);
                        let bent = if rod_index == Some(i) { 0.0 } else { bend };
                        c * rod + bent * x * 0.5 * (rod_length - x)
                    };
                    let carried = match spring {
                        Some((s, length, _)) if s == i => 0.5 * length,
                        Some((_, length, reference)) => length + grown(c - reference),
                        None => grown(c),
                    };
                    centres[i] = Some(carried);
                    break Some(carried);
                }
                Placement::RestsOn(j) | Placement::Held { part: j, .. } => {
                    if j >= parts.len() || j == i {
                        return Err(DesignError {
                            part: p.name.clone(),
                            field: "rests_on",
                            message: "names no other part".into(),
                        });
                    }
                    if on_chain[i] {
                        break None;
                    }
                    on_chain[i] = true;
                    chain.push(i);
                    i = j;
                }
            }
        };
        // Back up the chain: each part held by the one below it in the
        // chain (its bottom on that one's top, or the point it is held at
        // on that one's end).
        while let Some(k) = chain.pop() {
            on_chain[k] = false;
            let held = |j: usize, end: End, height: f64, holder: f64| {
                let half = 0.5 * parts[j].shape.height();
                let point = match end {
                    End::Top => holder - half,
                    End::Bottom => holder + half,
                };
                point + height - 0.5 * parts[k].shape.height()
            };
            let c = match (base, &parts[k].placement) {
                (Some(holder), Placement::RestsOn(j)) => Some(held(*j, End::Top, 0.0, holder)),
                (Some(holder), Placement::Held { part, end, height }) => {
                    Some(held(*part, *end, *height, holder))
                }
                _ => None,
            };
            if let Some(c) = c {
                centres[k] = Some(c);
                base = Some(c);
            }
        }
    }
    let mut out = Vec::with_capacity(parts.len());
    for (p, c) in parts.iter().zip(centres) {
        let Some(c) = c else {
            return Err(DesignError {
                part: p.name.clone(),
                field: "rests_on",
                message: "the parts rest on each other in a circle".into(),
            });
        };
        if !c.is_finite() {
            return Err(DesignError {
                part: p.name.clone(),
                field: "centre",
                message: "must be a finite number".into(),
            });
        }
        // Nothing above the pivot or through it (a rod may hang from it;
        // a top within 10 µm of the pivot is a dimension rounded, not a
        // part through it).
        if c - 0.5 * p.shape.height() < -PIVOT_TOLERANCE_M {
            return Err(DesignError {
                part: p.name.clone(),
                field: "centre",
                message: format!(
                    "its top would be {} mm above the pivot; parts hang below it",
                    crate::error::format_significant(-1e3 * (c - 0.5 * p.shape.height()), 4)
                ),
            });
        }
        out.push(c);
    }
    Ok(out)
}
