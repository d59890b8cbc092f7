//! `pendulum fit trajectory`: amplitude, frequency, damping, offset and g
//! from a tracked angle.

use super::common;
use super::measured::{read_track, PivotJson};
use crate::args::FitTrajectoryArgs;
use crate::data::Format;
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num};
use crate::plot::{render, Figure, Panel, Series, Target};
use pendulum_theory::fitting::trajectory::{fit_trajectory, largest_swing, TrajectoryModel};
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
    /// `auto`, `linear` or `nonlinear`, as asked (`model` is what was used).
    model_requested: String,
    /// What was read.
    format: Format,
    /// The pivot, when the angles came from x/y positions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pivot: Option<PivotJson>,
    /// The radius of the circle the bob traced (`--pivot fit`), file units.
    #[serde(skip_serializing_if = "Option::is_none")]
    track_radius: Option<f64>,
    /// The length g is computed with, m.
    length_m: Option<f64>,
    /// `given` (--length), `design` (--design) or `track_radius`.
    length_source: Option<&'static str>,
    /// What a person must know about these results.
    warnings: Vec<String>,
}

pub fn run(args: &FitTrajectoryArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let given_length = match (&args.length, &args.design) {
        (None, None) => None,
        (l, d) => Some(
            common::pendulum_of(l.as_deref(), d.as_deref(), &common::gravity_default())?.length_m(),
        ),
    };
    if let (Some(l), None) = (given_length, &args.design) {
        // A measured pendulum: from a 0.1 mm hair spring to a 10 km shaft.
        if !(1e-4..=1e4).contains(&l) {
            return Err(CliError::flag(
                "--length",
                format!(
                    "must lie between 0.1 mm and 10 km for a measured pendulum, got {} m",
                    crate::output::num(l, 6)
                ),
            ));
        }
    }
    let track = read_track(&args.file, &args.read)?;
    // Measured: 2 million samples of a 10° swing in 29 s (nonlinear).
    let fit_seconds = track.time.len() as f64 * 20e-6;
    crate::work::check_time(
        "FILE",
        format!("{} has {} rows", args.file.display(), track.time.len()),
        fit_seconds,
        args.read.force,
    )?;
    let _spinner =
        crate::work::Spinner::start(format!("fitting {} rows", track.time.len()), fit_seconds);
    // Without --length, a fitted pivot's radius is the length (in the
    // file's units, which Tracker calibrates to metres).
    let (length, length_source) = match (given_length, track.track_radius) {
        (Some(l), _) if args.design.is_some() => (Some(l), Some("design")),
        (Some(l), _) => (Some(l), Some("given")),
        (None, Some(r)) => (Some(r), Some("track_radius")),
        (None, None) => (None, None),
    };
    let (time, theta) = (&track.time, &track.angle);
    let model = match args.model.as_str() {
        "nonlinear" => TrajectoryModel::Nonlinear,
        "linear" => TrajectoryModel::Linear,
        // Auto: the nonlinear model when the largest swing exceeds 5°.
        _ => TrajectoryModel::auto(theta),
    };
    let file = track.table.file.clone();
    let fit =
        fit_trajectory(model, time, theta).map_err(|e| CliError::other(format!("{file}: {e}")))?;
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
    // The linear model's g carries a finite-amplitude bias larger than its
    // standard error above a few degrees (the correction takes the amplitude
    // at mid-record, but the swing decays through it): not reported there.
    let swing = largest_swing(theta);
    let mut warnings: Vec<String> = fit.fallback_note().into_iter().collect();
    if let Some(l) = length {
        if !fit.model.gives_gravity(theta) {
            warnings.push(format!(
                "g is not reported from the linear model at a {}° swing: its finite-amplitude \
                 correction leaves a bias beyond the standard error; use --model nonlinear",
                num(swing.to_degrees(), 3)
            ));
        } else {
            let (g, se) = fit.gravity(l);
            parameters.insert("g_m_s2", g);
            standard_errors.insert("g_m_s2", se);
        }
    }
    let undetermined = fit.undetermined();
    if undetermined.contains(&"zeta") {
        warnings.push(
            "zeta not determined (its standard error exceeds it): the swing decays too little \
             over the record to measure the damping; a longer record will"
                .to_string(),
        );
    }
    let shape: Vec<&str> = undetermined
        .iter()
        .copied()
        .filter(|n| *n != "zeta")
        .collect();
    if !shape.is_empty() {
        warnings.push(format!(
            "{} not determined by the data (standard error beyond the value): the record does \
             not follow the model (no swing in it, a pendulum that friction stops, a record \
             mostly at rest?); fit the swinging part only",
            shape.join(", ")
        ));
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
        file,
        points: time.len(),
        model: if fit.model == TrajectoryModel::Linear {
            "linear"
        } else {
            "nonlinear"
        },
        model_requested: args.model.clone(),
        parameters,
        standard_errors,
        residual_rms_rad: fit.fit.residual_rms,
        residuals_file,
        format: track.table.format.clone(),
        pivot: track.pivot.clone(),
        track_radius: track.track_radius,
        length_m: length,
        length_source,
        warnings,
    };
    if args.json {
        return output::json(&result);
    }
    let mut out = format!(
        "{}: {} points ({}), {} model\n",
        result.file,
        result.points,
        result.format.describe(),
        result.model
    );
    for (name, value) in &result.parameters {
        let se = result.standard_errors[name];
        let note = if undetermined.contains(name) {
            "  (not determined)"
        } else {
            ""
        };
        out.push_str(&format!(
            "  {name:<16} {} ± {}{note}\n",
            num(*value, 8),
            num(se, 2)
        ));
    }
    if let (Some(source), Some(l)) = (result.length_source, result.length_m) {
        if source == "track_radius" {
            out.push_str(&format!(
                "  length {} (the radius of the tracked arc; give --length to override)\n",
                num(l, 6)
            ));
        }
    }
    if let Some(g) = result.parameters.get("g_m_s2") {
        out.push_str(&format!(
            "  g differs from standard gravity by {} ppm\n",
            num((g / STANDARD_GRAVITY - 1.0) * 1e6, 3)
        ));
    }
    for w in &result.warnings {
        out.push_str(&format!("  WARNING: {w}\n"));
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
                "measured − fitted (°)",
                vec![Series::dots("residual", res)],
            ),
        ],
    }
}
