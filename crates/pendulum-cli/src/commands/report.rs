//! `pendulum report`: the one-command analysis of a pendulum. Everything
//! the other commands compute, for one pendulum, as an HTML page with SVG
//! figures beside it: self-contained, readable without network or script.

use super::common;
use super::damped::envelope_points;
use super::period::figure as period_figure;
use super::simulate::rundown_figure;
use crate::args::ReportArgs;
use crate::error::CliError;
use crate::file::{AtomicFile, AtomicFolder};
use crate::interrupt;
use crate::output::num;
use crate::plot::{render, Figure, Panel, Series, Target};
use crate::units::Dimension;
// Q and the mass are the clock's defaults: a regulator in air, a 5 kg bob.
use pendulum_theory::clock::analysis::{DEFAULT_MASS_KG, DEFAULT_Q};
use pendulum_theory::compound::datasheet::{datasheet, Air};
use pendulum_theory::damped::DampedPendulum;
use pendulum_theory::damping::Damping;
use pendulum_theory::energy::energy_budget;
use pendulum_theory::friction::DryFriction;
use pendulum_theory::period::PeriodAnalysis;
use pendulum_theory::simulation::{
    half_swing_rate, simulate, work_estimate, Action, Method, Model, Observer, Options,
    TurningPoint,
};
use pendulum_theory::Pendulum;
use std::path::Path;

/// The default pendulum: a seconds pendulum.
const DEFAULT_LENGTH: &str = "0.99362m";
const DEFAULT_AMPLITUDE: &str = "3deg";
/// The simulated run-down stops after this many periods at the most.
const MAX_RUNDOWN_PERIODS: f64 = 1e5;
/// ... and after about this much computing, s.
const MAX_RUNDOWN_SECONDS: f64 = 1.0;

/// Collects (time, amplitude °, rate s/day) at each turning point.
struct Turns {
    pendulum: Pendulum,
    previous: f64,
    points: Vec<(f64, f64, f64)>,
}

impl Observer for Turns {
    fn turning_point(&mut self, p: &TurningPoint) -> Action {
        if p.index > 0 {
            let rate = half_swing_rate(&self.pendulum, p.time - self.previous);
            self.points.push((p.time, p.angle.abs().to_degrees(), rate));
        }
        self.previous = p.time;
        Action::Continue
    }

    fn progress(&mut self, _time: f64) -> bool {
        !interrupt::requested()
    }
}

/// One line of the page's table: quantity, value with unit, note.
struct Row(&'static str, String, &'static str);

pub fn run(args: &ReportArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let pendulum = common::pendulum_of(
        Some(args.length.as_deref().unwrap_or(DEFAULT_LENGTH)),
        args.design.as_deref(),
        &gravity,
    )?;
    let amplitude = common::amplitude(
        "--amplitude",
        args.amplitude.as_deref().unwrap_or(DEFAULT_AMPLITUDE),
    )?;
    // With a design: its datasheet, in standard air at 20 °C.
    // Its swing's energy is M g d (1 - cos A0): the simple pendulum's
    // of the equivalent length with the mass M d / l.
    let (datasheet, design_mass) = match &args.design {
        Some(path) => {
            let design = crate::design::read_design(path)?;
            let sheet = datasheet(&design, Some(gravity.g_m_s2), &Air::default())
                .map_err(|r| CliError::other(format!("{}: {r}", path.display())))?;
            (
                Some(super::design::rows(&sheet, &gravity)),
                Some(design.pendulum.properties().effective_mass()),
            )
        }
        None => (None, None),
    };
    let mass = match (&args.mass, design_mass) {
        (Some(t), _) => {
            let m = common::quantity("--mass", t, Dimension::Mass)?;
            if !(m > 0.0 && m.is_finite()) {
                return Err(CliError::flag(
                    "--mass",
                    format!("must be positive, got {t}"),
                ));
            }
            m
        }
        (None, Some(m)) => m,
        (None, None) => DEFAULT_MASS_KG,
    };
    let damping = match common::damping(&args.damping, Some(mass), &pendulum)? {
        Some(d) => d,
        None => Damping::from_q(DEFAULT_Q).expect("a valid default"),
    };
    // Beyond these the report's figures and budget leave double precision
    // (measured: ζ = 1e200 and 1e-320 overflow, 1e100 and 1e-308 do not).
    let zeta = damping.zeta();
    if !(zeta == 0.0 || (1e-300..=1e100).contains(&zeta)) {
        return Err(CliError::flag(
            common::damping_flag(&args.damping),
            format!(
                "gives ζ = {}; the report takes ζ from 1e-300 to 1e100, or none",
                num(zeta, 4)
            ),
        ));
    }
    let output = AtomicFolder::create(&args.output, "--output")?;
    let folder = output.path().to_path_buf();

    // Section 1-6: the exact period around the working amplitude.
    let analysis = PeriodAnalysis::new(pendulum, amplitude, 3)
        .map_err(|e| CliError::input("--amplitude", &e))?;
    let a_deg = amplitude.degrees();
    write_figure(
        &folder,
        "period.svg",
        &period_figure(&pendulum, 0.0, (2.0 * a_deg).clamp(6.0, 170.0), Some(a_deg)),
    )?;

    // Section 1-4: the linear decay, its Q and the energy budget.
    let damped = DampedPendulum::new(pendulum, damping);
    let a0 = amplitude.radians();
    let friction = DryFriction::new(damped, 0.0).expect("no friction is valid");
    let half_loss = friction.half_swing_loss(a0);
    let budget = match (half_loss, damped.damped_period()) {
        (Some(loss), Some(period)) => energy_budget(&pendulum, mass, a0, loss, period).ok(),
        _ => None,
    };
    // The slowest time constant: the envelope's when underdamped, the
    // creep's when overdamped.
    let decay_time = damped.slowest_time_constant();
    let half_life = std::f64::consts::LN_2 * decay_time;
    let decay_span = if half_life.is_finite() {
        3.0 * half_life
    } else {
        100.0 * pendulum.small_angle_period()
    };
    write_figure(&folder, "decay.svg", &decay_figure(&damped, a0, decay_span))?;

    // The full nonlinear run-down until the amplitude halves: at most 10^5
    // periods and about a second of computing (a stiff, heavily overdamped
    // pendulum gets a shorter run), said on the page.
    let model = Model::new(pendulum, damping, 0.0, 0.0).expect("valid model");
    let t0 = pendulum.small_angle_period();
    let wanted = if half_life.is_finite() {
        half_life
    } else {
        100.0 * t0
    };
    let mut options = Options {
        duration: wanted.min(MAX_RUNDOWN_PERIODS * t0),
        tolerance: 1e-8,
        method: Method::Symplectic,
        sample_interval: None,
    };
    let work = work_estimate(&model, amplitude, &options);
    if work.seconds > MAX_RUNDOWN_SECONDS {
        options.duration *= MAX_RUNDOWN_SECONDS / work.seconds;
    }
    let run_note = if options.duration < wanted {
        "stopped short of half amplitude: at most 10^5 periods, or a second of computing"
    } else {
        "nonlinear, symplectic integrator"
    };
    let mut turns = Turns {
        pendulum,
        previous: 0.0,
        points: Vec::new(),
    };
    let outcome = simulate(&model, amplitude, &options, &mut turns)
        .map_err(|e| CliError::other(e.to_string()))?;
    if interrupt::requested() {
        return Err(interrupt::error());
    }
    write_figure(&folder, "rundown.svg", &rundown_figure(&turns.points))?;

    let rates = turns
        .points
        .first()
        .zip(turns.points.last())
        .map(|(a, b)| (a.2, b.2));
    let undamped = damping.zeta() == 0.0;
    let mut rows = vec![
        Row(
            if args.design.is_some() {
                "Equivalent length"
            } else {
                "Length"
            },
            format!("{} m", num(pendulum.length_m(), 8)),
            if args.design.is_some() {
                "I / (m d) of the design"
            } else {
                ""
            },
        ),
        Row("Gravity", gravity.describe(), ""),
        Row(
            "Working amplitude",
            format!("{}°", num(a_deg, 6)),
            "either side of the vertical",
        ),
        Row(
            "Period at that amplitude",
            format!("{} s", num(analysis.period_s, 12)),
            "exact: 4 sqrt(l/g) K(sin²(A0/2))",
        ),
        Row(
            "Small-angle period",
            format!("{} s", num(analysis.small_angle_period_s, 12)),
            "2π sqrt(l/g)",
        ),
        Row(
            "Beats per hour",
            num(analysis.beats_per_hour, 9),
            "a beat is half a period",
        ),
        Row(
            "Circular error",
            format!("{} s/day", num(analysis.circular_error_s_per_day(), 5)),
            "lost against a vanishing swing",
        ),
        Row(
            "… per degree of amplitude",
            format!(
                "{} s/day/°",
                num(analysis.circular_error_s_per_day_per_deg(), 5)
            ),
            "how a change of swing moves the rate",
        ),
        Row("Damping ratio ζ", num(damping.zeta(), 5), "section 1-4"),
        Row(
            "Q",
            if undamped {
                "infinite (undamped)".to_string()
            } else {
                num(damping.q_factor(), 6)
            },
            "1/(2ζ)",
        ),
    ];
    if let Some(delta) = damping.log_decrement() {
        rows.push(Row(
            "Logarithmic decrement",
            format!("{} per period", num(delta, 5)),
            "2πζ/sqrt(1-ζ²)",
        ));
    }
    if let (Some(exact), Some(approx)) = (
        damped.amplitude_loss_per_period(a0),
        damped.amplitude_loss_per_period_approx(a0),
    ) {
        rows.push(Row(
            "Amplitude lost per period",
            format!(
                "{}° (first order {}°)",
                num(exact.to_degrees(), 5),
                num(approx.to_degrees(), 5)
            ),
            "A₀ (1 − e^(−δ)), and the first-order δ A₀ of section 1-4",
        ));
    }
    let overdamped = damping.zeta() > 1.0;
    rows.push(Row(
        "Amplitude decay time",
        if undamped {
            "none (undamped)".to_string()
        } else {
            format!("{} s", num(decay_time, 6))
        },
        if overdamped {
            "the slow creep: (ζ + sqrt(ζ² - 1))/ω_n"
        } else {
            "1/(ζ ω_n)"
        },
    ));
    rows.push(Row(
        "Amplitude half-life",
        if undamped {
            "none (undamped)".to_string()
        } else if damped.damped_period().is_none() {
            format!(
                "none (overdamped: no swing; the creep halves in {} s)",
                num(half_life, 6)
            )
        } else {
            format!("{} s ({} min)", num(half_life, 6), num(half_life / 60.0, 4))
        },
        "ln 2 × decay time",
    ));
    rows.push(Row(
        if design_mass.is_some() && args.mass.is_none() {
            "Effective mass"
        } else {
            "Bob mass"
        },
        format!("{} kg", num(mass, 4)),
        if design_mass.is_some() && args.mass.is_none() {
            "the design's M d / l: its swing's energy is M g d (1 - cos A0)"
        } else {
            "for the energy budget"
        },
    ));
    if let Some(b) = budget {
        rows.push(Row(
            "Energy in the swing",
            format!("{} J", num(b.energy, 5)),
            "m g l (1 - cos A0)",
        ));
        rows.push(Row(
            "Energy lost per period",
            format!("{} J", num(b.loss_per_period, 5)),
            "what the escapement must restore",
        ));
        rows.push(Row(
            "Mean power",
            format!("{} µW", num(1e6 * b.power, 5)),
            "energy lost per period / period",
        ));
        rows.push(Row(
            "Impulse per beat",
            format!("{} kg m²/s", num(b.impulse_per_beat, 5)),
            "given at the bottom of the swing",
        ));
    }
    rows.push(Row(
        "Simulated run-down",
        format!(
            "{} s, {} turning points",
            num(outcome.final_time, 6),
            outcome.swings
        ),
        run_note,
    ));
    rows.push(Row(
        "Final amplitude",
        format!("{}°", num(outcome.final_amplitude.to_degrees(), 6)),
        if run_note == "nonlinear, symplectic integrator" && !undamped {
            "half the working amplitude"
        } else {
            "at the end of the simulated run"
        },
    ));
    rows.push(Row(
        "Rate drift during the run-down",
        rates.map_or("not determined (no full swing)".to_string(), |(a, b)| {
            format!("{} → {} s/day", num(a, 5), num(b, 5))
        }),
        "circular error falls as the swing shrinks",
    ));

    let page = html(&rows, datasheet.as_deref());
    crate::output::check_finite_text(&page)?;
    let mut file = AtomicFile::create(&folder.join("index.html"), "--output")?;
    file.writer()
        .write_all(page.as_bytes())
        .map_err(|e| file.write_error(e))?;
    file.commit()?;
    let written = output.commit(&args.output);
    Ok(format!("{}\n", written.join("index.html").display()))
}

fn write_figure(folder: &Path, name: &str, figure: &Figure) -> Result<(), CliError> {
    render(&Target::new(&folder.join(name), "--output")?, figure)?;
    Ok(())
}

/// The section 1-4 decay: the envelope of the linear theory over three half-lives.
fn decay_figure(damped: &DampedPendulum, a0: f64, span: f64) -> Figure {
    let (upper, lower) = envelope_points(damped, a0, span);
    Figure {
        panels: vec![Panel::new(
            match damped.damping.q_factor() {
                q if q.is_finite() => {
                    format!("Amplitude envelope, section 1-4 (Q = {})", num(q, 6))
                }
                _ => "Amplitude envelope, section 1-4 (undamped)".to_string(),
            },
            "time (s)",
            "angle (°)",
            vec![
                Series::line("envelope ±A₀ e^(−ζω₀t)/√(1−ζ²)", upper),
                Series::line("", lower).colored(0),
            ],
        )],
    }
}

/// The page: a table of figures with units, then the pictures.
fn html(rows: &[Row], datasheet: Option<&[(String, String)]>) -> String {
    let sheet = match datasheet {
        Some(sheet) => {
            let mut t = String::from(
                "<h2>The pendulum as designed</h2>\n<p>Its parts and what they make of it, in air at 1013.25 hPa, 20 °C and 50 % humidity (as <code>pendulum design</code> gives it).</p>\n<table class=\"datasheet\">\n",
            );
            for (name, value) in sheet {
                t.push_str(&format!(
                    "<tr><th>{}</th><td>{}</td></tr>\n",
                    escape(name),
                    escape(value)
                ));
            }
            t.push_str("</table>\n");
            t
        }
        None => String::new(),
    };
    let mut table = String::new();
    for Row(name, value, note) in rows {
        table.push_str(&format!(
            "<tr><th>{}</th><td>{}</td><td class=\"note\">{}</td></tr>\n",
            escape(name),
            escape(value),
            escape(note)
        ));
    }
    format!(
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>Pendulum report</title>
<style>
body {{ font-family: "DejaVu Sans", Verdana, sans-serif; max-width: 62em; margin: 2em auto; color: #222; }}
table {{ border-collapse: collapse; margin: 1em 0 2em; }}
th, td {{ text-align: left; padding: 0.25em 1em 0.25em 0; border-bottom: 1px solid #ddd; }}
th {{ font-weight: normal; }}
.note {{ color: #666; font-size: 90%; }}
img {{ width: 100%; max-width: 960px; display: block; margin: 1em 0 2em; }}
</style>
</head>
<body>
<h1>Pendulum report</h1>
<p>Made by <code>pendulum report</code>: the exact period (section 1-6), the viscous
damping of section 1-4, the energy an escapement must supply, and the full
nonlinear damped motion run down until the amplitude halves.</p>
<table>
{table}</table>
{sheet}<h2>The period and the circular error around the working amplitude</h2>
<img src="period.svg" alt="period ratio and circular error against amplitude">
<h2>The decay of section 1-4</h2>
<img src="decay.svg" alt="amplitude envelope against time">
<h2>The simulated run-down and the rate it causes</h2>
<img src="rundown.svg" alt="amplitude and rate against time">
<script>
// Only for automated checks: counts pictures that failed to load.
window.addEventListener("load", function () {{
  var broken = 0;
  for (var i = 0; i < document.images.length; i++) {{
    if (!document.images[i].complete || document.images[i].naturalWidth === 0) broken++;
  }}
  document.body.setAttribute("data-broken-images", String(broken));
}});
</script>
</body>
</html>
"#
    )
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
