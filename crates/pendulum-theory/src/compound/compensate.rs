//! Temperature compensation as one analysis: a design's temperature
//! coefficient and the compensator that cancels it, a tube or collar under
//! the bob, a tube inside a tube (zinc in steel), a steel and brass
//! gridiron in place of the rod, or a jar of mercury in place of the bob,
//! with the compensated design. The command
//! line's `compensate` and Python's `compensate` are this call; the
//! defaults (a glass jar of 4 mm walls, a tube 1 mm over the rod with
//! 1.5 mm walls) live here.

use super::description::Design;
use super::{CompoundPendulum, Material, Placement, Shape};
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
    /// a tube inside a tube (`zinc-steel`), `gridiron` or `mercury`; none:
    /// the coefficient alone.
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
    /// Its bore, m (for a tube inside a tube, the outer tube's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tube_bore_m: Option<f64>,
    /// For a tube inside a tube: the inner tube's material (standing on
    /// the nut), the outer's being the one it carries the bob by.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inner_tube_material: Option<String>,
    /// For a tube inside a tube: the outer tube's material.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub outer_tube_material: Option<String>,
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
    /// The compensated design's rate against the design as given, s/day
    /// (its period kept: within a few 1e-9 s/day unless a warning says it
    /// could not be kept).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compensated_rate_s_per_day: Option<f64>,
    /// How far the support of the bob (its rating nut, or the bob itself)
    /// was moved to keep the period, m (positive: down).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regulation_shift_m: Option<f64>,
    /// The part moved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regulation_part: Option<String>,
    /// The move in turns of the rating nut (positive: down), when the
    /// design states its thread and the nut alone moved.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub regulation_turns: Option<f64>,
    /// Whether the move was beyond the nut's travel ([`NUT_TRAVEL_M`]) or
    /// its rod, so that the rod was made as much shorter (or longer).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rod_follows: Option<bool>,
    /// What the result's own checks found.
    pub warnings: Vec<CompensationWarning>,
    /// The compensated design.
    #[serde(skip)]
    pub compensated: Option<CompoundPendulum>,
}

/// Something the result's own checks found.
#[derive(Clone, Debug, PartialEq)]
pub enum CompensationWarning {
    /// No move of the bob's support (nor of the rod with it) gives the
    /// compensated design the original's period: the design is written as
    /// sized, to be regulated by hand.
    PeriodNotKept {
        /// The part the compensator carries or replaces.
        part: String,
    },
}

impl crate::warning::Warn for CompensationWarning {
    fn code(&self) -> &'static str {
        match self {
            CompensationWarning::PeriodNotKept { .. } => "period_not_kept",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            CompensationWarning::PeriodNotKept { .. } => Some("period_s"),
        }
    }
}

impl std::fmt::Display for CompensationWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CompensationWarning::PeriodNotKept { part } => write!(
                f,
                "the compensated design's period could not be kept by moving the '{part}' or its support (it has none placed on the rod): regulate it to its beat"
            ),
        }
    }
}

crate::warning::serialize_as_warning!(CompensationWarning);

/// The index of the part `name`.
fn part_index(design: &CompoundPendulum, name: &str) -> Result<usize, Refusal> {
    design
        .parts()
        .iter()
        .position(|p| p.name == name)
        .ok_or_else(|| Refusal::field("part", format!("the design has no part named '{name}'")))
}

/// The diameter of the design's rod (the first upright cylinder hanging
/// from the pivot), or the refusal saying it has none.
fn rod_diameter(design: &CompoundPendulum) -> Result<f64, Refusal> {
    design
        .rod_index()
        .and_then(|i| match design.parts()[i].shape {
            Shape::Cylinder { diameter, .. } => Some(diameter),
            _ => None,
        })
        .ok_or_else(|| Refusal::field("design", "has no rod hanging from the pivot"))
}

/// A tube inside a tube named as `inner-outer` or `inner in outer`
/// (`zinc-steel`, `zinc in steel`): the two names, or `None`.
fn tube_pair(name: &str) -> Option<(&str, &str)> {
    name.split_once(" in ")
        .or_else(|| name.split_once('-'))
        .map(|(a, b)| (a.trim(), b.trim()))
        .filter(|(a, b)| !a.is_empty() && !b.is_empty())
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
/// and the compensated design, regulated back to the original's period:
/// the bob's support (its rating nut) moved along the rod, or, beyond
/// [`NUT_TRAVEL_M`], the rod made shorter or longer with it (see
/// [`Compensation::regulation_shift_m`]).
pub fn compensate(read: &Design, input: &CompensateInput) -> Result<Compensation, Refusal> {
    let design = &read.pendulum;
    let part = input.part.as_deref().unwrap_or(DEFAULT_PART);
    let before = design.temperature_coefficient();
    let original = design.properties().equivalent_length;
    let mut result = Compensation {
        temperature_coefficient_s_per_day_per_c: before,
        equivalent_length_m: original,
        ..Compensation::default()
    };
    let Some(unregulated) = sized(design, input, part, before, &mut result)? else {
        return Ok(result);
    };
    let support = support_of(design, part);
    let regulated = support.and_then(|nut| {
        // The nut alone while it stays on the rod and within its travel;
        // else the rod follows it.
        let solve = |follow| {
            keep_period(original, |shift| {
                let moved = design.moved(nut, shift, follow)?;
                sized(&moved, input, part, before, &mut result.clone()).ok()?
            })
        };
        match solve(false) {
            Some(shift) if shift.abs() <= NUT_TRAVEL_M => Some((shift, false)),
            _ => solve(true).map(|shift| (shift, true)),
        }
    });
    let compensated = match regulated {
        Some((shift, follow)) => {
            let moved = design
                .moved(support.unwrap_or(0), shift, follow)
                .ok_or_else(|| Refusal::data("the regulated design could not be built"))?;
            result.regulation_shift_m = Some(shift);
            result.rod_follows = Some(follow);
            result.regulation_part = support.map(|i| design.parts()[i].name.clone());
            result.regulation_turns = read
                .thread
                .as_ref()
                .filter(|t| Some(t.part) == support && !follow)
                .map(|t| shift / t.pitch);
            sized(&moved, input, part, before, &mut result)?
        }
        None => {
            result.warnings.push(CompensationWarning::PeriodNotKept {
                part: part.to_string(),
            });
            Some(unregulated)
        }
    };
    if let Some(c) = &compensated {
        let l = c.properties().equivalent_length;
        result.compensated_coefficient_s_per_day_per_c = Some(c.temperature_coefficient());
        result.compensated_equivalent_length_m = Some(l);
        result.compensated_rate_s_per_day = Some(super::rate_of_length_ratio(l / original));
    }
    result.compensated = compensated;
    Ok(result)
}

/// How far a rating nut is taken to travel either way on its thread, m:
/// 20 mm, about ±850 s/day on a seconds pendulum. A compensated design
/// whose period needs a longer move has its rod made shorter (or longer)
/// instead.
pub const NUT_TRAVEL_M: f64 = 0.02;

/// The part that carries `part` and is placed by its centre (the rating
/// nut a bob rests on, or the bob itself when it is placed on the rod).
fn support_of(design: &CompoundPendulum, part: &str) -> Option<usize> {
    let mut i = part_index(design, part).ok()?;
    for _ in 0..design.parts().len() {
        match design.parts()[i].placement {
            Placement::Centre(_) => return Some(i),
            Placement::RestsOn(j) | Placement::Held { part: j, .. } => i = j,
        }
    }
    None
}

/// The move, m (positive: down), of the support at which `build` gives a
/// design of equivalent length `target`: the secant method from no move
/// and the length's difference (the equivalent length moves about one for
/// one with the bob), to 1e-13 of the length (or 1e-11 where the rounding
/// of the nested solve stops the steps), or `None`.
fn keep_period(target: f64, build: impl Fn(f64) -> Option<CompoundPendulum>) -> Option<f64> {
    let miss = |shift: f64| build(shift).map(|c| c.properties().equivalent_length - target);
    let (mut a, mut fa) = (0.0, miss(0.0)?);
    let mut b = -fa;
    let mut fb = miss(b)?;
    for _ in 0..40 {
        // Converged; or the steps are down in the rounding of the nested
        // solves (each design's compensator is itself found by a solve)
        // with the length within 1e-11 of the target (1e-6 s/day).
        if fb.abs() <= 1e-13 * target
            || ((b - a).abs() <= 1e-14 * target && fb.abs() <= 1e-11 * target)
        {
            return Some(b);
        }
        if fb == fa {
            return None;
        }
        let next = b - fb * (b - a) / (fb - fa);
        if !next.is_finite() || next.abs() > target {
            return None;
        }
        (a, fa) = (b, fb);
        b = next;
        fb = miss(b)?;
    }
    None
}

/// `design`'s compensator sized, its sizes set in `result`; `None` when no
/// compensator was asked for.
fn sized(
    design: &CompoundPendulum,
    input: &CompensateInput,
    part: &str,
    before: f64,
    result: &mut Compensation,
) -> Result<Option<CompoundPendulum>, Refusal> {
    let kind = input.compensator.as_deref().map(str::to_ascii_lowercase);
    let sizing = Sizing {
        design,
        input,
        part,
        before,
    };
    let compensated = match kind.as_deref() {
        None => None,
        Some("gridiron") => Some(sizing.gridiron(result)?),
        Some("mercury") | Some("mercury jar") | Some("jar") => Some(sizing.mercury_jar(result)?),
        Some(name)
            if tube_pair(name).is_some_and(|(a, b)| {
                Material::named(a).is_some() && Material::named(b).is_some()
            }) =>
        {
            Some(sizing.tube_in_tube(name, result)?)
        }
        Some(name) => Some(sizing.tube(name, result)?),
    };
    Ok(compensated)
}

/// What sizing a compensator for a design takes: the design, the sizes
/// asked for, the part the compensator goes under or replaces, and the
/// design's temperature coefficient before it, s/day per °C.
struct Sizing<'a> {
    /// The design to compensate.
    design: &'a CompoundPendulum,
    /// The compensator asked for and its sizes.
    input: &'a CompensateInput,
    /// The part a tube goes under or a jar replaces.
    part: &'a str,
    /// The design's coefficient, s/day per °C.
    before: f64,
}

impl Sizing<'_> {
    /// The refusal of a tube (`what`: "a tube") when the design is already
    /// compensated or already gains as it warms: a tube lifts the bob as
    /// it warms, so it can only cancel a loss. `None` when it can.
    fn lifting(&self, what: &str) -> Option<Refusal> {
        let before = self.before;
        if before.abs() < 1e-6 {
            return Some(Refusal::field(
                "compensator",
                format!(
                    "the design is already compensated ({} s/day per °C): nothing to size",
                    format_significant(before, 3)
                ),
            ));
        }
        (before > 0.0).then(|| {
            Refusal::field(
                "compensator",
                format!(
                    "the design already gains as it warms ({} s/day per °C): {what} lifting the {} would add to it; support the bob nearer its centre, or use a rod that expands more",
                    format_significant(before, 3),
                    self.part
                ),
            )
        })
    }

    /// The design with a steel and brass gridiron in place of its rod,
    /// the brass in its series, m, set in `result`.
    fn gridiron(&self, result: &mut Compensation) -> Result<CompoundPendulum, Refusal> {
        let (steel, brass) = (
            Material::named("steel").ok_or_else(|| Refusal::data("steel is not in the table"))?,
            Material::named("brass").ok_or_else(|| Refusal::data("brass is not in the table"))?,
        );
        let (compensated, brass_length) =
            self.design.with_gridiron(&steel, &brass).ok_or_else(|| {
                Refusal::field(
                    "compensator",
                    "no steel and brass gridiron of this rod's drop cancels the coefficient (the design needs a rod hanging from the pivot)",
                )
            })?;
        result.compensator = Some("gridiron".into());
        result.brass_length_m = Some(brass_length);
        Ok(compensated)
    }

    /// The design with a jar of mercury in place of the part: the
    /// mercury's height, m, and mass, kg, and the jar's material, diameter
    /// and wall, m, set in `result`.
    fn mercury_jar(&self, result: &mut Compensation) -> Result<CompoundPendulum, Refusal> {
        let (design, input, part) = (self.design, self.input, self.part);
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
        Ok(compensated)
    }

    /// The design with a tube inside a tube under the part, named `name`
    /// (`zinc-steel`, `zinc in steel`), sized from the rod: the tubes'
    /// materials, length, m, and the outer tube's diameter and bore, m,
    /// set in `result`.
    fn tube_in_tube(
        &self,
        name: &str,
        result: &mut Compensation,
    ) -> Result<CompoundPendulum, Refusal> {
        let (design, input, part) = (self.design, self.input, self.part);
        let (inner_name, outer_name) = tube_pair(name).unwrap_or_default();
        let inner = table_material("compensator", inner_name)?;
        let outer = table_material("compensator", outer_name)?;
        for (field, given) in [
            ("tube_diameter", input.tube_diameter),
            ("tube_bore", input.tube_bore),
        ] {
            if given.is_some() {
                return Err(Refusal::field(
                    field,
                    "is for a single tube: a tube inside a tube is sized from the rod (each \
                     bore 1 mm over what it surrounds, walls of 1.5 mm)",
                ));
            }
        }
        if let Some(e) = self.lifting("a tube inside a tube") {
            return Err(e);
        }
        if inner.liquid || outer.liquid {
            return Err(Refusal::field(
                "compensator",
                "a liquid goes in a jar: give --compensator mercury",
            ));
        }
        let bob = part_index(design, part)?;
        let rod_diameter = rod_diameter(design)?;
        let (compensated, length) = design
            .with_tube_in_tube(bob, inner.clone(), outer.clone(), rod_diameter, TUBE_WALL_M)
            .map_err(|why| {
                no_tube(
                    why,
                    &format!("{} tube inside a {} tube", inner.name, outer.name),
                    part,
                    "the inner tube must expand more than the outer and the rod together",
                )
            })?;
        let tube = |name: &str| {
            compensated
                .parts()
                .iter()
                .find(|p| p.name == name)
                .map(|p| p.shape)
        };
        if let Some(Shape::Cylinder { diameter, bore, .. }) = tube("outer tube") {
            result.tube_diameter_m = Some(diameter);
            result.tube_bore_m = Some(bore);
        }
        result.compensator = Some(format!("{} in {}", inner.name, outer.name));
        result.inner_tube_material = Some(inner.name.clone());
        result.outer_tube_material = Some(outer.name.clone());
        result.tube_length_m = Some(length);
        Ok(compensated)
    }

    /// The material of a single tube named `name` (`collar`: brass);
    /// refused when the name is one side of a pair, not in the table, or a
    /// liquid.
    fn tube_material(&self, name: &str) -> Result<Material, Refusal> {
        // "zinc-" or "in steel": a pair with a side missing, not zinc.
        let trimmed = name.trim();
        if trimmed.starts_with('-')
            || trimmed.ends_with('-')
            || trimmed.starts_with("in ")
            || trimmed.ends_with(" in")
        {
            return Err(Refusal::field(
                "compensator",
                format!(
                    "'{name}' names one tube of a pair: give both, inner-outer (zinc-steel) \
                     or inner in outer"
                ),
            ));
        }
        let material = table_material(
            "compensator",
            if name == "collar" { "brass" } else { name },
        )
        .map_err(|_| {
            Refusal::field(
                "compensator",
                format!(
                    "'{name}' is neither gridiron, mercury, collar, a tube in a tube (zinc-steel) nor a material of the table ({})",
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
        Ok(material)
    }

    /// A single tube's bore and outer diameter, m, as given or by default
    /// (1 mm over the rod of `rod_diameter`, m, and walls of 1.5 mm);
    /// refused unless the bore clears the rod and the diameter the bore.
    fn tube_size(&self, rod_diameter: f64) -> Result<(f64, f64), Refusal> {
        let input = self.input;
        let bore = positive_length(
            "tube_bore",
            input.tube_bore.unwrap_or(rod_diameter + TUBE_CLEARANCE_M),
        )?;
        if bore <= rod_diameter {
            return Err(Refusal::field(
                "tube_bore",
                format!(
                    "the tube's bore ({} mm) must clear the rod ({} mm across)",
                    format_significant(bore * 1e3, 4),
                    format_significant(rod_diameter * 1e3, 4)
                ),
            ));
        }
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
        Ok((bore, diameter))
    }

    /// The design with a single tube (or collar) of the material `name`
    /// under the part: its material, length, diameter and bore, m, set in
    /// `result`.
    fn tube(&self, name: &str, result: &mut Compensation) -> Result<CompoundPendulum, Refusal> {
        let material = self.tube_material(name)?;
        let bob = part_index(self.design, self.part)?;
        if let Some(e) = self.lifting("a tube") {
            return Err(e);
        }
        let rod_diameter = rod_diameter(self.design)?;
        let (bore, diameter) = self.tube_size(rod_diameter)?;
        let (compensated, length) = self
            .design
            .with_compensating_tube(bob, material.clone(), diameter, bore)
            .map_err(|why| {
                no_tube(
                    why,
                    &format!("{} tube", material.name),
                    self.part,
                    "the tube must expand more than the rod, by enough to lift the bob over \
                     its length: zinc (30e-6/K) or a tube inside a tube",
                )
            })?;
        result.compensator = Some(material.name);
        result.tube_length_m = Some(length);
        result.tube_diameter_m = Some(diameter);
        result.tube_bore_m = Some(bore);
        Ok(compensated)
    }
}

/// The refusal of a tube compensator (`what`: "zinc tube") under the part
/// `part`, by the reason it could not be sized; `need` says what a tube
/// must do.
fn no_tube(why: super::compensator::NoCompensation, what: &str, part: &str, need: &str) -> Refusal {
    use super::compensator::NoCompensation as Why;
    let message = match why {
        Why::NotCarried => format!(
            "the '{part}' does not rest on or hang from another part: a {what} goes between \
             it and the nut it rests on"
        ),
        Why::SupportNotOnRod => format!(
            "what the '{part}' rests on is not placed on the rod by its centre (a nut): a \
             {what} stands on a nut on the rod"
        ),
        Why::NoRod => format!("the design has no rod hanging from the pivot for a {what}"),
        Why::SameSign {
            smallest,
            largest,
            size,
        } => format!(
            "no {what} from 0.1 mm to {} m long cancels this design's coefficient: it goes \
             from {} to {} s/day per °C over those lengths ({need})",
            format_significant(size, 3),
            format_significant(smallest, 3),
            format_significant(largest, 3)
        ),
        Why::Unbuildable => format!(
            "a {what} long enough would reach the pivot (or the design could not be made \
             with it)"
        ),
    };
    Refusal::field("compensator", message)
}
