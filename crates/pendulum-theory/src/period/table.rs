//! The period as one analysis: a pendulum at one amplitude, or a table
//! over a range of amplitudes, every row the seed's section 1-6 (exact
//! period, small-angle period, circular error, the power series to some
//! terms). The command line's `period` and Python's `period_table` are
//! this call: the steps of a range, their limits and the default number
//! of series terms live here.

use super::PeriodAnalysis;
use crate::analysis::{require_finite, Refusal};
use crate::pendulum::{Amplitude, Pendulum, STANDARD_GRAVITY};
use serde::Serialize;

/// Rows of a table when not given.
pub const DEFAULT_STEPS: u32 = 10;
/// The most rows a table may have.
pub const MAX_STEPS: u32 = 1_000_000;
/// Terms of the power series when not given.
pub const DEFAULT_SERIES_TERMS: u32 = 3;

/// The amplitudes asked for, rad.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Amplitudes {
    /// One amplitude.
    One(f64),
    /// `steps` amplitudes evenly spaced in degrees from `from` to `to`,
    /// both included.
    Range {
        /// The first, rad.
        from: f64,
        /// The last, rad.
        to: f64,
        /// How many (default [`DEFAULT_STEPS`]).
        steps: Option<i64>,
    },
}

/// A period question.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PeriodInput {
    /// The (equivalent) length, m.
    pub length: f64,
    /// Gravity, m/s² (default standard gravity).
    pub g: Option<f64>,
    /// The amplitudes.
    pub amplitudes: Amplitudes,
    /// Terms of the series (default [`DEFAULT_SERIES_TERMS`]).
    pub series_terms: Option<i64>,
}

/// The series' estimate of one row.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SeriesRow {
    /// Terms kept.
    pub terms: u32,
    /// The period the truncated series gives, s.
    pub period_s: f64,
    /// `(T_series - T)/T`.
    pub relative_error: f64,
    /// The bound on the truncation from the first dropped term.
    pub truncation_bound: f64,
}

/// One amplitude's row.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PeriodRow {
    /// Length, m.
    pub length_m: f64,
    /// Gravity, m/s².
    pub g_m_s2: f64,
    /// Amplitude, rad.
    pub amplitude_rad: f64,
    /// Amplitude, degrees.
    pub amplitude_deg: f64,
    /// The exact period, s.
    pub period_s: f64,
    /// The small-angle period, s.
    pub small_angle_period_s: f64,
    /// `T/T0`.
    pub period_ratio: f64,
    /// Beats per hour.
    pub beats_per_hour: f64,
    /// `1 - T0/T`.
    pub circular_error: f64,
    /// What the clock loses a day against a small-angle one, s/day.
    pub circular_error_s_per_day: f64,
    /// Its change per degree of amplitude.
    pub circular_error_s_per_day_per_deg: f64,
    /// The power series.
    pub series: SeriesRow,
}

impl From<&PeriodAnalysis> for PeriodRow {
    fn from(a: &PeriodAnalysis) -> Self {
        Self {
            length_m: a.pendulum.length_m(),
            g_m_s2: a.pendulum.g_m_s2(),
            amplitude_rad: a.amplitude.radians(),
            amplitude_deg: a.amplitude.degrees(),
            period_s: a.period_s,
            small_angle_period_s: a.small_angle_period_s,
            period_ratio: a.period_ratio,
            beats_per_hour: a.beats_per_hour,
            circular_error: a.circular_error,
            circular_error_s_per_day: a.circular_error_s_per_day(),
            circular_error_s_per_day_per_deg: a.circular_error_s_per_day_per_deg(),
            series: SeriesRow {
                terms: a.series.terms,
                period_s: a.series_period_s(),
                relative_error: a.series.relative_error,
                truncation_bound: a.series.truncation_bound,
            },
        }
    }
}

/// The pendulum of `length` m at `g` (default standard gravity), each
/// refusal named.
pub fn pendulum(
    length: f64,
    g: Option<f64>,
    length_field: &'static str,
) -> Result<Pendulum, Refusal> {
    let g = require_finite("g", g.unwrap_or(STANDARD_GRAVITY))?;
    Pendulum::new(length, g).map_err(|e| match e.quantity {
        crate::error::Quantity::Gravity => Refusal::input("g", &e),
        _ => Refusal::input(length_field, &e),
    })
}

/// The amplitudes of `a`, checked: a range has at least two rows and at
/// most [`MAX_STEPS`], spaced in degrees (the unit people type, so that
/// 1°..10° gives 1, 2, … 10).
pub fn amplitudes(a: Amplitudes) -> Result<Vec<Amplitude>, Refusal> {
    let one = |r: f64| Amplitude::from_radians(r).map_err(|e| Refusal::input("amplitude", &e));
    match a {
        Amplitudes::One(r) => Ok(vec![one(r)?]),
        Amplitudes::Range { from, to, steps } => {
            let steps = steps.unwrap_or(DEFAULT_STEPS.into());
            if !(2..=MAX_STEPS.into()).contains(&steps) {
                return Err(Refusal::field(
                    "steps",
                    format!(
                        "must be between 2 and {MAX_STEPS} with a range of amplitudes, got {steps}"
                    ),
                ));
            }
            one(from)?;
            one(to)?;
            let (from_deg, to_deg) = (from.to_degrees(), to.to_degrees());
            let last = (steps - 1) as f64;
            (0..steps)
                .map(|i| one((from_deg + (to_deg - from_deg) * (i as f64 / last)).to_radians()))
                .collect()
        }
    }
}

/// The rows of `input`.
pub fn table(input: &PeriodInput) -> Result<Vec<PeriodRow>, Refusal> {
    let pendulum = pendulum(input.length, input.g, "length")?;
    let terms = input.series_terms.unwrap_or(DEFAULT_SERIES_TERMS.into());
    if terms < 1 {
        return Err(Refusal::field(
            "series_terms",
            format!("must be at least 1, got {terms}"),
        ));
    }
    // Beyond u32 the series refuses it as above its maximum.
    let terms = u32::try_from(terms).unwrap_or(u32::MAX);
    amplitudes(input.amplitudes)?
        .into_iter()
        .map(|a| {
            PeriodAnalysis::new(pendulum, a, terms)
                .map(|p| PeriodRow::from(&p))
                .map_err(|e| Refusal::input("series_terms", &e))
        })
        .collect()
}
