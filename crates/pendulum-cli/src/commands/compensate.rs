//! `pendulum compensate`: a design's temperature coefficient, and the
//! compensator that cancels it (a tube or collar, a gridiron, a mercury
//! jar), optionally written back as a design file.

use super::common;
use crate::args::CompensateArgs;
use crate::error::CliError;
use crate::file::AtomicFile;
use crate::output::{self, num, Summary};
use pendulum_theory::compound::compensate::{
    compensate, CompensateInput, Compensation, DEFAULT_PART, NUT_TRAVEL_M,
};
use serde::Serialize;

/// The command's JSON: the library's result, and where the compensated
/// design was written.
#[derive(Serialize)]
struct CompensateJson<'a> {
    #[serde(flatten)]
    result: &'a Compensation,
    #[serde(skip_serializing_if = "Option::is_none")]
    written_to: Option<String>,
}

pub fn run(args: &CompensateArgs) -> Result<String, CliError> {
    let read = crate::design::read_design(&args.design)?;
    let length = |_flag: &str, t: &Option<crate::units::Length>| -> Result<_, CliError> {
        Ok(t.map(|l| l.0))
    };
    let input = CompensateInput {
        compensator: args.compensator.clone(),
        part: args.part.clone(),
        jar_material: args.jar_material.clone(),
        jar_diameter: length("--jar-diameter", &args.jar_diameter)?,
        jar_wall: length("--jar-wall", &args.jar_wall)?,
        tube_diameter: length("--tube-diameter", &args.tube_diameter)?,
        tube_bore: length("--tube-bore", &args.tube_bore)?,
    };
    let result = compensate(&read, &input).map_err(|e| common::refused(&e))?;
    let mut written_to = None;
    match (&args.write, &result.compensated) {
        (Some(path), Some(c)) => {
            let title = format!(
                "{} with a {} sized by `pendulum compensate`.",
                args.design.display(),
                match (&result.compensator, result.tube_length_m) {
                    (Some(m), Some(_)) => format!("{m} tube"),
                    (Some(m), None) => m.clone(),
                    (None, _) => "compensator".into(),
                }
            );
            let text = crate::design::to_toml(c, read.thread, &title);
            let mut file = AtomicFile::create(path, "--write")?;
            file.writer()
                .write_all(text.as_bytes())
                .map_err(|e| file.write_error(e))?;
            written_to = Some(file.commit()?);
        }
        (Some(_), None) => {
            return Err(CliError::flag(
                "--write",
                "writes a compensated design: give --compensator",
            ))
        }
        _ => {}
    }
    let part = args.part.as_deref().unwrap_or(DEFAULT_PART);
    let json = CompensateJson {
        result: &result,
        written_to,
    };
    if args.json {
        return output::json(&json);
    }
    render(&json, part)
}

/// The summary for people.
fn render(json: &CompensateJson, part: &str) -> Result<String, CliError> {
    let result = json.result;
    let before = result.temperature_coefficient_s_per_day_per_c;
    let mut s = Summary::default();
    s.row(
        "Temperature",
        format!(
            "{} s/day per °C as designed ({} as it warms)",
            num(before, 4),
            if before < 0.0 { "losing" } else { "gaining" }
        ),
    );
    if let (Some(inner), Some(outer), Some(l)) = (
        &result.inner_tube_material,
        &result.outer_tube_material,
        result.tube_length_m,
    ) {
        s.row(
            "Compensator",
            format!(
                "{} {inner} tube {} mm long standing on the nut round the rod, and {} {outer} tube as long ({} mm outside, {} mm bore) hanging from its top round it, the {part} on its lower end where the nut was, before regulating",
                article(inner),
                num(l * 1e3, 5),
                article(outer),
                num(result.tube_diameter_m.unwrap_or(0.0) * 1e3, 4),
                num(result.tube_bore_m.unwrap_or(0.0) * 1e3, 4),
            ),
        );
    } else if let (Some(name), Some(l)) = (&result.compensator, result.tube_length_m) {
        s.row(
            "Compensator",
            format!(
                "a {} of {name} {} mm long ({} mm outside, {} mm bore) under the {part}, the rod {} mm longer and the nut as much lower, before regulating",
                if l < 0.05 { "collar" } else { "tube" },
                num(l * 1e3, 5),
                num(result.tube_diameter_m.unwrap_or(0.0) * 1e3, 4),
                num(result.tube_bore_m.unwrap_or(0.0) * 1e3, 4),
                num(l * 1e3, 5)
            ),
        );
    }
    if let Some(b) = result.brass_length_m {
        s.row(
            "Gridiron",
            format!(
                "steel and brass rods in series, {} mm of brass against the drop's steel and as much again",
                num(b * 1e3, 5)
            ),
        );
    }
    if let (Some(h), Some(jar), Some(d), Some(w)) = (
        result.mercury_height_m,
        &result.jar_material,
        result.jar_diameter_m,
        result.jar_wall_m,
    ) {
        s.row(
            "Mercury jar",
            format!(
                "{} mm of mercury ({} kg) in a {jar} jar {} mm across with {} mm walls, in place of the {part}",
                num(h * 1e3, 5),
                num(result.mercury_mass_kg.unwrap_or(f64::NAN), 4),
                num(d * 1e3, 4),
                num(w * 1e3, 3)
            ),
        );
    }
    if let Some(after) = result.compensated_coefficient_s_per_day_per_c {
        s.row("Then", format!("{} s/day per °C", num(after, 3)));
    }
    if let (Some(shift), Some(follow)) = (result.regulation_shift_m, result.rod_follows) {
        let way = if shift >= 0.0 { "down" } else { "up" };
        let what = result.regulation_part.as_deref().unwrap_or("nut");
        let mm = num(shift.abs() * 1e3, 4);
        let moved = if follow {
            format!(
                "the '{what}' {mm} mm {way} and the rod {mm} mm {} (beyond a rating nut's {} mm of travel)",
                if shift >= 0.0 { "longer" } else { "shorter" },
                num(NUT_TRAVEL_M * 1e3, 3)
            )
        } else {
            match result.regulation_turns {
                Some(turns) => {
                    format!("the '{what}' {mm} mm {way} ({} turns)", num(turns.abs(), 3))
                }
                None => format!("the '{what}' {mm} mm {way}"),
            }
        };
        let rate = result.compensated_rate_s_per_day.unwrap_or(0.0);
        let kept = if rate.abs() < 1e-3 {
            "within 0.001 s/day".to_string()
        } else {
            format!("{} s/day", num(rate, 3))
        };
        s.row(
            "Regulated",
            format!("{moved}: the period of the design as given, {kept}"),
        );
    } else if let Some(l) = result.compensated_equivalent_length_m {
        s.row(
            "Length",
            format!(
                "equivalent length {} m (was {})",
                num(l, 7),
                num(result.equivalent_length_m, 7)
            ),
        );
    }
    for w in &result.warnings {
        s.row("Warning", w.to_string());
    }
    if let Some(w) = &json.written_to {
        s.row("Written", w.clone());
    }
    Ok(s.render())
}

/// "a" or "an" before `word`.
fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}
