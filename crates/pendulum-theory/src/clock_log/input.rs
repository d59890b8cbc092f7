//! The log read: every input checked and named in its refusal, samples
//! whose time did not advance and half periods the gate missed left out,
//! the columns checked against what a clock's room holds, the amplitude
//! read from a photogate's pulses, and the bin length chosen.

use super::result::{LogInput, LogKind, LogWarning};
use super::terms::{column_spec, ColumnSpec};
use super::wheels::Arbor;
use crate::analysis::{judge_work, require_finite, Refusal};
use crate::compound::datasheet::{datasheet, Air};
use crate::error::format_significant;

/// A log checked, in the analysis' terms.
pub(crate) struct Prepared {
    pub kind: LogKind,
    pub times: Vec<f64>,
    pub values: Vec<f64>,
    /// Each given column (the amplitude read from pulses among them), in
    /// its SI unit, one value a sample.
    pub columns: Vec<(&'static ColumnSpec, Vec<f64>)>,
    /// The nominal half period given, s.
    pub nominal_half: Option<f64>,
    pub arbors: Vec<Arbor>,
    /// The samples' typical spacing, s.
    pub dt: f64,
    pub span: f64,
    /// The bin length, s.
    pub bin: f64,
    pub warnings: Vec<LogWarning>,
}

impl Prepared {
    /// The column named `name`.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.columns
            .iter()
            .find(|(c, _)| c.name == name)
            .map(|(_, v)| v.as_slice())
    }
}

/// The least bins a mean rate needs (its standard error from two
/// degrees of freedom); fewer than [`FOR_TERMS`] give the mean rate
/// alone.
pub(crate) const LEAST: usize = 4;
/// The least bins the weather, the drift and the walk need.
pub(crate) const FOR_TERMS: usize = 10;

/// Which samples to keep, and the warning: samples whose time does not
/// advance (a logger's stamp repeated, files joined with an overlap: at
/// most 1% of them) are left out; more than that is a log out of order,
/// kept whole for the check that refuses it by line.
fn repeated_times(time_s: &[f64]) -> (Vec<bool>, Vec<LogWarning>) {
    let n = time_s.len();
    let mut keep = vec![true; n];
    let (mut last, mut repeated, mut first_repeated) = (f64::NEG_INFINITY, 0, None);
    for (i, &t) in time_s.iter().enumerate() {
        if t > last || !t.is_finite() {
            last = if t.is_finite() { t } else { last };
        } else {
            keep[i] = false;
            repeated += 1;
            first_repeated.get_or_insert(i);
        }
    }
    let mut warnings = Vec::new();
    if repeated * 100 > n {
        keep.fill(true);
    } else if let Some(first) = first_repeated {
        warnings.push(LogWarning::TimesRepeated {
            dropped: repeated,
            first_time_s: time_s[first],
        });
    }
    (keep, warnings)
}

/// The kept samples checked: finite, times rising, values that change,
/// half periods positive and evenly spaced.
fn check_samples(times: &[f64], values: &[f64], kind: LogKind) -> Result<(), Refusal> {
    let n = times.len();
    for (i, (&t, &v)) in times.iter().zip(values).enumerate() {
        crate::analysis::require_finite_sample("time", i, t)?;
        crate::analysis::require_finite_sample("values", i, v)?;
        if i > 0 && t <= times[i - 1] {
            return Err(Refusal::sample(
                "time",
                i,
                format!(
                    "{} s is not after the previous {} s; sort by time",
                    format_significant(t, 12),
                    format_significant(times[i - 1], 12)
                ),
            ));
        }
    }
    if values.iter().all(|&v| v == values[0]) {
        return Err(Refusal::data(format!(
            "the values never change (all {n} are {}): a logger stuck, or a column that is not the clock's?",
            format_significant(values[0], 6)
        )));
    }
    if kind == LogKind::HalfPeriods {
        if let Some(i) = values.iter().position(|&v| v <= 0.0) {
            return Err(Refusal::sample(
                "values",
                i,
                "a half period must be positive",
            ));
        }
        evenly_spaced(values)?;
    }
    Ok(())
}

/// The typical spacing of `times` (at least two), s: the median of at
/// most 100,000 intervals evenly spread.
fn typical_spacing(times: &[f64]) -> f64 {
    let n = times.len();
    let stride = ((n - 1) / 100_000).max(1);
    let mut spacing: Vec<f64> = (0..n - 1)
        .step_by(stride)
        .map(|i| times[i + 1] - times[i])
        .collect();
    let half = spacing.len() / 2;
    *spacing.select_nth_unstable_by(half, f64::total_cmp).1
}

/// Checks `input` and leaves out what cannot be used.
pub(crate) fn prepare(input: &LogInput) -> Result<Prepared, Refusal> {
    let n = input.time_s.len();
    if input.values.len() != n {
        return Err(Refusal::field(
            "values",
            format!("has {} values for {n} times", input.values.len()),
        ));
    }
    let mut columns: Vec<(&'static ColumnSpec, Vec<f64>)> = Vec::new();
    for c in &input.columns {
        let spec = column_spec(&c.name)?;
        if columns.iter().any(|(s, _)| s.name == spec.name) {
            return Err(Refusal::field(spec.name, "is given twice"));
        }
        columns.push((spec, checked_column(spec, &c.values, n)?));
    }
    let pulses = match &input.pulse_width_s {
        Some(p) => Some(checked("pulse_width", p, n, None)?),
        None => None,
    };
    let (mut keep, mut warnings) = repeated_times(&input.time_s);
    let kind = input.kind.unwrap_or(LogKind::Offset);
    if kind == LogKind::HalfPeriods {
        let odd = missed_beats(&input.values, &mut keep)?;
        if odd > 0 {
            warnings.push(LogWarning::BeatsMissed { left_out: odd });
        }
    }
    let pick = |v: &[f64]| -> Vec<f64> {
        v.iter()
            .zip(&keep)
            .filter(|(_, &k)| k)
            .map(|(x, _)| *x)
            .collect()
    };
    let times = pick(&input.time_s);
    let values = pick(&input.values);
    let mut columns: Vec<(&'static ColumnSpec, Vec<f64>)> =
        columns.into_iter().map(|(s, v)| (s, pick(&v))).collect();
    let pulses = pulses.map(|p| pick(&p));
    let n = times.len();
    if n < LEAST + 1 {
        return Err(Refusal::data(format!(
            "a log needs at least {} samples (four rates for a mean rate and its error), got {n}",
            LEAST + 1
        )));
    }
    check_samples(&times, &values, kind)?;
    let nominal_half = input
        .nominal
        .map(crate::listening::analysis::nominal_period)
        .transpose()?
        .map(|p| p / 2.0);
    check_sizes(input)?;
    let arbors = arbors(input)?;
    // A photogate's sizes without its pulses would be ignored: refused.
    if pulses.is_none() {
        for (field, given) in [
            ("flag_width", input.flag_width_m),
            ("gate_radius", input.gate_radius_m),
        ] {
            if given.is_some() {
                return Err(Refusal::field(
                    field,
                    "reads a photogate's pulse widths, and the log has none (a pulse_width column)",
                ));
            }
        }
    }
    let has_amplitude = columns.iter().any(|(s, _)| s.name == "amplitude");
    if let (false, Some(p)) = (has_amplitude, &pulses) {
        if p.iter().any(|v| v.is_finite()) {
            if input.flag_width_m.is_none() && input.gate_radius_m.is_none() {
                warnings.push(LogWarning::PulsesIgnored);
            } else {
                let spec = column_spec("amplitude")?;
                let kind_half = (kind == LogKind::HalfPeriods).then(|| mean(&values));
                columns.push((spec, amplitudes_from_pulses(input, p, kind_half)?));
            }
        }
    }
    let dt = typical_spacing(&times);
    let span = times[n - 1] - times[0];
    let bin = bin_length(input.bin_s, dt, span)?;
    // Work, measured on a year of 3 s samples in hourly bins: about
    // 0.3 µs a sample (binning, lagging the temperature, the stability)
    // and 0.2 ms a bin (the fits).
    let bins_n = span / bin;
    judge_work(
        "bin",
        format_args!(
            "{} samples in {} bins",
            crate::analysis::count(n as f64),
            crate::analysis::count(bins_n)
        ),
        n as f64 * 3e-7 + bins_n * 2e-4,
        input.force,
    )?;
    Ok(Prepared {
        kind,
        times,
        values,
        columns,
        nominal_half,
        arbors,
        dt,
        span,
        bin,
        warnings,
    })
}

/// The bin length: the one given, else an hour or the samples' spacing if
/// longer, or a 24th of a log too short for 24 of those; refused when it
/// leaves fewer than [`LEAST`] bins.
fn bin_length(given: Option<f64>, dt: f64, span: f64) -> Result<f64, Refusal> {
    let bin = match given {
        Some(b) => {
            let b = require_finite("bin", b)?;
            if b <= 0.0 {
                return Err(Refusal::field(
                    "bin",
                    format!("must be positive, got {} s", format_significant(b, 6)),
                ));
            }
            b
        }
        None => {
            let hour = 3600f64.max(dt);
            if span / hour < 24.0 {
                (span / 24.0).max(dt)
            } else {
                hour
            }
        }
    };
    if span / bin < LEAST as f64 - 1e-9 {
        let hint = if span / dt < LEAST as f64 - 1e-9 {
            format!(
                "the log holds only {} readings' spacing of {} s",
                (span / dt).round(),
                format_significant(dt, 6)
            )
        } else {
            "give a shorter --bin".to_string()
        };
        return Err(Refusal::field(
            "bin",
            format!(
                "{} s leaves {} bins over the log's {} s; a mean rate needs {LEAST}: {hint}",
                format_significant(bin, 6),
                (span / bin).floor(),
                format_significant(span, 6)
            ),
        ));
    }
    Ok(bin)
}

/// Half periods far from the typical one (under half or over 1.5 times
/// it): a transit the gate missed (two half periods read as one) or a
/// stray trigger (one cut in two). Marks them not kept; refuses a log
/// where more than a quarter are.
fn missed_beats(values: &[f64], keep: &mut [bool]) -> Result<usize, Refusal> {
    let n = values.len();
    if n < 10 {
        return Ok(0);
    }
    let mut typical: Vec<f64> = values
        .iter()
        .step_by((n / 10_000).max(1))
        .copied()
        .filter(|v| v.is_finite() && *v > 0.0)
        .collect();
    if typical.is_empty() {
        return Ok(0);
    }
    let h = typical.len() / 2;
    let median = *typical.select_nth_unstable_by(h, f64::total_cmp).1;
    let mut odd = 0;
    for (i, &v) in values.iter().enumerate() {
        if keep[i] && v.is_finite() && v > 0.0 && !(0.5 * median..=1.5 * median).contains(&v) {
            keep[i] = false;
            odd += 1;
        }
    }
    if odd * 4 > n {
        return Err(Refusal::data(format!(
            "{odd} of {n} half periods are less than half or more than 1.5 times the typical {} s: are they half periods of one pendulum?",
            format_significant(median, 6)
        )));
    }
    Ok(odd)
}

/// Refuses half periods that are all the same to a part in 10⁹, or
/// shorter than any clock's beat (36,000 beats an hour is 0.1 s): the
/// sample times of a recorder or a video's frames, not a pendulum's
/// beats, which no gate times alike.
fn evenly_spaced(values: &[f64]) -> Result<(), Refusal> {
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let typical = mean(values);
    if hi - lo <= 1e-9 * hi || typical < 0.05 {
        return Err(Refusal::data(format!(
            "the times are {} s apart{}: the sample times of a recorder or a video's frames, not a clock's beats; for a tracked swing use `fit trajectory` or `fit decay`",
            format_significant(typical, 6),
            if hi - lo <= 1e-9 * hi { ", all alike" } else { ", faster than any clock beats" }
        )));
    }
    Ok(())
}

/// A column checked: one value a sample, finite or NaN, inside the
/// column's range.
fn checked_column(spec: &ColumnSpec, c: &[f64], n: usize) -> Result<Vec<f64>, Refusal> {
    checked(spec.name, c, n, Some(spec))
}

fn checked(
    name: &'static str,
    c: &[f64],
    n: usize,
    spec: Option<&ColumnSpec>,
) -> Result<Vec<f64>, Refusal> {
    if c.len() != n {
        return Err(Refusal::field(
            name,
            format!("has {} values for {n} times", c.len()),
        ));
    }
    if let Some(i) = c.iter().position(|v| v.is_infinite()) {
        return Err(Refusal::sample(
            name,
            i,
            "must be finite, got an infinite value",
        ));
    }
    if let Some(spec) = spec {
        let (low, high) = spec.range;
        if let Some(i) = c
            .iter()
            .position(|v| v.is_finite() && !(low..=high).contains(v))
        {
            return Err(Refusal::sample(
                name,
                i,
                format!(
                    "{} is outside {} to {} {}",
                    format_significant(c[i], 6),
                    format_significant(low, 6),
                    format_significant(high, 6),
                    spec.hint
                ),
            ));
        }
    }
    Ok(c.to_vec())
}

/// The sizes a log may give, each in its range.
fn check_sizes(input: &LogInput) -> Result<(), Refusal> {
    if let Some(t) = input.train.as_ref().and_then(|t| t.arbor_turns_per_hour) {
        if require_finite("arbor_turns_per_hour", t)? <= 0.0 {
            return Err(Refusal::field(
                "arbor_turns_per_hour",
                format!("must be positive, got {}", format_significant(t, 6)),
            ));
        }
    }
    for (name, value, low, high) in [
        ("beat", input.beat_s, 1e-6, 3600.0),
        ("flag_width", input.flag_width_m, 1e-6, 1.0),
        ("gate_radius", input.gate_radius_m, 1e-3, 100.0),
    ] {
        if let Some(v) = value {
            let v = require_finite(name, v)?;
            if !(low..=high).contains(&v) {
                return Err(Refusal::field(
                    name,
                    format!(
                        "must be from {} to {}, got {}",
                        format_significant(low, 3),
                        format_significant(high, 3),
                        format_significant(v, 6)
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The train's arbors, each turning once in 1 ms to 10 years.
fn arbors(input: &LogInput) -> Result<Vec<Arbor>, Refusal> {
    let arbors = match &input.train {
        Some(train) => train.arbors().ok_or_else(|| {
            Refusal::field(
                "train",
                "needs one pinion fewer than wheels and no count zero",
            )
        })?,
        None => Vec::new(),
    };
    if let Some(a) = arbors
        .iter()
        .find(|a| !(1e-3..=3.2e8).contains(&a.period_s))
    {
        return Err(Refusal::field(
            "train",
            format!(
                "makes the {} turn {}; a clock's arbors turn once in 1 ms to 10 years (check the first arbor's turns an hour)",
                a.name,
                if a.period_s.is_finite() {
                    format!("once in {} s", format_significant(a.period_s, 3))
                } else {
                    "too slowly to count".to_string()
                }
            ),
        ));
    }
    Ok(arbors)
}

/// The mean of the finite values.
pub(crate) fn mean(v: &[f64]) -> f64 {
    let (s, n) = v
        .iter()
        .filter(|x| x.is_finite())
        .fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    s / n.max(1) as f64
}

/// The amplitude (rad) of every swing from its pulse: the flag and the
/// gate given, the pendulum's equivalent length from the design, else
/// from the nominal half period (a simple pendulum) or the log's own mean
/// half period, in the station's normal gravity (or standard gravity).
fn amplitudes_from_pulses(
    input: &LogInput,
    pulses: &[f64],
    measured_half: Option<f64>,
) -> Result<Vec<f64>, Refusal> {
    let flag = input
        .flag_width_m
        .ok_or_else(|| Refusal::field("flag_width", "is needed to read the pulse widths"))?;
    let radius = input
        .gate_radius_m
        .ok_or_else(|| Refusal::field("gate_radius", "is needed to read the pulse widths"))?;
    let g = match input.station {
        Some(s) => crate::gravity::normal_gravity(s.latitude_deg, s.height_m)
            .map_err(|e| Refusal::input("height", &e))?,
        None => crate::STANDARD_GRAVITY,
    };
    let nominal_half = input
        .nominal
        .map(crate::listening::analysis::nominal_period)
        .transpose()?
        .map(|p| p / 2.0);
    let length = match (&input.design, nominal_half.or(measured_half)) {
        (Some(d), _) => datasheet(d, Some(g), &Air::default())?.equivalent_length_m,
        (None, Some(h)) if h > 0.0 => g * (2.0 * h / std::f64::consts::TAU).powi(2),
        _ => return Err(Refusal::field(
            "design",
            "or a nominal beat (or half periods) is needed to turn pulse widths into amplitudes",
        )),
    };
    pulses
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            if p.is_nan() {
                return Ok(f64::NAN);
            }
            super::amplitude_from_pulse(p, flag, radius, length, g)
                .map_err(|r| Refusal::sample("pulse_width", i, r.reason))
        })
        .collect()
}
