//! `pendulum fit trajectory`: amplitude, frequency, damping, offset and g
//! from a tracked angle.

use super::common;
use crate::args::FitTrajectoryArgs;
use crate::data::{read_columns, Wanted, DEG};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num};
use crate::plot::{render, Figure, Panel, Series, Target};
use pendulum_theory::fitting::trajectory::{fit_trajectory, TrajectoryModel};
use pendulum_theory::STANDARD_GRAVITY;
use serde::Serialize;
use std::collections::BTreeMap;

#[derive(Serialize)]
struct TrajectoryJson {
    file: String,
    points: usize,
    model: &'static str,
    parameters: BTreeMap<&'static str, f64>,
    standard_errors: BTreeMap<&'static str, f64>,
    residual_rms_rad: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    residuals_file: Option<String>,
}

pub fn run(args: &FitTrajectoryArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let length = args
        .length
        .as_deref()
        .map(|l| common::pendulum(l, &common::gravity_default()).map(|p| p.length_m()))
        .transpose()?;
    let wanted = [
        Wanted {
            what: "time",
            names: &[("time_s", 1.0)],
        },
        Wanted {
            what: "angle",
            names: &[("angle_deg", DEG), ("angle_rad", 1.0)],
        },
    ];
    let columns = read_columns(&args.file, &wanted)?;
    columns.require_increasing(0)?;
    let model = if args.model == "nonlinear" {
        TrajectoryModel::Nonlinear
    } else {
        TrajectoryModel::Linear
    };
    let (time, theta) = (&columns.values[0], &columns.values[1]);
    let fit = fit_trajectory(model, time, theta)
        .map_err(|e| CliError::other(format!("{}: {e}", columns.file)))?;
    if let Some(target) = &plot {
        render(target, &figure(time, theta, &fit.fit.residuals))?;
    }
    let names = fit.names();
    let mut parameters: BTreeMap<&'static str, f64> = names
        .iter()
        .zip(&fit.fit.parameters)
        .map(|(n, v)| (*n, *v))
        .collect();
    let mut standard_errors: BTreeMap<&'static str, f64> = names
        .iter()
        .zip(&fit.fit.standard_errors)
        .map(|(n, v)| (*n, *v))
        .collect();
    // The envelope amplitude is a magnitude; a negative one is the same curve shifted by π.
    if let Some(a) = parameters.get_mut("amplitude_rad") {
        *a = a.abs();
    }
    if let Some(l) = length {
        let (g, se) = fit.gravity(l);
        parameters.insert("g_m_s2", g);
        standard_errors.insert("g_m_s2", se);
    }
    let residuals_file = match &args.residuals {
        Some(path) => {
            let mut file = CsvFile::create(path, "--residuals", "time_s,residual_rad")?;
            for (t, r) in time.iter().zip(&fit.fit.residuals) {
                file.number(Some(*t)).number(Some(*r)).end_row()?;
            }
            Some(file.commit()?)
        }
        None => None,
    };
    let result = TrajectoryJson {
        file: columns.file.clone(),
        points: time.len(),
        model: if model == TrajectoryModel::Linear {
            "linear"
        } else {
            "nonlinear"
        },
        parameters,
        standard_errors,
        residual_rms_rad: fit.fit.residual_rms,
        residuals_file,
    };
    if args.json {
        return output::json(&result);
    }
    let mut out = format!(
        "{}: {} points, {} model\n",
        result.file, result.points, result.model
    );
    for (name, value) in &result.parameters {
        let se = result.standard_errors[name];
        out.push_str(&format!(
            "  {name:<16} {} ± {}\n",
            num(*value, 8),
            num(se, 2)
        ));
    }
    if let Some(g) = result.parameters.get("g_m_s2") {
        out.push_str(&format!(
            "  g differs from standard gravity by {} ppm\n",
            num((g / STANDARD_GRAVITY - 1.0) * 1e6, 3)
        ));
    }
    out.push_str(&format!(
        "  residual rms     {} rad ({}°)\n",
        num(result.residual_rms_rad, 3),
        num(result.residual_rms_rad.to_degrees(), 3)
    ));
    Ok(out)
}

/// The tracked angle with the fitted curve (the data less the residuals),
/// and the residuals.
fn figure(time: &[f64], theta: &[f64], residuals: &[f64]) -> Figure {
    let deg = |v: f64| v.to_degrees();
    let data = time.iter().zip(theta).map(|(t, y)| (*t, deg(*y))).collect();
    let fitted = time
        .iter()
        .zip(theta.iter().zip(residuals))
        .map(|(t, (y, r))| (*t, deg(y - r)))
        .collect();
    let res = time
        .iter()
        .zip(residuals)
        .map(|(t, r)| (*t, deg(*r)))
        .collect();
    Figure {
        panels: vec![
            Panel::new(
                "Tracked angle and the fitted motion",
                "time (s)",
                "angle (°)",
                vec![
                    Series::dots("measured", data),
                    Series::line("fitted", fitted),
                ],
            ),
            Panel::new(
                "Residuals",
                "time (s)",
                "measured - fitted (°)",
                vec![Series::dots("residual", res)],
            ),
        ],
    }
}
