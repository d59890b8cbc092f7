//! `pendulum design`: a design's datasheet (also a section of `report
//! --design`).

use super::common::{self, ResolvedGravity};
use crate::args::DesignArgs;
use crate::error::CliError;
use crate::output::{self, num, Summary};
use pendulum_theory::compound::datasheet::{datasheet, Air, Datasheet};
use pendulum_theory::gas::Gas;
use serde::Serialize;

/// The command's JSON: the file, and the library's datasheet.
#[derive(Serialize)]
struct DesignJson<'a> {
    file: String,
    #[serde(flatten)]
    sheet: &'a Datasheet,
}

/// The datasheet for people: (quantity, value) rows.
pub fn rows(d: &Datasheet, gravity: &ResolvedGravity) -> Vec<(String, String)> {
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
    if let Some(sp) = &d.spring {
        rows.push((
            "Spring".into(),
            format!(
                "bends over {} mm (its bending length); the pendulum turns {} mm below the \
                 chops and gains {} s/day against a rigid pivot at the chops (in the length above); \
                 its modulus's change with temperature {} s/day per °C",
                num(sp.bending_length_m * 1e3, 4),
                num(sp.effective_pivot_m * 1e3, 4),
                num(sp.rate_s_per_day, 4),
                num(sp.modulus_temperature_coefficient_s_per_day_per_c, 3)
            ),
        ));
    }
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
        "Gradient".into(),
        format!(
            "{} s/day per K/m warmer upwards (at the same temperature half-way down)",
            num(d.gradient_coefficient_s_per_day_per_k_per_m, 3)
        ),
    ));
    if let (Some(c), Some(m)) = (
        d.humidity_coefficient_s_per_day_per_percent,
        d.wood_moisture_percent,
    ) {
        rows.push((
            "Humidity".into(),
            format!(
                "{} s/day per % relative humidity once the wood has settled (at {} % moisture)",
                num(c, 3),
                num(m, 3)
            ),
        ));
    }
    let humidity = if d.gas == Gas::Air {
        format!(", {} %", num(d.humidity * 100.0, 3))
    } else {
        String::new()
    };
    rows.push((
        if d.gas == Gas::Air {
            "Air".into()
        } else {
            format!("Gas ({})", d.gas.name())
        },
        format!(
            "{} kg/m³ ({} hPa, {} °C{humidity}): {} s/day against a vacuum ({} from buoyancy)",
            num(d.air_density_kg_m3, 5),
            num(d.pressure_pa / 100.0, 6),
            num(d.temperature_c, 4),
            num(d.air_rate_s_per_day, 4),
            num(d.air_buoyancy_rate_s_per_day, 4)
        ),
    ));
    let shares: Vec<String> = d
        .gas_parts
        .iter()
        .filter(|p| p.damping_share > 0.0)
        .map(|p| format!("{} {}%", p.name, num(100.0 * p.damping_share, 3)))
        .collect();
    let mut damping = match d.q_gas {
        Some(q) => format!(
            "Q {} from the gas's viscous damping ({})",
            num(q, 5),
            shares.join(", ")
        ),
        None => "nothing meets the gas (point masses on idealised rods)".into(),
    };
    if let Some(qp) = d.q_pivot {
        damping.push_str(&format!("; the pivot's Q {}", num(qp, 5)));
    }
    match (d.semi_arc_deg, d.q) {
        (Some(arc), Some(q)) => damping.push_str(&format!(
            "; at {}° with the form drag: Q {}",
            num(arc, 4),
            num(q, 5)
        )),
        (None, Some(q)) if d.q_pivot.is_some() => {
            damping.push_str(&format!("; together Q {}", num(q, 5)))
        }
        _ => {}
    }
    rows.push(("Damping".into(), damping));
    rows.push((
        "Barometer".into(),
        format!(
            "{} s/day per hPa ({} per inHg) at a constant arc",
            num(d.pressure_coefficient_s_per_day_per_hpa, 4),
            num(d.pressure_coefficient_s_per_day_per_hpa * 33.8639, 4)
        ),
    ));
    if let (Some(arc), Some(circ), Some(net)) = (
        d.semi_arc_deg,
        d.circular_pressure_coefficient_s_per_day_per_hpa,
        d.net_pressure_coefficient_s_per_day_per_hpa,
    ) {
        rows.push((
            "Arc".into(),
            format!(
                "at {}° the arc's change adds {} s/day per hPa through the circular error, \
                 {} s/day per hPa in all",
                num(arc, 4),
                num(circ, 4),
                num(net, 4)
            ),
        ));
    }
    rows.push((
        "Cancelling arc".into(),
        match d.cancelling_semi_arc_deg {
            Some(a) => format!(
                "{}° semi-arc: there the circular error cancels the barometric error",
                num(a, 4)
            ),
            None => "none up to 60°".into(),
        },
    ));
    for r in &d.against_pressure {
        let mut text = match r.q {
            Some(q) => format!("Q {}, ", num(q, 5)),
            None => String::new(),
        };
        text.push_str(&format!(
            "{} s/day against a vacuum",
            num(r.gas_rate_s_per_day, 4)
        ));
        match (
            r.semi_arc_deg,
            r.circular_rate_s_per_day,
            r.rate_change_s_per_day,
        ) {
            (Some(a), Some(c), Some(change)) => text.push_str(&format!(
                "; semi-arc {}° (circular error {} s/day): {} s/day against here",
                num(a, 4),
                num(c, 4),
                num(change, 4)
            )),
            _ if d.semi_arc_deg.is_some() => text.push_str("; the drive would swing it past 60°"),
            _ => {}
        }
        rows.push((format!("At {} hPa", num(r.pressure_pa / 100.0, 6)), text));
    }
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
    for w in &d.warnings {
        rows.push(("WARNING".into(), w.to_string()));
    }
    rows
}

pub fn run(args: &DesignArgs) -> Result<String, CliError> {
    let design = crate::design::read_design(&args.file)?;
    let gravity = common::gravity(&args.gravity)?;
    let air = Air {
        pressure_pa: args.pressure.map(|p| p.0 * 100.0),
        temperature_c: args.temperature.map(|t| t.0),
        humidity: args.humidity.map(|h| h.0 / 100.0),
        regulated_at_c: args.regulated_at.map(|t| t.0),
        gas: args
            .gas
            .as_deref()
            .map(Gas::parse)
            .transpose()
            .map_err(|e| common::refused(&e))?,
        pivot_q: args.pivot_q,
        amplitude_rad: args.amplitude.map(|a| a.0),
    };
    let sheet = datasheet(&design, Some(gravity.g_m_s2), &air).map_err(|e| common::refused(&e))?;
    if args.json {
        return output::json(&DesignJson {
            file: args.file.display().to_string(),
            sheet: &sheet,
        });
    }
    let mut s = Summary::default();
    for (k, v) in rows(&sheet, &gravity) {
        s.row(&k, v);
    }
    Ok(s.render())
}
