//! A design's datasheet as one analysis: its parts, mass, inertia,
//! equivalent length and period, its temperature and barometric
//! coefficients, the air's effect and the rating nut's, in an air and at
//! a temperature checked against the range of the air-density formula.
//! The command line's `design` and Python's `design` are this call.

use super::description::Design;
use super::rate_of_length_ratio;
use crate::air::{air_density, PRESSURE_RANGE_PA, TEMPERATURE_RANGE_C};
use crate::analysis::Refusal;
use crate::error::format_significant;
use crate::pendulum::{Pendulum, STANDARD_GRAVITY};
use serde::Serialize;

/// The air a datasheet is for when none is given: standard pressure, Pa.
pub const DEFAULT_PRESSURE_PA: f64 = 101_325.0;
/// The temperature when none is given, °C (also where it was regulated).
pub const DEFAULT_TEMPERATURE_C: f64 = 20.0;
/// Relative humidity when none is given (0 to 1).
pub const DEFAULT_HUMIDITY: f64 = 0.5;
/// Temperatures a clock may have been regulated at, °C.
pub const REGULATED_AT_RANGE_C: (f64, f64) = (-50.0, 100.0);

/// The air and temperature a datasheet is for; every `None` the default.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Air {
    /// Pressure, Pa.
    pub pressure_pa: Option<f64>,
    /// Temperature, °C.
    pub temperature_c: Option<f64>,
    /// Relative humidity, 0 to 1.
    pub humidity: Option<f64>,
    /// The temperature the clock was regulated at, °C (default the
    /// temperature's default).
    pub regulated_at_c: Option<f64>,
}

/// One part's row.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PartRow {
    /// Its name.
    pub name: String,
    /// Its material.
    pub material: String,
    /// Its mass, kg.
    pub mass_kg: f64,
    /// Its centre below the pivot, m.
    pub centre_m: f64,
}

/// A design's datasheet.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Datasheet {
    /// The parts.
    pub parts: Vec<PartRow>,
    /// Mass, kg.
    pub mass_kg: f64,
    /// Centre of mass below the pivot, m.
    pub centre_of_mass_m: f64,
    /// Inertia about the pivot, kg m².
    pub inertia_kg_m2: f64,
    /// Equivalent simple length `I / m d`, m.
    pub equivalent_length_m: f64,
    /// Small swings, in a vacuum, s.
    pub period_s: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// Rate change per °C, s/day.
    pub temperature_coefficient_s_per_day_per_c: f64,
    /// At `temperature_c` against `regulated_at_c`, s/day.
    pub temperature_rate_s_per_day: f64,
    /// The temperature, °C.
    pub temperature_c: f64,
    /// Where it was regulated, °C.
    pub regulated_at_c: f64,
    /// The air's density, kg/m³.
    pub air_density_kg_m3: f64,
    /// In that air against a vacuum (buoyancy and entrained air), s/day.
    pub air_rate_s_per_day: f64,
    /// Of which buoyancy, s/day.
    pub air_buoyancy_rate_s_per_day: f64,
    /// The change per hPa of pressure at that temperature and humidity.
    pub pressure_coefficient_s_per_day_per_hpa: f64,
    /// The rating nut: the part with a thread, or the part named `nut`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut: Option<String>,
    /// The rate change as the nut (and the bob on it) moves 1 mm down,
    /// s/day (negative: slower).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_rate_s_per_day_per_mm: Option<f64>,
    /// The nut's pitch, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_pitch_m: Option<f64>,
    /// Per turn of the nut lowering the bob, s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_rate_s_per_day_per_turn: Option<f64>,
    /// Per division of the nut, s/day.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nut_rate_s_per_day_per_division: Option<f64>,
    /// What to check before trusting the sheet.
    pub warnings: Vec<String>,
    /// The air as taken: pressure, Pa.
    #[serde(skip)]
    pub pressure_pa: f64,
    /// Relative humidity, 0 to 1.
    #[serde(skip)]
    pub humidity: f64,
}

/// Checks `value` within `range` (in the unit shown, `scale` times the
/// value's).
fn within(
    field: &'static str,
    value: f64,
    range: (f64, f64),
    scale: f64,
    unit: &str,
) -> Result<f64, Refusal> {
    if (range.0..=range.1).contains(&value) {
        return Ok(value);
    }
    let got = if value.is_finite() {
        format!(", got {}", format_significant(value * scale, 6))
    } else {
        String::new()
    };
    Err(Refusal::field(
        field,
        format!(
            "must lie between {} and {} {unit}{got}",
            range.0 * scale,
            range.1 * scale
        ),
    ))
}

/// The datasheet of `design` under `g` (default standard gravity) in
/// `air`.
pub fn datasheet(design: &Design, g: Option<f64>, air: &Air) -> Result<Datasheet, Refusal> {
    let p = within(
        "pressure",
        air.pressure_pa.unwrap_or(DEFAULT_PRESSURE_PA),
        PRESSURE_RANGE_PA,
        0.01,
        "hPa",
    )?;
    let t = within(
        "temperature",
        air.temperature_c.unwrap_or(DEFAULT_TEMPERATURE_C),
        TEMPERATURE_RANGE_C,
        1.0,
        "°C",
    )?;
    let h = within(
        "humidity",
        air.humidity.unwrap_or(DEFAULT_HUMIDITY),
        (0.0, 1.0),
        100.0,
        "%",
    )?;
    let regulated_at = within(
        "regulated_at",
        air.regulated_at_c.unwrap_or(DEFAULT_TEMPERATURE_C),
        REGULATED_AT_RANGE_C,
        1.0,
        "°C",
    )?;
    let g = crate::analysis::require_finite("g", g.unwrap_or(STANDARD_GRAVITY))?;
    let pendulum = &design.pendulum;
    let rho = air_density(p, t, h);
    let props = pendulum.properties();
    let period = Pendulum::new(props.equivalent_length, g)
        .map_err(|e| match e.quantity {
            crate::error::Quantity::Gravity => Refusal::input("g", &e),
            _ => Refusal::input("design", &e),
        })?
        .small_angle_period();
    let warmer = pendulum
        .at_temperature(t - regulated_at)
        .map_err(|e| Refusal::data(e.to_string()))?
        .properties()
        .equivalent_length;
    let rates = pendulum.rate_in_air(rho);
    let nut = design
        .thread
        .map(|th| th.part)
        .or_else(|| pendulum.parts().iter().position(|q| q.name == "nut"));
    let per_metre = nut.and_then(|i| pendulum.rate_per_metre(i));
    let pitch = design.thread.map(|th| th.pitch);
    let per_turn = per_metre.zip(pitch).map(|(r, p)| r * p);
    let per_division = per_turn.zip(design.thread.and_then(|th| th.divisions));
    Ok(Datasheet {
        parts: pendulum
            .parts()
            .iter()
            .zip(pendulum.centres())
            .map(|(q, &c)| PartRow {
                name: q.name.clone(),
                material: q.material.name.clone(),
                mass_kg: q.mass(),
                centre_m: c,
            })
            .collect(),
        mass_kg: props.mass,
        centre_of_mass_m: props.centre_of_mass,
        inertia_kg_m2: props.inertia,
        equivalent_length_m: props.equivalent_length,
        period_s: period,
        g_m_s2: g,
        temperature_coefficient_s_per_day_per_c: pendulum.temperature_coefficient(),
        temperature_rate_s_per_day: rate_of_length_ratio(warmer / props.equivalent_length),
        temperature_c: t,
        regulated_at_c: regulated_at,
        air_density_kg_m3: rho,
        air_rate_s_per_day: rates.total,
        air_buoyancy_rate_s_per_day: rates.buoyancy,
        pressure_coefficient_s_per_day_per_hpa: pendulum.pressure_coefficient(p, t, h),
        nut: per_metre.and(nut).map(|i| pendulum.parts()[i].name.clone()),
        nut_rate_s_per_day_per_mm: per_metre.map(|r| r * 1e-3),
        nut_pitch_m: per_metre.and(pitch),
        nut_rate_s_per_day_per_turn: per_turn,
        nut_rate_s_per_day_per_division: per_division.map(|(r, d)| r / f64::from(d)),
        warnings: crate::pendulum::length_warning(props.equivalent_length)
            .into_iter()
            .collect(),
        pressure_pa: p,
        humidity: h,
    })
}
