//! Reading measurement files: CSV with a header, `#` comment lines and
//! empty lines skipped, columns found by name. Every refusal names the
//! file, and where it can the line and the column.

use crate::error::CliError;
use std::path::Path;

/// One column wanted: its accepted names, each with the factor to SI.
pub struct Wanted {
    /// What it is, for messages ("time", "amplitude").
    pub what: &'static str,
    /// Accepted header names and the factor that turns their values into SI.
    pub names: &'static [(&'static str, f64)],
}

/// Columns read from a file, in SI.
pub struct Columns {
    /// The file, as given.
    pub file: String,
    /// The header name found for each wanted column.
    pub names: Vec<&'static str>,
    /// Values, one vector per wanted column.
    pub values: Vec<Vec<f64>>,
    /// The file line of each row, for messages.
    pub lines: Vec<u64>,
}

impl Columns {
    /// An error about row `row`, column `column`.
    pub fn error_at(&self, row: usize, column: usize, message: impl std::fmt::Display) -> CliError {
        CliError::other(format!(
            "{}: line {}, column {}: {message}",
            self.file, self.lines[row], self.names[column]
        ))
    }

    /// Checks that column `column` strictly increases.
    pub fn require_increasing(&self, column: usize) -> Result<(), CliError> {
        let v = &self.values[column];
        match (1..v.len()).find(|&i| v[i] <= v[i - 1]) {
            Some(i) => Err(self.error_at(
                i,
                column,
                format!(
                    "{} is not after the previous {}; sort the file by {}",
                    v[i],
                    v[i - 1],
                    self.names[column]
                ),
            )),
            None => Ok(()),
        }
    }

    /// Checks that the amplitudes of column `column` (radians) are below
    /// 180°: a pendulum released at or past the top never swings back.
    pub fn require_swing(&self, column: usize) -> Result<(), CliError> {
        let v = &self.values[column];
        match v.iter().position(|&x| x.abs() >= std::f64::consts::PI) {
            Some(i) => Err(self.error_at(
                i,
                column,
                format!(
                    "an amplitude of {}° is not a swing (it must be below 180°)",
                    crate::output::num(v[i].to_degrees(), 8)
                ),
            )),
            None => Ok(()),
        }
    }

    /// Checks that column `column` is positive throughout.
    pub fn require_positive(&self, column: usize) -> Result<(), CliError> {
        match self.values[column].iter().position(|&x| x <= 0.0) {
            Some(i) => Err(self.error_at(
                i,
                column,
                format!("must be positive, got {}", self.values[column][i]),
            )),
            None => Ok(()),
        }
    }
}

/// Reads the wanted columns of `path` into memory.
pub fn read_columns(path: &Path, wanted: &[Wanted]) -> Result<Columns, CliError> {
    let mut values: Vec<Vec<f64>> = vec![Vec::new(); wanted.len()];
    let mut lines = Vec::new();
    let (file, names) = stream_columns(path, wanted, |row, line| {
        for (column, v) in values.iter_mut().zip(row) {
            column.push(*v);
        }
        lines.push(line);
        Ok(())
    })?;
    Ok(Columns {
        file,
        names,
        values,
        lines,
    })
}

/// Streams the wanted columns of `path`, row by row (in SI, with the file
/// line), to `each`, in memory independent of the file's length. Returns
/// the file name and the header names found.
pub fn stream_columns(
    path: &Path,
    wanted: &[Wanted],
    mut each: impl FnMut(&[f64], u64) -> Result<(), CliError>,
) -> Result<(String, Vec<&'static str>), CliError> {
    let file = path.display().to_string();
    let fail = |message: String| CliError::other(format!("{file}: {message}"));
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_path(path)
        .map_err(|e| fail(format!("cannot read it: {}", io_message(&e))))?;
    let headers = reader
        .headers()
        .map_err(|e| fail(format!("cannot read its header: {}", io_message(&e))))?
        .clone();
    let mut indices = Vec::with_capacity(wanted.len());
    let mut names = Vec::with_capacity(wanted.len());
    let mut factors = Vec::with_capacity(wanted.len());
    for w in wanted {
        let found = w.names.iter().find_map(|&(name, factor)| {
            headers
                .iter()
                .position(|h| h == name)
                .map(|i| (i, name, factor))
        });
        let Some((index, name, factor)) = found else {
            let accepted: Vec<&str> = w.names.iter().map(|(n, _)| *n).collect();
            return Err(fail(format!(
                "no {} column: the header needs {} (found: {})",
                w.what,
                accepted.join(" or "),
                headers.iter().collect::<Vec<_>>().join(",")
            )));
        };
        indices.push(index);
        names.push(name);
        factors.push(factor);
    }
    let mut row = vec![0.0; wanted.len()];
    let mut record = csv::StringRecord::new();
    loop {
        match reader.read_record(&mut record) {
            Ok(false) => break,
            Ok(true) => {}
            Err(e) => {
                let line = e.position().map_or(0, |p| p.line());
                return Err(fail(format!("line {line}: {}", io_message(&e))));
            }
        }
        let line = record.position().map_or(0, |p| p.line());
        for (k, &i) in indices.iter().enumerate() {
            let cell = record.get(i).unwrap_or("");
            let value: f64 = match cell.parse::<f64>() {
                Ok(v) if v.is_finite() => v,
                _ => {
                    return Err(fail(format!(
                        "line {line}, column {}: '{cell}' is not a finite number",
                        names[k]
                    )))
                }
            };
            row[k] = value * factors[k];
        }
        each(&row, line)?;
    }
    Ok((file, names))
}

fn io_message(e: &csv::Error) -> String {
    match e.kind() {
        csv::ErrorKind::Io(io) => io.to_string(),
        csv::ErrorKind::UnequalLengths {
            expected_len, len, ..
        } => {
            format!("{len} fields where the header has {expected_len}")
        }
        _ => e.to_string(),
    }
}

/// Degrees to radians, for the column tables.
pub const DEG: f64 = std::f64::consts::PI / 180.0;
