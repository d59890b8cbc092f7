//! Reading measurement files as people have them: CSV, semicolon files
//! with decimal commas, tab-separated Tracker exports with a title line and
//! CRLF line ends, space-aligned tables, files without a header. One reader
//! for every `fit` command.
//!
//! * The separator (comma, semicolon, tab, runs of spaces) is the one that
//!   splits the first rows into the same number of numeric cells; decimal
//!   commas are recognised when the separator is not a comma.
//! * The header is the last non-numeric line before the first numeric row;
//!   lines above it (a title such as Tracker's `mass_A`) are skipped, as are
//!   `#` comments and empty lines.
//! * Columns are found by name, case-insensitively, with the unit as a
//!   suffix, in brackets or in parentheses (`time_s`, `t`, `Time (s)`,
//!   `t [s]`, `t_{1}`, `angle_deg`, `θ (rad)`, `amplitude (deg)`, `x`, `y`).
//! * A row with a blank cell in a used column is skipped and counted.
//!
//! Every refusal names the file, and where it can the line, the column and
//! the separator detected.

use crate::formats::Converted;
use crate::{Layout, ReadError, Source};
use serde::Serialize;
use std::io::{BufRead, Read};

/// The longest line a measurement file may have (a row of a few hundred
/// columns fits many times over); a longer one is not a table of numbers.
pub const MAX_LINE_BYTES: u64 = 64 * 1024;
/// The most bytes read from one measurement file (2 GiB: about 50 million
/// rows of three numbers).
pub const MAX_FILE_BYTES: u64 = 2 << 30;
/// The most rows of numbers read from one measurement file.
pub const MAX_ROWS: usize = 50_000_000;

/// Degrees to radians.
pub const DEG: f64 = std::f64::consts::PI / 180.0;

/// What a column holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Time.
    Time,
    /// A half-swing count.
    Swing,
    /// The angle of the pendulum.
    Angle,
    /// The amplitude of a swing.
    Amplitude,
    /// Horizontal position.
    X,
    /// Vertical position (up).
    Y,
    /// A factor on a clock's drive (a long run's schedule).
    DriveFactor,
    /// Air temperature, °C.
    Temperature,
    /// Air pressure (read in Pa).
    Pressure,
    /// A measured period (a period table).
    Period,
    /// A period's uncertainty: named for it, or a generic `error`,
    /// `uncertainty`, `sigma`, … column right after the period's.
    PeriodError,
    /// A pendulum's length (read in m).
    Length,
    /// Which light gate an event is of (a label: `U`, `D`, `A`…).
    Gate,
    /// Times counted in a clock's ticks (read with `--tick-rate`).
    Ticks,
    /// An angular velocity (read in rad/s), about no named axis.
    AngularVelocity,
    /// A gyroscope's angular velocity about its x axis (rad/s).
    GyroX,
    /// About its y axis.
    GyroY,
    /// About its z axis.
    GyroZ,
    /// A clock's offset from its reference (phase, time error; read in s).
    Offset,
    /// A clock's rate or fractional frequency (read as a fraction: s/day
    /// divided by 86,400).
    Frequency,
    /// A half period (one beat) timed by a photogate (read in s).
    HalfPeriod,
    /// A photogate's pulse: how long the bob's flag blocked it (read in s).
    PulseWidth,
    /// Relative humidity, %.
    Humidity,
    /// A vertical temperature gradient, K/m, warmer upwards.
    Gradient,
    /// A change of a clock's rate from outside, s/day (positive: gaining).
    RateChange,
}

/// The role a column named `name` has (`temperature`, `pressure`): how
/// a command finds the columns a library table names.
pub fn role_named(name: &str) -> Option<Role> {
    Role::of(name)
}

/// A role's name for messages ("offset", "half period").
pub fn role_name(role: Role) -> &'static str {
    role.name()
}

/// The angular-velocity roles, a gyroscope's axes after the axis-less one.
pub const RATE_ROLES: [Role; 4] = [Role::AngularVelocity, Role::GyroX, Role::GyroY, Role::GyroZ];

impl Role {
    fn name(self) -> &'static str {
        match self {
            Role::Time => "time",
            Role::Swing => "swing",
            Role::Angle => "angle",
            Role::Amplitude => "amplitude",
            Role::X => "x",
            Role::Y => "y",
            Role::DriveFactor => "drive_factor",
            Role::Temperature => "temperature",
            Role::Pressure => "pressure",
            Role::Period => "period",
            Role::PeriodError => "period_error",
            Role::Length => "length",
            Role::Gate => "gate",
            Role::Ticks => "ticks",
            Role::AngularVelocity => "angular velocity",
            Role::GyroX => "gyroscope x",
            Role::GyroY => "gyroscope y",
            Role::GyroZ => "gyroscope z",
            Role::Offset => "offset",
            Role::Frequency => "rate",
            Role::HalfPeriod => "half period",
            Role::PulseWidth => "pulse width",
            Role::Humidity => "humidity",
            Role::Gradient => "gradient",
            Role::RateChange => "rate change",
        }
    }

    /// The role of a base name (lower case, unit removed).
    fn of(base: &str) -> Option<Role> {
        Some(match base {
            // English, and the words of the spreadsheets of much of Europe.
            "t" | "time" | "timestamp" | "times" | "zeit" | "temps" | "tiempo" | "tempo"
            | "tijd" | "unix_time" | "time_unix" | "unixtime" | "unix" | "epoch" | "datetime"
            | "date_time" | "time_utc" | "utc" => Role::Time,
            "swing" | "swings" | "half_swing" | "halfswing" => Role::Swing,
            "angle" | "theta" | "θ" | "phi" | "φ" | "angular_position" | "winkel" | "ángulo"
            | "angulo" | "angolo" | "hoek" => Role::Angle,
            "amplitude" | "amp" | "peak" | "peaks" | "amplitud" | "ampiezza" | "amplitudine"
            | "release_angle" | "initial_angle" | "theta0" | "θ0" | "theta_0" | "θ_0" | "a0"
            | "angle0" | "release angle" | "initial angle" | "initial amplitude"
            | "initial_amplitude" | "release amplitude" | "release_amplitude"
            | "starting angle" | "start_angle" | "max_angle" | "max angle" => Role::Amplitude,
            "x" => Role::X,
            "y" => Role::Y,
            "drive_factor" | "drive" | "factor" | "drive factor" | "antrieb" => Role::DriveFactor,
            "temperature" | "temp" | "temperatur" | "température" | "temperatura"
            | "temperatuur" => Role::Temperature,
            "pressure" | "barometer" | "air_pressure" | "air pressure" | "druck" | "luftdruck"
            | "pression" | "presión" | "pressione" | "luchtdruk" => Role::Pressure,
            "period" | "periods" | "periode" | "période" | "periodo" | "período"
            | "periodendauer" | "schwingungsdauer" | "t0" | "tau_period" => Role::Period,
            "period_err" | "period_error" | "period_uncertainty" | "period_sd" | "period_std"
            | "period_sigma" | "sigma_period" | "σ_period" | "u_period" | "dt" | "δt"
            | "sigma_t" | "σ_t" | "σt" | "t_err" | "t_error" | "err_t" | "error_t" => {
                Role::PeriodError
            }
            "length" | "l" | "len" | "länge" | "laenge" | "longueur" | "longitud" | "lunghezza"
            | "lengte" | "comprimento" | "string_length" | "pendulum_length" | "cord_length"
            | "wire_length" | "rod_length" | "thread_length" => Role::Length,
            "gate" | "eventtype" | "event_type" | "event type" | "channel" | "sensor"
            | "photogate" => Role::Gate,
            "clockticks" | "clock_ticks" | "clock ticks" | "ticks" | "tick" | "counts"
            | "counter" | "timer_ticks" => Role::Ticks,
            "angular_velocity"
            | "angular velocity"
            | "angularvelocity"
            | "omega"
            | "ω"
            | "angvel"
            | "ang_vel"
            | "winkelgeschwindigkeit"
            | "vitesse angulaire"
            | "velocidad angular"
            | "velocità angolare"
            | "gyro"
            | "gyroscope" => Role::AngularVelocity,
            "offset"
            | "phase"
            | "time_error"
            | "time error"
            | "clock_offset"
            | "clock offset"
            | "clock-ref"
            | "clock_minus_reference"
            | "offset_from_reference"
            | "delta"
            | "clock_error" => Role::Offset,
            "rate"
            | "frequency"
            | "fractional_frequency"
            | "fractional frequency"
            | "freq"
            | "ffd"
            | "clock_rate"
            | "clock rate"
            | "daily_rate"
            | "daily rate" => Role::Frequency,
            "half_period" | "half period" | "halfperiod" | "half_periods" | "beat"
            | "beat_period" | "beat period" | "beats" | "half_swing_period" => Role::HalfPeriod,
            "pulse_width" | "pulse width" | "pulsewidth" | "pulse" | "width" | "gate_time"
            | "dwell" | "blocked" | "blocked_time" | "transit" | "transit_time" => Role::PulseWidth,
            "humidity" | "rh" | "relative_humidity" | "relative humidity" | "hum" | "feuchte"
            | "luftfeuchte" | "humidité" | "humedad" | "umidità" => Role::Humidity,
            "gradient"
            | "temperature_gradient"
            | "temperature gradient"
            | "vertical_gradient"
            | "vertical gradient"
            | "dt_dz"
            | "dtdz" => Role::Gradient,
            "rate_change" | "rate change" | "ratechange" => Role::RateChange,
            // phyphox's raw gyroscope data, in the app's languages.
            _ if gyro_axis(base).is_some() => gyro_axis(base)?,
            _ => return None,
        })
    }
}

/// The gyroscope axis a header base names: `gyroscope x`, `Gyroskop y`,
/// `gyro_z`, `ω_x`, `wx`.
fn gyro_axis(base: &str) -> Option<Role> {
    let (name, axis) = base.rsplit_once([' ', '_']).or_else(|| {
        let (i, _) = base.char_indices().last()?;
        Some(base.split_at(i))
    })?;
    let named = matches!(
        name.trim(),
        "gyroscope"
            | "gyro"
            | "gyroskop"
            | "giroscopio"
            | "gyroscoop"
            | "giroscópio"
            | "angular velocity"
            | "angular_velocity"
            | "rotation"
            | "rotation rate"
            | "drehrate"
            | "rotación"
            | "rotazione"
            | "omega"
            | "ω"
            | "w"
            | "g"
    );
    match (named, axis.trim()) {
        (true, "x") => Some(Role::GyroX),
        (true, "y") => Some(Role::GyroY),
        (true, "z") => Some(Role::GyroZ),
        _ => None,
    }
}

/// How angles without a unit in their header are to be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AngleUnit {
    /// Degrees.
    Degrees,
    /// Radians.
    Radians,
}

/// What the user said about the file on the command line.
#[derive(Clone, Debug, Default)]
pub struct ReadOptions {
    /// `--angle-unit`: for angle or amplitude columns without a unit.
    pub angle_unit: Option<AngleUnit>,
    /// `--columns`: the names of a headerless file's columns, in order.
    pub columns: Option<Vec<String>>,
    /// The command has no `--columns` for this file (a drive file, a
    /// log's events): a file without a header is told to name its columns
    /// in a header line.
    pub no_columns_flag: bool,
    /// `--frame-rate`: rebuild times as the first time + row index / rate.
    pub frame_rate: Option<f64>,
    /// Keep times as written instead of measuring them from the first row
    /// (a schedule against the run's own clock).
    pub absolute_time: bool,
    /// `--run N`: of a file whose times restart, the N-th run (from 1).
    pub run: Option<usize>,
    /// `--tick-rate HZ`: the clock whose ticks a `ticks` column counts.
    pub tick_rate: Option<f64>,
    /// A blank cell in a used column is refused, naming its line and
    /// column, instead of its row being skipped (a schedule, whose every
    /// row is a setting).
    pub refuse_blank: bool,
}

/// What was read, for the JSON output (`format`).
#[derive(Clone, Debug, Serialize)]
pub struct Format {
    /// `comma`, `semicolon`, `tab`, `spaces`, or `none` (one column).
    pub separator: &'static str,
    /// `point` or `comma`.
    pub decimal: &'static str,
    /// The header names of the columns used.
    pub columns_used: Vec<String>,
    /// Rows read.
    pub rows: usize,
    /// Rows skipped for a blank cell in a used column.
    pub skipped_rows: usize,
    /// The file lines of the first few of them, for the warning.
    #[serde(skip)]
    pub skipped_lines: Vec<u64>,
    /// What the reader left out that the user should hear of (rows with
    /// a blank cell, a second column of a kind), one sentence each naming
    /// the file: the command line prints them as warnings, the page shows
    /// them.
    #[serde(skip)]
    pub notes: Vec<String>,
    /// The frame rate the times were rebuilt from (`--frame-rate`), if any.
    pub frame_rate: Option<f64>,
    /// When the file writes several readings under one time stamp: their
    /// mean number, the readings spread evenly between stamps.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub readings_per_time: Option<f64>,
    /// The labels of a gate column, in the order first seen (their
    /// numbers in the analysis).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub gate_labels: Vec<String>,
    /// The run read (`--run`), counted from 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub run: Option<usize>,
    /// The runs the file holds (with `--run`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub runs: Option<usize>,
    /// A gyroscope's angular-velocity columns read (the analysis finds
    /// the swing's axis among them).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub angular_velocity_columns: Vec<String>,
    /// The file lines of rows dropped for repeating an earlier row (cell
    /// for cell, or its readings under another time) out of time order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repeated_rows_dropped: Option<Vec<u64>>,
    /// The first and last times fitted (`--from`, `--to`), s from the
    /// record's first sample.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub window_s: Option<[f64; 2]>,
    /// The reader the file went through: `text table`, or a format of
    /// [`crate::formats::FORMATS`] (`spreadsheet workbook`, `Tracker
    /// project`, `TICC log`), whose table the separator and decimal are of.
    pub reader: &'static str,
    /// The sheet read from a spreadsheet workbook (`.xls`, `.xlsx`, `.ods`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sheet: Option<String>,
    /// The point-mass track read from a Tracker project (`.trk`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tracker_track: Option<String>,
    /// The time of the first row, subtracted from every time (a data
    /// logger's Unix time, say), s; `null` when rebuilt from the frame rate
    /// or when there is no time column.
    pub time_origin_s: Option<f64>,
}

impl Format {
    /// For people: "tab-separated, decimal commas, 4 rows with blank cells skipped".
    pub fn describe(&self) -> String {
        let mut out = if self.separator == "none" {
            "one column".to_string()
        } else {
            format!("{}-separated", self.separator)
        };
        if self.decimal == "comma" {
            out.push_str(", decimal commas");
        }
        if self.skipped_rows > 0 {
            out.push_str(&format!(
                ", {} rows with blank cells skipped",
                self.skipped_rows
            ));
        }
        if let Some(lines) = &self.repeated_rows_dropped {
            let shown: Vec<String> = lines.iter().take(3).map(u64::to_string).collect();
            out.push_str(&format!(
                ", {} rows that repeat an earlier one out of time order dropped (line{} {}{})",
                lines.len(),
                if lines.len() > 1 { "s" } else { "" },
                shown.join(", "),
                if lines.len() > 3 { ", …" } else { "" }
            ));
        }
        out
    }
}

/// A column found in the header.
#[derive(Clone, Debug)]
pub struct Found {
    /// What it holds.
    pub role: Role,
    /// Its header name as written.
    pub header: String,
    index: usize,
    /// The unit written in the header, if any.
    unit: Option<String>,
    /// The factor to SI (time in s, angles in rad, pressure in Pa;
    /// temperature stays in °C); `None` for an angle column without a
    /// unit, or a unit that is not one of the column's kind.
    factor: Option<f64>,
    /// Added after the factor (a temperature in K or °F to °C).
    offset: f64,
}

/// The columns a command uses, chosen from those the header has: the
/// command sees every column found and returns the ones it wants, in its
/// order, or a message saying what is missing.
pub type Choose<'a> = dyn Fn(&[Found]) -> Result<Vec<Role>, String> + 'a;

/// Columns read into memory, in SI, times measured from the first row.
pub struct Table {
    /// The file, as given.
    pub file: String,
    /// The roles read, in the order asked for.
    pub roles: Vec<Role>,
    /// Their header names.
    pub names: Vec<String>,
    /// Values, one vector per role.
    pub values: Vec<Vec<f64>>,
    /// The file line of each row, for messages.
    pub lines: Vec<u64>,
    /// What was read.
    pub format: Format,
}

impl Table {
    /// The values of `role`, if read.
    pub fn column(&self, role: Role) -> Option<&[f64]> {
        self.roles
            .iter()
            .position(|&r| r == role)
            .map(|i| self.values[i].as_slice())
    }

    /// An error about row `row` of the column of `role`.
    pub fn error_at(&self, row: usize, role: Role, message: impl std::fmt::Display) -> ReadError {
        let column = self
            .roles
            .iter()
            .position(|&r| r == role)
            .map_or("?", |i| self.names[i].as_str());
        ReadError::other(format!(
            "{}: line {}, column {column}: {message}",
            self.file, self.lines[row]
        ))
    }

    /// Checks that the column of `role` strictly increases; repeated values
    /// are named as rounding, with the fix.
    pub fn require_increasing(&self, role: Role) -> Result<(), ReadError> {
        let Some(v) = self.column(role) else {
            return Ok(());
        };
        match (1..v.len()).find(|&i| v[i] <= v[i - 1]) {
            Some(i) if v[i] == v[i - 1] => Err(self.error_at(
                i,
                role,
                format!(
                    "{} repeats the time before it: the times look rounded (exported to too few \
                     digits); give --frame-rate FPS to rebuild them from the row numbers",
                    pendulum_theory::error::format_significant(v[i] + self.origin(role), 12)
                ),
            )),
            // The library's sentence for the same times from Python.
            Some(i) => Err(self.error_at(
                i,
                role,
                format!(
                    "{} is not after the previous {}; sort by time",
                    v[i] + self.origin(role),
                    v[i - 1] + self.origin(role),
                ),
            )),
            None => Ok(()),
        }
    }

    /// The value subtracted from the column (the first time), for messages.
    fn origin(&self, role: Role) -> f64 {
        match role {
            Role::Time => self.format.time_origin_s.unwrap_or(0.0),
            _ => 0.0,
        }
    }
}

/// Reads the columns `choose` picks from `source` into memory.
pub fn read_table(
    source: Source<'_>,
    options: &ReadOptions,
    choose: &Choose<'_>,
) -> Result<Table, ReadError> {
    let mut values: Vec<Vec<f64>> = Vec::new();
    let mut lines = Vec::new();
    let (file, roles, names, format) = stream_table(source, options, choose, |row, line| {
        if values.is_empty() {
            values = vec![Vec::new(); row.len()];
        }
        for (column, v) in values.iter_mut().zip(row) {
            column.push(*v);
        }
        lines.push(line);
        Ok(())
    })?;
    if values.is_empty() {
        values = vec![Vec::new(); roles.len()];
    }
    let mut format = format;
    if let Some(k) = roles.iter().position(|&r| r == Role::Time) {
        let dropped = drop_repeated_rows(&mut values, &mut lines, k, !options.refuse_blank);
        if !dropped.is_empty() {
            format.repeated_rows_dropped = Some(dropped);
        }
        if format.frame_rate.is_none() && !options.absolute_time {
            format.readings_per_time = spread_readings(&mut values[k]);
        }
    }
    Ok(Table {
        file,
        roles,
        names,
        values,
        lines,
        format,
    })
}

/// How far back a row out of time order is looked for as a copy.
const REPEAT_LOOKBACK: usize = 10;

/// Rows whose time does not advance and that repeat, cell for cell, one
/// of the [`REPEAT_LOOKBACK`] rows before them (a logger's buffer written
/// twice: 11 of the 12 faults of a real 18,000-row phyphox gyroscope
/// file) are dropped: they hold nothing new, and every analysis needs
/// times in order. With `restamped`, a row whose readings (two or more
/// columns beside the time) repeat such a row's under a time of its own
/// is a copy too (the twelfth: a sample written again under the next
/// stamp, which runs back). Returns their file lines. A row out of order
/// with a reading of its own, or a schedule's repeated setting under an
/// earlier time (`restamped` false), is left for the time check to name.
fn drop_repeated_rows(
    values: &mut [Vec<f64>],
    lines: &mut Vec<u64>,
    time: usize,
    restamped: bool,
) -> Vec<u64> {
    let restamped = restamped && values.len() >= 3;
    let rows = lines.len();
    let mut keep = vec![true; rows];
    // Whether row `i` copies a kept row of the few before it: cell for
    // cell, or (restamped) its readings under another time.
    let copies = |keep: &[bool], i: usize| {
        (i.saturating_sub(REPEAT_LOOKBACK)..i)
            .filter(|&j| keep[j])
            .any(|j| {
                values
                    .iter()
                    .enumerate()
                    .all(|(c, v)| v[j] == v[i] || (restamped && c == time))
            })
    };
    let mut kept: Vec<usize> = Vec::new();
    for i in 0..rows {
        let back = kept
            .last()
            .is_some_and(|&j| values[time][i] <= values[time][j]);
        if back {
            if copies(&keep, i) {
                keep[i] = false;
                continue;
            }
            // The copy may be the row before, written under the time this
            // one then takes again: that row goes, when this one follows
            // the row before it.
            let j = kept[kept.len() - 1];
            let before = kept.len().checked_sub(2).map(|k| kept[k]);
            if restamped
                && copies(&keep, j)
                && before.is_none_or(|b| values[time][i] > values[time][b])
            {
                keep[j] = false;
                kept.pop();
            }
        }
        kept.push(i);
    }
    if keep.iter().all(|&k| k) {
        return Vec::new();
    }
    let dropped: Vec<u64> = lines
        .iter()
        .zip(&keep)
        .filter(|(_, &k)| !k)
        .map(|(l, _)| *l)
        .collect();
    for column in values.iter_mut() {
        let mut k = keep.iter();
        column.retain(|_| *k.next().unwrap_or(&true));
    }
    let mut k = keep.iter();
    lines.retain(|_| *k.next().unwrap_or(&true));
    dropped
}

/// A logger that writes several readings under one time stamp (its clock
/// ticks slower than it samples): when most rows share their time with
/// another, the readings of each stamp are spread evenly over the interval
/// to the next (the last stamp's over the interval before it). Returns the
/// mean number of readings a stamp, or `None` when the times are left as
/// they are (a few repeats are rounding, said by the caller).
fn spread_readings(time: &mut [f64]) -> Option<f64> {
    let n = time.len();
    let repeated = (1..n).filter(|&i| time[i] == time[i - 1]).count();
    if n < 4 || 2 * repeated < n {
        return None;
    }
    let mut starts: Vec<usize> = vec![0];
    starts.extend((1..n).filter(|&i| time[i] != time[i - 1]));
    if starts.len() < 2 {
        return None;
    }
    let stamps: Vec<f64> = starts.iter().map(|&i| time[i]).collect();
    for (g, &start) in starts.iter().enumerate() {
        let end = starts.get(g + 1).copied().unwrap_or(n);
        let step = match stamps.get(g + 1) {
            Some(next) => next - stamps[g],
            None => stamps[g] - stamps[g - 1],
        };
        let k = (end - start) as f64;
        for (j, t) in time[start..end].iter_mut().enumerate() {
            *t = stamps[g] + j as f64 * step / k;
        }
    }
    Some(n as f64 / starts.len() as f64)
}

/// The separators tried, in order of preference.
const SEPARATORS: [(Separator, &str); 4] = [
    (Separator::Char('\t'), "tab"),
    (Separator::Char(';'), "semicolon"),
    (Separator::Char(','), "comma"),
    (Separator::Spaces, "spaces"),
];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Separator {
    Char(char),
    Spaces,
    /// One column: the whole line is the cell.
    Whole,
}

impl Separator {
    fn split(self, line: &str) -> Vec<&str> {
        match self {
            Separator::Char(c) => line.split(c).map(str::trim).collect(),
            Separator::Spaces => line.split_whitespace().collect(),
            Separator::Whole => vec![line.trim()],
        }
    }
}

/// Lines read before the separator is decided.
const SNIFF_LINES: usize = 64;

/// A cell as a number, with `decimal_comma` read as a point; `None` if
/// it is not one. An empty cell is `Some(None)`.
fn cell_value(cell: &str, decimal_comma: bool) -> Option<Option<f64>> {
    let cell = cell.trim().trim_matches('"');
    if cell.is_empty() {
        return Some(None);
    }
    let parsed = if decimal_comma {
        cell.replace(',', ".").parse::<f64>()
    } else {
        cell.parse::<f64>()
    };
    match parsed {
        Ok(v) if v.is_finite() => Some(Some(v)),
        Ok(_) => None,
        Err(_) => datetime_seconds(cell).map(Some),
    }
}

/// For a date-time cell (`2024-07-19T09:27:13Z`, `2024-07-19 09:27:13`):
/// whether it carries an offset from UTC; `None` for anything else.
fn datetime_has_offset(cell: &str) -> Option<bool> {
    let c = cell.trim().trim_matches('"');
    let (date, time) = c.split_once(['T', 't', ' '])?;
    if date.len() != 10 || date.as_bytes().get(4) != Some(&b'-') || !time.contains(':') {
        return None;
    }
    Some(time.ends_with(['Z', 'z']) || time.contains(['+', '-']))
}

/// The offset from UTC a date-time cell ends with (`+02:00`, `-0530`), in
/// hours; `None` without one (or `Z`).
fn utc_offset_hours(cell: &str) -> Option<f64> {
    let cell = cell.trim();
    let time = &cell[cell.find(['T', 't', ' '])? + 1..];
    let sign_at = time.rfind(['+', '-'])?;
    let sign = if time[sign_at..].starts_with('-') {
        -1.0
    } else {
        1.0
    };
    let digits: String = time[sign_at + 1..]
        .chars()
        .filter(char::is_ascii_digit)
        .collect();
    let hours: f64 = digits.get(..2)?.parse().ok()?;
    let minutes: f64 = digits.get(2..4).map_or(Some(0.0), |m| m.parse().ok())?;
    Some(sign * (hours + minutes / 60.0))
}

/// A date and time (ISO 8601 / RFC 3339: `2024-07-19T09:27:13.125Z`,
/// `2024-07-19 09:27:13.125+02:00`; without an offset read as UTC) as
/// seconds since 1970, or a time of day (`09:27:13.125`) as seconds since
/// midnight. Parsed by `jiff`; an f64 keeps 0.24 µs of a date in this
/// century, below any logger's resolution.
fn datetime_seconds(cell: &str) -> Option<f64> {
    use jiff::civil::{DateTime, Time};
    use jiff::Timestamp;
    if !cell.contains(':') {
        return None;
    }
    let of = |t: Timestamp| t.as_nanosecond() as f64 * 1e-9;
    if let Ok(t) = cell.parse::<Timestamp>() {
        // jiff takes offsets to ±25:59; the world's run from -12:00 to
        // +14:00 (Kiribati), and past them a cell is not a clock's time.
        return (utc_offset_hours(cell).is_none_or(|h| (-12.0..=14.0).contains(&h))).then(|| of(t));
    }
    if let Ok(d) = cell.parse::<DateTime>() {
        return jiff::tz::Offset::UTC.to_timestamp(d).ok().map(of);
    }
    cell.parse::<Time>().ok().map(|t| {
        f64::from(t.hour()) * 3600.0
            + f64::from(t.minute()) * 60.0
            + f64::from(t.second())
            + f64::from(t.subsec_nanosecond()) * 1e-9
    })
}

/// Whether every cell is a number or empty, with at least one number.
fn is_numeric(cells: &[&str], decimal_comma: bool) -> bool {
    let (mut numbers, mut labels) = (0, 0);
    for c in cells {
        match cell_value(c, decimal_comma) {
            None if is_label(c) => labels += 1,
            // A number too large for a double (`1e400`) is still a number:
            // its row is data, refused by its line and column.
            None if overflows(c, decimal_comma) => numbers += 1,
            None => return false,
            Some(Some(_)) => numbers += 1,
            Some(None) => {}
        }
    }
    // A row may carry short labels (a photogate's `U`/`D`) beside at
    // least as many numbers; a header of names has no number.
    numbers > 0 && labels <= numbers
}

/// The header and the row of a line that holds both, its line end lost
/// or turned into a separator, over rows of `width` cells: the header's
/// `width` names and then the row's numbers, the first glued to the last
/// name (`time_s,offset_s0.0,1.2e-06`: `2 width - 1` cells) or not
/// (`time_s offset_s 0.0 1.2e-06`: `2 width`); `None` for anything else.
/// A one-column line must end in a number with a point or an exponent
/// after a name the reader knows (`offset_s1.2e-06`), as a name may end
/// in a digit (`x2`, `t_1`). Returned as names and numbers joined by
/// `join`.
fn glued_row(
    cells: &[&str],
    width: usize,
    decimal_comma: bool,
    join: &str,
) -> Option<(String, String)> {
    let number = |c: &str| matches!(cell_value(c, decimal_comma), Some(Some(_)));
    let cells: Vec<&str> = cells.iter().map(|c| c.trim().trim_matches('"')).collect();
    let (names, row): (Vec<&str>, Vec<&str>) = if width > 1 && cells.len() == 2 * width {
        (cells[..width].to_vec(), cells[width..].to_vec())
    } else if cells.len() + 1 == 2 * width {
        // The longest number at the end of the last name.
        let cell = cells[width - 1];
        let (name, first) = cell
            .char_indices()
            .skip(1)
            .map(|(i, _)| cell.split_at(i))
            .find(|(name, first)| {
                first.starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c))
                    && !name.ends_with(|c: char| c.is_ascii_digit() || c == '.')
                    && number(first)
            })?;
        let fraction = first.contains(['.', 'e', 'E']) || decimal_comma && first.contains(',');
        if width == 1 && !(fraction && Role::of(&split_header(name).0).is_some()) {
            return None;
        }
        let mut names = cells[..width - 1].to_vec();
        names.push(name.trim());
        let mut row = vec![first];
        row.extend(&cells[width..]);
        (names, row)
    } else {
        return None;
    };
    (names.iter().all(|c| !c.is_empty() && !number(c)) && row.iter().all(|c| number(c)))
        .then(|| (names.join(join), row.join(join)))
}

/// Whether `cell` is written as a number (digits and an exponent, not the
/// words `inf` or `nan`) that is beyond double precision.
fn overflows(cell: &str, decimal_comma: bool) -> bool {
    let c = cell.trim().trim_matches('"');
    let c = if decimal_comma {
        c.replace(',', ".")
    } else {
        c.to_string()
    };
    c.chars().any(|ch| ch.is_ascii_digit())
        && !c.to_ascii_lowercase().contains(['i', 'n'])
        && c.parse::<f64>().is_ok_and(|v| v.is_infinite())
}

/// A short label in a row of numbers: one to four letters or digits,
/// starting with a letter (`U`, `D`, `A1`, `on`).
fn is_label(cell: &str) -> bool {
    let c = cell.trim().trim_matches('"');
    (1..=4).contains(&c.chars().count())
        && c.chars().next().is_some_and(char::is_alphabetic)
        && c.chars().all(char::is_alphanumeric)
}

/// The separator and decimal mark of the sampled `lines`: the candidate
/// under which the most numeric rows share one field count above 1 (ties
/// go to the earlier in [`SEPARATORS`]); a single column otherwise.
fn sniff(lines: &[String]) -> (Separator, &'static str, bool) {
    let mut best = (SEPARATORS[2].0, SEPARATORS[2].1, false, 0usize);
    for (sep, name) in SEPARATORS {
        for decimal_comma in [false, true] {
            if decimal_comma && sep == Separator::Char(',') {
                continue;
            }
            let mut counts: Vec<(usize, usize)> = Vec::new();
            for line in lines {
                let cells = sep.split(line);
                if cells.len() < 2 || !is_numeric(&cells, decimal_comma) {
                    continue;
                }
                match counts.iter_mut().find(|(n, _)| *n == cells.len()) {
                    Some(entry) => entry.1 += 1,
                    None => counts.push((cells.len(), 1)),
                }
            }
            let score = counts.iter().map(|&(_, c)| c).max().unwrap_or(0);
            if score > best.3 {
                best = (sep, name, decimal_comma, score);
            }
        }
    }
    // One number a line, in more lines than any separator's rows (a
    // logger's column under a few lines of metadata): one column.
    let single = |comma: bool| {
        lines
            .iter()
            .filter(|l| cell_value(l, comma).is_some_and(|v| v.is_some()))
            .count()
    };
    if best.3 == 0 || single(false) > best.3 {
        let comma = lines
            .iter()
            .any(|l| l.trim().parse::<f64>().is_err() && cell_value(l, true).is_some());
        return (Separator::Whole, "none", comma);
    }
    // Numbers with decimal commas under a header of one name: one column
    // (`1,0017` is not two integers there).
    let header_has_one_name = lines
        .iter()
        .take_while(|l| !is_numeric(&best.0.split(l), best.2))
        .last()
        .is_some_and(|h| !h.contains([',', ';', '\t']));
    if best.0 == Separator::Char(',') && header_has_one_name && single(true) >= best.3 {
        return (Separator::Whole, "none", true);
    }
    (best.0, best.1, best.2)
}

/// A header name split into its base (lower case) and unit, if any:
/// `Time (s)`, `t [s]`, `time_s`, `t_{1}`, `angle_deg`, `θ (rad)`.
fn split_header(header: &str) -> (String, Option<String>) {
    let mut text = header.trim().trim_matches('"').trim().to_lowercase();
    // Tracker's subscripts: t_{1}, x_{A}.
    if let Some(i) = text.find("_{") {
        if text.ends_with('}') {
            text.truncate(i);
        }
    }
    // A clock's rate in seconds a day, written out: `rate_s_per_day`,
    // `rate s/day`.
    for suffix in ["_s_per_day", " s per day", "_s/day", " s/day", "_s/d"] {
        if let Some(base) = text.strip_suffix(suffix) {
            if !base.trim().is_empty() {
                return (base.trim().to_string(), Some("s/day".to_string()));
            }
        }
    }
    // A gradient in kelvin a metre: `gradient_k_per_m`, `dT/dz K/m`.
    for (suffix, unit) in [
        ("_k_per_m", "k/m"),
        ("_c_per_m", "c/m"),
        (" k/m", "k/m"),
        ("_k/m", "k/m"),
    ] {
        if let Some(base) = text.strip_suffix(suffix) {
            if !base.trim().is_empty() {
                return (base.trim().to_string(), Some(unit.to_string()));
            }
        }
    }
    // `Time (s)`, `t [s]`, `Gyroscope x (rad/s)`: the unit in brackets.
    for (open, close) in [('(', ')'), ('[', ']'), ('{', '}')] {
        if let (Some(i), true) = (text.find(open), text.ends_with(close)) {
            let unit = text[i + 1..text.len() - 1].trim().to_string();
            let base = text[..i].trim().to_string();
            return (base, Some(unit));
        }
    }
    // `Time/s`, `Angle/rad`, `AngVel/rad/s`: the quantity over its unit.
    if let Some((base, unit)) = text.split_once('/') {
        let base = base.trim();
        if !base.is_empty() && !unit.trim().is_empty() && !base.ends_with('+') {
            return (base.to_string(), Some(unit.trim().to_string()));
        }
    }
    if let Some((base, unit)) = text.rsplit_once(['_', ' ']) {
        // A pressure's unit only after a pressure's name (`x_bar` is a
        // name).
        let known = unit_of(unit).is_some_and(|(kind, _)| {
            kind != Kind::Pressure
                || Role::of(base.trim()) == Some(Role::Pressure)
                || matches!(unit, "hpa" | "mbar" | "pa" | "kpa" | "inhg" | "mmhg")
        });
        if known && !base.is_empty() {
            return (base.trim().to_string(), Some(unit.to_string()));
        }
    }
    (text, None)
}

/// What a unit measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Time,
    Angle,
    Length,
    Temperature,
    Pressure,
    Rate,
    /// A clock's rate, as a fraction.
    ClockRate,
    /// A percentage.
    Percent,
    /// A temperature gradient, K/m.
    Gradient,
}

/// The index of a column the reader makes (times from a sample rate).
const MADE_COLUMN: usize = usize::MAX;

/// Whether a file's setting names its sample rate (Hz).
fn is_rate_name(name: &str) -> bool {
    let (base, unit) = split_header(name);
    matches!(
        base.as_str(),
        "sample_rate"
            | "samplerate"
            | "sampling_rate"
            | "sample rate"
            | "sampling rate"
            | "fs"
            | "rate"
            | "sampling_frequency"
            | "sample_frequency"
            | "frame_rate"
            | "framerate"
            | "fps"
    ) && unit.is_none_or(|u| u == "hz")
}

/// Whether a header's base names an uncertainty without saying of what
/// (it is then the uncertainty of the column before it).
fn is_generic_error(base: &str) -> bool {
    matches!(
        base,
        "err"
            | "error"
            | "errors"
            | "uncertainty"
            | "unc"
            | "sigma"
            | "σ"
            | "sd"
            | "std"
            | "stdev"
            | "std_dev"
            | "±"
            | "+/-"
            | "+-"
            | "u"
            | "fehler"
            | "erreur"
            | "incertitude"
            | "error_abs"
            | "abs_error"
            | "absolute_error"
    )
}

/// The SI factor of a length unit written in a header (pixels have none).
fn length_factor(unit: &str) -> Option<f64> {
    Some(match unit {
        "m" => 1.0,
        "cm" => 0.01,
        "mm" => 1e-3,
        "in" => 0.0254,
        _ => return None,
    })
}

/// The kind and SI factor of a unit written in a header (temperature in
/// °C, its only unit here).
fn unit_of(unit: &str) -> Option<(Kind, f64)> {
    // Pressures from the flags' table (units::PRESSURE): one list for both.
    if let Some(si) = crate::units::si_factor(crate::units::PRESSURE, unit) {
        return Some((Kind::Pressure, si));
    }
    Some(match unit {
        "s" | "sec" | "secs" | "second" | "seconds" => (Kind::Time, 1.0),
        "ms" => (Kind::Time, 1e-3),
        "us" | "µs" => (Kind::Time, 1e-6),
        "ns" => (Kind::Time, 1e-9),
        "min" => (Kind::Time, 60.0),
        "h" => (Kind::Time, 3600.0),
        "rad/s" | "rad/sec" | "rad s^-1" | "rad*s^-1" | "rad s-1" | "rad·s⁻¹" | "rad s⁻¹"
        | "rads" | "rad_s" => (Kind::Rate, 1.0),
        "deg/s" | "°/s" | "deg/sec" | "dps" | "deg s^-1" | "deg_s" | "degs" => (Kind::Rate, DEG),
        "deg" | "degree" | "degrees" | "°" => (Kind::Angle, DEG),
        "rad" | "radian" | "radians" => (Kind::Angle, 1.0),
        "mrad" | "milliradian" | "milliradians" => (Kind::Angle, 1e-3),
        "m" | "cm" | "mm" | "px" | "pixels" | "pixel" | "in" => (Kind::Length, 1.0),
        "c" | "°c" | "degc" | "celsius" => (Kind::Temperature, 1.0),
        // Kelvin and Fahrenheit (their offsets are applied where the
        // column is found).
        "k" | "kelvin" | "f" | "°f" | "degf" | "fahrenheit" => (Kind::Temperature, 1.0),
        "s/day" | "s/d" | "sec/day" | "s per day" | "s_per_day" | "spd" => {
            (Kind::ClockRate, 1.0 / 86_400.0)
        }
        "ppm" => (Kind::ClockRate, 1e-6),
        "ppb" => (Kind::ClockRate, 1e-9),
        "%" | "percent" | "pct" | "%rh" | "rh" => (Kind::Percent, 1.0),
        "k/m" | "°c/m" | "c/m" | "degc/m" | "k_per_m" | "c_per_m" => (Kind::Gradient, 1.0),
        "k/cm" | "°c/cm" | "c/cm" => (Kind::Gradient, 100.0),
        _ => return None,
    })
}

/// The units a column of `role` may carry, for messages.
fn units_for(role: Role) -> &'static str {
    match role {
        Role::Time => "s, ms, us, min, h",
        Role::Angle | Role::Amplitude => "deg, rad",
        Role::Temperature => "°C (c, degc, celsius), K, °F (f, degf)",
        Role::Pressure => "hPa, mbar, Pa, kPa, bar, atm, inHg, mmHg, Torr",
        Role::Period | Role::PeriodError => "s, ms, us, min, h",
        Role::Length => "m, cm, mm, in",
        Role::Ticks => "none: give the clock's rate with --tick-rate HZ",
        Role::AngularVelocity | Role::GyroX | Role::GyroY | Role::GyroZ => "rad/s, deg/s",
        Role::Offset | Role::HalfPeriod | Role::PulseWidth => "s, ms, us, ns",
        Role::Frequency => "s/day, ppm, ppb, or none (a fraction)",
        Role::Humidity => "%",
        Role::Gradient => "K/m, °C/m, K/cm",
        Role::RateChange => "s/day, ppm",
        _ => "none",
    }
}

/// The columns a header holds, with their roles and units.
fn find_columns(headers: &[String], options: &ReadOptions) -> Vec<Found> {
    let mut found: Vec<Found> = Vec::new();
    let mut previous: Option<Role> = None;
    for (index, header) in headers.iter().enumerate() {
        let (base, unit) = split_header(header);
        let role = Role::of(&base).or_else(|| {
            (is_generic_error(&base) && matches!(previous, Some(Role::Period | Role::Time)))
                .then_some(Role::PeriodError)
        });
        previous = role;
        let Some(role) = role else {
            continue;
        };
        if found.iter().any(|f| f.role == role) {
            continue; // The first column of a kind counts.
        }
        let kind = |k: Kind| {
            unit.as_deref()
                .and_then(unit_of)
                .filter(|(of, _)| *of == k)
                .map(|(_, f)| f)
        };
        // A temperature in kelvin or Fahrenheit: a factor and an offset.
        let kelvin_or_fahrenheit = match (role, unit.as_deref()) {
            (Role::Temperature, Some("k" | "kelvin")) => Some((1.0, -273.15)),
            (Role::Temperature, Some("f" | "°f" | "degf" | "fahrenheit")) => {
                Some((5.0 / 9.0, -160.0 / 9.0))
            }
            _ => None,
        };
        let factor = match (role, unit.as_deref()) {
            _ if kelvin_or_fahrenheit.is_some() => kelvin_or_fahrenheit.map(|(f, _)| f),
            (
                Role::Angle
                | Role::Amplitude
                | Role::AngularVelocity
                | Role::GyroX
                | Role::GyroY
                | Role::GyroZ,
                None,
            ) => options.angle_unit.map(|u| match u {
                AngleUnit::Degrees => DEG,
                AngleUnit::Radians => 1.0,
            }),
            (Role::Time, None)
            | (Role::Swing | Role::X | Role::Y | Role::DriveFactor, _)
            // A temperature without a unit is in °C.
            | (Role::Temperature, None) => Some(1.0),
            // A pressure without a unit is in hPa (a barometer's).
            (Role::Pressure, None) => Some(100.0),
            (Role::Time | Role::Period | Role::PeriodError, Some(_)) => kind(Kind::Time),
            (Role::Period | Role::PeriodError | Role::Length | Role::Gate, None) => Some(1.0),
            (Role::Gate, Some(_)) => Some(1.0),
            (Role::Ticks, _) => options.tick_rate.map(|r| 1.0 / r),
            (Role::Length, Some(u)) => length_factor(u),
            (Role::Angle | Role::Amplitude, Some(_)) => kind(Kind::Angle),
            (Role::AngularVelocity | Role::GyroX | Role::GyroY | Role::GyroZ, Some(_)) => {
                kind(Kind::Rate)
            }
            (Role::Temperature, Some(_)) => kind(Kind::Temperature),
            // A bare offset is in s; a bare half period or pulse, as an
            // Arduino timer prints it, in µs.
            (Role::Offset, None) => Some(1.0),
            (Role::HalfPeriod | Role::PulseWidth, None) => Some(1e-6),
            (Role::Offset | Role::HalfPeriod | Role::PulseWidth, Some(_)) => kind(Kind::Time),
            // A bare rate is a clock's, in s/day; a bare frequency a
            // fraction.
            (Role::Frequency, None) if base.contains("rate") => Some(1.0 / 86_400.0),
            (Role::Frequency, None) => Some(1.0),
            (Role::Frequency, Some(_)) => kind(Kind::ClockRate),
            (Role::Humidity, _) => unit.as_deref().map_or(Some(1.0), |_| kind(Kind::Percent)),
            // A bare gradient is in K/m.
            (Role::Gradient, _) => unit.as_deref().map_or(Some(1.0), |_| kind(Kind::Gradient)),
            // A rate change is read in s/day, bare or with its unit.
            (Role::RateChange, None) => Some(1.0),
            (Role::RateChange, Some(_)) => kind(Kind::ClockRate).map(|f| f * 86_400.0),
            (Role::Pressure, Some(_)) => kind(Kind::Pressure),
        };
        found.push(Found {
            role,
            header: header.trim().trim_matches('"').to_string(),
            index,
            unit,
            factor,
            offset: kelvin_or_fahrenheit.map_or(0.0, |(_, o)| o),
        });
    }
    found
}

/// Streams the columns `choose` picks from `path`, row by row (in SI, with
/// the file line), to `each`, in memory independent of the file's length.
/// Times are measured from the first row. Returns the file name, the roles
/// and header names used, and what was read.
pub fn stream_table<E: From<ReadError>>(
    source: Source<'_>,
    options: &ReadOptions,
    choose: &Choose<'_>,
    mut each: impl FnMut(&[f64], u64) -> Result<(), E>,
) -> Result<(String, Vec<Role>, Vec<String>, Format), E> {
    let Source {
        name: file,
        layout,
        reader: handle,
    } = source;
    let Opened {
        mut lines,
        mut converted,
        is_project,
    } = open_text(&file, layout, handle)?;
    // The first lines decide the separator; they are kept to be replayed.
    let sample = lines.sample()?;
    let shape = shape_of(&file, sample, is_project)?;
    let header = read_header(&file, options, &shape)?;
    let columns = choose_columns(&file, options, choose, &shape, &header)?;
    let names: Vec<String> = columns.used.iter().map(|f| f.header.clone()).collect();
    let mut format = format_of(&shape, &columns, names.clone(), &mut converted);
    let mut rows = Rows::new(&file, options, &shape, &columns);
    for (line_number, line) in shape.sample.iter().skip(shape.first_numeric) {
        if rows.read(*line_number, line, &mut format)? {
            each(&rows.row, *line_number)?;
        }
    }
    while let Some((number, line)) = lines.next_line()? {
        if rows.read(number, &line, &mut format)? {
            each(&rows.row, number)?;
        }
    }
    note_run(&file, options, rows.runs, &mut format)?;
    let converted = converted.as_ref().map(|(_, c)| c);
    note_left_out(
        &file,
        converted,
        &columns.used,
        &header.headers,
        &mut format,
    );
    Ok((file, columns.roles, names, format))
}

/// A refusal of the file called `file`: its name, then `message`.
fn refusal(file: &str, message: String) -> ReadError {
    ReadError::other(format!("{file}: {message}"))
}

/// A table's text read line by line within the limits of a measurement
/// file, each line numbered as the file numbers it.
struct Lines<'a, 'f> {
    /// The file, for messages.
    file: &'f str,
    /// The table's text.
    reader: Box<dyn BufRead + 'a>,
    /// The file's line of each line of a converted text (a TICC log's
    /// readings under their own line numbers).
    line_map: Vec<u64>,
    /// The lines read.
    raw_lines: usize,
    /// The bytes read.
    total: u64,
    /// The file's line of the latest line read.
    number: u64,
}

impl Lines<'_, '_> {
    /// The next line, without its line end or a byte-order mark, and its
    /// file line; `None` at the end. A file or a line over the limits is
    /// refused.
    fn next_line(&mut self) -> Result<Option<(u64, String)>, ReadError> {
        let fail = |message: String| refusal(self.file, message);
        let mut bytes = Vec::new();
        let read = (&mut self.reader)
            .take(MAX_LINE_BYTES + 1)
            .read_until(b'\n', &mut bytes)
            .map_err(|e| fail(format!("cannot read it: {e}")))?;
        if read == 0 {
            return Ok(None);
        }
        self.raw_lines += 1;
        let number = self
            .line_map
            .get(self.raw_lines - 1)
            .copied()
            .unwrap_or(self.number + 1);
        self.number = number;
        self.total += read as u64;
        if self.total > MAX_FILE_BYTES {
            return Err(fail(format!(
                "is larger than the {} GiB a measurement file may have",
                MAX_FILE_BYTES >> 30
            )));
        }
        if read as u64 > MAX_LINE_BYTES && bytes.last() != Some(&b'\n') {
            return Err(fail(format!(
                "line {number} is longer than {} KiB: not a table of numbers",
                MAX_LINE_BYTES >> 10
            )));
        }
        let text = String::from_utf8_lossy(&bytes);
        let text = text.trim_start_matches('\u{feff}');
        Ok(Some((
            number,
            text.trim_end_matches(['\n', '\r']).to_string(),
        )))
    }

    /// The first lines that are not blank or a `#` comment, up to
    /// `SNIFF_LINES` of them, each with its file line: what the layout is
    /// decided on.
    fn sample(&mut self) -> Result<Vec<(u64, String)>, ReadError> {
        let mut sample: Vec<(u64, String)> = Vec::new();
        while sample.len() < SNIFF_LINES {
            let Some((number, line)) = self.next_line()? else {
                break;
            };
            let t = line.trim();
            if t.is_empty() || t.starts_with('#') {
                continue;
            }
            sample.push((number, line));
        }
        Ok(sample)
    }
}

/// A file opened as a table's text.
struct Opened<'a, 'f> {
    /// Its lines.
    lines: Lines<'a, 'f>,
    /// For a format read whole: its name, and what its reader made of the
    /// file (the text taken out).
    converted: Option<(&'static str, Converted)>,
    /// Whether it is a Tracker project.
    is_project: bool,
}

/// Opens the bytes of `file` as a table's text: a format read whole (told
/// by the layout, else by the first bytes) is converted to text first.
/// Returns its lines and what the conversion made; a file that cannot be
/// read, is too large or that its format's reader refuses is refused.
fn open_text<'a, 'f>(
    file: &'f str,
    layout: Layout,
    handle: Box<dyn BufRead + 'a>,
) -> Result<Opened<'a, 'f>, ReadError> {
    let fail = |message: String| refusal(file, message);
    let mut handle = handle;
    // A format read whole: by the file's name, else by its first bytes.
    let whole = match layout {
        Layout::Whole(f) => Some(f),
        Layout::Text => match handle.fill_buf() {
            Ok(head) => crate::formats::by_contents(&head[..head.len().min(8192)]),
            Err(e) => return Err(fail(format!("cannot read it: {e}"))),
        },
    };
    let is_project = whole.is_some_and(|f| f.name == crate::tracker::FORMAT.name);
    let mut converted = None;
    let reader: Box<dyn BufRead + 'a> = if let Some(format) = whole {
        // Its contents become the table's text.
        let mut bytes = Vec::new();
        handle
            .take(MAX_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| fail(format!("cannot read it: {e}")))?;
        if bytes.len() as u64 > MAX_FILE_BYTES {
            return Err(fail(format!(
                "is larger than the {} GiB a measurement file may have",
                MAX_FILE_BYTES >> 30
            )));
        }
        let mut read = (format.read)(bytes).map_err(fail)?;
        let text = std::mem::take(&mut read.text);
        converted = Some((format.name, read));
        Box::new(std::io::Cursor::new(text.into_bytes()))
    } else {
        Box::new(handle.take(MAX_FILE_BYTES + 1))
    };
    // The file's line of each line of a converted text (a TICC log's
    // readings under their own line numbers).
    let line_map = converted
        .as_mut()
        .map(|c| std::mem::take(&mut c.1.lines))
        .unwrap_or_default();
    Ok(Opened {
        lines: Lines {
            file,
            reader,
            line_map,
            raw_lines: 0,
            total: 0,
            number: 0,
        },
        converted,
        is_project,
    })
}

/// How a table's lines split into cells and read as numbers.
#[derive(Clone, Copy)]
struct Dialect {
    /// What separates the cells.
    separator: Separator,
    /// Numbers are written with a decimal comma.
    decimal_comma: bool,
}

impl Dialect {
    /// Whether `line` is a row of numbers.
    fn numeric(self, line: &str) -> bool {
        is_numeric(&self.separator.split(line), self.decimal_comma)
    }

    /// The number of cells of `line`.
    fn width_of(self, line: &str) -> usize {
        self.separator.split(line).len()
    }
}

/// The layout of a table, read from its first lines.
struct Shape {
    /// The separator and the decimal mark.
    dialect: Dialect,
    /// The separator's name, for the output's `format.separator`.
    separator_name: &'static str,
    /// The separator and the decimal mark in words, for messages.
    shown_separator: String,
    /// The first lines, each with its file line (the rows among them are
    /// replayed).
    sample: Vec<(u64, String)>,
    /// The number of cells of a row of numbers.
    width: usize,
    /// The first row of numbers, in `sample`.
    first_numeric: usize,
}

/// The layout of a table whose first lines are `sample`: its separator and
/// decimal mark sniffed, its rows the numeric lines of the most common
/// width. A table without rows of numbers is refused (a Tracker project
/// told how to export its data).
fn shape_of(file: &str, sample: Vec<(u64, String)>, is_project: bool) -> Result<Shape, ReadError> {
    let texts: Vec<String> = sample.iter().map(|(_, l)| l.clone()).collect();
    let (separator, separator_name, decimal_comma) = sniff(&texts);
    let shown_separator = shown_separator(separator, separator_name, decimal_comma);
    let dialect = Dialect {
        separator,
        decimal_comma,
    };
    let width = row_width(&sample, dialect);
    let first_numeric = sample
        .iter()
        .position(|(_, l)| dialect.numeric(l) && Some(dialect.width_of(l)) == width);
    let Some(first_numeric) = first_numeric else {
        return Err(refusal(
            file,
            format!(
                "no rows of numbers found (read as {shown_separator}){}",
                if is_project {
                    "; a Tracker project (.trk) holds its data as XML: export the track's data \
                     table from Tracker (File > Export > Data) and give that file"
                } else {
                    ""
                }
            ),
        ));
    };
    Ok(Shape {
        dialect,
        separator_name,
        shown_separator,
        sample,
        width: width.unwrap_or(1),
        first_numeric,
    })
}

/// The separator and the decimal mark in words, for messages: `one
/// column`, `comma-separated`, `tab-separated with decimal commas`.
fn shown_separator(separator: Separator, separator_name: &str, decimal_comma: bool) -> String {
    if separator == Separator::Whole {
        format!(
            "one column{}",
            if decimal_comma {
                " with decimal commas"
            } else {
                ""
            }
        )
    } else if decimal_comma {
        format!("{separator_name}-separated with decimal commas")
    } else {
        format!("{separator_name}-separated")
    }
}

/// The number of cells of a table's rows, read from its first lines
/// `sample`; `None` if none of them is a row of numbers.
fn row_width(sample: &[(u64, String)], dialect: Dialect) -> Option<usize> {
    // The rows of data are the numeric lines of the most common width;
    // numeric lines of another width before the first of them are the
    // file's metadata (a logger's settings), named by the line above.
    let numeric = |l: &str| dialect.numeric(l);
    let width_of = |l: &str| dialect.width_of(l);
    let mut widths: Vec<(usize, usize)> = Vec::new();
    for (_, l) in sample.iter().filter(|(_, l)| numeric(l)) {
        let w = width_of(l);
        match widths.iter_mut().find(|(n, _)| *n == w) {
            Some(e) => e.1 += 1,
            None => widths.push((w, 1)),
        }
    }
    // On a tie (a short file), the width whose first row sits under a
    // header of as many names, then the wider.
    let under_header = |w: usize| {
        sample
            .iter()
            .position(|(_, l)| numeric(l) && width_of(l) == w)
            .and_then(|i| i.checked_sub(1))
            .is_some_and(|i| !numeric(&sample[i].1) && width_of(&sample[i].1) == w)
    };
    widths
        .iter()
        .max_by_key(|&&(w, c)| (c, under_header(w), w))
        .map(|&(w, _)| w)
}

/// What stands above a table's rows.
struct Header {
    /// The names of the columns, from the header line or `--columns`.
    headers: Vec<String>,
    /// The file's settings (a logger's), each name with its value.
    metadata: Vec<(String, f64)>,
}

/// Reads what stands above the rows of a table of `shape`: the file's
/// settings, and the names of the columns from the line over the first
/// row or `--columns`. A header run together with the first row, a
/// missing one, or one naming other columns than the rows hold is refused.
fn read_header(file: &str, options: &ReadOptions, shape: &Shape) -> Result<Header, ReadError> {
    let (metadata, settings_line) = settings(shape);
    let header_line = shape
        .first_numeric
        .checked_sub(1)
        .filter(|&i| Some(i) != settings_line)
        .map(|i| shape.sample[i].1.as_str())
        .filter(|l| !shape.dialect.numeric(l));
    refuse_glued(file, shape, header_line)?;
    let headers: Vec<String> = match (&options.columns, header_line) {
        (Some(names), _) => names.clone(),
        (None, None) => return Err(no_header(file, options, &metadata, shape.width)),
        (None, Some(line)) => header_cells(file, options, shape, line)?,
    };
    Ok(Header { headers, metadata })
}

/// The file's settings above the rows of a table of `shape`, each name
/// with its value, and the line (in the sample) of the last settings'
/// numbers, if any.
fn settings(shape: &Shape) -> (Vec<(String, f64)>, Option<usize>) {
    let Dialect {
        separator,
        decimal_comma,
    } = shape.dialect;
    let sample = &shape.sample;
    // Settings: a line of names over a line of as many numbers, under any
    // separator (a one-column file's settings are comma-separated).
    let mut metadata: Vec<(String, f64)> = Vec::new();
    let mut settings_line = None;
    for j in 1..shape.first_numeric {
        let (names, values) = (&sample[j - 1].1, &sample[j].1);
        let pair = [
            separator,
            Separator::Char(','),
            Separator::Char(';'),
            Separator::Char('\t'),
            Separator::Spaces,
        ]
        .into_iter()
        .map(|sep| (sep.split(names), sep.split(values)))
        .find(|(n, v)| {
            n.len() == v.len()
                && v.len() > 1
                && !is_numeric(n, decimal_comma)
                && v.iter()
                    .all(|c| matches!(cell_value(c, decimal_comma), Some(Some(_))))
        });
        if let Some((n, v)) = pair {
            for (n, v) in n.iter().zip(&v) {
                if let Some(Some(v)) = cell_value(v, decimal_comma) {
                    metadata.push((n.trim().trim_matches('"').to_string(), v));
                }
            }
            settings_line = Some(j);
        }
    }
    (metadata, settings_line)
}

/// Refuses a header line of a table of `shape` that holds the first row
/// of numbers too.
fn refuse_glued(file: &str, shape: &Shape, header_line: Option<&str>) -> Result<(), ReadError> {
    let Dialect {
        separator,
        decimal_comma,
    } = shape.dialect;
    // A header run together with the first row (its line end lost) is
    // refused by its line, with --columns too: it was taken as the header,
    // or skipped under --columns, and its row dropped without a word.
    if let Some((names, row)) = header_line.and_then(|line| {
        let join = match separator {
            Separator::Char('\t') | Separator::Spaces | Separator::Whole => " ".to_string(),
            Separator::Char(c) => c.to_string(),
        };
        glued_row(&separator.split(line), shape.width, decimal_comma, &join)
    }) {
        return Err(refusal(
            file,
            format!(
                "line {} holds the header and the first row of numbers run together \
                 ('{names}' then '{row}'): put the row on a line of its own",
                shape.sample[shape.first_numeric - 1].0
            ),
        ));
    }
    Ok(())
}

/// The refusal of a table without a header line (`width` cells a row),
/// naming the settings read above its rows and how to name its columns.
fn no_header(
    file: &str,
    options: &ReadOptions,
    metadata: &[(String, f64)],
    width: usize,
) -> ReadError {
    let described = || {
        metadata
            .iter()
            .map(|(n, v)| format!("{n} = {v}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let above = if metadata.is_empty() {
        String::new()
    } else {
        format!(
            " (the lines above the data are read as the file's settings: {})",
            described()
        )
    };
    if options.no_columns_flag {
        return refusal(
            file,
            format!(
                "no header line{above}: name the columns in a first line (e.g. \
                 time_s,temperature_c)"
            ),
        );
    }
    refusal(
        file,
        format!(
            "no header line{above}: name the columns with --columns (e.g. --columns \
             time_s,angle_deg{})",
            if width == 1 {
                ", or angle_deg alone"
            } else {
                ""
            }
        ),
    )
}

/// The names of the columns of a table of `shape`, the cells of its
/// header `line`. A header that names more or fewer columns than the rows
/// hold is refused.
fn header_cells(
    file: &str,
    options: &ReadOptions,
    shape: &Shape,
    line: &str,
) -> Result<Vec<String>, ReadError> {
    let (separator, width) = (shape.dialect.separator, shape.width);
    let mut cells: Vec<String> = separator
        .split(line)
        .into_iter()
        .map(String::from)
        .collect();
    let named: Vec<&String> = cells.iter().filter(|c| !c.trim().is_empty()).collect();
    // `x y dx dy` written with spaces in a tab-separated file.
    if named.len() == 1 && named[0].split_whitespace().count() == width {
        cells = named[0].split_whitespace().map(String::from).collect();
    }
    // A header must name the columns the rows hold: names over
    // columns that are not there shift every meaning.
    let names = cells.iter().filter(|c| !c.trim().is_empty()).count();
    let held = shape.sample[shape.first_numeric..]
        .iter()
        .filter(|(_, l)| shape.dialect.numeric(l) && shape.dialect.width_of(l) == width)
        .map(|(_, l)| {
            separator
                .split(l)
                .iter()
                .filter(|c| !c.trim().is_empty())
                .count()
        })
        .max()
        .unwrap_or(width);
    if names != held && cells.len() != width {
        return Err(refusal(
            file,
            format!(
                "the header (line {}) names {names} columns ({}) where the rows hold {held}: \
                 {}",
                shape.sample[shape.first_numeric - 1].0,
                cells
                    .iter()
                    .filter(|c| !c.trim().is_empty())
                    .cloned()
                    .collect::<Vec<_>>()
                    .join(", "),
                if options.no_columns_flag {
                    "give each row a cell under each name (numbers with a decimal comma \
                     need a semicolon or a tab between the cells)"
                } else {
                    "name the columns with --columns (e.g. --columns time_s,angle_deg)"
                }
            ),
        ));
    }
    Ok(cells)
}

/// The columns a table is read by.
struct Columns {
    /// The roles chosen, in the order asked for.
    roles: Vec<Role>,
    /// Their columns, in the same order.
    used: Vec<Found>,
    /// The rate times are made from: `--frame-rate`, or the file's sample
    /// rate for a file that writes no times.
    rate: Option<f64>,
}

/// The columns `choose` picks among those `header` names (a time column
/// made from the file's sample rate when it writes none). A choice refused,
/// or a column chosen that cannot be read in SI, is refused.
fn choose_columns(
    file: &str,
    options: &ReadOptions,
    choose: &Choose<'_>,
    shape: &Shape,
    header: &Header,
) -> Result<Columns, ReadError> {
    let (headers, metadata) = (&header.headers, &header.metadata);
    let shown_separator = &shape.shown_separator;
    // A logger's sample rate among the settings makes the times of a file
    // that writes none.
    let file_rate = metadata
        .iter()
        .find(|(n, _)| is_rate_name(n))
        .map(|&(_, v)| v)
        .filter(|v| *v > 0.0 && v.is_finite());
    let mut found = find_columns(headers, options);
    let made_time = options.frame_rate.is_none()
        && file_rate.is_some()
        && !found.iter().any(|f| f.role == Role::Time);
    if made_time {
        found.push(Found {
            role: Role::Time,
            header: format!(
                "time from the file's sample rate ({} Hz)",
                file_rate.unwrap_or(0.0)
            ),
            index: MADE_COLUMN,
            unit: None,
            factor: Some(1.0),
            offset: 0.0,
        });
    }
    let rate = options.frame_rate.or(file_rate.filter(|_| made_time));
    let roles = choose(&found).map_err(|m| {
        refusal(
            file,
            format!(
                "{m} (found: {}; read as {shown_separator})",
                headers.join(", ")
            ),
        )
    })?;
    let mut used: Vec<Found> = Vec::with_capacity(roles.len());
    for role in &roles {
        let f = found
            .iter()
            .find(|f| f.role == *role)
            .expect("choose returns found roles");
        check_unit(file, f)?;
        used.push(f.clone());
    }
    Ok(Columns { roles, used, rate })
}

/// Refuses a column chosen without a factor to SI: ticks without the
/// clock's rate, an angle without a unit, or a unit not of its kind.
fn check_unit(file: &str, f: &Found) -> Result<(), ReadError> {
    match (&f.unit, f.factor) {
        (_, Some(_)) => Ok(()),
        (_, None) if f.role == Role::Ticks => Err(refusal(
            file,
            format!(
                "column '{}' counts a clock's ticks: give the clock's rate with --tick-rate \
                 HZ",
                f.header
            ),
        )),
        (None, None) => Err(refusal(
            file,
            format!(
                "column '{}' has no unit: give --angle-unit deg or --angle-unit rad",
                f.header
            ),
        )),
        (Some(u), None) => Err(refusal(
            file,
            format!(
                "column '{}': '{u}' is not a unit of {} (use {})",
                f.header,
                f.role.name(),
                units_for(f.role)
            ),
        )),
    }
}

/// What is read from a table of `shape` by `columns` (headed `names`),
/// before its rows: the sheet and track of a converted file are taken out
/// of `converted`.
fn format_of(
    shape: &Shape,
    columns: &Columns,
    names: Vec<String>,
    converted: &mut Option<(&'static str, Converted)>,
) -> Format {
    Format {
        separator: shape.separator_name,
        decimal: if shape.dialect.decimal_comma {
            "comma"
        } else {
            "point"
        },
        columns_used: names,
        rows: 0,
        skipped_rows: 0,
        skipped_lines: Vec::new(),
        notes: Vec::new(),
        frame_rate: columns.rate,
        reader: converted.as_ref().map_or("text table", |c| c.0),
        tracker_track: converted.as_mut().and_then(|c| c.1.track.take()),
        sheet: converted.as_mut().and_then(|c| c.1.sheet.take()),
        angular_velocity_columns: Vec::new(),
        window_s: None,
        repeated_rows_dropped: None,
        run: None,
        runs: None,
        readings_per_time: None,
        gate_labels: Vec::new(),
        time_origin_s: None,
    }
}

/// The reading of a table's rows: what each is read against, the row
/// read, and what the rows before it left.
struct Rows<'s> {
    /// The file, for messages.
    file: &'s str,
    options: &'s ReadOptions,
    shape: &'s Shape,
    /// The columns used, in the order of `row`.
    used: &'s [Found],
    /// The time (or ticks) column, in `row`.
    time_column: Option<usize>,
    /// The rate times are made from.
    rate: Option<f64>,
    /// The latest row read, in SI.
    row: Vec<f64>,
    /// The time of the first row of the run read, as written.
    first_time: Option<f64>,
    /// The rows of numbers read so far.
    index: u64,
    /// The run being read (from 1), and its first and latest times.
    runs: usize,
    run_span: Option<(f64, f64)>,
    /// The days passed (times of day past midnight), s.
    day_offset: f64,
    /// Whether the date-times read so far have an offset from UTC.
    time_offsets: Option<bool>,
}

impl<'s> Rows<'s> {
    /// Ready to read the rows of `file`, a table of `shape`, by `columns`.
    fn new(
        file: &'s str,
        options: &'s ReadOptions,
        shape: &'s Shape,
        columns: &'s Columns,
    ) -> Self {
        Rows {
            file,
            options,
            shape,
            used: &columns.used,
            time_column: columns
                .roles
                .iter()
                .position(|&r| r == Role::Time || r == Role::Ticks),
            rate: columns.rate,
            row: vec![0.0; columns.used.len()],
            first_time: None,
            index: 0,
            runs: 1,
            run_span: None,
            day_offset: 0.0,
            time_offsets: None,
        }
    }

    /// Reads `line` (the file's line `line_number`) into `self.row`,
    /// counting it in `format`. Returns whether it is a row to hand on (not
    /// blank or a comment, without a blank cell, in the run read); a line
    /// that cannot be read is refused.
    fn read(
        &mut self,
        line_number: u64,
        line: &str,
        format: &mut Format,
    ) -> Result<bool, ReadError> {
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            return Ok(false);
        }
        let cells = self.shape.dialect.separator.split(line);
        self.refuse_extra_cells(line_number, &cells)?;
        let row_index = self.index;
        self.index += 1;
        let blank = self.read_cells(line_number, &cells, format)?;
        if blank {
            format.skipped_rows += 1;
            if format.skipped_lines.len() < 3 {
                format.skipped_lines.push(line_number);
            }
            return Ok(false);
        }
        if let Some(k) = self.time_column {
            if !self.place_time(k, row_index, line_number, format)? {
                return Ok(false);
            }
        }
        format.rows += 1;
        if format.rows > MAX_ROWS {
            return Err(refusal(
                self.file,
                format!(
                    "has more than {MAX_ROWS} rows of numbers, the most a measurement file may have"
                ),
            ));
        }
        Ok(true)
    }

    /// Refuses a line of numbers with more cells than the table's rows hold.
    fn refuse_extra_cells(&self, line_number: u64, cells: &[&str]) -> Result<(), ReadError> {
        let Dialect {
            separator,
            decimal_comma,
        } = self.shape.dialect;
        let (width, shown_separator) = (self.shape.width, &self.shape.shown_separator);
        // A row of numbers with more cells than the table's rows hold
        // would shift no meaning, but says the file is not what it seems.
        if self.options.columns.is_none()
            && cells.len() > width
            && cells[width..].iter().any(|c| !c.trim().is_empty())
            && is_numeric(cells, decimal_comma)
        {
            return Err(refusal(
                self.file,
                format!(
                    "line {line_number} holds {} cells where the rows before it hold {width} \
                     (read as {shown_separator}){}",
                    cells.len(),
                    if separator == Separator::Char(',') {
                        ": numbers with a decimal comma need a semicolon or a tab between the cells"
                    } else {
                        ""
                    }
                ),
            ));
        }
        Ok(())
    }

    /// Reads the cells of the columns used into `self.row`, in SI (a gate's
    /// label as its number, new labels added to `format`). Returns whether
    /// one of them is blank; a cell that is not a number is refused.
    fn read_cells(
        &mut self,
        line_number: u64,
        cells: &[&str],
        format: &mut Format,
    ) -> Result<bool, ReadError> {
        let mut blank = false;
        let used = self.used;
        for (k, f) in used.iter().enumerate() {
            if f.index == MADE_COLUMN {
                continue; // Made from the rate below.
            }
            let cell = cells.get(f.index).copied().unwrap_or("");
            if f.role == Role::Gate {
                match gate_number(&mut format.gate_labels, cell) {
                    Some(i) => self.row[k] = i,
                    None => blank = true,
                }
                continue;
            }
            if Some(k) == self.time_column {
                self.check_offset(line_number, f, cell)?;
            }
            match cell_value(cell, self.shape.dialect.decimal_comma) {
                Some(Some(v)) => self.row[k] = v * f.factor.unwrap_or(1.0) + f.offset,
                Some(None) if self.options.refuse_blank => {
                    return Err(refusal(
                        self.file,
                        format!(
                            "line {line_number}, column {}: empty: every row of this file needs \
                             a value in every column it uses (fill the cell, or leave the column \
                             out)",
                            f.header
                        ),
                    ));
                }
                Some(None) => blank = true,
                None => return Err(self.not_a_number(line_number, f, cell)),
            }
        }
        Ok(blank)
    }

    /// Refuses a date-time `cell` of the time column `f` with an offset
    /// from UTC after times without one, or the other way round.
    fn check_offset(&mut self, line_number: u64, f: &Found, cell: &str) -> Result<(), ReadError> {
        // Date-times with an offset and without one do not mix:
        // the naive ones would be read as UTC, hours away.
        if let Some(offset) = datetime_has_offset(cell) {
            match self.time_offsets {
                Some(first) if first != offset => {
                    return Err(refusal(
                        self.file,
                        format!(
                            "line {line_number}, column {}: '{}' {} where the times \
                             before it {}: give every time its offset, or none",
                            f.header,
                            cell.trim(),
                            if offset {
                                "has an offset from UTC"
                            } else {
                                "has no offset from UTC"
                            },
                            if first { "have one" } else { "have none" }
                        ),
                    ));
                }
                _ => self.time_offsets = Some(offset),
            }
        }
        Ok(())
    }

    /// The refusal of a `cell` of column `f` that is not a finite number.
    fn not_a_number(&self, line_number: u64, f: &Found, cell: &str) -> ReadError {
        let shown_separator = &self.shape.shown_separator;
        // A NaN or infinite cell in the library's words (the
        // same value from Python gets the same sentence).
        let what = match cell.trim().trim_matches('"').parse::<f64>() {
            Ok(v) if v.is_nan() => {
                "must be a finite number, got a value that is not a number".to_string()
            }
            Ok(_) => "must be a finite number, got an infinite value".to_string(),
            Err(_) => format!("'{cell}' is not a number (read as {shown_separator})"),
        };
        refusal(
            self.file,
            format!("line {line_number}, column {}: {what}", f.header),
        )
    }

    /// Sets the time in column `k` of the row counted `row_index`: made
    /// from the rate, kept as written, or measured from the first row of
    /// the run read (setting `format`'s origin). Returns whether the row is
    /// in the run read.
    fn place_time(
        &mut self,
        k: usize,
        row_index: u64,
        line_number: u64,
        format: &mut Format,
    ) -> Result<bool, ReadError> {
        if let Some(rate) = self.rate {
            // Frames counted from the first row of numbers.
            self.row[k] = row_index as f64 / rate;
        } else if self.options.absolute_time {
            format.time_origin_s = Some(0.0);
        } else {
            self.follow_runs(k, line_number)?;
            if self.options.run.is_some_and(|want| want != self.runs) {
                return Ok(false);
            }
            let origin = *self.first_time.get_or_insert(self.row[k]);
            format.time_origin_s = Some(origin);
            self.row[k] -= origin;
        }
        Ok(true)
    }

    /// Carries the time in column `k` past midnight into the next day, and
    /// counts a time that goes back as the start of a new run; without
    /// `--run`, a time that goes back is refused.
    fn follow_runs(&mut self, k: usize, line_number: u64) -> Result<(), ReadError> {
        // Times that go back over half the run so far start a new
        // run (a logger restarted, runs pasted one after another).
        // Times of day that pass midnight go on into the next day.
        if let Some((_, previous)) = self.run_span {
            let raw = self.row[k] + self.day_offset;
            if (82_800.0..86_400.0).contains(&(previous - self.day_offset))
                && (0.0..3_600.0).contains(&(raw - self.day_offset))
                && raw < previous
            {
                self.day_offset += 86_400.0;
            }
        }
        self.row[k] += self.day_offset;
        let raw = self.row[k];
        if let Some((start, previous)) = self.run_span {
            if raw < previous && raw <= start + 0.5 * (previous - start) {
                self.runs += 1;
                if self.options.run.is_none() {
                    return Err(refusal(
                        self.file,
                        format!(
                            "line {line_number}, column {}: {raw} is not after the \
                             previous {previous}: sort the rows by time, or, if the file \
                             holds runs one after another (the times restart), give --run 1 \
                             for the first, --run 2 for the next, …",
                            self.used[k].header
                        ),
                    ));
                }
                self.run_span = Some((raw, raw));
            } else {
                self.run_span = Some((start, raw));
            }
        } else {
            self.run_span = Some((raw, raw));
        }
        Ok(())
    }
}

/// The number of a gate's label in `cell`, labels numbered in the order
/// first seen (a new one added to `labels`); `None` for a blank cell.
fn gate_number(labels: &mut Vec<String>, cell: &str) -> Option<f64> {
    // A label, numbered in the order first seen.
    let label = cell.trim().trim_matches('"');
    if label.is_empty() {
        return None;
    }
    let i = match labels.iter().position(|l| l == label) {
        Some(i) => i,
        None => {
            labels.push(label.to_string());
            labels.len() - 1
        }
    };
    Some(i as f64)
}

/// Notes in `format` the run read (`--run`) and the runs `file` holds; a
/// run it does not hold is refused.
fn note_run(
    file: &str,
    options: &ReadOptions,
    runs: usize,
    format: &mut Format,
) -> Result<(), ReadError> {
    if let Some(want) = options.run {
        if want > runs {
            return Err(ReadError::option(
                "run",
                format!(
                    "{file} holds {runs} run{}; there is no run {want}",
                    if runs == 1 { "" } else { "s" }
                ),
            ));
        }
        format.run = Some(want);
        format.runs = Some(runs);
    }
    Ok(())
}

/// Notes, among what the reader says, what was left out of `file`: what
/// the format's reader left out (`converted`), the rows skipped for a blank
/// cell, and columns of a kind after the first of `headers`.
fn note_left_out(
    file: &str,
    converted: Option<&Converted>,
    used: &[Found],
    headers: &[String],
    format: &mut Format,
) {
    // Nothing left out without a word: what the format's reader left
    // out, rows skipped for a blank cell, and columns of a kind after the
    // first, which are not read.
    if let Some(c) = converted {
        format
            .notes
            .extend(c.notes.iter().map(|n| format!("{file}: {n}")));
    }
    if format.skipped_rows > 0 {
        let shown: Vec<String> = format.skipped_lines.iter().map(u64::to_string).collect();
        format.notes.push(format!(
            "{file}: {} row{} with a blank cell in a column used skipped (line{} {}{})",
            format.skipped_rows,
            if format.skipped_rows == 1 { "" } else { "s" },
            if format.skipped_rows == 1 { "" } else { "s" },
            shown.join(", "),
            if format.skipped_rows > shown.len() {
                ", …"
            } else {
                ""
            }
        ));
    }
    for f in used {
        let others: Vec<String> = headers
            .iter()
            .enumerate()
            .filter(|&(i, h)| i != f.index && Role::of(&split_header(h).0) == Some(f.role))
            .map(|(i, h)| format!("{} ('{}')", i + 1, h.trim().trim_matches('"')))
            .collect();
        if !others.is_empty() && f.index != MADE_COLUMN {
            format.notes.push(format!(
                "{file}: column {} ('{}') is read as the {}; column{} {} of the same kind {} not",
                f.index + 1,
                f.header,
                f.role.name(),
                if others.len() == 1 { "" } else { "s" },
                others.join(", "),
                if others.len() == 1 { "is" } else { "are" }
            ));
        }
    }
}

/// A chooser for commands that need exactly these roles (each given as
/// alternatives, the first found wins): `[[Time], [Angle]]`.
pub fn need<'a>(groups: &'a [&'a [Role]]) -> impl Fn(&[Found]) -> Result<Vec<Role>, String> + 'a {
    move |found: &[Found]| {
        let mut out = Vec::new();
        for group in groups {
            match group.iter().find(|r| found.iter().any(|f| f.role == **r)) {
                Some(r) => out.push(*r),
                None => {
                    let names: Vec<&str> = group.iter().map(|r| r.name()).collect();
                    return Err(format!("no {} column", names.join(" or ")));
                }
            }
        }
        Ok(out)
    }
}

/// The number of cells of the first data line of a file with no header
/// (its first line that is not blank or a `#` comment is all numbers),
/// or `None` (a header, an unreadable file): for commands that read a
/// bare column or two of a stability program's export.
pub fn headerless_width(reader: impl BufRead) -> Option<usize> {
    let reader = reader.take(MAX_LINE_BYTES * 4);
    for line in reader.lines() {
        let line = line.ok()?;
        let t = line.trim().trim_start_matches('\u{feff}');
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        let cells: Vec<&str> = t
            .split(|c: char| c == ',' || c == ';' || c == '\t' || c.is_whitespace())
            .filter(|c| !c.is_empty())
            .collect();
        let numeric = cells
            .iter()
            .all(|c| cell_value(c, false).is_some_and(|v| v.is_some()));
        return numeric.then_some(cells.len());
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A phone's copies of a sample, as a real phyphox export has them:
    /// under the same time (dropped), under the time before (the copy
    /// runs back: dropped), and under the next time, which the next
    /// sample then takes again (the copy is the row before: dropped, the
    /// sample kept); a schedule's repeated setting under an earlier time
    /// is left for the time check.
    #[test]
    fn copies_of_a_sample_are_dropped_wherever_their_time_puts_them() {
        let t = vec![0.0, 0.01, 0.02, 0.02, 0.03, 0.02, 0.04, 0.05, 0.05, 0.07];
        let a = vec![1.0, 2.0, 3.0, 3.0, 4.0, 4.0, 5.0, 5.0, 6.0, 7.0];
        let b = vec![9.0, 8.0, 7.0, 7.0, 6.0, 6.0, 5.0, 5.0, 4.0, 3.0];
        let lines: Vec<u64> = (1..=10).collect();
        let mut values = vec![t.clone(), a.clone(), b.clone()];
        let mut kept = lines.clone();
        let dropped = drop_repeated_rows(&mut values, &mut kept, 0, true);
        assert_eq!(dropped, vec![4, 6, 8]);
        assert_eq!(values[0], vec![0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.07]);
        assert_eq!(values[1], vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
        // A schedule: only the exact copy goes.
        let mut values = vec![t, a, b];
        let mut kept = lines;
        assert_eq!(
            drop_repeated_rows(&mut values, &mut kept, 0, false),
            vec![4]
        );
    }

    #[test]
    fn header_names_with_units() {
        let cases = [
            ("time_s", "time", Some("s")),
            ("Time (s)", "time", Some("s")),
            ("t [s]", "t", Some("s")),
            ("t_{1}", "t", None),
            ("angle_deg", "angle", Some("deg")),
            ("θ (rad)", "θ", Some("rad")),
            ("amplitude (deg)", "amplitude", Some("deg")),
            ("x", "x", None),
            ("amplitude_rad", "amplitude", Some("rad")),
            ("temperature_c", "temperature", Some("c")),
            ("Pressure (hPa)", "pressure", Some("hpa")),
            ("drive_factor", "drive_factor", None),
        ];
        for (header, base, unit) in cases {
            let (b, u) = split_header(header);
            assert_eq!(b, base, "{header}");
            assert_eq!(u.as_deref(), unit, "{header}");
        }
    }

    #[test]
    fn separators_and_decimal_commas() {
        let lines = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let (s, name, comma) = sniff(&lines(&[
            "t\tx\ty",
            "0.0\t0.41\t-1.41",
            "0.03\t0.40\t-1.42",
        ]));
        assert_eq!((s, name, comma), (Separator::Char('\t'), "tab", false));
        let (_, name, comma) = sniff(&lines(&["zeit;winkel", "0,0;5,2", "0,5;4,9"]));
        assert_eq!((name, comma), ("semicolon", true));
        let (_, name, _) = sniff(&lines(&["  t    angle", "  0.0  5.0", "  0.1  4.9"]));
        assert_eq!(name, "spaces");
        let (_, name, comma) = sniff(&lines(&["time (s),amplitude (rad)", "0,0.1", "1,0.09"]));
        assert_eq!((name, comma), ("comma", false));
    }
}

#[cfg(test)]
mod offsets {
    use super::{datetime_seconds, utc_offset_hours};

    /// Offsets from UTC as the world has them, -12:00 to +14:00; jiff
    /// takes them to ±25:59, which no clock's log holds (a new user's
    /// `+25:00` was read).
    #[test]
    fn only_the_worlds_offsets_are_read() {
        assert_eq!(utc_offset_hours("2024-07-19T09:27:13+02:00"), Some(2.0));
        assert_eq!(utc_offset_hours("2024-07-19 09:27:13.5-0530"), Some(-5.5));
        assert_eq!(utc_offset_hours("2024-07-19T09:27:13Z"), None);
        let utc = datetime_seconds("2024-07-19T09:27:13Z").unwrap();
        let kiribati = datetime_seconds("2024-07-19T23:27:13+14:00").unwrap();
        assert_eq!(utc, kiribati);
        assert!(datetime_seconds("2024-07-19T09:27:13-12:00").is_some());
        assert!(datetime_seconds("2024-07-19T09:27:13+25:00").is_none());
        assert!(datetime_seconds("2024-07-19T09:27:13-12:30").is_none());
    }
}
