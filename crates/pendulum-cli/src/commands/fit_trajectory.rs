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
use pendulum_theory::fitting::tracked::{
    analyse, LengthSource, TimeRebuilt, Track, TrackInput, SECONDS_PER_ROW,
};
use serde::Serialize;

/// What the command prints as JSON: the file read, then the analysis.
#[derive(Serialize)]
struct TrajectoryJson {
    file: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    residuals_file: Option<String>,
    /// What was read.
    format: Format,
    /// The pivot, when the angles came from x/y positions.
    #[serde(skip_serializing_if = "Option::is_none")]
    pivot: Option<PivotJson>,
    /// The radius of the circle the bob traced (`--pivot fit`), file units.
    #[serde(skip_serializing_if = "Option::is_none")]
    track_radius: Option<f64>,
    /// Its standard error, carried into g's.
    #[serde(skip_serializing_if = "Option::is_none")]
    track_radius_standard_error: Option<f64>,
    #[serde(flatten)]
    analysis: Track,
}

pub fn run(args: &FitTrajectoryArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let given_length = match (args.length, &args.design) {
        (None, None) => None,
        (l, d) => {
            Some(common::pendulum_of(l, d.as_deref(), &common::gravity_default()?)?.length_m())
        }
    };
    if args.length_uncertainty.is_some() && given_length.is_none() {
        return Err(CliError::flag(
            "--length-uncertainty",
            "is the uncertainty of --length (or of --design's length): give the length too",
        ));
    }
    let track =
        read_track(&args.file, &args.read)?.window(args.from.map(|t| t.0), args.to.map(|t| t.0))?;
    // Without --length, a fitted pivot's radius is the length (in the
    // file's units, which Tracker calibrates to metres).
    let length = match (given_length, track.track_radius) {
        (Some(l), _) if args.design.is_some() => Some((l, LengthSource::Design)),
        (Some(l), _) => Some((l, LengthSource::Given)),
        (None, Some(r)) => Some((r, LengthSource::TrackRadius)),
        (None, None) => None,
    };
    let rate = !track.angular_velocity.is_empty();
    let (time, theta) = (&track.time, &track.angle);
    let axes: Vec<&[f64]> = track.angular_velocity.iter().map(Vec::as_slice).collect();
    let file = track.table.file.clone();
    let _spinner = crate::work::Spinner::start(
        format!("fitting {} rows", time.len()),
        time.len() as f64 * SECONDS_PER_ROW,
    );
    let analysis = analyse(&TrackInput {
        time,
        angle: theta,
        angular_velocity: &axes,
        model: args.model.as_deref(),
        length,
        length_standard_error: match given_length {
            Some(_) => args.length_uncertainty.map(|l| l.0),
            None => track.track_radius_error,
        },
        force: args.read.force,
        angle_from_positions: track.pivot.is_some(),
        declared_degrees: super::measured::declared_degrees(
            &track.table,
            crate::data::Role::Angle,
            args.read.angle_unit.as_deref(),
        ),
    })
    .map_err(|r| {
        let flags = [
            ("time", "FILE"),
            ("length_standard_error", "--length-uncertainty"),
        ];
        CliError::refused(&r, &flags, &|at, reason| match at {
            Some((_, i)) => CliError::other(format!("{file}: sample {}: {reason}", i + 1)),
            None => CliError::other(format!("{file}: {reason}")),
        })
    })?;
    let mut analysis = analysis;
    if analysis.time_rebuilt.is_none() {
        analysis.time_rebuilt = track.time_rebuilt.as_ref().map(TimeRebuilt::from);
    }
    // The samples fitted: after a gap, from the run fitted on, at their
    // times as fitted (rebuilt where they were written rounded).
    let rows = analysis.first_row..analysis.first_row + analysis.time.len();
    if let Some(target) = &plot {
        // The rate about the swing's axis, as fitted.
        let values: Vec<f64> = match &analysis.gyroscope_axis {
            Some(d) => rows
                .clone()
                .map(|i| axes.iter().zip(d).map(|(a, c)| a[i] * c).sum())
                .collect(),
            None => theta[rows.clone()].to_vec(),
        };
        render(
            target,
            &figure(&analysis.time, &values, &analysis.residuals, rate),
        )?;
    }
    let residuals_file = match &args.residuals {
        Some(path) => {
            let header = if rate {
                "time_s,residual_rad_s"
            } else {
                "time_s,residual_rad"
            };
            let mut file = CsvFile::create(path, "--residuals", header)?;
            for (t, r) in analysis.time.iter().zip(&analysis.residuals) {
                file.number(Some(*t)).number(Some(*r)).end_row()?;
            }
            Some(file.commit()?)
        }
        None => None,
    };
    let result = TrajectoryJson {
        file,
        residuals_file,
        format: track.table.format.clone(),
        pivot: track.pivot.clone(),
        track_radius: track.track_radius,
        track_radius_standard_error: track.track_radius_error,
        analysis,
    };
    if args.json {
        return output::json(&result);
    }
    let a = &result.analysis;
    let mut out = format!(
        "{}: {} points ({}), {} model, {} damping\n",
        result.file,
        a.points,
        result.format.describe(),
        a.model,
        a.damping_law
    );
    if let (Some(d), Some(share)) = (&a.gyroscope_axis, a.gyroscope_axis_share) {
        let columns = &result.format.angular_velocity_columns;
        let axis: Vec<String> = columns
            .iter()
            .zip(d)
            .map(|(c, v)| format!("{} {c}", num(*v, 3)))
            .collect();
        out.push_str(&format!(
            "  a gyroscope's angular velocity, fitted by the models' derivative: the swing's \
             axis is {} ({}% of the rotation)\n",
            axis.join(" + "),
            num(100.0 * share, 3)
        ));
    }
    if let Some(r) = &a.time_rebuilt {
        out.push_str(&format!(
            "  the times were written rounded ({} s steps{}): rebuilt on their frame grid, \
             one frame every {} s (each moved {} s at most)\n",
            num(r.quantum_s, 2),
            if r.repeated_times > 0 {
                format!(", {} repeating the row before", r.repeated_times)
            } else {
                String::new()
            },
            num(r.frame_interval_s, 8),
            num(r.largest_change_s, 2)
        ));
    }
    match a.held_samples {
        0 => {}
        1 => out
            .push_str("  the first sample holds the bob at rest before its release: not fitted\n"),
        n => out.push_str(&format!(
            "  the first {n} samples hold the bob at rest before its release: not fitted\n"
        )),
    }
    for (name, value) in &a.parameters {
        let note = if a.undetermined.contains(name) {
            "  (not determined)"
        } else {
            ""
        };
        let error = a
            .standard_errors
            .get(name)
            .map_or(String::new(), |se| format!(" ± {}", num(*se, 2)));
        let parts = a.standard_error_parts.get(name).map_or(String::new(), |p| {
            format!("  ({})", super::fit_decay::error_parts(p))
        });
        out.push_str(&format!(
            "  {name:<32} {}{error}{note}{parts}\n",
            num(*value, 8)
        ));
    }
    out.push_str(&super::fit_decay::q_line(
        32,
        6,
        a.q_factor,
        a.q_factor_standard_error,
        a.q_factor_lower_bound,
    ));
    if let (Some(q), true) = (a.q_viscous, a.damping_law != "viscous") {
        let error = a
            .q_viscous_standard_error
            .map_or(String::new(), |se| format!(" ± {}", num(se, 2)));
        out.push_str(&format!(
            "  {:<32} {}{error} (1/(2ζ): the viscous part alone, not the pendulum's Q)\n",
            "q_viscous",
            num(q, 6)
        ));
    }
    if let (Some(LengthSource::TrackRadius), Some(l)) = (a.length_source, a.length_m) {
        out.push_str(&format!(
            "  length {} (the radius of the tracked arc; give --length to override)\n",
            num(l, 6)
        ));
    }
    if let Some(g) = a.parameters.get("g_m_s2") {
        out.push_str(&format!(
            "  g differs from standard gravity by {} ppm\n",
            num(pendulum_theory::gravity::deviation_from_standard_ppm(*g), 3)
        ));
    }
    for w in &a.warnings {
        out.push_str(&format!("  WARNING: {w}\n"));
    }
    let (rms, per) = match (a.residual_rms_rad, a.residual_rms_rad_s) {
        (Some(rms), _) => (rms, ""),
        (None, Some(rms)) => (rms, "/s"),
        (None, None) => (f64::NAN, ""),
    };
    if rms.is_finite() {
        out.push_str(&format!(
            "  {:<32} {} rad{per} ({}°{per})\n",
            "residual rms",
            num(rms, 3),
            num(rms.to_degrees(), 3)
        ));
    }
    // What the standard errors stand on: the residuals' scatter (as
    // SciPy's curve_fit scales them), widened for their correlation.
    if let Some(ratio) = a.residual_to_noise.filter(|r| *r > 1.5) {
        out.push_str(&format!(
            "  the residuals are {} times the record's sample-to-sample noise (a pattern the \
             model leaves, or tracking errors correlated from sample to sample): the standard \
             errors are from the residuals' scatter, widened {} times for their correlation\n",
            num(ratio, 2),
            num(a.standard_error_inflation, 3)
        ));
    }
    Ok(out)
}

/// The tracked angle (or angular velocity) with the fitted curve (the
/// data less the residuals), and the residuals.
fn figure(time: &[f64], theta: &[f64], residuals: &[f64], rate: bool) -> Figure {
    let (title, unit, residual_unit) = if rate {
        (
            "Angular velocity and the fitted motion's",
            "angular velocity (°/s)",
            "measured − fitted (°/s)",
        )
    } else {
        (
            "Tracked angle and the fitted motion",
            "angle (°)",
            "measured − fitted (°)",
        )
    };
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
                title,
                crate::plot::TIME_AXIS,
                unit,
                vec![
                    Series::dots("measured", data),
                    Series::line("fitted", fitted),
                ],
            ),
            Panel::new(
                "Residuals",
                crate::plot::TIME_AXIS,
                residual_unit,
                vec![Series::dots("residual", res)],
            ),
        ],
    }
}
