//! `pendulum fit trajectory`: amplitude, frequency, damping, offset and g
//! from a tracked angle.

use super::common;
use super::measured::{opener, positions, read_options};
use crate::args::FitTrajectoryArgs;
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num};
use crate::plot::{render, Target};
use pendulum_data::fits::{trajectory, TrajectoryOptions};
use pendulum_theory::fitting::tracked::{LengthSource, SECONDS_PER_ROW};

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
    let source = if args.design.is_some() {
        LengthSource::Design
    } else {
        LengthSource::Given
    };
    let options = TrajectoryOptions {
        read: read_options(&args.read)?,
        positions: positions(&args.read)?,
        from: args.from.map(|t| t.0),
        to: args.to.map(|t| t.0),
        model: args.model.clone(),
        drag_law: args.drag_law.clone(),
        length: given_length.map(|l| (l, source)),
        length_standard_error: args.length_uncertainty.map(|l| l.0),
        force: args.read.force,
    };
    let mut spinner = None;
    let mut fitted = trajectory(&opener(&args.file), &options, &mut |rows| {
        spinner = Some(crate::work::Spinner::start(
            format!("fitting {rows} rows"),
            rows as f64 * SECONDS_PER_ROW,
        ));
    })?;
    crate::data::say(&fitted.json.format);
    if let Some(target) = &plot {
        render(target, &fitted.figure())?;
    }
    let rate = fitted.rate;
    let result = &mut fitted.json;
    let analysis = &result.analysis;
    result.residuals_file = match &args.residuals {
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
    drop(spinner);
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
