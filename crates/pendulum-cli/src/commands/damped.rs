//! `pendulum damped`: the damped pendulum of section 1-4 of the clock book, with dry
//! friction (book section 2-4) and the energy budget.

use super::common::{self, finite};
use crate::args::DampedArgs;
use crate::error::CliError;
use crate::file::CsvFile;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Points, Series, Target};
use crate::work;
use pendulum_theory::damped::{DampedPendulum, Extremum, Regime};
use pendulum_theory::energy::{energy_budget, EnergyBudget};
use pendulum_theory::friction::{DryFriction, RunDown};
use pendulum_theory::{Amplitude, Pendulum, Quantity};
use serde::Serialize;

#[derive(Serialize)]
struct DampedJson {
    length_m: f64,
    g_m_s2: f64,
    amplitude_rad: f64,
    zeta: f64,
    q_factor: Option<f64>,
    log_decrement: Option<f64>,
    natural_angular_frequency_rad_s: f64,
    damped_angular_frequency_rad_s: Option<f64>,
    damped_period_s: Option<f64>,
    phase_rad: Option<f64>,
    regime: &'static str,
    decay_time_s: Option<f64>,
    amplitude_half_life_s: Option<f64>,
    amplitude_loss_per_period_rad: Option<f64>,
    amplitude_loss_per_period_approx_rad: Option<f64>,
    amplitude_loss_per_period_difference_rad: Option<f64>,
    friction_angle_rad: f64,
    extrema: Vec<ExtremumJson>,
    stop: Option<StopJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    mass_kg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    damping_coefficient_n_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    energy_j: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    energy_loss_per_period_j: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    power_w: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    impulse_per_beat_kg_m2_s: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    trajectory: Option<TrajectoryJson>,
    /// The exact period at the amplitude, s (the small-angle theory's
    /// damped period ignores the amplitude).
    exact_period_s: f64,
    /// What a person must know about these results.
    warnings: Vec<String>,
}

/// Above this amplitude the small-angle theory is off by more than 0.2%
/// in the period: a warning names the exact period.
const SMALL_ANGLE_LIMIT_DEG: f64 = 10.0;
/// More turning points than this need `--force`.
const MAX_EXTREMA: u64 = 100_000;
/// More turning points than this are refused even with `--force`.
const MAX_EXTREMA_FORCED: u64 = 10_000_000;

#[derive(Serialize)]
struct ExtremumJson {
    index: u64,
    time_s: f64,
    angle_rad: f64,
}

#[derive(Serialize)]
struct StopJson {
    time_s: Option<f64>,
    angle_rad: f64,
}

#[derive(Serialize)]
struct TrajectoryJson {
    path: String,
    samples: u64,
    duration_s: f64,
    sample_interval_s: f64,
}

/// What the library computed, gathered for the renderers.
struct Results {
    pendulum: Pendulum,
    amplitude: Amplitude,
    damped: DampedPendulum,
    friction: DryFriction,
    extrema: Vec<Extremum>,
    run: RunDown,
    mass: Option<f64>,
    budget: Option<EnergyBudget>,
}

pub fn run(args: &DampedArgs) -> Result<String, CliError> {
    // The turning points are held and printed: past 10^7 (a few hundred
    // MB of text) not even --force; a trajectory file streams instead.
    if args.extrema > MAX_EXTREMA_FORCED {
        return Err(CliError::flag(
            "--extrema",
            format!(
                "{} turning points requested; at most {MAX_EXTREMA_FORCED} are printed \
                 (--trajectory FILE streams a run of any length)",
                args.extrema
            ),
        ));
    }
    if args.extrema > MAX_EXTREMA && !args.force {
        return Err(CliError::flag(
            "--extrema",
            format!(
                "{} turning points requested; more than {MAX_EXTREMA} needs --force \
                 (or a trajectory file)",
                args.extrema
            ),
        ));
    }
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let swing = common::swing(&args.swing)?;
    let (pendulum, amplitude, mass) = (swing.pendulum, swing.amplitude, swing.mass);
    let damping = swing.damping.ok_or_else(|| {
        CliError::other(
            "give the damping: one of --zeta, --q, --damping-coefficient, --log-decrement, --decay-time",
        )
    })?;
    let damped = DampedPendulum::new(pendulum, damping);
    let friction = friction(swing.friction_angle, damped, amplitude)?;
    let a0 = amplitude.radians();
    let run = friction.run_down(a0, args.extrema);
    // Without friction the closed form gives every turning point directly,
    // with no rounding carried from one to the next.
    let extrema = if friction.friction_angle() == 0.0 {
        damped.extrema(a0, args.extrema)
    } else {
        run.extrema.clone()
    };
    let budget = match (mass, friction.half_swing_loss(a0), damped.damped_period()) {
        (Some(m), Some(loss), Some(period)) => Some(
            energy_budget(&pendulum, m, a0, loss, period).map_err(|e| match e.quantity {
                Quantity::Length => CliError::input("--length", &e),
                _ => CliError::input("--mass", &e),
            })?,
        ),
        _ => None,
    };
    let results = Results {
        pendulum,
        amplitude,
        damped,
        friction,
        extrema,
        run,
        mass,
        budget,
    };
    let trajectory = match &args.trajectory {
        Some(path) => Some(write_trajectory(args, path, &results)?),
        None => None,
    };
    if let Some(target) = &plot {
        let t0 = results.pendulum.small_angle_period();
        let duration = common::duration(args.duration.as_deref(), 10.0 * t0)?;
        render(target, &figure(&results, duration))?;
    }
    let json = to_json(&results, trajectory);
    if args.json {
        output::json(&json)
    } else {
        Ok(text(&results, &json))
    }
}

/// The small-angle theory's limits, said where they bite.
fn warnings(r: &Results, exact_period: f64) -> Vec<String> {
    let mut out = Vec::new();
    let a_deg = r.amplitude.degrees();
    if a_deg > SMALL_ANGLE_LIMIT_DEG {
        out.push(format!(
            "at {}° the small-angle theory (book section 1-4) is only approximate: \
             the exact period at this amplitude is {} s, not {}; \
             `pendulum simulate` integrates the full nonlinear damped motion",
            num(a_deg, 10),
            num(exact_period, 7),
            r.damped
                .damped_period()
                .map_or("the small-angle one".to_string(), |p| format!(
                    "{} s",
                    num(p, 7)
                ))
        ));
    }
    out
}

/// The friction angle, which must be below the amplitude for any motion.
fn friction(r: f64, damped: DampedPendulum, amplitude: Amplitude) -> Result<DryFriction, CliError> {
    let flag = "--friction-angle";
    let friction = DryFriction::new(damped, r).map_err(|e| CliError::input(flag, &e))?;
    if r > 0.0 && r >= amplitude.radians() {
        let show = |x| Quantity::FrictionAngle.format_value(x);
        return Err(CliError::flag(
            flag,
            format!(
                "must be less than the amplitude {}, got {}: friction would hold the pendulum at rest",
                show(amplitude.radians()),
                show(r)
            ),
        ));
    }
    Ok(friction)
}

fn to_json(r: &Results, trajectory: Option<TrajectoryJson>) -> DampedJson {
    let d = &r.damped;
    let damping = d.damping;
    let a0 = r.amplitude.radians();
    let exact = r.friction.amplitude_loss_per_period(a0);
    let approx = r.friction.amplitude_loss_per_period_approx(a0);
    DampedJson {
        length_m: r.pendulum.length_m(),
        g_m_s2: r.pendulum.g_m_s2(),
        amplitude_rad: a0,
        zeta: damping.zeta(),
        q_factor: finite(damping.q_factor()),
        log_decrement: damping.log_decrement(),
        natural_angular_frequency_rad_s: d.natural_angular_frequency(),
        damped_angular_frequency_rad_s: d.damped_angular_frequency(),
        damped_period_s: d.damped_period(),
        phase_rad: d.phase(),
        regime: d.regime().name(),
        // The time constant a user sees: the slow creep when overdamped.
        decay_time_s: finite(d.slowest_time_constant()),
        // An envelope e^{-ζω_n t} exists only when the pendulum oscillates.
        amplitude_half_life_s: d
            .damped_period()
            .and_then(|_| finite(damping.amplitude_half_life(&r.pendulum))),
        amplitude_loss_per_period_rad: exact,
        amplitude_loss_per_period_approx_rad: approx,
        amplitude_loss_per_period_difference_rad: exact.zip(approx).map(|(e, a)| a - e),
        friction_angle_rad: r.friction.friction_angle(),
        extrema: r
            .extrema
            .iter()
            .map(|e| ExtremumJson {
                index: e.index,
                time_s: e.time,
                angle_rad: e.angle,
            })
            .collect(),
        stop: r.run.stop.map(|s| StopJson {
            time_s: s.time,
            angle_rad: s.angle,
        }),
        mass_kg: r.mass,
        damping_coefficient_n_s: r.mass.map(|m| damping.coefficient(m, &r.pendulum)),
        energy_j: r.budget.map(|b| b.energy),
        energy_loss_per_period_j: r.budget.map(|b| b.loss_per_period),
        power_w: r.budget.map(|b| b.power),
        impulse_per_beat_kg_m2_s: r.budget.map(|b| b.impulse_per_beat),
        trajectory,
        exact_period_s: r.pendulum.period(r.amplitude),
        warnings: warnings(r, r.pendulum.period(r.amplitude)),
    }
}

fn opt(value: Option<f64>, digits: usize, unit: &str) -> String {
    value.map_or_else(
        || "none".to_string(),
        |v| format!("{} {unit}", num(v, digits)),
    )
}

fn text(r: &Results, j: &DampedJson) -> String {
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
            if r.damped.regime() == Regime::Overdamped {
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
    if let (Some(m), Some(b)) = (r.mass, r.budget) {
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
    if let Some(t) = &j.trajectory {
        s.row("Trajectory", format!("{} ({} samples)", t.path, t.samples));
    }
    for w in &j.warnings {
        s.row("WARNING", w.clone());
    }
    let mut out = s.render();
    out.push_str("\nTurning points\n");
    let rows: Vec<Vec<String>> = r
        .extrema
        .iter()
        .map(|e| {
            vec![
                e.index.to_string(),
                num(e.time, 10),
                num(e.angle.to_degrees(), 8),
            ]
        })
        .collect();
    out.push_str(&output::table(&["n", "time s", "angle °"], &rows));
    if r.damped.regime() != Regime::Underdamped {
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
    r: &Results,
) -> Result<TrajectoryJson, CliError> {
    let t0 = r.pendulum.small_angle_period();
    let duration = common::duration(args.duration.as_deref(), 10.0 * t0)?;
    let (interval, samples) = common::sampling(
        args.sample_interval.as_deref(),
        t0 / 100.0,
        duration,
        args.force,
    )?;
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
    let mut progress = work::Progress::new(rows, "sampled", false);
    let mut sampler = r.friction.sampler(r.amplitude.radians());
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
fn figure(r: &Results, duration: f64) -> Figure {
    let a0 = r.amplitude.radians();
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
    let half = r
        .damped
        .damped_angular_frequency()
        .map(|w| std::f64::consts::PI / w);
    let count = half.map_or(1, |h| ((duration / h).ceil() as u64 + 1).min(MAX_EXTREMA));
    let friction = r.friction.friction_angle();
    let (extrema, stop) = if friction == 0.0 {
        (r.damped.extrema(a0, count), None)
    } else {
        let run = r.friction.run_down(a0, count);
        (run.extrema, run.stop.and_then(|s| s.time))
    };
    if friction == 0.0 {
        let (upper, lower) = envelope_points(&r.damped, a0, duration);
        if !upper.is_empty() {
            series.push(Series::line("envelope ±A₀ e^(−ζω₀t)/√(1−ζ²)", upper));
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
                num(r.damped.damping.zeta(), 4),
                r.damped.regime().name()
            ),
            "time (s)",
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
