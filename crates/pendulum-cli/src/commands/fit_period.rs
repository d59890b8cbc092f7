//! `pendulum fit period`: a table of periods against amplitude or length.

use crate::args::FitPeriodArgs;
use crate::data::{read_table, Format, Found, ReadOptions, Role};
use crate::error::CliError;
use crate::output::{self, num};
use crate::plot::{render, Figure, Panel, Series, Target};
use pendulum_theory::fitting::period_table::{analyse, Against, PeriodTable, PeriodTableInput};
use serde::Serialize;

/// What the command prints as JSON: the file read, then the analysis.
#[derive(Serialize)]
struct PeriodJson {
    file: String,
    /// What was read.
    format: Format,
    #[serde(flatten)]
    analysis: PeriodTable,
}

/// The columns of a period table: the period (a column named for it, or a
/// time column), then what is there of its uncertainty, the amplitude (or
/// an angle) and the length.
fn choose(found: &[Found]) -> Result<Vec<Role>, String> {
    let has = |r: Role| found.iter().any(|f| f.role == r);
    let period = if has(Role::Period) {
        Role::Period
    } else if has(Role::Time) {
        Role::Time
    } else {
        return Err("no period column (period_s, T (s), …)".to_string());
    };
    let mut roles = vec![period];
    if has(Role::PeriodError) {
        roles.push(Role::PeriodError);
    }
    if has(Role::Amplitude) {
        roles.push(Role::Amplitude);
    } else if has(Role::Angle) {
        roles.push(Role::Angle);
    }
    if has(Role::Length) {
        roles.push(Role::Length);
    }
    if roles.len() == 1 || roles == [period, Role::PeriodError] {
        return Err(
            "no amplitude or length column to fit the periods against (amplitude_deg, \
             length_m, …)"
                .to_string(),
        );
    }
    Ok(roles)
}

pub fn run(args: &FitPeriodArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let options = ReadOptions {
        angle_unit: super::measured::angle_unit(args.angle_unit.as_deref()),
        columns: super::measured::columns(args.columns.as_deref()),
        frame_rate: None,
        // Periods are not times from a start.
        absolute_time: true,
        run: None,
        tick_rate: None,
        no_columns_flag: false,
        refuse_blank: false,
    };
    let table = read_table(&args.file, &options, &choose)?;
    let file = table.file.clone();
    let period = table.values[0].clone();
    let amplitude = table
        .column(Role::Amplitude)
        .or_else(|| table.column(Role::Angle))
        .map(|a| a.iter().map(|v| v.abs()).collect::<Vec<f64>>());
    let analysis = analyse(&PeriodTableInput {
        period: &period,
        period_standard_error: table.column(Role::PeriodError),
        amplitude: amplitude.as_deref(),
        length: table.column(Role::Length),
        pendulum_length: args.length.map(|l| l.0),
        pendulum_length_standard_error: args.length_uncertainty.map(|l| l.0),
        bob_radius: args.bob_radius.map(|l| l.0),
        force: false,
    })
    .map_err(|r| {
        CliError::refused(
            &r,
            &[
                ("pendulum_length", "--length"),
                ("pendulum_length_standard_error", "--length-uncertainty"),
            ],
            &|at, reason| match at {
                Some((field, i)) => {
                    let role = match field {
                        "period_standard_error" => Role::PeriodError,
                        "amplitude" if table.column(Role::Amplitude).is_some() => Role::Amplitude,
                        "amplitude" => Role::Angle,
                        "length" => Role::Length,
                        _ => table.roles[0],
                    };
                    table.error_at(i, role, reason)
                }
                None => CliError::other(format!("{file}: {reason}")),
            },
        )
    })?;
    if let Some(target) = &plot {
        render(target, &figure(&analysis, &period, amplitude.as_deref()))?;
    }
    let result = PeriodJson {
        file,
        format: table.format.clone(),
        analysis,
    };
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

/// The periods measured, as points, above the fitted law.
fn figure(a: &PeriodTable, period: &[f64], amplitude: Option<&[f64]>) -> Figure {
    let (x, label): (Vec<f64>, &str) = match (a.against, amplitude) {
        (Against::Length, _) => (a.equivalent_length.clone(), "length (m)"),
        (_, Some(amp)) => (
            amp.iter().map(|v| v.to_degrees()).collect(),
            "amplitude (°)",
        ),
        (_, None) => ((1..=period.len()).map(|i| i as f64).collect(), "row"),
    };
    let mut order: Vec<usize> = (0..x.len()).collect();
    order.sort_by(|&i, &j| x[i].total_cmp(&x[j]));
    let data = order.iter().map(|&i| (x[i], period[i])).collect();
    let fitted = order.iter().map(|&i| (x[i], a.fitted_period[i])).collect();
    let residuals = order
        .iter()
        .map(|&i| (x[i], (period[i] - a.fitted_period[i]) * 1e3))
        .collect();
    let law = match a.against {
        Against::Length => "fitted: T² = 4π² (L + offset) / g",
        Against::Amplitude => "fitted: the exact law, T₀ · 2K(sin²(A/2))/π",
        Against::Repeats => "fitted: their mean",
    };
    Figure {
        panels: vec![
            Panel::new(
                "Measured periods and the fitted law",
                label,
                "period (s)",
                vec![Series::dots("measured", data), Series::line(law, fitted)],
            ),
            Panel::new(
                "Residuals",
                label,
                "measured − fitted (ms)",
                vec![Series::dots("residual", residuals)],
            ),
        ],
    }
}
