//! `pendulum simulate`: the nonlinear damped pendulum over days of swings,
//! with every turning point streamed to a CSV file.

use super::common;
use crate::args::SimulateArgs;
use crate::error::CliError;
use crate::file::CsvFile;
use crate::interrupt;
use crate::output::{self, num, Output, Summary};
use crate::plot::{render, thin, Figure, Panel, Series, Target};
use crate::work::{self, Progress};
use clap::ValueEnum;
use pendulum_theory::damped::State;
use pendulum_theory::simulation::analysis::{
    method_of, prepare, Prepared, Simulation, SimulationInput, SAMPLES_PER_PERIOD,
};
use pendulum_theory::simulation::{
    half_swing_rate, Action, Observer, Options, Stopped, TurningPoint,
};
use pendulum_theory::Pendulum;
use serde::Serialize;
use std::time::Instant;

/// Whole periods drawn in the phase portrait (evenly chosen over the run).
const PHASE_PERIODS: u64 = 60;
/// Samples a period for the phase portrait (from the dense output).
const PHASE_SAMPLES: usize = 360;
/// Points kept for the amplitude and rate plot.
const PLOT_POINTS: usize = 4000;

/// What the command prints as JSON: the library's summary, the time it
/// took and the files written.
#[derive(Serialize)]
struct SimulateJson {
    #[serde(flatten)]
    run: Simulation,
    elapsed_s: f64,
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
    let pendulum = swing.pendulum;
    let quadratic_drag = args.quadratic_drag.map(|b| b.0);
    let duration = args.duration.0;
    let tolerance = args.tolerance.map(|t| t.0);
    let sample_interval = match &args.trajectory {
        // The phase portrait alone: PHASE_SAMPLES a period, from the
        // dense output (with --trajectory it uses the trajectory's).
        None if args.phase_plot.is_some() => {
            Some(pendulum.small_angle_period() / PHASE_SAMPLES as f64)
        }
        None => None,
        Some(_) => {
            let default = pendulum.small_angle_period() / SAMPLES_PER_PERIOD;
            let interval = args.sample_interval.map(|h| h.0);
            let (h, _) =
                pendulum_theory::analysis::sampling(interval, default, duration, args.force)
                    .map_err(|e| common::refused(&e))?;
            Some(h)
        }
    };
    let damping_field = common::damping_field(&args.swing.damping);
    let drag = common::drag_laws(&args.drag)?;
    let input = SimulationInput {
        length: pendulum.length_m(),
        g: Some(pendulum.g_m_s2()),
        amplitude: swing.amplitude.radians(),
        duration,
        damping: swing.damping.map(|d| (d, damping_field)),
        quadratic_drag,
        drag,
        friction_angle: Some(swing.friction_angle),
        method: args
            .method
            .and_then(|m| m.to_possible_value())
            .map(|v| method_of(v.get_name()))
            .transpose()
            .map_err(|e| common::refused(&e))?,
        tolerance,
        sample_interval,
        force: args.force,
        elastic_share: Some(swing.elastic_share),
    };
    // A drag law given by name is said of `--drag NAME` (the quadratic
    // drag has its own flag too).
    let law_flags = common::drag_flags(if args.quadratic_drag.is_some() {
        &["quadratic_drag"]
    } else {
        &[]
    });
    let flags: Vec<(&str, &str)> = law_flags.iter().map(|(n, f)| (*n, f.as_str())).collect();
    let refused = |r: pendulum_theory::analysis::Refusal| {
        CliError::refused(&r, &flags, &|_, reason| CliError::other(reason))
    };
    let prepared = prepare(&input).map_err(refused)?;
    check_space(args, &prepared)?;
    let mut observer = CliObserver::new(args, &pendulum, &prepared.options)?;
    let started = Instant::now();
    let run = prepared.run(&mut observer).map_err(refused)?;
    let elapsed = started.elapsed().as_secs_f64();
    observer.draw(args)?;
    let files = observer.close()?;
    let status = if run.outcome.stopped == Stopped::Interrupted && interrupt::requested() {
        interrupt::EXIT_INTERRUPTED
    } else {
        0
    };
    let result = SimulateJson {
        run,
        elapsed_s: elapsed,
        swings_file: files.0,
        trajectory_file: files.1,
    };
    let stdout = if args.json {
        output::json(&result)?
    } else {
        text(&result)
    };
    Ok(Output {
        stdout,
        status,
        ..Output::default()
    })
}

/// Refuses, before any file is made, files that would not fit the disk
/// (a swings row of about 90 bytes a half period, a trajectory row of
/// about 60 bytes a sample); even with --force.
fn check_space(args: &SimulateArgs, prepared: &Prepared) -> Result<(), CliError> {
    let half_swings = 2.0 * prepared.work.periods + 2.0;
    if let Some(path) = &args.swings {
        work::check_space("--swings", path, 90.0 * half_swings)?;
    }
    let options = &prepared.options;
    if let (Some(path), Some(h)) = (&args.trajectory, options.sample_interval) {
        work::check_space("--trajectory", path, 60.0 * (options.duration / h + 1.0))?;
    }
    Ok(())
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
    /// The exact period at the release amplitude (the longest the swing
    /// has, as it decays), set at the first sample: the loops are drawn
    /// over 1.1 of it, so that they close at any amplitude.
    loop_period: Option<f64>,
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
            progress: Progress::new(options.duration, "simulated"),
            error: None,
            previous_turn: 0.0,
            pendulum: *pendulum,
            turns: args.plot.as_ref().map(|_| Vec::new()),
            phase: args.phase_plot.as_ref().map(|_| Vec::new()),
            phase_stride: periods.div_ceil(PHASE_PERIODS).max(1),
            phase_period: None,
            loop_period: None,
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
                    "angular velocity θ′ (°/s)",
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
            // the kept periods' loops, each drawn over 1.1 periods at the
            // release amplitude so that it closes (at 120° the period is
            // 1.37 T0: loops of 1.1 T0 would stay open).
            let t0 = self.pendulum.small_angle_period();
            let period = *self.loop_period.get_or_insert_with(|| {
                pendulum_theory::pendulum::Amplitude::from_radians(state.angle.abs())
                    .map_or(t0, |a| self.pendulum.period(a))
                    .max(t0)
            });
            let period = if period.is_finite() { period } else { t0 };
            let u = time / period;
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

fn text(r: &SimulateJson) -> String {
    let outcome = &r.run.outcome;
    let elapsed_s = r.elapsed_s;
    let (swings_file, trajectory_file) = (&r.swings_file, &r.trajectory_file);
    let r = &r.run;
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
            num(r.final_time_s / pendulum_theory::period::SECONDS_PER_DAY, 6)
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
            num(elapsed_s, 3)
        ),
    );
    for w in &r.warnings {
        s.row("WARNING", w.to_string());
    }
    if let Some(f) = swings_file {
        s.row("Swings file", f.clone());
    }
    if let Some(f) = trajectory_file {
        s.row("Trajectory file", f.clone());
    }
    s.render()
}

/// Amplitude and rate against time from the turning points
/// `(time s, amplitude °, rate s/day)`, thinned for drawing.
pub fn rundown_figure(turns: &[(f64, f64, f64)]) -> Figure {
    let amplitude = thin(turns.iter().map(|&(t, a, _)| (t, a)).collect(), PLOT_POINTS);
    // The loss is the rate with its sign turned (the rate is positive when
    // the clock gains; a free swing always loses).
    let loss = thin(
        turns.iter().map(|&(t, _, r)| (t, -r)).collect(),
        PLOT_POINTS,
    );
    Figure {
        panels: vec![
            Panel::new(
                "Amplitude as the swing decays",
                crate::plot::TIME_AXIS,
                "amplitude (°)",
                vec![Series::line("amplitude at each turning point", amplitude)],
            )
            .log_y_beyond(1.5),
            Panel::new(
                "What each half swing loses against the small-angle beat",
                crate::plot::TIME_AXIS,
                "loss (s/day)",
                vec![Series::line("86400 s × (1 − (T₀/2) / half period)", loss)],
            )
            .log_y_beyond(1.5),
        ],
    }
}
