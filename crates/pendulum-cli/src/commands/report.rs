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
use pendulum_theory::damped::DampedPendulum;
use pendulum_theory::report::{report, Report, ReportInput, UNDAMPED_RUNDOWN_PERIODS};
use pendulum_theory::Pendulum;

/// One line of the page's table: quantity, value with unit, note.
struct Row(&'static str, String, &'static str);

pub fn run(args: &ReportArgs) -> Result<String, CliError> {
    let gravity = common::gravity(&args.gravity)?;
    let input = ReportInput {
        length: args.length.map(|l| l.0),
        design: args
            .design
            .as_deref()
            .map(crate::design::read_design)
            .transpose()?,
        g: Some(gravity.g_m_s2),
        amplitude: args.amplitude.map(|a| a.0),
        damping: common::damping_given(&args.damping)?,
        mass: args.mass.map(|m| m.0),
    };
    let design_file = args.design.as_ref().map(|p| p.display().to_string());
    let refused = |e: &pendulum_theory::analysis::Refusal| {
        if interrupt::requested() {
            return interrupt::error();
        }
        let in_file = |_: Option<(&'static str, usize)>, reason: &str| match &design_file {
            Some(file) => CliError::other(format!("{file}: {reason}")),
            None => CliError::other(reason),
        };
        CliError::refused(e, &[], &in_file)
    };
    let r = report(&input, &mut || !interrupt::requested()).map_err(|e| refused(&e))?;
    // The log is read and analysed before anything is written.
    let log = args
        .log
        .as_ref()
        .map(|file| log_section(args, file))
        .transpose()?;
    let json = args
        .json
        .then(|| {
            crate::output::json(&ReportJson {
                report: &r,
                log: log.as_ref().map(|l| &l.result),
            })
        })
        .transpose()?;
    let mut output = AtomicFolder::create(&args.output, "--output")?;
    let damped = r.damped.friction.damped;
    let pendulum = damped.pendulum;
    let a0 = r.damped.amplitude_rad;
    let a_deg = a0.to_degrees();
    write_figure(
        &mut output,
        "period.svg",
        &period_figure(
            &pendulum,
            r.period.elastic_share.unwrap_or(0.0),
            0.0,
            (2.0 * a_deg).clamp(6.0, 170.0),
            Some(a_deg),
        ),
    )?;
    let decay_span = r.damped.decay_time_s.map_or(
        UNDAMPED_RUNDOWN_PERIODS * pendulum.small_angle_period(),
        |t| 3.0 * std::f64::consts::LN_2 * t,
    );
    write_figure(
        &mut output,
        "decay.svg",
        &decay_figure(&damped, a0, decay_span),
    )?;
    let points: Vec<(f64, f64, f64)> = r
        .rundown
        .points
        .iter()
        .map(|p| (p.time_s, p.amplitude_rad.to_degrees(), p.rate_s_per_day))
        .collect();
    write_figure(&mut output, "rundown.svg", &rundown_figure(&points))?;
    let datasheet = r
        .datasheet
        .as_ref()
        .map(|sheet| super::design::rows(sheet, &gravity));
    let air = r.datasheet.as_ref().map(|d| {
        format!(
            "{} hPa, {} °C and {} % humidity",
            num(d.pressure_pa / 100.0, 6),
            num(d.temperature_c, 4),
            num(d.humidity * 100.0, 3)
        )
    });
    let mut log_html = String::new();
    if let Some(l) = &log {
        log_html = format!(
            "<h2>The clock's log</h2>\n<p>As <code>pendulum log</code> gives it: the rate against the weather{}, its stability before and after the model, and its periodic errors.</p>\n<pre>{}</pre>\n",
            if args.longitude.is_some() { " and the tides" } else { "" },
            escape(&super::log::text(&l.file, &l.result))
        );
        for (name, figure) in super::log::figures(&l.result) {
            let file = format!("log-{name}.svg");
            write_figure(&mut output, &file, &figure)?;
            log_html.push_str(&format!("<img src=\"{file}\" alt=\"the log: {name}\">\n"));
        }
    }
    let page = html(
        &rows(&r, &gravity, &pendulum),
        datasheet.as_deref().zip(air.as_deref()),
        &log_html,
    );
    crate::output::check_finite_text(&page)?;
    let mut file = AtomicFile::create(&output.file("index.html"), "--output")?;
    file.writer()
        .write_all(page.as_bytes())
        .map_err(|e| file.write_error(e))?;
    file.commit()?;
    let written = output.commit(&args.output)?;
    Ok(json.unwrap_or_else(|| format!("{}\n", written.join("index.html").display())))
}

/// The page's table of the report's numbers.
fn rows(r: &Report, gravity: &common::ResolvedGravity, pendulum: &Pendulum) -> Vec<Row> {
    let d = &r.damped;
    let p = &r.period;
    let undamped = d.zeta == 0.0;
    let mut rows = vec![
        Row(
            if r.from_design {
                "Equivalent length"
            } else {
                "Length"
            },
            format!("{} m", num(pendulum.length_m(), 8)),
            if r.from_design {
                "I / (m d) of the design"
            } else {
                ""
            },
        ),
        Row("Gravity", gravity.describe(), ""),
        Row(
            "Working amplitude",
            format!("{}°", num(p.amplitude_deg, 6)),
            "either side of the vertical",
        ),
        Row(
            "Period at that amplitude",
            format!("{} s", num(p.period_s, 12)),
            if p.elastic_share.is_some() {
                "exact, on the suspension spring: θ'' = −ω²[(1 − ε) sin θ + ε θ]"
            } else {
                "exact: 4 √(l/g) K(sin²(A₀/2))"
            },
        ),
        Row(
            "Small-angle period",
            format!("{} s", num(p.small_angle_period_s, 12)),
            "2π √(l/g)",
        ),
        Row(
            "Beats per hour",
            num(p.beats_per_hour, 9),
            "a beat is half a period",
        ),
        Row(
            "Circular error",
            format!("{} s/day", num(p.circular_error_s_per_day, 5)),
            "lost against a vanishing swing",
        ),
        Row(
            "… per degree of amplitude",
            format!("{} s/day/°", num(p.circular_error_s_per_day_per_deg, 5)),
            "how a change of swing moves the rate",
        ),
        Row("Damping ratio ζ", num(d.zeta, 5), "section 1-4"),
        Row(
            "Q",
            d.q_factor
                .map_or("infinite (undamped)".to_string(), |q| num(q, 6)),
            "1 / (2ζ)",
        ),
    ];
    if let Some(delta) = d.log_decrement {
        rows.push(Row(
            "Logarithmic decrement",
            format!("{} per period", num(delta, 5)),
            "2πζ / √(1 − ζ²)",
        ));
    }
    if let (Some(exact), Some(approx)) = (
        d.amplitude_loss_per_period_rad,
        d.amplitude_loss_per_period_approx_rad,
    ) {
        rows.push(Row(
            "Amplitude lost per period",
            format!(
                "{}° (first order {}°)",
                num(exact.to_degrees(), 5),
                num(approx.to_degrees(), 5)
            ),
            "A₀ (1 − exp(−δ)), and the first-order δ A₀ of section 1-4",
        ));
    }
    let decay_time = d.decay_time_s.unwrap_or(f64::INFINITY);
    let half_life = std::f64::consts::LN_2 * decay_time;
    rows.push(Row(
        "Amplitude decay time",
        if undamped {
            "none (undamped)".to_string()
        } else {
            format!("{} s", num(decay_time, 6))
        },
        if d.zeta > 1.0 {
            "the slow creep: (ζ + √(ζ² − 1)) / ωₙ"
        } else {
            "1 / (ζ ωₙ)"
        },
    ));
    rows.push(Row(
        "Amplitude half-life",
        if undamped {
            "none (undamped)".to_string()
        } else if d.damped_period_s.is_none() {
            format!(
                "none (overdamped: no swing; the creep halves in {} s)",
                num(half_life, 6)
            )
        } else {
            format!("{} s ({} min)", num(half_life, 6), num(half_life / 60.0, 4))
        },
        "ln 2 × decay time",
    ));
    let mass = d.mass_kg.unwrap_or(f64::NAN);
    rows.push(Row(
        if r.effective_mass {
            "Effective mass"
        } else {
            "Bob mass"
        },
        format!("{} kg", num(mass, 4)),
        if r.effective_mass {
            "the design's M d / l: its swing's energy is M g d (1 − cos A₀)"
        } else {
            "for the energy budget"
        },
    ));
    if let Some(b) = d.budget {
        rows.push(Row(
            "Energy in the swing",
            prefixed(b.energy, "J", 5),
            "m g l (1 − cos A₀)",
        ));
        rows.push(Row(
            "Energy lost per period",
            prefixed(b.loss_per_period, "J", 5),
            "what the escapement must restore",
        ));
        rows.push(Row(
            "Mean power",
            prefixed(b.power, "W", 5),
            "energy lost per period / period",
        ));
        rows.push(Row(
            "Impulse per beat",
            format!("{} kg m²/s", num(b.impulse_per_beat, 5)),
            "given at the bottom of the swing",
        ));
    }
    let run = &r.rundown;
    rows.push(Row(
        "Simulated run-down",
        format!(
            "{} s, {} turning points",
            num(run.final_time_s, 6),
            run.turning_points
        ),
        if run.stopped_short {
            "stopped short of half amplitude: at most 10⁵ periods, or a second of computing"
        } else {
            "nonlinear, symplectic integrator"
        },
    ));
    rows.push(Row(
        "Final amplitude",
        format!("{}°", num(run.final_amplitude_rad.to_degrees(), 6)),
        if !run.stopped_short && !undamped {
            "half the working amplitude"
        } else {
            "at the end of the simulated run"
        },
    ));
    rows.push(Row(
        "Rate drift during the run-down",
        match (run.first_rate_s_per_day, run.last_rate_s_per_day) {
            (Some(a), Some(b)) => format!("{} → {} s/day", num(a, 5), num(b, 5)),
            _ => "not determined (no full swing)".to_string(),
        },
        "circular error falls as the swing shrinks",
    ));
    for w in &r.warnings {
        rows.push(Row("Warning", w.to_string(), ""));
    }
    rows
}

/// What `--json` prints: the report's numbers and the log's analysis.
#[derive(serde::Serialize)]
struct ReportJson<'a> {
    #[serde(flatten)]
    report: &'a Report,
    #[serde(skip_serializing_if = "Option::is_none")]
    log: Option<&'a pendulum_theory::clock_log::LogResult>,
}

/// The log of `--log`, read as `pendulum log` reads it: the pendulum's
/// design beside it, the tides with --latitude and --longitude.
fn log_section(
    args: &ReportArgs,
    file: &crate::paths::InputPath,
) -> Result<super::log::Analysed, CliError> {
    super::log::analyse_file(&crate::args::LogArgs {
        file: file.clone(),
        kind: None,
        columns: None,
        latitude: args.gravity.latitude,
        longitude: args.longitude,
        height: args.gravity.height,
        tides: args.longitude.is_some(),
        start: None,
        design: args.design.clone(),
        length: None,
        nut: crate::args::NutArgs::default(),
        events: args.events.clone(),
        bin: None,
        beat: None,
        bph: None,
        period: None,
        flag_width: args.flag_width,
        gate_radius: args.gate_radius,
        train: args.train.clone(),
        arbor_turns_per_hour: args.arbor_turns_per_hour,
        plot: None,
        residuals: None,
        force: false,
        json: false,
    })
}

/// Draws `figure` as the report's file `name`.
fn write_figure(folder: &mut AtomicFolder, name: &str, figure: &Figure) -> Result<(), CliError> {
    render(&Target::new(&folder.file(name), "--output")?, figure)?;
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
            crate::plot::TIME_AXIS,
            "angle (°)",
            vec![
                Series::line("envelope ±A₀ exp(−ζω₀t) / √(1 − ζ²)", upper),
                Series::line("", lower).colored(0),
            ],
        )],
    }
}

/// `value` in `unit` with the SI prefix that puts it between 1 and 1000
/// (`41.936 µJ`, not `4.1936e-5 J`), to `digits` significant digits.
fn prefixed(value: f64, unit: &str, digits: usize) -> String {
    const PREFIXES: [(f64, &str); 9] = [
        (1e9, "G"),
        (1e6, "M"),
        (1e3, "k"),
        (1.0, ""),
        (1e-3, "m"),
        (1e-6, "µ"),
        (1e-9, "n"),
        (1e-12, "p"),
        (1e-15, "f"),
    ];
    let magnitude = value.abs();
    let (scale, prefix) = PREFIXES
        .iter()
        .copied()
        .find(|(scale, _)| magnitude >= *scale)
        .unwrap_or((1.0, ""));
    let scale = if magnitude == 0.0 { 1.0 } else { scale };
    let prefix = if magnitude == 0.0 { "" } else { prefix };
    format!("{} {prefix}{unit}", num(value / scale, digits))
}

/// Text with the minus sign (U+2212) for the hyphen before a number
/// (`−14.8`), where it is a sign, not a dash between words.
fn minus_signs(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    chars
        .iter()
        .enumerate()
        .map(|(i, &c)| {
            let sign = c == '-'
                && chars.get(i + 1).is_some_and(|n| n.is_ascii_digit())
                && (i == 0 || !chars[i - 1].is_alphanumeric());
            if sign {
                '−'
            } else {
                c
            }
        })
        .collect()
}

/// HTML text with every number in exponent form (`5e-5`, `1.2e7`) written
/// as a scientist would: `5 × 10<sup>−5</sup>`.
fn powers_of_ten(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        // A mantissa: digits with at most one point, not inside a word.
        let starts = chars[i].is_ascii_digit()
            && (i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '.'));
        if starts {
            let mut j = i;
            while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
                j += 1;
            }
            let mut k = j;
            if k < chars.len() && chars[k] == 'e' {
                k += 1;
                let negative = k < chars.len() && chars[k] == '-';
                if k < chars.len() && (chars[k] == '-' || chars[k] == '+') {
                    k += 1;
                }
                let digits_from = k;
                while k < chars.len() && chars[k].is_ascii_digit() {
                    k += 1;
                }
                let after_is_word = k < chars.len() && chars[k].is_alphanumeric();
                if k > digits_from && !after_is_word {
                    let mantissa: String = chars[i..j].iter().collect();
                    let power: String = chars[digits_from..k].iter().collect();
                    let power = power.trim_start_matches('0');
                    let sign = if negative { "−" } else { "" };
                    if mantissa == "1" {
                        out.push_str(&format!("10<sup>{sign}{power}</sup>"));
                    } else {
                        out.push_str(&format!("{mantissa} × 10<sup>{sign}{power}</sup>"));
                    }
                    i = k;
                    continue;
                }
            }
            out.extend(&chars[i..j]);
            i = j;
            continue;
        }
        out.push(chars[i]);
        i += 1;
    }
    out
}

/// The page: a table of figures with units, then the pictures.
fn html(rows: &[Row], datasheet: Option<(&[(String, String)], &str)>, log: &str) -> String {
    let sheet = match datasheet {
        Some((sheet, air)) => {
            let mut t = format!(
                "<h2>The pendulum as designed</h2>\n<p>Its parts and what they make of it, in air at {} (as <code>pendulum design</code> gives it).</p>\n<table class=\"datasheet\">\n",
                escape(air)
            );
            for (name, value) in sheet {
                t.push_str(&format!(
                    "<tr><th>{}</th><td>{}</td></tr>\n",
                    escape(name),
                    powers_of_ten(&minus_signs(&escape(value)))
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
            powers_of_ten(&minus_signs(&escape(value))),
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
<p class="note">The sections are those of <i lang="ja">機械式時計の理論</i> (The theory of
mechanical clocks and watches), part 1, <i lang="ja">振り子の運動</i> (The motion of the
pendulum): a web book at horology.sakura.ne.jp whose pages name no author.</p>
<table>
{table}</table>
{sheet}<h2>The period and the circular error around the working amplitude</h2>
<img src="period.svg" alt="period ratio and circular error against amplitude">
<h2>The decay of section 1-4</h2>
<img src="decay.svg" alt="amplitude envelope against time">
<h2>The simulated run-down and the rate it causes</h2>
<img src="rundown.svg" alt="amplitude and rate against time">
{log}<script>
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_as_a_report_prints_them() {
        assert_eq!(prefixed(4.1936e-5, "J", 5), "41.936 µJ");
        assert_eq!(prefixed(2.0968e-5, "W", 5), "20.968 µW");
        assert_eq!(prefixed(0.0667696, "J", 6), "66.7696 mJ");
        assert_eq!(prefixed(0.0, "J", 3), "0 J");
        assert_eq!(powers_of_ten("5e-5"), "5 × 10<sup>−5</sup>");
        assert_eq!(
            powers_of_ten("1e6 s, 2.5e+3 J"),
            "10<sup>6</sup> s, 2.5 × 10<sup>3</sup> J"
        );
        assert_eq!(powers_of_ten("0.99362 m"), "0.99362 m");
        assert_eq!(powers_of_ten("A0e5 x1e3"), "A0e5 x1e3");
        assert_eq!(
            minus_signs("-14.787 → -3.6879 s/day"),
            "−14.787 → −3.6879 s/day"
        );
        assert_eq!(minus_signs("section 1-4, e-5"), "section 1-4, e-5");
    }
}
