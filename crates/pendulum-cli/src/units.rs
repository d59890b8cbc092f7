//! Quantities with units on the command line: `994mm`, `3deg`, `1.5ms`.
//!
//! A value is a decimal number, optionally followed (with or without a
//! space) by a unit. A bare number is SI, except angles, which people type
//! in degrees. The result is always SI (radians for angles). The parser is
//! hand-written so that every refusal can say exactly what was wrong.

use std::fmt;

/// What kind of quantity an argument wants.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    /// Metres.
    Length,
    /// Radians (bare numbers are degrees).
    Angle,
    /// Seconds.
    Time,
    /// Kilograms.
    Mass,
    /// Metres per second squared.
    Acceleration,
    /// Newton metres.
    Torque,
    /// Joules.
    Energy,
    /// Pascals.
    Pressure,
    /// Degrees Celsius (an affine scale: kelvin and °F carry an offset).
    Temperature,
    /// A pure ratio: a rate (s/day, ppm), a humidity (%), a fraction.
    Ratio,
    /// Hertz.
    Frequency,
    /// Beats per hour (a clock's beat rate).
    BeatRate,
    /// Decibels.
    Level,
}

use pendulum_data::units::{unit, Unit, PRESSURE};

const LENGTH: &[Unit] = &[
    unit(&["m"], 1.0),
    unit(&["cm"], 0.01),
    unit(&["mm"], 0.001),
    unit(&["um", "µm"], 1e-6),
    unit(&["km"], 1000.0),
    unit(&["in", "inch", "\""], 0.0254),
    unit(&["ft", "foot", "feet"], 0.3048),
];

const ANGLE: &[Unit] = &[
    unit(
        &["deg", "°", "degree", "degrees"],
        std::f64::consts::PI / 180.0,
    ),
    unit(&["rad"], 1.0),
    unit(&["mrad"], 0.001),
    unit(&["arcmin", "′"], std::f64::consts::PI / 10_800.0),
    unit(&["arcsec", "″"], std::f64::consts::PI / 648_000.0),
];

const TIME: &[Unit] = &[
    unit(&["s", "sec"], 1.0),
    unit(&["ms"], 0.001),
    unit(&["us", "µs"], 1e-6),
    unit(&["ns"], 1e-9),
    unit(&["min"], 60.0),
    unit(&["h", "hour", "hours"], 3600.0),
    unit(&["day", "days", "d"], 86_400.0),
    unit(&["week", "weeks"], 604_800.0),
    // The Julian year, 365.25 days.
    unit(&["year", "years", "yr"], 31_557_600.0),
];

const MASS: &[Unit] = &[
    unit(&["kg"], 1.0),
    unit(&["g"], 0.001),
    unit(&["mg"], 1e-6),
    unit(&["lb"], 0.453_592_37),
];

const ACCELERATION: &[Unit] = &[
    unit(&["m/s^2", "m/s2", "m/s²"], 1.0),
    unit(&["cm/s^2", "cm/s2", "gal", "Gal"], 0.01),
];

const TORQUE: &[Unit] = &[
    unit(&["N m", "Nm", "N·m", "N*m"], 1.0),
    unit(&["mN m", "mNm", "mN·m"], 1e-3),
    unit(&["uN m", "uNm", "µN m", "µNm", "µN·m"], 1e-6),
];

const ENERGY: &[Unit] = &[
    unit(&["J"], 1.0),
    unit(&["mJ"], 1e-3),
    unit(&["uJ", "µJ"], 1e-6),
];

const TEMPERATURE: &[Unit] = &[
    unit(&["°C", "C", "degC", "celsius"], 1.0),
    Unit {
        names: &["K", "kelvin"],
        si: 1.0,
        offset: -273.15,
    },
    Unit {
        names: &["°F", "F", "degF"],
        si: 5.0 / 9.0,
        offset: -160.0 / 9.0,
    },
];

const RATIO: &[Unit] = &[
    unit(&["%", "percent"], 0.01),
    unit(&["ppm"], 1e-6),
    unit(&["ppb"], 1e-9),
    unit(&["s/day", "s/d", "sec/day"], 1.0 / 86_400.0),
    unit(&["s/week"], 1.0 / 604_800.0),
];

const FREQUENCY: &[Unit] = &[unit(&["Hz", "/s", "fps"], 1.0), unit(&["kHz"], 1000.0)];

const BEAT_RATE: &[Unit] = &[unit(&["bph", "A/h", "beats/h", "/h"], 1.0)];

const LEVEL: &[Unit] = &[unit(&["dB"], 1.0)];

impl Dimension {
    fn units(self) -> &'static [Unit] {
        match self {
            Dimension::Length => LENGTH,
            Dimension::Angle => ANGLE,
            Dimension::Time => TIME,
            Dimension::Mass => MASS,
            Dimension::Acceleration => ACCELERATION,
            Dimension::Torque => TORQUE,
            Dimension::Energy => ENERGY,
            Dimension::Pressure => PRESSURE,
            Dimension::Temperature => TEMPERATURE,
            Dimension::Ratio => RATIO,
            Dimension::Frequency => FREQUENCY,
            Dimension::BeatRate => BEAT_RATE,
            Dimension::Level => LEVEL,
        }
    }

    /// The factor applied to a bare number.
    fn bare_factor(self) -> f64 {
        match self {
            Dimension::Angle => std::f64::consts::PI / 180.0,
            _ => 1.0,
        }
    }

    fn noun(self) -> &'static str {
        match self {
            Dimension::Length => "a length",
            Dimension::Angle => "an angle",
            Dimension::Time => "a time",
            Dimension::Mass => "a mass",
            Dimension::Acceleration => "an acceleration",
            Dimension::Torque => "a torque",
            Dimension::Energy => "an energy",
            Dimension::Pressure => "a pressure",
            Dimension::Temperature => "a temperature",
            Dimension::Ratio => "a ratio",
            Dimension::Frequency => "a frequency",
            Dimension::BeatRate => "a beat rate",
            Dimension::Level => "a level",
        }
    }

    fn unit_list(self) -> String {
        let names: Vec<&str> = self.units().iter().map(|u| u.names[0]).collect();
        names.join(", ")
    }

    const ALL: [Dimension; 13] = [
        Dimension::Length,
        Dimension::Angle,
        Dimension::Time,
        Dimension::Mass,
        Dimension::Acceleration,
        Dimension::Torque,
        Dimension::Energy,
        Dimension::Pressure,
        Dimension::Temperature,
        Dimension::Ratio,
        Dimension::Frequency,
        Dimension::BeatRate,
        Dimension::Level,
    ];
}

/// Why a value could not be read.
#[derive(Clone, Debug, PartialEq)]
pub enum UnitError {
    /// Nothing was given.
    Empty,
    /// No number at the start.
    NotANumber(String),
    /// A number too large for a double.
    NotFinite(String),
    /// A unit nobody knows.
    UnknownUnit {
        /// The whole text.
        text: String,
        /// The unit part.
        unit: String,
        /// What was wanted.
        wanted: Dimension,
    },
    /// A ratio in a unit other than % where only % is meaningful.
    NotPercent(String),
    /// A unit of another kind of quantity.
    WrongDimension {
        /// The whole text.
        text: String,
        /// What the unit measures.
        found: Dimension,
        /// What was wanted.
        wanted: Dimension,
    },
}

impl fmt::Display for UnitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UnitError::Empty => write!(f, "is empty; give a number (with its unit where one is wanted)"),
            UnitError::NotPercent(text) => write!(
                f,
                "'{text}' is not a percentage; give it in % (60% or a bare 60)"
            ),
            UnitError::NotANumber(text) => write!(
                f,
                "'{text}' is not a number; give a finite number (with a unit where one is wanted, like 0.994m or 3deg)"
            ),
            // The library's words for the same value given from Python.
            UnitError::NotFinite(text) => {
                let what = if text.to_ascii_lowercase().contains("nan") {
                    "a value that is not a number"
                } else {
                    "an infinite value"
                };
                write!(f, "must be a finite number, got {what}")
            }
            UnitError::UnknownUnit { text, unit, wanted } => write!(
                f,
                "unknown unit '{unit}' in '{text}'; {} takes {}",
                wanted.noun(),
                wanted.unit_list()
            ),
            UnitError::WrongDimension {
                text,
                found,
                wanted,
            } => write!(
                f,
                "'{text}' is {}, but {} is wanted ({})",
                found.noun(),
                wanted.noun(),
                wanted.unit_list()
            ),
        }
    }
}

/// Refuses `nan`, `inf` and `infinity` (any case, signed, with or without
/// a unit) as the value they name, not as text that is not a number: the
/// same sentence as the library gives for the value from Python.
fn non_finite_word(text: &str) -> Result<(), UnitError> {
    let word: String = text
        .trim_start_matches(['+', '-'])
        .chars()
        .take_while(|c| c.is_ascii_alphabetic())
        .collect::<String>()
        .to_ascii_lowercase();
    if matches!(word.as_str(), "nan" | "inf" | "infinity") {
        Err(UnitError::NotFinite(text.to_string()))
    } else {
        Ok(())
    }
}

/// Reads `text` as a quantity of `dimension`, in SI.
pub fn parse_quantity(text: &str, dimension: Dimension) -> Result<f64, UnitError> {
    let (trimmed, number, unit) = split_quantity(text, dimension)?;
    let value = match unit {
        Some(u) => number * u.si + u.offset,
        None => number * dimension.bare_factor(),
    };
    finite(trimmed, value)
}

/// `text` trimmed, its number, and the unit written after it (`None`: a
/// bare number), each refusal in our words: the reading every quantity
/// shares.
fn split_quantity(
    text: &str,
    dimension: Dimension,
) -> Result<(&str, f64, Option<&'static Unit>), UnitError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(UnitError::Empty);
    }
    non_finite_word(trimmed)?;
    let split = number_prefix_len(trimmed);
    if split == 0 {
        return Err(UnitError::NotANumber(trimmed.to_string()));
    }
    let number: f64 = trimmed[..split]
        .parse()
        .map_err(|_| UnitError::NotANumber(trimmed.to_string()))?;
    let unit = unit_of(trimmed, trimmed[split..].trim(), dimension)?;
    Ok((trimmed, number, unit))
}

/// `value`, or the refusal of a value too large for a double.
fn finite(text: &str, value: f64) -> Result<f64, UnitError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(UnitError::NotFinite(text.to_string()))
    }
}

/// Reads a plain number (no unit), as for `ζ` or `Q`.
pub fn parse_number(text: &str) -> Result<f64, UnitError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(UnitError::Empty);
    }
    non_finite_word(trimmed)?;
    let split = number_prefix_len(trimmed);
    if split == 0 || split != trimmed.len() {
        return Err(UnitError::NotANumber(trimmed.to_string()));
    }
    let value: f64 = trimmed
        .parse()
        .map_err(|_| UnitError::NotANumber(trimmed.to_string()))?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(UnitError::NotFinite(trimmed.to_string()))
    }
}

/// Reads `from..to` (both with units) as a pair of SI values.
pub fn parse_range(text: &str, dimension: Dimension) -> Option<Result<(f64, f64), UnitError>> {
    let (from, to) = text.split_once("..")?;
    Some(parse_quantity(from, dimension).and_then(|a| Ok((a, parse_quantity(to, dimension)?))))
}

/// The unit `unit` names (`None`: no unit was written).
fn unit_of(
    text: &str,
    unit: &str,
    dimension: Dimension,
) -> Result<Option<&'static Unit>, UnitError> {
    if unit.is_empty() {
        return Ok(None);
    }
    if let Some(u) = lookup(dimension, unit) {
        return Ok(Some(u));
    }
    match Dimension::ALL.iter().find(|d| lookup(**d, unit).is_some()) {
        Some(&found) => Err(UnitError::WrongDimension {
            text: text.to_string(),
            found,
            wanted: dimension,
        }),
        None => Err(UnitError::UnknownUnit {
            text: text.to_string(),
            unit: unit.to_string(),
            wanted: dimension,
        }),
    }
}

/// Reads `text` as a quantity of `dimension` and gives it in the unit
/// named `bare`, which is also what a bare number means (`""`: a pure
/// number, for a ratio). A value written in `bare` itself, or bare, is the
/// number as written, bit for bit; another unit is converted through the
/// ratio of the two units' sizes.
pub fn parse_in(text: &str, dimension: Dimension, bare: &str) -> Result<f64, UnitError> {
    let (trimmed, number, unit) = split_quantity(text, dimension)?;
    let (bare_si, bare_offset) = match lookup(dimension, bare) {
        Some(u) => (u.si, u.offset),
        None => (1.0, 0.0),
    };
    let value = match unit {
        None => number,
        Some(u) if u.names.contains(&bare) => number,
        Some(u) => (number * u.si + u.offset - bare_offset) / bare_si,
    };
    finite(trimmed, value)
}

fn lookup(dimension: Dimension, unit: &str) -> Option<&'static Unit> {
    dimension.units().iter().find(|u| u.names.contains(&unit))
}

/// Length of the longest prefix of the form `[+-]?(d+[.d*]|.d+)([eE][+-]?d+)?`.
fn number_prefix_len(text: &str) -> usize {
    let bytes = text.as_bytes();
    let mut i = 0;
    if matches!(bytes.first(), Some(b'+' | b'-')) {
        i += 1;
    }
    let digits_from = |mut j: usize| {
        while j < bytes.len() && bytes[j].is_ascii_digit() {
            j += 1;
        }
        j
    };
    let int_end = digits_from(i);
    let mut end = int_end;
    let mut has_digits = int_end > i;
    if end < bytes.len() && bytes[end] == b'.' {
        let frac_end = digits_from(end + 1);
        has_digits |= frac_end > end + 1;
        end = frac_end;
    }
    if !has_digits {
        return 0;
    }
    if end < bytes.len() && matches!(bytes[end], b'e' | b'E') {
        let mut j = end + 1;
        if j < bytes.len() && matches!(bytes[j], b'+' | b'-') {
            j += 1;
        }
        let exp_end = digits_from(j);
        if exp_end > j {
            end = exp_end;
        }
    }
    end
}

impl std::error::Error for UnitError {}

/// A value the command line refused, in words of our own (for a type whose
/// refusal is not a [`UnitError`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ValueError(pub String);

impl fmt::Display for ValueError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ValueError {}

/// Declares a quantity the command line takes: a newtype over its SI
/// value that clap parses with [`parse_quantity`] (or [`parse_number`]),
/// so that a value clap refuses names its flag (see
/// [`crate::error::one_line_clap_error`]).
/// A value parsed from the command line, in the unit its type names.
pub trait Quantity: Copy {
    /// The value.
    fn value(self) -> f64;
}

/// The value given, or `default` (the library's) when none was.
pub fn or_default<Q: Quantity>(given: Option<Q>, default: f64) -> f64 {
    given.map_or(default, Quantity::value)
}

macro_rules! quantity_type {
    ($(#[$doc:meta])* $name:ident, $parse:expr) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct $name(pub f64);

        impl Quantity for $name {
            fn value(self) -> f64 {
                self.0
            }
        }

        impl std::str::FromStr for $name {
            type Err = UnitError;
            fn from_str(text: &str) -> Result<Self, UnitError> {
                let parse: fn(&str) -> Result<f64, UnitError> = $parse;
                parse(text).map($name)
            }
        }
    };
}

quantity_type!(
    /// A length, m (`994mm`, `39.1in`; a bare number is metres).
    Length,
    |t| parse_quantity(t, Dimension::Length)
);
quantity_type!(
    /// An angle, rad (`3deg`, `0.05rad`; a bare number is degrees).
    Angle,
    |t| parse_quantity(t, Dimension::Angle)
);
quantity_type!(
    /// A time, s (`2s`, `1.5ms`, `7day`; a bare number is seconds).
    Time,
    |t| parse_quantity(t, Dimension::Time)
);
quantity_type!(
    /// A mass, kg (`5kg`, `250g`; a bare number is kilograms).
    Mass,
    |t| parse_quantity(t, Dimension::Mass)
);
quantity_type!(
    /// An acceleration, m/s² (a bare number is m/s²).
    Acceleration,
    |t| parse_quantity(t, Dimension::Acceleration)
);
quantity_type!(
    /// A plain number (a ratio, a count of beats an hour, a decibel level).
    Number,
    parse_number
);
quantity_type!(
    /// A clock's rate, s/day (`+12s/day`, `-30 s/d`, `50ppm`; a bare
    /// number is s/day).
    RatePerDay,
    |t| parse_in(t, Dimension::Ratio, "s/day")
);
quantity_type!(
    /// How fast a rate changes, s/day an hour (`2s/day/h`; a bare number
    /// is s/day an hour).
    RateChange,
    |t| {
        let t = t.trim();
        let per_hour = ["/h", "/hour", " an hour", " per hour"]
            .iter()
            .find_map(|u| t.strip_suffix(u))
            .unwrap_or(t);
        parse_in(per_hour, Dimension::Ratio, "s/day")
    }
);
quantity_type!(
    /// A small ratio in parts per million (`20ppm`, `1.7s/day`; a bare
    /// number is ppm).
    Ppm,
    |t| parse_in(t, Dimension::Ratio, "ppm")
);
quantity_type!(
    /// A percentage (`60%`; a bare number is percent): only in % (a
    /// humidity in s/day or ppm is a mistake, not a conversion).
    Percent,
    |t| {
        let value = parse_in(t, Dimension::Ratio, "%").map_err(|e| match e {
            UnitError::WrongDimension { .. } | UnitError::UnknownUnit { .. } => {
                UnitError::NotPercent(t.trim().to_string())
            }
            other => other,
        })?;
        match split_quantity(t, Dimension::Ratio)?.2 {
            Some(u) if !u.names.contains(&"%") => Err(UnitError::NotPercent(t.trim().to_string())),
            _ => Ok(value),
        }
    }
);
quantity_type!(
    /// A fraction (`0.05`, `5%`).
    Fraction,
    |t| parse_in(t, Dimension::Ratio, "")
);
quantity_type!(
    /// A short time in milliseconds (`1.5ms`, `800us`; a bare number is
    /// milliseconds).
    Milliseconds,
    |t| parse_in(t, Dimension::Time, "ms")
);
quantity_type!(
    /// A pressure in hectopascals (`1000hPa`, `29.9inHg`, `101.3kPa`; a
    /// bare number is hPa, a barometer's unit).
    Hectopascals,
    |t| parse_in(t, Dimension::Pressure, "hPa")
);
quantity_type!(
    /// A temperature in °C (`25°C`, `298K`, `77°F`; a bare number is °C).
    Celsius,
    |t| parse_in(t, Dimension::Temperature, "°C")
);
quantity_type!(
    /// A frequency in hertz (`30fps`, `48kHz`; a bare number is Hz).
    Hertz,
    |t| parse_in(t, Dimension::Frequency, "Hz")
);
quantity_type!(
    /// A beat rate in beats per hour (`3600bph`; a bare number is bph).
    BeatsPerHour,
    |t| parse_in(t, Dimension::BeatRate, "bph")
);
quantity_type!(
    /// A level in decibels (`20dB`; a bare number is dB).
    Decibels,
    |t| parse_in(t, Dimension::Level, "dB")
);
quantity_type!(
    /// A thread's count per inch (`36tpi`; a bare number is threads an
    /// inch).
    ThreadsPerInch,
    |t| {
        let t = t.trim();
        parse_number(t.strip_suffix("tpi").unwrap_or(t).trim())
    }
);

/// A sample rate, a whole number of hertz (`48000`, `48kHz`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleRate(pub u32);

impl std::str::FromStr for SampleRate {
    type Err = ValueError;
    fn from_str(text: &str) -> Result<Self, ValueError> {
        let hz =
            parse_in(text, Dimension::Frequency, "Hz").map_err(|e| ValueError(e.to_string()))?;
        if hz.fract() != 0.0 || !(0.0..=f64::from(u32::MAX)).contains(&hz) {
            return Err(ValueError(format!(
                "must be a whole number of samples a second (48000, 44.1kHz), got '{}'",
                text.trim()
            )));
        }
        Ok(SampleRate(hz as u32))
    }
}

/// An escapement's drive: a torque (N m), or an energy per beat (J).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drive(pub pendulum_theory::clock::escapement::spec::Drive);

impl std::str::FromStr for Drive {
    type Err = ValueError;
    fn from_str(text: &str) -> Result<Self, ValueError> {
        use pendulum_theory::clock::escapement::spec::Drive::{Energy, Torque};
        match (
            parse_quantity(text, Dimension::Torque),
            parse_quantity(text, Dimension::Energy),
        ) {
            (Ok(t), _) => Ok(Drive(Torque(t))),
            (_, Ok(e)) => Ok(Drive(Energy(e))),
            (Err(e @ UnitError::NotFinite(_)), _) => Err(ValueError(e.to_string())),
            _ => Err(ValueError(format!(
                "'{text}' is neither a torque (2e-4Nm, 0.2mNm) nor an energy per beat (20uJ, 0.02mJ)"
            ))),
        }
    }
}

/// How far out of beat: a beat error (`20ms`) or the escapement's offset
/// from the pendulum's rest (`0.3deg`). A bare number is refused: a
/// timegrapher's milliseconds and a clockmaker's degrees are both usual.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BeatError(pub pendulum_theory::clock::analysis::BeatError);

impl std::str::FromStr for BeatError {
    type Err = ValueError;
    fn from_str(text: &str) -> Result<Self, ValueError> {
        use pendulum_theory::clock::analysis::BeatError::{Angle, Time};
        if parse_number(text.trim()).is_ok() {
            return Err(ValueError(format!(
                "give a unit: a beat error ({}ms) or the escapement's offset from the rest ({}deg)",
                text.trim(),
                text.trim()
            )));
        }
        match (
            parse_quantity(text, Dimension::Time),
            parse_quantity(text, Dimension::Angle),
        ) {
            (Ok(t), _) => Ok(BeatError(Time(t))),
            (_, Ok(a)) => Ok(BeatError(Angle(a))),
            (Err(e @ UnitError::NotFinite(_)), _) => Err(ValueError(e.to_string())),
            _ => Err(ValueError(format!(
                "'{text}' is neither a beat error (20ms) nor an angle out of beat (0.3deg)"
            ))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn examples_from_the_issue() {
        let l = |t| parse_quantity(t, Dimension::Length).unwrap();
        assert_eq!(l("994mm"), 0.994);
        assert!((l("99.4cm") - 0.994).abs() < 1e-15);
        assert_eq!(l("0.994m"), 0.994);
        assert!((l("39.1in") - 0.99314).abs() < 1e-12);
        let a = |t| parse_quantity(t, Dimension::Angle).unwrap();
        assert_eq!(a("3deg"), 3.0_f64.to_radians());
        assert_eq!(a("3°"), a("3"));
        assert_eq!(a("0.05rad"), 0.05);
        assert!((a("30arcmin") - 0.5_f64.to_radians()).abs() < 1e-16);
        let t = |s| parse_quantity(s, Dimension::Time).unwrap();
        assert_eq!(t("2s"), 2.0);
        assert_eq!(t("1.5ms"), 0.0015);
        assert_eq!(t("3h"), 10_800.0);
        assert_eq!(t("1day"), 86_400.0);
        let m = |s| parse_quantity(s, Dimension::Mass).unwrap();
        assert_eq!(m("1kg"), 1.0);
        assert_eq!(m("500g"), 0.5);
        assert_eq!(
            parse_quantity("-33.87", Dimension::Angle).unwrap(),
            (-33.87_f64).to_radians()
        );
        assert_eq!(parse_quantity("-1", Dimension::Length).unwrap(), -1.0);
        assert_eq!(
            parse_quantity("3 deg", Dimension::Angle).unwrap(),
            a("3deg")
        );
        assert_eq!(parse_quantity("1e-3m", Dimension::Length).unwrap(), 1e-3);
    }

    #[test]
    fn refusals_say_why() {
        let err = parse_quantity("3parsecs", Dimension::Length).unwrap_err();
        assert!(matches!(err, UnitError::UnknownUnit { .. }));
        assert!(err.to_string().contains("'parsecs'"));
        let err = parse_quantity("3m", Dimension::Angle).unwrap_err();
        assert_eq!(
            err.to_string(),
            "'3m' is a length, but an angle is wanted (deg, rad, mrad, arcmin, arcsec)"
        );
        assert!(matches!(
            parse_quantity("nan", Dimension::Length),
            Err(UnitError::NotFinite(_))
        ));
        assert!(matches!(
            parse_quantity("-inf m", Dimension::Length),
            Err(UnitError::NotFinite(_))
        ));
        assert_eq!(
            parse_quantity("NaN", Dimension::Length)
                .unwrap_err()
                .to_string(),
            "must be a finite number, got a value that is not a number"
        );
        assert!(matches!(
            parse_quantity("1e999", Dimension::Length),
            Err(UnitError::NotFinite(_))
        ));
        assert_eq!(parse_quantity("", Dimension::Length), Err(UnitError::Empty));
        assert!(parse_quantity("-", Dimension::Length).is_err());
        assert!(parse_quantity(".", Dimension::Length).is_err());
    }

    /// The flags whose help names a unit other than SI: a bare number is
    /// that unit, the same unit written is the number bit for bit, and
    /// other units convert (figures from NIST SP 811, appendix B).
    #[test]
    fn values_in_a_named_unit() {
        let hpa = |t| parse_in(t, Dimension::Pressure, "hPa").unwrap();
        assert_eq!(hpa("1013.25"), 1013.25);
        assert_eq!(hpa("1013.25hPa"), 1013.25);
        assert_eq!(hpa("1013.25 mbar"), 1013.25);
        assert!((hpa("29.92inHg") - 1013.21).abs() < 0.01);
        assert!((hpa("1atm") - 1013.25).abs() < 1e-9);
        let c = |t| parse_in(t, Dimension::Temperature, "°C").unwrap();
        assert_eq!(c("25"), 25.0);
        assert_eq!(c("25°C"), 25.0);
        assert!((c("298.15K") - 25.0).abs() < 1e-12);
        assert!((c("77°F") - 25.0).abs() < 1e-12);
        assert!((c("-40F") + 40.0).abs() < 1e-12);
        let pct = |t| parse_in(t, Dimension::Ratio, "%").unwrap();
        assert_eq!(pct("60"), 60.0);
        assert_eq!(pct("60%"), 60.0);
        let per_day = |t| parse_in(t, Dimension::Ratio, "s/day").unwrap();
        assert_eq!(per_day("+12s/day"), 12.0);
        assert_eq!(per_day("-30 s/d"), -30.0);
        assert!((per_day("1ppm") - 0.0864).abs() < 1e-15);
        let ppm = |t| parse_in(t, Dimension::Ratio, "ppm").unwrap();
        assert_eq!(ppm("20ppm"), 20.0);
        assert!((ppm("8.64s/day") - 100.0).abs() < 1e-12);
        assert!((parse_in("5%", Dimension::Ratio, "").unwrap() - 0.05).abs() < 1e-17);
        let ms = |t| parse_in(t, Dimension::Time, "ms").unwrap();
        assert_eq!(ms("1.5"), 1.5);
        assert_eq!(ms("1.5ms"), 1.5);
        assert!((ms("800us") - 0.8).abs() < 1e-15);
        assert_eq!(
            parse_in("3600bph", Dimension::BeatRate, "bph").unwrap(),
            3600.0
        );
        assert_eq!("44.1kHz".parse::<SampleRate>().unwrap().0, 44_100);
        assert!("44.1".parse::<SampleRate>().is_err());
        assert_eq!("2s/day/h".parse::<RateChange>().unwrap().0, 2.0);
        assert_eq!("36tpi".parse::<ThreadsPerInch>().unwrap().0, 36.0);
        assert_eq!(
            parse_in("20m", Dimension::Ratio, "ppm")
                .unwrap_err()
                .to_string(),
            "'20m' is a length, but a ratio is wanted (%, ppm, ppb, s/day, s/week)"
        );
    }

    #[test]
    fn plain_numbers() {
        assert_eq!(parse_number("0.05"), Ok(0.05));
        assert_eq!(parse_number(" 1e4 "), Ok(1e4));
        assert!(parse_number("3deg").is_err());
        assert!(parse_number("nan").is_err());
        assert!(matches!(
            parse_number("1e400"),
            Err(UnitError::NotFinite(_))
        ));
    }

    #[test]
    fn ranges() {
        let (a, b) = parse_range("1deg..10deg", Dimension::Angle)
            .unwrap()
            .unwrap();
        assert_eq!((a, b), (1.0_f64.to_radians(), 10.0_f64.to_radians()));
        assert!(parse_range("3deg", Dimension::Angle).is_none());
        assert!(parse_range("1deg..x", Dimension::Angle).unwrap().is_err());
    }

    fn any_unit() -> impl Strategy<Value = (Dimension, &'static str, f64, f64)> {
        let all: Vec<(Dimension, &'static str, f64, f64)> = Dimension::ALL
            .iter()
            .flat_map(|&d| {
                d.units()
                    .iter()
                    .flat_map(move |u| u.names.iter().map(move |&n| (d, n, u.si, u.offset)))
            })
            .collect();
        proptest::sample::select(all)
    }

    proptest! {
        /// Any text: a value or a refusal, never a panic.
        #[test]
        fn never_panics(text in ".{0,24}") {
            for d in Dimension::ALL {
                let _ = parse_quantity(&text, d);
                let _ = parse_range(&text, d);
            }
        }

        /// A value written with a unit reads back as value × unit, with or
        /// without a space, in any of the unit's spellings.
        #[test]
        fn round_trip((dimension, name, si, offset) in any_unit(), value in -1e6_f64..1e6) {
            let tight = parse_quantity(&format!("{value}{name}"), dimension).unwrap();
            let spaced = parse_quantity(&format!("{value} {name}"), dimension).unwrap();
            prop_assert_eq!(tight, spaced);
            prop_assert_eq!(tight, value * si + offset);
        }

        /// Exponents: `1.5e-3m` equals `1.5mm`.
        #[test]
        fn exponent_notation(mantissa in 1_u32..10_000) {
            let m = f64::from(mantissa);
            let a = parse_quantity(&format!("{m}e-3m"), Dimension::Length).unwrap();
            let b = parse_quantity(&format!("{m}mm"), Dimension::Length).unwrap();
            prop_assert!((a - b).abs() <= 2.0 * f64::EPSILON * a.abs());
        }

        /// A unit of the wrong kind is named as such.
        #[test]
        fn wrong_dimension_is_named((dimension, name, _si, _offset) in any_unit(), value in 0.0_f64..100.0) {
            for wanted in Dimension::ALL {
                if wanted == dimension || lookup(wanted, name).is_some() {
                    continue;
                }
                let err = parse_quantity(&format!("{value}{name}"), wanted).unwrap_err();
                let is_wrong_dimension = matches!(err, UnitError::WrongDimension { .. });
                prop_assert!(is_wrong_dimension);
            }
        }
    }
}
