//! `pendulum design`: a design's datasheet (also a section of `report
//! --design`).

use super::common::{self, ResolvedGravity};
use crate::args::DesignArgs;
use crate::design::Design;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::air::air_density;
use pendulum_theory::compound::rate_of_length_ratio;
use pendulum_theory::Pendulum;
use serde::Serialize;

#[derive(Serialize)]
pub struct PartJson {
    name: String,
    material: String,
    mass_kg: f64,
    centre_m: f64,
}

#[derive(Serialize)]
pub struct DesignJson {
    file: String,
    parts: Vec<PartJson>,
    mass_kg: f64,
    centre_of_mass_m: f64,
    inertia_kg_m2: f64,
    equivalent_length_m: f64,
    /// Small swings, in a vacuum.
    period_s: f64,
    g_m_s2: f64,
    temperature_coefficient_s_per_day_per_c: f64,
    /// At `temperature_c` against `regulated_at_c`.
    temperature_rate_s_per_day: f64,
    temperature_c: f64,
    regulated_at_c: f64,
    air_density_kg_m3: f64,
    /// In that air against a vacuum: buoyancy and entrained air.
    air_rate_s_per_day: f64,
    air_buoyancy_rate_s_per_day: f64,
    /// The change per hPa of pressure at that temperature and humidity.
    pressure_coefficient_s_per_day_per_hpa: f64,
    /// The rating nut: the part with a thread, or the part named `nut`.
    #[serde(skip_serializing_if = "Option::is_none")]
    nut: Option<String>,
    /// The rate change as the nut (and the bob on it) moves 1 mm down,
    /// s/day (negative: slower).
    #[serde(skip_serializing_if = "Option::is_none")]
    nut_rate_s_per_day_per_mm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    nut_pitch_m: Option<f64>,
    /// ... per turn of the nut lowering the bob.
    #[serde(skip_serializing_if = "Option::is_none")]
    nut_rate_s_per_day_per_turn: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    nut_rate_s_per_day_per_division: Option<f64>,
}

/// The air a datasheet is given for, checked against the range of the
/// air-density formula.
pub struct Air {
    /// hPa.
    pub pressure_hpa: f64,
    /// °C.
    pub temperature_c: f64,
    /// %.
    pub humidity_pct: f64,
    /// The temperature the clock was regulated at, °C.
    pub regulated_at_c: f64,
}

impl Air {
    /// Standard air at 20 °C and 50 %, regulated at 20 °C.
    pub fn standard() -> Self {
        Self {
            pressure_hpa: 1013.25,
            temperature_c: 20.0,
            humidity_pct: 50.0,
            regulated_at_c: 20.0,
        }
    }

    fn check(&self) -> Result<(), CliError> {
        let ranges = [
            ("--pressure", self.pressure_hpa, 600.0, 1100.0, "hPa"),
            ("--temperature", self.temperature_c, -20.0, 60.0, "°C"),
            ("--humidity", self.humidity_pct, 0.0, 100.0, "%"),
            ("--regulated-at", self.regulated_at_c, -50.0, 100.0, "°C"),
        ];
        for (flag, value, low, high, unit) in ranges {
            if !(low..=high).contains(&value) {
                let got = if value.is_finite() {
                    format!(", got {}", num(value, 6))
                } else {
                    String::new()
                };
                return Err(CliError::flag(
                    flag,
                    format!("must lie between {low} and {high} {unit}{got}"),
                ));
            }
        }
        Ok(())
    }
}

/// The datasheet of `design` (read from `file`) under `gravity` in `air`.
pub fn datasheet(
    design: &Design,
    file: &str,
    gravity: &ResolvedGravity,
    air: &Air,
) -> Result<DesignJson, CliError> {
    air.check()?;
    let pendulum = &design.pendulum;
    let (p, t, h) = (
        air.pressure_hpa * 100.0,
        air.temperature_c,
        air.humidity_pct / 100.0,
    );
    let rho = air_density(p, t, h);
    let props = pendulum.properties();
    let period = Pendulum::new(props.equivalent_length, gravity.g_m_s2)
        .map_err(|e| CliError::input("--design", &e))?
        .small_angle_period();
    let warmer = pendulum
        .at_temperature(t - air.regulated_at_c)
        .map_err(|e| CliError::other(format!("{file}: {e}")))?
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
    Ok(DesignJson {
        file: file.to_string(),
        parts: pendulum
            .parts()
            .iter()
            .zip(pendulum.centres())
            .map(|(q, &c)| PartJson {
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
        g_m_s2: gravity.g_m_s2,
        temperature_coefficient_s_per_day_per_c: pendulum.temperature_coefficient(),
        temperature_rate_s_per_day: rate_of_length_ratio(warmer / props.equivalent_length),
        temperature_c: t,
        regulated_at_c: air.regulated_at_c,
        air_density_kg_m3: rho,
        air_rate_s_per_day: rates.total,
        air_buoyancy_rate_s_per_day: rates.buoyancy,
        pressure_coefficient_s_per_day_per_hpa: pendulum.pressure_coefficient(p, t, h),
        nut: per_metre.and(nut).map(|i| pendulum.parts()[i].name.clone()),
        nut_rate_s_per_day_per_mm: per_metre.map(|r| r * 1e-3),
        nut_pitch_m: per_metre.and(pitch),
        nut_rate_s_per_day_per_turn: per_turn,
        nut_rate_s_per_day_per_division: per_division.map(|(r, d)| r / f64::from(d)),
    })
}

/// The datasheet for people: (quantity, value) rows.
pub fn rows(d: &DesignJson, air: &Air, gravity: &ResolvedGravity) -> Vec<(String, String)> {
    let mut rows = Vec::new();
    for q in &d.parts {
        rows.push((
            format!("Part {}", q.name),
            format!(
                "{}, {} kg, centre {} mm below the pivot",
                q.material,
                num(q.mass_kg, 4),
                num(q.centre_m * 1e3, 5)
            ),
        ));
    }
    rows.push(("Mass".into(), format!("{} kg", num(d.mass_kg, 5))));
    rows.push((
        "Centre of mass".into(),
        format!("{} mm below the pivot", num(d.centre_of_mass_m * 1e3, 6)),
    ));
    rows.push((
        "Inertia".into(),
        format!("{} kg m² about the pivot", num(d.inertia_kg_m2, 6)),
    ));
    rows.push((
        "Equivalent length".into(),
        format!("{} m (I / m d)", num(d.equivalent_length_m, 7)),
    ));
    rows.push((
        "Period".into(),
        format!(
            "{} s (small swings, {})",
            num(d.period_s, 7),
            gravity.describe()
        ),
    ));
    rows.push((
        "Temperature".into(),
        format!(
            "{} s/day per °C; at {} °C against {} °C: {} s/day",
            num(d.temperature_coefficient_s_per_day_per_c, 4),
            num(d.temperature_c, 4),
            num(d.regulated_at_c, 4),
            num(d.temperature_rate_s_per_day, 4)
        ),
    ));
    rows.push((
        "Air".into(),
        format!(
            "{} kg/m³ ({} hPa, {} °C, {} %): {} s/day against a vacuum ({} from buoyancy)",
            num(d.air_density_kg_m3, 5),
            num(air.pressure_hpa, 6),
            num(d.temperature_c, 4),
            num(air.humidity_pct, 3),
            num(d.air_rate_s_per_day, 4),
            num(d.air_buoyancy_rate_s_per_day, 4)
        ),
    ));
    rows.push((
        "Barometer".into(),
        format!(
            "{} s/day per hPa ({} per inHg)",
            num(d.pressure_coefficient_s_per_day_per_hpa, 4),
            num(d.pressure_coefficient_s_per_day_per_hpa * 33.8639, 4)
        ),
    ));
    if let (Some(name), Some(per_mm)) = (&d.nut, d.nut_rate_s_per_day_per_mm) {
        let mut text = format!("{} s/day per mm the {name} moves down", num(per_mm, 4));
        if let (Some(p), Some(turn)) = (d.nut_pitch_m, d.nut_rate_s_per_day_per_turn) {
            text.push_str(&format!(
                "; {} s/day per turn ({} mm pitch)",
                num(turn, 4),
                num(p * 1e3, 4)
            ));
        }
        if let Some(div) = d.nut_rate_s_per_day_per_division {
            text.push_str(&format!("; {} s/day per division", num(div, 4)));
        }
        rows.push(("Nut".into(), text));
    }
    rows
}

pub fn run(args: &DesignArgs) -> Result<String, CliError> {
    let design = crate::design::read_design(&args.file)?;
    let gravity = common::gravity(&args.gravity)?;
    let air = Air {
        pressure_hpa: args.pressure,
        temperature_c: args.temperature,
        humidity_pct: args.humidity,
        regulated_at_c: args.regulated_at,
    };
    let result = datasheet(&design, &args.file.display().to_string(), &gravity, &air)?;
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    for (k, v) in rows(&result, &air, &gravity) {
        s.row(&k, v);
    }
    Ok(s.render())
}
