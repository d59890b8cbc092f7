//! The rate model's terms, one table that every user of the model reads:
//! the columns a log may carry (their SI unit, the range a clock's room
//! holds, the hint when a value is outside it), how each term's
//! regressor is made, its coefficient's key and unit, the largest value
//! a pendulum gives it, and what a design predicts for it.
//!
//! A new term is a new row here: `analyse` builds its column, the choice
//! of terms judges it, the result carries its coefficient under `key`,
//! `log`'s text, figures and JSON and Python's `clock_log` show it.

use crate::analysis::Refusal;
use crate::compound::datasheet::{datasheet, Air};
use crate::compound::description::Design;
use crate::error::format_significant;

/// How a term's regressor is made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// Days from the log's mean time: the rate's drift.
    Time,
    /// A column of the log, averaged over each bin as the rate is.
    Column,
    /// A column of the log through a first-order lag whose time constant
    /// is fitted (a compensator follows the air late).
    LaggedColumn,
    /// The body tide's pendulum rate at the clock (`Δg/2g`, s/day): the
    /// coefficient is the admittance.
    Tide,
}

/// A column a log may carry beside its values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColumnSpec {
    /// Its name (the `LogInput` column's, the refusals').
    pub name: &'static str,
    /// The SI unit its values are given in.
    pub si_unit: &'static str,
    /// The range a clock's surroundings hold, in the SI unit: a value
    /// outside is a column in other units.
    pub range: (f64, f64),
    /// What to check when a value is outside.
    pub hint: &'static str,
}

/// What a design predicts for a coefficient at the log's mean weather.
pub type Predict = fn(&Design, &Air) -> Result<f64, Refusal>;

/// A term of the rate model.
#[derive(Clone, Copy, Debug)]
pub struct ModelTerm {
    /// Its name (`terms`, `parameters`, warnings).
    pub name: &'static str,
    /// Its label for people.
    pub label: &'static str,
    /// Where its regressor comes from.
    pub source: Source,
    /// The column it reads.
    pub column: Option<ColumnSpec>,
    /// The regressor's unit (the coefficient is per one of it) and its
    /// size in the column's SI unit: hPa is 100 Pa.
    pub variable_unit: &'static str,
    /// One `variable_unit` in the column's SI unit.
    pub variable_si: f64,
    /// The coefficient's key in `coefficients` and `standard_errors`.
    pub key: &'static str,
    /// The coefficient's unit for people.
    pub unit: &'static str,
    /// Why a coefficient is more than a pendulum gives, given the
    /// variable's mean (`None`: plausible).
    pub implausible: fn(f64, f64) -> Option<String>,
    /// What a design predicts for the coefficient at the log's mean
    /// weather (`None`: no prediction).
    pub predicted: Option<Predict>,
}

/// Every term, in the model's order after the constant.
pub const TERMS: [ModelTerm; 6] = [
    ModelTerm {
        name: "drift",
        label: "Drift",
        source: Source::Time,
        column: None,
        variable_unit: "day",
        variable_si: 86_400.0,
        key: "drift_s_per_day_per_day",
        unit: "s/day a day",
        implausible: |_, _| None,
        predicted: None,
    },
    ModelTerm {
        name: "temperature",
        label: "Temperature",
        source: Source::LaggedColumn,
        column: Some(ColumnSpec {
            name: "temperature",
            si_unit: "°C",
            range: (-60.0, 70.0),
            hint: "°C: is the column in °F or K?",
        }),
        variable_unit: "°C",
        variable_si: 1.0,
        key: "temperature_s_per_day_per_c",
        unit: "s/day per °C",
        implausible: |a, _| {
            (a.abs() > 2.0).then(|| {
                format!(
                    "{} s/day per °C is more than an uncompensated brass rod's 0.8: are the rates in s/day and the temperatures in °C?",
                    format_significant(a, 3)
                )
            })
        },
        predicted: Some(|d, air| {
            Ok(datasheet(d, None, air)?.temperature_coefficient_s_per_day_per_c)
        }),
    },
    ModelTerm {
        name: "pressure",
        label: "Pressure",
        source: Source::Column,
        column: Some(ColumnSpec {
            name: "pressure",
            si_unit: "Pa",
            range: (30_000.0, 110_000.0),
            hint: "Pa: is the column in hPa, kPa or inHg without its unit?",
        }),
        variable_unit: "hPa",
        variable_si: 100.0,
        key: "pressure_s_per_day_per_hpa",
        unit: "s/day per hPa",
        implausible: |a, _| {
            (a.abs() > 0.1).then(|| {
                format!(
                    "{} s/day per hPa is ten times what air does to any clock pendulum: are the pressures in hPa?",
                    format_significant(a, 3)
                )
            })
        },
        predicted: Some(|d, air| {
            Ok(datasheet(d, None, air)?.pressure_coefficient_s_per_day_per_hpa)
        }),
    },
    ModelTerm {
        name: "humidity",
        label: "Humidity",
        source: Source::Column,
        column: Some(ColumnSpec {
            name: "humidity",
            si_unit: "%",
            range: (0.0, 100.0),
            hint: "%: is the column a fraction (0 to 1)?",
        }),
        variable_unit: "%",
        variable_si: 1.0,
        key: "humidity_s_per_day_per_percent",
        unit: "s/day per % RH",
        implausible: |_, _| None,
        predicted: Some(|d, air| {
            // The air's rate one point of humidity wetter (or drier at
            // saturation), by difference.
            let h0 = air.humidity.unwrap_or(0.5);
            let at = |h: f64| {
                datasheet(
                    d,
                    None,
                    &Air {
                        humidity: Some(h),
                        ..*air
                    },
                )
                .map(|s| s.air_rate_s_per_day)
            };
            let (lo, hi) = if h0 + 0.01 <= 1.0 {
                (h0, h0 + 0.01)
            } else {
                (h0 - 0.01, h0)
            };
            Ok(at(hi)? - at(lo)?)
        }),
    },
    ModelTerm {
        name: "amplitude",
        label: "Amplitude",
        source: Source::Column,
        column: Some(ColumnSpec {
            name: "amplitude",
            si_unit: "rad",
            range: (0.0, std::f64::consts::FRAC_PI_2),
            hint: "rad: is the column in degrees, mrad or mm without its unit?",
        }),
        variable_unit: "°",
        variable_si: std::f64::consts::PI / 180.0,
        key: "amplitude_s_per_day_per_deg",
        unit: "s/day per degree of swing",
        // The circular error makes the rate fall with the amplitude by
        // 86400·A/8 s/day a radian (ΔT/T = A²/16); an escapement may add
        // to it or offset it, but not tenfold.
        implausible: |a, mean_deg| {
            let circular = 86_400.0 * mean_deg.to_radians() / 8.0 * 1f64.to_radians();
            (a.abs() > 10.0 * circular.max(0.01)).then(|| {
                format!(
                    "{} s/day per degree is more than ten times the circular error's {} at {}°: the amplitude hardly changes, or changes with something else that moves the rate (the bins cut a cycle of impulses?)",
                    format_significant(a, 3),
                    format_significant(-circular, 3),
                    format_significant(mean_deg, 3)
                )
            })
        },
        predicted: None,
    },
    ModelTerm {
        name: "tide",
        label: "Tide",
        source: Source::Tide,
        column: None,
        variable_unit: "s/day",
        variable_si: 1.0,
        key: "tide_admittance",
        unit: "admittance (1: the full body tide)",
        implausible: |_, _| None,
        predicted: None,
    },
];

impl PartialEq for ModelTerm {
    /// Terms are one row each of the table: equal when named alike.
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

/// The term named `name`.
pub fn term(name: &str) -> Option<&'static ModelTerm> {
    TERMS.iter().find(|t| t.name == name)
}

/// The columns a log may carry, in the table's order.
pub fn columns() -> impl Iterator<Item = &'static ColumnSpec> {
    TERMS.iter().filter_map(|t| t.column.as_ref())
}

/// The column named `name`, or a refusal listing those there are.
pub fn column_spec(name: &str) -> Result<&'static ColumnSpec, Refusal> {
    columns().find(|c| c.name == name).ok_or_else(|| {
        Refusal::data(format!(
            "'{name}' is not a column a log's model reads (it reads {})",
            columns().map(|c| c.name).collect::<Vec<_>>().join(", ")
        ))
    })
}
