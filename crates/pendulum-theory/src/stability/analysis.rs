//! One call for a series' stability: every deviation at each averaging
//! time, its confidence interval and the noise that dominates there, and
//! a plain reading of the whole.

use super::deviations::{oadev, phase_from_frequency};
use super::edf::greenhall;
use super::noise::{identify_pooled, Noise};
use super::outliers::{find_accidents, remove_accidents, AccidentKind};
use super::periodic::{find_periodic, PeriodicSignal};
use super::registry::{Deviation, ADEV, DEVIATIONS, HDEV};
use crate::analysis::{judge_work, require_finite, Refusal};
use crate::error::format_significant;
use serde::Serialize;
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// What the series holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DataKind {
    /// Time error (clock minus reference), s.
    Phase,
    /// Fractional frequency (a rate in s/day divided by 86,400).
    Frequency,
}

/// Which averaging times.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Taus {
    /// `τ₀, 2τ₀, 4τ₀, …` (Stable32's octave spacing).
    Octave,
    /// Every multiple of `τ₀` (work grows as the square of the length).
    All,
}

/// A series to analyse.
#[derive(Clone, Debug)]
pub struct StabilityInput {
    /// The samples, one every `tau0_s`; NaN marks a gap.
    pub data: Vec<f64>,
    /// Phase or frequency.
    pub kind: DataKind,
    /// The spacing of the samples, s.
    pub tau0_s: f64,
    /// Which averaging times.
    pub taus: Taus,
    /// Run even when the work estimate is long.
    pub force: bool,
    /// What to do with jumps and glitches found
    /// ([`super::outliers`]): keep them (and warn, with how much they
    /// raise the shortest τ's deviation) or take them out (Stable32's
    /// practice: a glitch becomes a gap, a jump is taken back).
    pub outliers: Outliers,
}

/// What to do with jumps and glitches.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Outliers {
    /// Keep them, and warn.
    #[default]
    Keep,
    /// Take them out, and say so.
    Remove,
}

/// One deviation's value at one averaging time, and its interval.
#[derive(Clone, Copy, Debug)]
pub struct Measured {
    /// Which deviation ([`DEVIATIONS`]).
    pub deviation: &'static Deviation,
    /// Its value, `None` where the series is too short for it.
    pub value: Option<f64>,
    /// Its 68.3% (1σ) confidence interval, from Greenhall's EDF for the
    /// noise identified at this τ, where the deviation has one.
    pub interval: Option<(f64, f64)>,
}

/// Every deviation of [`DEVIATIONS`] at one averaging time, in its order.
/// Written as each one's key with its value, and for those with an
/// interval `KEY_low` and `KEY_high`.
#[derive(Clone, Debug)]
pub struct Deviations(pub Vec<Measured>);

impl Deviations {
    /// The entry of `deviation`.
    pub fn get(&self, deviation: &Deviation) -> Option<&Measured> {
        self.0.iter().find(|m| m.deviation == deviation)
    }
}

impl Serialize for Deviations {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = serializer.serialize_map(None)?;
        for m in &self.0 {
            map.serialize_entry(m.deviation.key, &m.value)?;
            if m.deviation.interval.is_some() {
                map.serialize_entry(
                    &format!("{}_low", m.deviation.key),
                    &m.interval.map(|i| i.0),
                )?;
                map.serialize_entry(
                    &format!("{}_high", m.deviation.key),
                    &m.interval.map(|i| i.1),
                )?;
            }
        }
        map.end()
    }
}

/// One averaging time.
#[derive(Clone, Debug, Serialize)]
pub struct StabilityRow {
    /// The averaging time `τ = m τ₀`, s.
    pub tau_s: f64,
    /// The averaging factor `m`.
    pub averaging_factor: usize,
    /// Each deviation of [`DEVIATIONS`] with its interval (the keys
    /// `adev`, `adev_low`, `adev_high`, `mdev`, …, `tdev`, `hdev`, …,
    /// `totdev`, `mtie_s`).
    #[serde(flatten)]
    pub deviations: Deviations,
    /// The overlapping Allan deviation as a rate, s/day (`adev × 86,400`).
    pub adev_s_per_day: Option<f64>,
    /// The noise that dominates at this τ (lag-1 autocorrelation), or, with
    /// too few points to tell, the one at the τ below it.
    pub noise: Option<Noise>,
    /// Its exponent `α` of `S_y(f) ∝ f^α`.
    pub noise_alpha: Option<i32>,
    /// The noise was carried from a shorter τ (fewer than 30 points here).
    pub noise_carried: bool,
    /// The equivalent degrees of freedom behind the Allan interval.
    pub adev_edf: Option<f64>,
    /// The row is a periodic signal's more than noise (its Allan variance
    /// more than half the row's): no noise type, no interval.
    pub periodic: bool,
    /// Why the row has no interval, when it has none.
    pub no_interval_reason: Option<&'static str>,
}

impl StabilityRow {
    /// The value of `deviation` here.
    pub fn value(&self, deviation: &Deviation) -> Option<f64> {
        self.deviations.get(deviation)?.value
    }

    /// The 68% interval of `deviation` here.
    pub fn interval(&self, deviation: &Deviation) -> Option<(f64, f64)> {
        self.deviations.get(deviation)?.interval
    }

    /// The overlapping Allan deviation ([`ADEV`]).
    pub fn adev(&self) -> Option<f64> {
        self.value(&ADEV)
    }
}

/// The averaging time at which the clock is steadiest.
#[derive(Clone, Debug, Serialize)]
pub struct Best {
    /// The averaging time of the lowest overlapping Allan deviation, s.
    pub tau_s: f64,
    /// The deviation there (fractional).
    pub adev: f64,
    /// The same as a rate, s/day.
    pub adev_s_per_day: f64,
    /// Whether the lowest is at the longest τ computed: the clock may
    /// average down further than the record shows.
    pub at_longest_tau: bool,
}

/// What an analysis noticed that a reader must know.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(remote = "Self", tag = "code", rename_all = "snake_case")]
pub enum StabilityWarning {
    /// Gaps (NaN samples) in the series.
    Gaps {
        /// How many samples were missing.
        missing: usize,
        /// Out of how many.
        of: usize,
    },
    /// The noise could not be identified at any τ: no intervals.
    NoNoiseType,
    /// Jumps and glitches of the series (a missed pulse, the reference
    /// slipping): found, and kept or taken out.
    Accidents {
        /// Glitches (samples read wrong, then right).
        glitches: usize,
        /// Jumps (steps of the phase that stay).
        jumps: usize,
        /// The first one's time, s from the first sample.
        first_time_s: f64,
        /// The largest, s of phase (frequency data: fractional frequency).
        largest: f64,
        /// The Allan deviation at the shortest τ with them over without.
        adev_factor: f64,
        /// Taken out (`--outliers remove`), or kept.
        removed: bool,
        /// Phase or frequency: the unit of `largest`.
        #[serde(skip)]
        kind: DataKind,
        /// The sample spacing, s: the τ of `adev_factor`.
        #[serde(skip)]
        tau0_s: f64,
    },
    /// A periodic signal dominates some averaging times: their rows are
    /// the signal's, not noise.
    Periodic {
        /// Its period, s.
        period_s: f64,
        /// Its amplitude, s/day.
        amplitude_s_per_day: f64,
        /// The shortest and longest τ it dominates, s.
        from_tau_s: f64,
        /// The longest.
        to_tau_s: f64,
    },
}

impl std::fmt::Display for StabilityWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let num = format_significant;
        match self {
            StabilityWarning::Gaps { missing, of } => write!(
                f,
                "{missing} of {of} samples missing (gaps): the terms that touch them are left out"
            ),
            StabilityWarning::NoNoiseType => {
                f.write_str("too few points to tell the noise at any τ (30 needed): no intervals")
            }
            StabilityWarning::Accidents {
                glitches,
                jumps,
                first_time_s,
                largest,
                adev_factor,
                removed,
                kind,
                tau0_s,
            } => {
                let unit = match kind {
                    DataKind::Phase => " s",
                    DataKind::Frequency => " (fractional frequency)",
                };
                let counted = |n: usize, one: &str, many: &str| match n {
                    0 => None,
                    1 => Some(format!("1 {one}")),
                    _ => Some(format!("{n} {many}")),
                };
                let counts: Vec<String> = [
                    counted(*glitches, "glitch", "glitches"),
                    counted(*jumps, "jump", "jumps"),
                ]
                .into_iter()
                .flatten()
                .collect();
                let what = format!(
                    "{} (the first at {} s from the start, the largest {}{unit})",
                    counts.join(" and "),
                    num(*first_time_s, 8),
                    num(*largest, 3)
                );
                if *removed {
                    write!(
                        f,
                        "{what} taken out (--outliers remove): with them ADEV at τ = {} s was {} \
                         times as large",
                        num(*tau0_s, 4),
                        num(*adev_factor, 3)
                    )
                } else {
                    write!(
                        f,
                        "ADEV and the noise types: {what} raise ADEV at τ = {} s {} times, and \
                         the noise types read from it; --outliers remove takes them out \
                         (`pendulum log` does)",
                        num(*tau0_s, 4),
                        num(*adev_factor, 3)
                    )
                }
            }
            StabilityWarning::Periodic {
                period_s,
                amplitude_s_per_day,
                from_tau_s,
                to_tau_s,
            } => write!(
                f,
                "ADEV from τ = {} to {} s is a periodic signal's (period {} h, {} s/day), not \
                 noise: no noise type or interval there; `pendulum log` models a daily cycle \
                 with the room's temperature",
                num(*from_tau_s, 4),
                num(*to_tau_s, 4),
                num(period_s / 3600.0, 4),
                num(*amplitude_s_per_day, 3)
            ),
        }
    }
}

impl crate::warning::Warn for StabilityWarning {
    fn code(&self) -> &'static str {
        match self {
            StabilityWarning::Gaps { .. } => "gaps",
            StabilityWarning::NoNoiseType => "no_noise_type",
            StabilityWarning::Accidents { .. } => "accidents",
            StabilityWarning::Periodic { .. } => "periodic",
        }
    }

    fn figure(&self) -> Option<&'static str> {
        match self {
            StabilityWarning::NoNoiseType => Some("adev_low"),
            _ => Some("adev"),
        }
    }
}

impl Serialize for StabilityWarning {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let fields = StabilityWarning::serialize(self, serde_json::value::Serializer);
        crate::warning::serialize_with_fields(self, fields, s)
    }
}

/// The stability of a series.
#[derive(Clone, Debug, Serialize)]
pub struct Stability {
    /// Phase or frequency, as given.
    pub kind: DataKind,
    /// The sample spacing, s.
    pub tau0_s: f64,
    /// The number of phase points analysed (frequency samples + 1).
    pub phase_points: usize,
    /// Each averaging time (the key `stability`, as in `log`'s output).
    #[serde(rename = "stability")]
    pub rows: Vec<StabilityRow>,
    /// The steadiest averaging time, if any deviation was computed.
    pub best: Option<Best>,
    /// What to be careful of.
    pub warnings: Vec<StabilityWarning>,
    /// A periodic signal in the series, when one stands out.
    pub periodic: Option<PeriodicSignal>,
}

/// The `1σ` (68.27%) interval of a deviation `dev` with `edf` degrees of
/// freedom: `dev √(ν/χ²_{ν,0.841})` to `dev √(ν/χ²_{ν,0.159})` (SP 1065
/// eq. 45, the χ² quantiles from `statrs`).
pub fn interval(dev: f64, edf: f64) -> Option<(f64, f64)> {
    let chi = ChiSquared::new(edf).ok()?;
    let tail = (1.0 - ONE_SIGMA) / 2.0;
    let (lo, hi) = (chi.inverse_cdf(1.0 - tail), chi.inverse_cdf(tail));
    let pair = (dev * (edf / lo).sqrt(), dev * (edf / hi).sqrt());
    (pair.0.is_finite() && pair.1.is_finite()).then_some(pair)
}

/// `erf(1/√2)`, the probability within one standard deviation.
const ONE_SIGMA: f64 = 0.682_689_492_137_085_9;

/// The series' jumps and glitches, kept or taken out as `input` says,
/// and the warning that names them with how much they raise the Allan
/// deviation at the shortest τ.
fn accidents(input: &StabilityInput, tau0: f64) -> (Vec<f64>, Option<StabilityWarning>) {
    let data = &input.data;
    let times: Vec<f64> = (0..data.len()).map(|i| i as f64 * tau0).collect();
    let (found, mut cleaned) = match input.kind {
        DataKind::Phase => {
            let found = find_accidents(&times, data);
            let mut cleaned = data.clone();
            remove_accidents(&mut cleaned, &found);
            (found, cleaned)
        }
        DataKind::Frequency => {
            // An outlying rate is a glitch of one sample.
            let found: Vec<_> = super::outliers::frequency_outliers(data)
                .into_iter()
                .map(|(i, d)| super::outliers::Accident {
                    kind: AccidentKind::Glitch,
                    time_s: times[i],
                    first_sample: i,
                    samples: 1,
                    size_s: d,
                    sigmas: 0.0,
                })
                .collect();
            let mut cleaned = data.clone();
            for a in &found {
                cleaned[a.first_sample] = f64::NAN;
            }
            (found, cleaned)
        }
    };
    if found.is_empty() {
        return (cleaned, None);
    }
    let phase = |d: &[f64]| match input.kind {
        DataKind::Phase => d.to_vec(),
        DataKind::Frequency => phase_from_frequency(d, tau0),
    };
    let with = oadev(&phase(data), tau0, 1);
    let without = oadev(&phase(&cleaned), tau0, 1);
    let factor = match (with, without) {
        (Some(a), Some(b)) if b > 0.0 => a / b,
        _ => 1.0,
    };
    let warning = StabilityWarning::Accidents {
        glitches: found
            .iter()
            .filter(|a| a.kind == AccidentKind::Glitch)
            .count(),
        jumps: found
            .iter()
            .filter(|a| a.kind == AccidentKind::Jump)
            .count(),
        first_time_s: found[0].time_s,
        largest: found
            .iter()
            .map(|a| a.size_s)
            .fold(0.0, |a: f64, b| if b.abs() > a.abs() { b } else { a }),
        adev_factor: factor,
        removed: input.outliers == Outliers::Remove,
        kind: input.kind,
        tau0_s: tau0,
    };
    if input.outliers == Outliers::Keep {
        cleaned = data.clone();
    }
    (cleaned, Some(warning))
}

/// The samples' spacing checked: from a microsecond (a photogate's
/// timer) to a year (a clock checked once a year); the refusal names
/// `tau0`.
fn spacing(tau0: f64) -> Result<f64, Refusal> {
    let tau0 = require_finite("tau0", tau0)?;
    if tau0 <= 0.0 {
        return Err(Refusal::field(
            "tau0",
            format!("must be positive, got {} s", format_significant(tau0, 6)),
        ));
    }
    if !(1e-6..=3.2e7).contains(&tau0) {
        return Err(Refusal::field(
            "tau0",
            format!(
                "must be from 1 µs to a year (3.2e7 s), got {} s",
                format_significant(tau0, 6)
            ),
        ));
    }
    Ok(tau0)
}

/// Seconds of computing per deviation term (four statistics and the
/// noise identification), measured on this project's benchmark machine.
const SECONDS_PER_TERM: f64 = 2e-9;

/// Computes the stability of `input`.
///
/// Validation: `tau0_s` positive and finite; at least three finite
/// samples; infinite samples refused (NaN is a gap). Work: octave τ is
/// linear in the length; every τ is quadratic and judged by
/// [`judge_work`].
///
/// # Examples
///
/// ```
/// use pendulum_theory::stability::{stability, DataKind, Outliers, StabilityInput, Taus, HDEV};
///
/// // A frequency drifting steadily, y = D t: σ_y(τ) = D τ/√2 (NIST SP 1065).
/// let drift = 1e-9; // per second
/// let s = stability(&StabilityInput {
///     data: (0..256).map(|k| drift * k as f64).collect(),
///     kind: DataKind::Frequency,
///     tau0_s: 1.0,
///     taus: Taus::Octave,
///     force: false,
///     outliers: Outliers::Keep,
/// })?;
/// let row = &s.rows[2];
/// assert_eq!(row.tau_s, 4.0);
/// assert!((row.adev().unwrap() - drift * 4.0 / 2f64.sqrt()).abs() < 1e-15);
/// assert!(row.value(&HDEV).unwrap() < 1e-15); // Hadamard's is blind to a drift
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn stability(input: &StabilityInput) -> Result<Stability, Refusal> {
    let tau0 = spacing(input.tau0_s)?;
    if let Some(i) = input.data.iter().position(|v| v.is_infinite()) {
        return Err(Refusal::sample(
            "data",
            i,
            "must be finite, got an infinite value",
        ));
    }
    let missing = input.data.iter().filter(|v| v.is_nan()).count();
    let finite = input.data.len() - missing;
    if finite < 3 {
        return Err(Refusal::data(format!(
            "a stability needs at least 3 samples, got {finite}"
        )));
    }
    let (data, accident) = accidents(input, tau0);
    let phase = match input.kind {
        DataKind::Phase => data.clone(),
        DataKind::Frequency => phase_from_frequency(&data, tau0),
    };
    // The periodic signal, read from the frequency.
    let frequency: Vec<f64> = match input.kind {
        DataKind::Frequency => data.clone(),
        DataKind::Phase => data.windows(2).map(|w| (w[1] - w[0]) / tau0).collect(),
    };
    let signal = find_periodic(&frequency, tau0);
    let n = phase.len();
    let factors: Vec<usize> = match input.taus {
        Taus::Octave => std::iter::successors(Some(1usize), |m| m.checked_mul(2))
            .take_while(|m| 4 * m < n)
            .collect(),
        Taus::All => (1..).take_while(|m| 4 * m < n).collect(),
    };
    let terms = factors.len() as f64 * n as f64;
    judge_work(
        "taus",
        format_args!("{} averaging times of {n} points", factors.len()),
        terms * SECONDS_PER_TERM * 6.0,
        input.force,
    )?;

    let is_phase = input.kind == DataKind::Phase;
    let mut previous: Option<Noise> = None;
    let mut rows = Vec::with_capacity(factors.len());
    for &m in &factors {
        let row = row_at(&phase, &data, tau0, m, is_phase, signal.as_ref(), previous);
        if !row.periodic {
            previous = row.noise;
        }
        rows.push(row);
    }
    // Rows past the last computable deviation say nothing.
    rows.retain(|r| r.adev().is_some() || r.value(&HDEV).is_some());
    let best = rows
        .iter()
        .filter_map(|r| Some((r.tau_s, r.adev()?)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(tau_s, adev)| Best {
            tau_s,
            adev,
            adev_s_per_day: adev * 86_400.0,
            at_longest_tau: rows
                .iter()
                .rev()
                .find(|r| r.adev().is_some())
                .is_some_and(|r| r.tau_s == tau_s),
        });
    let mut warnings = Vec::new();
    if missing > 0 {
        warnings.push(StabilityWarning::Gaps {
            missing,
            of: input.data.len(),
        });
    }
    if let Some(a) = accident {
        warnings.push(a);
    }
    let dominated: Vec<f64> = rows
        .iter()
        .filter(|r| r.periodic)
        .map(|r| r.tau_s)
        .collect();
    if let (Some(sig), Some(&from), Some(&to)) = (&signal, dominated.first(), dominated.last()) {
        warnings.push(StabilityWarning::Periodic {
            period_s: sig.period_s,
            amplitude_s_per_day: sig.amplitude_s_per_day,
            from_tau_s: from,
            to_tau_s: to,
        });
    }
    if rows.iter().all(|r| r.noise.is_none()) && dominated.is_empty() {
        warnings.push(StabilityWarning::NoNoiseType);
    }
    Ok(Stability {
        kind: input.kind,
        tau0_s: tau0,
        phase_points: n,
        rows,
        best,
        warnings,
        periodic: signal.filter(|_| !dominated.is_empty()),
    })
}

/// The row at averaging factor `m`: every deviation of [`DEVIATIONS`]
/// on `phase`, the noise identified on `data` (as given, phase or
/// frequency; carried from `previous` where too few points tell it), the
/// intervals for that noise, and whether `signal` dominates here.
fn row_at(
    phase: &[f64],
    data: &[f64],
    tau0: f64,
    m: usize,
    is_phase: bool,
    signal: Option<&PeriodicSignal>,
    previous: Option<Noise>,
) -> StabilityRow {
    let n = phase.len();
    let tau = m as f64 * tau0;
    let a = oadev(phase, tau0, m);
    let periodic = match (signal, a) {
        (Some(sig), Some(a)) => sig.allan_variance(tau) > 0.5 * a * a,
        _ => false,
    };
    let identified = if periodic {
        None
    } else {
        identify_pooled(data, m, is_phase, 2)
    };
    let carried = identified.is_none() && previous.is_some() && !periodic;
    let noise = if periodic {
        None
    } else {
        identified.or(previous)
    };
    // The noise a deviation's interval reads: identified with its own
    // highest difference where it can be, else the row's.
    let noise_for = |d_max: u32| match identified {
        Some(_) if d_max != 2 => identify_pooled(data, m, is_phase, d_max),
        _ => noise,
    };
    let mut adev_edf = None;
    let deviations = DEVIATIONS
        .iter()
        .map(|deviation| {
            let value = (deviation.compute)(phase, tau0, m);
            let with_edf = deviation.interval.and_then(|rule| {
                let edf = greenhall(noise_for(rule.d_max)?.alpha(), rule.edf, m, n)?;
                Some((edf, interval(value?, edf)?))
            });
            if deviation == &ADEV {
                adev_edf = with_edf.map(|c| c.0);
            }
            Measured {
                deviation,
                value,
                interval: with_edf.map(|c| c.1),
            }
        })
        .collect();
    let no_interval_reason = match (adev_edf, periodic, noise) {
        (Some(_), _, _) => None,
        (None, true, _) => Some("a periodic signal, not noise, makes this deviation"),
        (None, false, None) => Some("too few points to tell the noise (30 needed)"),
        (None, false, Some(_)) => {
            Some("too few points for the equivalent degrees of freedom at this τ")
        }
    };
    StabilityRow {
        tau_s: tau,
        averaging_factor: m,
        deviations: Deviations(deviations),
        adev_s_per_day: a.map(|v| v * 86_400.0),
        noise,
        noise_alpha: noise.map(Noise::alpha),
        noise_carried: carried,
        adev_edf,
        periodic,
        no_interval_reason,
    }
}

/// A series at possibly irregular times, put on a regular grid.
#[derive(Clone, Debug, Serialize)]
pub struct Gridded {
    /// One value every `tau0_s` from the first time; NaN where no sample
    /// fell (a gap).
    #[serde(skip)]
    pub data: Vec<f64>,
    /// The grid's spacing, s.
    pub tau0_s: f64,
    /// Grid points with no sample.
    pub missing: usize,
    /// Samples that shared a grid point with another (averaged).
    pub merged: usize,
}

/// Puts `values` at `times` (s, increasing) on a grid of spacing `tau0`
/// (default: the median interval), each sample at its nearest grid point
/// (several at one point averaged), so that gaps become NaN: SP 1065
/// section 5.14's gap markers. Refuses times that go back, a spacing
/// that is not positive, and a grid more than 100 times the samples (the
/// spacing is far shorter than the data's).
pub fn grid(times: &[f64], values: &[f64], tau0: Option<f64>) -> Result<Gridded, Refusal> {
    if times.len() != values.len() || times.len() < 3 {
        return Err(Refusal::data(format!(
            "a stability needs at least 3 samples, got {}",
            times.len().min(values.len())
        )));
    }
    if let Some(i) = (1..times.len())
        .find(|&i| times[i].partial_cmp(&times[i - 1]) != Some(std::cmp::Ordering::Greater))
    {
        return Err(Refusal::sample(
            "time",
            i,
            format!(
                "{} s is not after the previous {} s; sort by time",
                format_significant(times[i], 12),
                format_significant(times[i - 1], 12)
            ),
        ));
    }
    let tau0 = match tau0 {
        Some(t) => t,
        None => {
            let mut d: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
            let half = d.len() / 2;
            *d.select_nth_unstable_by(half, f64::total_cmp).1
        }
    };
    let tau0 = spacing(tau0)?;
    let span = (times[times.len() - 1] - times[0]) / tau0;
    if span.is_nan() || span > 100.0 * times.len() as f64 {
        return Err(Refusal::field(
            "tau0",
            format!(
                "{} s makes a grid of {} points for {} samples; give the data's own spacing",
                format_significant(tau0, 6),
                crate::analysis::count(span),
                times.len()
            ),
        ));
    }
    let n = span.round() as usize + 1;
    let (mut sum, mut count) = (vec![0.0; n], vec![0u32; n]);
    for (t, v) in times.iter().zip(values) {
        let k = (((t - times[0]) / tau0).round() as usize).min(n - 1);
        sum[k] += v;
        count[k] += 1;
    }
    let merged = count.iter().map(|&c| c.saturating_sub(1) as usize).sum();
    let missing = count.iter().filter(|&&c| c == 0).count();
    let data = sum
        .iter()
        .zip(&count)
        .map(|(s, &c)| if c == 0 { f64::NAN } else { s / c as f64 })
        .collect();
    Ok(Gridded {
        data,
        tau0_s: tau0,
        missing,
        merged,
    })
}
