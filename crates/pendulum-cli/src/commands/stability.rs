//! `pendulum stability`: the deviations of any series, with intervals and
//! the noise at each averaging time.

use crate::args::{SeriesKind, StabilityArgs};
use crate::data::{headerless_width, read_table, ReadOptions, Role};
use crate::error::CliError;
use crate::output::{self, num, Summary};
use crate::plot::{render, Figure, Panel, Series, Target};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::stability::{
    grid, stability, DataKind, DeviationUnit, Gridded, Measured, Outliers, Stability,
    StabilityInput, StabilityRow, Taus, ADEV, DEVIATIONS,
};
use serde::Serialize;

/// What the command prints as JSON.
#[derive(Serialize)]
struct StabilityJson<'a> {
    file: String,
    format: crate::data::Format,
    /// The grid the samples were put on, when a time column was read.
    #[serde(skip_serializing_if = "Option::is_none")]
    grid: Option<&'a Gridded>,
    #[serde(flatten)]
    analysis: &'a Stability,
}

/// The role of the values of `kind`.
fn role(kind: SeriesKind) -> Role {
    match kind {
        SeriesKind::Phase => Role::Offset,
        SeriesKind::Frequency => Role::Frequency,
    }
}

pub fn run(args: &StabilityArgs) -> Result<String, CliError> {
    let plot = args
        .plot
        .as_deref()
        .map(|p| Target::new(p, "--plot"))
        .transpose()?;
    let file = args.file.display().to_string();
    // A bare column or two (a stability program's export) is named here.
    let columns = match (&args.columns, headerless_width(&args.file)) {
        (Some(c), _) => Some(super::measured::columns(Some(c)).unwrap_or_default()),
        (None, Some(width)) => {
            let Some(kind) = args.kind else {
                return Err(CliError::flag(
                    "--kind",
                    format!(
                        "{file} has no header to say what its values are: give --kind phase or \
                         --kind frequency"
                    ),
                ));
            };
            let value = match kind {
                SeriesKind::Phase => "offset_s",
                SeriesKind::Frequency => "frequency",
            };
            match width {
                1 => Some(vec![value.to_string()]),
                2 => Some(vec!["time_s".to_string(), value.to_string()]),
                n => {
                    return Err(CliError::other(format!(
                        "{file}: {n} columns and no header: name them with --columns (e.g. \
                         --columns time_s,offset_s)"
                    )))
                }
            }
        }
        (None, None) => None,
    };
    let options = ReadOptions {
        columns,
        ..ReadOptions::default()
    };
    let wanted = args.kind;
    let chooser = |found: &[crate::data::Found]| {
        let has = |r: Role| found.iter().any(|f| f.role == r);
        let value = match wanted {
            Some(k) if has(role(k)) => role(k),
            Some(k) => {
                return Err(format!(
                    "no {} column (named offset, phase, … for phase; rate, frequency, … for \
                     frequency)",
                    match k {
                        SeriesKind::Phase => "offset",
                        SeriesKind::Frequency => "rate",
                    }
                ))
            }
            None if has(Role::Offset) => Role::Offset,
            None if has(Role::Frequency) => Role::Frequency,
            None => {
                return Err(
                    "no offset (phase) or rate (frequency) column: name one, or give \
                            --kind"
                        .to_string(),
                )
            }
        };
        let mut roles = vec![value];
        if has(Role::Time) {
            roles.push(Role::Time);
        }
        Ok(roles)
    };
    let table = read_table(&args.file, &options, &chooser)?;
    let kind = match table.roles[0] {
        Role::Offset => DataKind::Phase,
        _ => DataKind::Frequency,
    };
    let values = &table.values[0];
    let refused = |r: &Refusal| {
        CliError::refused(r, &[("tau0", "--tau0")], &|at, reason| match at {
            Some((_, i)) => CliError::other(format!(
                "{file}: line {}: {reason}",
                table.lines.get(i).copied().unwrap_or(0)
            )),
            None => CliError::other(format!("{file}: {reason}")),
        })
    };
    let tau0 = args.tau0.map(|t| t.0);
    let gridded = match table.column(Role::Time) {
        Some(times) => Some(grid(times, values, tau0).map_err(|r| refused(&r))?),
        None => None,
    };
    let (data, tau0_s) = match &gridded {
        Some(g) => (g.data.clone(), g.tau0_s),
        None => (
            values.clone(),
            tau0.ok_or_else(|| {
                CliError::flag(
                    "--tau0",
                    "the file has no time column: give the spacing of its samples",
                )
            })?,
        ),
    };
    let result = stability(&StabilityInput {
        data,
        kind,
        tau0_s,
        taus: if args.all_taus {
            Taus::All
        } else {
            Taus::Octave
        },
        force: args.force,
        outliers: match args.outliers {
            crate::args::OutliersArg::Keep => Outliers::Keep,
            crate::args::OutliersArg::Remove => Outliers::Remove,
        },
    })
    .map_err(|r| refused(&r))?;
    if let Some(target) = &plot {
        render(target, &figure(&result))?;
    }
    if args.json {
        return output::json(&StabilityJson {
            file,
            format: table.format,
            grid: gridded.as_ref(),
            analysis: &result,
        });
    }
    if args.csv {
        return output::csv_flat(&result.rows);
    }
    Ok(text(&file, &result, gridded.as_ref()))
}

/// A deviation and its interval: "1.23e-7 (1.1e-7 … 1.4e-7)".
fn with_interval(m: &Measured) -> String {
    match (m.value, m.interval) {
        (Some(v), Some((l, h))) => format!("{} ({} … {})", num(v, 4), num(l, 2), num(h, 2)),
        (Some(v), None) => num(v, 4),
        _ => "–".to_string(),
    }
}

/// The whole for people: the table, the noises in words, the best τ.
pub(crate) fn text(file: &str, s: &Stability, gridded: Option<&Gridded>) -> String {
    let mut summary = Summary::default();
    summary.row("File", file).row(
        "Series",
        format!(
            "{} phase points, τ0 = {} s{}",
            s.phase_points,
            num(s.tau0_s, 6),
            match s.kind {
                DataKind::Phase => " (offsets)",
                DataKind::Frequency => " (rates, summed into phase)",
            }
        ),
    );
    if let Some(g) = gridded.filter(|g| g.missing > 0 || g.merged > 0) {
        summary.row(
            "Gaps",
            format!(
                "{} of the grid's points have no sample{}",
                g.missing,
                if g.merged > 0 {
                    format!("; {} samples shared a point and were averaged", g.merged)
                } else {
                    String::new()
                }
            ),
        );
    }
    let mut out = summary.render();
    out.push('\n');
    // One column per deviation of the library's list, then the rate and
    // the noise.
    let mut header: Vec<String> = vec!["τ (s)".into()];
    for d in DEVIATIONS {
        header.push(match (d.interval, d.unit) {
            (Some(_), _) => format!("{} (68% interval)", d.name),
            (None, DeviationUnit::Seconds) => format!("{} (s)", d.name),
            (None, DeviationUnit::Fractional) => d.name.to_string(),
        });
    }
    header.extend(["ADEV (s/day)".into(), "noise".into()]);
    let rows: Vec<Vec<String>> = s
        .rows
        .iter()
        .map(|r| {
            let mut cells = vec![num(r.tau_s, 6)];
            cells.extend(r.deviations.0.iter().map(with_interval));
            cells.push(r.adev_s_per_day.map_or("–".into(), |v| num(v, 3)));
            cells.push(match r.noise {
                Some(n) if r.noise_carried => format!("{} (from shorter τ)", n.name()),
                Some(n) => n.name().to_string(),
                None if r.periodic => "periodic signal".into(),
                None => "–".into(),
            });
            cells
        })
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    out.push_str(&output::table(&header, &rows));
    out.push('\n');
    // The noises in words, each where it starts; the rows a periodic
    // signal makes are said apart.
    let mut previous = None;
    for r in &s.rows {
        if r.periodic {
            previous = None;
            continue;
        }
        if let Some(n) = r.noise.filter(|&n| Some(n) != previous) {
            out.push_str(&format!(
                "From τ = {} s: {}: {}.\n",
                num(r.tau_s, 4),
                n.name(),
                n.meaning()
            ));
        }
        previous = r.noise;
    }
    // Rows without an interval, runs of one reason named once.
    let mut reasons: Vec<(f64, f64, &str)> = Vec::new();
    for r in &s.rows {
        match (r.no_interval_reason, reasons.last_mut()) {
            (Some(why), Some((_, last, said))) if *said == why => *last = r.tau_s,
            (Some(why), _) => reasons.push((r.tau_s, r.tau_s, why)),
            (None, _) => {}
        }
    }
    if !reasons.is_empty() {
        let said: Vec<String> = reasons
            .iter()
            .map(|&(first, last, why)| {
                let taus = if first == last {
                    format!("τ = {} s", num(first, 4))
                } else {
                    format!("τ = {} to {} s", num(first, 4), num(last, 4))
                };
                format!("{taus}: {why}")
            })
            .collect();
        out.push_str(&format!("No interval at {}.\n", said.join("; ")));
    }
    if let Some(b) = &s.best {
        out.push_str(&format!(
            "Steadiest at τ = {} s: ADEV {} = {} s/day{}.\n",
            num(b.tau_s, 4),
            num(b.adev, 3),
            num(b.adev_s_per_day, 3),
            if b.at_longest_tau {
                " (the longest τ the record allows: it may average down further)"
            } else {
                ""
            }
        ));
    }
    for w in &s.warnings {
        out.push_str(&format!("warning: {w}\n"));
    }
    out
}

/// Each row's (τ, ADEV, interval low, high), a point without a bar where
/// the row has no interval: the figures of `stability` and `log` draw them.
pub(crate) fn adev_bars(rows: &[StabilityRow]) -> Vec<(f64, f64, f64, f64)> {
    rows.iter()
        .filter_map(|r| {
            let a = r.adev()?;
            let (low, high) = r.interval(&ADEV).unwrap_or((a, a));
            Some((r.tau_s, a, low, high))
        })
        .collect()
}

/// A deviation axis's title: the fractional frequency.
pub(crate) fn deviation_axis(name: &str) -> String {
    format!("{name} (fractional frequency)")
}

/// The same deviations in seconds a day (a clockmaker's unit), for the
/// axis on the right: a fraction times the day's 86,400 s.
pub(crate) const S_PER_DAY_AXIS: (&str, f64) = ("the same in s/day", 86_400.0);

/// The deviations against τ, log–log, the Allan deviation's interval as
/// a bar on its point (none where a periodic signal rules).
fn figure(s: &Stability) -> Figure {
    let pick = |f: &dyn Fn(&StabilityRow) -> Option<f64>| -> Vec<(f64, f64)> {
        s.rows
            .iter()
            .filter_map(|r| Some((r.tau_s, f(r)?)))
            .collect()
    };
    // The other fractional deviations of the library's list as light
    // lines (the times, TDEV and MTIE, have another unit), ADEV on top.
    let mut series: Vec<Series> = DEVIATIONS
        .iter()
        .filter(|d| d.unit == DeviationUnit::Fractional && **d != ADEV)
        .enumerate()
        .map(|(i, d)| {
            Series::line(d.name, pick(&|r| r.value(d)))
                .colored(i + 1)
                .light()
        })
        .collect();
    series.push(
        Series::dots_with_bars(
            "ADEV (overlapping), 68% interval as a bar",
            adev_bars(&s.rows),
        )
        .colored(0),
    );
    let panel = Panel::new(
        "Frequency stability",
        "averaging time τ (s)",
        deviation_axis("deviation"),
        series,
    )
    .log_log()
    .twin_y(S_PER_DAY_AXIS.0, S_PER_DAY_AXIS.1);
    Figure {
        panels: vec![panel],
    }
}
