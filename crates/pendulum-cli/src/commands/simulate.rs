//! `pendulum simulate`: the nonlinear damped pendulum over days of swings,
//! with every turning point streamed to a CSV file.

use super::common::{self, finite};
use crate::args::{MethodArg, SimulateArgs};
use crate::error::CliError;
use crate::file::CsvFile;
use crate::interrupt;
use crate::output::{self, num, Output, Summary};
use crate::plot::{render, thin, Figure, Panel, Series, Target};
use crate::units::parse_number;
use crate::work::{self, Progress};
use pendulum_theory::damped::State;
use pendulum_theory::damping::Damping;
use pendulum_theory::simulation::{
    half_swing_rate, simulate, work_estimate, Action, Limit, Method, Model, Observer, Options,
    Outcome, SimulationError, Stopped, TurningPoint,
};
use pendulum_theory::{Amplitude, Pendulum, Quantity};
use serde::Serialize;
use std::time::Instant;

/// Whole periods drawn in the phase portrait (evenly chosen over the run).
const PHASE_PERIODS: u64 = 60;
/// Samples a period for the phase portrait (from the dense output).
const PHASE_SAMPLES: usize = 360;
/// Points kept for the amplitude and rate plot.
const PLOT_POINTS: usize = 4000;

/// Longer simulated durations need `--force`, s.
const MAX_DURATION: f64 = 1e9;
#[derive(Serialize)]
struct SimulateJson {
    method: &'static str,
    swings: u64,
    final_time_s: f64,
    final_angle_rad: f64,
    final_angular_velocity_rad_s: f64,
    final_amplitude_rad: f64,
    steps: u64,
    /// The steps estimated before the run (what `--force` is judged on).
    estimated_steps: f64,
    rejected_steps: u64,
    function_evaluations: u64,
    stopped: &'static str,
    duration_s: f64,
    tolerance: f64,
    length_m: f64,
    g_m_s2: f64,
    amplitude_rad: f64,
    zeta: f64,
    q_factor: Option<f64>,
    quadratic_drag: f64,
    friction_angle_rad: f64,
    elapsed_s: f64,
    /// Problems a person must see: an energy gain no damping explains, a
    /// pendulum over the top, a step that fell to nothing.
    warnings: Vec<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    swings_file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    trajectory_file: Option<String>,
}

pub fn run(args: &SimulateArgs) -> Result<Output, CliError> {
    // Refuse a bad plot name before any work.
    for (path, flag) in [(&args.plot, "--plot"), (&args.phase_plot, "--phase-plot")] {
        if let Some(p) = path {
            Target::new(p, flag)?;
        }
    }
    let swing = common::swing(&args.swing)?;
    let (pendulum, amplitude) = (swing.pendulum, swing.amplitude);
    let damping = swing.damping.unwrap_or(Damping::NONE);
    let friction_angle = swing.friction_angle;
    let quadratic_drag = match &args.quadratic_drag {
        Some(t) => parse_number(t).map_err(|e| CliError::flag("--quadratic-drag", e))?,
        None => 0.0,
    };
    let model =
        Model::new(pendulum, damping, quadratic_drag, friction_angle).map_err(|e| {
            match e.quantity {
                Quantity::QuadraticDrag => CliError::input("--quadratic-drag", &e),
                _ => CliError::input("--friction-angle", &e),
            }
        })?;
    let options = options(args, &pendulum)?;
    let estimated_steps = check_work(args, &model, amplitude, &options)?;
    let mut observer = CliObserver::new(args, &pendulum, &options)?;
    let started = Instant::now();
    let outcome = simulate(&model, amplitude, &options, &mut observer).map_err(|e| match e {
        SimulationError::ExactWithDamping | SimulationError::AveragedUnsupported => {
            CliError::flag("--method", e)
        }
        SimulationError::AveragedNeedsWeakDamping { .. } => {
            CliError::flag(common::damping_flag(&args.swing.damping), e)
        }
        SimulationError::Input(e) => CliError::input(flag_for(e.quantity), &e),
    })?;
    let elapsed = started.elapsed().as_secs_f64();
    observer.draw(args)?;
    let files = observer.close()?;
    let result = SimulateJson {
        method: outcome.method.name(),
        swings: outcome.swings,
        final_time_s: outcome.final_time,
        final_angle_rad: outcome.final_state.angle,
        final_angular_velocity_rad_s: outcome.final_state.angular_velocity,
        final_amplitude_rad: outcome.final_amplitude,
        steps: outcome.steps,
        estimated_steps,
        rejected_steps: outcome.rejected_steps,
        function_evaluations: outcome.function_evaluations,
        stopped: outcome.stopped.name(),
        duration_s: options.duration,
        tolerance: options.tolerance,
        length_m: pendulum.length_m(),
        g_m_s2: pendulum.g_m_s2(),
        amplitude_rad: amplitude.radians(),
        zeta: damping.zeta(),
        q_factor: finite(damping.q_factor()),
        quadratic_drag,
        friction_angle_rad: friction_angle,
        elapsed_s: elapsed,
        warnings: warnings(&outcome, args.method),
        swings_file: files.0,
        trajectory_file: files.1,
    };
    let status = if outcome.stopped == Stopped::Interrupted && interrupt::requested() {
        interrupt::EXIT_INTERRUPTED
    } else {
        0
    };
    let stdout = if args.json {
        output::json(&result)?
    } else {
        text(&result, &outcome)
    };
    Ok(Output {
        stdout,
        status,
        ..Output::default()
    })
}

/// What a person must be told about a run's numerics.
fn warnings(outcome: &Outcome, method: MethodArg) -> Vec<String> {
    let mut out = Vec::new();
    let exact_hint = if method == MethodArg::Exact {
        ""
    } else {
        " (without damping, --method exact is exact at any amplitude)"
    };
    if let Some(gain) = outcome.energy_gain {
        out.push(format!(
            "the energy at a turning point changed by {} of itself (or of the period it \
             implies) at {} s, which the damping does not explain: the tolerance is too \
             loose for this motion; tighten --tolerance{exact_hint}",
            num(gain.relative, 3),
            num(gain.time, 8)
        ));
    }
    match outcome.stopped {
        Stopped::OverTheTop => out.push(format!(
            "the pendulum passed over the top at {} s, impossible from rest below 180°: \
             the release is too close to 180° for this method and tolerance; \
             the run was stopped there{exact_hint}",
            num(outcome.final_time, 8)
        )),
        Stopped::StepTooSmall => out.push(format!(
            "the step size fell to nothing at {} s; the run was stopped there",
            num(outcome.final_time, 8)
        )),
        _ => {}
    }
    out
}

/// Refuses, before any file is made, a run that would take more than a few
/// seconds (unless `--force`) or more than a day, naming what makes it
/// long; returns the estimated steps.
fn check_work(
    args: &SimulateArgs,
    model: &Model,
    amplitude: Amplitude,
    options: &Options,
) -> Result<f64, CliError> {
    let work = work_estimate(model, amplitude, options);
    // The files: a swings row (about 90 bytes) a half period, a trajectory
    // row (about 60 bytes) a sample; refused, even with --force, when they
    // would not fit the disk.
    let half_swings = 2.0 * work.periods + 2.0;
    if let Some(path) = &args.swings {
        work::check_space("--swings", path, 90.0 * half_swings)?;
    }
    if let (Some(path), Some(h)) = (&args.trajectory, options.sample_interval) {
        work::check_space("--trajectory", path, 60.0 * (options.duration / h + 1.0))?;
    }
    let (flag, why) = match work.limit {
        Limit::Oscillation => (
            "--duration",
            format!(
                "{} s is {} periods of this pendulum",
                num(options.duration, 6),
                work::count(work.periods)
            ),
        ),
        Limit::Viscous => (
            common::damping_flag(&args.swing.damping),
            format!(
                "ζ = {} makes the equation stiff for an explicit method (the overdamped \
                 creep has a closed form: pendulum damped)",
                num(model.damping.zeta(), 4)
            ),
        ),
        Limit::Drag => (
            "--quadratic-drag",
            format!(
                "a drag of {} makes the equation stiff{}",
                num(model.quadratic_drag, 4),
                if args.method == MethodArg::Symplectic {
                    " (--method dop853 often takes fewer steps in the drag-limited creep)"
                } else {
                    ""
                }
            ),
        ),
    };
    work::check_time(
        flag,
        format!("{why}: about {} integration steps", work::count(work.steps)),
        work.seconds,
        args.force,
    )?;
    Ok(work.steps)
}

fn flag_for(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::Tolerance => "--tolerance",
        Quantity::SampleInterval => "--sample-interval",
        _ => "--duration",
    }
}

fn options(args: &SimulateArgs, pendulum: &Pendulum) -> Result<Options, CliError> {
    let duration = common::duration(Some(&args.duration), 0.0)?;
    if duration > MAX_DURATION && !args.force {
        return Err(CliError::flag(
            "--duration",
            format!(
                "{} s is over 10^9 s (32 years); add --force if you mean it",
                num(duration, 4)
            ),
        ));
    }
    let tolerance = parse_number(&args.tolerance).map_err(|e| CliError::flag("--tolerance", e))?;
    // Below 1e-15 the tolerance asks for more than double precision holds.
    if !(1e-15..1.0).contains(&tolerance) {
        return Err(CliError::flag(
            "--tolerance",
            format!(
                "must lie between 1e-15 (double precision) and 1 (e.g. 1e-10), got {}",
                args.tolerance.trim()
            ),
        ));
    }
    let sample_interval = match &args.trajectory {
        // The phase portrait alone: PHASE_SAMPLES a period, from the
        // dense output (with --trajectory it uses the trajectory's).
        None if args.phase_plot.is_some() => {
            Some(pendulum.small_angle_period() / PHASE_SAMPLES as f64)
        }
        None => None,
        Some(_) => {
            let default = pendulum.small_angle_period() / 100.0;
            let (h, _) = common::sampling(
                args.sample_interval.as_deref(),
                default,
                duration,
                args.force,
            )?;
            Some(h)
        }
    };
    let method = match args.method {
        MethodArg::Dop853 => Method::Dop853,
        MethodArg::Symplectic => Method::Symplectic,
        MethodArg::Vern9 => Method::Vern9,
        MethodArg::Exact => Method::Exact,
        MethodArg::Averaged => Method::Averaged,
    };
    Ok(Options {
        duration,
        tolerance,
        method,
        sample_interval,
    })
}

/// Streams turning points and samples to their files, shows progress and
/// listens for Ctrl-C.
struct CliObserver {
    swings: Option<SwingsFile>,
    trajectory: Option<CsvFile>,
    progress: Progress,
    error: Option<CliError>,
    /// For the plots: the previous turning point's time, half the small-
    /// angle period, (time, amplitude °, rate s/day) of every turning point,
    /// and the samples (θ °, θ' °/s) of every `phase_stride`-th period: whole
    /// periods keep the portrait's curves smooth however long the run.
    previous_turn: f64,
    pendulum: Pendulum,
    turns: Option<Vec<(f64, f64, f64)>>,
    phase: Option<Vec<Vec<(f64, f64)>>>,
    phase_stride: u64,
    /// The group of periods whose loop is being drawn.
    phase_period: Option<u64>,
}

struct SwingsFile {
    file: CsvFile,
}

impl CliObserver {
    fn new(args: &SimulateArgs, pendulum: &Pendulum, options: &Options) -> Result<Self, CliError> {
        let swings = match &args.swings {
            Some(path) => Some(SwingsFile {
                file: CsvFile::create(
                    path,
                    "--swings",
                    "index,time_s,angle_rad,half_period_s,rate_s_per_day",
                )?,
            }),
            None => None,
        };
        let trajectory = match &args.trajectory {
            Some(path) => Some(CsvFile::create(
                path,
                "--trajectory",
                "time_s,angle_rad,angular_velocity_rad_s",
            )?),
            None => None,
        };
        let periods = (options.duration / pendulum.small_angle_period()).ceil() as u64;
        Ok(Self {
            swings,
            trajectory,
            progress: Progress::new(options.duration, "simulated", args.quiet),
            error: None,
            previous_turn: 0.0,
            pendulum: *pendulum,
            turns: args.plot.as_ref().map(|_| Vec::new()),
            phase: args.phase_plot.as_ref().map(|_| Vec::new()),
            phase_stride: periods.div_ceil(PHASE_PERIODS).max(1),
            phase_period: None,
        })
    }

    /// Keeps the first write error; says whether to go on.
    fn keep(&mut self, result: Result<(), CliError>) -> bool {
        match result {
            Ok(()) => true,
            Err(e) => {
                self.error.get_or_insert(e);
                false
            }
        }
    }

    /// Draws the plots asked for.
    fn draw(&self, args: &SimulateArgs) -> Result<(), CliError> {
        if let (Some(path), Some(turns)) = (&args.plot, &self.turns) {
            render(&Target::new(path, "--plot")?, &rundown_figure(turns))?;
        }
        if let (Some(path), Some(phase)) = (&args.phase_plot, &self.phase) {
            // One curve per period kept, all in one colour.
            let series = phase
                .iter()
                .enumerate()
                .map(|(i, period)| {
                    let label = if i == 0 {
                        match self.phase_stride {
                            1 => "(θ, θ′) over the whole run".to_string(),
                            n => format!("(θ, θ′), one period in {n}"),
                        }
                    } else {
                        String::new()
                    };
                    Series::line(label, period.clone()).colored(0)
                })
                .collect();
            let figure = Figure {
                panels: vec![Panel::new(
                    "Phase portrait",
                    "angle θ (°)",
                    "angular velocity θ' (°/s)",
                    series,
                )],
            };
            render(&Target::new(path, "--phase-plot")?, &figure)?;
        }
        Ok(())
    }

    /// Commits the files; returns their paths.
    fn close(mut self) -> Result<(Option<String>, Option<String>), CliError> {
        self.progress.finish();
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        let swings = self.swings.take().map(|s| s.file.commit()).transpose()?;
        let trajectory = self.trajectory.take().map(CsvFile::commit).transpose()?;
        Ok((swings, trajectory))
    }
}

impl Observer for CliObserver {
    fn turning_point(&mut self, point: &TurningPoint) -> Action {
        // Row 0 is the release: no half period and no rate.
        let half = (point.index > 0).then_some(point.time - self.previous_turn);
        let rate = half.map(|h| half_swing_rate(&self.pendulum, h));
        self.previous_turn = point.time;
        if let (Some(turns), Some(r)) = (self.turns.as_mut(), rate) {
            turns.push((point.time, point.angle.abs().to_degrees(), r));
        }
        let Some(s) = self.swings.as_mut() else {
            return Action::Continue;
        };
        let result = s
            .file
            .integer(point.index)
            .number(Some(point.time))
            .number(Some(point.angle))
            .number(half)
            .number(rate)
            .end_row();
        // A write error ends the run; close() then reports the error.
        if self.keep(result) {
            Action::Continue
        } else {
            Action::Stop
        }
    }

    fn sample(&mut self, time: f64, state: &State) -> bool {
        if let Some(phase) = self.phase.as_mut() {
            // Every sample when all periods are kept (one spiral); else
            // the kept periods' loops, each drawn over 1.1 periods so that
            // it closes although the true period exceeds T0.
            let u = time / self.pendulum.small_angle_period();
            let stride = self.phase_stride as f64;
            let group = if self.phase_stride == 1 {
                0
            } else {
                (u / stride).floor() as u64
            };
            let kept = self.phase_stride == 1 || u - group as f64 * stride < 1.1;
            if kept {
                if self.phase_period != Some(group) || phase.is_empty() {
                    phase.push(Vec::with_capacity(PHASE_SAMPLES * 11 / 10 + 1));
                    self.phase_period = Some(group);
                }
                if let Some(curve) = phase.last_mut() {
                    curve.push((
                        state.angle.to_degrees(),
                        state.angular_velocity.to_degrees(),
                    ));
                }
            }
        }
        let Some(file) = self.trajectory.as_mut() else {
            return true;
        };
        let result = file
            .number(Some(time))
            .number(Some(state.angle))
            .number(Some(state.angular_velocity))
            .end_row();
        self.keep(result)
    }

    fn progress(&mut self, time: f64) -> bool {
        self.progress.update(time, || format!("{} s", num(time, 6)));
        !interrupt::requested() && self.error.is_none()
    }
}

fn text(r: &SimulateJson, outcome: &Outcome) -> String {
    let deg = |x: f64| format!("{}°", num(x.to_degrees(), 8));
    let mut s = Summary::default();
    s.row(
        "Method",
        format!("{} (tolerance {})", r.method, num(r.tolerance, 3)),
    )
    .row(
        "Simulated",
        format!(
            "{} s ({} days)",
            num(r.final_time_s, 10),
            num(r.final_time_s / 86_400.0, 6)
        ),
    )
    .row(
        "Stopped",
        match outcome.stopped {
            Stopped::Duration => "at the end of the duration".to_string(),
            Stopped::Friction => "held by friction at a turning point".to_string(),
            Stopped::Interrupted => "interrupted; files hold everything up to then".to_string(),
            Stopped::Event => "at an event".to_string(),
            Stopped::AmplitudeBelowTolerance => {
                format!(
                    "the swing decayed below {} rad, the end of double precision",
                    num(
                        pendulum_theory::simulation::amplitude_floor(outcome.method),
                        2
                    )
                )
            }
            Stopped::OverTheTop => "over the top (see the warning)".to_string(),
            Stopped::StepTooSmall => "the step size fell to nothing".to_string(),
        },
    )
    .row("Turning points", r.swings.to_string())
    .row(
        "Amplitude",
        format!(
            "{} at release, {} at the end",
            deg(r.amplitude_rad),
            deg(r.final_amplitude_rad)
        ),
    )
    .row(
        "Final state",
        format!(
            "{}, {} rad/s",
            deg(r.final_angle_rad),
            num(r.final_angular_velocity_rad_s, 8)
        ),
    )
    .row(
        "Work",
        format!(
            "{} steps ({} rejected), {} evaluations, {} s",
            r.steps,
            r.rejected_steps,
            r.function_evaluations,
            num(r.elapsed_s, 3)
        ),
    );
    for w in &r.warnings {
        s.row("WARNING", w.clone());
    }
    if let Some(f) = &r.swings_file {
        s.row("Swings file", f.clone());
    }
    if let Some(f) = &r.trajectory_file {
        s.row("Trajectory file", f.clone());
    }
    s.render()
}

/// Amplitude and rate against time from the turning points
/// `(time s, amplitude °, rate s/day)`, thinned for drawing.
pub fn rundown_figure(turns: &[(f64, f64, f64)]) -> Figure {
    let amplitude = thin(turns.iter().map(|&(t, a, _)| (t, a)).collect(), PLOT_POINTS);
    let rate = thin(turns.iter().map(|&(t, _, r)| (t, r)).collect(), PLOT_POINTS);
    Figure {
        panels: vec![
            Panel::new(
                "Amplitude as the swing decays",
                "time (s)",
                "amplitude (°)",
                vec![Series::line("amplitude at each turning point", amplitude)],
            )
            .log_y_beyond(1.5),
            Panel::new(
                "What each half swing loses against the small-angle beat",
                "time (s)",
                "loss (s/day)",
                vec![Series::line("86400 s × (1 − (T₀/2) / half period)", rate)],
            )
            .log_y_beyond(1.5),
        ],
    }
}
