//! `pendulum fit decay`: which damping, and how much, from a run-down.

use super::common::{self, finite};
use super::measured::{has_track, read_options, track_of, track_roles};
use crate::args::FitDecayArgs;
use crate::data::{need, read_table, Format, Found, Role};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num};
use crate::plot::{render, Figure, Panel, Series, Target};
use crate::units::Dimension;
use crate::work;
use pendulum_theory::energy::energy_budget;
use pendulum_theory::fitting::decay::{
    akaike_weights, effective_angular_frequency, fit_decay, half_swing_loss, preferred,
    swings_to_time, DecayFit, DecayModel,
};
use pendulum_theory::fitting::turning::{turning_points, Turns};
use pendulum_theory::fitting::FitError;
use pendulum_theory::Pendulum;
use serde::Serialize;
use std::collections::BTreeMap;

#[derive(Serialize)]
struct DecayJson {
    file: String,
    points: usize,
    /// What was read.
    format: Format,
    /// The angular frequency rates are converted with, rad/s.
    omega_rad_s: Option<f64>,
    /// `period` (--period), `turning_points` (their times) or `length`.
    omega_source: Option<&'static str>,
    /// With a track: the zero of the swing removed from the turning angles.
    #[serde(skip_serializing_if = "Option::is_none")]
    zero_offset_rad: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    turning_points_file: Option<String>,
    models: Vec<ModelJson>,
    preferred: Option<&'static str>,
}

#[derive(Serialize)]
struct ModelJson {
    model: &'static str,
    /// Why the law could not be fitted (then no other key).
    #[serde(skip_serializing_if = "Option::is_none")]
    failed: Option<String>,
    #[serde(flatten)]
    fitted: Option<FittedJson>,
}

#[derive(Serialize)]
struct FittedJson {
    parameters: BTreeMap<&'static str, f64>,
    standard_errors: BTreeMap<&'static str, f64>,
    q_factor: Option<f64>,
    /// With no measurable viscous decay: the two-sigma lower bound on Q.
    #[serde(skip_serializing_if = "Option::is_none")]
    q_factor_lower_bound: Option<f64>,
    /// The Q of the exponential that decays as much over the record: what
    /// a trajectory fit reports, for any law.
    q_factor_mean: Option<f64>,
    /// Damping coefficients held at their bound 0 (the law is then a
    /// simpler one, never preferred).
    at_bound: Vec<&'static str>,
    residual_rms: f64,
    aic: f64,
    bic: f64,
    akaike_weight: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    energy_loss_per_period_j: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    power_w: Option<f64>,
}

pub fn run(args: &FitDecayArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let pendulum = match (&args.length, &args.design) {
        (None, None) => None,
        (l, d) => Some(common::pendulum_of(
            l.as_deref(),
            d.as_deref(),
            &common::gravity(&args.gravity)?,
        )?),
    };
    let mass = match (&args.mass, &args.design) {
        (Some(t), _) if pendulum.is_none() => {
            return Err(CliError::flag(
                "--mass",
                format!(
                    "{t} given without --length or --design: the energy budget needs the pendulum"
                ),
            ))
        }
        (Some(t), _) => Some(common::quantity("--mass", t, Dimension::Mass)?),
        (None, Some(path)) => Some(crate::design::read(path)?.properties().effective_mass()),
        (None, None) => None,
    };
    if let Some(m) = mass {
        if m <= 0.0 {
            return Err(CliError::flag(
                "--mass",
                format!("must be positive, got {m} kg"),
            ));
        }
    }
    let period = args
        .period
        .as_deref()
        .map(|t| common::quantity("--period", t, Dimension::Time))
        .transpose()?;
    if let Some(p) = period {
        // From a 1 cm pendulum (0.2 s) to Foucault's 67 m (16 s), with room.
        if !(1e-3..=1e4).contains(&p) {
            return Err(CliError::flag(
                "--period",
                format!(
                    "must lie between 1 ms and 10^4 s for a pendulum, got {} s",
                    num(p, 6)
                ),
            ));
        }
    }
    let options = read_options(&args.read)?;
    // A track (angle, or x and y, against time) to find the amplitudes in;
    // else a column of amplitudes. A track wins: Tracker files carry
    // per-frame columns a user may have called "amp".
    let choose = |found: &[Found]| {
        if has_track(found) {
            track_roles(found)
        } else if found.iter().any(|f| f.role == Role::Amplitude) {
            need(&[&[Role::Time, Role::Swing], &[Role::Amplitude]])(found)
        } else {
            Err(
                "no amplitude column (amplitude_deg, amplitude (rad), …), nor a track \
                 (time with angle, or with x and y)"
                    .to_string(),
            )
        }
    };
    let table = read_table(&args.file, &options, &choose)?;
    // Measured: 2 million rows of amplitudes in 41 s (six laws fitted); a
    // track is fitted by its turning points, a few per period.
    let fit_seconds = if table.column(Role::Amplitude).is_some() {
        table.format.rows as f64 * 25e-6
    } else {
        0.0
    };
    work::check_time(
        "FILE",
        format!("{} has {} rows", table.file, table.format.rows),
        fit_seconds,
        args.read.force,
    )?;
    let _spinner = work::Spinner::start(format!("fitting {} rows", table.format.rows), fit_seconds);
    let file = table.file.clone();
    let format = table.format.clone();
    let (time, amplitude, turns_found, half_period) = if table.column(Role::Amplitude).is_some() {
        table.require_increasing(table.roles[0])?;
        table.require_positive(Role::Amplitude)?;
        table.require_swing(Role::Amplitude)?;
        let amplitude = table.column(Role::Amplitude).unwrap_or(&[]).to_vec();
        let first = table.values[0].clone();
        let time = if table.roles[0] == Role::Swing {
            let p = pendulum.as_ref().ok_or_else(|| {
                CliError::flag(
                    "--length",
                    format!("is needed to turn the swing column of {file} into time"),
                )
            })?;
            swings_to_time(p, &first, &amplitude)
        } else {
            first
        };
        (time, amplitude, None, None)
    } else {
        let track = track_of(table, args.read.pivot.as_deref())?;
        let found = turning_points(&track.time, &track.angle);
        if found.turns.len() < 4 {
            return Err(CliError::other(format!(
                "{file}: only {} turning points found in the track; a decay needs more swings",
                found.turns.len()
            )));
        }
        let half = found.half_period();
        let time = found.turns.iter().map(|t| t.time).collect();
        let amplitude = found.turns.iter().map(|t| t.amplitude).collect();
        (time, amplitude, Some(found), half)
    };
    let turning_points_file = match (&args.turning_points, &turns_found) {
        (Some(path), Some(found)) => Some(write_turns(path, found)?),
        (Some(_), None) => {
            return Err(CliError::flag(
                "--turning-points",
                format!("{file} holds amplitudes already, not a track"),
            ))
        }
        _ => None,
    };
    let (omega, omega_source) = match (period, half_period, &pendulum) {
        (Some(p), _, _) => (Some(std::f64::consts::TAU / p), Some("period")),
        (None, Some(h), _) => (Some(std::f64::consts::PI / h), Some("turning_points")),
        (None, None, Some(p)) => (
            Some(effective_angular_frequency(p, &amplitude)),
            Some("length"),
        ),
        (None, None, None) => (None, None),
    };
    let models: Vec<DecayModel> = match DecayModel::from_name(&args.model) {
        Some(m) => vec![m],
        None => DecayModel::ALL.to_vec(),
    };
    // Every law is listed: fitted, or failed with the reason.
    let mut fits = Vec::new();
    let mut failures: Vec<(DecayModel, FitError)> = Vec::new();
    for model in models {
        match fit_decay(model, &time, &amplitude, omega) {
            Ok(fit) => fits.push(fit),
            Err(e) => failures.push((model, e)),
        }
    }
    if fits.is_empty() {
        let e = failures
            .into_iter()
            .next()
            .map_or(FitError::Singular, |(_, e)| e);
        return Err(CliError::other(format!("{file}: {e}")));
    }
    let best = preferred(&fits);
    let weights = akaike_weights(&fits);
    if let Some(target) = &plot {
        render(target, &figure(&time, &amplitude, &fits, best))?;
    }
    let result = DecayJson {
        file,
        points: time.len(),
        format,
        omega_rad_s: omega,
        omega_source,
        zero_offset_rad: turns_found.as_ref().map(|t| t.offset),
        turning_points_file,
        models: DecayModel::ALL
            .iter()
            .filter_map(|&m| {
                if let Some(i) = fits.iter().position(|f| f.model == m) {
                    Some(model_json(&fits[i], weights[i], pendulum.as_ref(), mass))
                } else {
                    failures
                        .iter()
                        .find(|(f, _)| *f == m)
                        .map(|(_, e)| ModelJson {
                            model: m.name(),
                            failed: Some(e.to_string()),
                            fitted: None,
                        })
                }
            })
            .collect(),
        preferred: best.map(DecayModel::name),
    };
    if args.json {
        output::json(&result)
    } else {
        Ok(text(&result))
    }
}

/// Whether the parameter `name` is the one the bound name `bound` (a
/// physical or a rate name) refers to.
fn bound_of(bound: &str, name: &str) -> bool {
    let rate_of = |n: &str| match n {
        "zeta" | "decay_rate_per_s" => "viscous",
        "friction_angle_rad" | "amplitude_fall_rad_per_s" => "dry",
        "quadratic_drag" | "quadratic_decay_per_rad_s" => "drag",
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

fn model_json(
    f: &DecayFit,
    weight: f64,
    pendulum: Option<&Pendulum>,
    mass: Option<f64>,
) -> ModelJson {
    let parameters = f.parameters.iter().map(|e| (e.name, e.value)).collect();
    let standard_errors = f
        .parameters
        .iter()
        .map(|e| (e.name, e.standard_error))
        .collect();
    let budget = match (pendulum, mass) {
        (Some(p), Some(m)) => {
            let a0 = f.fit.parameters[0];
            let period = p.period(
                pendulum_theory::Amplitude::from_radians(a0.abs().min(3.1)).unwrap_or_else(|_| {
                    pendulum_theory::Amplitude::from_radians(0.0).expect("zero is valid")
                }),
            );
            energy_budget(p, m, a0, half_swing_loss(f, a0, 0.5 * period), period).ok()
        }
        _ => None,
    };
    ModelJson {
        model: f.model.name(),
        failed: None,
        fitted: Some(FittedJson {
            parameters,
            standard_errors,
            q_factor: f.q_factor.and_then(finite),
            q_factor_lower_bound: f.q_factor_lower_bound.and_then(finite),
            q_factor_mean: f.q_factor_mean.and_then(finite),
            at_bound: f.at_bound.clone(),
            residual_rms: f.fit.residual_rms,
            aic: f.fit.aic,
            bic: f.fit.bic,
            akaike_weight: weight,
            energy_loss_per_period_j: budget.map(|b| b.loss_per_period),
            power_w: budget.map(|b| b.power),
        }),
    }
}

fn text(r: &DecayJson) -> String {
    let mut out = format!(
        "{}: {} points ({})\n",
        r.file,
        r.points,
        r.format.describe()
    );
    if let Some(offset) = r.zero_offset_rad {
        out.push_str(&format!(
            "turning points of the track, zero offset {}° removed\n",
            num(offset.to_degrees(), 3)
        ));
    }
    if let (Some(w), Some(source)) = (r.omega_rad_s, r.omega_source) {
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
    for m in &r.models {
        let Some(fitted) = &m.fitted else {
            out.push_str(&format!(
                "\n{}: failed ({})\n",
                m.model,
                m.failed.as_deref().unwrap_or("?")
            ));
            continue;
        };
        let mark = if Some(m.model) == r.preferred {
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
        if let Some(q) = fitted.q_factor {
            out.push_str(&format!("  {:<28} {}\n", "Q (viscous part)", num(q, 5)));
        } else if let Some(q) = fitted.q_factor_lower_bound {
            out.push_str(&format!(
                "  {:<28} no measurable decay: Q > {} (two standard errors)\n",
                "Q",
                num(q, 3)
            ));
        }
        if let Some(q) = fitted.q_factor_mean {
            out.push_str(&format!(
                "  {:<28} {} (the exponential that decays as much over the record)\n",
                "Q over the record",
                num(q, 5)
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
    out
}

/// The data with every fitted law, and the preferred law's residuals.
fn figure(time: &[f64], amplitude: &[f64], fits: &[DecayFit], best: Option<DecayModel>) -> Figure {
    let data: Vec<(f64, f64)> = time
        .iter()
        .zip(amplitude)
        .map(|(t, a)| (*t, a.to_degrees()))
        .collect();
    let (t0, t1) = (time[0], time[time.len() - 1]);
    let mut curves = vec![Series::dots("measured", data)];
    for f in fits {
        let curve = (0..=300)
            .map(|i| {
                let t = t0 + (t1 - t0) * f64::from(i) / 300.0;
                (t, f.model.amplitude(t, &f.fit.parameters).to_degrees())
            })
            // A law whose amplitude reaches zero has stopped the
            // pendulum: its curve ends there.
            .filter(|p: &(f64, f64)| p.1 >= 0.0)
            .collect();
        let label = if Some(f.model) == best {
            format!("{} (preferred)", f.model.name())
        } else {
            f.model.name().to_string()
        };
        curves.push(Series::line(label, curve));
    }
    let mut panels = vec![Panel::new(
        "Amplitude decay and the fitted laws",
        "time (s)",
        "amplitude (°)",
        curves,
    )
    .log_y_beyond(1.5)];
    if let Some(f) = fits.iter().find(|f| Some(f.model) == best) {
        let residuals = time
            .iter()
            .zip(&f.fit.residuals)
            .map(|(t, r)| (*t, r.to_degrees()))
            .collect();
        panels.push(Panel::new(
            format!("Residuals of the preferred law ({})", f.model.name()),
            "time (s)",
            "measured − fitted (°)",
            vec![Series::dots("residual", residuals)],
        ));
    }
    Figure { panels }
}
