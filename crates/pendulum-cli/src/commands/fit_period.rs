//! `pendulum fit period`: a table of periods against amplitude or length.

use crate::args::FitPeriodArgs;
use crate::data::ReadOptions;
use crate::error::CliError;
use crate::output::{self, num};
use crate::plot::{render, Target};
use pendulum_data::fits::{periods, PeriodOptions};
use pendulum_theory::fitting::period_table::Against;

pub fn run(args: &FitPeriodArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let options = PeriodOptions {
        read: ReadOptions {
            angle_unit: super::measured::angle_unit(args.angle_unit.as_deref()),
            columns: super::measured::columns(args.columns.as_deref()),
            ..ReadOptions::default()
        },
        pendulum_length: args.length.map(|l| l.0),
        pendulum_length_standard_error: args.length_uncertainty.map(|l| l.0),
        bob_radius: args.bob_radius.map(|l| l.0),
    };
    let fitted = periods(&super::measured::opener(&args.file), &options)?;
    crate::data::say(&fitted.json.format);
    if let Some(target) = &plot {
        render(target, &fitted.figure())?;
    }
    let result = fitted.json;
    if args.json {
        return output::json(&result);
    }
    let a = &result.analysis;
    let against = match a.against {
        Against::Amplitude => "against amplitude (the exact law)",
        Against::Length => "against length (T² = 4π²(L + offset)/g)",
        Against::Repeats => "at one amplitude and length (repeats)",
    };
    let mut out = format!(
        "{}: {} periods {against}, {}{}\n",
        result.file,
        a.rows,
        result.format.describe(),
        if a.weighted {
            ", weighted by their uncertainties"
        } else {
            ""
        }
    );
    for (name, value) in &a.parameters {
        let error = a
            .standard_errors
            .get(name)
            .map_or(String::new(), |se| format!(" ± {}", num(*se, 2)));
        let note = match (*name, a.circular_error_coefficient_theory) {
            ("circular_error_coefficient", Some(c)) => format!("  (theory {})", num(c, 4)),
            _ => String::new(),
        };
        let parts = a.standard_error_parts.get(name).map_or(String::new(), |p| {
            format!("  ({})", super::fit_decay::error_parts(p))
        });
        out.push_str(&format!(
            "  {name:<28} {}{error}{note}{parts}\n",
            num(*value, 8)
        ));
    }
    for s in &a.series {
        out.push_str(&format!(
            "  T0 from the series, {} terms {}{}\n",
            s.terms,
            num(s.small_angle_period_s, 8),
            s.shift_standard_errors.map_or(String::new(), |z| format!(
                " ({} standard errors from the exact law's)",
                num(z, 2)
            ))
        ));
    }
    for w in &a.warnings {
        out.push_str(&format!("  WARNING: {w}\n"));
    }
    out.push_str(&format!(
        "  {:<28} {} s{}\n",
        "residual rms",
        num(a.residual_rms_s, 3),
        a.chi_square.map_or(String::new(), |c| format!(
            " (χ² {} for {} degrees of freedom)",
            num(c, 3),
            a.degrees_of_freedom
        ))
    ));
    Ok(out)
}
