//! The list of deviations [`stability()`](super::stability()) reports at
//! each averaging time. Every user of a deviation reads it from here: the
//! analysis computes each entry (and its interval where it has one), the
//! result's rows carry one value per entry under its key, and the command
//! line's table, CSV, figure and help, the page and Python take the
//! names, units and help from the entries. A new deviation is one file
//! with its function and its [`Deviation`], and one line in
//! [`DEVIATIONS`] (see [`mod@super::totdev`], [`mod@super::mtie`]).

use super::deviations::{mdev, oadev, ohdev, tdev};
use super::edf;

/// What a deviation measures, and so its unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DeviationUnit {
    /// A fractional frequency (dimensionless; × 86,400 for s/day).
    Fractional,
    /// A time, s.
    Seconds,
}

/// How a deviation's confidence interval is found: Greenhall's
/// equivalent degrees of freedom for the variance `edf`, with the noise
/// identified by differences up to `d_max` ([`super::noise`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IntervalRule {
    /// The variance the degrees of freedom are for.
    pub edf: edf::Estimator,
    /// The highest difference the noise identification may take (2 for
    /// the Allan family, 3 for Hadamard's).
    pub d_max: u32,
}

/// One deviation: its key, its name, what it is, its unit, its function
/// and how its interval is found.
#[derive(Clone, Copy, Debug)]
pub struct Deviation {
    /// The key of its value in the JSON and CSV (the interval's ends are
    /// `KEY_low` and `KEY_high`), with the unit in it where it has one.
    pub key: &'static str,
    /// Its name in tables and figures (Stable32's).
    pub name: &'static str,
    /// One sentence on what it is, for help and legends.
    pub help: &'static str,
    /// Fractional frequency or time.
    pub unit: DeviationUnit,
    /// Its value at `τ = m τ₀` from phase data `x` (NaN a gap), `None`
    /// where the series is too short.
    pub compute: fn(x: &[f64], tau0: f64, m: usize) -> Option<f64>,
    /// How its 68% interval is found; `None`: no interval.
    pub interval: Option<IntervalRule>,
}

impl PartialEq for Deviation {
    fn eq(&self, other: &Self) -> bool {
        self.key == other.key
    }
}

/// The overlapping Allan deviation (SP 1065 eq. 11): the analysis' noise
/// types, best τ and s/day read from it.
pub const ADEV: Deviation = Deviation {
    key: "adev",
    name: "ADEV",
    help: "the overlapping Allan deviation (SP 1065 eq. 11)",
    unit: DeviationUnit::Fractional,
    compute: oadev,
    interval: Some(IntervalRule {
        edf: edf::OADEV,
        d_max: 2,
    }),
};

/// The modified Allan deviation (SP 1065 eq. 14): tells white from
/// flicker phase noise.
pub const MDEV: Deviation = Deviation {
    key: "mdev",
    name: "MDEV",
    help: "the modified Allan deviation (SP 1065 eq. 14): tells white from flicker phase noise",
    unit: DeviationUnit::Fractional,
    compute: mdev,
    interval: Some(IntervalRule {
        edf: edf::MDEV,
        d_max: 2,
    }),
};

/// The time deviation `τ MDEV / √3` (SP 1065 eq. 15), s. Its key has no
/// unit suffix (the key `stability` has given it since the start; a time
/// deviation is always in seconds).
pub const TDEV: Deviation = Deviation {
    key: "tdev",
    name: "TDEV",
    help: "the time deviation τ·MDEV/√3 (SP 1065 eq. 15), s",
    unit: DeviationUnit::Seconds,
    compute: tdev,
    interval: None,
};

/// The overlapping Hadamard deviation (SP 1065 eq. 18): blind to a steady
/// drift of the rate.
pub const HDEV: Deviation = Deviation {
    key: "hdev",
    name: "HDEV",
    help:
        "the overlapping Hadamard deviation (SP 1065 eq. 18): blind to a steady drift of the rate",
    unit: DeviationUnit::Fractional,
    compute: ohdev,
    interval: Some(IntervalRule {
        edf: edf::OHDEV,
        d_max: 3,
    }),
};

/// Every deviation the analysis reports, in the order of the output's
/// keys and the table's columns.
pub const DEVIATIONS: &[Deviation] = &[
    ADEV,
    MDEV,
    TDEV,
    HDEV,
    super::totdev::TOTDEV,
    super::mtie::MTIE,
];
