//! `pendulum design`: a design's datasheet.

use super::common;
use crate::args::DesignArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::air::air_density;
use pendulum_theory::compound::rate_of_length_ratio;
use pendulum_theory::Pendulum;
use serde::Serialize;

#[derive(Serialize)]
struct PartJson {
    name: String,
    material: String,
    mass_kg: f64,
    centre_m: f64,
}

#[derive(Serialize)]
struct DesignJson {
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
}

pub fn run(args: &DesignArgs) -> Result<String, CliError> {
    let design = crate::design::read(&args.file)?;
    let gravity = common::gravity(&args.gravity)?;
    let (p, t, h) = (
        args.pressure * 100.0,
        args.temperature,
        args.humidity / 100.0,
    );
    // The air formula's range, each flag on its own.
    if !(600.0..=1100.0).contains(&args.pressure) {
        return Err(CliError::flag(
            "--pressure",
            format!("must lie between 600 and 1100 hPa, got {}", args.pressure),
        ));
    }
    if !(-20.0..=60.0).contains(&t) {
        return Err(CliError::flag(
            "--temperature",
            format!("must lie between -20 and 60 °C, got {t}"),
        ));
    }
    if !(0.0..=100.0).contains(&args.humidity) {
        return Err(CliError::flag(
            "--humidity",
            format!("must lie between 0 and 100 %, got {}", args.humidity),
        ));
    }
    let rho = air_density(p, t, h);
    if !(-50.0..=100.0).contains(&args.regulated_at) {
        return Err(CliError::flag(
            "--regulated-at",
            "must lie between -50 and 100 °C",
        ));
    }
    let props = design.properties();
    let period = Pendulum::new(props.equivalent_length, gravity.g_m_s2)
        .map_err(|e| CliError::input("--design", &e))?
        .small_angle_period();
    let warmer = design
        .at_temperature(t - args.regulated_at)
        .properties()
        .equivalent_length;
    let air = design.rate_in_air(rho);
    let per_hpa = design.pressure_coefficient(p, t, h);
    let result = DesignJson {
        file: args.file.display().to_string(),
        parts: design
            .parts()
            .iter()
            .zip(design.centres())
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
        temperature_coefficient_s_per_day_per_c: design.temperature_coefficient(),
        temperature_rate_s_per_day: rate_of_length_ratio(warmer / props.equivalent_length),
        temperature_c: t,
        regulated_at_c: args.regulated_at,
        air_density_kg_m3: rho,
        air_rate_s_per_day: air.total,
        air_buoyancy_rate_s_per_day: air.buoyancy,
        pressure_coefficient_s_per_day_per_hpa: per_hpa,
    };
    if args.json {
        return output::json(&result);
    }
    let mut s = Summary::default();
    for q in &result.parts {
        s.row(
            &format!("Part {}", q.name),
            format!(
                "{}, {} kg, centre {} mm below the pivot",
                q.material,
                num(q.mass_kg, 4),
                num(q.centre_m * 1e3, 5)
            ),
        );
    }
    s.row("Mass", format!("{} kg", num(result.mass_kg, 5)))
        .row(
            "Centre of mass",
            format!(
                "{} mm below the pivot",
                num(result.centre_of_mass_m * 1e3, 6)
            ),
        )
        .row(
            "Inertia",
            format!("{} kg m² about the pivot", num(result.inertia_kg_m2, 6)),
        )
        .row(
            "Equivalent length",
            format!("{} m (I / m d)", num(result.equivalent_length_m, 7)),
        )
        .row(
            "Period",
            format!(
                "{} s (small swings, {})",
                num(period, 7),
                gravity.describe()
            ),
        )
        .row(
            "Temperature",
            format!(
                "{} s/day per °C; at {} °C against {} °C: {} s/day",
                num(result.temperature_coefficient_s_per_day_per_c, 4),
                num(t, 4),
                num(args.regulated_at, 4),
                num(result.temperature_rate_s_per_day, 4)
            ),
        )
        .row(
            "Air",
            format!(
                "{} kg/m³ ({} hPa, {} °C, {} %): {} s/day against a vacuum ({} from buoyancy)",
                num(rho, 5),
                num(args.pressure, 6),
                num(t, 4),
                num(args.humidity, 3),
                num(result.air_rate_s_per_day, 4),
                num(result.air_buoyancy_rate_s_per_day, 4)
            ),
        )
        .row(
            "Barometer",
            format!(
                "{} s/day per hPa ({} per inHg)",
                num(per_hpa, 4),
                num(per_hpa * 33.8639, 4)
            ),
        );
    Ok(s.render())
}
