//! One call for a clock's log: validation, binning, the rate model with
//! its terms chosen, the design's prediction beside it, and stability.

use super::model::{fit, Fit, Walk};
use super::series::{lagged, lagged_means, offsets_to_bins, rates_to_bins, unwrap, Bins, Wrap};
use super::spectrum::{spectrum, Spectrum, TIDAL_LINES};
use super::swing::{swing, Swing};
use super::wheels::{folds, Arbor, Fold, TrainInput};
use crate::analysis::{judge_work, require_finite, Refusal};
use crate::compound::datasheet::{datasheet, Air};
use crate::compound::description::Design;
use crate::error::format_significant;
use crate::fitting::beats::standard_rate_near;
use crate::period::Nominal;
use crate::stability::{stability, DataKind, StabilityInput, StabilityRow, Taus};
use crate::tide::{gravity_change, rate_s_per_day, Station};
use serde::Serialize;

/// What a log's values are.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LogKind {
    /// The clock's offset from a reference (clock minus reference), s.
    Offset,
    /// The clock's rate, s/day (positive: gaining).
    Rate,
    /// Half periods (beats) from a photogate, s.
    HalfPeriods,
}

/// A clock's log, in SI.
#[derive(Clone, Debug, Default)]
pub struct LogInput {
    /// Each sample's time, s, increasing (the log's own clock).
    pub time_s: Vec<f64>,
    /// The Unix time of `time_s = 0`, s: needed for the tides.
    pub epoch_unix_s: Option<f64>,
    /// What `values` are.
    pub kind: Option<LogKind>,
    /// Offsets (s), rates (s/day) or half periods (s).
    pub values: Vec<f64>,
    /// Air temperature, °C, a sample each (NaN: not read).
    pub temperature_c: Option<Vec<f64>>,
    /// Air pressure, hPa.
    pub pressure_hpa: Option<Vec<f64>>,
    /// Relative humidity, %.
    pub humidity_percent: Option<Vec<f64>>,
    /// The swing's amplitude, degrees.
    pub amplitude_deg: Option<Vec<f64>>,
    /// A photogate's pulse widths, s (the amplitude from them, exactly,
    /// when `amplitude_deg` is not given: [`super::amplitude_from_pulse`]).
    pub pulse_width_s: Option<Vec<f64>>,
    /// The flag's width, m (with `pulse_width_s`).
    pub flag_width_m: Option<f64>,
    /// The gate's distance from the pivot, m (with `pulse_width_s`).
    pub gate_radius_m: Option<f64>,
    /// For half periods: the nominal beat rate or period (default: the
    /// standard beat within 2% of the mean half period, else the mean).
    pub nominal: Option<Nominal>,
    /// For offsets: the beat a reference comparison slips by, s (default:
    /// found from the jumps).
    pub beat_s: Option<f64>,
    /// Where the clock is: with `tides`, the tidal term.
    pub station: Option<Station>,
    /// Fit the tidal term.
    pub tides: bool,
    /// Times of steps of the rate (a regulation, a weight added), s of
    /// the log's time.
    pub events_s: Vec<f64>,
    /// The bin length, s (default an hour, or the samples' spacing if
    /// longer; a 24th of the log when that leaves fewer than 24 bins).
    pub bin_s: Option<f64>,
    /// The clock's design: its predicted coefficients shown beside the
    /// measured ones.
    pub design: Option<Design>,
    /// Run even when the work estimate is long.
    pub force: bool,
    /// Leave out the stability (the result's two lists empty): for a
    /// caller that wants the model alone, sooner.
    pub skip_stability: bool,
    /// The going train: its wheels' periods marked in the spectrum and
    /// the rate folded over each.
    pub train: Option<TrainInput>,
}

/// The model's coefficients (or their standard errors), each `None` when
/// the term is not in the model.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Coefficients {
    /// Rate change per °C of the lagged temperature, s/day/°C.
    pub temperature_s_per_day_per_c: Option<f64>,
    /// Per hPa, s/day/hPa.
    pub pressure_s_per_day_per_hpa: Option<f64>,
    /// Per % of relative humidity, s/day/%.
    pub humidity_s_per_day_per_percent: Option<f64>,
    /// Per degree of amplitude, s/day/°.
    pub amplitude_s_per_day_per_deg: Option<f64>,
    /// The tide's admittance: 1 when the clock's rate follows the body
    /// tide's Δg/2g in full.
    pub tide_admittance: Option<f64>,
    /// The rate steps at the events, s/day, in their order.
    pub steps_s_per_day: Vec<f64>,
}

/// A term the information criterion judged.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Term {
    /// Its name (`drift`, `temperature`, …).
    pub name: &'static str,
    /// Kept in the model.
    pub kept: bool,
    /// The BIC of the model without it minus with it: positive means the
    /// data want it (above 6: strongly; Kass & Raftery 1995).
    pub delta_bic: f64,
}

/// The design's predicted coefficients beside the measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DesignComparison {
    /// Predicted s/day/°C.
    pub temperature_s_per_day_per_c: f64,
    /// Measured minus predicted, in the measured standard errors.
    pub temperature_difference_se: Option<f64>,
    /// Predicted s/day/hPa.
    pub pressure_s_per_day_per_hpa: f64,
    /// Measured minus predicted, in standard errors.
    pub pressure_difference_se: Option<f64>,
    /// Predicted s/day/% of humidity.
    pub humidity_s_per_day_per_percent: f64,
    /// Measured minus predicted, in standard errors.
    pub humidity_difference_se: Option<f64>,
}

/// What a reader of the result must know.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LogWarning {
    /// Whole-beat jumps of the offsets were undone.
    WrapsUndone {
        /// How many.
        count: usize,
    },
    /// A coefficient no pendulum has: the units or the columns are
    /// likely wrong.
    Implausible {
        /// Which.
        term: &'static str,
        /// Why, in words.
        reason: String,
    },
    /// The tidal admittance is far from 1: something the model lacks
    /// shares the tide's periods, or the times are not UTC.
    TideAdmittance {
        /// The admittance.
        admittance: f64,
        /// In standard errors from 1.
        from_one_se: f64,
    },
    /// Too short a log to tell the tide (under 3 days) or the drift.
    Short {
        /// What cannot be told.
        what: &'static str,
    },
    /// Samples whose time did not advance were left out.
    TimesRepeated {
        /// How many.
        dropped: usize,
        /// The first one's time, s.
        first_time_s: f64,
    },
    /// Half periods were compared with their own mean: the rate is
    /// against the clock's average, not a standard beat.
    RateAgainstMean,
    /// Half periods far from the typical one (under half or over 1.5
    /// times it: a transit the gate missed, a stray trigger) were left
    /// out; the beats they span count as a gap.
    BeatsMissed {
        /// How many.
        left_out: usize,
    },
    /// An event the model leaves out.
    EventIgnored {
        /// Its time, s of the log's time.
        time_s: f64,
        /// Why.
        reason: &'static str,
    },
    /// Pulse widths were given without the flag and the gate that turn
    /// them into amplitudes: they are left aside.
    PulsesIgnored,
    /// The train's beat is not the log's.
    TrainBeat {
        /// Beats an hour the train gives.
        train_bph: f64,
        /// Beats an hour of the log.
        log_bph: f64,
    },
}

/// The analysis of a log.
#[derive(Clone, Debug, Serialize)]
pub struct LogResult {
    /// What the values were.
    pub kind: LogKind,
    /// The Unix time of the log's time 0, when known, s.
    pub epoch_unix_s: Option<f64>,
    /// Samples read.
    pub samples: usize,
    /// The log's span, s.
    pub span_s: f64,
    /// The bin length, s.
    pub bin_s: f64,
    /// Bins fitted.
    pub bins: usize,
    /// The rate at the log's mean time and mean weather, s/day.
    pub rate_s_per_day: f64,
    /// Its standard error.
    pub rate_standard_error_s_per_day: f64,
    /// The log time the rate is at (the bins' mean), s.
    pub reference_time_s: f64,
    /// The rate's drift, s/day a day (`None`: not in the model).
    pub drift_s_per_day_per_day: Option<f64>,
    /// Its standard error.
    pub drift_standard_error_s_per_day_per_day: Option<f64>,
    /// The coefficients.
    pub coefficients: Coefficients,
    /// Their standard errors.
    pub standard_errors: Coefficients,
    /// The names of the fitted parameters, in the order of `correlations`.
    pub parameters: Vec<String>,
    /// The parameters' correlation matrix.
    pub correlations: Vec<Vec<f64>>,
    /// The temperature lag's time constant, s (0: none).
    pub temperature_lag_s: Option<f64>,
    /// The lags within 2 of the best log-likelihood (a 95% range), s.
    pub temperature_lag_range_s: Option<[f64; 2]>,
    /// The means the coefficients are about: temperature °C, pressure
    /// hPa, humidity %, amplitude °.
    pub reference_weather: [Option<f64>; 4],
    /// The terms the criterion judged.
    pub terms: Vec<Term>,
    /// The white frequency noise of one bin's rate, s/day.
    pub white_noise_s_per_day: f64,
    /// The random walk of the rate in a day, s/day (0: none found).
    pub random_walk_s_per_day_per_day: f64,
    /// The RMS of the residuals, each bin weighted by the time it covers,
    /// s/day.
    pub residual_rms_s_per_day: f64,
    /// Stability of the raw series.
    pub stability: Vec<StabilityRow>,
    /// Stability of the bins' residuals after the model.
    pub residual_stability: Vec<StabilityRow>,
    /// The design's predictions beside the measured coefficients.
    pub design: Option<DesignComparison>,
    /// Whole-beat jumps undone.
    pub wraps: Vec<Wrap>,
    /// What to be careful of.
    pub warnings: Vec<LogWarning>,
    /// The spectrum of the rate with the tides', the day's and the
    /// wheels' lines (`None` when the log is too short for one).
    pub spectrum: Option<Spectrum>,
    /// The train's arbors and their periods.
    pub arbors: Vec<Arbor>,
    /// The rate folded over each arbor's turn (those the log resolves).
    pub folds: Vec<Fold>,
    /// Q and the energy's scatter, from amplitudes a half swing.
    pub swing: Option<Swing>,
    /// For half periods: the beat error, s (alternate half periods
    /// differ by twice it).
    pub beat_error_s: Option<f64>,
    /// Per bin: centre time (s), rate, model, residual (s/day).
    #[serde(skip)]
    pub per_bin: Vec<[f64; 4]>,
    /// Each weather and tide term's partial residuals, for plots.
    #[serde(skip)]
    pub partials: Vec<Partial>,
    /// The weather a bin, for plots: `temperature` (°C, as read, not
    /// lagged), `pressure` (hPa), `humidity` (%), `amplitude` (°), those
    /// the log has.
    #[serde(skip)]
    pub weather_per_bin: Vec<(&'static str, Vec<f64>)>,
}

/// One term's partial residuals: the rate with every other term taken
/// out, against the term's variable, and the fitted line through them.
#[derive(Clone, Debug, PartialEq)]
pub struct Partial {
    /// The term (`temperature`, `pressure`, …).
    pub term: &'static str,
    /// The variable a bin (the lagged temperature °C, the pressure hPa,
    /// the humidity %, the amplitude °, the tidal rate s/day).
    pub x: Vec<f64>,
    /// The rate less every other term, s/day.
    pub y: Vec<f64>,
    /// The fitted line's slope, s/day per the variable's unit.
    pub slope: f64,
    /// The line's value at the variable's mean, s/day.
    pub at_mean: f64,
    /// The variable's mean.
    pub mean: f64,
}

/// The optional terms, in the model's order after the constant.
const OPTIONAL: [&str; 6] = [
    "drift",
    "temperature",
    "pressure",
    "humidity",
    "amplitude",
    "tide",
];

/// Checks an environment column: one value a sample, finite or NaN, and
/// at least one finite.
fn column(name: &'static str, c: &Option<Vec<f64>>, n: usize) -> Result<Option<Vec<f64>>, Refusal> {
    let Some(c) = c else { return Ok(None) };
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
    // What a clock's room can hold: a value outside is a column in other
    // units (pressure in Pa or kPa, temperature in °F or K), refused
    // before it makes a coefficient 100 times off.
    let range = match name {
        "temperature" => Some((-60.0, 70.0, "°C: is the column in °F or K?")),
        "pressure" => Some((
            300.0,
            1100.0,
            "hPa: is the column in Pa, kPa or inHg without its unit?",
        )),
        "humidity" => Some((0.0, 100.0, "%: is the column a fraction (0 to 1)?")),
        "amplitude" => Some((
            0.0,
            90.0,
            "degrees: is the column in mrad or mm without its unit?",
        )),
        _ => None,
    };
    if let Some((low, high, hint)) = range {
        if let Some(i) = c
            .iter()
            .position(|v| v.is_finite() && !(low..=high).contains(v))
        {
            return Err(Refusal::sample(
                name,
                i,
                format!(
                    "{} is outside {low} to {high} {hint}",
                    format_significant(c[i], 6)
                ),
            ));
        }
    }
    Ok(c.iter().any(|v| v.is_finite()).then(|| c.clone()))
}

/// The mean of the finite values.
fn mean(v: &[f64]) -> f64 {
    let (s, n) = v
        .iter()
        .filter(|x| x.is_finite())
        .fold((0.0, 0usize), |(s, n), x| (s + x, n + 1));
    s / n.max(1) as f64
}

/// Analyses a clock's log. A few samples whose time does not advance (a
/// logger's stamp repeated, files joined with an overlap: at most 1% of
/// them) are left out, with a warning; more are refused as a log out of
/// order.
pub fn analyse(input: &LogInput) -> Result<LogResult, Refusal> {
    let t = &input.time_s;
    let n = t.len();
    let advances = |ti: f64, last: f64| ti > last || !ti.is_finite();
    let mut keep = vec![true; n];
    let (mut last, mut repeated, mut first_repeated) = (f64::NEG_INFINITY, 0, None);
    for (i, &ti) in t.iter().enumerate() {
        if advances(ti, last) {
            last = if ti.is_finite() { ti } else { last };
        } else {
            keep[i] = false;
            repeated += 1;
            first_repeated.get_or_insert(i);
        }
    }
    if repeated * 100 > n {
        // Out of order, not a few repeated stamps: refused by name below.
        return analyse_sorted(input);
    }
    // Half periods far from the typical one: a transit the gate missed
    // (two half periods read as one) or a stray trigger (one cut in two).
    let mut odd = 0;
    if input.kind == Some(LogKind::HalfPeriods) && input.values.len() == n && n >= 10 {
        let mut typical: Vec<f64> = input
            .values
            .iter()
            .step_by((n / 10_000).max(1))
            .copied()
            .filter(|v| v.is_finite() && *v > 0.0)
            .collect();
        if !typical.is_empty() {
            let h = typical.len() / 2;
            let median = *typical.select_nth_unstable_by(h, f64::total_cmp).1;
            for (i, &v) in input.values.iter().enumerate() {
                if keep[i]
                    && v.is_finite()
                    && v > 0.0
                    && !(0.5 * median..=1.5 * median).contains(&v)
                {
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
        }
    }
    if repeated == 0 && odd == 0 {
        return analyse_sorted(input);
    }
    let pick = |v: &Vec<f64>| -> Vec<f64> {
        if v.len() == n {
            v.iter()
                .zip(&keep)
                .filter(|(_, &k)| k)
                .map(|(x, _)| *x)
                .collect()
        } else {
            v.clone()
        }
    };
    let filtered = LogInput {
        time_s: pick(&input.time_s),
        values: pick(&input.values),
        temperature_c: input.temperature_c.as_ref().map(pick),
        pressure_hpa: input.pressure_hpa.as_ref().map(pick),
        humidity_percent: input.humidity_percent.as_ref().map(pick),
        amplitude_deg: input.amplitude_deg.as_ref().map(pick),
        pulse_width_s: input.pulse_width_s.as_ref().map(pick),
        ..input.clone()
    };
    let mut result = analyse_sorted(&filtered)?;
    if odd > 0 {
        result
            .warnings
            .insert(0, LogWarning::BeatsMissed { left_out: odd });
    }
    if let Some(first) = first_repeated {
        result.warnings.insert(
            0,
            LogWarning::TimesRepeated {
                dropped: repeated,
                first_time_s: t[first],
            },
        );
    }
    Ok(result)
}

/// [`analyse`] of a log whose times increase.
fn analyse_sorted(input: &LogInput) -> Result<LogResult, Refusal> {
    let n = input.time_s.len();
    if input.values.len() != n {
        return Err(Refusal::field(
            "values",
            format!("has {} values for {n} times", input.values.len()),
        ));
    }
    if n < 10 {
        return Err(Refusal::data(format!(
            "a log needs at least 10 samples, got {n}"
        )));
    }
    for (i, (&t, &v)) in input.time_s.iter().zip(&input.values).enumerate() {
        crate::analysis::require_finite_sample("time", i, t)?;
        crate::analysis::require_finite_sample("values", i, v)?;
        if i > 0 && t <= input.time_s[i - 1] {
            return Err(Refusal::sample(
                "time",
                i,
                format!(
                    "{} s is not after the previous {} s; sort by time",
                    format_significant(t, 12),
                    format_significant(input.time_s[i - 1], 12)
                ),
            ));
        }
    }
    if input.values.iter().all(|&v| v == input.values[0]) {
        return Err(Refusal::data(format!(
            "the values never change (all {n} are {}): a logger stuck, or a column that is not the clock's?",
            format_significant(input.values[0], 6)
        )));
    }
    let kind = input.kind.unwrap_or(LogKind::Offset);
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
    let nominal_half = input
        .nominal
        .map(crate::listening::analysis::nominal_period)
        .transpose()?
        .map(|p| p / 2.0);
    let times = &input.time_s;
    let span = times[n - 1] - times[0];
    let temperature = column("temperature", &input.temperature_c, n)?;
    let pressure = column("pressure", &input.pressure_hpa, n)?;
    let humidity = column("humidity", &input.humidity_percent, n)?;
    let mut amplitude = column("amplitude", &input.amplitude_deg, n)?;
    let mut warnings = Vec::new();
    // A photogate's sizes without its pulses would be ignored: refused.
    if input.pulse_width_s.is_none() {
        for (field, given) in [
            ("flag_width", input.flag_width_m),
            ("gate_radius", input.gate_radius_m),
        ] {
            if given.is_some() {
                return Err(Refusal::field(
                    field,
                    "reads a photogate's pulse widths, and the log has none (a pulse_width \
                     column)",
                ));
            }
        }
    }
    if let (None, Some(pulses)) = (&amplitude, column("pulse_width", &input.pulse_width_s, n)?) {
        if input.flag_width_m.is_none() && input.gate_radius_m.is_none() {
            warnings.push(LogWarning::PulsesIgnored);
        } else {
            amplitude = Some(amplitudes_from_pulses(input, &pulses)?);
        }
    }
    // The typical spacing, from at most 100,000 intervals evenly spread.
    let stride = ((n - 1) / 100_000).max(1);
    let mut spacing: Vec<f64> = (0..n - 1)
        .step_by(stride)
        .map(|i| times[i + 1] - times[i])
        .collect();
    let half = spacing.len() / 2;
    let dt = *spacing.select_nth_unstable_by(half, f64::total_cmp).1;
    let bin = match input.bin_s {
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
        // An hour, or the samples' spacing if longer; a log too short
        // for 24 of those in 24 bins.
        None => {
            let hour = 3600f64.max(dt);
            if span / hour < 24.0 {
                (span / 24.0).max(dt)
            } else {
                hour
            }
        }
    };
    if span / bin < 10.0 {
        return Err(Refusal::field(
            "bin",
            format!(
                "{} s leaves {} bins over the log's {} s; a model needs 10: give a shorter --bin",
                format_significant(bin, 6),
                (span / bin).floor(),
                format_significant(span, 6)
            ),
        ));
    }
    // Work, measured on a year of 3 s samples in hourly bins (2 s): about
    // 0.15 µs a sample (reading them into bins, lagging the temperature a
    // few times, the stability) and 0.1 ms a bin (the fits).
    let bins_n = span / bin;
    judge_work(
        "bin",
        format_args!(
            "{} samples in {} bins",
            crate::analysis::count(n as f64),
            crate::analysis::count(bins_n)
        ),
        n as f64 * 1.5e-7 + bins_n * 1e-4,
        input.force,
    )?;

    // The values as a rate or an offset.
    let mut log_half = nominal_half;
    let mut early_swing = None;
    let mut values = input.values.clone();
    let mut wraps = Vec::new();
    let env_raw: Vec<&[f64]> = [&pressure, &humidity, &amplitude]
        .iter()
        .map(|c| c.as_deref().unwrap_or(&[]))
        .collect();
    // Environment columns binned alongside (empty columns give NaN bins).
    let env = env_raw.clone();
    let (bins, raw_kind, raw_series): (Bins, DataKind, Vec<f64>) = match kind {
        LogKind::Offset => {
            wraps = unwrap(times, &mut values, input.beat_s);
            if !wraps.is_empty() {
                warnings.push(LogWarning::WrapsUndone { count: wraps.len() });
            }
            (
                offsets_to_bins(times, &values, &env, bin),
                DataKind::Phase,
                values,
            )
        }
        LogKind::Rate => (
            rates_to_bins(times, &values, None, &env, bin),
            DataKind::Frequency,
            values.iter().map(|r| r / 86_400.0).collect(),
        ),
        LogKind::HalfPeriods => {
            if let Some(i) = values.iter().position(|&v| v <= 0.0) {
                return Err(Refusal::sample(
                    "values",
                    i,
                    "a half period must be positive",
                ));
            }
            let mean_half = mean(&values);
            let nominal = match nominal_half {
                Some(h) => h,
                None => match standard_rate_near(3600.0 / mean_half) {
                    Some(s) => 3600.0 / s.beats_per_hour,
                    None => {
                        warnings.push(LogWarning::RateAgainstMean);
                        mean_half
                    }
                },
            };
            log_half = Some(nominal);
            let rates: Vec<f64> = values
                .iter()
                .map(|h| (nominal / h - 1.0) * 86_400.0)
                .collect();
            if let Some(a) = amplitude.as_deref() {
                early_swing = swing(a, &|i| times[i] - times[i - 1] > 1.5 * nominal);
            }
            // A bin that ends part way through a cycle the swing repeats
            // (an impulse every few swings, the escape wheel's turn) takes
            // part of the cycle's pattern into its rate and its mean
            // amplitude alike, which the model would read as an effect of
            // the amplitude: both are averaged over whole cycles first.
            let cycle = whole_cycle(
                early_swing.as_ref(),
                arbors.last().map(|a| a.period_s / nominal),
                bin / nominal,
            );
            let b = match cycle {
                Some(w) => {
                    let smooth_amplitude = amplitude.as_deref().map(|a| running_mean(a, w));
                    let env_smooth: Vec<&[f64]> = vec![
                        env_raw[0],
                        env_raw[1],
                        smooth_amplitude.as_deref().unwrap_or(&[]),
                    ];
                    // Weighted by the half periods, as the bins are.
                    let timed: Vec<f64> = rates.iter().zip(&values).map(|(r, h)| r * h).collect();
                    let smooth: Vec<f64> = running_mean(&timed, w)
                        .iter()
                        .zip(running_mean(&values, w))
                        .map(|(rh, h)| rh / h)
                        .collect();
                    rates_to_bins(times, &smooth, Some(&values), &env_smooth, bin)
                }
                None => rates_to_bins(times, &rates, Some(&values), &env, bin),
            };
            let fractional = rates.iter().map(|r| r / 86_400.0).collect();
            (b, DataKind::Frequency, fractional)
        }
    };
    let m = bins.centre.len();
    if m < 10 {
        return Err(Refusal::data(format!(
            "only {m} bins hold enough samples for a rate; a model needs 10"
        )));
    }

    // The columns: constant, drift, lagged temperature (chosen below),
    // pressure, humidity, amplitude, tide, steps.
    let t_ref = mean(&bins.centre);
    let day = 86_400.0;
    let centred = |v: &[f64]| -> (Vec<f64>, f64) {
        let mu = mean(v);
        (
            v.iter()
                .map(|x| if x.is_finite() { x - mu } else { 0.0 })
                .collect(),
            mu,
        )
    };
    let mut optional: Vec<Option<Vec<f64>>> = vec![None; OPTIONAL.len() + 1];
    let mut reference = [None; 4];
    if span >= 2.0 * day {
        optional[0] = Some(bins.centre.iter().map(|t| (t - t_ref) / day).collect());
    } else {
        warnings.push(LogWarning::Short { what: "drift" });
    }
    for (k, slot) in [2usize, 3, 4].into_iter().enumerate() {
        if !env_raw[k].is_empty() {
            let (c, mu) = centred(&bins.env[k]);
            optional[slot] = Some(c);
            reference[k + 1] = Some(mu);
        }
    }
    if input.tides {
        let station = input.station.ok_or_else(|| {
            Refusal::field(
                "latitude",
                "the tides need the clock's latitude and longitude",
            )
        })?;
        let epoch = input.epoch_unix_s.ok_or_else(|| {
            Refusal::field(
                "time",
                "the tides need the log's times as dates (ISO 8601 or Unix time), or its start",
            )
        })?;
        if span < 3.0 * day {
            warnings.push(LogWarning::Short { what: "tide" });
        }
        // Each bin's mean by the two-point Gauss rule.
        let h = bin / (2.0 * 3f64.sqrt());
        let at: Vec<f64> = bins
            .centre
            .iter()
            .flat_map(|&t| [epoch + t - h, epoch + t + h])
            .collect();
        let dg = gravity_change(station, &at)?;
        let g = crate::gravity::normal_gravity(station.latitude_deg, station.height_m)
            .map_err(|e| Refusal::input("height", &e))?;
        optional[5] = Some(
            dg.chunks(2)
                .map(|c| rate_s_per_day(0.5 * (c[0] + c[1]), g))
                .collect(),
        );
    }
    // A step needs bins on both sides of it: at least two whole ones, or
    // it cannot be told from the rate (at the log's start) or from one
    // bin's noise (at its end).
    let (first_centre, last_centre) = (bins.centre[0], bins.centre[m - 1]);
    let mut steps: Vec<Vec<f64>> = Vec::new();
    for &e in &input.events_s {
        let reason = if !e.is_finite() || e < times[0] || e > times[n - 1] {
            Some("outside the log")
        } else if e < first_centre + 1.5 * bin || e > last_centre - 1.5 * bin {
            Some("within two bins of the log's start or end: a step there cannot be told from the rate or from one bin's noise")
        } else {
            None
        };
        match reason {
            Some(reason) => warnings.push(LogWarning::EventIgnored {
                time_s: if e.is_finite() { e } else { 0.0 },
                reason,
            }),
            None => steps.push(
                bins.centre
                    .iter()
                    .map(|&c| ((c + 0.5 * bin - e) / bin).clamp(0.0, 1.0))
                    .collect(),
            ),
        }
    }

    // The temperature lag: the best time constant by likelihood with every
    // other term in. The search lags a coarse copy of the temperatures
    // (each bin's samples in up to 32 weighted chunks) with the random
    // walk's share held; the time constant found is then applied to every
    // sample.
    let mut lag = None;
    let mut lag_range = None;
    if let Some(tc) = &temperature {
        let coarse = Coarse::new(&bins, times, tc);
        let start = |tau: f64| -> Option<Vec<f64>> {
            (tau > 0.0).then(|| {
                bins.centre
                    .iter()
                    .map(|&t| (-(t - times[0]) / tau).exp())
                    .collect()
            })
        };
        let column = |binned: Vec<f64>, tau: f64, optional: &mut Vec<Option<Vec<f64>>>| -> f64 {
            let (c, mu) = centred(&binned);
            optional[1] = Some(c);
            optional[TRANSIENT] = start(tau);
            mu
        };
        let score = |tau: f64, walk: Walk, optional: &mut Vec<Option<Vec<f64>>>| -> Option<Fit> {
            column(coarse.lagged_means(tau), tau, optional);
            let x = design_matrix(optional, &steps, m, &[true; 6]);
            fit(&bins.rate, &x, &bins.weight, walk)
        };
        let candidates: Vec<f64> = std::iter::once(0.0)
            .chain((0..15).map(|i| bin * 0.25 * 2f64.powf(i as f64 * 0.75)))
            .filter(|&tau| tau < span / 2.0)
            .collect();
        let walk = score(
            candidates[candidates.len() / 2],
            Walk::Fitted,
            &mut optional,
        )
        .map_or(Walk::Fixed(0.0), |f| Walk::Fixed(f.lambda));
        let mut scored: Vec<(f64, f64)> = Vec::new();
        for &tau in &candidates {
            if let Some(f) = score(tau, walk, &mut optional) {
                scored.push((tau, f.log_likelihood));
            }
        }
        // The best grid point refined by golden sections in log τ, to 1%,
        // with the walk's share found afresh there.
        if let Some((i, _)) = scored
            .iter()
            .enumerate()
            .max_by(|a, b| a.1 .1.total_cmp(&b.1 .1))
        {
            if scored[i].0 > 0.0 {
                let walk = score(scored[i].0, Walk::Fitted, &mut optional)
                    .map_or(walk, |f| Walk::Fixed(f.lambda));
                let mut at = |l: f64| {
                    score(l.exp(), walk, &mut optional)
                        .map_or(f64::NEG_INFINITY, |f| f.log_likelihood)
                };
                let lo = scored[i.saturating_sub(1)].0.max(scored[i].0 / 2.0).ln();
                let hi = scored.get(i + 1).map_or(scored[i].0 * 2.0, |s| s.0).ln();
                let phi = (5f64.sqrt() - 1.0) / 2.0;
                let (mut a, mut b) = (lo, hi);
                let mut c = b - phi * (b - a);
                let mut d = a + phi * (b - a);
                let (mut fc, mut fd) = (at(c), at(d));
                while b - a > 0.005 {
                    if fc > fd {
                        (b, d, fd) = (d, c, fc);
                        c = b - phi * (b - a);
                        fc = at(c);
                    } else {
                        (a, c, fc) = (c, d, fd);
                        d = a + phi * (b - a);
                        fd = at(d);
                    }
                }
                let tau = (0.5 * (a + b)).exp();
                let best = at(tau.ln());
                // The grid's scores, on the same walk, for the range.
                scored = candidates
                    .iter()
                    .filter_map(|&t| score(t, walk, &mut optional).map(|f| (t, f.log_likelihood)))
                    .collect();
                scored.push((tau, best));
            }
        }
        if let Some(&(tau, best)) = scored.iter().max_by(|a, b| a.1.total_cmp(&b.1)) {
            let within: Vec<f64> = scored
                .iter()
                .filter(|s| s.1 >= best - 2.0)
                .map(|s| s.0)
                .collect();
            lag = Some(tau);
            lag_range = Some([
                within.iter().copied().fold(f64::INFINITY, f64::min),
                within.iter().copied().fold(0.0, f64::max),
            ]);
            reference[0] = Some(column(
                lagged_means(&bins, times, tc, tau),
                tau,
                &mut optional,
            ));
        } else {
            optional[1] = None;
        }
    }

    // Backward elimination by BIC from every term the data allow.
    let bic = |f: &Fit, k: usize| -2.0 * f.log_likelihood + (k + 2) as f64 * (m as f64).ln();
    let mut keep: Vec<bool> = optional[..OPTIONAL.len()]
        .iter()
        .map(|c| c.is_some())
        .collect();
    let transient = optional[TRANSIENT].is_some();
    let count = |keep: &[bool]| {
        1 + keep.iter().filter(|&&k| k).count() + steps.len() + usize::from(transient && keep[1])
    };
    let mut current = fit(
        &bins.rate,
        &design_matrix(&optional, &steps, m, &keep),
        &bins.weight,
        Walk::Fitted,
    )
    .ok_or_else(|| Refusal::data("the rate model cannot be fitted: its terms are not independent (a weather column that never changes?)"))?;
    let mut judged: Vec<Term> = Vec::new();
    loop {
        let base = bic(&current, count(&keep));
        let mut best: Option<(usize, f64, Fit)> = None;
        for i in (0..OPTIONAL.len()).filter(|&i| keep[i]) {
            let mut trial = keep.clone();
            trial[i] = false;
            if let Some(f) = fit(
                &bins.rate,
                &design_matrix(&optional, &steps, m, &trial),
                &bins.weight,
                Walk::Fitted,
            ) {
                let delta = bic(&f, count(&trial)) - base;
                if best.as_ref().is_none_or(|b| delta < b.1) {
                    best = Some((i, delta, f));
                }
            }
        }
        match best {
            Some((i, delta, f)) if delta < 0.0 => {
                keep[i] = false;
                judged.push(Term {
                    name: OPTIONAL[i],
                    kept: false,
                    delta_bic: delta,
                });
                current = f;
            }
            _ => break,
        }
    }
    // The kept terms' ΔBIC, each against the final model without it.
    let base = bic(&current, count(&keep));
    for i in (0..OPTIONAL.len()).filter(|&i| keep[i]) {
        let mut trial = keep.clone();
        trial[i] = false;
        let delta = fit(
            &bins.rate,
            &design_matrix(&optional, &steps, m, &trial),
            &bins.weight,
            Walk::Fitted,
        )
        .map_or(f64::INFINITY, |f| bic(&f, count(&trial)) - base);
        judged.push(Term {
            name: OPTIONAL[i],
            kept: true,
            delta_bic: delta,
        });
    }
    judged.sort_by_key(|t| OPTIONAL.iter().position(|n| *n == t.name));
    if !keep[1] {
        lag = None;
        lag_range = None;
        reference[0] = None;
    }
    for (k, slot) in [2usize, 3, 4].into_iter().enumerate() {
        if !keep[slot] {
            reference[k + 1] = None;
        }
    }

    // The lag's own uncertainty carried into every coefficient (the delta
    // method): the profile likelihood's curvature in ln τ gives var(ln τ),
    // refits at ln τ ± 0.05 give each coefficient's slope in ln τ.
    if let (Some(tau), Some(tc), true) = (lag, &temperature, keep[1]) {
        if tau > 0.0 {
            let h: f64 = 0.05;
            let walk = Walk::Fixed(current.lambda);
            let refit = |t: f64| -> Option<Fit> {
                let mut trial = optional.clone();
                let (c, _) = centred(&lagged_means(&bins, times, tc, t));
                trial[1] = Some(c);
                trial[TRANSIENT] = Some(
                    bins.centre
                        .iter()
                        .map(|&c| (-(c - times[0]) / t).exp())
                        .collect(),
                );
                fit(
                    &bins.rate,
                    &design_matrix(&trial, &steps, m, &keep),
                    &bins.weight,
                    walk,
                )
            };
            if let (Some(up), Some(down), Some(mid)) = (
                refit(tau * h.exp()),
                refit(tau * (-h).exp()),
                fit(
                    &bins.rate,
                    &design_matrix(&optional, &steps, m, &keep),
                    &bins.weight,
                    walk,
                ),
            ) {
                let curvature =
                    (up.log_likelihood - 2.0 * mid.log_likelihood + down.log_likelihood) / (h * h);
                if curvature < 0.0 {
                    let var = -1.0 / curvature;
                    let g: Vec<f64> = up
                        .beta
                        .iter()
                        .zip(&down.beta)
                        .map(|(u, d)| (u - d) / (2.0 * h))
                        .collect();
                    for i in 0..g.len() {
                        for j in 0..g.len() {
                            current.cov[(i, j)] += g[i] * g[j] * var;
                        }
                    }
                }
            }
        }
    }

    // Name the parameters and read them out.
    let mut names = vec!["rate".to_string()];
    for (i, name) in OPTIONAL.iter().enumerate() {
        if keep[i] {
            names.push(name.to_string());
        }
    }
    let first_step = names.len();
    for k in 0..steps.len() {
        names.push(format!("step_{}", k + 1));
    }
    if transient && keep[1] {
        names.push("temperature_start".to_string());
    }
    let se: Vec<f64> = (0..names.len())
        .map(|i| current.cov[(i, i)].sqrt())
        .collect();
    let index = |name: &str| names.iter().position(|n| n == name);
    let value = |name: &str| index(name).map(|i| current.beta[i]);
    let error = |name: &str| index(name).map(|i| se[i]);
    let coefficients = Coefficients {
        temperature_s_per_day_per_c: value("temperature"),
        pressure_s_per_day_per_hpa: value("pressure"),
        humidity_s_per_day_per_percent: value("humidity"),
        amplitude_s_per_day_per_deg: value("amplitude"),
        tide_admittance: value("tide"),
        steps_s_per_day: (0..steps.len())
            .map(|k| current.beta[first_step + k])
            .collect(),
    };
    let standard_errors = Coefficients {
        temperature_s_per_day_per_c: error("temperature"),
        pressure_s_per_day_per_hpa: error("pressure"),
        humidity_s_per_day_per_percent: error("humidity"),
        amplitude_s_per_day_per_deg: error("amplitude"),
        tide_admittance: error("tide"),
        steps_s_per_day: (0..steps.len()).map(|k| se[first_step + k]).collect(),
    };
    let correlations: Vec<Vec<f64>> = (0..names.len())
        .map(|i| {
            (0..names.len())
                .map(|j| current.cov[(i, j)] / (se[i] * se[j]))
                .collect()
        })
        .collect();

    // Checks against what pendulums can do.
    if let (Some(a), Some(s)) = (
        coefficients.tide_admittance,
        standard_errors.tide_admittance,
    ) {
        let from_one = (a - 1.0) / s;
        if from_one.abs() > 4.0 && s < 0.5 {
            warnings.push(LogWarning::TideAdmittance {
                admittance: a,
                from_one_se: from_one,
            });
        }
    }
    if let Some(a) = coefficients.temperature_s_per_day_per_c {
        if a.abs() > 2.0 {
            warnings.push(LogWarning::Implausible {
                term: "temperature",
                reason: format!(
                    "{} s/day per °C is more than an uncompensated brass rod's 0.8: are the rates in s/day and the temperatures in °C?",
                    format_significant(a, 3)
                ),
            });
        }
    }
    if let Some(a) = coefficients.pressure_s_per_day_per_hpa {
        if a.abs() > 0.1 {
            warnings.push(LogWarning::Implausible {
                term: "pressure",
                reason: format!(
                    "{} s/day per hPa is ten times what air does to any clock pendulum: are the pressures in hPa?",
                    format_significant(a, 3)
                ),
            });
        }
    }

    // The circular error makes the rate fall with the amplitude by
    // 86400·A/8 s/day a radian (ΔT/T = A²/16); an escapement may add to
    // it or offset it, but not tenfold.
    if let (Some(a), Some(mean_deg)) = (coefficients.amplitude_s_per_day_per_deg, reference[3]) {
        let circular = 86_400.0 * mean_deg.to_radians() / 8.0 * 1f64.to_radians();
        if a.abs() > 10.0 * circular.max(0.01) {
            warnings.push(LogWarning::Implausible {
                term: "amplitude",
                reason: format!(
                    "{} s/day per degree is more than ten times the circular error's {} at {}°: the amplitude hardly changes, or changes with something else that moves the rate (the bins cut a cycle of impulses?)",
                    format_significant(a, 3),
                    format_significant(-circular, 3),
                    format_significant(mean_deg, 3)
                ),
            });
        }
    }

    // The design's predictions at the log's mean weather.
    let design = match &input.design {
        Some(d) => {
            let air = |h: f64| Air {
                pressure_pa: reference[1].map(|p| p * 100.0),
                temperature_c: reference[0],
                humidity: Some(h),
                ..Air::default()
            };
            let h0 = reference[2].map_or(0.5, |h| h / 100.0);
            let sheet = datasheet(d, None, &air(h0))?;
            let wetter = datasheet(d, None, &air((h0 + 0.01).min(1.0)))?;
            let dh = if h0 + 0.01 <= 1.0 {
                1.0
            } else {
                100.0 * (1.0 - h0)
            };
            let humidity = if dh > 0.0 {
                (wetter.air_rate_s_per_day - sheet.air_rate_s_per_day) / dh
            } else {
                0.0
            };
            let diff = |measured: Option<f64>, se: Option<f64>, predicted: f64| {
                Some((measured? - predicted) / se?)
            };
            Some(DesignComparison {
                temperature_s_per_day_per_c: sheet.temperature_coefficient_s_per_day_per_c,
                temperature_difference_se: diff(
                    coefficients.temperature_s_per_day_per_c,
                    standard_errors.temperature_s_per_day_per_c,
                    sheet.temperature_coefficient_s_per_day_per_c,
                ),
                pressure_s_per_day_per_hpa: sheet.pressure_coefficient_s_per_day_per_hpa,
                pressure_difference_se: diff(
                    coefficients.pressure_s_per_day_per_hpa,
                    standard_errors.pressure_s_per_day_per_hpa,
                    sheet.pressure_coefficient_s_per_day_per_hpa,
                ),
                humidity_s_per_day_per_percent: humidity,
                humidity_difference_se: diff(
                    coefficients.humidity_s_per_day_per_percent,
                    standard_errors.humidity_s_per_day_per_percent,
                    humidity,
                ),
            })
        }
        None => None,
    };

    // Stability: the raw series at its own spacing, the residuals per bin.
    let (raw_stability, residual_stability) = if input.skip_stability {
        (Vec::new(), Vec::new())
    } else {
        let raw = crate::stability::grid(times, &raw_series, Some(dt))?;
        let raw_stability = stability(&StabilityInput {
            data: raw.data,
            kind: raw_kind,
            tau0_s: raw.tau0_s,
            taus: Taus::Octave,
            force: true,
        })?
        .rows;
        let residual_fraction: Vec<f64> = current.residuals.iter().map(|r| r / 86_400.0).collect();
        let residual = crate::stability::grid(&bins.centre, &residual_fraction, Some(bin))?;
        let residual_stability = stability(&StabilityInput {
            data: residual.data,
            kind: DataKind::Frequency,
            tau0_s: bin,
            taus: Taus::Octave,
            force: true,
        })
        .map(|s| s.rows)
        .unwrap_or_default();
        (raw_stability, residual_stability)
    };

    // Periodic errors: the spectrum, the wheels' folds, the swing.
    if let (Some(train), Some(h)) = (&input.train, log_half) {
        if let Some(train_bph) = train.beats_per_hour() {
            let log_bph = 3600.0 / h;
            if (train_bph / log_bph - 1.0).abs() > 0.01 {
                warnings.push(LogWarning::TrainBeat { train_bph, log_bph });
            }
        }
    }
    let periodic = periodic(&Periodic {
        times,
        raw: &raw_series,
        kind: raw_kind,
        half: (kind == LogKind::HalfPeriods).then_some(log_half).flatten(),
        dt,
        arbors: &arbors,
        swing: early_swing,
    })?;

    // The weather a bin and each term's partial residuals, for plots.
    let mut weather_per_bin = Vec::new();
    if let Some(tc) = &temperature {
        weather_per_bin.push(("temperature", bins.means(tc)));
    }
    for (k, name) in ["pressure", "humidity", "amplitude"]
        .into_iter()
        .enumerate()
    {
        if !env_raw[k].is_empty() {
            weather_per_bin.push((name, bins.env[k].clone()));
        }
    }
    let r0 = current.beta[0];
    let partials = [
        ("temperature", 1usize, reference[0]),
        ("pressure", 2, reference[1]),
        ("humidity", 3, reference[2]),
        ("amplitude", 4, reference[3]),
        ("tide", 5, Some(0.0)),
    ]
    .into_iter()
    .filter_map(|(term, slot, offset)| {
        let beta = value(term)?;
        let column = optional[slot].as_ref()?;
        let offset = offset?;
        let present = |i: usize| slot < 2 || slot == 5 || bins.env[slot - 2][i].is_finite();
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for i in (0..m).filter(|&i| present(i)) {
            x.push(column[i] + offset);
            y.push(current.residuals[i] + beta * column[i] + r0);
        }
        let mean = mean(&x);
        Some(Partial {
            term,
            slope: beta,
            at_mean: r0 + beta * (mean - offset),
            mean,
            x,
            y,
        })
    })
    .collect();

    // Weighted as the fit weights the bins: a bin of one sample (the
    // log's last) counts as little as it holds.
    let total_weight: f64 = bins.weight.iter().sum();
    let residual_rms = (current
        .residuals
        .iter()
        .zip(&bins.weight)
        .map(|(r, w)| w * r * r)
        .sum::<f64>()
        / total_weight)
        .sqrt();
    let per_bin = (0..m)
        .map(|i| {
            [
                bins.centre[i],
                bins.rate[i],
                bins.rate[i] - current.residuals[i],
                current.residuals[i],
            ]
        })
        .collect();
    Ok(LogResult {
        kind,
        epoch_unix_s: input.epoch_unix_s,
        samples: n,
        span_s: span,
        bin_s: bin,
        bins: m,
        rate_s_per_day: current.beta[0],
        rate_standard_error_s_per_day: se[0],
        reference_time_s: t_ref,
        drift_s_per_day_per_day: value("drift"),
        drift_standard_error_s_per_day_per_day: error("drift"),
        coefficients,
        standard_errors,
        parameters: names,
        correlations,
        temperature_lag_s: lag,
        temperature_lag_range_s: lag_range,
        reference_weather: reference,
        terms: judged,
        white_noise_s_per_day: current.sigma2.sqrt(),
        random_walk_s_per_day_per_day: (current.lambda * current.sigma2 * day / bin).sqrt(),
        residual_rms_s_per_day: residual_rms,
        stability: raw_stability,
        residual_stability,
        design,
        wraps,
        warnings,
        spectrum: periodic.spectrum,
        arbors,
        folds: periodic.folds,
        swing: periodic.swing,
        beat_error_s: periodic.beat_error_s,
        per_bin,
        partials,
        weather_per_bin,
    })
}

/// The amplitude (degrees) of every swing from its pulse: the flag and
/// the gate given, the pendulum's equivalent length from the design, else
/// from the nominal half period (a simple pendulum), in the station's
/// normal gravity (or standard gravity).
fn amplitudes_from_pulses(input: &LogInput, pulses: &[f64]) -> Result<Vec<f64>, Refusal> {
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
    // A log of half periods measures its own: their mean.
    let measured_half = (input.kind == Some(LogKind::HalfPeriods)).then(|| mean(&input.values));
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
                .map(f64::to_degrees)
                .map_err(|r| Refusal::sample("pulse_width", i, r.reason))
        })
        .collect()
}

/// What the periodic analyses read.
struct Periodic<'a> {
    /// The samples' times, s.
    times: &'a [f64],
    /// Offsets (s) or fractional rates a sample.
    raw: &'a [f64],
    /// Which.
    kind: DataKind,
    /// For half periods: the nominal half period, s.
    half: Option<f64>,
    /// The samples' typical spacing, s.
    dt: f64,
    /// The train's arbors.
    arbors: &'a [Arbor],
    /// Q and the energy's scatter, found before binning.
    swing: Option<Swing>,
}

/// What they found.
struct PeriodicFound {
    spectrum: Option<Spectrum>,
    folds: Vec<Fold>,
    swing: Option<Swing>,
    beat_error_s: Option<f64>,
}

/// The mean of the finite values at even and at odd indices (`None`
/// when either parity has none).
fn parity_means(values: impl Iterator<Item = (usize, f64)>) -> Option<[f64; 2]> {
    let (mut s, mut c) = ([0.0; 2], [0usize; 2]);
    for (j, v) in values.filter(|(_, v)| v.is_finite()) {
        s[j % 2] += v;
        c[j % 2] += 1;
    }
    (c[0] > 0 && c[1] > 0).then(|| [s[0] / c[0] as f64, s[1] / c[1] as f64])
}

/// Takes the alternation of a series a beat out: each parity's mean
/// moved to the mean of the two.
fn take_out_alternation(values: &mut [f64]) {
    let Some(m) = parity_means(values.iter().copied().enumerate()) else {
        return;
    };
    let shift = [0.5 * (m[0] - m[1]), 0.5 * (m[1] - m[0])];
    for (j, v) in values.iter_mut().enumerate() {
        *v -= shift[j % 2];
    }
}

/// The grid the spectrum and the folds read: at most this many points.
const FINE_POINTS: f64 = 1_048_576.0;

/// The rate's spectrum on a grid of the samples' spacing (coarser when
/// that would exceed [`FINE_POINTS`]), the folds over the arbors (by
/// the count of beats for half periods, by the clock's time otherwise),
/// and the swing's Q from amplitudes a half swing.
fn periodic(p: &Periodic) -> Result<PeriodicFound, Refusal> {
    let times = p.times;
    let span = times[times.len() - 1] - times[0];
    let step = p.dt.max(span / FINE_POINTS);
    let gridded = crate::stability::grid(times, p.raw, Some(step))?.data;
    // The rate (s/day) a grid point, and the clock's own time there.
    let (rate, position): (Vec<f64>, Vec<f64>) = match p.kind {
        DataKind::Phase => {
            let rate: Vec<f64> = gridded
                .windows(2)
                .map(|w| (w[1] - w[0]) / step * 86_400.0)
                .collect();
            let mut last = 0.0;
            let position = (0..rate.len())
                .map(|j| {
                    if gridded[j].is_finite() {
                        last = gridded[j];
                    }
                    j as f64 * step + last
                })
                .collect();
            (rate, position)
        }
        DataKind::Frequency => {
            let rate: Vec<f64> = gridded.iter().map(|f| f * 86_400.0).collect();
            let mut clock = 0.0;
            let position = rate
                .iter()
                .enumerate()
                .map(|(j, r)| {
                    let at = j as f64 * step + clock;
                    if r.is_finite() {
                        clock += r / 86_400.0 * step;
                    }
                    at
                })
                .collect();
            (rate, position)
        }
    };
    let mut named: Vec<(String, f64)> = TIDAL_LINES
        .iter()
        .map(|(name, hours)| (name.to_string(), hours * 3600.0))
        .collect();
    named.extend(p.arbors.iter().map(|a| (a.name.clone(), a.period_s)));
    let spectrum = Some(spectrum(&detrended(&rate), step, &named)).filter(|s| !s.points.is_empty());
    // Half periods are placed on their beat's slot (a gap advances the
    // count by the beats it spans): the folds read them by the count,
    // the beat error by its parity.
    let slots: Option<Vec<usize>> = p.half.map(|half| {
        let mut index = 0usize;
        (0..times.len())
            .map(|i| {
                if i > 0 {
                    index += ((times[i] - times[i - 1]) / half).round().max(1.0) as usize;
                }
                index
            })
            .collect()
    });
    let folds = match (p.half, &slots) {
        (Some(half), Some(slots)) if !p.arbors.is_empty() => {
            let last = slots.last().copied().unwrap_or(0);
            if last > 4 * times.len() {
                Vec::new()
            } else {
                let mut by_beat = vec![f64::NAN; last + 1];
                for (&slot, f) in slots.iter().zip(p.raw) {
                    by_beat[slot] = f * 86_400.0;
                }
                // The beat error alternates every beat: a pattern of every
                // turn with an even count of beats, not a wheel's.
                take_out_alternation(&mut by_beat);
                folds(p.arbors, by_beat, &|j| j as f64 * half, half)
            }
        }
        _ => folds(p.arbors, rate.clone(), &|j| position[j], step),
    };
    // Tick and tock: alternate half periods differ by twice the beat error.
    let beat_error_s = p.half.zip(slots.as_ref()).map(|(half, slots)| {
        parity_means(slots.iter().copied().zip(p.raw.iter().copied()))
            .map_or(0.0, |m| 0.5 * half * (m[0] - m[1]).abs())
    });
    Ok(PeriodicFound {
        spectrum,
        folds,
        swing: p.swing.clone(),
        beat_error_s,
    })
}

/// The half swings a cycle of the swing takes: the least common multiple
/// of the impulse's period (from `swing`) and the escape wheel's turn
/// (`escape_beats`), when one of them is known and the cycle is under half
/// a bin (`bin_beats`).
fn whole_cycle(swing: Option<&Swing>, escape_beats: Option<f64>, bin_beats: f64) -> Option<usize> {
    let impulse = swing
        .filter(|s| s.q.is_some())
        .and_then(|s| s.half_swings_per_impulse)
        .map(|n| n.round() as usize)
        .filter(|&n| n >= 2);
    let escape = escape_beats.map(|b| b.round() as usize).filter(|&b| b >= 2);
    let gcd = |mut a: usize, mut b: usize| {
        while b > 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    let cycle = match (impulse, escape) {
        (Some(a), Some(b)) => a / gcd(a, b) * b,
        (a, b) => a.or(b)?,
    };
    (cycle >= 2 && (cycle as f64) < bin_beats / 2.0).then_some(cycle)
}

/// The centred running mean of `values` over `window` samples (at the
/// ends the first or last `window`; NaN left out).
fn running_mean(values: &[f64], window: usize) -> Vec<f64> {
    let n = values.len();
    let (sum, count) = super::series::cumulative(values);
    (0..n)
        .map(|i| {
            // A whole window at the ends too, moved inward: a part of a
            // cycle would bring its pattern back.
            let a = i.saturating_sub(window / 2).min(n.saturating_sub(window));
            let b = (a + window).min(n);
            let c = count[b] - count[a];
            if c > 0 && values[i].is_finite() {
                (sum[b] - sum[a]) / c as f64
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// `values` less their least-squares line (NaN kept).
fn detrended(values: &[f64]) -> Vec<f64> {
    let (mut n, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (j, &v) in values.iter().enumerate().filter(|(_, v)| v.is_finite()) {
        let x = j as f64;
        n += 1.0;
        sx += x;
        sy += v;
        sxx += x * x;
        sxy += x * v;
    }
    let d = n * sxx - sx * sx;
    let (slope, intercept) = if d > 0.0 {
        let b = (n * sxy - sx * sy) / d;
        (b, (sy - b * sx) / n)
    } else {
        (0.0, if n > 0.0 { sy / n } else { 0.0 })
    };
    values
        .iter()
        .enumerate()
        .map(|(j, v)| v - intercept - slope * j as f64)
        .collect()
}

/// The design matrix: the constant, the kept optional columns, the
/// steps, and with the temperature the lag's start (`steps`' last column
/// when `transient`).
fn design_matrix(
    optional: &[Option<Vec<f64>>],
    steps: &[Vec<f64>],
    m: usize,
    keep: &[bool],
) -> Vec<Vec<f64>> {
    let mut x = vec![vec![1.0; m]];
    for (c, &k) in optional.iter().zip(keep) {
        if let (Some(c), true) = (c, k) {
            x.push(c.clone());
        }
    }
    x.extend(steps.iter().cloned());
    if let (Some(Some(t)), true) = (optional.get(TRANSIENT), keep[1]) {
        x.push(t.clone());
    }
    x
}

/// The slot of the temperature lag's start in the optional columns:
/// `exp(−(t − t₀)/τ)`, the compensator's unknown state when the log
/// begins (the lag starts from the first temperature, which a clock that
/// was warmer or colder before does not), fitted with the temperature
/// and not reported.
const TRANSIENT: usize = OPTIONAL.len();

/// A coarse copy of the temperatures for the lag search: each bin's
/// samples in up to 32 consecutive chunks, each with its end time, its
/// mean temperature (held over the chunk) and its total weight in the
/// bin's mean. The lag at the chunk's weighted time is taken linear
/// between its values at the chunk's ends: second order in the chunk
/// over the time constant, exact for chunks of one sample.
struct Coarse {
    end: Vec<f64>,
    value: Vec<f64>,
    weight: Vec<f64>,
    /// Where in the chunk its samples' weighted times lie, as a fraction
    /// from its start (the previous chunk's end) to its end: the lag there
    /// is taken linear between the two.
    at: Vec<f64>,
    /// Each bin's chunks, as an index range.
    ranges: Vec<(usize, usize)>,
    /// The first sample's temperature (the lag's start).
    first: f64,
}

impl Coarse {
    fn new(bins: &Bins, times: &[f64], values: &[f64]) -> Coarse {
        let mut c = Coarse {
            end: Vec::new(),
            value: Vec::new(),
            weight: Vec::new(),
            at: Vec::new(),
            ranges: Vec::new(),
            first: values
                .iter()
                .copied()
                .find(|v| v.is_finite())
                .unwrap_or(0.0),
        };
        for &(a, b) in &bins.ranges {
            let first = c.end.len();
            let size = (b - a).div_ceil(32).max(1);
            let mut i = a;
            while i < b {
                let end = (i + size).min(b);
                let (mut w, mut wt, mut sum, mut n) = (0.0, 0.0, 0.0, 0usize);
                for j in i..end {
                    if values[j].is_finite() {
                        w += bins.sample_weight[j];
                        wt += bins.sample_weight[j] * times[j];
                        sum += values[j];
                        n += 1;
                    }
                }
                if n > 0 {
                    let start = c.end.last().copied().unwrap_or(times[i]).min(times[i]);
                    let start = if i > 0 {
                        times[i - 1].max(start)
                    } else {
                        start
                    };
                    let span = times[end - 1] - start;
                    let at = if w > 0.0 && span > 0.0 {
                        ((wt / w - start) / span).clamp(0.0, 1.0)
                    } else {
                        1.0
                    };
                    c.end.push(times[end - 1]);
                    c.value.push(sum / n as f64);
                    c.weight.push(w);
                    c.at.push(at);
                }
                i = end;
            }
            c.ranges.push((first, c.end.len()));
        }
        c
    }

    /// Each bin's weighted mean of the temperature lagged by `tau`.
    fn lagged_means(&self, tau: f64) -> Vec<f64> {
        let mut series = Vec::with_capacity(self.end.len() + 1);
        let mut times = Vec::with_capacity(self.end.len() + 1);
        series.push(self.first);
        times.push(self.end.first().copied().unwrap_or(0.0));
        series.extend_from_slice(&self.value);
        times.extend_from_slice(&self.end);
        // l[k + 1] is chunk k's end; l[k] its start.
        let l = lagged(&times, &series, tau);
        self.ranges
            .iter()
            .map(|&(a, b)| {
                let w: f64 = self.weight[a..b].iter().sum();
                if b > a && w > 0.0 {
                    (a..b)
                        .map(|k| self.weight[k] * (l[k] + self.at[k] * (l[k + 1] - l[k])))
                        .sum::<f64>()
                        / w
                } else {
                    f64::NAN
                }
            })
            .collect()
    }
}
