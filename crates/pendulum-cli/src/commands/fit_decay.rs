//! `pendulum fit decay`: which damping, and how much, from a run-down.

use super::common;
use super::measured::{opener, positions, read_options};
use crate::args::FitDecayArgs;
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num};
use crate::plot::{render, Target};
use crate::work;
use pendulum_data::fits::{decay, DecayJson, DecayOptions};
use pendulum_theory::fitting::rundown::SECONDS_PER_ROW;
use pendulum_theory::fitting::turning::Turns;

pub fn run(args: &FitDecayArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let pendulum = match (&args.length, &args.design) {
        (None, None) => None,
        (l, d) => Some(common::pendulum_of(
            *l,
            d.as_deref(),
            &common::gravity(&args.gravity)?,
        )?),
    };
    let mass = match (&args.mass, &args.design) {
        (Some(m), _) => Some(m.0),
        (None, Some(path)) => Some(crate::design::read(path)?.properties().effective_mass()),
        (None, None) => None,
    };
    let options = DecayOptions {
        read: read_options(&args.read)?,
        positions: positions(&args.read)?,
        model: args.model.clone(),
        period: args.period.map(|t| t.0),
        length: pendulum.map(|p| (p.length_m(), p.g_m_s2())),
        length_standard_error: args.length_uncertainty.map(|l| l.0),
        mass,
        force: args.read.force,
    };
    let mut spinner = None;
    let mut fitted = decay(&opener(&args.file), &options, &mut |rows| {
        spinner = Some(work::Spinner::start(
            format!("fitting {rows} rows"),
            rows as f64 * SECONDS_PER_ROW,
        ));
    })?;
    crate::data::say(&fitted.json.format);
    fitted.json.turning_points_file = match (&args.turning_points, &fitted.turns) {
        (Some(path), Some(found)) => Some(write_turns(path, found)?),
        (Some(_), None) => {
            return Err(CliError::flag(
                "--turning-points",
                format!("{} holds amplitudes already, not a track", fitted.json.file),
            ))
        }
        _ => None,
    };
    if let Some(target) = &plot {
        render(target, &fitted.figure())?;
    }
    let json = fitted.json;
    drop(spinner);
    if args.json {
        output::json(&json)
    } else {
        Ok(text(&json))
    }
}

/// Whether the parameter `name` is the one the bound name `bound` (a
/// physical or a rate name) refers to.
fn bound_of(bound: &str, name: &str) -> bool {
    // A drag law's rate and coefficient, by the names the library's list
    // gives them (the quadratic's coefficient by its key).
    let drag = |n: &str| {
        n == "quadratic_drag_per_rad"
            || pendulum_theory::forces::DRAG_LAWS
                .iter()
                .any(|l| l.name() == n || l.decay_rate_name() == n)
    };
    let rate_of = |n: &str| match n {
        "zeta" | "decay_rate_per_s" => "viscous",
        "friction_angle_rad" | "amplitude_fall_rad_per_s" => "dry",
        _ if drag(n) => "drag",
        _ => "",
    };
    !rate_of(name).is_empty() && rate_of(name) == rate_of(bound)
}

/// Writes the turning points found (time_s,amplitude_rad,side).
fn write_turns(path: &std::path::Path, found: &Turns) -> Result<String, CliError> {
    let mut file = CsvFile::create(path, "--turning-points", "time_s,amplitude_rad,side")?;
    for t in &found.turns {
        file.number(Some(t.time))
            .number(Some(t.amplitude))
            .number(Some(t.side))
            .end_row()?;
    }
    file.commit()
}

fn text(r: &DecayJson) -> String {
    let mut out = format!(
        "{}: {} points ({})\n",
        r.file,
        r.analysis.points,
        r.format.describe()
    );
    if let Some(t) = &r.time_rebuilt {
        out.push_str(&format!(
            "the track's times were written rounded ({} s steps): rebuilt on their frame grid, \
             one frame every {} s (each moved {} s at most)\n",
            num(t.quantum_s, 2),
            num(t.frame_interval_s, 8),
            num(t.largest_change_s, 2)
        ));
    }
    if let Some(offset) = r.zero_offset_rad {
        out.push_str(&format!(
            "turning points of the track, zero offset {}° removed\n",
            num(offset.to_degrees(), 3)
        ));
    }
    if let (Some(w), Some(source)) = (r.analysis.omega_rad_s, r.analysis.omega_source) {
        let from = match source {
            "period" => "--period",
            "turning_points" => "the turning points' times",
            _ => "--length and g",
        };
        out.push_str(&format!(
            "ω = {} rad/s (period {} s), from {from}\n",
            num(w, 6),
            num(std::f64::consts::TAU / w, 6)
        ));
    }
    if let Some(g) = &r.analysis.gravity {
        out.push_str(&format!(
            "g from the turning points' times and the length: {} ± {} m/s² ({})\n",
            num(g.g_m_s2, 7),
            num(g.standard_error_m_s2, 2),
            error_parts(&g.standard_error_parts)
        ));
    }
    for w in &r.analysis.warnings {
        out.push_str(&format!("WARNING: {w}\n"));
    }
    for m in &r.analysis.models {
        let Some(fitted) = &m.fitted else {
            out.push_str(&format!(
                "\n{}: failed ({})\n",
                m.model,
                m.failed.as_deref().unwrap_or("?")
            ));
            continue;
        };
        let mark = if Some(m.model) == r.analysis.preferred {
            "  <- preferred (lowest BIC)".to_string()
        } else if !fitted.at_bound.is_empty() {
            format!(
                "  ({} at 0: the simpler law, not preferred)",
                fitted.at_bound.join(", ")
            )
        } else {
            String::new()
        };
        out.push_str(&format!("\n{}{mark}\n", m.model));
        for (name, value) in &fitted.parameters {
            let se = fitted.standard_errors.get(name).copied().unwrap_or(0.0);
            if *value == 0.0 && fitted.at_bound.iter().any(|b| bound_of(b, name)) {
                let spread = if se > 0.0 {
                    format!("; ± {}", num(se, 2))
                } else {
                    String::new()
                };
                out.push_str(&format!("  {name:<28} 0 (at its bound{spread})\n"));
            } else {
                out.push_str(&format!(
                    "  {name:<28} {} ± {}\n",
                    num(*value, 6),
                    num(se, 2)
                ));
            }
        }
        out.push_str(&q_line(
            28,
            5,
            fitted.q_factor,
            fitted.q_factor_standard_error,
            fitted.q_factor_lower_bound,
        ));
        // The viscous part: alone in its law, 1/(2ζ) (Q takes the energy
        // at the record's amplitudes, 1 − cos A, where it takes A²).
        let others = m.model != "viscous";
        if let Some(q) = fitted.q_viscous {
            let error = fitted
                .q_viscous_standard_error
                .map_or(String::new(), |e| format!(" ± {}", num(e, 2)));
            out.push_str(&format!(
                "  {:<28} {}{error} ({})\n",
                "q_viscous",
                num(q, 5),
                if others {
                    "1/(2ζ): the viscous part alone, not the pendulum's Q"
                } else {
                    "1/(2ζ)"
                }
            ));
        } else if let (Some(q), true) = (fitted.q_viscous_lower_bound, others) {
            out.push_str(&format!(
                "  {:<28} no measurable viscous part: > {} (two standard errors)\n",
                "q_viscous",
                num(q, 3)
            ));
        }
        if let (Some(e), Some(p)) = (fitted.energy_loss_per_period_j, fitted.power_w) {
            out.push_str(&format!(
                "  {:<28} {} J per period, {} W\n",
                "energy lost",
                num(e, 4),
                num(p, 4)
            ));
        }
        out.push_str(&format!(
            "  {:<28} {} rad;  AIC {}  BIC {}  Akaike weight {}\n",
            "residual rms",
            num(fitted.residual_rms, 3),
            num(fitted.aic, 6),
            num(fitted.bic, 6),
            num(fitted.akaike_weight, 3)
        ));
    }
    if let (Some(best), Some(next)) = (r.analysis.preferred, &r.analysis.runner_up) {
        out.push_str(&format!(
            "\n{best} preferred over {} by ΔBIC {} ({})\n",
            next.model,
            num(next.delta_bic, 3),
            if next.delta_bic < 2.0 {
                "the data hardly choose between them"
            } else if next.delta_bic < 10.0 {
                "a positive but not decisive preference"
            } else {
                "a clear preference"
            }
        ));
    }
    out
}

/// The row of Q over the record (the energy lost per cycle), or of its
/// lower bound where no loss is measurable; empty where neither is known.
/// Both fits print it so, at `width` and `digits`.
pub fn q_line(
    width: usize,
    digits: usize,
    q: Option<f64>,
    standard_error: Option<f64>,
    lower_bound: Option<f64>,
) -> String {
    match (q, lower_bound) {
        (Some(q), _) => {
            let error = standard_error.map_or(String::new(), |e| format!(" ± {}", num(e, 2)));
            format!(
                "  {:<width$} {}{error} (over the record: the energy lost per cycle)\n",
                "Q",
                num(q, digits)
            )
        }
        (None, Some(q)) => format!(
            "  {:<width$} no measurable loss over the record: Q > {} (two standard errors)\n",
            "Q",
            num(q, 3)
        ),
        (None, None) => String::new(),
    }
}

/// What a standard error is made of, for people: "fit 0.00012, length
/// 0.0245", or what it leaves out.
pub fn error_parts(parts: &pendulum_theory::fitting::ErrorParts) -> String {
    match parts.length {
        Some(l) => format!("fit {}, length {}", num(parts.fit, 2), num(l, 2)),
        None => "the fit's alone: the length's uncertainty is not in it; give \
                 --length-uncertainty"
            .to_string(),
    }
}
