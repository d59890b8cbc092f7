//! What a log's analysis takes and gives.

use super::jumps::Wrap;
use super::spectrum::Spectrum;
use super::swing::Swing;
use super::terms::{ModelTerm, TERMS};
use super::wheels::{Arbor, Fold, TrainInput};
use crate::compound::description::Design;
use crate::error::format_significant;
use crate::period::Nominal;
use crate::stability::{Accident, StabilityRow};
use crate::tide::Station;
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};
use std::fmt;

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

/// A column beside the log's values: one of
/// [`super::terms::columns`], in its SI unit, one value a sample (NaN:
/// not read).
#[derive(Clone, Debug, PartialEq)]
pub struct LogColumn {
    /// Its name (`temperature`, `pressure`, …).
    pub name: String,
    /// Its values, in the column's SI unit (°C, Pa, %, rad).
    pub values: Vec<f64>,
}

impl LogColumn {
    /// A column named `name` of `values`.
    pub fn new(name: impl Into<String>, values: Vec<f64>) -> LogColumn {
        LogColumn {
            name: name.into(),
            values,
        }
    }
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
    /// The weather and the swing beside them (temperature °C, pressure
    /// Pa, humidity %, amplitude rad; [`super::terms::TERMS`]).
    pub columns: Vec<LogColumn>,
    /// A photogate's pulse widths, s (the amplitude from them, exactly,
    /// when no amplitude column is given: [`super::amplitude_from_pulse`]).
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

impl LogInput {
    /// The values of the column named `name`, if given.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.columns
            .iter()
            .find(|c| c.name == name)
            .map(|c| c.values.as_slice())
    }
}

/// One number a term of the table: its coefficient, or its standard
/// error (`None` when the term is not in the model), in the order of
/// [`TERMS`] without the drift (which the result gives on its own); with
/// the steps at the events. Serialised as `{key: value, …,
/// "steps_s_per_day": […]}`, each key the term's.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Coefficients {
    /// Each term's value, in [`TERMS`]' order (the drift's slot unused).
    pub values: Vec<Option<f64>>,
    /// The rate steps at the events, s/day, in their order.
    pub steps_s_per_day: Vec<f64>,
}

impl Coefficients {
    /// The value of the term named `name`.
    pub fn get(&self, name: &str) -> Option<f64> {
        let i = TERMS.iter().position(|t| t.name == name)?;
        self.values.get(i).copied().flatten()
    }

    /// Each term but the drift with its value.
    pub fn iter(&self) -> impl Iterator<Item = (&'static ModelTerm, Option<f64>)> + '_ {
        TERMS
            .iter()
            .enumerate()
            .filter(|(_, t)| t.name != "drift")
            .map(|(i, t)| (t, self.values.get(i).copied().flatten()))
    }
}

impl Serialize for Coefficients {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(None)?;
        for (term, value) in self.iter() {
            map.serialize_entry(term.key, &value)?;
        }
        map.serialize_entry("steps_s_per_day", &self.steps_s_per_day)?;
        map.end()
    }
}

/// A term the information criterion judged.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Term {
    /// Its name (`drift`, `temperature`, …, `random_walk`).
    pub name: &'static str,
    /// Kept in the model.
    pub kept: bool,
    /// The BIC of the model without it minus with it: positive means the
    /// data want it (above 6: strongly; Kass & Raftery 1995).
    pub delta_bic: f64,
    /// Its coefficient in the model with it (for a term left out: what
    /// the log allows it to be), in the key's unit (`None` for the
    /// random walk).
    pub estimate: Option<f64>,
    /// Its standard error there.
    pub standard_error: Option<f64>,
}

/// A design's prediction for one coefficient beside the measured one.
#[derive(Clone, Debug, PartialEq)]
pub struct Predicted {
    /// The term.
    pub term: &'static ModelTerm,
    /// What the design predicts, in the coefficient's unit.
    pub predicted: f64,
    /// Measured minus predicted, in the measured standard errors (`None`:
    /// not measured).
    pub difference_se: Option<f64>,
}

/// The design's predicted coefficients beside the measured. Serialised
/// flat: `{temperature_s_per_day_per_c: predicted,
/// temperature_difference_se: …, …}`.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct DesignComparison {
    /// Each prediction, in the table's order.
    pub predictions: Vec<Predicted>,
}

impl DesignComparison {
    /// The prediction for the term named `name`.
    pub fn get(&self, name: &str) -> Option<&Predicted> {
        self.predictions.iter().find(|p| p.term.name == name)
    }
}

impl Serialize for DesignComparison {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(None)?;
        for p in &self.predictions {
            map.serialize_entry(p.term.key, &p.predicted)?;
            map.serialize_entry(&format!("{}_difference_se", p.term.name), &p.difference_se)?;
        }
        map.end()
    }
}

/// The means the coefficients are about, a term's variable in its unit
/// (°C, hPa, %, °). Serialised as `{temperature_c: …, pressure_hpa: …}`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ReferenceWeather {
    /// `(term, mean)` for each weather term in the model.
    pub means: Vec<(&'static ModelTerm, f64)>,
}

impl ReferenceWeather {
    /// The mean of the term named `name`.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.means.iter().find(|(t, _)| t.name == name).map(|m| m.1)
    }
}

/// A variable's unit as a key's suffix: `°C` → `c`, `hPa` → `hpa`,
/// `%` → `percent`, `°` → `deg`.
pub fn unit_suffix(unit: &str) -> String {
    match unit {
        "°C" => "c".into(),
        "%" => "percent".into(),
        "°" => "deg".into(),
        other => other.to_lowercase().replace('/', "_per_"),
    }
}

impl Serialize for ReferenceWeather {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.means.len()))?;
        for (t, v) in &self.means {
            map.serialize_entry(&format!("{}_{}", t.name, unit_suffix(t.variable_unit)), v)?;
        }
        map.end()
    }
}

/// What a reader of the result must know.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(remote = "Self", tag = "code", rename_all = "snake_case")]
pub enum LogWarning {
    /// Whole-beat jumps of the offsets were undone.
    WrapsUndone {
        /// How many.
        count: usize,
    },
    /// Jumps of the offsets that stayed (not whole beats) were taken
    /// back: the clock set, stopped, or the reference changed.
    JumpsUndone {
        /// How many.
        count: usize,
        /// The first one's time, s of the log's time.
        first_time_s: f64,
        /// The largest, s.
        largest_s: f64,
        /// The Unix time of the log's time 0, when known, s (its time is
        /// then written as a date).
        #[serde(skip)]
        epoch_unix_s: Option<f64>,
    },
    /// Offsets read wrong and then right again (a missed pulse) were
    /// left out.
    GlitchesLeftOut {
        /// How many glitches.
        count: usize,
        /// Samples left out.
        samples: usize,
        /// The first one's time, s.
        first_time_s: f64,
        /// The largest, s.
        largest_s: f64,
        /// The Unix time of the log's time 0, when known, s.
        #[serde(skip)]
        epoch_unix_s: Option<f64>,
    },
    /// Rates far out of line with their neighbours were left out.
    RatesLeftOut {
        /// How many.
        count: usize,
        /// The first one's time, s.
        first_time_s: f64,
        /// The largest departure, s/day.
        largest_s_per_day: f64,
        /// The Unix time of the log's time 0, when known, s.
        #[serde(skip)]
        epoch_unix_s: Option<f64>,
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
    /// The temperature's lag is at the longest the log can tell: it may
    /// be longer, and the temperature coefficient with it.
    LagAtLimit {
        /// The lag found, s.
        lag_s: f64,
    },
    /// The residuals are correlated beyond the noise model: every
    /// standard error (the rate's, the coefficients', the lag's range)
    /// was widened by `factor`.
    ErrorsWidened {
        /// The widening.
        factor: f64,
        /// The standardised residuals' lag-1 autocorrelation.
        autocorrelation: f64,
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

impl LogWarning {
    /// Dates the warning's times from the log's time 0 at `epoch` (Unix
    /// s), when the log has dates.
    pub fn date(&mut self, epoch: Option<f64>) {
        match self {
            LogWarning::JumpsUndone { epoch_unix_s, .. }
            | LogWarning::GlitchesLeftOut { epoch_unix_s, .. }
            | LogWarning::RatesLeftOut { epoch_unix_s, .. } => *epoch_unix_s = epoch,
            _ => {}
        }
    }
}

/// A log's time `t` (s from its time 0) in words: a UTC date when the
/// log has dates (`epoch`, Unix s), else seconds.
fn log_time(t: f64, epoch: Option<f64>) -> String {
    match epoch {
        Some(e) => iso_utc(e + t),
        None => format!("{} s", format_significant(t, 10)),
    }
}

/// Unix time `t` (s) as an ISO 8601 UTC date and time, to the
/// millisecond when it has one (`2026-03-01T12:00:00Z`,
/// `…T12:00:00.250Z`): the proleptic Gregorian calendar from the day
/// count (H. Hinnant's `civil_from_days`, exact over ±10⁵ years).
pub fn iso_utc(t: f64) -> String {
    let ms = (t * 1e3).round();
    if !ms.is_finite() || ms.abs() > 3e15 {
        return format!("{t}");
    }
    let ms = ms as i64;
    let (days, in_day) = (ms.div_euclid(86_400_000), ms.rem_euclid(86_400_000));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    let (h, m, s, milli) = (
        in_day / 3_600_000,
        in_day / 60_000 % 60,
        in_day / 1000 % 60,
        in_day % 1000,
    );
    if milli == 0 {
        format!("{year:04}-{month:02}-{day:02}T{h:02}:{m:02}:{s:02}Z")
    } else {
        format!("{year:04}-{month:02}-{day:02}T{h:02}:{m:02}:{s:02}.{milli:03}Z")
    }
}

impl fmt::Display for LogWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let num = format_significant;
        match self {
            LogWarning::JumpsUndone {
                count,
                first_time_s,
                largest_s,
                epoch_unix_s,
            } => write!(
                f,
                "rate: {count} jumps of the offset taken out (the first at {}, the largest {} s): \
                 the clock set or stopped, or the reference changed; the rate is read across \
                 them, and a stop's lost time is not in it",
                log_time(*first_time_s, *epoch_unix_s),
                num(*largest_s, 4)
            ),
            LogWarning::GlitchesLeftOut {
                count,
                samples,
                first_time_s,
                largest_s,
                epoch_unix_s,
            } => write!(
                f,
                "rate and stability: {count} glitches left out ({samples} offsets read wrong and \
                 then right, the first at {}, the largest {} s off: a missed pulse?)",
                log_time(*first_time_s, *epoch_unix_s),
                num(*largest_s, 4)
            ),
            LogWarning::RatesLeftOut {
                count,
                first_time_s,
                largest_s_per_day,
                epoch_unix_s,
            } => write!(
                f,
                "rate: {count} rates far out of line with their neighbours left out (the first \
                 at {}, the largest {} s/day off)",
                log_time(*first_time_s, *epoch_unix_s),
                num(*largest_s_per_day, 4)
            ),
            LogWarning::LagAtLimit { lag_s } => write!(
                f,
                "temperature: its lag, {} h, is the longest this log can tell: the lag may be \
                 longer, and the temperature coefficient larger with it",
                num(lag_s / 3600.0, 3)
            ),
            LogWarning::ErrorsWidened {
                factor,
                autocorrelation,
            } => write!(
                f,
                "every standard error (the rate's and the coefficients') widened {}×: the \
                 residuals are correlated beyond the noise model (lag-1 autocorrelation {})",
                num(*factor, 3),
                num(*autocorrelation, 2)
            ),
            LogWarning::WrapsUndone { count } => write!(
                f,
                "rate: {count} whole-beat jumps of the offset undone (the reference slipped a \
                 tick); the rate is read across them"
            ),
            LogWarning::Implausible { term, reason } => write!(f, "{term}: {reason}"),
            LogWarning::TideAdmittance {
                admittance,
                from_one_se,
            } => write!(
                f,
                "tide: the admittance {} is {} standard errors from 1: something else shares \
                 the tide's periods (a daily temperature cycle?), or the times are not UTC",
                num(*admittance, 3),
                num(*from_one_se, 2)
            ),
            LogWarning::Short { what } => write!(f, "{what}: the log is too short to tell it"),
            LogWarning::TimesRepeated {
                dropped,
                first_time_s,
            } => write!(
                f,
                "{dropped} samples whose time did not advance left out (the first at {} s): a \
                 logger's repeated stamp, or files joined with an overlap",
                num(*first_time_s, 10)
            ),
            LogWarning::BeatsMissed { left_out } => write!(
                f,
                "{left_out} half periods under half or over 1.5 times the typical one left out \
                 (a transit the gate missed, a stray trigger): the beats they span count as a \
                 gap"
            ),
            LogWarning::EventIgnored { time_s, reason } => write!(
                f,
                "the event at {} s of the log is left out: {reason}",
                num(*time_s, 10)
            ),
            LogWarning::PulsesIgnored => f.write_str(
                "the pulse widths are left aside: give --flag-width and --gate-radius to read \
                 the swing's amplitude, Q and steadiness from them",
            ),
            LogWarning::TrainBeat { train_bph, log_bph } => write!(
                f,
                "the train gives {} beats an hour, the log {}: check --train and \
                 --arbor-turns-per-hour",
                num(*train_bph, 6),
                num(*log_bph, 6)
            ),
            LogWarning::RateAgainstMean => f.write_str(
                "no standard beat within 2% of the half periods: the rate is against their \
                 mean; give --bph or --period",
            ),
        }
    }
}

impl crate::warning::Warn for LogWarning {
    fn code(&self) -> &'static str {
        match self {
            LogWarning::WrapsUndone { .. } => "wraps_undone",
            LogWarning::JumpsUndone { .. } => "jumps_undone",
            LogWarning::GlitchesLeftOut { .. } => "glitches_left_out",
            LogWarning::RatesLeftOut { .. } => "rates_left_out",
            LogWarning::Implausible { .. } => "implausible",
            LogWarning::TideAdmittance { .. } => "tide_admittance",
            LogWarning::Short { .. } => "short",
            LogWarning::LagAtLimit { .. } => "lag_at_limit",
            LogWarning::ErrorsWidened { .. } => "errors_widened",
            LogWarning::TimesRepeated { .. } => "times_repeated",
            LogWarning::RateAgainstMean => "rate_against_mean",
            LogWarning::BeatsMissed { .. } => "beats_missed",
            LogWarning::EventIgnored { .. } => "event_ignored",
            LogWarning::PulsesIgnored => "pulses_ignored",
            LogWarning::TrainBeat { .. } => "train_beat",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            LogWarning::WrapsUndone { .. }
            | LogWarning::JumpsUndone { .. }
            | LogWarning::GlitchesLeftOut { .. }
            | LogWarning::RatesLeftOut { .. }
            | LogWarning::RateAgainstMean => Some("rate_s_per_day"),
            LogWarning::Implausible { term, .. } => Some(term),
            LogWarning::TideAdmittance { .. } => Some("tide"),
            LogWarning::Short { .. } => None,
            LogWarning::LagAtLimit { .. } => Some("temperature_lag_s"),
            LogWarning::ErrorsWidened { .. } => Some("rate_standard_error_s_per_day"),
            LogWarning::TimesRepeated { .. } | LogWarning::BeatsMissed { .. } => Some("samples"),
            LogWarning::EventIgnored { .. } => Some("steps_s_per_day"),
            LogWarning::PulsesIgnored => Some("swing"),
            LogWarning::TrainBeat { .. } => Some("arbors"),
        }
    }
}

impl Serialize for LogWarning {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let fields = LogWarning::serialize(self, serde_json::value::Serializer);
        crate::warning::serialize_with_fields(self, fields, s)
    }
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
    /// The clock's mean rate over the log, at its mean weather, s/day
    /// (the constant of the model with the random walk's mean over the
    /// log: the rate the log's own ends give, less the weather).
    pub rate_s_per_day: f64,
    /// Its standard error (the walk's uncertainty included).
    pub rate_standard_error_s_per_day: f64,
    /// The log time at the bins' mean, s (the drift's zero).
    pub reference_time_s: f64,
    /// The rate at the log's last bin (the model with the walk smoothed
    /// there), at the mean weather, s/day: where the clock is now.
    pub rate_at_end_s_per_day: f64,
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
    /// The temperature lag's time constant, s (0: none found).
    pub temperature_lag_s: Option<f64>,
    /// Its 95% range from the profile likelihood, s (the lower end 0
    /// when no lag is told from none).
    pub temperature_lag_range_s: Option<[f64; 2]>,
    /// The means the coefficients are about.
    pub reference_weather: ReferenceWeather,
    /// The terms the criterion judged.
    pub terms: Vec<Term>,
    /// The white frequency noise of one bin's rate, s/day.
    pub white_noise_s_per_day: f64,
    /// The random walk of the rate in a day, s/day (0: none found).
    pub random_walk_s_per_day_per_day: f64,
    /// The RMS of the residuals, each bin weighted by the time it covers,
    /// s/day (the walk taken out).
    pub residual_rms_s_per_day: f64,
    /// Stability of the raw series.
    pub stability: Vec<StabilityRow>,
    /// Stability of the bins' residuals after the model.
    pub residual_stability: Vec<StabilityRow>,
    /// The design's predictions beside the measured coefficients.
    pub design: Option<DesignComparison>,
    /// Whole-beat jumps undone.
    pub wraps: Vec<Wrap>,
    /// Other jumps undone and glitches left out.
    pub accidents: Vec<Accident>,
    /// What to be careful of.
    pub warnings: Vec<LogWarning>,
    /// The spectrum of the rate less the model's weather, drift and
    /// steps, with the tides', the day's and the wheels' lines (`None`
    /// when the log is too short for one).
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
    /// The clock's beat, when the log gives it: the half periods' mean,
    /// or the beat a reference comparison slips by as given, s.
    pub beat_s: Option<f64>,
    /// What to do ([`crate::advice`]): the rate at the log's end
    /// ([`LogResult::rate_at_end_s_per_day`]) as the move of the bob and
    /// the turns of the nut, and for half periods the beat error as the
    /// move at the crutch; from the pendulum known
    /// ([`LogResult::advise`]), else the simple pendulum of the beat.
    /// Empty when neither the beat nor the pendulum is known.
    pub advice: Vec<crate::advice::Advice>,
    /// Per bin: centre time (s), rate, model with the walk, residual
    /// (s/day).
    #[serde(skip)]
    pub per_bin: Vec<[f64; 4]>,
    /// Each weather and tide term's partial residuals, for plots.
    #[serde(skip)]
    pub partials: Vec<Partial>,
    /// The weather a bin, for plots, in each term's variable unit (the
    /// temperature as read, not lagged).
    #[serde(skip)]
    pub weather_per_bin: Vec<(&'static ModelTerm, Vec<f64>)>,
}

/// One term's partial residuals: the rate with every other term and the
/// walk taken out, against the term's variable, and the fitted line
/// through them.
#[derive(Clone, Debug, PartialEq)]
pub struct Partial {
    /// The term.
    pub term: &'static ModelTerm,
    /// The variable a bin, in its unit (the lagged temperature °C, the
    /// pressure hPa, the humidity %, the amplitude °, the tidal rate
    /// s/day).
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

impl LogResult {
    /// The standard error of [`LogResult::rate_at_end_s_per_day`], s/day:
    /// the mean rate's (the walk's uncertainty included) and the drift's
    /// over the time from the bins' mean to the log's end, added in
    /// quadrature (the two are uncorrelated about the bins' mean, the
    /// drift's zero).
    pub fn rate_at_end_standard_error_s_per_day(&self) -> f64 {
        let end = self.per_bin.last().map_or(self.reference_time_s, |b| b[0]);
        let days = (end - self.reference_time_s) / 86_400.0;
        let drift = self.drift_standard_error_s_per_day_per_day.unwrap_or(0.0) * days;
        self.rate_standard_error_s_per_day.hypot(drift)
    }

    /// Fills [`LogResult::advice`] from the rate at the log's end and
    /// `known`: the beat is the log's ([`LogResult::beat_s`]) or, when it
    /// has none, the beat of the pendulum known (`π √(L/g)` of its
    /// equivalent length, standard gravity: [`crate::advice::beat_of_length`]). Refused when the regulation
    /// cannot be figured (a nut's thread out of range, a design's part
    /// not found).
    pub fn advise(&mut self, known: &crate::advice::Known) -> Result<(), crate::analysis::Refusal> {
        crate::advice::check(known)?;
        let beat = match (self.beat_s, &known.pendulum) {
            (Some(b), _) => b,
            (None, Some(pendulum)) => crate::advice::beat_of_length(
                crate::compound::regulate::regulate(pendulum, 0.0, known.nut, None)?
                    .equivalent_length_m,
            ),
            (None, None) => {
                self.advice.clear();
                return Ok(());
            }
        };
        self.advice = crate::advice::advise(&crate::advice::Clockwork {
            rate_s_per_day: Some(self.rate_at_end_s_per_day),
            rate_standard_error_s_per_day: Some(self.rate_at_end_standard_error_s_per_day()),
            beat_s: beat,
            beat_error_s: self.beat_error_s.map(f64::abs),
            beat_error_standard_error_s: None,
            oscillator: None,
            amplitude_rad: None,
            lift_rad: None,
            known: known.clone(),
        })?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::iso_utc;

    #[test]
    fn unix_times_are_written_as_utc_dates() {
        // Known instants: the epoch, a leap day, a billennium, before 1970.
        assert_eq!(iso_utc(0.0), "1970-01-01T00:00:00Z");
        assert_eq!(iso_utc(951_782_400.0), "2000-02-29T00:00:00Z");
        assert_eq!(iso_utc(1_700_000_000.0), "2023-11-14T22:13:20Z");
        assert_eq!(iso_utc(-1.0), "1969-12-31T23:59:59Z");
        assert_eq!(iso_utc(1_700_000_000.25), "2023-11-14T22:13:20.250Z");
        assert_eq!(iso_utc(4_107_542_400.0), "2100-03-01T00:00:00Z");
    }
}
