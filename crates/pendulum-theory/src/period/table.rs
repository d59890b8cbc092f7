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
    /// Amplitudes from `from` to `to`, spaced in degrees: `steps` of them
    /// evenly (both ends included), or every `step` from `from` while
    /// within `to`, or, neither given, a round step (see [`grid`]).
    Range {
        /// The first, rad.
        from: f64,
        /// The last, rad.
        to: f64,
        /// How many.
        steps: Option<i64>,
        /// The spacing, rad.
        step: Option<f64>,
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
    /// The elastic share of the restoring torque of a pendulum hanging from
    /// a suspension spring (0 to 1; none or 0: a rigid pivot): its period
    /// at each amplitude is [`crate::suspension::period_ratio`]'s, and the
    /// rows have no power series (the seed's is a rigid pendulum's).
    pub elastic_share: Option<f64>,
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
    /// The power series (none on a suspension spring).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series: Option<SeriesRow>,
    /// The elastic share of a suspension spring (none: a rigid pivot).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elastic_share: Option<f64>,
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
            series: Some(SeriesRow {
                terms: a.series.terms,
                period_s: a.series_period_s(),
                relative_error: a.series.relative_error,
                truncation_bound: a.series.truncation_bound,
            }),
            elastic_share: None,
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

/// The amplitudes of `a`, checked: [`grid`] without the degrees.
pub fn amplitudes(a: Amplitudes) -> Result<Vec<Amplitude>, Refusal> {
    Ok(grid(a)?.into_iter().map(|(a, _)| a).collect())
}

/// `x` to 12 significant digits: a grid value as the user would write
/// it (15, not 14.999999999999998), far beyond any amplitude's meaning.
fn as_written(x: f64) -> f64 {
    format!("{x:.11e}").parse().unwrap_or(x)
}

/// The amplitudes of `a` with each one's value in degrees as written,
/// checked: a range has at least two rows and at most [`MAX_STEPS`],
/// spaced in degrees (the unit people type, so that 1°..10° gives 1, 2, …
/// 10). With neither `steps` nor `step`, the step is the largest round
/// one (1, 2 or 5 times a power of ten degrees) that gives at least
/// [`DEFAULT_STEPS`] rows, and the rows are `from`, the multiples of the
/// step between, and `to`: 1°..30° gives 1, 2, 4, … 28, 30; 5°..90° gives
/// 5, 10, … 90.
pub fn grid(a: Amplitudes) -> Result<Vec<(Amplitude, f64)>, Refusal> {
    let one = |r: f64| Amplitude::from_radians(r).map_err(|e| Refusal::input("amplitude", &e));
    let row = |deg: f64| -> Result<(Amplitude, f64), Refusal> {
        let deg = as_written(deg);
        Ok((one(deg.to_radians())?, deg))
    };
    let (from, to, steps, step) = match a {
        Amplitudes::One(r) => return Ok(vec![(one(r)?, as_written(r.to_degrees()))]),
        Amplitudes::Range {
            from,
            to,
            steps,
            step,
        } => (from, to, steps, step),
    };
    one(from)?;
    one(to)?;
    let (from_deg, to_deg) = (as_written(from.to_degrees()), as_written(to.to_degrees()));
    let span = to_deg - from_deg;
    let too_many = |n: f64| {
        Refusal::field(
            "step",
            format!(
                "gives {} rows; a table has at most {MAX_STEPS}",
                crate::error::format_significant(n, 6)
            ),
        )
    };
    let values: Vec<f64> = match (steps, step) {
        (Some(_), Some(_)) => {
            return Err(Refusal::field(
                "step",
                "give the number of rows (steps) or the spacing (step), not both",
            ))
        }
        (Some(steps), None) => {
            if !(2..=MAX_STEPS.into()).contains(&steps) {
                return Err(Refusal::field(
                    "steps",
                    format!(
                        "must be between 2 and {MAX_STEPS} with a range of amplitudes, got {steps}"
                    ),
                ));
            }
            let last = (steps - 1) as f64;
            (0..steps)
                .map(|i| from_deg + span * (i as f64 / last))
                .collect()
        }
        (None, Some(step)) => {
            let step_deg = as_written(step.to_degrees());
            if !(step_deg.is_finite() && step_deg > 0.0) {
                return Err(Refusal::field(
                    "step",
                    format!(
                        "must be a positive angle, got {}°",
                        crate::error::format_significant(step_deg, 6)
                    ),
                ));
            }
            // Rows from `from` towards `to`, the last within 1e-9 of a
            // step past it (so that 5°..90° by 5° ends on 90°).
            let n = (span.abs() / step_deg * (1.0 + 1e-9)).floor() + 1.0;
            if n > f64::from(MAX_STEPS) {
                return Err(too_many(n));
            }
            if n < 2.0 {
                return Err(Refusal::field(
                    "step",
                    "is wider than the range: a table has at least two rows",
                ));
            }
            let sign = if span < 0.0 { -1.0 } else { 1.0 };
            (0..n as i64)
                .map(|i| from_deg + sign * step_deg * i as f64)
                .collect()
        }
        (None, None) => round_steps(from_deg, to_deg),
    };
    values.into_iter().map(row).collect()
}

/// The default rows from `from` to `to` (degrees): `from`, the multiples
/// of the largest round step that gives at least [`DEFAULT_STEPS`] rows,
/// and `to`; [`DEFAULT_STEPS`] even rows when the range is empty.
fn round_steps(from: f64, to: f64) -> Vec<f64> {
    let span = (to - from).abs();
    let wanted = span / f64::from(DEFAULT_STEPS - 1);
    let even = || -> Vec<f64> {
        let last = f64::from(DEFAULT_STEPS - 1);
        (0..DEFAULT_STEPS)
            .map(|i| from + (to - from) * (f64::from(i) / last))
            .collect()
    };
    if !(wanted.is_finite() && wanted > 0.0) {
        return even();
    }
    let decade = 10f64.powf(wanted.log10().floor());
    let step = [5.0, 2.0, 1.0]
        .iter()
        .map(|m| m * decade)
        .find(|&s| s <= wanted * (1.0 + 1e-12))
        .unwrap_or(decade);
    let (low, high) = (from.min(to), from.max(to));
    let mut values = vec![low];
    let mut k = (low / step).floor() + 1.0;
    while k * step < high * (1.0 - 1e-12) - 1e-12 {
        let v = as_written(k * step);
        if v > low {
            values.push(v);
        }
        k += 1.0;
    }
    values.push(high);
    if to < from {
        values.reverse();
    }
    values
}

/// The rows of `input`.
///
/// # Examples
///
/// ```
/// use pendulum_theory::period::table::{table, Amplitudes, PeriodInput};
///
/// // The seconds pendulum swinging 2° either side, under standard gravity.
/// let a = 2f64.to_radians();
/// let rows = table(&PeriodInput {
///     length: 0.99362,
///     g: None,
///     amplitudes: Amplitudes::One(a),
///     series_terms: None,
///     elastic_share: None,
/// })?;
/// assert!((rows[0].small_angle_period_s - 2.0).abs() < 1e-5);
/// // The circular error, 86400 A²/16 s/day to first order: 6.58 s/day at 2°.
/// assert!((rows[0].circular_error_s_per_day - 86_400.0 * a * a / 16.0).abs() < 1e-3);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
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
    let share = crate::suspension::elastic_share(input.elastic_share)?;
    grid(input.amplitudes)?
        .into_iter()
        .map(|(a, degrees)| {
            let row = PeriodAnalysis::new(pendulum, a, terms)
                .map(|p| PeriodRow {
                    amplitude_deg: degrees,
                    ..PeriodRow::from(&p)
                })
                .map_err(|e| Refusal::input("series_terms", &e))?;
            Ok(if share > 0.0 {
                on_spring(row, share)
            } else {
                row
            })
        })
        .collect()
}

/// A rigid pendulum's row `row` for the same pendulum on a suspension
/// spring of elastic share `share`: the period ratio is
/// [`crate::suspension::period_ratio`]'s, the circular error `1 - 1/ratio`
/// and its slope per degree a central difference of ±1e-4 of the amplitude
/// (its truncation `1e-8` relative, rounding `1e-12`: the slope to 8
/// digits); no series.
fn on_spring(row: PeriodRow, share: f64) -> PeriodRow {
    use crate::suspension::period_ratio;
    let a = row.amplitude_rad;
    let ratio = period_ratio(a, share);
    let error = |r: f64| 1.0 - 1.0 / r;
    let h = 1e-4 * a;
    // At rest the circular error is flat.
    let slope = if a == 0.0 {
        0.0
    } else {
        (error(period_ratio(a + h, share)) - error(period_ratio(a - h, share))) / (2.0 * h)
    };
    let day = super::SECONDS_PER_DAY;
    let period = row.small_angle_period_s * ratio;
    PeriodRow {
        period_s: period,
        period_ratio: ratio,
        beats_per_hour: 7200.0 / period,
        circular_error: error(ratio),
        circular_error_s_per_day: day * error(ratio),
        circular_error_s_per_day_per_deg: day * slope * std::f64::consts::PI / 180.0,
        series: None,
        elastic_share: Some(share),
        ..row
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn degrees(a: Amplitudes) -> Vec<f64> {
        grid(a).unwrap().into_iter().map(|(_, d)| d).collect()
    }

    fn range(from: f64, to: f64, steps: Option<i64>, step: Option<f64>) -> Amplitudes {
        Amplitudes::Range {
            from: from.to_radians(),
            to: to.to_radians(),
            steps,
            step: step.map(f64::to_radians),
        }
    }

    /// The grids a teacher writes: by a step, by a count, and the round
    /// default, each value as written (no 14.999999999999998).
    #[test]
    fn grids_as_written() {
        let by_five: Vec<f64> = (1..=18).map(|i| 5.0 * f64::from(i)).collect();
        assert_eq!(degrees(range(5.0, 90.0, None, Some(5.0))), by_five);
        assert_eq!(degrees(range(5.0, 90.0, Some(18), None)), by_five);
        assert_eq!(degrees(range(5.0, 90.0, None, None)), by_five);
        let mut default = vec![1.0];
        default.extend((1..=15).map(|i| 2.0 * f64::from(i)));
        assert_eq!(degrees(range(1.0, 30.0, None, None)), default);
        let ten: Vec<f64> = (1..=10).map(f64::from).collect();
        assert_eq!(degrees(range(1.0, 10.0, None, None)), ten);
        assert_eq!(degrees(range(1.0, 10.0, Some(10), None)), ten);
        // Downwards, and a step that does not land on the end.
        assert_eq!(
            degrees(range(30.0, 20.0, None, Some(5.0))),
            [30.0, 25.0, 20.0]
        );
        assert_eq!(
            degrees(range(1.0, 30.0, None, Some(10.0))),
            [1.0, 11.0, 21.0]
        );
        assert!(grid(range(1.0, 30.0, Some(3), Some(1.0))).is_err());
        assert!(grid(range(1.0, 30.0, None, Some(0.0))).is_err());
        assert!(grid(range(1.0, 30.0, None, Some(40.0))).is_err());
        assert!(grid(range(1.0, 90.0, None, Some(1e-6))).is_err());
    }

    proptest! {
        /// Any range by any step: rows from the first amplitude, a step
        /// apart, never past the last, each written with at most 12
        /// significant digits; the default has at least the default rows.
        #[test]
        fn steps_stay_in_the_range(from in 0.5_f64..80.0, span in 1.0_f64..90.0, step in 0.01_f64..10.0) {
            let to = (from + span).min(179.0);
            if let Ok(rows) = grid(range(from, to, None, Some(step))) {
                for pair in rows.windows(2) {
                    prop_assert!((pair[1].1 - pair[0].1 - step).abs() < 1e-9 * to);
                }
                prop_assert!(rows.last().unwrap().1 <= to * (1.0 + 1e-9));
                for (_, d) in &rows {
                    prop_assert_eq!(*d, format!("{d:.11e}").parse::<f64>().unwrap());
                }
            }
            let rows = grid(range(from, to, None, None)).unwrap();
            prop_assert!(rows.len() >= DEFAULT_STEPS as usize);
            prop_assert!(rows.len() <= 3 * DEFAULT_STEPS as usize);
        }
    }
}
