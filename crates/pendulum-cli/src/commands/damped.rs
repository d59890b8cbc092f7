//! `pendulum damped`: the damped pendulum of section 1-4 of the clock book, with dry
//! friction (book section 2-4) and the energy budget.

use super::common;
use crate::args::DampedArgs;
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Points, Series, Target};
use crate::work;
use pendulum_theory::damped::analysis::{damped, Damped, DampedInput, MAX_EXTREMA};
use pendulum_theory::damped::{DampedPendulum, Regime};
use serde::Serialize;

/// The command's JSON: the library's result and the trajectory file.
#[derive(Serialize)]
struct DampedJson<'a> {
    #[serde(flatten)]
    result: &'a Damped,
    #[serde(skip_serializing_if = "Option::is_none")]
    trajectory: Option<TrajectoryJson>,
}

#[derive(Serialize)]
struct TrajectoryJson {
    path: String,
    samples: u64,
    duration_s: f64,
    sample_interval_s: f64,
}

pub fn run(args: &DampedArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let swing = &args.swing;
    let gravity = common::gravity(&swing.gravity)?;
    let pendulum = common::pendulum_of(
        swing.pendulum.length,
        swing.pendulum.design.as_deref(),
        &gravity,
    )?;
    let input = DampedInput {
        length: pendulum.length_m(),
        g: Some(pendulum.g_m_s2()),
        amplitude: swing.amplitude.0,
        damping: common::damping_given(&swing.damping)?,
        friction_angle: swing.friction_angle.map(|r| r.0),
        mass: swing.mass.map(|m| m.0),
        extrema: args.extrema,
        force: args.force,
    };
    let r = damped(&input).map_err(|e| common::refused(&e))?;
    let trajectory = match &args.trajectory {
        Some(path) => Some(write_trajectory(args, path, &r)?),
        None => None,
    };
    if let Some(target) = &plot {
        let duration = r.span(duration(args)?).map_err(|e| common::refused(&e))?;
        render(target, &figure(&r, duration))?;
    }
    let json = DampedJson {
        result: &r,
        trajectory,
    };
    if args.json {
        output::json(&json)
    } else {
        Ok(text(&json))
    }
}

/// `--duration`, if given.
fn duration(args: &DampedArgs) -> Result<Option<f64>, CliError> {
    Ok(args.duration.map(|d| d.0))
}

fn opt(value: Option<f64>, digits: usize, unit: &str) -> String {
    value.map_or_else(
        || "none".to_string(),
        |v| format!("{} {unit}", num(v, digits)),
    )
}

fn text(json: &DampedJson) -> String {
    let j = json.result;
    let deg = |x: f64| format!("{}°", num(x.to_degrees(), 6));
    let mut s = Summary::default();
    s.row("Length", format!("{} m", num(j.length_m, 10)))
        // Ten digits: a release at 179.999999° must not read as 180°.
        .row(
            "Amplitude",
            format!("{}°", num(j.amplitude_rad.to_degrees(), 10)),
        )
        .row(
            "Damping",
            format!(
                "ζ = {}, Q = {}, {}",
                num(j.zeta, 6),
                j.q_factor.map_or("infinite".into(), |q| num(q, 6)),
                j.regime
            ),
        )
        .row("Log decrement", opt(j.log_decrement, 6, "per period"))
        .row(
            "ω_n, ω_d",
            format!(
                "{} rad/s, {}",
                num(j.natural_angular_frequency_rad_s, 8),
                opt(j.damped_angular_frequency_rad_s, 8, "rad/s")
            ),
        )
        .row("Damped period", opt(j.damped_period_s, 10, "s"))
        .row("Phase φ", opt(j.phase_rad, 6, "rad"))
        .row(
            if j.regime == Regime::Overdamped.name() {
                "Decay time (slow creep)"
            } else {
                "Decay time"
            },
            j.decay_time_s.map_or("none (undamped)".to_string(), |t| {
                format!("{} s", num(t, 6))
            }),
        )
        .row("Amplitude half-life", opt(j.amplitude_half_life_s, 6, "s"));
    if let (Some(e), Some(a)) = (
        j.amplitude_loss_per_period_rad,
        j.amplitude_loss_per_period_approx_rad,
    ) {
        s.row(
            "Amplitude lost per period",
            format!("{} (first-order: {})", deg(e), deg(a)),
        );
    }
    if j.friction_angle_rad > 0.0 {
        s.row("Friction angle", deg(j.friction_angle_rad));
    }
    if let Some(stop) = &j.stop {
        let when = stop.time_s.map_or("never quite (creeps)".to_string(), |t| {
            format!("at {} s", num(t, 8))
        });
        s.row("Stops", format!("{when}, at {}", deg(stop.angle_rad)));
    }
    if let (Some(m), Some(b)) = (j.mass_kg, j.budget) {
        s.row("Bob mass", format!("{} kg", num(m, 6)))
            .row("Stored energy", format!("{} J", num(b.energy, 6)))
            .row(
                "Lost per period",
                format!("{} J  ({} W)", num(b.loss_per_period, 6), num(b.power, 6)),
            )
            .row(
                "Impulse per beat",
                format!("{} kg m²/s", num(b.impulse_per_beat, 6)),
            );
    }
    if let Some(t) = &json.trajectory {
        s.row("Trajectory", format!("{} ({} samples)", t.path, t.samples));
    }
    for w in &j.warnings {
        s.row("WARNING", w.to_string());
    }
    let mut out = s.render();
    out.push_str("\nTurning points\n");
    let rows: Vec<Vec<String>> = j
        .extrema
        .iter()
        .map(|e| {
            vec![
                e.index.to_string(),
                num(e.time_s, 10),
                num(e.angle_rad.to_degrees(), 8),
            ]
        })
        .collect();
    out.push_str(&output::table(&["n", "time s", "angle °"], &rows));
    if !j.oscillates() {
        out.push_str("(no oscillation: the pendulum creeps back without turning)\n");
    }
    out
}

/// Computing time of one trajectory row, s (0.29 s for a million rows,
/// measured on the machine of bench/RESULTS.md, rounded up).
const SECONDS_PER_ROW: f64 = 0.4e-6;
/// Bytes of one trajectory row (41.4 measured on a million rows, rounded up).
const BYTES_PER_ROW: f64 = 45.0;

/// Streams the closed-form motion to `path`, sample by sample.
fn write_trajectory(
    args: &DampedArgs,
    path: &std::path::Path,
    r: &Damped,
) -> Result<TrajectoryJson, CliError> {
    let duration = r.span(duration(args)?).map_err(|e| common::refused(&e))?;
    let interval = args.sample_interval.map(|h| h.0);
    let (interval, samples) = r
        .sampling(duration, interval, args.force)
        .map_err(|e| common::refused(&e))?;
    // Measured: 0.3 µs and about 42 bytes a row (bench/RESULTS.md).
    let rows = samples as f64;
    work::check_time(
        "--duration",
        format!("{} samples", num(rows, 3)),
        rows * SECONDS_PER_ROW,
        args.force,
    )?;
    work::check_space("--trajectory", path, rows * BYTES_PER_ROW)?;
    let mut file = CsvFile::create(
        path,
        "--trajectory",
        "time_s,angle_rad,angular_velocity_rad_s",
    )?;
    let mut progress = work::Progress::new(rows, "sampled");
    let mut sampler = r.friction.sampler(r.amplitude_rad);
    for i in 0..samples {
        // Ctrl-C: the temporary file is removed, nothing is left.
        if i % 4096 == 0 {
            if crate::interrupt::requested() {
                return Err(crate::interrupt::error());
            }
            progress.update(i as f64, || format!("{i} rows"));
        }
        let t = i as f64 * interval;
        let state = sampler.state_at(t);
        file.number(Some(t))
            .number(Some(state.angle))
            .number(Some(state.angular_velocity))
            .end_row()?;
    }
    let path = file.commit()?;
    Ok(TrajectoryJson {
        path,
        samples,
        duration_s: duration,
        sample_interval_s: interval,
    })
}

/// Turning points drawn at most (evenly thinned beyond).
const FIGURE_TURNS: usize = 1000;

/// θ(t) with its envelope and every turning point over `duration`: the
/// viscous envelope `±A0 e^(-ζωt)/√(1-ζ²)` that the motion touches, or
/// with dry friction the envelope through the turning points (a straight
/// line without viscous damping) up to where the pendulum sticks.
fn figure(r: &Damped, duration: f64) -> Figure {
    let a0 = r.amplitude_rad;
    let damped = &r.friction.damped;
    let mut sampler = r.friction.sampler(a0);
    let motion: Vec<(f64, f64)> = (0..=2000)
        .map(|i| {
            let t = duration * f64::from(i) / 2000.0;
            (t, sampler.state_at(t).angle.to_degrees())
        })
        .collect();
    let mut series = vec![Series::line("θ(t)", motion)];
    // Every turning point within the duration, not only the --extrema
    // listed in the table.
    let half = damped
        .damped_angular_frequency()
        .map(|w| std::f64::consts::PI / w);
    let count = half.map_or(1, |h| ((duration / h).ceil() as u64 + 1).min(MAX_EXTREMA));
    let friction = r.friction.friction_angle();
    let (extrema, stop) = if friction == 0.0 {
        (damped.extrema(a0, count), None)
    } else {
        let run = r.friction.run_down(a0, count);
        (run.extrema, run.stop.and_then(|s| s.time))
    };
    if friction == 0.0 {
        let (upper, lower) = envelope_points(damped, a0, duration);
        if !upper.is_empty() {
            series.push(Series::line("envelope ±A₀ exp(−ζω₀t) / √(1 − ζ²)", upper));
            series.push(Series::line("", lower).colored(1));
        }
    } else if half.is_some() {
        let end = stop.unwrap_or(duration).min(duration);
        let upper: Points = (0..=400)
            .filter_map(|i| {
                let t = end * f64::from(i) / 400.0;
                r.friction
                    .envelope(a0, t)
                    .map(|e| (t, e.max(friction).to_degrees()))
            })
            .collect();
        let lower = upper.iter().map(|&(t, e)| (t, -e)).collect();
        series.push(Series::line(
            "envelope through the turning points (dry friction)",
            upper,
        ));
        series.push(Series::line("", lower).colored(1));
    }
    let turns: Vec<(f64, f64)> = extrema
        .iter()
        .filter(|e| e.time <= duration)
        .map(|e| (e.time, e.angle.to_degrees()))
        .collect();
    series.push(Series::dots(
        "turning points",
        crate::plot::thin(turns, FIGURE_TURNS),
    ));
    Figure {
        panels: vec![Panel::new(
            format!(
                "Damped pendulum: ζ = {}, {}",
                num(damped.damping.zeta(), 4),
                damped.regime().name()
            ),
            crate::plot::TIME_AXIS,
            "angle (°)",
            series,
        )],
    }
}

/// The envelope `±A0 e^{-ζωt}/sqrt(1-ζ²)` in degrees over `[0, duration]`
/// (empty unless underdamped).
pub fn envelope_points(damped: &DampedPendulum, a0: f64, duration: f64) -> (Points, Points) {
    let upper: Vec<(f64, f64)> = (0..=200)
        .filter_map(|i| {
            let t = duration * f64::from(i) / 200.0;
            damped.envelope(a0, t).map(|e| (t, e.to_degrees()))
        })
        .collect();
    let lower = upper.iter().map(|&(t, e)| (t, -e)).collect();
    (upper, lower)
}
